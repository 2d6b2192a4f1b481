// Textures on the GL side (issue 15): every level uploaded as the Texture holds it, block-
// compressed levels uploaded compressed and sampled by llvmpipe exactly as
// scene/block_compression.h decodes them, the six filters, the three wrap modes, sRGB
// formats, and the phong permutations for normal-map conventions and per-map uv transforms.
// Textures are built in code (rows bottom first, as scene/texture.h stores them). With the
// front camera a quad at depth 2 spanning [-2, 2]^2 fills the 64 x 64 image, uv (0, 0) at the
// bottom-left corner: pixel (x, top-first row) samples uv ((x + 0.5) / 64, (63 - row + 0.5) / 64).
#include "gl_test_scenes.h"
#include "glrender/context_osmesa.h"
#include "glrender/gl_context.h"
#include "glrender/gl_renderer.h"
#include "glrender/gl_scene_draw.h"
#include "glrender/gl_upload_cache.h"
#include "scene/block_compression.h"
#include "scene/errors.h"
#include "scene/texture.h"
#include "tests/missing_dependency.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <memory>
#include <random>
#include <sstream>
#include <string>
#include <vector>

namespace twr {
namespace {

using gltest::addNode;
using gltest::covered;
using gltest::emptyScene;
using gltest::kSide;
using gltest::pixel;
using gltest::quadAt;

using Rgb = std::array<int, 3>;

Rgb rgbAt(const RenderOutput& out, int x, int row) {
  const std::uint8_t* p = pixel(out, x, row);
  return {p[0], p[1], p[2]};
}

std::string str(const Rgb& c) {
  return "(" + std::to_string(c[0]) + ", " + std::to_string(c[1]) + ", " + std::to_string(c[2]) + ")";
}

// A width x height RGBA8 texture of one colour per level (level 0 and `levelColours.size() - 1`
// mips, each side halved, at least 1).
std::shared_ptr<Texture> levelTexture(int width, int height, const std::vector<Rgb>& levelColours) {
  auto texture = std::make_shared<Texture>();
  texture->path = "levels";
  texture->width = width;
  texture->height = height;
  int w = width, h = height;
  for (std::size_t level = 0; level < levelColours.size(); ++level) {
    std::vector<std::uint8_t> rgba;
    for (int i = 0; i < w * h; ++i) {
      const Rgb& c = levelColours[level];
      rgba.insert(rgba.end(), {static_cast<std::uint8_t>(c[0]), static_cast<std::uint8_t>(c[1]),
                               static_cast<std::uint8_t>(c[2]), 255});
    }
    if (level == 0) {
      texture->rgba = std::move(rgba);
    } else {
      texture->mips.push_back(TextureLevel{w, h, std::move(rgba)});
    }
    w = std::max(w / 2, 1);
    h = std::max(h / 2, 1);
  }
  texture->mipSource = texture->mips.empty() ? MipSource::None : MipSource::Built;
  return texture;
}

// A texture from rows of RGB texels, bottom row first.
std::shared_ptr<Texture> texelTexture(int width, int height, const std::vector<Rgb>& texels) {
  auto texture = std::make_shared<Texture>();
  texture->path = "texels";
  texture->width = width;
  texture->height = height;
  for (const Rgb& c : texels) {
    texture->rgba.insert(texture->rgba.end(), {static_cast<std::uint8_t>(c[0]), static_cast<std::uint8_t>(c[1]),
                                               static_cast<std::uint8_t>(c[2]), 255});
  }
  return texture;
}

TextureChannels channelsOf(BlockFormat format) {
  if (format == BlockFormat::Bc4) return TextureChannels::Red;
  if (format == BlockFormat::Bc5) return TextureChannels::RedGreen;
  return TextureChannels::Rgba;
}

// A compressed texture whose levels are `levels` (level 0 first, block rows bottom first);
// its RGBA8 levels are what decodeBlockLevel gives, as the loader stores them.
std::shared_ptr<Texture> blockTexture(BlockFormat format, int width, int height,
                                      std::vector<std::vector<std::uint8_t>> levels) {
  auto texture = std::make_shared<Texture>();
  texture->path = std::string(toString(format));
  texture->formatName = texture->path;
  texture->width = width;
  texture->height = height;
  texture->channels = channelsOf(format);
  int w = width, h = height;
  for (std::size_t level = 0; level < levels.size(); ++level) {
    std::vector<std::uint8_t> rgba = decodeBlockLevel(format, w, h, levels[level].data());
    if (level == 0) {
      texture->rgba = std::move(rgba);
    } else {
      texture->mips.push_back(TextureLevel{w, h, std::move(rgba)});
    }
    w = std::max(w / 2, 1);
    h = std::max(h / 2, 1);
  }
  texture->blockFormat = format;
  texture->blockLevels = std::move(levels);
  texture->mipSource = texture->mips.empty() ? MipSource::None : MipSource::File;
  return texture;
}

// BC1 colour half: endpoints c0, c1 (RGB565) and 2-bit indices t0..t15 packed from bit 0.
void putColourHalf(std::uint8_t* half, std::uint16_t c0, std::uint16_t c1, std::uint32_t indices) {
  half[0] = static_cast<std::uint8_t>(c0);
  half[1] = static_cast<std::uint8_t>(c0 >> 8);
  half[2] = static_cast<std::uint8_t>(c1);
  half[3] = static_cast<std::uint8_t>(c1 >> 8);
  for (int i = 0; i < 4; ++i) half[4 + i] = static_cast<std::uint8_t>(indices >> (8 * i));
}

// BC4 half: endpoints a0, a1 and 3-bit indices t0..t15 packed from bit 0.
void putValueHalf(std::uint8_t* half, std::uint8_t a0, std::uint8_t a1, std::uint64_t indices) {
  half[0] = a0;
  half[1] = a1;
  for (int i = 0; i < 6; ++i) half[2 + i] = static_cast<std::uint8_t>(indices >> (8 * i));
}

// Indices 0, 1, 2, 3, 0, 1, ... (BC1) and 0..7, 0..7 (BC4): every palette entry used.
constexpr std::uint32_t kAllColourIndices = 0xE4E4E4E4u;
constexpr std::uint64_t kAllValueIndices = 0xFAC688FAC688ull;  // t = 0..7 -> 0..7, twice

// `count` blocks of `format`: random bytes (fixed seed, std::mt19937 is the same everywhere),
// the first ones replaced by the cases each decoder branches on: BC1 c0 > c1 (4 colours),
// c0 < c1 and c0 == c1 (3 colours + transparent black), extreme endpoints; BC4 a0 > a1
// (8 values), a0 < a1 and a0 == a1 (6 values + 0 and 255).
std::vector<std::uint8_t> testBlocks(BlockFormat format, int count, std::uint32_t seed) {
  const int bytes = blockBytes(format);
  std::vector<std::uint8_t> blocks(static_cast<std::size_t>(count * bytes));
  std::mt19937 random(seed);
  for (std::uint8_t& b : blocks) b = static_cast<std::uint8_t>(random() & 0xFF);
  struct ColourCase {
    std::uint16_t c0, c1;
  };
  const ColourCase colourCases[] = {{0xF800, 0x001F}, {0x001F, 0xF800}, {0x8410, 0x8410}, {0xFFFF, 0x0000},
                                    {0x0000, 0xFFFF}, {0x1234, 0xFEDC}, {0xFEDC, 0x1234}, {0x07E0, 0x07E1}};
  struct ValueCase {
    std::uint8_t a0, a1;
  };
  const ValueCase valueCases[] = {{255, 0}, {0, 255}, {128, 128}, {200, 13}, {13, 200}, {1, 0}, {0, 1}, {254, 255}};
  constexpr int kCases = 8;
  for (int i = 0; i < std::min(count, kCases); ++i) {
    std::uint8_t* block = &blocks[static_cast<std::size_t>(i * bytes)];
    const ColourCase& cc = colourCases[i];
    const ValueCase& vc = valueCases[i];
    switch (format) {
      case BlockFormat::Bc1: putColourHalf(block, cc.c0, cc.c1, kAllColourIndices); break;
      case BlockFormat::Bc2:
        for (int a = 0; a < 8; ++a) block[a] = static_cast<std::uint8_t>(0x10 * (2 * a) + (2 * a + 1));  // alphas 0..15
        putColourHalf(block + 8, cc.c0, cc.c1, kAllColourIndices);
        break;
      case BlockFormat::Bc3:
        putValueHalf(block, vc.a0, vc.a1, kAllValueIndices);
        putColourHalf(block + 8, cc.c0, cc.c1, kAllColourIndices);
        break;
      case BlockFormat::Bc4: putValueHalf(block, vc.a0, vc.a1, kAllValueIndices); break;
      case BlockFormat::Bc5:
        putValueHalf(block, vc.a0, vc.a1, kAllValueIndices);
        putValueHalf(block + 8, vc.a1, vc.a0, kAllValueIndices);
        break;
    }
  }
  return blocks;
}

constexpr BlockFormat kAllBlockFormats[] = {BlockFormat::Bc1, BlockFormat::Bc2, BlockFormat::Bc3, BlockFormat::Bc4,
                                            BlockFormat::Bc5};

// Texel index along a side of `size` texels that nearest filtering reads at texture
// coordinate `c`, per wrap mode (GL 3.3 section 3.8.11), for coordinates away from a
// texel boundary.
int wrappedTexel(double c, int size, TextureWrap wrap) {
  switch (wrap) {
    case TextureWrap::Repeat: {
      const double f = c - std::floor(c);
      return std::min(static_cast<int>(std::floor(f * size)), size - 1);
    }
    case TextureWrap::MirroredRepeat: {
      double f = c - 2.0 * std::floor(c / 2.0);  // [0, 2)
      if (f > 1.0) f = 2.0 - f;
      return std::clamp(static_cast<int>(std::floor(f * size)), 0, size - 1);
    }
    case TextureWrap::ClampToEdge: return std::clamp(static_cast<int>(std::floor(c * size)), 0, size - 1);
  }
  return 0;
}

// Largest difference between tangent- and world-space lighting of a flat quad, 8-bit levels:
// measured 0 in every view on llvmpipe 22.3.6.
constexpr int kLightingSpaceLevels = 0;

// A GL renderer per test; the test is skipped when no GL context can be created (no OSMesa).
class GlTextures : public ::testing::Test {
 protected:
  void SetUp() override {
    try {
      renderer_ = makeGlRenderer();
      const Scene probe = emptyScene();
      renderer_->render(probe, probe.settings, 4, 4);  // the context is created on the first render
    } catch (const InputError& e) {
      TWR_MISSING_DEPENDENCY("OSMesa") << "no GL context: " << e.what();
    }
  }

  // The full-screen quad at depth 2 with `material`, drawn with `settings` (view albedo and
  // filter nearest unless the test says otherwise).
  RenderOutput renderQuad(const Material& material, const RenderSettings& settings, int side = kSide,
                          Mesh mesh = quadAt(-2.0f, -2.0f, -2.0f, 2.0f, 2.0f)) {
    Scene scene = emptyScene();
    scene.materials.push_back(material);
    addNode(scene, std::move(mesh), "quad", 0);
    return renderer_->render(scene, settings, side, side);
  }

  static RenderSettings albedoNearest() {
    RenderSettings settings;
    settings.view = View::Albedo;
    settings.textureFilter = TextureFilter::Nearest;
    return settings;
  }

  std::unique_ptr<Renderer> renderer_;
};

// (a) Every block format, sampled nearest through the whole renderer (albedo view, kd = 1, so
// a texel byte comes back as the same byte): llvmpipe's decode of the uploaded blocks equals
// decodeBlockLevel on every texel. 64 x 64 texels at 64 x 64 pixels: one texel per pixel,
// each pixel centre a texel centre. A 10 x 6 level (blocks cut at the edge) is checked too.
TEST_F(GlTextures, NearestSampledBlockFormatsMatchTheCpuDecodeTexelForTexel) {
  struct Size {
    int width, height;
  };
  for (const Size size : {Size{64, 64}, Size{10, 6}}) {
    for (const BlockFormat format : kAllBlockFormats) {
      const int blockCount = blocksAlong(size.width) * blocksAlong(size.height);
      const std::vector<std::uint8_t> blocks =
          testBlocks(format, blockCount, 1500u + static_cast<std::uint32_t>(format));
      Material material;
      material.diffuseMap = blockTexture(format, size.width, size.height, {blocks});
      const std::vector<std::uint8_t> expected = material.diffuseMap->rgba;  // decodeBlockLevel's
      const RenderOutput out = renderQuad(material, albedoNearest());

      int mismatches = 0;
      int maxDifference = 0;
      std::ostringstream firstOnes;
      for (int row = 0; row < kSide; ++row) {
        for (int x = 0; x < kSide; ++x) {
          const int tx = static_cast<int>(std::floor((x + 0.5) * size.width / kSide));
          const int ty = static_cast<int>(std::floor((kSide - 1 - row + 0.5) * size.height / kSide));
          const std::uint8_t* want = &expected[(static_cast<std::size_t>(ty) * size.width + tx) * 4];
          const Rgb got = rgbAt(out, x, row);
          bool same = true;
          for (int c = 0; c < 3; ++c) {
            const int difference = std::abs(got[c] - want[c]);
            maxDifference = std::max(maxDifference, difference);
            same = same && difference == 0;
          }
          if (!same && ++mismatches <= 8) {
            const int block = (ty / kBlockSide) * blocksAlong(size.width) + tx / kBlockSide;
            firstOnes << "\n  texel (" << tx << ", " << ty << ") block " << block << " texel (" << tx % kBlockSide
                      << ", " << ty % kBlockSide << "): gl " << str(got) << ", cpu ("
                      << int(want[0]) << ", " << int(want[1]) << ", " << int(want[2]) << ")";
          }
        }
      }
      EXPECT_EQ(mismatches, 0) << toString(format) << " " << size.width << " x " << size.height << ": "
                               << mismatches << " pixels differ, by up to " << maxDifference << firstOnes.str();
    }
  }
}

// (b) A plane receding to the horizon with one solid colour per level: the mipmapped filters
// read ever smaller levels towards the horizon; nearest and bilinear read level 0 alone.
TEST_F(GlTextures, MipmappedFiltersShowSmallerLevelsOnARecedingPlane) {
  const std::vector<Rgb> levelColours = {{255, 0, 0},   {0, 255, 0},   {0, 0, 255},    {255, 255, 0},
                                         {0, 255, 255}, {255, 0, 255}, {255, 255, 255}};  // 64 .. 1
  constexpr float kPlaneY = -1.0f;     // world units below the eye
  constexpr float kPlaneFar = 100.0f;  // world units
  constexpr float kHalfWidth = 100.0f;
  // uv = (x, -z): one texture (64 texels) per world unit.
  Mesh plane = makeTriangles({{-kHalfWidth, kPlaneY, 0.0f}, {kHalfWidth, kPlaneY, 0.0f}, {kHalfWidth, kPlaneY, -kPlaneFar},
                              {-kHalfWidth, kPlaneY, 0.0f}, {kHalfWidth, kPlaneY, -kPlaneFar}, {-kHalfWidth, kPlaneY, -kPlaneFar}},
                             {{-kHalfWidth, 0.0f}, {kHalfWidth, 0.0f}, {kHalfWidth, kPlaneFar},
                              {-kHalfWidth, 0.0f}, {kHalfWidth, kPlaneFar}, {-kHalfWidth, kPlaneFar}},
                             {});
  Scene scene = emptyScene();
  scene.camera.far = 2.0f * kPlaneFar;
  Material material;
  material.diffuseMap = levelTexture(64, 64, levelColours);
  scene.materials.push_back(material);
  addNode(scene, std::move(plane), "floor", 0);
  RenderSettings settings = scene.settings;
  settings.view = View::Albedo;
  settings.cull = CullMode::None;

  const auto levelOf = [&](const Rgb& c) {
    for (std::size_t i = 0; i < levelColours.size(); ++i)
      if (levelColours[i] == c) return static_cast<int>(i);
    return -1;
  };
  constexpr int kColumn = kSide / 2;
  for (const TextureFilter filter : kAllTextureFilters) {
    settings.textureFilter = filter;
    const RenderOutput out = renderer_->render(scene, settings, kSide, kSide);
    std::vector<Rgb> column;  // bottom row first, covered pixels only
    for (int row = kSide - 1; row >= 0 && covered(out, kColumn, row); --row) column.push_back(rgbAt(out, kColumn, row));
    ASSERT_GE(column.size(), 20u) << toString(filter);
    if (!usesMipmaps(filter)) {
      for (const Rgb& c : column) EXPECT_EQ(levelOf(c), 0) << toString(filter) << ": " << str(c);
      continue;
    }
    // Far away the LOD is past the last level: every mipmapped filter reads it alone.
    EXPECT_EQ(levelOf(column.back()), 6) << toString(filter) << ": " << str(column.back());
    EXPECT_NE(levelOf(column.front()), 6) << toString(filter) << ": " << str(column.front());
    if (!levelsLinear(filter)) {
      // One level per pixel, never a smaller one below a larger one.
      int previous = 0;
      std::vector<bool> seen(levelColours.size(), false);
      for (std::size_t i = 0; i < column.size(); ++i) {
        const int level = levelOf(column[i]);
        ASSERT_GE(level, 0) << toString(filter) << " row " << kSide - 1 - static_cast<int>(i) << ": " << str(column[i]);
        EXPECT_GE(level, previous) << toString(filter) << " row " << kSide - 1 - static_cast<int>(i);
        previous = level;
        seen[static_cast<std::size_t>(level)] = true;
      }
      EXPECT_GE(std::count(seen.begin(), seen.end(), true), 4) << toString(filter);
    } else {
      // Two levels blended: some pixels are no single level's colour.
      EXPECT_TRUE(std::any_of(column.begin(), column.end(), [&](const Rgb& c) { return levelOf(c) < 0; }))
          << toString(filter);
    }
  }
}

// (b) Compressed levels are all uploaded: a BC1 chain of solid blocks, one colour per level,
// read at a LOD of 0, 2 and 4 (the diffuse map's uv scale 1, 4, 16 on a 64-texel texture
// drawn over 64 pixels), with the mag filter nearest for nearest_mipmap_nearest.
TEST_F(GlTextures, CompressedMipChainIsUploadedLevelByLevel) {
  const std::uint16_t colours565[] = {0xF800, 0x07E0, 0x001F, 0xFFE0, 0x07FF, 0xF81F, 0xFFFF};  // 64 .. 1
  std::vector<std::vector<std::uint8_t>> levels;
  for (int level = 0, side = 64; level < 7; ++level, side = std::max(side / 2, 1)) {
    const int count = blocksAlong(side) * blocksAlong(side);
    std::vector<std::uint8_t> blocks(static_cast<std::size_t>(count * blockBytes(BlockFormat::Bc1)));
    for (int b = 0; b < count; ++b) putColourHalf(&blocks[static_cast<std::size_t>(b * 8)], colours565[level], 0, 0);
    levels.push_back(std::move(blocks));
  }
  const std::shared_ptr<Texture> texture = blockTexture(BlockFormat::Bc1, 64, 64, levels);
  ASSERT_EQ(texture->levelCount(), 7);
  RenderSettings settings = albedoNearest();
  settings.textureFilter = TextureFilter::NearestMipmapNearest;
  struct Case {
    float uvScale;
    int level;
  };
  for (const Case c : {Case{1.0f, 0}, Case{4.0f, 2}, Case{16.0f, 4}}) {
    auto scaled = std::make_shared<Texture>(*texture);
    scaled->options.uvScale = vec2(c.uvScale);
    Material material;
    material.diffuseMap = scaled;
    const RenderOutput out = renderQuad(material, settings);
    const std::uint8_t* want = scaled->levelTexels(c.level).data();
    for (const int probe : {8, 24, 40, 56}) {
      EXPECT_EQ(rgbAt(out, probe, probe), (Rgb{want[0], want[1], want[2]}))
          << "uv scale " << c.uvScale << ", expected level " << c.level;
    }
  }
}

// The mag filter follows the texel filter: nearest for nearest_mipmap_*, linear for
// linear_mipmap_* (a 2 x 1 black | white texture magnified over the quad).
TEST_F(GlTextures, MagFilterFollowsTheTexelFilter) {
  Material material;
  material.diffuseMap = levelTexture(2, 1, {{0, 0, 0}, {0, 0, 0}});
  auto ramp = std::make_shared<Texture>(*material.diffuseMap);
  ramp->rgba = {0, 0, 0, 255, 255, 255, 255, 255};
  material.diffuseMap = ramp;
  RenderSettings settings = albedoNearest();
  for (const TextureFilter filter : kAllTextureFilters) {
    settings.textureFilter = filter;
    const RenderOutput out = renderQuad(material, settings);
    // Column 31 is just left of u = 0.5: picked black, or blended nearly half grey.
    if (texelsLinear(filter)) {
      EXPECT_GT(pixel(out, 31, 32)[0], 100) << toString(filter);
    } else {
      EXPECT_EQ(pixel(out, 31, 32)[0], 0) << toString(filter);
    }
  }
}

// (c) Each wrap mode reaches GL: uv from -1 to 2 over the quad, a 2 x 2 texture of four
// colours, nearest; every pixel is the texel the mode picks. Changing the wrap on the same
// object between renders is seen too (the cache re-sets the parameter).
TEST_F(GlTextures, WrapModesPickTheTexelsGlDefines) {
  constexpr float kUvLow = -1.0f, kUvHigh = 2.0f;
  const Mesh mesh = makeTriangles(
      {{-2, -2, -2}, {2, -2, -2}, {2, 2, -2}, {-2, -2, -2}, {2, 2, -2}, {-2, 2, -2}},
      {{kUvLow, kUvLow}, {kUvHigh, kUvLow}, {kUvHigh, kUvHigh}, {kUvLow, kUvLow}, {kUvHigh, kUvHigh}, {kUvLow, kUvHigh}},
      {});
  const std::vector<Rgb> texels = {{255, 0, 0}, {0, 255, 0}, {0, 0, 255}, {255, 255, 255}};  // bottom row first
  const std::shared_ptr<Texture> texture = texelTexture(2, 2, texels);
  Material material;
  material.diffuseMap = texture;
  Scene scene = emptyScene();
  scene.materials.push_back(material);
  addNode(scene, mesh, "quad", 0);
  for (const TextureWrap wrap : {TextureWrap::ClampToEdge, TextureWrap::MirroredRepeat, TextureWrap::Repeat}) {
    texture->options.wrap = wrap;  // the same object each time
    const RenderOutput out = renderer_->render(scene, albedoNearest(), kSide, kSide);
    int mismatches = 0;
    for (int row = 0; row < kSide; ++row) {
      for (int x = 0; x < kSide; ++x) {
        const double u = kUvLow + (kUvHigh - kUvLow) * (x + 0.5) / kSide;
        const double v = kUvLow + (kUvHigh - kUvLow) * (kSide - 1 - row + 0.5) / kSide;
        const Rgb want = texels[static_cast<std::size_t>(wrappedTexel(v, 2, wrap) * 2 + wrappedTexel(u, 2, wrap))];
        if (rgbAt(out, x, row) != want && ++mismatches <= 4) {
          ADD_FAILURE() << toString(wrap) << " pixel (" << x << ", " << row << ") uv (" << u << ", " << v << "): gl "
                        << str(rgbAt(out, x, row)) << ", expected " << str(want);
        }
      }
    }
    EXPECT_EQ(mismatches, 0) << toString(wrap);
  }
}

// (d) sRGB: byte 128 decodes to linear 0.2158 -> 55 in the (linear) colour buffer; without
// srgb it stays 128. The sRGB S3TC formats decode the same way after the block decode.
TEST_F(GlTextures, SrgbTexturesAreDecodedToLinearBeforeShading) {
  const auto linearByte = [](int byte) { return static_cast<int>(std::lround(linearFromSrgb(byte / 255.0) * 255.0)); };
  ASSERT_EQ(linearByte(128), 55);
  auto grey = levelTexture(2, 2, {{128, 128, 128}, {128, 128, 128}});
  Material material;
  material.diffuseMap = grey;
  EXPECT_EQ(rgbAt(renderQuad(material, albedoNearest()), 32, 32), (Rgb{128, 128, 128}));
  auto srgbGrey = std::make_shared<Texture>(*grey);
  srgbGrey->options.srgb = true;
  material.diffuseMap = srgbGrey;
  EXPECT_EQ(rgbAt(renderQuad(material, albedoNearest()), 32, 32), (Rgb{55, 55, 55}));
  // The same object switched to sRGB in place is uploaded again in the sRGB format.
  grey->options.srgb = true;
  material.diffuseMap = grey;
  EXPECT_EQ(rgbAt(renderQuad(material, albedoNearest()), 32, 32), (Rgb{55, 55, 55}));

  for (const BlockFormat format : {BlockFormat::Bc1, BlockFormat::Bc2, BlockFormat::Bc3}) {
    std::vector<std::uint8_t> block(static_cast<std::size_t>(blockBytes(format)), 0xFF);  // BC2/3: alpha 255
    putColourHalf(&block[block.size() - 8], 0x8410, 0x8410, 0);  // (132, 130, 132)
    auto texture = blockTexture(format, 4, 4, {block});
    texture->options.srgb = true;
    material.diffuseMap = texture;
    const std::uint8_t* texel = texture->rgba.data();
    EXPECT_EQ(rgbAt(renderQuad(material, albedoNearest()), 32, 32),
              (Rgb{linearByte(texel[0]), linearByte(texel[1]), linearByte(texel[2])}))
        << toString(format);
  }
}

// The mapped-normal view of the quad (tangent +x, bitangent +y, normal +z) with a normal map
// of one texel.
class GlNormalMaps : public GlTextures {
 protected:
  Rgb mappedNormal(Material material) {
    RenderSettings settings;
    settings.view = View::MappedNormal;
    settings.textureFilter = TextureFilter::Nearest;
    return rgbAt(renderQuad(material, settings), 32, 32);
  }
  // (v + 1) / 2 * 255 of the normalised tangent-space normal, as the view shows it.
  static Rgb expectedColour(vec3 tangentNormal) {
    const vec3 n = glm::normalize(tangentNormal);
    return {static_cast<int>(std::lround((n.x + 1.0) * 0.5 * 255.0)), static_cast<int>(std::lround((n.y + 1.0) * 0.5 * 255.0)),
            static_cast<int>(std::lround((n.z + 1.0) * 0.5 * 255.0))};
  }
  static void expectNear(const Rgb& got, const Rgb& want, const std::string& what) {
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(got[c], want[c], 1) << what << ": gl " << str(got) << ", expected " << str(want);
  }
};

// Encoded (128, 204, 230): tangent normal (0.004, 0.6, 0.804), leaning towards +v.
constexpr Rgb kUpTexel = {128, 204, 230};
vec3 decoded(const Rgb& texel) { return vec3(texel[0], texel[1], texel[2]) * (2.0f / 255.0f) - vec3(1.0f); }

// (e) green down flips the normal's v component; up (the default) leaves it.
TEST_F(GlNormalMaps, GreenDownFlipsTheNormalMapsRelief) {
  Material material;
  auto up = texelTexture(1, 1, {kUpTexel});
  material.normalMap = up;
  const Rgb upColour = mappedNormal(material);
  expectNear(upColour, expectedColour(decoded(kUpTexel)), "green up");
  auto down = std::make_shared<Texture>(*up);
  down->options.green = GreenAxis::Down;
  material.normalMap = down;
  const Rgb downColour = mappedNormal(material);
  vec3 flipped = decoded(kUpTexel);
  flipped.y = -flipped.y;
  expectNear(downColour, expectedColour(flipped), "green down");
  EXPECT_GT(upColour[1], 200);
  EXPECT_LT(downColour[1], 55);
  EXPECT_EQ(upColour[0], downColour[0]);
  EXPECT_EQ(upColour[2], downColour[2]);
}

// normalStrength scales x and y before normalising: 0 flattens, 2 steepens.
TEST_F(GlNormalMaps, StrengthScalesTheTangentXY) {
  Material material;
  material.normalMap = texelTexture(1, 1, {kUpTexel});
  for (const float strength : {0.0f, 0.5f, 2.0f}) {
    material.normalStrength = strength;
    vec3 n = decoded(kUpTexel);
    n.x *= strength;
    n.y *= strength;
    expectNear(mappedNormal(material), expectedColour(n), "strength " + std::to_string(strength));
  }
}

// A BC5 normal map samples as (r, g, 0, 1): NORMAL_MAP_XY rebuilds z from x and y.
TEST_F(GlNormalMaps, TwoChannelNormalMapRebuildsZ) {
  std::vector<std::uint8_t> block(16);
  putValueHalf(block.data(), 128, 128, 0);      // red 128: x = 0.004
  putValueHalf(block.data() + 8, 51, 51, 0);    // green 51: y = -0.6
  Material material;
  material.normalMap = blockTexture(BlockFormat::Bc5, 4, 4, {block});
  const vec3 xy = decoded({128, 51, 0});
  const float z = std::sqrt(std::max(1.0f - (xy.x * xy.x + xy.y * xy.y), 0.0f));
  expectNear(mappedNormal(material), expectedColour(vec3(xy.x, xy.y, z)), "BC5");
}

// Each map's uv transform moves that map alone; the uv view keeps the untransformed uv.
TEST_F(GlTextures, PerMapUvTransformsMoveTheirMapOnly) {
  const std::vector<Rgb> texels = {{255, 0, 0}, {0, 255, 0}, {0, 0, 255}, {255, 255, 255}};  // bottom row first
  auto plain = texelTexture(2, 2, texels);
  Material material;
  material.diffuseMap = plain;
  // Pixel (16, 48): uv (0.258, 0.242), the bottom-left texel.
  EXPECT_EQ(rgbAt(renderQuad(material, albedoNearest()), 16, 48), texels[0]);
  auto shifted = std::make_shared<Texture>(*plain);
  shifted->options.uvOffset = vec2(0.5f, 0.0f);
  material.diffuseMap = shifted;
  EXPECT_EQ(rgbAt(renderQuad(material, albedoNearest()), 16, 48), texels[1]);
  auto scaled = std::make_shared<Texture>(*plain);
  scaled->options.uvScale = vec2(2.0f, 2.0f);  // uv (0.516, 0.484)
  material.diffuseMap = scaled;
  EXPECT_EQ(rgbAt(renderQuad(material, albedoNearest()), 16, 48), texels[1]);

  RenderSettings uvView = albedoNearest();
  uvView.view = View::Uv;
  material.diffuseMap = plain;
  const RenderOutput plainUv = renderQuad(material, uvView);
  material.diffuseMap = shifted;
  EXPECT_EQ(renderQuad(material, uvView).rgba, plainUv.rgba);

  // The normal map's own offset: left half flat (128, 128, 255) shows the right texel.
  auto normals = texelTexture(2, 1, {kUpTexel, {128, 128, 255}});
  Material bumpy;
  bumpy.normalMap = normals;
  RenderSettings mapped = albedoNearest();
  mapped.view = View::MappedNormal;
  const Rgb leftPlain = rgbAt(renderQuad(bumpy, mapped), 16, 32);
  auto normalsShifted = std::make_shared<Texture>(*normals);
  normalsShifted->options.uvOffset = vec2(0.5f, 0.0f);
  bumpy.normalMap = normalsShifted;
  const Rgb leftShifted = rgbAt(renderQuad(bumpy, mapped), 16, 32);
  EXPECT_GT(leftPlain[1], 200);
  EXPECT_NEAR(leftShifted[1], 128, 1);
}

// Every new define comes only with the material option that asks for it, so a material
// without them compiles the program it always did; all of them together compile and link.
TEST_F(GlTextures, PermutationDefinesOnlyWhenTheMaterialNeedsThem) {
  const RenderSettings settings;
  Material material;
  material.diffuseMap = texelTexture(1, 1, {{200, 100, 50}});
  material.normalMap = texelTexture(1, 1, {kUpTexel});
  material.specularMap = texelTexture(1, 1, {{255, 255, 255}});
  material.ks = vec3(0.5f);
  EXPECT_EQ(phongDefines(material, settings),
            (std::vector<std::string>{"HAS_DIFFUSE_MAP", "HAS_NORMAL_MAP", "HAS_SPECULAR_MAP", "VIEW_SHADED"}));

  Material plainStrength;
  plainStrength.normalStrength = 2.0f;  // no normal map: nothing to scale
  EXPECT_EQ(phongDefines(plainStrength, settings), (std::vector<std::string>{"VIEW_SHADED"}));

  auto withOptions = [](const std::shared_ptr<const Texture>& t, auto&& edit) {
    auto copy = std::make_shared<Texture>(*t);
    edit(*copy);
    return copy;
  };
  Material all = material;
  all.normalMap = withOptions(material.normalMap, [](Texture& t) {
    t.options.green = GreenAxis::Down;
    t.channels = TextureChannels::RedGreen;
    t.options.uvOffset = vec2(0.25f, 0.0f);
  });
  all.normalStrength = 0.5f;
  all.diffuseMap = withOptions(material.diffuseMap, [](Texture& t) { t.options.uvScale = vec2(2.0f, 1.0f); });
  all.specularMap = withOptions(material.specularMap, [](Texture& t) { t.options.uvOffset = vec2(0.0f, 0.5f); });
  const std::vector<std::string> defines = phongDefines(all, settings);
  for (const char* define : {"NORMAL_MAP_GREEN_DOWN", "NORMAL_MAP_XY", "NORMAL_MAP_STRENGTH", "DIFFUSE_UV_TRANSFORM",
                             "NORMAL_UV_TRANSFORM", "SPECULAR_UV_TRANSFORM"}) {
    EXPECT_NE(std::find(defines.begin(), defines.end(), define), defines.end()) << define;
  }
  // Every view compiles and draws the whole quad, and lights it the same in both spaces: the
  // quad is flat, so its tangent frame is exact.
  for (const View view : kAllViews) {
    RenderSettings s = settings;
    s.view = view;
    s.lightingSpace = LightingSpace::Tangent;
    RenderOutput tangent, world;
    ASSERT_NO_THROW(tangent = renderQuad(all, s)) << toString(view);
    s.lightingSpace = LightingSpace::World;
    ASSERT_NO_THROW(world = renderQuad(all, s)) << toString(view);
    for (const RenderOutput* out : {&tangent, &world}) {
      ASSERT_EQ(out->triangleId.size(), static_cast<std::size_t>(kSide) * kSide) << toString(view);
      EXPECT_EQ(std::count(out->triangleId.begin(), out->triangleId.end(), kNoTriangle), 0) << toString(view);
    }
    int largest = 0;
    for (std::size_t i = 0; i < tangent.rgba.size(); ++i) {
      if (i % 4 != 3) largest = std::max(largest, std::abs(int{tangent.rgba[i]} - int{world.rgba[i]}));
    }
    EXPECT_LE(largest, kLightingSpaceLevels) << toString(view) << ": tangent and world lighting differ";
  }
}

// Levels GL could not use (a mip not half the previous level, a compressed level of the
// wrong size, a compressed chain shorter than the texture's) are refused with a message
// rather than sampled as an incomplete (black) texture.
TEST_F(GlTextures, InconsistentLevelsAreRefused) {
  Material material;
  auto badMip = levelTexture(8, 8, {{1, 2, 3}, {4, 5, 6}});
  badMip->mips[0] = TextureLevel{3, 4, std::vector<std::uint8_t>(3 * 4 * 4, 0)};
  material.diffuseMap = badMip;
  EXPECT_THROW(renderQuad(material, albedoNearest()), InputError);

  auto shortBlocks = blockTexture(BlockFormat::Bc1, 8, 8, {std::vector<std::uint8_t>(4 * 8, 0)});
  shortBlocks->blockLevels[0].resize(3 * 8);
  material.diffuseMap = shortBlocks;
  EXPECT_THROW(renderQuad(material, albedoNearest()), InputError);

  auto missingLevel = blockTexture(BlockFormat::Bc1, 8, 8, {std::vector<std::uint8_t>(4 * 8, 0), std::vector<std::uint8_t>(8, 0)});
  missingLevel->blockLevels.pop_back();
  material.diffuseMap = missingLevel;
  EXPECT_THROW(renderQuad(material, albedoNearest()), InputError);
}

// The sampler alone, in an OSMesa context of this test: a full-screen triangle writes
// texture(tex, uv) into an RGBA8 framebuffer texel for texel, so alpha is compared too (the
// phong program always writes alpha 1). Textures go through GlUploadCache.
class GlRawSampling : public ::testing::Test {
 protected:
  void SetUp() override {
    try {
      context_ = std::make_unique<OsMesaContext>(OsMesaContextDesc{});
      context_->makeCurrent();
      OsMesaContext* raw = context_.get();
      loadCoreGl([raw](const char* name) { return raw->procAddress(name); }, "test context");
    } catch (const InputError& e) {
      TWR_MISSING_DEPENDENCY("OSMesa") << "no GL context: " << e.what();
    }
    cache_ = std::make_unique<GlUploadCache>();
    program_ = makeProgram();
  }
  void TearDown() override {
    program_.reset();
    cache_.reset();  // GL objects die while their context is current
    context_.reset();
  }

  static GlShader compile(GLenum type, const char* source) {
    GlShader shader(glCreateShader(type));
    glShaderSource(shader.id(), 1, &source, nullptr);
    glCompileShader(shader.id());
    GLint ok = 0;
    glGetShaderiv(shader.id(), GL_COMPILE_STATUS, &ok);
    EXPECT_EQ(ok, GL_TRUE);
    return shader;
  }
  static GlProgram makeProgram() {
    const GlShader vertex = compile(GL_VERTEX_SHADER, R"(#version 330 core
const vec2 kCorners[3] = vec2[3](vec2(-1.0, -1.0), vec2(3.0, -1.0), vec2(-1.0, 3.0));
void main() { gl_Position = vec4(kCorners[gl_VertexID], 0.0, 1.0); })");
    const GlShader fragment = compile(GL_FRAGMENT_SHADER, R"(#version 330 core
uniform sampler2D tex;
uniform vec2 size;
out vec4 colour;
void main() { colour = texture(tex, gl_FragCoord.xy / size); })");
    GlProgram program(glCreateProgram());
    glAttachShader(program.id(), vertex.id());
    glAttachShader(program.id(), fragment.id());
    glLinkProgram(program.id());
    GLint ok = 0;
    glGetProgramiv(program.id(), GL_LINK_STATUS, &ok);
    EXPECT_EQ(ok, GL_TRUE);
    return program;
  }

  // The texture's level 0 sampled nearest at every texel centre, rows bottom first.
  std::vector<std::uint8_t> sampleLevel0(const std::shared_ptr<const Texture>& texture) {
    const int width = texture->width, height = texture->height;
    GlRenderbuffer colour = makeGlRenderbuffer();
    glBindRenderbuffer(GL_RENDERBUFFER, colour.id());
    glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, width, height);
    GlFramebuffer framebuffer = makeGlFramebuffer();
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer.id());
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, colour.id());
    EXPECT_EQ(glCheckFramebufferStatus(GL_FRAMEBUFFER), static_cast<GLenum>(GL_FRAMEBUFFER_COMPLETE));
    glViewport(0, 0, width, height);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_BLEND);
    glUseProgram(program_.id());
    glActiveTexture(GL_TEXTURE0);
    cache_->beginFrame();
    cache_->texture(texture, TextureFilter::Nearest);
    glUniform1i(glGetUniformLocation(program_.id(), "tex"), 0);
    glUniform2f(glGetUniformLocation(program_.id(), "size"), static_cast<float>(width), static_cast<float>(height));
    GlVertexArray vertexArray = makeGlVertexArray();  // core profile: a draw needs one bound
    glBindVertexArray(vertexArray.id());
    glDrawArrays(GL_TRIANGLES, 0, 3);
    std::vector<std::uint8_t> out(static_cast<std::size_t>(width) * height * 4);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, out.data());
    cache_->endFrame();
    glBindVertexArray(0);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
    return out;
  }

  std::unique_ptr<OsMesaContext> context_;
  std::unique_ptr<GlUploadCache> cache_;
  GlProgram program_;
};

// (a) with alpha: all four channels of every texel of every block format. BC4 and BC5 come
// back as (r, 0, 0, 1) and (r, g, 0, 1), as decodeBlockLevel gives them.
TEST_F(GlRawSampling, BlockFormatsDecodeAsTheCpuDoesInAllFourChannels) {
  constexpr int kTexels = 64;
  for (const BlockFormat format : kAllBlockFormats) {
    const int blockCount = blocksAlong(kTexels) * blocksAlong(kTexels);
    auto texture = blockTexture(format, kTexels, kTexels, {testBlocks(format, blockCount, 7000u + static_cast<std::uint32_t>(format))});
    const std::vector<std::uint8_t> got = sampleLevel0(texture);
    const std::vector<std::uint8_t>& want = texture->rgba;
    ASSERT_EQ(got.size(), want.size());
    int mismatches = 0;
    std::array<int, 4> maxDifference{};
    std::ostringstream firstOnes;
    for (int t = 0; t < kTexels * kTexels; ++t) {
      bool same = true;
      for (int c = 0; c < 4; ++c) {
        const int d = std::abs(int(got[static_cast<std::size_t>(t * 4 + c)]) - int(want[static_cast<std::size_t>(t * 4 + c)]));
        maxDifference[static_cast<std::size_t>(c)] = std::max(maxDifference[static_cast<std::size_t>(c)], d);
        same = same && d == 0;
      }
      if (!same && ++mismatches <= 8) {
        const int x = t % kTexels, y = t / kTexels;
        firstOnes << "\n  texel (" << x << ", " << y << ") block " << (y / 4) * (kTexels / 4) + x / 4 << ": gl";
        for (int c = 0; c < 4; ++c) firstOnes << " " << int(got[static_cast<std::size_t>(t * 4 + c)]);
        firstOnes << ", cpu";
        for (int c = 0; c < 4; ++c) firstOnes << " " << int(want[static_cast<std::size_t>(t * 4 + c)]);
      }
    }
    EXPECT_EQ(mismatches, 0) << toString(format) << ": " << mismatches << " texels differ, by up to (r, g, b, a) = ("
                             << maxDifference[0] << ", " << maxDifference[1] << ", " << maxDifference[2] << ", "
                             << maxDifference[3] << ")" << firstOnes.str();
  }
}

// The anisotropy helper sets the parameter when the context offers the extension (llvmpipe
// does), clamped to the driver's most; it is not called by the renderer yet.
TEST_F(GlRawSampling, AnisotropyHelperSetsTheParameterWhenOffered) {
  auto texture = levelTexture(4, 4, {{1, 2, 3}});
  glActiveTexture(GL_TEXTURE0);
  cache_->beginFrame();
  cache_->texture(texture, TextureFilter::Trilinear);
  const bool offered = setGlTextureAnisotropy(4.0f);
  if (offered) {
    GLfloat most = 0.0f, set = 0.0f;
    glGetFloatv(GL_MAX_TEXTURE_MAX_ANISOTROPY, &most);
    glGetTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_MAX_ANISOTROPY, &set);
    EXPECT_EQ(set, std::min(4.0f, most));
    std::printf("GL_MAX_TEXTURE_MAX_ANISOTROPY = %g\n", static_cast<double>(most));
  } else {
    std::printf("no EXT/ARB_texture_filter_anisotropic in this context\n");
  }
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
  cache_->endFrame();
}

}  // namespace
}  // namespace twr
