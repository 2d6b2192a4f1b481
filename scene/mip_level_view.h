// The mip_level debug view: which mip level each pixel's texture reads, as a colour, drawn
// the same way by both renderers. Instead of a formula for the LOD (each renderer's own, and
// GL's textureQueryLod is not the LOD llvmpipe samples with), every material's first map
// (diffuse, else normal, else specular) is replaced by a texture of the same level sizes,
// wrap and uv transform whose level k is one solid colour, and the scene is drawn in the
// albedo view with kd = 1. The sampler then shows its own choice: a mipmapped filter picks or
// blends level colours exactly as it would pick or blend the map's levels; nearest and
// bilinear show level 0 everywhere; anisotropic filtering shows the level of the ellipse's
// short axis.
//
// Level colours walk the edges of the RGB cube, one channel changing per step, so a blend of
// two neighbouring levels (trilinear) is a point on one segment and reads back as a
// fractional level: 0 blue, 1 cyan, 2 green, 3 yellow, 4 red, 5 magenta, 6 white, 7 light
// grey, 8 grey, 9 black, 10 navy, 11 purple, 12 maroon; levels past 12 keep maroon.
#pragma once

#include "scene/scene.h"
#include "scene/settings.h"

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

namespace twr {

inline constexpr int kMipLevelColourCount = 13;
// A surface with no map: brown (128, 64, 0), on no segment between level colours.
inline constexpr vec3 kNoMapColour{128.0f / 255.0f, 64.0f / 255.0f, 0.0f};
// RGB bytes of level k (k clamped to [0, kMipLevelColourCount - 1]).
std::array<std::uint8_t, 3> mipLevelColour(int level);

// The level a colour of the view shows: k + t for a point within `toleranceLevels` (bytes) of
// the segment from level k's colour to level k + 1's; nullopt for a colour on no segment
// (the background, an untextured surface).
std::optional<float> mipLevelFromColour(const std::array<std::uint8_t, 3>& rgb, int toleranceLevels = 2);

// A texture with `like`'s level sizes, wrap and uv transform (not sRGB), level k filled with
// mipLevelColour(k). Cached: the same sizes and options give the same object, so renderers'
// upload caches keep it across frames.
std::shared_ptr<const Texture> mipLevelTexture(const Texture& like);

// The materials the view draws with (stable addresses for DrawItem::material).
struct MipLevelView {
  std::vector<std::unique_ptr<Material>> materials;
};
// For settings.view == MipLevel (else nothing): points every item at its material's mip_level stand-in (kd = ka = 1, no specular, the first
// map replaced by mipLevelTexture, no other map; no map at all: kd = kNoMapColour) and sets
// the view to albedo. Keep the returned storage alive while the items are drawn.
MipLevelView applyMipLevelView(std::vector<DrawItem>& items, RenderSettings& settings);

}  // namespace twr
