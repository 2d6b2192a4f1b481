// Stage 7, shade: the course's Phong model with attenuation, diffuse / normal / specular
// maps, world or tangent lighting space, and the debug views. The C++ twin of
// shaders/phong.frag, line by line as docs/shading.md writes it:
//
//   C = ka albedo Ia + sum_i (kd albedo max(N.L, 0) Id + [N.L > 0] ks specScale (R.V)^a Is) If
//   If = 1 / max(A_C + A_L d + A_Q d^2, kMinAttenuationDenominator),  R = 2 (N.L) N - L
//
// Templated on the material's features and the view, so a scene compiles (and pays for)
// only the paths it uses, as the GLSL #define permutations do.
#pragma once

#include "scene/scene.h"
#include "softrender/interpolate.h"
#include "softrender/texture_sample.h"

#include <array>
#include <cmath>

namespace twr {

struct LightUniform {
  vec3 posWorld{0.0f};
  vec3 diffuse{0.0f};      // Id
  vec3 specular{0.0f};     // Is
  vec3 attenuation{1.0f, 0.0f, 0.0f};  // A_C, A_L, A_Q
};

// What the fragment stage reads besides the fragment (the GLSL uniforms and samplers).
struct ShadeUniforms {
  vec3 ka{1.0f}, kd{1.0f}, ks{0.0f};
  float shininess = 32.0f;
  const Texture* diffuseMap = nullptr;
  const Texture* normalMap = nullptr;
  const Texture* specularMap = nullptr;
  TextureFilter filter = TextureFilter::Bilinear;
  vec3 ambient{0.0f};  // Ia
  std::array<LightUniform, kMaxLights> lights{};
  int lightCount = 0;  // in [0, kMaxLights]
  vec3 eyePosWorld{0.0f};
};

ShadeUniforms makeShadeUniforms(const Material& material, const Scene& scene, const RenderSettings& settings);

// Every intermediate value of one shading, for the pixel trace.
struct LightTerms {
  vec3 lVec{0.0f}, vVec{0.0f};  // unnormalised light and eye directions (lighting space)
  float distance = 0.0f;        // d, world units, always from posWorld
  vec3 l{0.0f}, v{0.0f}, r{0.0f};
  float nDotL = 0.0f, rDotV = 0.0f;
  float attenuation = 0.0f;  // If
  vec3 diffuse{0.0f}, specular{0.0f};
};
struct ShadeTerms {
  vec3 n{0.0f}, t{0.0f}, b{0.0f};  // normalised interpolated frame (world space)
  vec3 albedo{1.0f}, specScale{1.0f};
  vec4 normalTexel{0.0f};          // raw normal-map sample in [0, 1] (0 without a map)
  vec3 mappedTangent{0.0f, 0.0f, 1.0f};
  vec3 nl{0.0f};                   // the normal lighting uses (lighting space)
  vec3 ambient{0.0f};              // ka albedo Ia
  std::array<LightTerms, kMaxLights> lights{};
  int lightCount = 0;
  vec4 colour{0.0f};               // the fragment's output
};

// pow(x, s) for x >= 0 with 0^s = 0 for s > 0 and 0^0 = 1 (both renderers agree on it).
float phongPow(float x, float s);

// (v + 1) / 2 with alpha 1: how the debug views show a vector.
inline vec4 vectorAsColour(vec3 v) { return vec4((v + 1.0f) * 0.5f, 1.0f); }

// The compile-time feature set of one shader permutation.
template <bool DiffuseMap, bool NormalMap, bool SpecularMap, LightingSpace Space, View ViewMode>
struct ShaderFeatures {
  static constexpr bool kHasDiffuseMap = DiffuseMap;
  static constexpr bool kHasNormalMap = NormalMap;
  static constexpr bool kHasSpecularMap = SpecularMap;
  static constexpr LightingSpace kSpace = Space;
  static constexpr View kView = ViewMode;
};

// Shades one fragment; fills `terms` when it is not null (the pixel trace).
template <typename Features>
vec4 shadeFragment(const Fragment& f, const ShadeUniforms& u, ShadeTerms* terms) {
  constexpr bool kTangentSpace = Features::kSpace == LightingSpace::Tangent;
  const vec3 n = safeNormalize(f.nWorld);
  const vec3 t = safeNormalize(f.tWorld);
  const vec3 b = safeNormalize(f.bWorld);

  vec3 albedo(1.0f);
  if constexpr (Features::kHasDiffuseMap) albedo = vec3(sampleTexture(*u.diffuseMap, f.uv, u.filter));
  vec3 specScale(1.0f);
  if constexpr (Features::kHasSpecularMap) specScale = vec3(sampleTexture(*u.specularMap, f.uv, u.filter));
  vec3 mappedTangent(0.0f, 0.0f, 1.0f);
  vec4 normalTexel(0.0f);
  if constexpr (Features::kHasNormalMap) {
    normalTexel = sampleTexture(*u.normalMap, f.uv, u.filter);
    mappedTangent = safeNormalize(2.0f * vec3(normalTexel) - 1.0f);
  }

  vec3 nl = n;
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

  vec4 colour(0.0f);
  if constexpr (Features::kView == View::Shaded) {
    vec3 sum(0.0f);
    for (int i = 0; i < u.lightCount; ++i) {
      const LightUniform& light = u.lights[static_cast<std::size_t>(i)];
      vec3 lVec, vVec;
      if constexpr (kTangentSpace) {
        lVec = f.lightDirTangent[static_cast<std::size_t>(i)];
        vVec = f.eyeDirTangent;
      } else {
        lVec = light.posWorld - f.posWorld;
        vVec = u.eyePosWorld - f.posWorld;
      }
      const float d = glm::length(light.posWorld - f.posWorld);
      const vec3 l = safeNormalize(lVec);
      const vec3 v = safeNormalize(vVec);
      const float nDotL = glm::dot(nl, l);
      const vec3 r = 2.0f * nDotL * nl - l;
      const float rDotV = std::fmax(glm::dot(r, v), 0.0f);
      const float attenuation =
          1.0f / std::fmax(light.attenuation.x + light.attenuation.y * d + light.attenuation.z * d * d,
                           kMinAttenuationDenominator);
      const vec3 diffuse = u.kd * albedo * std::fmax(nDotL, 0.0f) * light.diffuse;
      const vec3 specular =
          nDotL > 0.0f ? u.ks * specScale * phongPow(rDotV, u.shininess) * light.specular : vec3(0.0f);
      sum += (diffuse + specular) * attenuation;
      if (terms) {
        LightTerms& lt = terms->lights[static_cast<std::size_t>(i)];
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
    const vec3 ambient = u.ka * albedo * u.ambient;
    colour = vec4(ambient + sum, 1.0f);
    if (terms) {
      terms->ambient = ambient;
      terms->lightCount = u.lightCount;
    }
  } else if constexpr (Features::kView == View::Albedo) {
    colour = vec4(albedo * u.kd, 1.0f);
  } else if constexpr (Features::kView == View::Normal) {
    colour = vectorAsColour(n);
  } else if constexpr (Features::kView == View::Tangent) {
    colour = vectorAsColour(t);
  } else if constexpr (Features::kView == View::Bitangent) {
    colour = vectorAsColour(b);
  } else if constexpr (Features::kView == View::MappedNormal) {
    colour = vectorAsColour(nl);
  } else if constexpr (Features::kView == View::Uv) {
    colour = vec4(f.uv.x - std::floor(f.uv.x), f.uv.y - std::floor(f.uv.y), 0.0f, 1.0f);
  } else if constexpr (Features::kView == View::Depth) {
    colour = vec4(f.depth, f.depth, f.depth, 1.0f);
  } else if constexpr (Features::kView == View::LightTangent || Features::kView == View::EyeTangent) {
    constexpr bool kLight = Features::kView == View::LightTangent;
    vec3 dirTangent(0.0f);  // no light: (0, 0, 0), shown as grey 0.5
    if (!kLight || u.lightCount > 0) {
      if constexpr (kTangentSpace) {
        dirTangent = safeNormalize(kLight ? f.lightDirTangent[0] : f.eyeDirTangent);
      } else {
        const vec3 w = (kLight ? u.lights[0].posWorld : u.eyePosWorld) - f.posWorld;
        dirTangent = safeNormalize(vec3(glm::dot(t, w), glm::dot(b, w), glm::dot(n, w)));
      }
    }
    colour = vectorAsColour(dirTangent);
  }
  colour = glm::clamp(colour, vec4(0.0f), vec4(1.0f));
  if (terms) terms->colour = colour;
  return colour;
}

// Which permutation a draw item needs (runtime values of the template parameters).
struct ShaderKey {
  bool diffuseMap = false, normalMap = false, specularMap = false;
  LightingSpace space = LightingSpace::World;
  View view = View::Shaded;
};

ShaderKey shaderKeyFor(const ShadeUniforms& uniforms, const RenderSettings& settings);

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
