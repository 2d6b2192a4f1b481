// Stage 5, interpolation: per pixel, the screen-space barycentrics of the pixel centre, the
// window depth interpolated linearly in screen space, and every varying interpolated
// perspective-correctly with 1/w:
//   lambda_i  = screen-space barycentric of the pixel centre (px + 0.5, py + 0.5)
//   z_win     = the window z plane, set up and evaluated like uv's below (llvmpipe interpolates
//               position.z so), then stored as llvmpipe's 24-bit depth buffer holds it
//   p_i       = (lambda_i / w_i) / sum_k (lambda_k / w_k)          (perspective weights)
//   attribute = sum p_i a_i
// Barycentrics come from the unsnapped window positions (as llvmpipe's attribute setup),
// in double precision; the snapped positions stand in when those have no area.
//
// The texture coordinate is the one varying interpolated exactly as llvmpipe does it,
// because a nearest-filtered texel flips on one ULP of uv (docs/textures.md, "Which texel"):
// u/w, v/w and 1/w are each a plane set up in float from the float window positions, in the
// corner order setup uses (a counter-clockwise triangle has its first two corners swapped):
//   da01 = a0 - a1, da20 = a2 - a0, 1/area = 1 / (dx01 dy20 - dy01 dx20)
//   dadx = da01 (dy20 / area) - da20 (dy01 / area),  dady = da20 (dx01 / area) - da01 (dx20 / area)
//   a(px, py) = fma(dady, py, fma(dadx, px, A0)),     A0 = a0 - (dadx (x0 - 0.5) + dady (y0 - 0.5))
//   uv = (u/w, v/w) * (1 / (1/w))                      (a product with the reciprocal, not a quotient)
// with one rounding per operation and the two fused multiply-adds llvmpipe's JIT code emits on
// a CPU with FMA (every x86-64 CPU since 2013, every AArch64 one).
//
// The per-pixel part (weights and varyings) is written once over the lane type in
// interpolate-inl.h; the functions below are its scalar entry points, templated on T (float:
// the pipeline, double: the reference).
#pragma once

#include "softrender/setup.h"
#include "softrender/vertex.h"

#include <array>

namespace twr {

// One attribute as a plane over pixel indices: a(px, py) = fma(dy, py, fma(dx, px, atOrigin))
// (the pixel-centre offset folded into atOrigin).
template <typename T>
struct AttributePlaneT {
  T atOrigin = T(0), dx = T(0), dy = T(0);
};
// The texture coordinate's three planes (see above).
template <typename T>
struct UvPlanesT {
  AttributePlaneT<T> uOverW, vOverW, oneOverW;
};

// lambda_i(px, py) = atOrigin[i] + dx[i] * px + dy[i] * py (pixel indices; the centre offset
// is folded into atOrigin).
template <typename T>
struct InterpolationSetupT {
  std::array<double, 3> atOrigin{}, dx{}, dy{};
  std::array<T, 3> zWindow{};  // window depth of each corner
  std::array<T, 3> invW{};     // 1 / w_clip of each corner
  UvPlanesT<T> uv;             // the texture coordinate, as llvmpipe interpolates it
  // Window depth as llvmpipe interpolates it: its position.z plane, set up like uv's (no 1/w),
  // left non-finite where the float corners are collinear (llvmpipe's fragments then fail the
  // depth test; storedDepthLanes).
  AttributePlaneT<T> depth;
};
using InterpolationSetup = InterpolationSetupT<float>;

// Corner i of `window` and of `uv` is vertex i of the triangle (before setup's reordering).
template <typename T = float>
InterpolationSetupT<T> makeInterpolationSetup(const std::array<WindowVertexT<T>, 3>& window,
                                              const std::array<Vec2T<T>, 3>& uv, const TriangleSetup& setup);

// The uv planes alone (part of makeInterpolationSetup). Where the float corners are collinear
// (setup accepted their snapped positions) the planes would divide by zero; they then hold the
// first corner's uv everywhere.
template <typename T>
UvPlanesT<T> makeUvPlanes(const std::array<WindowVertexT<T>, 3>& window, const std::array<Vec2T<T>, 3>& uv,
                          const TriangleSetup& setup);

template <typename T>
struct PixelWeightsT {
  std::array<T, 3> screen{};       // lambda_i, sum 1
  std::array<T, 3> perspective{};  // p_i, sum 1
  T depth = T(0);                  // the depth the test compares and stores (storedDepthLanes)
  Vec2T<T> uv{T(0)};               // the texture coordinate, from the uv planes
};
using PixelWeights = PixelWeightsT<float>;


// The interpolated varyings a fragment is shaded from (names as in phong.frag).
template <typename T>
struct FragmentT {
  Vec3T<T> posWorld{T(0)};
  Vec3T<T> nWorld{T(0)};
  Vec3T<T> tWorld{T(0)};
  Vec3T<T> bWorld{T(0)};
  Vec2T<T> uv{T(0)};
  // The 2x2 quad's uv differences, top-left pixel to its right and upper neighbours (helper
  // pixels included, as a GPU takes them): set for mipmapped filters only, else 0.
  Vec2T<T> uvDx{T(0)}, uvDy{T(0)};
  Vec2T<T> uvDxFine{T(0)}, uvDyFine{T(0)};  // GLSL's dFdx / dFdy (fine, per row and column)
  std::array<Vec3T<T>, kMaxLights> lightDirTangent{};
  Vec3T<T> eyeDirTangent{T(0)};
  T depth = T(0);  // window depth
};
using Fragment = FragmentT<float>;

}  // namespace twr

#include "softrender/interpolate-inl.h"

namespace twr {

template <typename T>
PixelWeightsT<T> pixelWeights(const InterpolationSetupT<T>& setup, int px, int py) {
  return pixelWeightsLanes<T>(setup, static_cast<double>(px), static_cast<double>(py));
}

// Perspective-correct varyings at one pixel. Tangent-space light and eye directions are
// interpolated only for the first `tangentLightCount` lights (0 in world lighting space, and
// then eyeDirTangent is left zero too).
template <typename T>
FragmentT<T> interpolateFragment(const ClipVertexT<T>& v0, const ClipVertexT<T>& v1, const ClipVertexT<T>& v2,
                                 const PixelWeightsT<T>& weights, bool tangentLighting, int tangentLightCount) {
  return interpolateFragmentLanes<T>(v0, v1, v2, weights, tangentLighting, tangentLightCount);
}

}  // namespace twr
