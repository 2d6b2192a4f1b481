// Texture sampling exactly as GL 3.3 defines it for GL_REPEAT without mipmaps
// (spec section 3.8.8), texel centres at +0.5, texels normalised as c / 255:
//   nearest:  i = floor(u * w), j = floor(v * h), both wrapped into [0, w) and [0, h)
//   bilinear: u' = u * w - 0.5, i0 = floor(u'), alpha = frac(u'), i1 = i0 + 1 (same for v),
//             wrapped; result = (1-alpha)(1-beta) T(i0,j0) + alpha (1-beta) T(i1,j0)
//                             + (1-alpha) beta T(i0,j1) + alpha beta T(i1,j1)
// Row 0 of a texture is v = 0 (rows are stored bottom row first).
//
// Templated on the scalar T of the coordinates and the result (float: the pipeline, double:
// the reference); T defaults to float.
#pragma once

#include "scene/conventions.h"
#include "scene/settings.h"
#include "scene/texture.h"
#include "softrender/precision.h"

namespace twr {

// The texel index floor(coord * size) wrapped, computed without overflow for any finite
// coordinate (a non-finite coordinate gives texel 0).
template <typename T = float>
int nearestTexelIndex(T coord, int size);

template <typename T = float>
Vec4T<T> texelAt(const Texture& texture, int x, int y);  // RGBA in [0, 1]
template <typename T = float>
Vec4T<T> sampleNearest(const Texture& texture, Vec2T<T> uv);
template <typename T = float>
Vec4T<T> sampleBilinear(const Texture& texture, Vec2T<T> uv);
template <typename T = float>
Vec4T<T> sampleTexture(const Texture& texture, Vec2T<T> uv, TextureFilter filter);

// Which texel(s) a sample read and with what weights, for the pixel trace.
template <typename T>
struct SampleFootprintT {
  int x0 = 0, y0 = 0, x1 = 0, y1 = 0;  // texel indices (x1, y1 unused for nearest)
  T alpha = T(0), beta = T(0);         // bilinear weights towards x1 and y1
};
using SampleFootprint = SampleFootprintT<float>;
template <typename T = float>
SampleFootprintT<T> sampleFootprint(const Texture& texture, Vec2T<T> uv, TextureFilter filter);

}  // namespace twr
