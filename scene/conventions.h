// The conventions both renderers follow, written once (see docs/conventions.md).
//
// - Right-handed world, +Y up, the camera looks down -Z. Angles are radians inside the
//   code and degrees in scene files. Column vectors, column-major GLM matrices.
// - Points and directions are named by their space (posWorld, nView, lightDirTangent);
//   transforms are named xFromY: clipFromWorld = clipFromView * viewFromWorld.
// - Normals transform with the inverse transpose, tangents with the model matrix, the
//   bitangent is rebuilt as sign * cross(N, T).
// - NDC z in [-1, 1]; window depth = 0.5 * z_ndc + 0.5; pixel centres at +0.5; GL window
//   origin bottom-left. Image buffers handed between modules are top row first.
// - Textures: GL_REPEAT, texel centres at +0.5; texture rows are stored bottom row first
//   (row 0 is v = 0), as glTexImage2D expects, so uv (0,0) is the image's bottom-left.
#pragma once

#include <glm/glm.hpp>

#include <cmath>
#include <cstdint>
#include <numbers>

namespace twr {

using glm::mat3;
using glm::mat4;
using glm::ivec2;
using glm::vec2;
using glm::vec3;
using glm::vec4;

inline constexpr double kPi = std::numbers::pi;  // radians in half a turn

// Fixed-point precision of snapped window coordinates, as llvmpipe: 8 fractional bits,
// so one pixel is 256 sub-pixel units.
inline constexpr int kSubpixelBits = 8;
inline constexpr int kSubpixelScale = 1 << kSubpixelBits;

// Most point lights a scene may have (GLSL arrays are sized by it; inclusive bound).
inline constexpr int kMaxLights = 8;
// Most user clip planes (GL guarantees GL_MAX_CLIP_DISTANCES >= 8; inclusive bound).
inline constexpr int kMaxUserClipPlanes = 8;

// Below this squared length (world units^2) a vector has no usable direction.
inline constexpr float kMinLengthSquared = 1e-20f;
// Smallest attenuation denominator A_C + A_L d + A_Q d^2 we divide by (unitless).
inline constexpr float kMinAttenuationDenominator = 1e-6f;

// Height fields (docs/parallax.md), shared by both renderers' shaders:
// smallest tangent-space z (cosine to the normal, unitless) the parallax methods divide by, so
// views at or below the tangent plane give a finite shift;
inline constexpr float kMinParallaxViewZ = 1e-3f;
// a height march's shadow: occlusion (depth units, 1 = heightScale) times this, clamped to 1;
inline constexpr float kSelfShadowSharpness = 8.0f;
// a horizon map's shadow: 0.5 + (light elevation sine - horizon sine) times this, clamped;
inline constexpr float kHorizonSharpness = 4.0f;
// the parallax_offset view: 0.5 + uv shift times this (a shift of 0.05 uv reaches 0 or 1).
inline constexpr float kParallaxOffsetViewGain = 10.0f;

// normalize() that never returns NaN: a zero-length vector yields `fallback`.
inline vec3 safeNormalize(vec3 v, vec3 fallback = vec3(0.0f, 0.0f, 1.0f)) {
  const float lengthSquared = glm::dot(v, v);
  if (!(lengthSquared > kMinLengthSquared) || !std::isfinite(lengthSquared)) return fallback;
  return v / std::sqrt(lengthSquared);
}

inline float degreesToRadians(float degrees) { return degrees * (3.14159265358979323846f / 180.0f); }

// Window depth from NDC z, as glDepthRange(0, 1) defines it.
inline float windowDepthFromNdc(float zNdc) { return 0.5f * zNdc + 0.5f; }

}  // namespace twr
