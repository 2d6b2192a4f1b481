// Texture sampling: GL_REPEAT, texel centres at +0.5, nearest and bilinear by hand.
#include "softrender/texture_sample.h"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>

namespace twr {
namespace {

// 2 x 2 texture, red channel: row 0 (v = 0) holds 0 and 100, row 1 holds 200 and 255.
Texture twoByTwo() {
  Texture t;
  t.width = 2;
  t.height = 2;
  // The texels' bytes in one go (RGBA, bottom row first), not appended texel by texel: GCC 12
  // at -O3 flags the vector's growth in insert() as a stringop-overflow it cannot rule out.
  t.rgba = {
      0,   0, 0, 255,  100, 0, 0, 255,  // row 0: texels (0, 0) and (1, 0)
      200, 0, 0, 255,  255, 0, 0, 255,  // row 1: texels (0, 1) and (1, 1)
  };
  return t;
}

float red(vec4 c) { return c.r * 255.0f; }

TEST(TextureSample, NearestPicksTheTexelUnderTheCoordinate) {
  const Texture t = twoByTwo();
  EXPECT_FLOAT_EQ(red(sampleNearest(t, {0.25f, 0.25f})), 0.0f);    // texel (0, 0)'s centre
  EXPECT_FLOAT_EQ(red(sampleNearest(t, {0.75f, 0.25f})), 100.0f);  // texel (1, 0)
  EXPECT_FLOAT_EQ(red(sampleNearest(t, {0.25f, 0.75f})), 200.0f);  // texel (0, 1): rows are bottom first
  EXPECT_FLOAT_EQ(red(sampleNearest(t, {0.5f, 0.5f})), 255.0f);    // floor(1) = texel 1 on both axes
}

TEST(TextureSample, NearestWrapsAtTheEdges) {
  const Texture t = twoByTwo();
  EXPECT_FLOAT_EQ(red(sampleNearest(t, {1.0f, 0.0f})), 0.0f);     // floor(2) = 2 wraps to 0
  EXPECT_FLOAT_EQ(red(sampleNearest(t, {-0.25f, 0.25f})), 100.0f);  // floor(-0.5) = -1 wraps to 1
  // u: floor(7.5) = 7 -> 1; v: floor(-2.5) = -3 -> 1: texel (1, 1).
  EXPECT_FLOAT_EQ(red(sampleNearest(t, {3.75f, -1.25f})), 255.0f);
  // u: floor(-2.5) = -3 -> 1; v: floor(0.5) = 0: texel (1, 0).
  EXPECT_FLOAT_EQ(red(sampleNearest(t, {-1.25f, 0.25f})), 100.0f);
}

TEST(TextureSample, BilinearAtTexelCentresIsTheTexel) {
  const Texture t = twoByTwo();
  EXPECT_NEAR(red(sampleBilinear(t, {0.25f, 0.25f})), 0.0f, 1e-4f);
  EXPECT_NEAR(red(sampleBilinear(t, {0.75f, 0.75f})), 255.0f, 1e-4f);
}

TEST(TextureSample, BilinearWeightsAsGlDefinesThem) {
  const Texture t = twoByTwo();
  // u = 0.5: u' = 0.5 * 2 - 0.5 = 0.5 -> i0 = 0, alpha = 0.5, on row 0 (v = 0.25).
  EXPECT_NEAR(red(sampleBilinear(t, {0.5f, 0.25f})), 50.0f, 1e-4f);
  // The centre of the texture: all four texels with weight 1/4.
  EXPECT_NEAR(red(sampleBilinear(t, {0.5f, 0.5f})), (0.0f + 100 + 200 + 255) / 4, 1e-3f);
  // u = 0.375: u' = 0.25 -> alpha 0.25: 0.75 * 0 + 0.25 * 100.
  EXPECT_NEAR(red(sampleBilinear(t, {0.375f, 0.25f})), 25.0f, 1e-4f);
}

TEST(TextureSample, BilinearWrapsAcrossTheEdge) {
  const Texture t = twoByTwo();
  // u = 0: u' = -0.5 -> i0 = -1 (wraps to 1), i1 = 0, alpha = 0.5: mean of texels 1 and 0.
  EXPECT_NEAR(red(sampleBilinear(t, {0.0f, 0.25f})), 50.0f, 1e-4f);
  // u = 1 is the same point as u = 0 under GL_REPEAT.
  EXPECT_NEAR(red(sampleBilinear(t, {1.0f, 0.25f})), 50.0f, 1e-4f);
  const SampleFootprint f = sampleFootprint(t, {0.0f, 0.25f}, TextureFilter::Bilinear);
  EXPECT_EQ(f.x0, 1);
  EXPECT_EQ(f.x1, 0);
  EXPECT_FLOAT_EQ(f.alpha, 0.5f);
}

TEST(TextureSample, HugeAndNonFiniteCoordinatesStayInRange) {
  const Texture t = twoByTwo();
  for (float u : {1e9f, -1e9f, 3e38f, std::numeric_limits<float>::infinity(), std::numeric_limits<float>::quiet_NaN()}) {
    for (TextureFilter filter : {TextureFilter::Nearest, TextureFilter::Bilinear}) {
      const SampleFootprint f = sampleFootprint(t, {u, u}, filter);
      EXPECT_GE(f.x0, 0);
      EXPECT_LT(f.x0, 2);
      EXPECT_GE(f.y1, 0);
      EXPECT_LT(f.y1, 2);
      const vec4 c = sampleTexture(t, {u, u}, filter);
      EXPECT_TRUE(std::isfinite(c.r) && std::isfinite(c.a));
    }
  }
}

TEST(TextureSample, NearestIndexFloorsTheProductInFloat) {
  EXPECT_EQ(nearestTexelIndex(0.999999f, 4), 3);
  EXPECT_EQ(nearestTexelIndex(-0.000001f, 4), 3);
  EXPECT_EQ(nearestTexelIndex(2.5f, 4), 2);
}

// A texture of pseudo-random bytes with its mip chain, for reads compared bit for bit.
Texture noiseTexture(int width, int height) {
  Texture t;
  t.width = width;
  t.height = height;
  t.rgba.resize(static_cast<std::size_t>(width) * height * 4);
  std::uint32_t state = 12345u;
  for (std::uint8_t& byte : t.rgba) {
    state = state * 1664525u + 1013904223u;  // a 32-bit LCG (Numerical Recipes' constants)
    byte = static_cast<std::uint8_t>(state >> 24);
  }
  buildMipChain(t);
  return t;
}

TEST(TextureSample, AMagnifiedOrWholeLodTrilinearReadTakesOneLevel) {
  const Texture t = noiseTexture(16, 16);
  for (float lod : {-3.0f, -0.25f, 0.0f, 1.0f, 2.0f}) {
    const lanes::MipLevelsL<float> m = lanes::mipLevels<float>(t, TextureFilter::Trilinear, lod);
    EXPECT_EQ(m.fraction, 0.0f) << lod;
    EXPECT_EQ(m.level1, m.level0) << lod;
    EXPECT_EQ(m.highest, m.lowest) << lod;  // the second level is never read
  }
  const lanes::MipLevelsL<float> blend = lanes::mipLevels<float>(t, TextureFilter::Trilinear, 1.5f);
  EXPECT_EQ(blend.level0, 1.0f);
  EXPECT_EQ(blend.level1, 2.0f);
  EXPECT_EQ(blend.fraction, 0.5f);
}

TEST(TextureSample, TheMarchsCompiledCaseReadsTheSameBitsAsTheGeneralOne) {
  const Texture t = noiseTexture(32, 8);  // not square: each axis its own size
  std::uint32_t state = 7u;
  const auto next = [&state] {
    state = state * 1664525u + 1013904223u;
    return static_cast<float>(state >> 8) / 16777216.0f;  // [0, 1)
  };
  for (TextureFilter filter : {TextureFilter::Bilinear, TextureFilter::Trilinear, TextureFilter::LinearMipmapNearest}) {
    for (int i = 0; i < 2000; ++i) {
      const vec2 uv(next() * 6.0f - 3.0f, next() * 6.0f - 3.0f);
      const float lod = next() * 7.0f - 2.0f;
      const lanes::MipLevelsL<float> m = lanes::mipLevels<float>(t, filter, lod);
      const float any = lanes::sampleMipLevelsInline<float, Texture, float, lanes::SamplerCase::kAny>(t, uv, filter, m);
      const float fixed =
          lanes::sampleMipLevelsInline<float, Texture, float, lanes::SamplerCase::kRepeatLinearUnorm>(t, uv, filter, m);
      ASSERT_EQ(std::bit_cast<std::uint32_t>(any), std::bit_cast<std::uint32_t>(fixed))
          << "uv " << uv.x << ", " << uv.y << " lod " << lod;
    }
  }
}

}  // namespace
}  // namespace twr
