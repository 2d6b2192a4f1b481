// Stage 7, shade: the course's Phong model with attenuation, diffuse / normal / specular
// maps, world or tangent lighting space, and the debug views. The C++ twin of
// shaders/phong.frag, line by line as docs/shading.md writes it:
//
//   C = ka albedo Ia + sum_i (kd albedo max(N.L, 0) Id + [N.L > 0] ks specScale (R.V)^a Is) If
//   If = 1 / max(A_C + A_L d + A_Q d^2, kMinAttenuationDenominator),  R = 2 (N.L) N - L
//
// Templated on the material's features and the view, so a scene compiles (and pays for)
// only the paths it uses, as the GLSL #define permutations do. The shading itself is written
// once over the lane type in shade-inl.h (float: the teaching pipeline, double: the
// reference, Highway vectors: the fast path); this header holds its uniforms, the trace's
// record of it and the scalar entry point shadeFragment.
#pragma once

#include "scene/scene.h"
#include "softrender/environment_uniforms.h"
#include "softrender/interpolate.h"
#include "softrender/lanes.h"
#include "softrender/phong_pow.h"
#include "softrender/shadow_uniforms.h"
#include "softrender/texture_sample.h"

#include <array>
#include <cmath>
#include <type_traits>

namespace twr {

template <typename T>
struct LightUniformT {
  // lightVectorWorld: (position, 1) for a point light, (towards the light, 0) for a directional
  // one; the vector to the light from P is xyz - w P (toLightWorld).
  Vec4T<T> vectorWorld{T(0)};
  Vec3T<T> diffuse{T(0)};                         // Id
  Vec3T<T> specular{T(0)};                        // Is
  Vec3T<T> attenuation{T(1), T(0), T(0)};         // A_C, A_L, A_Q
  // A spot light's cone (scene.h's SpotUniform): spot false for any other light.
  bool spot = false;
  Vec3T<T> spotAxis{T(0), T(-1), T(0)};           // the cone's axis, the way the light shines, unit
  T spotCosOuter = T(-1), spotCosRange = T(1);    // cos outer; cos inner - cos outer (>= kMinSpotCosineRange)
  ShadowUniformT<T> shadow;                       // its shadow map (shadow.depth null: none)
};
using LightUniform = LightUniformT<float>;

// What the fragment stage reads besides the fragment (the GLSL uniforms and samplers).
template <typename T>
struct ShadeUniformsT {
  Vec3T<T> ka{T(1)}, kd{T(1)}, ks{T(0)};
  T shininess = T(32);
  T ssrReflect = T(0);  // the material's share of the screen-space reflection (the G-buffer's specular.w)
  const Texture* diffuseMap = nullptr;
  const Texture* normalMap = nullptr;
  const Texture* specularMap = nullptr;
  TextureFilter filter = TextureFilter::Bilinear;
  // settings.anisotropy > 1: llvmpipe's elliptical filter (texture_sample-inl.h), which does not
  // depend on the ratio itself.
  bool anisotropic = false;
  // Whether fragments need their quad's uv differences (a LOD or the filter's ellipse).
  bool needsQuadDifferences() const { return usesMipmaps(filter) || anisotropic; }
  // Normal-map conventions (phong.frag's NORMAL_MAP_* defines): green pointing down (flip it),
  // two channels (BC5: z rebuilt), a strength scaling x and y (an MTL's -bm).
  bool normalGreenDown = false;
  bool normalXy = false;
  bool normalStrengthOn = false;
  T normalStrength = T(1);
  // Each map's own uv transform (<MAP>_UV_TRANSFORM): uv * scale + offset, for diffuse,
  // normal and specular in that order.
  std::array<bool, 3> uvTransform{};
  std::array<Vec2T<T>, 3> uvScale{Vec2T<T>(T(1)), Vec2T<T>(T(1)), Vec2T<T>(T(1))};
  std::array<Vec2T<T>, 3> uvOffset{};
  // Height field (surface_detail-inl.h): the method, the depth in texture-space units, one
  // level-0 texel in uv (Blinn's finite differences), the layer counts as floats, the cap on
  // any march's iterations (the max layer count), relief's refinement steps, the self-shadow
  // method and the horizon map's azimuth count (4 per horizon texture).
  const Texture* heightMap = nullptr;
  SurfaceDetail surfaceDetail = SurfaceDetail::NormalMap;
  T heightScale = T(kDefaultHeightScale);
  Vec2T<T> heightTexel{T(1)};
  T layersMin = T(8), layersMax = T(32);
  int layerCap = 32;
  int refinementSteps = 5;
  SelfShadow selfShadow = SelfShadow::None;
  int horizonDirections = 0;
  std::array<const Texture*, kMaxHorizonDirections / 4> horizonMaps{};
  // The environment (environment-inl.h): a runtime branch per draw item, not a permutation
  // (it adds a few reads per fragment, not a loop, and doubling every kernel doubles the
  // fast path's build); environment.cube is null when the material does not use one.
  EnvironmentUniformsT<T> environment;
  // The view this draw's fragments show (fragmentViewOf): the shaded colour, the environment,
  // shadow or Phong-term value in its place, or a debug view. A runtime branch, not a kernel:
  // every view is drawn by the permutation of the material's features.
  View view = View::Shaded;
  Vec3T<T> ambient{T(0)};  // Ia
  std::array<LightUniformT<T>, kMaxLights> lights{};
  int lightCount = 0;  // in [0, kMaxLights]
  Vec3T<T> eyePosWorld{T(0)};
};
using ShadeUniforms = ShadeUniformsT<float>;

template <typename T = float>
ShadeUniformsT<T> makeShadeUniforms(const Material& material, const Scene& scene, const RenderSettings& settings);
// Points each light's uniform at its shadow map (`maps`, per light index; a missing or null
// entry: none). The maps must outlive the uniforms.
template <typename T>
void setShadowUniforms(ShadeUniformsT<T>& u, const ShadowMaps& maps) {
  for (int i = 0; i < u.lightCount; ++i) {
    const std::size_t k = static_cast<std::size_t>(i);
    u.lights[k].shadow = makeShadowUniform<T>(k < maps.size() ? maps[k].get() : nullptr);
  }
}

// Every intermediate value of one shading, for the pixel trace.
template <typename T>
struct LightTermsT {
  Vec3T<T> lVec{T(0)}, vVec{T(0)};  // unnormalised light and eye directions (lighting space)
  T distance = T(0);                // d, world units, always from posWorld
  Vec3T<T> l{T(0)}, v{T(0)}, r{T(0)};
  T nDotL = T(0), rDotV = T(0);
  T attenuation = T(0);  // If
  T selfShadow = T(1);   // 1 = lit, 0 = in the height field's shadow
  // Its shadow map's test (shadowOn: the light has one): visibility 1 = lit; the fragment's
  // depth from the light, the bias and the map's depth at its texel; what every tap compares
  // (depth - bias), whether the fragment lies inside the map, and its texel (x, y, layer).
  bool shadowOn = false;
  T shadowVisibility = T(1), shadowDepth = T(0), shadowBias = T(0), shadowStored = T(1);
  T shadowReference = T(0);
  bool shadowInside = false;
  Vec3T<T> shadowTexel{T(0)};
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
  Vec2T<T> uvShifted{T(0)};            // where the maps were read (the parallax methods move it)
  T height = T(1);                     // the height there (1 without a height map)
  T parallaxSteps = T(0);              // layers marched
  Vec3T<T> ambient{T(0)};              // ka albedo Ia
  // The lights' diffuse and specular terms summed with their If and shadows: the Phong-term
  // views' values (0 in any other view, where the light loop does not keep them).
  Vec3T<T> diffuseSum{T(0)}, specularSum{T(0)};
  std::array<LightTermsT<T>, kMaxLights> lights{};
  // The environment (when the material uses one): the directions read in world space (0 when
  // not read), what each gave, the reflected share and the Phong colour it was mixed into.
  bool environmentOn = false;
  Vec3T<T> reflectWorld{T(0)}, refractWorld{T(0)};
  Vec3T<T> environmentReflected{T(0)}, environmentTransmitted{T(0)};
  T environmentShare = T(0);
  // The LOD the reflection was read at: texture()'s from the direction's differences, or the
  // shininess's with a prefiltered reflection (environmentPrefiltered).
  T environmentReflectLod = T(0);
  bool environmentPrefiltered = false;
  bool totalInternalReflection = false;
  Vec3T<T> phongColour{T(0)};
  // The environment's diffuse light (environment_diffuse): D at the normal, times the intensity.
  bool environmentDiffuseOn = false;
  Vec3T<T> environmentDiffuse{T(0)};
  int lightCount = 0;
  Vec4T<T> colour{T(0)};               // the fragment's output
};
using ShadeTerms = ShadeTermsT<float>;

// (v + 1) / 2 with alpha 1: how the debug views show a vector.
template <typename T>
Vec4T<T> vectorAsColour(Vec3T<T> v) {
  return Vec4T<T>((v + T(1)) * T(0.5), T(1));
}

// The compile-time feature set of one shader permutation: what changes the hot loop (the
// normal and height maps, which change how the surface frame is built; the lighting space).
// The view is not one (ShadeUniformsT::view): a debug view costs a branch per vector of
// fragments, not a kernel per view (and the varyings a kernel of its own would have dropped:
// docs/performance.md, "Debug views at run time"). Nor are the diffuse and specular maps:
// each is one texture read or none, a uniform branch per vector (materialTexels), and as
// template parameters they made four times the kernels for the same speed
// (docs/performance.md, "The material's colour maps at run time").
// HeightMap: the material's surface detail reads its height map (surface_detail-inl.h); the
// method itself is a uniform (one branch per draw item), as each adds a loop, not a variant.
template <bool NormalMap, LightingSpace Space, bool HeightMap = false>
struct ShaderFeatures {
  static constexpr bool kHasHeightMap = HeightMap;
  static constexpr bool kHasNormalMap = NormalMap;
  static constexpr LightingSpace kSpace = Space;
};

// Whether a view reads the material's diffuse or specular map: the shaded view and what draws
// as it (the environment, shadow, Phong-term and reflection views) read both; albedo and
// mip_level the diffuse map alone.
constexpr bool viewDrawsAsShaded(View v) { return isShadedView(v) || isSsrView(v); }
constexpr bool viewReadsDiffuseMap(View v) { return viewDrawsAsShaded(v) || v == View::Albedo || v == View::MipLevel; }
constexpr bool viewReadsSpecularMap(View v) { return viewDrawsAsShaded(v); }

// The view a fragment shows for the frame's view: the reflection views draw a shaded frame the
// reflection pass then writes over (isSsrView); mip_level draws as albedo, its maps swapped for
// coloured levels (scene/mip_level_view.h).
constexpr View fragmentViewOf(View v) {
  if (isSsrView(v)) return View::Shaded;
  if (v == View::MipLevel) return View::Albedo;
  return v;
}

// The material's maps as the scalar lanes read them (null where the uniforms have none).
struct TextureMaps {
  const Texture* diffuse = nullptr;
  const Texture* normal = nullptr;
  const Texture* specular = nullptr;
  const Texture* height = nullptr;
  std::array<const Texture*, kMaxHorizonDirections / 4> horizon{};
};

}  // namespace twr

#include "softrender/shade-inl.h"

namespace twr {

// Shades one fragment; fills `terms` when it is not null (the pixel trace). T is the scalar
// of the pipeline (float, or double for the reference).
template <typename Features, typename T>
Vec4T<T> shadeFragment(const FragmentT<T>& f, const ShadeUniformsT<T>& u, std::type_identity_t<ShadeTermsT<T>>* terms) {
  return lanes::shadeFragment<Features, T>(f, u, TextureMaps{u.diffuseMap, u.normalMap, u.specularMap, u.heightMap, u.horizonMaps},
                                           terms);
}

// The environment's direction differences of the fragment at pixel (px, py) on the triangle
// whose varyings `planes` holds (setEnvironmentDifferences, shade-inl.h): for a material
// that reads the environment, in the shaded view; otherwise nothing to do.
template <typename Features, typename T>
void setEnvironmentDifferences(const VaryingPlanesT<T>& planes, int px, int py, const ShadeUniformsT<T>& u,
                               FragmentT<T>& f) {
  if (isShadedView(u.view)) {
    if (!u.environment.cube) return;
    lanes::setEnvironmentDifferences<Features, T>(
        planes, static_cast<T>(px), static_cast<T>(py), static_cast<T>(px & ~1), static_cast<T>(py & ~1), u,
        TextureMaps{u.diffuseMap, u.normalMap, u.specularMap, u.heightMap, u.horizonMaps}, f);
  }
}

// Which permutation a draw item needs (runtime values of the template parameters), and the
// view, which decides what the permutation needs to read.
struct ShaderKey {
  bool diffuseMap = false, normalMap = false, specularMap = false, heightMap = false;
  LightingSpace space = LightingSpace::World;
  View view = View::Shaded;
};

// The key with the features its view does not read cleared, so equal pictures share one
// permutation: albedo reads the diffuse map; mapped_normal the normal map; shaded everything;
// the height views and a parallax method (which moves every map's uv) the height map. A view
// that reads no lighting-space vector draws the same in both spaces: world's permutation.
constexpr bool viewReadsLightingSpace(View v) {
  return v == View::Shaded || v == View::MappedNormal || v == View::LightTangent || v == View::EyeTangent;
}
inline ShaderKey canonicalShaderKey(ShaderKey key) {
  key.diffuseMap = key.diffuseMap && viewReadsDiffuseMap(key.view);
  key.specularMap = key.specularMap && viewReadsSpecularMap(key.view);
  if (viewDrawsAsShaded(key.view)) {
    // The environment, shadow and Phong-term views read what the shaded view reads; the
    // reflection views draw a shaded frame the reflection pass then writes over.
    key.view = View::Shaded;
  }
  switch (key.view) {
    case View::Shaded: break;
    case View::Albedo:
    case View::MipLevel: key.normalMap = false; break;
    case View::MappedNormal: break;
    case View::Height:
    case View::ParallaxOffset:
    case View::ParallaxSteps:
    case View::SelfShadow: key.normalMap = false; break;
    default: key.normalMap = key.heightMap = false; break;
  }
  if (!key.heightMap && !viewReadsLightingSpace(key.view)) key.space = LightingSpace::World;
  return key;
}

template <typename T>
ShaderKey shaderKeyFor(const ShadeUniformsT<T>& uniforms, const RenderSettings& settings) {
  ShaderKey key;
  key.diffuseMap = uniforms.diffuseMap != nullptr;
  key.normalMap = uniforms.normalMap != nullptr;
  key.specularMap = uniforms.specularMap != nullptr;
  key.heightMap = uniforms.heightMap != nullptr;
  key.space = settings.lightingSpace;
  key.view = settings.view;
  return canonicalShaderKey(key);
}

// Calls body.template operator()<ShaderFeatures<...>>() for the permutation `key` names: the
// one runtime branch per draw item, so nothing per pixel is dispatched at run time. The
// features a view does not read are off (canonicalShaderKey), so a debug view runs the
// permutation of fewer maps: 2^3 permutations in all, whatever the view.
template <typename Body>
void withShaderFeatures(const ShaderKey& keyIn, Body&& body) {
  const ShaderKey key = canonicalShaderKey(keyIn);
  auto withSpace = [&]<bool N, bool H>() {
    if (key.space == LightingSpace::Tangent) {
      body.template operator()<ShaderFeatures<N, LightingSpace::Tangent, H>>();
    } else {
      body.template operator()<ShaderFeatures<N, LightingSpace::World, H>>();
    }
  };
  auto withHeight = [&]<bool N>() {
    if (key.heightMap) return withSpace.template operator()<N, true>();
    withSpace.template operator()<N, false>();
  };
  if (key.normalMap) return withHeight.template operator()<true>();
  withHeight.template operator()<false>();
}

// Shades with the permutation `key` names (one runtime dispatch; for single fragments such
// as the pixel trace and tests).
vec4 shadeFragmentDynamic(const ShaderKey& key, const Fragment& f, const ShadeUniforms& u, ShadeTerms* terms);
// setEnvironmentDifferences with the permutation `key` names (the pixel trace).
void setEnvironmentDifferencesDynamic(const ShaderKey& key, const VaryingPlanes& planes, int px, int py,
                                      const ShadeUniforms& u, Fragment& f);

}  // namespace twr
