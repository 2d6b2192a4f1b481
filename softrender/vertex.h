// Stage 1, vertex: one mesh vertex from model space to world space and clip space, plus the
// varyings the fragment stage needs. The C++ twin of shaders/phong.vert (docs/shading.md,
// "Vertex stage"): same inputs, same names, same order of operations.
#pragma once

#include "scene/conventions.h"
#include "scene/mesh.h"
#include "scene/scene.h"
#include "scene/settings.h"

#include <array>

namespace twr {

// What the vertex stage reads besides the vertex itself (the GLSL uniforms).
struct VertexUniforms {
  mat4 worldFromModel{1.0f};
  mat4 clipFromWorld{1.0f};
  mat3 normalFromModel{1.0f};   // inverse transpose of the upper 3x3 of worldFromModel
  mat3 tangentFromModel{1.0f};  // upper 3x3 (tangent_transform = model) or normalFromModel
  float mirrorSign = 1.0f;      // -1 when det(upper 3x3 of worldFromModel) < 0, else +1
  vec3 eyePosWorld{0.0f};
  std::array<vec3, kMaxLights> lightPosWorld{};
  int lightCount = 0;            // in [0, kMaxLights]
  bool tangentLighting = false;  // compute lightDirTangent / eyeDirTangent
  std::array<vec4, kMaxUserClipPlanes> userClipPlanes{};  // world space, keeps dot(p, (x,y,z,1)) >= 0
  int userClipPlaneCount = 0;                             // in [0, kMaxUserClipPlanes]
};

// The vertex stage's output and the clipper's unit of work: the clip-space position and
// every varying, so a vertex the clipper creates carries all of them.
struct ClipVertex {
  vec4 posClip{0.0f};  // gl_Position
  vec3 posWorld{0.0f};
  vec3 nWorld{0.0f};  // not normalised (the fragment stage normalises per pixel)
  vec3 tWorld{0.0f};
  vec3 bWorld{0.0f};
  vec2 uv{0.0f};
  std::array<vec3, kMaxLights> lightDirTangent{};  // tangent lighting space only
  vec3 eyeDirTangent{0.0f};                        // tangent lighting space only
  std::array<float, kMaxUserClipPlanes> clipDistance{};  // gl_ClipDistance[j]
  // Made by the clipper rather than the vertex stage. llvmpipe maps such vertices to the
  // window with a separate multiply and add (Mesa's C clipper) but original vertices with a
  // fused multiply-add (its JIT vertex shader); setup does the same to snap identically.
  bool fromClipper = false;
};

// m * vec4(p, 1) summed column by column from the left, ((c0 x + c1 y) + c2 z) + c3, the
// order a GLSL compiler evaluates mat4 * vec4 in, so both renderers round alike.
vec4 transformPoint(const mat4& m, vec3 p);
// m * v, columns summed from the left like transformPoint.
vec3 transformVector(const mat3& m, vec3 v);

// Inverse transpose of the upper 3x3; for a singular matrix the cofactor matrix (the same
// directions up to scale, never Inf or NaN).
mat3 normalMatrixFrom(const mat4& worldFromModel);

// clipFromWorld = clipFromView(camera, width / height) * viewFromWorld(camera). Throws
// InputError for an unusable camera.
mat4 clipFromWorldFor(const Camera& camera, int width, int height);

// The uniforms for one draw item.
VertexUniforms makeVertexUniforms(const mat4& worldFromModel, const mat4& clipFromWorld, const Scene& scene,
                                  const RenderSettings& settings);

// Runs the vertex stage on one vertex.
ClipVertex runVertexStage(const Vertex& vertex, const VertexUniforms& uniforms);

}  // namespace twr
