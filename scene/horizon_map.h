// Horizon maps (Max 1988; Sloan and Cohen 2000; docs/parallax.md): for every texel of a height
// map and each of `directions` azimuths, the sine of the elevation angle of the horizon seen
// from that texel, computed once at load and sampled by both renderers like any texture.
#pragma once

#include "scene/texture.h"

#include <memory>
#include <vector>

namespace twr {

struct HorizonMap {
  int directions = 0;  // a multiple of 4 in [kMinHorizonDirections, kMaxHorizonDirections]
  // directions / 4 RGBA8 textures of the height map's size and wrap, linear (not sRGB), with
  // their mip chains: azimuth 4 k + c lies in channel c of textures[k].
  std::vector<std::shared_ptr<const Texture>> textures;
};

// Azimuth k's direction in the uv plane: the point at "diamond angle" 4 k / directions on the
// unit diamond |x| + |y| = 1 (0 = +u, 1 = +v, 2 = -u, 3 = -v), which the shader finds again
// without trigonometry. Not normalised.
vec2 horizonDirectionUv(int k, int directions);

// The horizon map of `heightMap` for a relief heightScale texture-space units deep: for each
// texel centre and azimuth, the largest (h(q) - h(p)) heightScale / |q - p| (uv units) over
// points q up to kHorizonReachTexels texels away along the azimuth, h bilinear in level 0 with
// the map's wrap; stored as the sine of that slope's angle, 0 when nothing rises.
HorizonMap makeHorizonMap(const Texture& heightMap, float heightScale, int directions);

// How far the horizon search looks (texels of level 0 along the azimuth): the cost at load is
// width * height * directions * this.
inline constexpr int kHorizonReachTexels = 32;
// Most texels times azimuths a horizon map is built for (inclusive): 1024 x 1024 at 16
// azimuths, 5.4e8 height reads. Rows are built on every core: measured at 512 x 512 on two
// cores, 1.3 s at 8 azimuths and 2.7 s at 16 (2.5 s and 5.0 s of CPU), so the largest map takes
// about 11 s at load there. Larger maps are refused.
inline constexpr long long kMaxHorizonTexelDirections = 1024LL * 1024LL * 16LL;

}  // namespace twr
