// Height maps read as geometry: the exact height a height map holds at a uv, for the true
// displaced surface (makeHeightfield) that parallax mapping is measured against, and the
// normal map of that same surface, so a parallax material lights like the displaced mesh.
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

// The tangent-space normal map of the surface `heightMap` describes at depth `heightScale`
// (texture-space units, Material::heightScale): per level-0 texel,
//   n = normalize(-heightScale dh/du, -heightScale dh/dv, 1),   encoded rgb = round((n + 1) / 2 * 255),
// +x = +u, +y = +v (GreenAxis::Up), with dh/du and dh/dv central differences over the two
// neighbouring texels (2 / width and 2 / height in uv) read through the map's wrap mode, the
// red channel as heightAt reads it (sRGB-decoded when asked). The same slopes makeHeightfield
// gives its vertex normals, so a normal-mapped plane and the displaced mesh light alike; the
// assets' bricks_normal.png is this at depth 0.012 (app/assets_tool.cpp). The result keeps
// the height map's wrap and uv transform and has its own mip chain (buildMipChain).
// Throws InputError when the map holds no texels or heightScale is negative or not finite.
Texture normalMapFromHeight(const Texture& heightMap, double heightScale);

}  // namespace twr
