#include "softrender/texture_sample.h"

#include <cmath>

namespace twr {

namespace {

constexpr float kTexelCentre = 0.5f;     // texel centres at +0.5
constexpr float kByteToUnit = 1.0f / 255.0f;

// floor(s) reduced modulo `size`, exact in double for any finite float s (|s| < 2^128 fits a
// double's exponent; fmod is exact).
int wrappedFloor(double s, int size) {
  if (!std::isfinite(s) || size <= 0) return 0;
  double wrapped = std::fmod(std::floor(s), static_cast<double>(size));
  if (wrapped < 0.0) wrapped += size;
  const int i = static_cast<int>(wrapped);
  return i >= size ? 0 : i;
}

}  // namespace

int nearestTexelIndex(float coord, int size) {
  // The product is rounded to float as GL computes it, then floored and wrapped exactly.
  return wrappedFloor(static_cast<double>(coord * static_cast<float>(size)), size);
}

vec4 texelAt(const Texture& texture, int x, int y) {
  const std::uint8_t* t = texture.texel(x, y);
  return vec4(t[0], t[1], t[2], t[3]) * kByteToUnit;
}

SampleFootprint sampleFootprint(const Texture& texture, vec2 uv, TextureFilter filter) {
  SampleFootprint f;
  if (filter == TextureFilter::Nearest) {
    f.x0 = nearestTexelIndex(uv.x, texture.width);
    f.y0 = nearestTexelIndex(uv.y, texture.height);
    return f;
  }
  const float u = uv.x * static_cast<float>(texture.width) - kTexelCentre;
  const float v = uv.y * static_cast<float>(texture.height) - kTexelCentre;
  if (std::isfinite(u)) {
    const float fu = std::floor(u);
    f.alpha = u - fu;
    f.x0 = wrappedFloor(fu, texture.width);
  }
  if (std::isfinite(v)) {
    const float fv = std::floor(v);
    f.beta = v - fv;
    f.y0 = wrappedFloor(fv, texture.height);
  }
  f.x1 = f.x0 + 1 == texture.width ? 0 : f.x0 + 1;
  f.y1 = f.y0 + 1 == texture.height ? 0 : f.y0 + 1;
  return f;
}

vec4 sampleNearest(const Texture& texture, vec2 uv) {
  if (texture.width <= 0 || texture.height <= 0) return vec4(0.0f);
  const SampleFootprint f = sampleFootprint(texture, uv, TextureFilter::Nearest);
  return texelAt(texture, f.x0, f.y0);
}

vec4 sampleBilinear(const Texture& texture, vec2 uv) {
  if (texture.width <= 0 || texture.height <= 0) return vec4(0.0f);
  const SampleFootprint f = sampleFootprint(texture, uv, TextureFilter::Bilinear);
  const float a = f.alpha, b = f.beta;
  return (1.0f - a) * (1.0f - b) * texelAt(texture, f.x0, f.y0) + a * (1.0f - b) * texelAt(texture, f.x1, f.y0) +
         (1.0f - a) * b * texelAt(texture, f.x0, f.y1) + a * b * texelAt(texture, f.x1, f.y1);
}

vec4 sampleTexture(const Texture& texture, vec2 uv, TextureFilter filter) {
  return filter == TextureFilter::Nearest ? sampleNearest(texture, uv) : sampleBilinear(texture, uv);
}

}  // namespace twr
