// scene/horizon_map: the azimuth layout the shaders find again, and the horizon of a known step.
#include "scene/horizon_map.h"

#include <gtest/gtest.h>

#include <cmath>

namespace twr {
namespace {

// The shader's diamond angle of a direction (surface_detail-inl.h, surface_detail.glsl).
float diamondAngle(vec2 d) {
  const float q = std::fabs(d.y) / (std::fabs(d.x) + std::fabs(d.y));
  float a = d.x >= 0.0f ? (d.y >= 0.0f ? q : 4.0f - q) : (d.y >= 0.0f ? 2.0f - q : 2.0f + q);
  return a >= 4.0f ? a - 4.0f : a;
}

TEST(HorizonMap, AzimuthKLiesAtDiamondAngleFourKOverDirections) {
  for (int directions : {4, 8, 12, 16}) {
    for (int k = 0; k < directions; ++k) {
      const vec2 d = horizonDirectionUv(k, directions);
      EXPECT_NEAR(std::fabs(d.x) + std::fabs(d.y), 1.0f, 1e-6f);
      EXPECT_NEAR(diamondAngle(d) * static_cast<float>(directions) / 4.0f, static_cast<float>(k), 1e-5f)
          << "k " << k << " of " << directions;
    }
  }
}

// An 8x1 map, 0 everywhere but texel 4 (255), repeat wrap. From texel 3 the step rises one
// texel (1/8 uv) away towards +u and seven texels away towards -u (wrapping round).
TEST(HorizonMap, HorizonOfAStepIsItsElevationSine) {
  Texture step;
  step.path = "step";
  step.width = 8;
  step.height = 1;
  step.rgba.assign(8 * 4, 0);
  step.rgba[4 * 4] = 255;
  const float scale = 0.05f;  // texture-space units
  const HorizonMap horizon = makeHorizonMap(step, scale, 4);
  ASSERT_EQ(horizon.textures.size(), 1u);
  const auto sineByte = [](double slope) { return std::lround(slope / std::sqrt(1.0 + slope * slope) * 255.0); };
  const std::uint8_t* texel3 = horizon.textures[0]->texel(3, 0);
  EXPECT_EQ(texel3[0], sineByte(scale / (1.0 / 8.0)));  // azimuth 0: +u
  EXPECT_EQ(texel3[2], sineByte(scale / (7.0 / 8.0)));  // azimuth 2: -u
  EXPECT_EQ(horizon.textures[0]->texel(4, 0)[0], 0);    // the top sees nothing above it
  EXPECT_FALSE(horizon.textures[0]->mips.empty());       // sampled with mipmaps like any map
}

}  // namespace
}  // namespace twr
