// twinraster-assets: regenerating the textures reproduces the committed PNGs byte for byte,
// and the normal map is what its header promises: unit normals, +z out of the surface, +y
// up in the image (+v), derived from bricks_height.png by central differences with wrap.
#include "scene/image.h"

#include <gtest/gtest.h>

#include <sys/wait.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace {

const std::filesystem::path kTextures = std::filesystem::path(TWINRASTER_SOURCE_DIR) / "assets" / "textures";
const char* const kFiles[] = {"bricks_diffuse.png", "bricks_height.png", "bricks_normal.png", "bricks_specular.png",
                              "blocks_height.png",  "blocks_diffuse.png"};
// The sky's files, at sizes of their own (--size does not change them).
const char* const kSkyFiles[] = {"sky_px.png", "sky_nx.png", "sky_py.png",     "sky_ny.png",
                                 "sky_pz.png", "sky_nz.png", "sky_equirect.png"};
// Relief depth in texture units, as app/assets_tool.cpp's kReliefDepthUv.
constexpr double kReliefDepthUv = 0.012;
// One 8-bit step of a decoded component: c / 255 * 2 - 1 moves by 2 / 255 per level.
constexpr double kDecodeStep = 2.0 / 255.0;

std::string readBytes(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream bytes;
  bytes << in.rdbuf();
  return bytes.str();
}

int runTool(const std::string& args) {
  const std::string command = "\"" + std::string(TWINRASTER_ASSETS_TOOL) + "\" " + args + " >/dev/null 2>&1";
  const int status = std::system(command.c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

std::filesystem::path freshDir(const std::string& name) {
  const std::filesystem::path dir = std::filesystem::path(TWINRASTER_TEST_OUT) / name;
  std::filesystem::remove_all(dir);
  return dir;
}

TEST(AssetsTool, ReproducesTheCommittedTexturesByteForByte) {
  const std::filesystem::path dir = freshDir("assets_tool_default");
  ASSERT_EQ(runTool("--out \"" + dir.string() + "\""), 0);
  for (const char* file : kFiles) {
    const std::string committed = readBytes(kTextures / file);
    ASSERT_FALSE(committed.empty()) << file;
    EXPECT_TRUE(readBytes(dir / file) == committed) << file << " differs from assets/textures/" << file;
  }
  for (const char* file : kSkyFiles) {
    const std::string committed = readBytes(kTextures / file);
    ASSERT_FALSE(committed.empty()) << file;
    EXPECT_TRUE(readBytes(dir / file) == committed) << file << " differs from assets/textures/" << file;
  }
}

TEST(AssetsTool, SizeOptionAndBadArguments) {
  const std::filesystem::path dir = freshDir("assets_tool_small");
  ASSERT_EQ(runTool("--out \"" + dir.string() + "\" --size 64"), 0);
  for (const char* file : kFiles) {
    const twr::Image image = twr::loadPng((dir / file).string());
    EXPECT_EQ(image.width, 64) << file;
    EXPECT_EQ(image.height, 64) << file;
  }
  EXPECT_EQ(runTool("--size 64"), 2);                                            // --out is required
  EXPECT_EQ(runTool("--out \"" + dir.string() + "\" --size 8"), 2);              // below 16
  EXPECT_EQ(runTool("--out \"" + dir.string() + "\" --size 100000"), 2);         // above 4096
  EXPECT_EQ(runTool("--out /proc/no_such_dir/cannot_write"), 2);                 // unwritable
  EXPECT_EQ(runTool("--help"), 0);
}

double decode(std::uint8_t c) { return c / 255.0 * 2.0 - 1.0; }

TEST(AssetsTool, NormalMapIsUnitOutwardAndFollowsTheHeight) {
  const twr::Image normal = twr::loadPng((kTextures / "bricks_normal.png").string());
  const twr::Image height = twr::loadPng((kTextures / "bricks_height.png").string());
  ASSERT_EQ(normal.width, height.width);
  ASSERT_EQ(normal.height, height.height);
  const int n = normal.width;
  ASSERT_EQ(normal.height, n);
  const auto h = [&](int x, int y) { return height.pixel(((x % n) + n) % n, ((y % n) + n) % n)[0] / 255.0; };

  int flatTexels = 0, risingRight = 0, risingUp = 0;
  for (int y = 0; y < n; ++y) {
    for (int x = 0; x < n; ++x) {
      const std::uint8_t* p = normal.pixel(x, y);
      const double nx = decode(p[0]), ny = decode(p[1]), nz = decode(p[2]);
      // Unit length within the 8-bit error: each component off by at most half a step.
      const double length = std::sqrt(nx * nx + ny * ny + nz * nz);
      ASSERT_NEAR(length, 1.0, std::sqrt(3.0) * 0.5 * kDecodeStep) << "texel " << x << ", " << y;
      ASSERT_GT(nz, 0.0) << "texel " << x << ", " << y << " points into the surface";

      // Re-derive from the height file: row y - 1 is higher v (the file is top row first).
      const double dhdu = (h(x + 1, y) - h(x - 1, y)) / (2.0 / n);
      const double dhdv = (h(x, y - 1) - h(x, y + 1)) / (2.0 / n);
      const double ex = -kReliefDepthUv * dhdu, ey = -kReliefDepthUv * dhdv;
      const double el = std::sqrt(ex * ex + ey * ey + 1.0);
      ASSERT_NEAR(nx, ex / el, kDecodeStep) << "texel " << x << ", " << y;
      ASSERT_NEAR(ny, ey / el, kDecodeStep) << "texel " << x << ", " << y;
      ASSERT_NEAR(nz, 1.0 / el, kDecodeStep) << "texel " << x << ", " << y;

      if (dhdu == 0.0 && dhdv == 0.0) {
        // Flat: exactly +z, encoded (128, 128, 255) since 0.5 * 255 = 127.5 rounds up.
        ++flatTexels;
        EXPECT_EQ(p[0], 128);
        EXPECT_EQ(p[1], 128);
        EXPECT_EQ(p[2], 255);
      }
      // The sign convention: a slope rising to the right leans to -x, rising up leans to -y.
      const double steep = 20.0 / 255.0 / (2.0 / n);
      if (dhdu > steep) {
        ++risingRight;
        EXPECT_LT(p[0], 128) << "texel " << x << ", " << y;
      }
      if (dhdv > steep) {
        ++risingUp;
        EXPECT_LT(p[1], 128) << "texel " << x << ", " << y;
      }
    }
  }
  // The checks above must have had something to check.
  EXPECT_GT(flatTexels, n);
  EXPECT_GT(risingRight, n);
  EXPECT_GT(risingUp, n);
}

// The blocks are steep walls: every texel is floor (0) or a block top (at least 0.45, as
// app/assets_tool.cpp's kBlockMinHeight), so a height change between neighbours is a whole
// wall within one texel; every block stands on floor on all four sides.
TEST(AssetsTool, BlocksHaveVerticalWalls) {
  const twr::Image height = twr::loadPng((kTextures / "blocks_height.png").string());
  const int n = height.width;
  ASSERT_EQ(height.height, n);
  const std::uint8_t minBlock = static_cast<std::uint8_t>(0.45 * 255.0);
  int floor = 0, top = 0, walls = 0;
  for (int y = 0; y < n; ++y) {
    for (int x = 0; x < n; ++x) {
      const std::uint8_t h = height.pixel(x, y)[0];
      ASSERT_TRUE(h == 0 || h >= minBlock) << "texel " << x << ", " << y << " is " << int(h);
      (h == 0 ? floor : top)++;
      const std::uint8_t right = height.pixel((x + 1) % n, y)[0];
      if ((h == 0) != (right == 0)) ++walls;
    }
  }
  // 25 blocks of 24% to 40% half-extent: between about 9% and 64% of the texels are tops.
  EXPECT_GT(top, n * n / 12);
  EXPECT_LT(top, n * n * 2 / 3);
  EXPECT_GT(floor, n * n / 3);
  // Each block row crossing has two walls; 25 blocks, each at least 0.48 * n / 5 texels tall.
  EXPECT_GT(walls, 2 * 25 * (n / 11));
}

}  // namespace
