// Stage 3, setup: divide by w, viewport transform, snap to the sub-pixel grid, face culling,
// and the three integer edge functions the rasterizer evaluates. Mirrors llvmpipe
// (lp_setup_tri.c) so that coverage matches GL on llvmpipe pixel for pixel:
//
//   x_ndc = x_clip * (1 / w_clip)                 (the reciprocal first, as llvmpipe)
//   x_win = x_ndc * (W / 2) + W / 2,  y_win = y_ndc * (H / 2) + H / 2   (GL: origin bottom-left;
//       one fused multiply-add for vertex-stage vertices, a rounded multiply then an add for
//       clipper-made ones, exactly as llvmpipe computes each kind)
//   z_win = 0.5 z_ndc + 0.5
//   X = rint((x_win - 0.5) * 256),    Y = rint((y_win - 0.5) * 256)     (24.8 fixed point,
//       round half to even; subtracting the pixel-centre offset first puts pixel (px, py)'s
//       centre at the integer point (256 px, 256 py))
//
// Edge i runs from corner i to corner j = i + 1 (mod 3) of a triangle ordered clockwise in
// window coordinates (setup swaps corners 0 and 1 of a counter-clockwise one):
//   E_i(px, py) = (Y_i - Y_j)(X_i - 256 px) - (X_i - X_j)(Y_i - 256 py) + bias_i
// and pixel (px, py) is covered when E_i > 0 for all three edges. bias_i = 1 for a left edge
// (Y_i < Y_j) and for a bottom edge (Y_i == Y_j, X_i > X_j), else 0: a pixel centre exactly on
// an edge belongs to the triangle on its right or above, so a shared edge is covered exactly
// once (GL's rule on llvmpipe for a bottom-left-origin window).
//
// Integer ranges: window coordinates are clamped to +-kMaxWindowCoord = 2^16 px (the guard
// band keeps real ones within [-2^14, 2^15]), so |X|, |Y| <= 2^24, edge deltas < 2^25, the
// constant term < 2^51 and E for any pixel of a 2^14 x 2^14 image < 2^52: int64 never overflows.
//
// The window transform is templated on the scalar T (float: the pipeline, double: the
// reference); snapping makes everything after it integer, the same for both.
#pragma once

#include "scene/conventions.h"
#include "scene/settings.h"
#include "softrender/vertex.h"

#include <array>
#include <cstdint>

namespace twr {

struct Viewport {
  int width = 0;   // pixels
  int height = 0;  // pixels
};

// A vertex after the divide by w and the viewport transform.
template <typename T>
struct WindowVertexT {
  T x = T(0), y = T(0);  // pixels, GL window coordinates (origin bottom-left)
  T z = T(0);            // window depth 0.5 z_ndc + 0.5 (not yet clamped)
  T invW = T(0);         // 1 / w_clip, for perspective-correct interpolation
};
using WindowVertex = WindowVertexT<float>;

// Largest |window coordinate| setup snaps (pixels, inclusive); see the range note above.
inline constexpr float kMaxWindowCoord = 65536.0f;

// Pixel centres sit at +0.5 (pixels); removing it before snapping puts them on integer
// multiples of 256.
inline constexpr double kPixelCentreOffset = 0.5;

// Largest |z / w| (inclusive, NDC units) windowFromClip passes on; beyond it z / w is clamped.
// Only depth-clamped geometry within about 1e-30 of w = 0 gets there (float overflows at 3.4e38).
inline constexpr float kMaxNdcDepth = 1e30f;

// Requires w_clip > 0 (the clipper guarantees w >= kMinClipW). `fusedMultiplyAdd`: see above
// (true for vertices straight from the vertex stage).
template <typename T>
WindowVertexT<T> windowFromClip(const Vec4T<T>& posClip, const Viewport& viewport, bool fusedMultiplyAdd);
template <typename T>
WindowVertexT<T> windowFromClip(const ClipVertexT<T>& vertex, const Viewport& viewport) {
  return windowFromClip(vertex.posClip, viewport, !vertex.fromClipper);
}

// Window coordinate to 24.8 fixed point, pixel-centre offset removed (clamped to the range).
template <typename T>
std::int32_t snapToSubpixel(T windowCoord);

// E(px, py) = c + stepX * px + stepY * py; the pixel is covered when E > 0 for all edges.
struct EdgeFunction {
  std::int64_t c = 0;
  std::int64_t stepX = 0;  // -(Y_i - Y_j) * 256
  std::int64_t stepY = 0;  //  (X_i - X_j) * 256
  bool ownsPixelsOnIt = false;  // left or bottom edge (bias 1)

  std::int64_t at(int px, int py) const { return c + stepX * px + stepY * py; }
};

enum class SetupResult { Ready, ZeroArea, CulledBack, CulledFront };

struct TriangleSetup {
  std::array<std::int32_t, 3> xFixed{}, yFixed{};  // 1/256 px, pixel-centre offset removed
  std::array<int, 3> corner{0, 1, 2};              // input vertex of each corner (0/1 may swap)
  std::array<EdgeFunction, 3> edges;
  std::int64_t doubleAreaFixed = 0;  // twice the snapped area, 1/65536 px^2, > 0 once ordered
  bool frontFacing = true;
  // Pixels that may be covered (inclusive), clipped to the viewport; empty when x0 > x1.
  int x0 = 0, x1 = -1, y0 = 0, y1 = -1;
};

// Snaps, orders clockwise, culls and builds the edge functions. Front faces are those
// counter-clockwise (FrontFace::Ccw) or clockwise (Cw) in GL window coordinates, decided on
// the snapped positions like llvmpipe; zero snapped area is always rejected. A rejected
// triangle's `out` holds its corners, frontFacing and an empty box; its edges are not built.
template <typename T = float>
SetupResult setupTriangle(const std::array<WindowVertexT<T>, 3>& window, CullMode cull, FrontFace frontFace,
                          const Viewport& viewport, TriangleSetup& out);

// setupTriangle after the snapping: corners already in 24.8 fixed point (snapToSubpixel of
// each window x and y, in triangle order). The fast path snaps each vertex once and calls it.
SetupResult setupSnappedTriangle(const std::array<std::int32_t, 3>& xFixed, const std::array<std::int32_t, 3>& yFixed,
                                 CullMode cull, FrontFace frontFace, const Viewport& viewport, TriangleSetup& out);
// The same with each corner's coordinates as a value (xa, ya the first corner's): the front
// end's loop passes them in registers, since arrays it had just stored one by one would be
// read back in wider loads that wait for the stores (store forwarding fails), a million
// times a frame.
SetupResult setupSnappedCorners(std::int32_t xa, std::int32_t ya, std::int32_t xb, std::int32_t yb, std::int32_t xc,
                                std::int32_t yc, CullMode cull, FrontFace frontFace, const Viewport& viewport,
                                TriangleSetup& out);

// Pixels (inclusive), like TriangleSetup's box; empty when x0 > x1 or y0 > y1.
struct PixelBox {
  int x0 = 0, x1 = -1, y0 = 0, y1 = -1;
  bool empty() const { return x0 > x1 || y0 > y1; }
};

// The pixels of an accepted triangle's box whose centres lie within its snapped corners' extent
// (a covered centre lies in the closed triangle, so in that extent): the only ones it can
// cover. Tighter than the box, which holds every pixel the extent touches; empty for a small
// triangle that falls between pixel centres, which covers nothing.
PixelBox pixelCentreBox(const TriangleSetup& setup);

const char* toString(SetupResult result);

}  // namespace twr
