// The mip_level debug view's stand-ins (scene/mip_level_view.h): level colours that read back
// as levels, textures with the map's level sizes and options, materials swapped per item.
#include "scene/mip_level_view.h"

#include "scene/texture.h"

#include <gtest/gtest.h>

#include <set>

namespace twr {
namespace {

TEST(MipLevelView, EveryLevelColourAndEveryHalfwayBlendReadsBack) {
  for (int k = 0; k < kMipLevelColourCount; ++k) {
    const std::optional<float> level = mipLevelFromColour(mipLevelColour(k));
    ASSERT_TRUE(level.has_value()) << "level " << k;
    EXPECT_FLOAT_EQ(*level, static_cast<float>(k));
  }
  for (int k = 0; k + 1 < kMipLevelColourCount; ++k) {
    const auto a = mipLevelColour(k), b = mipLevelColour(k + 1);
    std::array<std::uint8_t, 3> half{};
    for (int c = 0; c < 3; ++c) {
      half[static_cast<std::size_t>(c)] =
          static_cast<std::uint8_t>((a[static_cast<std::size_t>(c)] + b[static_cast<std::size_t>(c)] + 1) / 2);
    }
    const std::optional<float> level = mipLevelFromColour(half);
    ASSERT_TRUE(level.has_value()) << "between " << k << " and " << k + 1;
    EXPECT_NEAR(*level, k + 0.5f, 0.01f);
  }
  // Past the last colour, levels keep it; the no-map colour and a background are no level.
  EXPECT_EQ(mipLevelColour(40), mipLevelColour(kMipLevelColourCount - 1));
  EXPECT_FALSE(mipLevelFromColour({128, 64, 0}).has_value());
  EXPECT_FALSE(mipLevelFromColour({13, 13, 20}).has_value());
}

TEST(MipLevelView, TextureHasTheMapsLevelsAndOptionsAndIsCached) {
  Texture map;
  map.width = 8;
  map.height = 2;
  map.rgba.assign(8 * 2 * 4, 7);
  map.mips = {TextureLevel{4, 1, std::vector<std::uint8_t>(16, 7)}, TextureLevel{2, 1, std::vector<std::uint8_t>(8, 7)},
              TextureLevel{1, 1, std::vector<std::uint8_t>(4, 7)}};
  map.mipSource = MipSource::Built;
  map.options.wrap = TextureWrap::ClampToEdge;
  map.options.srgb = true;
  map.options.uvScale = vec2(2.0f, 3.0f);
  const std::shared_ptr<const Texture> levels = mipLevelTexture(map);
  ASSERT_EQ(levels->levelCount(), 4);
  for (int k = 0; k < 4; ++k) {
    EXPECT_EQ(levels->levelWidth(k), map.levelWidth(k));
    EXPECT_EQ(levels->levelHeight(k), map.levelHeight(k));
    const auto colour = mipLevelColour(k);
    const std::vector<std::uint8_t>& texels = levels->levelTexels(k);
    for (std::size_t i = 0; i < texels.size(); i += 4) {
      ASSERT_EQ(texels[i], colour[0]);
      ASSERT_EQ(texels[i + 1], colour[1]);
      ASSERT_EQ(texels[i + 2], colour[2]);
      ASSERT_EQ(texels[i + 3], 255);
    }
  }
  EXPECT_EQ(levels->options.wrap, TextureWrap::ClampToEdge);
  EXPECT_FALSE(levels->options.srgb) << "level colours are exact bytes, never decoded";
  EXPECT_EQ(levels->options.uvScale, vec2(2.0f, 3.0f));
  EXPECT_EQ(mipLevelTexture(map).get(), levels.get()) << "the same map must give the same object (upload caches)";
}

TEST(MipLevelView, ItemsGetStandInsAndTheViewBecomesAlbedo) {
  Material textured;
  auto normal = std::make_shared<Texture>();
  normal->width = normal->height = 4;
  normal->rgba.assign(64, 128);
  textured.normalMap = normal;  // no diffuse map: the normal map's levels are shown
  textured.ks = vec3(1.0f);
  Material plain;
  Mesh mesh;
  std::vector<DrawItem> items(3);
  items[0].mesh = items[1].mesh = items[2].mesh = &mesh;
  items[0].material = &textured;
  items[1].material = &plain;
  items[2].material = &textured;
  RenderSettings settings;
  settings.view = View::MipLevel;
  const MipLevelView view = applyMipLevelView(items, settings);
  EXPECT_EQ(settings.view, View::Albedo);
  EXPECT_EQ(view.materials.size(), 2u) << "one stand-in per distinct material";
  EXPECT_EQ(items[0].material, items[2].material);
  ASSERT_TRUE(items[0].material->diffuseMap);
  EXPECT_EQ(items[0].material->diffuseMap->width, 4);
  EXPECT_FALSE(items[0].material->normalMap);
  EXPECT_EQ(items[0].material->kd, vec3(1.0f));
  EXPECT_EQ(items[0].material->ks, vec3(0.0f));
  EXPECT_FALSE(items[1].material->diffuseMap);
  EXPECT_EQ(items[1].material->kd, kNoMapColour);
}

}  // namespace
}  // namespace twr
