// Stage 1, vertex, over any lane type: the one C++ source of shaders/phong.vert's main (vertex.h
// has the uniforms and the ClipVertex the teaching path keeps). Instantiated for float (the
// teaching path, one vertex at a time), double (the reference) and Highway vectors (the fast
// path, one vertex per lane); the same operations in the same order in every instantiation.
// Shared source, included plainly and per Highway target (softrender/lanes.h).

#if defined(TWR_LANES_HIGHWAY)
#if defined(TWR_VERTEX_STAGE_INL_TARGET) == defined(HWY_TARGET_TOGGLE)
#ifdef TWR_VERTEX_STAGE_INL_TARGET
#undef TWR_VERTEX_STAGE_INL_TARGET
#else
#define TWR_VERTEX_STAGE_INL_TARGET
#endif
#define TWR_VERTEX_STAGE_INL_EMIT
#endif
#elif !defined(TWR_VERTEX_STAGE_INL_PLAIN)
#define TWR_VERTEX_STAGE_INL_PLAIN
#define TWR_VERTEX_STAGE_INL_EMIT
#endif

#ifdef TWR_VERTEX_STAGE_INL_EMIT
#undef TWR_VERTEX_STAGE_INL_EMIT

#include "softrender/lane_math-inl.h"
#include "softrender/lanes.h"
#include "softrender/vertex.h"

#include <array>
#include <cstddef>

TWR_LANES_BEGIN

// m * vec4(p, 1) summed column by column from the left, ((c0 x + c1 y) + c2 z) + c3, the
// order a GLSL compiler evaluates mat4 * vec4 in, so both renderers round alike.
template <typename L>
TWR_LANE_INLINE Vec4L<L> transformPoint(const Mat4T<ScalarOf<L>>& m, const Vec3L<L>& p) {
  const auto row = [&](int r) {
    return ((L(m[0][r]) * p.x + L(m[1][r]) * p.y) + L(m[2][r]) * p.z) + L(m[3][r]);
  };
  return Vec4L<L>(row(0), row(1), row(2), row(3));
}
// m * v, columns summed from the left like transformPoint.
template <typename L>
TWR_LANE_INLINE Vec3L<L> transformVector(const Mat3T<ScalarOf<L>>& m, const Vec3L<L>& v) {
  const auto row = [&](int r) { return (L(m[0][r]) * v.x + L(m[1][r]) * v.y) + L(m[2][r]) * v.z; };
  return Vec3L<L>(row(0), row(1), row(2));
}
// glm::cross, component by component in its order.
template <typename L>
TWR_LANE_INLINE Vec3L<L> crossOf(const Vec3L<L>& a, const Vec3L<L>& b) {
  return Vec3L<L>(a.y * b.z - b.y * a.z, a.z * b.x - b.z * a.x, a.x * b.y - b.x * a.y);
}
// gl_ClipDistance = dot(plane, vec4(p, 1)) summed in the order llvmpipe's compiled shader
// sums it: from the last component, ((c z + d) + b y) + a x (a probe of 4,096 random planes
// and points matched this order bit for bit, and no other; glm::dot's pairwise sum missed a
// third). Geometry lying on a plane has distances of a few ULPs either side of 0, so the
// order decides which vertices are inside.
template <typename L>
TWR_LANE_INLINE L clipDistanceFrom(const Vec4T<ScalarOf<L>>& plane, const Vec3L<L>& p) {
  return ((L(plane.z) * p.z + L(plane.w)) + L(plane.y) * p.y) + L(plane.x) * p.x;
}
// The vector (x, y, z) - w p of a light (lightVectorWorld's (position, 1) or (direction, 0))
// from p, multiplied first as glm's vec3 - float * vec3.
template <typename L>
TWR_LANE_INLINE Vec3L<L> minusScaled(const Vec4T<ScalarOf<L>>& light, const Vec3L<L>& p) {
  const L w(light.w);
  return Vec3L<L>(L(light.x) - w * p.x, L(light.y) - w * p.y, L(light.z) - w * p.z);
}

// One mesh vertex as the vertex stage reads it (scene/mesh.h's Vertex).
template <typename L>
struct VertexInL {
  Vec3L<L> posModel, nModel;
  Vec4L<L> tangentModel;
  Vec2L<L> uv;
};
// What the vertex stage writes (ClipVertex without the clipper's mark).
template <typename L>
struct VertexOutL {
  Vec4L<L> posClip;
  Vec3L<L> posWorld, nWorld, tWorld, bWorld;
  Vec2L<L> uv;
  std::array<Vec3L<L>, kMaxLights> lightDirTangent;  // tangent lighting space only
  Vec3L<L> eyeDirTangent;                            // tangent lighting space only
  std::array<L, kMaxUserClipPlanes> clipDistance;    // the first u.userClipPlaneCount
};

// phong.vert's main: world and clip positions, the world frame (B rebuilt from N, T and the
// handedness sign), the uv, in tangent lighting space the light and eye directions in the
// vertex's tangent frame (left unnormalised, the tutorial's linear interpolation), and the
// user clip distances.
template <typename L>
TWR_LANE_INLINE VertexOutL<L> vertexStage(const VertexInL<L>& in, const VertexUniformsT<ScalarOf<L>>& u) {
  VertexOutL<L> out;
  const Vec4L<L> world = transformPoint<L>(u.worldFromModel, in.posModel);
  out.posWorld = Vec3L<L>(world.x, world.y, world.z);
  out.nWorld = transformVector<L>(u.normalFromModel, in.nModel);
  out.tWorld = transformVector<L>(u.tangentFromModel, Vec3L<L>(in.tangentModel.x, in.tangentModel.y, in.tangentModel.z));
  // A mirroring transform reverses the handedness of the (T, B, N) frame, so the sign that
  // rebuilds B from N and T flips with it.
  const L sign = in.tangentModel.w * L(u.mirrorSign);
  out.posClip = transformPoint<L>(u.clipFromWorld, out.posWorld);
  out.bWorld = sign * crossOf<L>(out.nWorld, out.tWorld);
  out.uv = in.uv;
  if (u.tangentLighting) {
    const Vec3L<L> t = safeNormalize<L>(out.tWorld);
    const Vec3L<L> b = safeNormalize<L>(out.bWorld);
    const Vec3L<L> n = safeNormalize<L>(out.nWorld);
    for (int i = 0; i < u.lightCount; ++i) {
      const Vec3L<L> lw = minusScaled<L>(u.lightVectorWorld[static_cast<std::size_t>(i)], out.posWorld);
      out.lightDirTangent[static_cast<std::size_t>(i)] = Vec3L<L>(dot3<L>(t, lw), dot3<L>(b, lw), dot3<L>(n, lw));
    }
    const Vec3L<L> ew = Vec3L<L>(L(u.eyePosWorld.x), L(u.eyePosWorld.y), L(u.eyePosWorld.z)) - out.posWorld;
    out.eyeDirTangent = Vec3L<L>(dot3<L>(t, ew), dot3<L>(b, ew), dot3<L>(n, ew));
  }
  for (int j = 0; j < u.userClipPlaneCount; ++j) {
    out.clipDistance[static_cast<std::size_t>(j)] =
        clipDistanceFrom<L>(u.userClipPlanes[static_cast<std::size_t>(j)], out.posWorld);
  }
  return out;
}

TWR_LANES_END

#endif  // TWR_VERTEX_STAGE_INL_EMIT
