// Stage 1, vertex: one mesh vertex from model space to world space and clip space, plus the
// varyings the fragment stage needs. The C++ twin of shaders/phong.vert (docs/shading.md,
// "Vertex stage"): same inputs, same names, same order of operations.
//
// Templated on the scalar T (softrender/precision.h): float is the pipeline that matches GL,
// double the reference. VertexUniforms and ClipVertex name the float versions.
#pragma once

#include "scene/conventions.h"
#include "scene/mesh.h"
#include "scene/scene.h"
#include "scene/settings.h"
#include "softrender/precision.h"

#include <array>

namespace twr {

// What the vertex stage reads besides the vertex itself (the GLSL uniforms).
template <typename T>
struct VertexUniformsT {
  Mat4T<T> worldFromModel{T(1)};
  Mat4T<T> clipFromWorld{T(1)};
  Mat3T<T> normalFromModel{T(1)};   // inverse transpose of the upper 3x3 of worldFromModel
  Mat3T<T> tangentFromModel{T(1)};  // upper 3x3 (tangent_transform = model) or normalFromModel
  T mirrorSign = T(1);              // -1 when det(upper 3x3 of worldFromModel) < 0, else +1
  Vec3T<T> eyePosWorld{T(0)};
  // Each light as lightVectorWorld gives it: (position, 1) or (towards the light, 0).
  std::array<Vec4T<T>, kMaxLights> lightVectorWorld{};
  int lightCount = 0;            // in [0, kMaxLights]
  bool tangentLighting = false;  // compute lightDirTangent / eyeDirTangent
  std::array<Vec4T<T>, kMaxUserClipPlanes> userClipPlanes{};  // world space, keeps dot(p, (x,y,z,1)) >= 0
  int userClipPlaneCount = 0;                                 // in [0, kMaxUserClipPlanes]
};
using VertexUniforms = VertexUniformsT<float>;

// The vertex stage's output and the clipper's unit of work: the clip-space position and
// every varying, so a vertex the clipper creates carries all of them.
template <typename T>
struct ClipVertexT {
  Vec4T<T> posClip{T(0)};  // gl_Position
  Vec3T<T> posWorld{T(0)};
  Vec3T<T> nWorld{T(0)};  // not normalised (the fragment stage normalises per pixel)
  Vec3T<T> tWorld{T(0)};
  Vec3T<T> bWorld{T(0)};
  Vec2T<T> uv{T(0)};
  std::array<Vec3T<T>, kMaxLights> lightDirTangent{};  // tangent lighting space only
  Vec3T<T> eyeDirTangent{T(0)};                        // tangent lighting space only
  std::array<T, kMaxUserClipPlanes> clipDistance{};    // gl_ClipDistance[j]
  // Made by the clipper rather than the vertex stage. llvmpipe maps such vertices to the
  // window with a separate multiply and add (Mesa's C clipper) but original vertices with a
  // fused multiply-add (its JIT vertex shader); setup does the same to snap identically.
  bool fromClipper = false;
};
using ClipVertex = ClipVertexT<float>;

// Inverse transpose of the upper 3x3; for a singular matrix the cofactor matrix (the same
// directions up to scale, never Inf or NaN).
template <typename T>
Mat3T<T> normalMatrixFrom(const Mat4T<T>& worldFromModel);

// clipFromWorld = clipFromView(camera, width / height) * viewFromWorld(camera). Throws
// InputError for an unusable camera.
mat4 clipFromWorldFor(const Camera& camera, int width, int height);

// The uniforms for one draw item.
template <typename T>
VertexUniformsT<T> makeVertexUniforms(const Mat4T<T>& worldFromModel, const Mat4T<T>& clipFromWorld,
                                      const Scene& scene, const RenderSettings& settings);

// Runs the vertex stage on one vertex.
template <typename T>
ClipVertexT<T> runVertexStage(const Vertex& vertex, const VertexUniformsT<T>& uniforms);

}  // namespace twr

// The stage itself, over any lane type (plainly: twr::lanes).
#include "softrender/vertex_stage-inl.h"

namespace twr {

// The shared source's transforms for one vertex (vertex_stage-inl.h has the order of operations).
template <typename T>
Vec4T<T> transformPoint(const Mat4T<T>& m, Vec3T<T> p) {
  return lanes::transformPoint<T>(m, p);
}
template <typename T>
Vec3T<T> transformVector(const Mat3T<T>& m, Vec3T<T> v) {
  return lanes::transformVector<T>(m, v);
}
template <typename T>
T clipDistanceFrom(const Vec4T<T>& plane, const Vec3T<T>& p) {
  return lanes::clipDistanceFrom<T>(plane, p);
}

}  // namespace twr
