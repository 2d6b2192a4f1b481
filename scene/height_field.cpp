#include "scene/height_field.h"

#include "scene/errors.h"

#include <algorithm>
#include <cmath>
#include <string>

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

// Texel index i of an axis of `size` texels, one step past either end, through the wrap mode.
int wrappedIndex(int i, int size, TextureWrap wrap) {
  if (i >= 0 && i < size) return i;
  if (wrap == TextureWrap::Repeat) return ((i % size) + size) % size;
  if (wrap == TextureWrap::MirroredRepeat) return i < 0 ? std::min(-i - 1, size - 1) : std::max(2 * size - i - 1, 0);
  return std::clamp(i, 0, size - 1);
}

std::uint8_t byteFromUnit(double c) {
  return static_cast<std::uint8_t>(std::floor(std::clamp(c, 0.0, 1.0) * 255.0 + 0.5));
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

Texture normalMapFromHeight(const Texture& heightMap, double heightScale) {
  const int width = heightMap.width, height = heightMap.height;
  if (width <= 0 || height <= 0 ||
      heightMap.rgba.size() < 4 * static_cast<std::size_t>(width) * static_cast<std::size_t>(height)) {
    throw InputError("normal map from height: " + heightMap.path + " holds no texels");
  }
  if (!(heightScale >= 0.0) || !std::isfinite(heightScale)) {
    throw InputError("normal map from height: height_scale must be a finite number >= 0, got " +
                     std::to_string(heightScale));
  }
  const TextureOptions& options = heightMap.options;
  const auto value = [&](int x, int y) {
    const double red = heightMap.texel(wrappedIndex(x, width, options.wrap), wrappedIndex(y, height, options.wrap))[0] / 255.0;
    return options.srgb ? linearFromSrgb(red) : red;
  };
  Texture normal;
  normal.path = heightMap.path + " (normals at height_scale " + std::to_string(heightScale) + ")";
  normal.width = width;
  normal.height = height;
  normal.rgba.resize(4 * static_cast<std::size_t>(width) * static_cast<std::size_t>(height));
  normal.options.wrap = options.wrap;
  normal.options.uvScale = options.uvScale;
  normal.options.uvOffset = options.uvOffset;
  normal.formatName = "derived from a height map";
  // Central differences over two texels: 2 / width in u, 2 / height in v (rows bottom first,
  // so row y + 1 is higher v).
  const double uvAcrossU = 2.0 / width, uvAcrossV = 2.0 / height;
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      const double dhDu = (value(x + 1, y) - value(x - 1, y)) / uvAcrossU;
      const double dhDv = (value(x, y + 1) - value(x, y - 1)) / uvAcrossV;
      const double nx = -heightScale * dhDu, ny = -heightScale * dhDv;
      const double length = std::sqrt(nx * nx + ny * ny + 1.0);  // >= 1: never zero
      std::uint8_t* texel = &normal.rgba[4 * (static_cast<std::size_t>(y) * width + x)];
      texel[0] = byteFromUnit(0.5 * (nx / length + 1.0));
      texel[1] = byteFromUnit(0.5 * (ny / length + 1.0));
      texel[2] = byteFromUnit(0.5 * (1.0 / length + 1.0));
      texel[3] = 255;
    }
  }
  buildMipChain(normal);
  return normal;
}

}  // namespace twr
