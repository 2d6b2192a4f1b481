// Stage 7, shade: the course's Phong model with attenuation, diffuse / normal / specular
// maps, world or tangent lighting space, and the debug views. The C++ twin of
// shaders/phong.frag, line by line as docs/shading.md writes it:
//
//   C = ka albedo Ia + sum_i (kd albedo max(N.L, 0) Id + [N.L > 0] ks specScale (R.V)^a Is) If
//   If = 1 / max(A_C + A_L d + A_Q d^2, kMinAttenuationDenominator),  R = 2 (N.L) N - L
//
// Templated on the material's features and the view, so a scene compiles (and pays for)
// only the paths it uses, as the GLSL #define permutations do. Also templated on the scalar T
// (float: the pipeline, double: the reference).
#pragma once

#include "scene/scene.h"
#include "softrender/interpolate.h"
#include "softrender/phong_pow.h"
#include "softrender/texture_sample.h"

#include <array>
#include <cmath>
#include <type_traits>

namespace twr {

template <typename T>
struct LightUniformT {
  Vec3T<T> posWorld{T(0)};
  Vec3T<T> diffuse{T(0)};                         // Id
  Vec3T<T> specular{T(0)};                        // Is
  Vec3T<T> attenuation{T(1), T(0), T(0)};         // A_C, A_L, A_Q
};
using LightUniform = LightUniformT<float>;

// What the fragment stage reads besides the fragment (the GLSL uniforms and samplers).
template <typename T>
struct ShadeUniformsT {
  Vec3T<T> ka{T(1)}, kd{T(1)}, ks{T(0)};
  T shininess = T(32);
  const Texture* diffuseMap = nullptr;
  const Texture* normalMap = nullptr;
  const Texture* specularMap = nullptr;
  TextureFilter filter = TextureFilter::Bilinear;
  Vec3T<T> ambient{T(0)};  // Ia
  std::array<LightUniformT<T>, kMaxLights> lights{};
  int lightCount = 0;  // in [0, kMaxLights]
  Vec3T<T> eyePosWorld{T(0)};
};
using ShadeUniforms = ShadeUniformsT<float>;

template <typename T = float>
ShadeUniformsT<T> makeShadeUniforms(const Material& material, const Scene& scene, const RenderSettings& settings);

// Every intermediate value of one shading, for the pixel trace.
template <typename T>
struct LightTermsT {
  Vec3T<T> lVec{T(0)}, vVec{T(0)};  // unnormalised light and eye directions (lighting space)
  T distance = T(0);                // d, world units, always from posWorld
  Vec3T<T> l{T(0)}, v{T(0)}, r{T(0)};
  T nDotL = T(0), rDotV = T(0);
  T attenuation = T(0);  // If
  Vec3T<T> diffuse{T(0)}, specular{T(0)};
};
using LightTerms = LightTermsT<float>;
template <typename T>
struct ShadeTermsT {
  Vec3T<T> n{T(0)}, t{T(0)}, b{T(0)};  // normalised interpolated frame (world space)
  Vec3T<T> albedo{T(1)}, specScale{T(1)};
  Vec4T<T> normalTexel{T(0)};          // raw normal-map sample in [0, 1] (0 without a map)
  Vec3T<T> mappedTangent{T(0), T(0), T(1)};
  Vec3T<T> nl{T(0)};                   // the normal lighting uses (lighting space)
  Vec3T<T> ambient{T(0)};              // ka albedo Ia
  std::array<LightTermsT<T>, kMaxLights> lights{};
  int lightCount = 0;
  Vec4T<T> colour{T(0)};               // the fragment's output
};
using ShadeTerms = ShadeTermsT<float>;

// pow(x, s) for x >= 0 with 0^s = 0 for s > 0 and 0^0 = 1 (both renderers agree on it).
// float: powPositive (softrender/phong_pow.h), which the SIMD fast path repeats bit for bit;
// double (the reference): libm.
template <typename T>
T phongPow(T x, std::type_identity_t<T> s) {
  if (!(x > T(0))) return s > T(0) ? T(0) : T(1);
  if constexpr (std::is_same_v<T, float>) {
    return powPositive(x, s);
  } else {
    return std::pow(x, s);
  }
}

// (v + 1) / 2 with alpha 1: how the debug views show a vector.
template <typename T>
Vec4T<T> vectorAsColour(Vec3T<T> v) {
  return Vec4T<T>((v + T(1)) * T(0.5), T(1));
}

// The compile-time feature set of one shader permutation.
template <bool DiffuseMap, bool NormalMap, bool SpecularMap, LightingSpace Space, View ViewMode>
struct ShaderFeatures {
  static constexpr bool kHasDiffuseMap = DiffuseMap;
  static constexpr bool kHasNormalMap = NormalMap;
  static constexpr bool kHasSpecularMap = SpecularMap;
  static constexpr LightingSpace kSpace = Space;
  static constexpr View kView = ViewMode;
};

// Shades one fragment; fills `terms` when it is not null (the pixel trace). T is the scalar
// of the pipeline (float, or double for the reference).
template <typename Features, typename T>
Vec4T<T> shadeFragment(const FragmentT<T>& f, const ShadeUniformsT<T>& u, std::type_identity_t<ShadeTermsT<T>>* terms) {
  constexpr bool kTangentSpace = Features::kSpace == LightingSpace::Tangent;
  const Vec3T<T> n = safeNormalize(f.nWorld);
  const Vec3T<T> t = safeNormalize(f.tWorld);
  const Vec3T<T> b = safeNormalize(f.bWorld);

  Vec3T<T> albedo(T(1));
  if constexpr (Features::kHasDiffuseMap) albedo = Vec3T<T>(sampleTexture(*u.diffuseMap, f.uv, u.filter));
  Vec3T<T> specScale(T(1));
  if constexpr (Features::kHasSpecularMap) specScale = Vec3T<T>(sampleTexture(*u.specularMap, f.uv, u.filter));
  Vec3T<T> mappedTangent(T(0), T(0), T(1));
  Vec4T<T> normalTexel(T(0));
  if constexpr (Features::kHasNormalMap) {
    normalTexel = sampleTexture(*u.normalMap, f.uv, u.filter);
    mappedTangent = safeNormalize(T(2) * Vec3T<T>(normalTexel) - T(1));
  }

  Vec3T<T> nl = n;
  if constexpr (kTangentSpace) {
    nl = mappedTangent;
  } else if constexpr (Features::kHasNormalMap) {
    nl = safeNormalize(t * mappedTangent.x + b * mappedTangent.y + n * mappedTangent.z);
  }

  if (terms) {
    terms->n = n;
    terms->t = t;
    terms->b = b;
    terms->albedo = albedo;
    terms->specScale = specScale;
    terms->normalTexel = normalTexel;
    terms->mappedTangent = mappedTangent;
    terms->nl = nl;
  }

  Vec4T<T> colour(T(0));
  if constexpr (Features::kView == View::Shaded) {
    Vec3T<T> sum(T(0));
    for (int i = 0; i < u.lightCount; ++i) {
      const LightUniformT<T>& light = u.lights[static_cast<std::size_t>(i)];
      Vec3T<T> lVec, vVec;
      if constexpr (kTangentSpace) {
        lVec = f.lightDirTangent[static_cast<std::size_t>(i)];
        vVec = f.eyeDirTangent;
      } else {
        lVec = light.posWorld - f.posWorld;
        vVec = u.eyePosWorld - f.posWorld;
      }
      const T d = glm::length(light.posWorld - f.posWorld);
      const Vec3T<T> l = safeNormalize(lVec);
      const Vec3T<T> v = safeNormalize(vVec);
      const T nDotL = glm::dot(nl, l);
      const Vec3T<T> r = T(2) * nDotL * nl - l;
      const T rDotV = std::fmax(glm::dot(r, v), T(0));
      const T attenuation =
          T(1) / std::fmax(light.attenuation.x + light.attenuation.y * d + light.attenuation.z * d * d,
                           static_cast<T>(kMinAttenuationDenominator));
      const Vec3T<T> diffuse = u.kd * albedo * std::fmax(nDotL, T(0)) * light.diffuse;
      const Vec3T<T> specular =
          nDotL > T(0) ? u.ks * specScale * phongPow(rDotV, u.shininess) * light.specular : Vec3T<T>(T(0));
      sum += (diffuse + specular) * attenuation;
      if (terms) {
        LightTermsT<T>& lt = terms->lights[static_cast<std::size_t>(i)];
        lt.lVec = lVec;
        lt.vVec = vVec;
        lt.distance = d;
        lt.l = l;
        lt.v = v;
        lt.r = r;
        lt.nDotL = nDotL;
        lt.rDotV = rDotV;
        lt.attenuation = attenuation;
        lt.diffuse = diffuse;
        lt.specular = specular;
      }
    }
    const Vec3T<T> ambient = u.ka * albedo * u.ambient;
    colour = Vec4T<T>(ambient + sum, T(1));
    if (terms) {
      terms->ambient = ambient;
      terms->lightCount = u.lightCount;
    }
  } else if constexpr (Features::kView == View::Albedo) {
    colour = Vec4T<T>(albedo * u.kd, T(1));
  } else if constexpr (Features::kView == View::Normal) {
    colour = vectorAsColour(n);
  } else if constexpr (Features::kView == View::Tangent) {
    colour = vectorAsColour(t);
  } else if constexpr (Features::kView == View::Bitangent) {
    colour = vectorAsColour(b);
  } else if constexpr (Features::kView == View::MappedNormal) {
    colour = vectorAsColour(nl);
  } else if constexpr (Features::kView == View::Uv) {
    colour = Vec4T<T>(f.uv.x - std::floor(f.uv.x), f.uv.y - std::floor(f.uv.y), T(0), T(1));
  } else if constexpr (Features::kView == View::Depth) {
    colour = Vec4T<T>(f.depth, f.depth, f.depth, T(1));
  } else if constexpr (Features::kView == View::LightTangent || Features::kView == View::EyeTangent) {
    constexpr bool kLight = Features::kView == View::LightTangent;
    Vec3T<T> dirTangent(T(0));  // no light: (0, 0, 0), shown as grey 0.5
    if (!kLight || u.lightCount > 0) {
      if constexpr (kTangentSpace) {
        dirTangent = safeNormalize(kLight ? f.lightDirTangent[0] : f.eyeDirTangent);
      } else {
        const Vec3T<T> w = (kLight ? u.lights[0].posWorld : u.eyePosWorld) - f.posWorld;
        dirTangent = safeNormalize(Vec3T<T>(glm::dot(t, w), glm::dot(b, w), glm::dot(n, w)));
      }
    }
    colour = vectorAsColour(dirTangent);
  }
  colour = glm::clamp(colour, Vec4T<T>(T(0)), Vec4T<T>(T(1)));
  if (terms) terms->colour = colour;
  return colour;
}

// Which permutation a draw item needs (runtime values of the template parameters).
struct ShaderKey {
  bool diffuseMap = false, normalMap = false, specularMap = false;
  LightingSpace space = LightingSpace::World;
  View view = View::Shaded;
};

template <typename T>
ShaderKey shaderKeyFor(const ShadeUniformsT<T>& uniforms, const RenderSettings& settings) {
  ShaderKey key;
  key.diffuseMap = uniforms.diffuseMap != nullptr;
  key.normalMap = uniforms.normalMap != nullptr;
  key.specularMap = uniforms.specularMap != nullptr;
  key.space = settings.lightingSpace;
  key.view = settings.view;
  return key;
}

// Calls body.template operator()<ShaderFeatures<...>>() for the permutation `key` names: the
// one runtime branch per draw item, so nothing per pixel is dispatched at run time.
template <typename Body>
void withShaderFeatures(const ShaderKey& key, Body&& body) {
  auto withView = [&]<bool D, bool N, bool S, LightingSpace L>() {
    switch (key.view) {
      case View::Shaded: body.template operator()<ShaderFeatures<D, N, S, L, View::Shaded>>(); break;
      case View::Albedo: body.template operator()<ShaderFeatures<D, N, S, L, View::Albedo>>(); break;
      case View::Normal: body.template operator()<ShaderFeatures<D, N, S, L, View::Normal>>(); break;
      case View::Tangent: body.template operator()<ShaderFeatures<D, N, S, L, View::Tangent>>(); break;
      case View::Bitangent: body.template operator()<ShaderFeatures<D, N, S, L, View::Bitangent>>(); break;
      case View::MappedNormal: body.template operator()<ShaderFeatures<D, N, S, L, View::MappedNormal>>(); break;
      case View::Uv: body.template operator()<ShaderFeatures<D, N, S, L, View::Uv>>(); break;
      case View::Depth: body.template operator()<ShaderFeatures<D, N, S, L, View::Depth>>(); break;
      case View::LightTangent: body.template operator()<ShaderFeatures<D, N, S, L, View::LightTangent>>(); break;
      case View::EyeTangent: body.template operator()<ShaderFeatures<D, N, S, L, View::EyeTangent>>(); break;
    }
  };
  auto withSpace = [&]<bool D, bool N, bool S>() {
    if (key.space == LightingSpace::Tangent) {
      withView.template operator()<D, N, S, LightingSpace::Tangent>();
    } else {
      withView.template operator()<D, N, S, LightingSpace::World>();
    }
  };
  auto withSpecular = [&]<bool D, bool N>() {
    if (key.specularMap) {
      withSpace.template operator()<D, N, true>();
    } else {
      withSpace.template operator()<D, N, false>();
    }
  };
  auto withNormal = [&]<bool D>() {
    if (key.normalMap) {
      withSpecular.template operator()<D, true>();
    } else {
      withSpecular.template operator()<D, false>();
    }
  };
  if (key.diffuseMap) {
    withNormal.template operator()<true>();
  } else {
    withNormal.template operator()<false>();
  }
}

// Shades with the permutation `key` names (one runtime dispatch; for single fragments such
// as the pixel trace and tests).
vec4 shadeFragmentDynamic(const ShaderKey& key, const Fragment& f, const ShadeUniforms& u, ShadeTerms* terms);

}  // namespace twr
