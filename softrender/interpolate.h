// Stage 5, interpolation: per pixel, the screen-space barycentrics of the pixel centre, the
// window depth interpolated linearly in screen space, and every varying interpolated
// perspective-correctly with 1/w:
//   lambda_i  = screen-space barycentric of the pixel centre (px + 0.5, py + 0.5)
//   z_win     = sum lambda_i z_i                                  (linear in screen space)
//   p_i       = (lambda_i / w_i) / sum_k (lambda_k / w_k)          (perspective weights)
//   attribute = sum p_i a_i
// Barycentrics come from the unsnapped window positions (as llvmpipe's attribute setup),
// in double precision; the snapped positions stand in when those have no area.
#pragma once

#include "softrender/setup.h"
#include "softrender/vertex.h"

#include <array>

namespace twr {

// lambda_i(px, py) = atOrigin[i] + dx[i] * px + dy[i] * py (pixel indices; the centre offset
// is folded into atOrigin).
struct InterpolationSetup {
  std::array<double, 3> atOrigin{}, dx{}, dy{};
  std::array<float, 3> zWindow{};  // window depth of each corner
  std::array<float, 3> invW{};     // 1 / w_clip of each corner
};

// Corner i of `window` is vertex i of the triangle (before setup's reordering).
InterpolationSetup makeInterpolationSetup(const std::array<WindowVertex, 3>& window, const TriangleSetup& setup);

struct PixelWeights {
  std::array<float, 3> screen{};       // lambda_i, sum 1
  std::array<float, 3> perspective{};  // p_i, sum 1
  float depth = 0.0f;                  // window depth clamped to [0, 1] (GL clamps to the depth range)
};

PixelWeights pixelWeights(const InterpolationSetup& setup, int px, int py);

// The interpolated varyings a fragment is shaded from (names as in phong.frag).
struct Fragment {
  vec3 posWorld{0.0f};
  vec3 nWorld{0.0f};
  vec3 tWorld{0.0f};
  vec3 bWorld{0.0f};
  vec2 uv{0.0f};
  std::array<vec3, kMaxLights> lightDirTangent{};
  vec3 eyeDirTangent{0.0f};
  float depth = 0.0f;  // window depth
};

// Perspective-correct varyings at one pixel. Tangent-space light and eye directions are
// interpolated only for the first `tangentLightCount` lights (0 in world lighting space, and
// then eyeDirTangent is left zero too).
Fragment interpolateFragment(const ClipVertex& v0, const ClipVertex& v1, const ClipVertex& v2,
                             const PixelWeights& weights, bool tangentLighting, int tangentLightCount);

}  // namespace twr
