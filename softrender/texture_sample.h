// Texture sampling exactly as GL 3.3 defines it for GL_REPEAT without mipmaps
// (spec section 3.8.8), texel centres at +0.5, texels normalised as c / 255:
//   nearest:  i = floor(u * w), j = floor(v * h), both wrapped into [0, w) and [0, h)
//   bilinear: u' = u * w - 0.5, i0 = floor(u'), alpha = frac(u'), i1 = i0 + 1 (same for v),
//             wrapped; result = (1-alpha)(1-beta) T(i0,j0) + alpha (1-beta) T(i1,j0)
//                             + (1-alpha) beta T(i0,j1) + alpha beta T(i1,j1)
// Row 0 of a texture is v = 0 (rows are stored bottom row first).
//
// The sampling itself is written once over the lane type in texture_sample-inl.h; this header
// gives it a Texture to read (the view functions below) and the scalar entry points, templated
// on T (float: the pipeline, double: the reference; T defaults to float).
#pragma once

#include "scene/conventions.h"
#include "scene/settings.h"
#include "scene/texture.h"
#include "softrender/lanes.h"
#include "softrender/precision.h"

#include <cmath>
#include <cstdint>

namespace twr {

// floor(s) reduced modulo `size` for an integer-valued s, exact in double for any finite
// float s (|s| < 2^128 fits a double's exponent; fmod is exact); 0 for a non-finite s.
inline std::int32_t wrappedFloorIndex(double s, int size) {
  if (!std::isfinite(s) || size <= 0) return 0;
  double wrapped = std::fmod(std::floor(s), static_cast<double>(size));
  if (wrapped < 0.0) wrapped += size;
  const std::int32_t i = static_cast<std::int32_t>(wrapped);
  return i >= size ? 0 : i;
}

// A Texture as texture_sample-inl.h reads it.
inline int texWidth(const Texture& t) { return t.width; }
inline int texHeight(const Texture& t) { return t.height; }
template <ScalarLane S>
inline std::int32_t wrapTexelIndex(int size, S integral) {
  return wrappedFloorIndex(static_cast<double>(integral), size);
}
inline std::int32_t nextTexelIndex(std::int32_t i, int size) { return i + 1 == size ? 0 : i + 1; }
template <typename T = float>
Vec4T<T> texelAt(const Texture& texture, int x, int y);  // RGBA in [0, 1]
template <typename L>
inline Vec4T<L> fetchTexel(const Texture& texture, std::int32_t x, std::int32_t y) {
  return texelAt<L>(texture, x, y);
}

}  // namespace twr

#include "softrender/texture_sample-inl.h"

namespace twr {

// The texel index floor(coord * size) wrapped, computed without overflow for any finite
// coordinate (a non-finite coordinate gives texel 0).
template <typename T = float>
int nearestTexelIndex(T coord, int size);

template <typename T = float>
Vec4T<T> sampleNearest(const Texture& texture, Vec2T<T> uv);
template <typename T = float>
Vec4T<T> sampleBilinear(const Texture& texture, Vec2T<T> uv);
template <typename T = float>
Vec4T<T> sampleTexture(const Texture& texture, Vec2T<T> uv, TextureFilter filter);

// Which texel(s) a sample read and with what weights, for the pixel trace.
template <typename T>
struct SampleFootprintT {
  int x0 = 0, y0 = 0, x1 = 0, y1 = 0;  // texel indices (x1, y1 equal x0, y0 for nearest)
  T alpha = T(0), beta = T(0);         // bilinear weights towards x1 and y1
};
using SampleFootprint = SampleFootprintT<float>;
template <typename T = float>
SampleFootprintT<T> sampleFootprint(const Texture& texture, Vec2T<T> uv, TextureFilter filter);

}  // namespace twr
