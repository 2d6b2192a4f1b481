#include "scene/height_field.h"

#include <algorithm>
#include <cmath>

namespace twr {

namespace {

// The two texels a bilinear tap reads along one axis and the weight of the second.
struct AxisTaps {
  int i0 = 0;
  int i1 = 0;
  double weight = 0.0;  // of i1, in [0, 1)
};

// GL_LINEAR along an axis of `size` texels (GL 3.3, 3.8.11): c' = c size - 0.5, i0 = floor(c'),
// i1 = i0 + 1, weight c' - i0, each index wrapped. Repeat takes the fraction of c first, so
// the indices stay small for any c; mirrored repeat folds c into [0, 1] (period 2, mirrored
// about every integer), after which it clamps like clamp_to_edge.
AxisTaps linearTaps(double c, int size, TextureWrap wrap) {
  if (!std::isfinite(c)) c = 0.0;
  if (wrap == TextureWrap::Repeat) {
    c -= std::floor(c);
  } else if (wrap == TextureWrap::MirroredRepeat) {
    const double half = 0.5 * c;
    c = std::fabs(2.0 * (half - std::nearbyint(half)));
  }
  const double texel = c * size - 0.5;  // texel centres at +0.5
  const double below = std::floor(texel);
  AxisTaps taps;
  taps.weight = texel - below;
  if (wrap == TextureWrap::Repeat) {
    // c in [0, 1]: `below` is in [-1, size - 1] (c rounds up to 1 only when just below 0,
    // where both ends read the same texels).
    taps.i0 = below < 0.0 ? size - 1 : static_cast<int>(below);
    taps.i1 = taps.i0 + 1 == size ? 0 : taps.i0 + 1;
  } else {
    const double last = static_cast<double>(size - 1);
    taps.i0 = static_cast<int>(std::clamp(below, 0.0, last));
    taps.i1 = static_cast<int>(std::clamp(below + 1.0, 0.0, last));
  }
  return taps;
}

}  // namespace

double heightAt(const Texture& heightMap, glm::dvec2 uv) {
  if (heightMap.width <= 0 || heightMap.height <= 0) return 0.0;
  const TextureOptions& options = heightMap.options;
  const glm::dvec2 lookup = uv * glm::dvec2(options.uvScale) + glm::dvec2(options.uvOffset);
  const AxisTaps u = linearTaps(lookup.x, heightMap.width, options.wrap);
  const AxisTaps v = linearTaps(lookup.y, heightMap.height, options.wrap);
  const auto value = [&](int x, int y) {
    const double red = heightMap.texel(x, y)[0] / 255.0;
    return options.srgb ? linearFromSrgb(red) : red;
  };
  // a + w (b - a): equal texels give exactly their value, so a flat map gives a flat surface.
  const auto lerp = [](double a, double b, double w) { return a + w * (b - a); };
  const double rowV0 = lerp(value(u.i0, v.i0), value(u.i1, v.i0), u.weight);
  const double rowV1 = lerp(value(u.i0, v.i1), value(u.i1, v.i1), u.weight);
  return lerp(rowV0, rowV1, v.weight);
}

}  // namespace twr
