// Stage 2, clip: Sutherland-Hodgman in homogeneous clip space, before the divide by w.
//
// Planes, in the order they are applied (bit i of a plane mask is plane i; the order and the
// arithmetic follow Mesa's draw module, so clipped triangles snap to the same positions as
// on llvmpipe):
//   0 right  w - x >= 0      1 left   w + x >= 0
//   2 top    w - y >= 0      3 bottom w + y >= 0
//   4 near   w + z >= 0      5 far    w - z >= 0
//   6..13 user planes: clipDistance[j] >= 0 (world space, as gl_ClipDistance)
//   14 w >= kMinClipW (only when near is off: never divide by w <= 0)
// A switched-off right/left/top/bottom plane is replaced by its guard-band plane
// (g w -/+ x >= 0, g = ClipConfig::guardBandX or Y), so window x and y stay bounded.
// A switched-off near or far plane is dropped (GL depth clamp); setup clamps depth to [0, 1].
// A vertex exactly on a plane (distance 0) is inside.
//
// Templated on the scalar T like the vertex stage (float: the pipeline, double: the reference).
#pragma once

#include "softrender/vertex.h"

#include <array>
#include <cstdint>
#include <type_traits>

namespace twr {

inline constexpr int kClipPlaneRight = 0;
inline constexpr int kClipPlaneLeft = 1;
inline constexpr int kClipPlaneTop = 2;
inline constexpr int kClipPlaneBottom = 3;
inline constexpr int kClipPlaneNear = 4;
inline constexpr int kClipPlaneFar = 5;
inline constexpr int kClipPlaneUser0 = 6;
inline constexpr int kClipPlaneMinW = kClipPlaneUser0 + kMaxUserClipPlanes;  // 14
inline constexpr int kClipPlaneCount = kClipPlaneMinW + 1;                   // 15

// Smallest w the clipper lets through when the near plane is off (clip-space units, world
// units for a perspective camera).
inline constexpr float kMinClipW = 1e-5f;

// Each plane cuts a convex polygon into a convex polygon with at most one more vertex, so a
// triangle leaves the clipper with at most 3 + 6 (frustum or guard band) +
// kMaxUserClipPlanes (8) + 1 (w) = 18 vertices (inclusive bound).
inline constexpr int kMaxClipVertices = 3 + kClipPlaneCount;

struct ClipConfig {
  ClipSwitches frustum;     // which of the six frustum planes are on
  float guardBandX = 1.0f;  // |x| <= guardBandX * w when left/right is off (NDC units, >= 1)
  float guardBandY = 1.0f;  // |y| <= guardBandY * w when bottom/top is off
  int userPlaneCount = 0;   // clipDistance[0, userPlaneCount) are tested
  // Affine: a cut vertex takes its varyings at the edge's screen-space parameter
  // (screenLinearT), so they stay linear on the screen across the whole original triangle, as
  // GLSL's noperspective requires; the position and clip distances always use clip space's t.
  Interpolation varyings = Interpolation::Perspective;
};

// Guard band in pixels beyond each side of the viewport when a side plane is switched off.
// Bounds window coordinates to [-kGuardBandPixels, size + kGuardBandPixels].
inline constexpr float kGuardBandPixels = 16384.0f;

ClipConfig makeClipConfig(const ClipSwitches& frustum, int userPlaneCount, int viewportWidth, int viewportHeight,
                          Interpolation varyings = Interpolation::Perspective);

// A convex polygon in clip space; vertex i is v[i] for i in [0, count).
template <typename T>
struct ClipPolygonT {
  std::array<ClipVertexT<T>, kMaxClipVertices> v;
  int count = 0;
};
using ClipPolygon = ClipPolygonT<float>;

// The polygon's vertices forming fan triangle k (k = 0 .. count - 3), in the corner order Mesa's
// clipper hands them to llvmpipe's setup (draw_pipe_clip.c, GL's last-vertex provoking
// convention): (v[k + 1], v[k + 2], v[0]) for a polygon the clipper made; an unclipped triangle
// stays (v[0], v[1], v[2]). Coverage does not depend on the rotation, but llvmpipe builds its
// attribute planes from the first corner, so the uv roundings do (interpolate.h).
inline std::array<int, 3> fanTriangleCorners(int k, bool clipped) {
  return clipped ? std::array<int, 3>{k + 1, k + 2, 0} : std::array<int, 3>{0, 1, 2};
}

// Signed distance of a vertex from plane `plane` (inside when >= 0).
template <typename T>
T clipDistanceTo(const ClipVertexT<T>& vertex, int plane, const ClipConfig& config);

// Bit `plane` set for each active plane the vertex is outside of; kClipNonFiniteBit alone when
// !clipVertexUsable (no distance of such a vertex is meaningful).
template <typename T>
std::uint32_t outcode(const ClipVertexT<T>& vertex, const ClipConfig& config);

// from + t (to - from) for the position and every varying (the new vertex is marked
// fromClipper). The clipper calls it with `from` the edge endpoint nearer to the plane and
// t = dFrom / (dFrom - dTo), as Mesa's draw clipper does, so an edge shared by two triangles
// gets the same new vertex whichever way round the triangles walk it (no cracks), and the
// snapped positions equal llvmpipe's.
template <typename T>
ClipVertexT<T> interpolateClipVertex(const ClipVertexT<T>& from, const ClipVertexT<T>& to, std::type_identity_t<T> t);
// The same with the varyings (not the position or the clip distances) taken at tVaryings.
template <typename T>
ClipVertexT<T> interpolateClipVertex(const ClipVertexT<T>& from, const ClipVertexT<T>& to, std::type_identity_t<T> t,
                                     std::type_identity_t<T> tVaryings);

// Where the cut point `cut` (from + t (to - from) in clip space) lies along the edge on the
// screen: (cut - from) / (to - from) in NDC x, or in y where the edge's clip x are equal, each
// coordinate divided by its w; t itself where both are equal (the edge is a point on the
// screen, so its varyings cannot matter). Mesa's draw clipper takes noperspective varyings at it.
template <typename T>
T screenLinearT(const Vec4T<T>& from, const Vec4T<T>& to, const Vec4T<T>& cut, std::type_identity_t<T> t);

// Largest magnitude (inclusive) of a clip-space coordinate or user clip distance the clipper
// accepts, clip-space units. Beyond it the guard-band distance (g w, g up to 32769) or the
// difference of two endpoints could overflow float and the cut vertex would come out infinite;
// a perspective camera with a far plane under 1e20 world units never gets near it.
inline constexpr float kMaxClipCoordinate = 1e30f;

// Set in a returned plane mask (and by outcode) when a vertex had a non-finite clip position,
// or a coordinate or active clip distance beyond kMaxClipCoordinate, or when a vertex the
// clipper made ended at w <= 0 (the polygon reaches the eye): the triangle is removed.
inline constexpr std::uint32_t kClipNonFiniteBit = 1u << 31;

// False when the clipper must remove a primitive with this vertex (see kClipNonFiniteBit).
template <typename T>
bool clipVertexUsable(const ClipVertexT<T>& vertex, const ClipConfig& config);

// Clips triangle (a, b, c) into `out` (count 0 when nothing is left; otherwise the vertices
// keep the triangle's winding). Returns the mask of planes that cut or removed it (0 when
// the triangle was entirely inside). `scratch` is working space of the same size.
template <typename T>
std::uint32_t clipTriangle(const ClipVertexT<T>& a, const ClipVertexT<T>& b, const ClipVertexT<T>& c,
                           const ClipConfig& config, ClipPolygonT<T>& out, ClipPolygonT<T>& scratch);

// Clips segment (a, b) in place (Mesa's line clipper: the largest cut from each end); returns false when nothing is left. `planesCut` gets the
// mask of planes that cut it.
template <typename T>
bool clipSegment(ClipVertexT<T>& a, ClipVertexT<T>& b, const ClipConfig& config, std::uint32_t& planesCut);

// Name of a plane for traces ("left", "near", "w>=eps", "user0", ...).
const char* clipPlaneName(int plane);

}  // namespace twr
