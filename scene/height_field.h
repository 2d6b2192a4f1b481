// Height maps read as geometry: the exact height a height map holds at a uv, for the true
// displaced surface (makeHeightfield) that parallax mapping is measured against.
#pragma once

#include "scene/conventions.h"
#include "scene/texture.h"

namespace twr {

// The height at `uv` as the renderers' bilinear filter reads level 0, in double: the red
// channel (byte / 255; sRGB-decoded when the texture's "srgb" asks for it), texel centres at
// +0.5, the texture's wrap mode (repeat, mirrored_repeat, clamp_to_edge) in u and v, and its
// own uv transform (looked up at uv * uvScale + uvOffset, as an MTL's -s and -o ask).
// 1 = top of the relief, 0 = bottom. A non-finite uv reads as uv 0; never NaN.
double heightAt(const Texture& heightMap, glm::dvec2 uv);

}  // namespace twr
