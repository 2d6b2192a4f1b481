// twinraster-assets: generates the textures in assets/textures deterministically: the bricks
// (diffuse, height, normal, specular) and the blocks, a height field with vertical walls
// (height, diffuse) that the report's height-field section measures steep parallax on.
//
// Everything is computed from integer hashes with a fixed seed and IEEE +, -, *, /, sqrt
// (no std::rand, no libm transcendental functions), so the PNGs are identical on every run;
// tests/cli/test_assets_tool.cpp checks the committed files byte for byte.
//
// Coordinates. Texel (x, y) of an N x N image (y = 0 is the top row of the file) has its
// centre at u = (x + 0.5) / N, v = 1 - (y + 0.5) / N: textures are stored bottom row first
// (scene/texture.h), so the file's top row is v = 1. Every pattern is periodic with period
// 1 in u and v, so the textures tile under GL_REPEAT at any size.
//
// Normal map sign convention (tangent space, as docs/shading.md decodes it):
//   +x = +u (right in the image), +y = +v (UP in the image, "OpenGL style"), +z = out of the
//   surface. The surface is p(u, v) = (u, v, depth * h(u, v)), so
//   n = normalize(-depth * dh/du, -depth * dh/dv, 1), encoded as rgb = round((n + 1) / 2 * 255).
//   A brick's left edge, where h rises with u, therefore leans to -x (red < 128); its bottom
//   edge, where h rises with v, leans to -y (green < 128).
// dh/du and dh/dv are central differences over two texels with wrap-around, taken from the
// 8-bit heights exactly as written to bricks_height.png, so the normal map can be re-derived
// from that file alone.
#include "scene/environment.h"
#include "scene/errors.h"
#include "scene/image.h"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <iostream>
#include <numbers>
#include <string>
#include <vector>

namespace {

using twr::Image;

// ---- layout, in texture units (1 = the whole texture) ----
constexpr int kBrickRows = 8;                              // courses per texture; even so odd rows tile
constexpr int kBricksPerRow = 4;                           // a brick is 1/4 wide, 1/8 tall (2:1)
constexpr double kBrickWidthUv = 1.0 / kBricksPerRow;
constexpr double kBrickHeightUv = 1.0 / kBrickRows;
constexpr double kMortarHalfWidthUv = 0.007;               // half the mortar joint
constexpr double kBevelWidthUv = 0.012;                    // rounded brick edge, mortar to face
constexpr double kEdgeJitterUv = 0.004;                    // irregular brick outlines
// Relief depth: how far a brick face stands above the mortar floor, in texture units.
// Also written in tests/cli/test_assets_tool.cpp, which re-derives the normal map.
constexpr double kReliefDepthUv = 0.012;

// ---- heights (unitless, [0, 1]) ----
constexpr double kMortarHeight = 0.12;
constexpr double kBrickHeight = 0.78;
constexpr double kBrickHeightVariation = 0.08;  // per brick, +-
constexpr double kMortarRoughness = 0.10;       // noise amplitude in the joints
constexpr double kBrickRoughness = 0.06;        // noise amplitude on the faces

// ---- colours (linear RGB) and specular ----
constexpr double kBrickColour[3] = {0.56, 0.25, 0.16};
constexpr double kMortarColour[3] = {0.66, 0.63, 0.58};
constexpr double kBrickTintVariation = 0.22;  // per brick brightness, +-
constexpr double kBrickSpecular = 0.28;
constexpr double kMortarSpecular = 0.05;

// ---- blocks: raised rectangular blocks with vertical walls on a flat floor ----
// One block per cell of a kBlockCells x kBlockCells grid (period 1 in u and v). Each block's
// half-extent along u and v is drawn from [kBlockMinHalf, kBlockMaxHalf] of the cell and its
// centre shifted within the slack, so every block lies inside its cell; its height from
// [kBlockMinHeight, 1]. A texel belongs to a block when its centre lies inside it, so every
// wall is a one-texel step from the floor (height 0) to the block's height: the steepest wall
// a height map holds.
constexpr int kBlockCells = 5;                 // cells per texture side
constexpr double kBlockMinHalf = 0.24;         // of the cell side
constexpr double kBlockMaxHalf = 0.40;         // of the cell side; < 0.5 keeps a floor margin
constexpr double kBlockMinHeight = 0.45;       // unitless, the floor is 0
constexpr double kFloorCheckerUv = 1.0 / 40.0; // floor checker square, texture units
constexpr double kFloorGreys[2] = {0.42, 0.58};
constexpr double kBlockRimUv = 0.006;          // darker band inside each block's edge, texture units
constexpr double kBlockRimShade = 0.55;        // rim colour = top colour times this
// Block top colours (linear RGB), picked per block.
constexpr double kBlockPalette[5][3] = {
    {0.70, 0.22, 0.16}, {0.20, 0.45, 0.70}, {0.85, 0.70, 0.20}, {0.25, 0.60, 0.30}, {0.60, 0.35, 0.65}};

constexpr std::uint32_t kSeed = 0x7b1c5a3du;  // fixed: the assets are committed
constexpr int kDefaultSize = 512;             // pixels
constexpr int kMinSize = 16;                  // pixels, inclusive
constexpr int kMaxSize = 4096;                // pixels, inclusive

// 32-bit integer mix (xorshift-multiply), good enough to decorrelate neighbouring lattice points.
std::uint32_t hash32(std::uint32_t x) {
  x ^= x >> 16;
  x *= 0x7feb352du;
  x ^= x >> 15;
  x *= 0x846ca68bu;
  x ^= x >> 16;
  return x;
}

std::uint32_t hash3(std::uint32_t a, std::uint32_t b, std::uint32_t c) { return hash32(a ^ hash32(b ^ hash32(c))); }

// Uniform in [0, 1] from a hash.
double unit(std::uint32_t h) { return static_cast<double>(h) / 4294967295.0; }

// Uniform in [-1, 1] for lattice point (i, j) of layer `layer`.
double latticeValue(int i, int j, std::uint32_t layer) {
  return 2.0 * unit(hash3(static_cast<std::uint32_t>(i), static_cast<std::uint32_t>(j), kSeed + layer)) - 1.0;
}

double smooth(double t) { return t * t * (3.0 - 2.0 * t); }

int wrap(int i, int n) { return ((i % n) + n) % n; }

// Value noise on a cells x cells lattice that wraps at u, v = 1, in [-1, 1].
double periodicNoise(double u, double v, int cells, std::uint32_t layer) {
  const double x = u * cells, y = v * cells;
  const double fx = std::floor(x), fy = std::floor(y);
  const int i = static_cast<int>(fx), j = static_cast<int>(fy);
  const double tx = smooth(x - fx), ty = smooth(y - fy);
  const double v00 = latticeValue(wrap(i, cells), wrap(j, cells), layer);
  const double v10 = latticeValue(wrap(i + 1, cells), wrap(j, cells), layer);
  const double v01 = latticeValue(wrap(i, cells), wrap(j + 1, cells), layer);
  const double v11 = latticeValue(wrap(i + 1, cells), wrap(j + 1, cells), layer);
  const double bottom = v00 + (v10 - v00) * tx;
  const double top = v01 + (v11 - v01) * tx;
  return bottom + (top - bottom) * ty;
}

// Sum of octaves, amplitudes 1, 1/2, 1/4, ..., normalised back to [-1, 1].
double fractalNoise(double u, double v, int baseCells, int octaves, std::uint32_t layer) {
  double sum = 0.0, amplitude = 1.0, total = 0.0;
  int cells = baseCells;
  for (int o = 0; o < octaves; ++o) {
    sum += amplitude * periodicNoise(u, v, cells, layer + static_cast<std::uint32_t>(o) * 101u);
    total += amplitude;
    amplitude *= 0.5;
    cells *= 2;
  }
  return sum / total;
}

struct BrickSample {
  double faceWeight;  // 0 in the mortar, 1 on the flat brick face, smooth across the bevel
  int row, column;    // which brick (column already wrapped into [0, kBricksPerRow))
};

BrickSample brickAt(double u, double v) {
  const double rowF = std::floor(v * kBrickRows);
  const int row = wrap(static_cast<int>(rowF), kBrickRows);
  // Running bond: every other course shifted by half a brick.
  const double uShifted = u + ((row % 2 == 1) ? 0.5 * kBrickWidthUv : 0.0);
  const double columnF = std::floor(uShifted * kBricksPerRow);
  const int column = wrap(static_cast<int>(columnF), kBricksPerRow);
  const double du = (uShifted * kBricksPerRow - columnF) * kBrickWidthUv;  // from the brick's left edge
  const double dv = (v * kBrickRows - rowF) * kBrickHeightUv;              // from the brick's bottom edge
  const double edgeDistance = std::min(std::min(du, kBrickWidthUv - du), std::min(dv, kBrickHeightUv - dv)) +
                              kEdgeJitterUv * fractalNoise(u, v, 16, 3, 11u);
  const double t = std::clamp((edgeDistance - kMortarHalfWidthUv) / kBevelWidthUv, 0.0, 1.0);
  return {smooth(t), row, column};
}

// Per-brick random number in [-1, 1], different for each `channel`.
double brickRandom(const BrickSample& b, std::uint32_t channel) {
  return 2.0 * unit(hash3(static_cast<std::uint32_t>(b.row), static_cast<std::uint32_t>(b.column), kSeed ^ channel)) - 1.0;
}

std::uint8_t toByte(double c) { return static_cast<std::uint8_t>(std::floor(std::clamp(c, 0.0, 1.0) * 255.0 + 0.5)); }

void setPixel(Image& image, int x, int y, double r, double g, double b) {
  std::uint8_t* p = image.pixel(x, y);
  p[0] = toByte(r);
  p[1] = toByte(g);
  p[2] = toByte(b);
  p[3] = 255;
}

struct BrickTextures {
  Image diffuse, height, normal, specular;
};

BrickTextures generate(int size) {
  BrickTextures t{twr::makeImage(size, size), twr::makeImage(size, size), twr::makeImage(size, size),
                  twr::makeImage(size, size)};
  std::vector<std::uint8_t> height8(static_cast<std::size_t>(size) * size);
  for (int y = 0; y < size; ++y) {
    for (int x = 0; x < size; ++x) {
      const double u = (x + 0.5) / size;
      const double v = 1.0 - (y + 0.5) / size;
      const BrickSample b = brickAt(u, v);
      const double w = b.faceWeight;

      const double mortarHeight = kMortarHeight + kMortarRoughness * fractalNoise(u, v, 32, 4, 21u);
      const double faceHeight = kBrickHeight + kBrickHeightVariation * brickRandom(b, 1u) +
                                kBrickRoughness * fractalNoise(u, v, 16, 5, 31u);
      const double h = mortarHeight + (faceHeight - mortarHeight) * w;
      height8[static_cast<std::size_t>(y) * size + x] = toByte(h);
      const double hq = height8[static_cast<std::size_t>(y) * size + x] / 255.0;
      setPixel(t.height, x, y, hq, hq, hq);

      const double grime = fractalNoise(u, v, 8, 4, 41u);
      const double brickTint = 1.0 + kBrickTintVariation * brickRandom(b, 2u) + 0.10 * grime;
      const double redShift = 0.05 * brickRandom(b, 3u);  // some bricks redder, some browner
      const double brick[3] = {kBrickColour[0] * brickTint + redShift, kBrickColour[1] * brickTint,
                               kBrickColour[2] * brickTint - 0.5 * redShift};
      const double mortarTint = 1.0 + 0.08 * fractalNoise(u, v, 32, 2, 51u);
      double rgb[3];
      for (int c = 0; c < 3; ++c) rgb[c] = kMortarColour[c] * mortarTint + (brick[c] - kMortarColour[c] * mortarTint) * w;
      setPixel(t.diffuse, x, y, rgb[0], rgb[1], rgb[2]);

      const double brickSpecular = kBrickSpecular * (1.0 + 0.3 * brickRandom(b, 4u) + 0.3 * grime);
      const double s = kMortarSpecular + (brickSpecular - kMortarSpecular) * w;
      setPixel(t.specular, x, y, s, s, s);
    }
  }

  // Central differences over two texels (2 / size in texture units), wrapping at the edges.
  const double texelsToUv = 2.0 / size;
  const auto h8 = [&](int x, int y) { return height8[static_cast<std::size_t>(wrap(y, size)) * size + wrap(x, size)] / 255.0; };
  for (int y = 0; y < size; ++y) {
    for (int x = 0; x < size; ++x) {
      const double dhdu = (h8(x + 1, y) - h8(x - 1, y)) / texelsToUv;
      const double dhdv = (h8(x, y - 1) - h8(x, y + 1)) / texelsToUv;  // row y - 1 is higher v
      const double nx = -kReliefDepthUv * dhdu, ny = -kReliefDepthUv * dhdv, nz = 1.0;
      const double length = std::sqrt(nx * nx + ny * ny + nz * nz);  // >= 1, never zero
      setPixel(t.normal, x, y, 0.5 * (nx / length + 1.0), 0.5 * (ny / length + 1.0), 0.5 * (nz / length + 1.0));
    }
  }
  return t;
}

struct BlockTextures {
  Image height, diffuse;
};

// The block of cell (i, j) in texture units, and its height.
struct Block {
  double u0, u1, v0, v1;  // [u0, u1) x [v0, v1), inside the cell
  double height;
  int colour;             // index into kBlockPalette
};

Block blockOfCell(int i, int j) {
  const double cell = 1.0 / kBlockCells;
  const auto random = [&](std::uint32_t channel) {
    return unit(hash3(static_cast<std::uint32_t>(i), static_cast<std::uint32_t>(j), (kSeed + 0x9e37u) ^ channel));
  };
  const double halfU = cell * (kBlockMinHalf + (kBlockMaxHalf - kBlockMinHalf) * random(1u));
  const double halfV = cell * (kBlockMinHalf + (kBlockMaxHalf - kBlockMinHalf) * random(2u));
  const double centreU = cell * (i + 0.5) + (0.5 * cell - halfU) * (2.0 * random(3u) - 1.0);
  const double centreV = cell * (j + 0.5) + (0.5 * cell - halfV) * (2.0 * random(4u) - 1.0);
  Block b;
  b.u0 = centreU - halfU;
  b.u1 = centreU + halfU;
  b.v0 = centreV - halfV;
  b.v1 = centreV + halfV;
  b.height = kBlockMinHeight + (1.0 - kBlockMinHeight) * random(5u);
  b.colour = static_cast<int>(hash3(static_cast<std::uint32_t>(i), static_cast<std::uint32_t>(j), kSeed ^ 0x51u) % 5u);
  return b;
}

BlockTextures generateBlocks(int size) {
  BlockTextures t{twr::makeImage(size, size), twr::makeImage(size, size)};
  for (int y = 0; y < size; ++y) {
    for (int x = 0; x < size; ++x) {
      const double u = (x + 0.5) / size;
      const double v = 1.0 - (y + 0.5) / size;
      const int i = std::min(static_cast<int>(u * kBlockCells), kBlockCells - 1);
      const int j = std::min(static_cast<int>(v * kBlockCells), kBlockCells - 1);
      const Block b = blockOfCell(i, j);
      const bool inside = u >= b.u0 && u < b.u1 && v >= b.v0 && v < b.v1;
      const double h = inside ? b.height : 0.0;
      setPixel(t.height, x, y, h, h, h);
      if (inside) {
        const double edge = std::min(std::min(u - b.u0, b.u1 - u), std::min(v - b.v0, b.v1 - v));
        const double shade = edge < kBlockRimUv ? kBlockRimShade : 1.0;
        const double* c = kBlockPalette[b.colour];
        setPixel(t.diffuse, x, y, c[0] * shade, c[1] * shade, c[2] * shade);
      } else {
        const int checker = (static_cast<int>(std::floor(u / kFloorCheckerUv)) + static_cast<int>(std::floor(v / kFloorCheckerUv))) & 1;
        const double g = kFloorGreys[checker];
        setPixel(t.diffuse, x, y, g, g, g);
      }
    }
  }
  return t;
}


// ---- the sky: one direction function, written as six cube faces and an equirect ----
// Sky above the horizon (a gradient and a sun), a checkered ground plane below it, and grid
// lines every 30 degrees of azimuth and elevation, so a student sees where a mapping
// stretches or tears. Faces follow GL's cube table (scene/environment.h; top row t = 0).
constexpr int kSkyFaceSize = 256;                 // texels per cube face side
constexpr int kSkyEquirectWidth = 1024;           // texels; height is half
constexpr double kSkyGridStepDeg = 30.0;          // grid spacing, degrees
constexpr double kSkyGridHalfWidthDeg = 0.35;     // half a grid line, degrees
constexpr double kSunHalfAngleDeg = 4.0;          // the sun's disc radius, degrees
using twr::kPi;
constexpr double kSunDirection[3] = {0.45, 0.55, -0.70};  // towards the sun (normalised below)
constexpr double kHorizonColour[3] = {0.86, 0.90, 0.95};
constexpr double kZenithColour[3] = {0.16, 0.36, 0.78};
constexpr double kSunColour[3] = {1.0, 0.92, 0.62};
constexpr double kGroundColours[2][3] = {{0.30, 0.26, 0.20}, {0.52, 0.47, 0.36}};
constexpr double kGroundDepth = 1.0;  // the ground plane lies this far below the eye (y = -1)
constexpr double kSunEdgeSharpness = 4.0;       // the disc's rim goes from 0 to 1 over a quarter of it
constexpr double kHazeRisePerUnitY = 6.0;       // the ground fades into haze within y > -1/6
constexpr double kHazeStrength = 0.8;           // how far towards the horizon colour the haze goes
constexpr double kGridDarkening = 0.35;         // a grid line's colour, times the sky's
constexpr double kAzimuthLinesEndDeg = 75.0;    // azimuth lines stop at this elevation, short of the poles (degrees)

std::array<double, 3> skyAt(double x, double y, double z) {
  const double length = std::sqrt(x * x + y * y + z * z);
  x /= length, y /= length, z /= length;
  std::array<double, 3> c{};
  if (y >= 0.0) {
    const double up = std::sqrt(y);
    for (int k = 0; k < 3; ++k) c[k] = kHorizonColour[k] + (kZenithColour[k] - kHorizonColour[k]) * up;
    const double sunLength = std::sqrt(kSunDirection[0] * kSunDirection[0] + kSunDirection[1] * kSunDirection[1] +
                                       kSunDirection[2] * kSunDirection[2]);
    const double cosSun = (x * kSunDirection[0] + y * kSunDirection[1] + z * kSunDirection[2]) / sunLength;
    const double edge = std::cos(kSunHalfAngleDeg * kPi / 180.0);
    const double sun = std::clamp((cosSun - edge) / (1.0 - edge) * kSunEdgeSharpness, 0.0, 1.0);
    for (int k = 0; k < 3; ++k) c[k] += (kSunColour[k] - c[k]) * sun;
  } else {
    // The ground plane's 1 x 1 tiles, fading into the horizon's haze towards it.
    const double gx = x / -y * kGroundDepth, gz = z / -y * kGroundDepth;
    const int tile = (static_cast<int>(std::floor(gx)) + static_cast<int>(std::floor(gz))) & 1;
    const double haze = std::clamp(1.0 + y * kHazeRisePerUnitY, 0.0, 1.0);
    for (int k = 0; k < 3; ++k) {
      c[k] = kGroundColours[tile][k] + (kHorizonColour[k] - kGroundColours[tile][k]) * haze * kHazeStrength;
    }
  }
  const double azimuthDeg = std::atan2(x, -z) * 180.0 / kPi, elevationDeg = std::asin(std::clamp(y, -1.0, 1.0)) * 180.0 / kPi;
  const auto nearLine = [](double angle) {
    const double offset = std::fmod(std::fabs(angle) + kSkyGridStepDeg * 0.5, kSkyGridStepDeg) - kSkyGridStepDeg * 0.5;
    return std::fabs(offset) <= kSkyGridHalfWidthDeg;
  };
  // Azimuth lines thin out towards the poles, where they all meet.
  if (nearLine(elevationDeg) || (std::fabs(elevationDeg) < kAzimuthLinesEndDeg && nearLine(azimuthDeg))) {
    for (double& v : c) v *= kGridDarkening;
  }
  return c;
}

struct SkyImages {
  std::array<Image, 6> faces;
  Image equirect;
};

SkyImages generateSky() {
  SkyImages sky;
  for (int f = 0; f < 6; ++f) {
    Image& face = sky.faces[static_cast<std::size_t>(f)];
    face = twr::makeImage(kSkyFaceSize, kSkyFaceSize);
    for (int y = 0; y < kSkyFaceSize; ++y) {
      for (int x = 0; x < kSkyFaceSize; ++x) {
        // GL's cube table inverted (scene/environment.h): the direction of the texel's centre.
        const glm::dvec3 d = twr::directionFromCubeCoord(f, (x + 0.5) / kSkyFaceSize, (y + 0.5) / kSkyFaceSize);
        const std::array<double, 3> c = skyAt(d.x, d.y, d.z);
        setPixel(face, x, y, c[0], c[1], c[2]);  // row y (top first) is t = (y + 0.5) / size
      }
    }
  }
  const int height = kSkyEquirectWidth / 2;
  sky.equirect = twr::makeImage(kSkyEquirectWidth, height);
  for (int y = 0; y < height; ++y) {
    const double latitude = (y + 0.5) / height * kPi;  // 0 at +Y (the top row)
    for (int x = 0; x < kSkyEquirectWidth; ++x) {
      const double longitude = ((x + 0.5) / kSkyEquirectWidth - 0.5) * 2.0 * kPi;  // 0 towards -Z
      const double r = std::sin(latitude);
      const std::array<double, 3> c = skyAt(r * std::sin(longitude), std::cos(latitude), -r * std::cos(longitude));
      setPixel(sky.equirect, x, y, c[0], c[1], c[2]);
    }
  }
  return sky;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{
      "twinraster-assets: writes the brick textures (bricks_diffuse.png, bricks_height.png, "
      "bricks_normal.png, bricks_specular.png) and the blocks, a height field with vertical walls "
      "(blocks_height.png, blocks_diffuse.png), and a sky as six cube faces (sky_px.png, sky_nx.png, "
      "sky_py.png, sky_ny.png, sky_pz.png, sky_nz.png, GL order and orientation, 256x256) and as an "
      "equirectangular image (sky_equirect.png, 1024x512), deterministically into DIR.\n"
      "The normal map is tangent space, +x = +u, +y = +v (up in the image), encoded (n + 1) / 2.\n"
      "Exit codes: 0 ok, 2 bad arguments or a file that cannot be written."};
  std::string outDir;
  int size = kDefaultSize;
  app.add_option("--out", outDir, "Directory to write the PNGs into (created if missing)")->required();
  app.add_option("--size", size, "Width and height of every texture, in pixels")
      ->check(CLI::Range(kMinSize, kMaxSize))
      ->capture_default_str();
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    return code == 0 ? twr::kExitOk : twr::kExitBadInput;
  }

  try {
    const BrickTextures textures = generate(size);
    const BlockTextures blocks = generateBlocks(size);
    const SkyImages sky = generateSky();
    const std::filesystem::path dir(outDir);
    const std::pair<const char*, const Image*> files[] = {{"bricks_diffuse.png", &textures.diffuse},
                                                          {"bricks_height.png", &textures.height},
                                                          {"bricks_normal.png", &textures.normal},
                                                          {"bricks_specular.png", &textures.specular},
                                                          {"blocks_height.png", &blocks.height},
                                                          {"blocks_diffuse.png", &blocks.diffuse}};
    for (const auto& [name, image] : files) {
      const std::string path = (dir / name).string();
      twr::savePng(path, *image);
      std::cout << "wrote " << path << " (" << size << "x" << size << ")\n";
    }
    // The sky has sizes of its own (--size is the material textures').
    const char* const faceNames[6] = {"sky_px.png", "sky_nx.png", "sky_py.png", "sky_ny.png", "sky_pz.png", "sky_nz.png"};
    std::vector<std::pair<std::string, const Image*>> skyFiles;
    for (std::size_t f = 0; f < 6; ++f) skyFiles.emplace_back(faceNames[f], &sky.faces[f]);
    skyFiles.emplace_back("sky_equirect.png", &sky.equirect);
    for (const auto& [name, image] : skyFiles) {
      const std::string path = (dir / name).string();
      twr::savePng(path, *image);
      std::cout << "wrote " << path << " (" << image->width << "x" << image->height << ")\n";
    }
  } catch (const twr::InputError& e) {
    std::cerr << "twinraster-assets: error: " << e.what() << "\n";
    return twr::kExitBadInput;
  }
  return twr::kExitOk;
}
