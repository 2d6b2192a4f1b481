// Texture sampling as llvmpipe (Mesa 22.3) does it in twinraster's precise mode (its float
// sampler, GALLIVM_PERF=no_aos_sampling,no_quad_lod; docs/compare.md), measured texel for
// texel (docs/textures.md): texel centres at +0.5, texels normalised as c / 255, and
//   nearest   repeat: i = trunc(min(u - floor(u), 1 - 2^-24) w); clamp_to_edge:
//             clamp(trunc(u w), 0, w - 1); mirrored_repeat: folded into [0, 1] first
//   bilinear  u' = u w - 0.5, i0 = floor(u'), alpha = u' - i0, i1 = i0 + 1, wrapped (repeat on
//             a non-power-of-two size takes the fraction of u first); a lerp along u on both
//             rows, then along v
//   mipmaps   one LOD per 2x2 quad from its top-left pixel's uv differences, lod =
//             fastLog2(rho^2) / 2; levels and their blend as texture_sample-inl.h says.
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

#include <array>
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
inline int texLevelCount(const Texture& t) { return t.levelCount(); }
inline int texLevelWidth(const Texture& t, int level) { return t.levelWidth(level); }
inline int texLevelHeight(const Texture& t, int level) { return t.levelHeight(level); }
inline TextureWrap texWrap(const Texture& t) { return t.options.wrap; }
inline bool texSrgb(const Texture& t) { return t.options.srgb; }
template <ScalarLane S>
inline std::int32_t wrapTexelIndex(int size, S integral) {
  return wrappedFloorIndex(static_cast<double>(integral), size);
}
inline std::int32_t nextTexelIndex(std::int32_t i, int size) { return i + 1 == size ? 0 : i + 1; }
template <typename L>
inline Vec4T<L> fetchTexelBytes(const Texture& texture, int level, std::int32_t x, std::int32_t y) {
  const std::uint8_t* t =
      &texture.levelTexels(level)[(static_cast<std::size_t>(y) * static_cast<std::size_t>(texture.levelWidth(level)) +
                                   static_cast<std::size_t>(x)) * 4];
  return Vec4T<L>(t[0], t[1], t[2], t[3]);
}
template <typename L>
inline L fetchTexelRedByte(const Texture& texture, int level, std::int32_t x, std::int32_t y) {
  return L(texture.levelTexels(level)[(static_cast<std::size_t>(y) * static_cast<std::size_t>(texture.levelWidth(level)) +
                                       static_cast<std::size_t>(x)) * 4]);
}
template <typename L>
inline Vec4T<L> fetchRedFootprintBytes(const Texture& texture, int level, std::int32_t x0, std::int32_t x1,
                                       std::int32_t y0, std::int32_t y1) {
  return Vec4T<L>(fetchTexelRedByte<L>(texture, level, x0, y0), fetchTexelRedByte<L>(texture, level, x1, y0),
                  fetchTexelRedByte<L>(texture, level, x0, y1), fetchTexelRedByte<L>(texture, level, x1, y1));
}
// sRGB byte value -> linear, GL's formula in double rounded to the lane type.
const std::array<double, 256>& srgbDecodeTable();
template <ScalarLane S>
inline S linearFromSrgbByte(S byte) {
  return static_cast<S>(srgbDecodeTable()[static_cast<std::size_t>(byte)]);
}
template <typename T = float>
Vec4T<T> texelAt(const Texture& texture, int x, int y);  // RGBA in [0, 1], level 0

// The anisotropic filter's weights (texture_sample-inl.h, sampleEwaLevel), as llvmpipe
// holds them: exp(-2 i / 1023) in float for i in [0, 1024), printed with six decimals into
// its source and read back as float (gallivm's aniso_filter_table).
inline constexpr int kEwaWeightCount = 1024;
const std::array<float, kEwaWeightCount>& ewaWeightTable();

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
// `lod` as quadLod gives it (ignored by filters without mipmaps).
template <typename T = float>
Vec4T<T> sampleTexture(const Texture& texture, Vec2T<T> uv, TextureFilter filter, T lod = T(0));
// With GL_TEXTURE_MAX_ANISOTROPY > 1: the quad's uv differences instead of a LOD.
template <typename T = float>
Vec4T<T> sampleTextureAnisotropic(const Texture& texture, Vec2T<T> uv, TextureFilter filter, Vec2T<T> dUvDx,
                                  Vec2T<T> dUvDy);

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
