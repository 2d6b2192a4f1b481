// Stage 2, clip: Sutherland-Hodgman in homogeneous clip space, before the divide by w.
//
// Planes, in the order they are applied (bit i of a plane mask is plane i):
//   0 left   w + x >= 0      1 right  w - x >= 0
//   2 bottom w + y >= 0      3 top    w - y >= 0
//   4 near   w + z >= 0      5 far    w - z >= 0
//   6 w >= kMinClipW (never divide by w <= 0; only ever cuts when near is off)
//   7.. user planes: clipDistance[j] >= 0 (world space, as gl_ClipDistance)
// A switched-off left/right/bottom/top plane is replaced by its guard-band plane
// (g w -/+ x >= 0, g = ClipConfig::guardBandX or Y), so window x and y stay bounded.
// A switched-off near or far plane is dropped (GL depth clamp); setup clamps depth to [0, 1].
// A vertex exactly on a plane (distance 0) is inside.
#pragma once

#include "softrender/vertex.h"

#include <array>
#include <cstdint>

namespace twr {

inline constexpr int kClipPlaneLeft = 0;
inline constexpr int kClipPlaneRight = 1;
inline constexpr int kClipPlaneBottom = 2;
inline constexpr int kClipPlaneTop = 3;
inline constexpr int kClipPlaneNear = 4;
inline constexpr int kClipPlaneFar = 5;
inline constexpr int kClipPlaneMinW = 6;
inline constexpr int kClipPlaneUser0 = 7;
inline constexpr int kClipPlaneCount = kClipPlaneUser0 + kMaxUserClipPlanes;  // 15

// Smallest w the clipper lets through (clip-space units, world units for a perspective
// camera); far below any sensible near plane, so it only cuts when near is off.
inline constexpr float kMinClipW = 1e-5f;

// Each plane cuts a convex polygon into a convex polygon with at most one more vertex, so a
// triangle leaves the clipper with at most 3 + 6 (frustum or guard band) + 1 (w) +
// kMaxUserClipPlanes (8) = 18 vertices (inclusive bound).
inline constexpr int kMaxClipVertices = 3 + kClipPlaneCount;

struct ClipConfig {
  ClipSwitches frustum;     // which of the six frustum planes are on
  float guardBandX = 1.0f;  // |x| <= guardBandX * w when left/right is off (NDC units, >= 1)
  float guardBandY = 1.0f;  // |y| <= guardBandY * w when bottom/top is off
  int userPlaneCount = 0;   // clipDistance[0, userPlaneCount) are tested
};

// Guard band in pixels beyond each side of the viewport when a side plane is switched off.
// Bounds window coordinates to [-kGuardBandPixels, size + kGuardBandPixels].
inline constexpr float kGuardBandPixels = 16384.0f;

ClipConfig makeClipConfig(const ClipSwitches& frustum, int userPlaneCount, int viewportWidth, int viewportHeight);

// A convex polygon in clip space; vertex i is v[i] for i in [0, count).
struct ClipPolygon {
  std::array<ClipVertex, kMaxClipVertices> v;
  int count = 0;
};

// Signed distance of a vertex from plane `plane` (inside when >= 0).
float clipDistanceTo(const ClipVertex& vertex, int plane, const ClipConfig& config);

// Bit `plane` set for each active plane the vertex is outside of.
std::uint32_t outcode(const ClipVertex& vertex, const ClipConfig& config);

// The point where edge (outside, inside) crosses a plane: outside + t (inside - outside) with
// t = dOutside / (dOutside - dInside), every varying interpolated with the same t. Always
// interpolated from the outside vertex, so an edge shared by two triangles gets the same
// new vertex whichever way round the triangles walk it (no cracks).
ClipVertex interpolateClipVertex(const ClipVertex& outside, const ClipVertex& inside, float t);

// Set in a returned plane mask when a vertex had a non-finite clip position (removed).
inline constexpr std::uint32_t kClipNonFiniteBit = 1u << 31;

// Clips triangle (a, b, c) into `out` (count 0 when nothing is left; otherwise the vertices
// keep the triangle's winding). Returns the mask of planes that cut or removed it (0 when
// the triangle was entirely inside). `scratch` is working space of the same size.
std::uint32_t clipTriangle(const ClipVertex& a, const ClipVertex& b, const ClipVertex& c, const ClipConfig& config,
                           ClipPolygon& out, ClipPolygon& scratch);

// Clips segment (a, b) in place; returns false when nothing is left. `planesCut` gets the
// mask of planes that cut it.
bool clipSegment(ClipVertex& a, ClipVertex& b, const ClipConfig& config, std::uint32_t& planesCut);

// Name of a plane for traces ("left", "near", "w>=eps", "user0", ...).
const char* clipPlaneName(int plane);

}  // namespace twr
