// Stage 5, interpolation: per pixel, the screen-space barycentrics of the pixel centre, the
// window depth interpolated linearly in screen space, and every varying interpolated
// perspective-correctly with 1/w:
//   lambda_i  = screen-space barycentric of the pixel centre (px + 0.5, py + 0.5)
//   z_win     = sum lambda_i z_i                                  (linear in screen space)
//   p_i       = (lambda_i / w_i) / sum_k (lambda_k / w_k)          (perspective weights)
//   attribute = sum p_i a_i
// Barycentrics come from the unsnapped window positions (as llvmpipe's attribute setup),
// in double precision; the snapped positions stand in when those have no area.
//
// The per-pixel part (weights and varyings) is written once over the lane type in
// interpolate-inl.h; the functions below are its scalar entry points, templated on T (float:
// the pipeline, double: the reference).
#pragma once

#include "softrender/setup.h"
#include "softrender/vertex.h"

#include <array>

namespace twr {

// lambda_i(px, py) = atOrigin[i] + dx[i] * px + dy[i] * py (pixel indices; the centre offset
// is folded into atOrigin).
template <typename T>
struct InterpolationSetupT {
  std::array<double, 3> atOrigin{}, dx{}, dy{};
  std::array<T, 3> zWindow{};  // window depth of each corner
  std::array<T, 3> invW{};     // 1 / w_clip of each corner
};
using InterpolationSetup = InterpolationSetupT<float>;

// Corner i of `window` is vertex i of the triangle (before setup's reordering).
template <typename T = float>
InterpolationSetupT<T> makeInterpolationSetup(const std::array<WindowVertexT<T>, 3>& window,
                                              const TriangleSetup& setup);

template <typename T>
struct PixelWeightsT {
  std::array<T, 3> screen{};       // lambda_i, sum 1
  std::array<T, 3> perspective{};  // p_i, sum 1
  T depth = T(0);                  // window depth clamped to [0, 1] (GL clamps to the depth range)
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
