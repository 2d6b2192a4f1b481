// Texture files as real assets ship them: DDS (BC1-BC5 with their mip chains, uncompressed
// masks, DX10 headers), BMP and TGA, Radiance HDR, the mip chain built for files without one,
// texture options in scene files, and OBJ/MTL maps (node materials, "mtl": false, options,
// height maps, warnings for what is not drawn). DDS files are written here byte by byte from
// Microsoft's layout; BMP, TGA and a second set of DDS files come from ImageMagick when it is
// installed (CI installs it), so files written by another tool go through the same loaders.
#include "scene/block_compression.h"
#include "scene/dds.h"
#include "scene/errors.h"
#include "scene/image.h"
#include "scene/obj_loader.h"
#include "scene/scene_file.h"
#include "scene/texture.h"
#include "tests/missing_dependency.h"

#include <gtest/gtest.h>
#include <stb_image_write.h>

#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <random>
#include <string>
#include <vector>

namespace twr {
namespace {

namespace fs = std::filesystem;
using Bytes = std::vector<std::uint8_t>;

fs::path caseDir() {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  const fs::path dir =
      fs::path(TWINRASTER_TEST_OUT) / "texture_formats" / (std::string(info->test_suite_name()) + "." + info->name());
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

std::string writeFile(const fs::path& path, const Bytes& bytes) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
  return path.string();
}

std::string writeText(const fs::path& path, const std::string& text) { return writeFile(path, Bytes(text.begin(), text.end())); }

template <typename F>
std::string errorOf(F&& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  ADD_FAILURE() << "expected an InputError";
  return "";
}

void put32(Bytes& b, std::size_t at, std::uint32_t v) {
  for (int i = 0; i < 4; ++i) b[at + static_cast<std::size_t>(i)] = static_cast<std::uint8_t>(v >> (8 * i));
}

// A DDS header (128 bytes) for a FourCC or a masked RGB layout.
Bytes ddsHeader(int width, int height, int mipCount, const char* fourCc, std::uint32_t bitCount = 0,
                std::array<std::uint32_t, 4> masks = {}) {
  Bytes b(128, 0);
  std::memcpy(b.data(), "DDS ", 4);
  put32(b, 4, 124);
  put32(b, 8, 0x1007 | (mipCount > 1 ? 0x20000u : 0u));
  put32(b, 12, static_cast<std::uint32_t>(height));
  put32(b, 16, static_cast<std::uint32_t>(width));
  put32(b, 28, static_cast<std::uint32_t>(mipCount));
  put32(b, 76, 32);
  if (fourCc) {
    put32(b, 80, 0x4);
    std::memcpy(&b[84], fourCc, 4);
  } else {
    put32(b, 80, 0x40 | (masks[3] ? 0x1u : 0u));
    put32(b, 88, bitCount);
    for (int i = 0; i < 4; ++i) put32(b, 92 + 4 * static_cast<std::size_t>(i), masks[static_cast<std::size_t>(i)]);
  }
  put32(b, 108, 0x1000 | (mipCount > 1 ? 0x400008u : 0u));
  return b;
}

Bytes randomBytes(std::size_t n, std::uint32_t seed) {
  std::mt19937 rng(seed);
  Bytes b(n);
  for (auto& v : b) v = static_cast<std::uint8_t>(rng());
  return b;
}

// ---- block decoding: hand-worked blocks ----

TEST(BlockDecode, Bc1FourColourModeUsesLlvmpipesEightBitLerps) {
  // c0 = pure red (0xF800) > c1 = pure blue (0x001F); indices: texel t takes t % 4.
  const std::uint8_t block[8] = {0x00, 0xF8, 0x1F, 0x00, 0xE4, 0xE4, 0xE4, 0xE4};
  const BlockTexels t = decodeBlock(BlockFormat::Bc1, block);
  EXPECT_EQ(t[0][0], 255);
  EXPECT_EQ(t[1][2], 255);
  // lerp8(85, 255, 0) = 255 + ((85 * -255) >> 8) = 255 - 85 = 170; the textbook (2 * 255 + 0) / 3 = 170 too,
  // but blue: lerp8(85, 0, 255) = (85 * 255) >> 8 = 84, where (0 * 2 + 255) / 3 = 85.
  EXPECT_EQ(t[2][0], 170);
  EXPECT_EQ(t[2][2], 84);
  EXPECT_EQ(t[3][0], 255 + ((170 * -255) >> 8));
  EXPECT_EQ(t[3][2], (170 * 255) >> 8);
  EXPECT_EQ(t[3][3], 255);
}

TEST(BlockDecode, Bc1ThreeColourModeHasTransparentBlack) {
  // c0 = blue < c1 = red: index 2 = rounded average, index 3 = transparent black.
  const std::uint8_t block[8] = {0x1F, 0x00, 0x00, 0xF8, 0xE4, 0xE4, 0xE4, 0xE4};
  const BlockTexels t = decodeBlock(BlockFormat::Bc1, block);
  EXPECT_EQ(t[2][0], (0 + 255 + 1) >> 1);
  EXPECT_EQ(t[2][2], (255 + 0 + 1) >> 1);
  EXPECT_EQ(t[3][0], 0);
  EXPECT_EQ(t[3][3], 0);
}

TEST(BlockDecode, Bc3AlphaAndBc4ValuesInterpolate) {
  // a0 = 255 > a1 = 0, all 16 indices 2: lerp8(36, 255, 0) = 255 + ((36 * -255) >> 8) = 219.
  std::uint8_t bc4[8] = {255, 0, 0, 0, 0, 0, 0, 0};
  std::uint64_t bits = 0;
  for (int i = 0; i < 16; ++i) bits |= std::uint64_t{2} << (3 * i);
  for (int i = 0; i < 6; ++i) bc4[2 + i] = static_cast<std::uint8_t>(bits >> (8 * i));
  const BlockTexels r = decodeBlock(BlockFormat::Bc4, bc4);
  EXPECT_EQ(r[5][0], 255 + ((36 * -255) >> 8));
  EXPECT_EQ(r[5][1], 0);
  EXPECT_EQ(r[5][3], 255);
  // a0 <= a1: index 6 is 0, index 7 is 255.
  std::uint8_t six[8] = {10, 20, 0, 0, 0, 0, 0, 0};
  std::uint64_t sixBits = (std::uint64_t{6}) | (std::uint64_t{7} << 3);
  for (int i = 0; i < 6; ++i) six[2 + i] = static_cast<std::uint8_t>(sixBits >> (8 * i));
  const BlockTexels s = decodeBlock(BlockFormat::Bc4, six);
  EXPECT_EQ(s[0][0], 0);
  EXPECT_EQ(s[1][0], 255);
  EXPECT_EQ(s[2][0], 10);
}

TEST(BlockDecode, FlippingBlockRowsIsDecodingThenFlipping) {
  for (BlockFormat format : {BlockFormat::Bc1, BlockFormat::Bc2, BlockFormat::Bc3, BlockFormat::Bc4, BlockFormat::Bc5}) {
    for (const auto& [w, h] : {std::pair{8, 8}, std::pair{12, 4}, std::pair{5, 2}, std::pair{4, 1}, std::pair{16, 12}}) {
      const Bytes blocks = randomBytes(blockLevelBytes(format, w, h), 7u + static_cast<std::uint32_t>(w * h));
      const std::vector<std::uint8_t> decoded = decodeBlockLevel(format, w, h, blocks.data());
      const auto flipped = flipBlockLevelRows(format, w, h, blocks.data());
      ASSERT_TRUE(flipped.has_value()) << toString(format) << " " << w << "x" << h;
      const std::vector<std::uint8_t> decodedFlipped = decodeBlockLevel(format, w, h, flipped->data());
      for (int y = 0; y < h; ++y) {
        ASSERT_EQ(0, std::memcmp(&decodedFlipped[static_cast<std::size_t>(y * w) * 4],
                                 &decoded[static_cast<std::size_t>((h - 1 - y) * w) * 4], static_cast<std::size_t>(w) * 4))
            << toString(format) << " " << w << "x" << h << " row " << y;
      }
    }
  }
  const Bytes blocks = randomBytes(blockLevelBytes(BlockFormat::Bc1, 8, 6), 3);
  EXPECT_FALSE(flipBlockLevelRows(BlockFormat::Bc1, 8, 6, blocks.data()).has_value());  // rows cross blocks
}

// ---- DDS files ----

TEST(Dds, Dxt3WithItsMipChainLoadsEveryLevelBottomRowFirst) {
  const int w = 16, h = 8;
  Bytes file = ddsHeader(w, h, 5, "DXT3");
  std::vector<Bytes> levels;
  int lw = w, lh = h;
  for (int l = 0; l < 5; ++l) {
    levels.push_back(randomBytes(blockLevelBytes(BlockFormat::Bc2, lw, lh), 100u + static_cast<std::uint32_t>(l)));
    file.insert(file.end(), levels.back().begin(), levels.back().end());
    lw = std::max(1, lw / 2);
    lh = std::max(1, lh / 2);
  }
  const std::string path = writeFile(caseDir() / "chain.dds", file);
  const Texture texture = loadTexture(path);
  EXPECT_EQ(texture.formatName, "DDS BC2 (DXT3)");
  ASSERT_EQ(texture.levelCount(), 5);
  EXPECT_EQ(texture.mipSource, MipSource::File);
  ASSERT_TRUE(texture.blockFormat.has_value());
  EXPECT_EQ(*texture.blockFormat, BlockFormat::Bc2);
  ASSERT_EQ(texture.blockLevels.size(), 5u);
  lw = w;
  lh = h;
  for (int l = 0; l < 5; ++l) {
    ASSERT_EQ(texture.levelWidth(l), lw);
    ASSERT_EQ(texture.levelHeight(l), lh);
    const std::vector<std::uint8_t> fileOrder = decodeBlockLevel(BlockFormat::Bc2, lw, lh, levels[static_cast<std::size_t>(l)].data());
    const std::vector<std::uint8_t>& texels = texture.levelTexels(l);
    // The file's first row is the top (v = 1): texture row 0 is the file's last row.
    for (int y = 0; y < lh; ++y) {
      ASSERT_EQ(0, std::memcmp(&texels[static_cast<std::size_t>(y * lw) * 4],
                               &fileOrder[static_cast<std::size_t>((lh - 1 - y) * lw) * 4], static_cast<std::size_t>(lw) * 4))
          << "level " << l << " row " << y;
    }
    // The blocks GL receives decode to exactly those texels.
    EXPECT_EQ(decodeBlockLevel(BlockFormat::Bc2, lw, lh, texture.blockLevels[static_cast<std::size_t>(l)].data()), texels);
    lw = std::max(1, lw / 2);
    lh = std::max(1, lh / 2);
  }
}

TEST(Dds, FlipVKeepsTheFilesRowOrder) {
  Bytes file = ddsHeader(4, 4, 1, "DXT1");
  const Bytes block = randomBytes(8, 5);
  file.insert(file.end(), block.begin(), block.end());
  const std::string path = writeFile(caseDir() / "one.dds", file);
  TextureOptions options;
  options.flipV = true;
  std::uintmax_t budget = kMaxSceneTextureBytes;
  const Texture texture = loadTexture(path, options, budget);
  EXPECT_EQ(std::vector<std::uint8_t>(texture.rgba), decodeBlockLevel(BlockFormat::Bc1, 4, 4, block.data()));
  // One level in the file: the chain is built, and GL gets decoded texels for every level.
  EXPECT_EQ(texture.mipSource, MipSource::Built);
  EXPECT_FALSE(texture.blockFormat.has_value());
}

TEST(Dds, UncompressedMasksAndDx10Headers) {
  // 32-bit BGRA masks, as ImageMagick writes uncompressed DDS.
  Bytes file = ddsHeader(2, 1, 1, nullptr, 32, {0x00FF0000, 0x0000FF00, 0x000000FF, 0xFF000000});
  const Bytes texels = {10, 20, 30, 40, 50, 60, 70, 80};  // B G R A, B G R A
  file.insert(file.end(), texels.begin(), texels.end());
  const Texture t = loadTexture(writeFile(caseDir() / "bgra.dds", file));
  EXPECT_EQ(t.rgba, (std::vector<std::uint8_t>{30, 20, 10, 40, 70, 60, 50, 80}));
  // 16-bit 565: widened by rounding v * 255 / max.
  Bytes f565 = ddsHeader(1, 1, 1, nullptr, 16, {0xF800, 0x07E0, 0x001F, 0});
  f565.push_back(0x10);  // r = 0, g = 0b000000 -> low bits: 0x0010 = b 16
  f565.push_back(0x00);
  const Texture t565 = loadTexture(writeFile(caseDir() / "565.dds", f565));
  EXPECT_EQ(t565.rgba, (std::vector<std::uint8_t>{0, 0, static_cast<std::uint8_t>((16 * 255 + 15) / 31), 255}));
  // A DX10 header naming BC5: two channels.
  Bytes dx10 = ddsHeader(4, 4, 1, "DX10");
  Bytes extra(20, 0);
  put32(extra, 0, 83);  // DXGI_FORMAT_BC5_UNORM
  put32(extra, 4, 3);   // texture 2D
  put32(extra, 12, 1);  // array size
  dx10.insert(dx10.end(), extra.begin(), extra.end());
  const Bytes bc5 = randomBytes(16, 9);
  dx10.insert(dx10.end(), bc5.begin(), bc5.end());
  const Texture t5 = loadTexture(writeFile(caseDir() / "bc5.dds", dx10));
  EXPECT_EQ(t5.channels, TextureChannels::RedGreen);
  EXPECT_EQ(t5.formatName, "DDS BC5 (RGTC2, ATI2)");
}

TEST(Dds, BadFilesNameTheFileAndTheProblem) {
  const fs::path dir = caseDir();
  Bytes truncated = ddsHeader(8, 8, 4, "DXT5");
  truncated.resize(128 + 64 + 10);  // level 0 is 64 bytes, level 1 needs 16
  std::string path = writeFile(dir / "truncated.dds", truncated);
  std::string message = errorOf([&] { loadTexture(path); });
  EXPECT_EQ(message.rfind(path + ": DDS: the file ends inside mip level 1", 0), 0u) << message;

  Bytes cube = ddsHeader(4, 4, 1, "DXT1");
  put32(cube, 112, 0x200);
  path = writeFile(dir / "cube.dds", cube);
  EXPECT_NE(errorOf([&] { loadTexture(path); }).find("a cube map"), std::string::npos);

  Bytes bc7 = ddsHeader(4, 4, 1, "DX10");
  Bytes extra(20, 0);
  put32(extra, 0, 98);
  put32(extra, 4, 3);
  bc7.insert(bc7.end(), extra.begin(), extra.end());
  path = writeFile(dir / "bc7.dds", bc7);
  EXPECT_NE(errorOf([&] { loadTexture(path); }).find("BC7 is not read"), std::string::npos);

  Bytes unknown = ddsHeader(4, 4, 1, "XYZW");
  path = writeFile(dir / "unknown.dds", unknown);
  EXPECT_NE(errorOf([&] { loadTexture(path); }).find("FourCC 'XYZW'"), std::string::npos);

  Bytes huge = ddsHeader(100000, 4, 1, "DXT1");
  path = writeFile(dir / "huge.dds", huge);
  EXPECT_NE(errorOf([&] { loadTexture(path); }).find("expected each side in [1, 16384]"), std::string::npos);

  Bytes header = ddsHeader(4, 4, 1, "DXT1");
  header.resize(60);
  path = writeFile(dir / "short.dds", header);
  EXPECT_NE(errorOf([&] { loadTexture(path); }).find("ends inside its header"), std::string::npos);
}

TEST(Dds, ExtraLevelsAndTrailingBytesAreWarnings) {
  Bytes file = ddsHeader(4, 2, 9, "DXT1");  // a 4x2 chain has 3 levels
  for (int l = 0; l < 3; ++l) {
    const Bytes b = randomBytes(8, 20u + static_cast<std::uint32_t>(l));
    file.insert(file.end(), b.begin(), b.end());
  }
  file.push_back(0);
  const Texture t = loadTexture(writeFile(caseDir() / "extra.dds", file));
  EXPECT_EQ(t.levelCount(), 3);
  ASSERT_EQ(t.warnings.size(), 2u);
  EXPECT_NE(t.warnings[0].find("declares 9 mip levels"), std::string::npos) << t.warnings[0];
  EXPECT_NE(t.warnings[1].find("1 bytes after the last mip level"), std::string::npos) << t.warnings[1];
}

// ---- the built chain ----

TEST(MipChain, EvenSidesAverageTwoByTwoOddSidesSpreadTheirTexels) {
  Texture t;
  t.width = 4;
  t.height = 2;
  t.rgba = {0, 0, 0, 255, 100, 0, 0, 255, 200, 0, 0, 255, 255, 0, 0, 255,
            0, 0, 0, 255, 100, 0, 0, 255, 200, 0, 0, 255, 255, 0, 0, 255};
  buildMipChain(t);
  ASSERT_EQ(t.levelCount(), 3);
  EXPECT_EQ(t.levelWidth(1), 2);
  EXPECT_EQ(t.levelHeight(1), 1);
  EXPECT_EQ(t.levelTexels(1)[0], 50);
  EXPECT_EQ(t.levelTexels(1)[4], 228);  // (200 + 255) / 2 = 227.5, rounded half away from zero
  EXPECT_EQ(t.levelTexels(2)[0], 139);  // (0 + 100 + 200 + 255) / 4 = 138.75
  // 3 -> 1: each texel weighs a third.
  Texture odd;
  odd.width = 3;
  odd.height = 1;
  odd.rgba = {0, 0, 0, 0, 30, 0, 0, 0, 90, 0, 0, 0};
  buildMipChain(odd);
  ASSERT_EQ(odd.levelCount(), 2);
  EXPECT_EQ(odd.levelTexels(1)[0], 40);
}

TEST(MipChain, SrgbAveragesLinearLight) {
  Texture t;
  t.width = 2;
  t.height = 1;
  t.rgba = {0, 0, 0, 0, 255, 255, 255, 255};
  t.options.srgb = true;
  buildMipChain(t);
  // Half of white in linear light is 0.5, encoded 188; averaging the bytes would give 128.
  EXPECT_EQ(t.levelTexels(1)[0], 188);
  EXPECT_EQ(t.levelTexels(1)[3], 128);  // alpha averages linearly
}

// ---- other formats ----

TEST(ImageFormats, HdrIsRefusedAsAMaterialMapAndReadAsFloats) {
  const std::string hdr = "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 1 +X 2\n";
  Bytes bytes(hdr.begin(), hdr.end());
  // Flat RGBE: (128, 64, 32, 129) = (1, 0.5, 0.25) * 2^(129 - 136) * 256 ... = 0.5 ... per stb
  for (std::uint8_t v : {128, 64, 32, 129, 128, 128, 128, 128}) bytes.push_back(v);
  const std::string path = writeFile(caseDir() / "sky.hdr", bytes);
  EXPECT_NE(errorOf([&] { loadTexture(path); }).find("floating-point texels"), std::string::npos);
  const ImageF image = loadHdrImage(path);
  ASSERT_EQ(image.width, 2);
  ASSERT_EQ(image.height, 1);
  // RGBE: value = (mantissa + 0.5) / 256 * 2^(e - 128) as stb decodes it... check ratios only.
  EXPECT_GT(image.rgba[0], 0.0f);
  EXPECT_NEAR(image.rgba[1] / image.rgba[0], 64.0f / 128.0f, 0.01f);
  EXPECT_FLOAT_EQ(image.rgba[3], 1.0f);
}

TEST(ImageFormats, UnknownAndRefusedFormatsSayWhatIsRead) {
  const fs::path dir = caseDir();
  const std::string gif = writeText(dir / "a.gif", "GIF89a\x01\x00\x01\x00");
  EXPECT_NE(errorOf([&] { loadImage(gif); }).find("PNG, JPEG, BMP, TGA, DDS or Radiance HDR"), std::string::npos);
  const std::string junk = writeText(dir / "junk.tga", "this is not an image at all");
  EXPECT_NE(errorOf([&] { loadImage(junk); }).find("not a TGA header either"), std::string::npos);
}

// ImageMagick writes BMP, TGA and DDS; skipped when `convert` is missing (CI installs it).
bool haveImageMagick() { return std::system("convert -version > /dev/null 2>&1") == 0; }

TEST(ImageFormats, FilesWrittenByImageMagickLoadAsThePngTheyCameFrom) {
  if (!haveImageMagick()) TWR_MISSING_DEPENDENCY("ImageMagick") << "its convert is not installed (apt-get install imagemagick)";
  const fs::path dir = caseDir();
  // A 8x4 gradient with every channel different, written as PNG by stb, converted by ImageMagick.
  Image source = makeImage(8, 4);
  for (int y = 0; y < 4; ++y) {
    for (int x = 0; x < 8; ++x) {
      std::uint8_t* p = source.pixel(x, y);
      p[0] = static_cast<std::uint8_t>(x * 30);
      p[1] = static_cast<std::uint8_t>(y * 60);
      p[2] = static_cast<std::uint8_t>(255 - x * 20);
      p[3] = 255;
    }
  }
  const std::string png = (dir / "source.png").string();
  savePng(png, source);
  const struct {
    const char* name;
    const char* options;
  } targets[] = {{"a.bmp", "-type TrueColor"},       {"b24.bmp", "-type TrueColor -define bmp:format=bmp3"},
                 // ImageMagick 6.9 stores a PNG's rows top first under a TGA header that says
                 // bottom first (ImageMagick issue 5148); -flip makes the file say what it holds.
                 {"c.tga", "-flip -type TrueColor"},  {"d_rle.tga", "-flip -compress RLE"},
                 {"e.dds", "-define dds:compression=none"}};
  for (const auto& target : targets) {
    const std::string out = (dir / target.name).string();
    const std::string command = "convert " + png + " -alpha off " + target.options + " " + out + " 2>&1";
    ASSERT_EQ(std::system(command.c_str()), 0) << command;
    const Image image = loadImage(out);
    ASSERT_EQ(image.width, 8) << target.name;
    ASSERT_EQ(image.height, 4) << target.name;
    for (int y = 0; y < 4; ++y) {
      for (int x = 0; x < 8; ++x) {
        for (int c = 0; c < 3; ++c) {
          ASSERT_EQ(image.pixel(x, y)[c], source.pixel(x, y)[c]) << target.name << " at " << x << "," << y << " channel " << c;
        }
      }
    }
  }
  // DXT1 with mipmaps, as tools write real assets: the chain comes from the file.
  const std::string dxt = (dir / "f.dds").string();
  ASSERT_EQ(std::system(("convert " + png + " -define dds:compression=dxt1 -define dds:mipmaps=3 " + dxt).c_str()), 0);
  const Texture t = loadTexture(dxt);
  EXPECT_EQ(t.formatName, "DDS BC1 (DXT1)");
  EXPECT_EQ(t.levelCount(), 4);
  EXPECT_EQ(t.mipSource, MipSource::File);
  EXPECT_TRUE(t.blockFormat.has_value());
}

// ---- scene files and OBJ/MTL ----

TEST(TextureOptions, SceneFileObjectsAreReadAndSharedPerOptionSet) {
  const fs::path dir = caseDir();
  Image image = makeImage(2, 2, 0x808080FF);
  savePng((dir / "t.png").string(), image);
  const std::string scene = writeText(dir / "s.json", R"({
    "materials": {
      "a": {"diffuse_map": "t.png", "normal_map": {"path": "t.png", "green": "down", "wrap": "clamp_to_edge"}},
      "b": {"diffuse_map": {"path": "t.png"}, "specular_map": {"path": "t.png", "srgb": true, "flip_v": true,
                                                                "wrap": "mirrored_repeat"}}
    },
    "settings": {"texture_filter": "trilinear", "anisotropy": 4},
    "nodes": []
  })");
  const Scene s = loadSceneFile(scene);
  ASSERT_EQ(s.materials.size(), 2u);
  const Material& a = s.materials[0];
  const Material& b = s.materials[1];
  EXPECT_EQ(a.diffuseMap, b.diffuseMap);  // same file, same options: one texture
  EXPECT_NE(a.diffuseMap, a.normalMap);
  EXPECT_EQ(a.normalMap->options.green, GreenAxis::Down);
  EXPECT_EQ(a.normalMap->options.wrap, TextureWrap::ClampToEdge);
  EXPECT_TRUE(b.specularMap->options.srgb);
  EXPECT_TRUE(b.specularMap->options.flipV);
  EXPECT_EQ(b.specularMap->options.wrap, TextureWrap::MirroredRepeat);
  EXPECT_EQ(s.settings.textureFilter, TextureFilter::Trilinear);
  EXPECT_FLOAT_EQ(s.settings.anisotropy, 4.0f);
  EXPECT_EQ(a.diffuseMap->levelCount(), 2);
}

TEST(TextureOptions, BadOptionsNameTheKey) {
  const fs::path dir = caseDir();
  savePng((dir / "t.png").string(), makeImage(1, 1));
  const auto messageFor = [&](const std::string& material, const std::string& settings = "{}") {
    const std::string path = writeText(dir / "s.json", R"({"materials": {"m": )" + material + R"(}, "settings": )" +
                                                             settings + R"(, "nodes": []})");
    return errorOf([&] { loadSceneFile(path); });
  };
  EXPECT_NE(messageFor(R"({"diffuse_map": {"path": "t.png", "green": "down"}})").find("materials.m.diffuse_map.green"),
            std::string::npos);
  EXPECT_NE(messageFor(R"({"diffuse_map": {"path": "t.png", "wrap": "clamp"}})").find("repeat|mirrored_repeat|clamp_to_edge"),
            std::string::npos);
  EXPECT_NE(messageFor(R"({"diffuse_map": {"wrap": "repeat"}})").find("materials.m.diffuse_map.path: missing"),
            std::string::npos);
  EXPECT_NE(messageFor(R"({"diffuse_map": 3})").find("or an object"), std::string::npos);
  EXPECT_NE(messageFor("{}", R"({"texture_filter": "cubic"})").find("nearest_mipmap_linear"), std::string::npos);
  EXPECT_NE(messageFor("{}", R"({"anisotropy": 32})").find("settings.anisotropy"), std::string::npos);
}

struct ObjFiles {
  std::string obj, mtl;
};

ObjFiles writeObj(const fs::path& dir, const std::string& mtlBody) {
  ObjFiles f;
  f.mtl = writeText(dir / "m.mtl", mtlBody);
  f.obj = writeText(dir / "m.obj", "mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 0 1\nusemtl mat\nf 1/1 2/2 3/3\n");
  return f;
}

TEST(ObjMaterials, ANodeMaterialMeansTheMtlsMissingMapsAreNeverOpened) {
  const fs::path dir = caseDir();
  const ObjFiles f = writeObj(dir, "newmtl mat\nKd 1 1 1\nmap_Kd missing.png\n");
  const std::string withOwn = writeText(dir / "own.json", R"({"materials": {"mine": {"kd": [1, 0, 0]}},
    "nodes": [{"mesh": {"type": "obj", "path": "m.obj"}, "material": "mine"}]})");
  const Scene s = loadSceneFile(withOwn);
  ASSERT_EQ(s.nodes.size(), 1u);
  // Without one, the missing map is an error naming it.
  const std::string without = writeText(dir / "without.json", R"({"nodes": [{"mesh": {"type": "obj", "path": "m.obj"}}]})");
  EXPECT_NE(errorOf([&] { loadSceneFile(without); }).find("missing.png"), std::string::npos);
  // "mtl": false ignores the MTL altogether.
  const std::string noMtl = writeText(dir / "nomtl.json", R"({"nodes": [{"mesh": {"type": "obj", "path": "m.obj", "mtl": false}}]})");
  const Scene plain = loadSceneFile(noMtl);
  EXPECT_TRUE(plain.materials.empty());
}

TEST(ObjMaterials, OptionsHeightMapsAndWarnings) {
  const fs::path dir = caseDir();
  savePng((dir / "grey.png").string(), makeImage(2, 2, 0x404040FF));
  savePng((dir / "normal.png").string(), makeImage(2, 2, 0x8080FFFF));
  const ObjFiles f = writeObj(dir,
                              "newmtl mat\n"
                              "Kd 1 1 1\n"
                              "d 1\n"
                              "illum 2\n"
                              "Ni 1.45\n"
                              "d 0.5\n"
                              "map_Kd -s 2 3 1 -o 0.25 0.5 0 -clamp on -blendu off normal.png\n"
                              "norm -bm 0.5 normal.png\n"
                              "bump -bm 0.1 grey.png\n"
                              "map_Ka grey.png\n"
                              "map_d grey.png\n");
  const ObjModel model = loadObj(f.obj);
  ASSERT_EQ(model.materials.size(), 1u);
  const Material& m = model.materials[0];
  ASSERT_TRUE(m.diffuseMap);
  EXPECT_EQ(m.diffuseMap->options.wrap, TextureWrap::ClampToEdge);
  EXPECT_EQ(m.diffuseMap->options.uvScale, vec2(2.0f, 3.0f));
  EXPECT_EQ(m.diffuseMap->options.uvOffset, vec2(0.25f, 0.5f));
  ASSERT_TRUE(m.normalMap);
  EXPECT_FLOAT_EQ(m.normalStrength, 0.5f);
  ASSERT_TRUE(m.heightMap);  // grey texels: a height map
  EXPECT_FLOAT_EQ(m.heightScale, kDefaultHeightScale * 0.1f);  // -bm 0.1 scales the default depth
  std::string all;
  for (const std::string& w : model.warnings) all += w + "\n";
  EXPECT_NE(all.find(f.mtl + ":6: 'd' (dissolve"), std::string::npos) << all;  // d 1 (line 3) is a no-op
  EXPECT_EQ(all.find(":3:"), std::string::npos) << all;
  EXPECT_EQ(all.find("illum"), std::string::npos) << all;
  EXPECT_NE(all.find(f.mtl + ":7: texture option '-blendu' on 'map_Kd' is not used"), std::string::npos) << all;
  EXPECT_EQ(all.find("'-s'"), std::string::npos) << all;
  EXPECT_NE(all.find(f.mtl + ":10: 'map_Ka'"), std::string::npos) << all;
  EXPECT_NE(all.find(f.mtl + ":11: 'map_d'"), std::string::npos) << all;
  EXPECT_NE(all.find("height map"), std::string::npos) << all;
}

}  // namespace
}  // namespace twr
