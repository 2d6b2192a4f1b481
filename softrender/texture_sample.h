// Texture sampling exactly as GL 3.3 defines it for GL_REPEAT without mipmaps
// (spec section 3.8.8), texel centres at +0.5, texels normalised as c / 255:
//   nearest:  i = floor(u * w), j = floor(v * h), both wrapped into [0, w) and [0, h)
//   bilinear: u' = u * w - 0.5, i0 = floor(u'), alpha = frac(u'), i1 = i0 + 1 (same for v),
//             wrapped; result = (1-alpha)(1-beta) T(i0,j0) + alpha (1-beta) T(i1,j0)
//                             + (1-alpha) beta T(i0,j1) + alpha beta T(i1,j1)
// Row 0 of a texture is v = 0 (rows are stored bottom row first).
#pragma once

#include "scene/conventions.h"
#include "scene/settings.h"
#include "scene/texture.h"

namespace twr {

// The texel index floor(coord * size) wrapped, computed without overflow for any finite
// coordinate (a non-finite coordinate gives texel 0).
int nearestTexelIndex(float coord, int size);

vec4 texelAt(const Texture& texture, int x, int y);  // RGBA in [0, 1]
vec4 sampleNearest(const Texture& texture, vec2 uv);
vec4 sampleBilinear(const Texture& texture, vec2 uv);
vec4 sampleTexture(const Texture& texture, vec2 uv, TextureFilter filter);

// Which texel(s) a sample read and with what weights, for the pixel trace.
struct SampleFootprint {
  int x0 = 0, y0 = 0, x1 = 0, y1 = 0;  // texel indices (x1, y1 unused for nearest)
  float alpha = 0.0f, beta = 0.0f;     // bilinear weights towards x1 and y1
};
SampleFootprint sampleFootprint(const Texture& texture, vec2 uv, TextureFilter filter);

}  // namespace twr
