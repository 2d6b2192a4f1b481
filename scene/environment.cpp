#include "scene/environment.h"

#include "scene/errors.h"
#include "scene/read_file.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <numbers>

namespace twr {

namespace {

constexpr std::array<std::pair<EnvironmentParameterization, std::string_view>, 3> kParameterizationNames{{
    {EnvironmentParameterization::Cube, "cube"},
    {EnvironmentParameterization::Sphere, "sphere"},
    {EnvironmentParameterization::DualParaboloid, "dual_paraboloid"},
}};

// Most pixels one environment image may have (inclusive): an 8192 x 4096 equirect. Its RGB
// floats are 384 MB while the cube is built from them.
constexpr long long kMaxEnvironmentImagePixels = 8192LL * 4096LL;

// One byte as the sampler reads an 8-bit texel: c * (1 / 255) in float.
float unitFromByte(std::uint8_t c) { return static_cast<float>(c) * (1.0f / 255.0f); }

// Halves a face (top row first, RGB) by 2x2 means in double; an odd side drops its last
// row or column (only for a face larger than kMaxCubeFaceSize, reduced with a warning).
FaceImage halvedFace(const FaceImage& face) {
  FaceImage half;
  half.width = std::max(face.width / 2, 1);
  half.height = std::max(face.height / 2, 1);
  half.rgb.resize(static_cast<std::size_t>(half.width) * static_cast<std::size_t>(half.height) * 3);
  for (int y = 0; y < half.height; ++y) {
    for (int x = 0; x < half.width; ++x) {
      for (int c = 0; c < 3; ++c) {
        double sum = 0.0;
        for (int dy = 0; dy < 2; ++dy) {
          for (int dx = 0; dx < 2; ++dx) {
            const int sx = std::min(2 * x + dx, face.width - 1), sy = std::min(2 * y + dy, face.height - 1);
            sum += face.rgb[(static_cast<std::size_t>(sy) * static_cast<std::size_t>(face.width) +
                             static_cast<std::size_t>(sx)) * 3 + static_cast<std::size_t>(c)];
          }
        }
        half.rgb[(static_cast<std::size_t>(y) * static_cast<std::size_t>(half.width) + static_cast<std::size_t>(x)) * 3 +
                 static_cast<std::size_t>(c)] = static_cast<float>(sum * 0.25);
      }
    }
  }
  return half;
}

CubeMapLevel allocateLevel(int size, int faces = kCubeFaces) {
  CubeMapLevel level;
  level.size = size;
  const std::size_t count = static_cast<std::size_t>(faces) * static_cast<std::size_t>(size) * static_cast<std::size_t>(size);
  level.r.assign(count, 0.0f);
  level.g.assign(count, 0.0f);
  level.b.assign(count, 0.0f);
  return level;
}

bool isPowerOfTwo(int n) { return n > 0 && (n & (n - 1)) == 0; }

// The bilinear value of an equirect (top row first, RGB) at image coordinate (u, v) in [0, 1],
// wrapping in u (longitude) and clamping in v (latitude), in double.
glm::dvec3 equirectBilinear(const FaceImage& image, double u, double v) {
  const double x = u * image.width - 0.5, y = v * image.height - 0.5;
  const double x0f = std::floor(x), y0f = std::floor(y);
  const double ax = x - x0f, ay = y - y0f;
  const auto texel = [&](long long tx, long long ty) {
    tx %= image.width;
    if (tx < 0) tx += image.width;
    ty = std::clamp<long long>(ty, 0, image.height - 1);
    const std::size_t i = (static_cast<std::size_t>(ty) * static_cast<std::size_t>(image.width) + static_cast<std::size_t>(tx)) * 3;
    return glm::dvec3(image.rgb[i], image.rgb[i + 1], image.rgb[i + 2]);
  };
  const long long x0 = static_cast<long long>(x0f), y0 = static_cast<long long>(y0f);
  const glm::dvec3 top = texel(x0, y0) * (1.0 - ax) + texel(x0 + 1, y0) * ax;
  const glm::dvec3 bottom = texel(x0, y0 + 1) * (1.0 - ax) + texel(x0 + 1, y0 + 1) * ax;
  return top * (1.0 - ay) + bottom * ay;
}

}  // namespace

std::string_view toString(EnvironmentParameterization v) {
  for (const auto& [value, name] : kParameterizationNames) {
    if (value == v) return name;
  }
  return "?";
}

bool parse(std::string_view s, EnvironmentParameterization& out) {
  for (const auto& [value, name] : kParameterizationNames) {
    if (name == s) {
      out = value;
      return true;
    }
  }
  return false;
}

FaceImage loadEnvironmentImage(const std::string& path) {
  std::error_code ec;
  if (!std::filesystem::exists(path, ec) && !ec) throw InputError(path + ": image file not found");
  const std::string bytes = readFileCapped(path, kMaxImageFileBytes, "image file");
  const auto* data = reinterpret_cast<const std::uint8_t*>(bytes.data());
  // The size from the header, before anything is decoded: the source is held as floats while
  // the cube is built.
  int width = 0, height = 0;
  if (readImageHeader(data, bytes.size(), width, height) &&
      static_cast<long long>(width) * height > kMaxEnvironmentImagePixels) {
    throw InputError(path + ": image is " + std::to_string(width) + "x" + std::to_string(height) +
                     ", more than the " + std::to_string(kMaxEnvironmentImagePixels / (1024 * 1024)) +
                     " Mpixels an environment image may have (an 8192x4096 equirect, or 4096^2 faces, at most)");
  }
  FaceImage face;
  if (imageFileFormat(data, bytes.size()) == ImageFileFormat::Hdr) {
    const ImageF hdr = decodeHdrImage(data, bytes.size(), path);
    face.width = hdr.width;
    face.height = hdr.height;
    face.rgb.resize(static_cast<std::size_t>(hdr.width) * static_cast<std::size_t>(hdr.height) * 3);
    for (std::size_t i = 0, n = static_cast<std::size_t>(hdr.width) * static_cast<std::size_t>(hdr.height); i < n; ++i) {
      for (std::size_t c = 0; c < 3; ++c) {
        const float value = hdr.rgba[i * 4 + c];
        // A NaN, an Inf or a negative radiance would reach pixels: read as 0. A huge one is
        // clamped, so that times the largest intensity and mixed it stays finite (no Inf - Inf).
        face.rgb[i * 3 + c] = std::isfinite(value) && value > 0.0f ? std::min(value, kMaxEnvironmentRadiance) : 0.0f;
      }
    }
    return face;
  }
  const Image image = decodeImage(data, bytes.size(), path);
  face.width = image.width;
  face.height = image.height;
  face.rgb.resize(static_cast<std::size_t>(image.width) * static_cast<std::size_t>(image.height) * 3);
  for (std::size_t i = 0, n = static_cast<std::size_t>(image.width) * static_cast<std::size_t>(image.height); i < n; ++i) {
    for (std::size_t c = 0; c < 3; ++c) face.rgb[i * 3 + c] = unitFromByte(image.rgba[i * 4 + c]);
  }
  return face;
}

bool readEnvironmentImageSize(const std::string& path, int& width, int& height) {
  std::error_code ec;
  if (!std::filesystem::exists(path, ec) && !ec) throw InputError(path + ": image file not found");
  const std::string bytes = readFileCapped(path, kMaxImageFileBytes, "image file");
  return readImageHeader(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size(), width, height);
}

FaceImage faceWithinCubeLimit(FaceImage face) {
  while (face.width > kMaxCubeFaceSize || face.height > kMaxCubeFaceSize) face = halvedFace(face);
  return face;
}

CubeMap cubeMapFromFaces(std::array<FaceImage, kCubeFaces> faces, const std::array<std::string, kCubeFaces>& paths,
                         std::vector<std::string>& warnings) {
  for (int f = 0; f < kCubeFaces; ++f) {
    const FaceImage& face = faces[static_cast<std::size_t>(f)];
    if (face.width != face.height) {
      throw InputError(paths[static_cast<std::size_t>(f)] + ": cube face " + kCubeFaceNames[f] + " is " +
                       std::to_string(face.width) + "x" + std::to_string(face.height) + "; cube faces must be square");
    }
    if (face.width != faces[0].width) {
      throw InputError(paths[static_cast<std::size_t>(f)] + ": cube face " + kCubeFaceNames[f] + " is " +
                       std::to_string(face.width) + "x" + std::to_string(face.height) + " but face +X (" + paths[0] +
                       ") is " + std::to_string(faces[0].width) + "x" + std::to_string(faces[0].height) +
                       "; all six faces must have one size");
    }
  }
  int size = faces[0].width;
  if (!isPowerOfTwo(size)) {
    throw InputError(paths[0] + ": cube faces are " + std::to_string(size) + "x" + std::to_string(size) +
                     "; twinraster needs a power-of-two side for the faces' mip chain (resample them, or give an "
                     "\"equirect\" image and a \"size\")");
  }
  if (size > kMaxCubeFaceSize) {
    const int from = size;
    while (size > kMaxCubeFaceSize) {
      for (FaceImage& face : faces) face = halvedFace(face);
      size /= 2;
    }
    warnings.push_back(paths[0] + ": cube faces are " + std::to_string(from) + "x" + std::to_string(from) +
                       ", more than " + std::to_string(kMaxCubeFaceSize) + "; read at their mip level of " +
                       std::to_string(size) + "x" + std::to_string(size));
  }
  CubeMap cube;
  cube.source = paths[0];
  CubeMapLevel level = allocateLevel(size);
  for (int f = 0; f < kCubeFaces; ++f) {
    const FaceImage& face = faces[static_cast<std::size_t>(f)];
    for (int y = 0; y < size; ++y) {
      for (int x = 0; x < size; ++x) {
        // Row 0 (t = 0) is the image's top row: no flip (the header says why).
        const std::size_t from = (static_cast<std::size_t>(y) * static_cast<std::size_t>(size) + static_cast<std::size_t>(x)) * 3;
        const std::size_t to = level.index(f, x, y);
        level.r[to] = face.rgb[from];
        level.g[to] = face.rgb[from + 1];
        level.b[to] = face.rgb[from + 2];
      }
    }
  }
  cube.levels.push_back(std::move(level));
  buildCubeMipChain(cube);
  return cube;
}

int defaultCubeSizeForEquirect(int equirectWidth) {
  const double quarter = std::max(equirectWidth / 4.0, 1.0);
  int size = 1;
  while (size < kMaxCubeFaceSize && std::abs(std::log2(size * 2.0) - std::log2(quarter)) <=
                                        std::abs(std::log2(static_cast<double>(size)) - std::log2(quarter))) {
    size *= 2;
  }
  return std::clamp(size, kMinCubeFaceSize, kMaxCubeFaceSize);
}

CubeMap cubeMapFromEquirect(const FaceImage& equirect, int size, const std::string& path) {
  if (!isPowerOfTwo(size) || size > kMaxCubeFaceSize) {
    throw InputError(path + ": a cube side of " + std::to_string(size) + " texels; expected a power of two in [1, " +
                     std::to_string(kMaxCubeFaceSize) + "]");
  }
  CubeMap cube;
  cube.source = path;
  CubeMapLevel level = allocateLevel(size);
  for (int f = 0; f < kCubeFaces; ++f) {
    for (int y = 0; y < size; ++y) {
      for (int x = 0; x < size; ++x) {
        const glm::dvec3 r = directionFromCubeCoord(f, (x + 0.5) / size, (y + 0.5) / size);
        const glm::dvec2 uv = equirectUvFromDirection(r);
        const glm::dvec3 c = equirectBilinear(equirect, uv.x, uv.y);
        const std::size_t i = level.index(f, x, y);
        level.r[i] = static_cast<float>(c.x);
        level.g[i] = static_cast<float>(c.y);
        level.b[i] = static_cast<float>(c.z);
      }
    }
  }
  cube.levels.push_back(std::move(level));
  buildCubeMipChain(cube);
  return cube;
}

namespace {

// Levels 1.. from level 0 for `faces` squares: each texel the mean of its 2x2 block, in double.
void buildMipChain(std::vector<CubeMapLevel>& levels, int faces) {
  levels.resize(1);
  while (levels.back().size > 1) {
    const CubeMapLevel& from = levels.back();
    CubeMapLevel to = allocateLevel(from.size / 2, faces);
    for (int f = 0; f < faces; ++f) {
      for (int y = 0; y < to.size; ++y) {
        for (int x = 0; x < to.size; ++x) {
          const std::size_t i00 = from.index(f, 2 * x, 2 * y), i10 = from.index(f, 2 * x + 1, 2 * y);
          const std::size_t i01 = from.index(f, 2 * x, 2 * y + 1), i11 = from.index(f, 2 * x + 1, 2 * y + 1);
          const std::size_t i = to.index(f, x, y);
          const auto mean = [&](const std::vector<float>& c) {
            return static_cast<float>((static_cast<double>(c[i00]) + c[i10] + c[i01] + c[i11]) * 0.25);
          };
          to.r[i] = mean(from.r);
          to.g[i] = mean(from.g);
          to.b[i] = mean(from.b);
        }
      }
    }
    levels.push_back(std::move(to));
  }
}

}  // namespace

void buildCubeMipChain(CubeMap& cube) { buildMipChain(cube.levels, kCubeFaces); }

CubeCoord cubeCoordFromDirection(const glm::dvec3& r) {
  const double ax = std::abs(r.x), ay = std::abs(r.y), az = std::abs(r.z);
  double sc = 0.0, tc = 0.0, ma = 1.0;
  CubeCoord c;
  if (az >= std::max(ax, ay)) {  // ties go to z, then y (llvmpipe's rule)
    const bool negative = std::signbit(r.z);
    c.face = negative ? 5 : 4;
    sc = negative ? -r.x : r.x;
    tc = -r.y;
    ma = az;
  } else if (ax > ay) {
    c.face = r.x >= 0.0 ? 0 : 1;
    sc = r.x >= 0.0 ? -r.z : r.z;
    tc = -r.y;
    ma = ax;
  } else {
    c.face = r.y >= 0.0 ? 2 : 3;
    sc = r.x;
    tc = r.y >= 0.0 ? r.z : -r.z;
    ma = ay;
  }
  if (ma > 0.0) {
    c.s = 0.5 * (sc / ma + 1.0);
    c.t = 0.5 * (tc / ma + 1.0);
  }
  return c;
}

glm::dvec3 directionFromCubeCoord(int face, double s, double t) {
  const double sc = 2.0 * s - 1.0, tc = 2.0 * t - 1.0;
  switch (face) {
    case 0: return {1.0, -tc, -sc};
    case 1: return {-1.0, -tc, sc};
    case 2: return {sc, 1.0, tc};
    case 3: return {sc, -1.0, -tc};
    case 4: return {sc, -tc, 1.0};
    default: return {-sc, -tc, -1.0};
  }
}

const CubeEdgeTable& cubeEdgeTable() {
  static const CubeEdgeTable table = [] {
    // On a face of 8 texels, the texel centre one step past each edge, pushed a hair further
    // out, lands on the neighbour's edge texel; two rows along the edge give the affine map.
    constexpr int kSize = 8;
    constexpr double kPast = 1e-6;  // beyond the edge, in s or t units
    CubeEdgeTable t;
    const auto neighbour = [&](int face, int edge, int along) {
      double s = 0.0, tt = 0.0;
      const double centre = (along + 0.5) / kSize;
      switch (edge) {
        case 0: s = -kPast, tt = centre; break;
        case 1: s = 1.0 + kPast, tt = centre; break;
        case 2: s = centre, tt = -kPast; break;
        default: s = centre, tt = 1.0 + kPast; break;
      }
      const CubeCoord c = cubeCoordFromDirection(directionFromCubeCoord(face, s, tt));
      return std::array<int, 3>{c.face, std::clamp(static_cast<int>(std::floor(c.s * kSize)), 0, kSize - 1),
                                std::clamp(static_cast<int>(std::floor(c.t * kSize)), 0, kSize - 1)};
    };
    for (int face = 0; face < kCubeFaces; ++face) {
      for (int edge = 0; edge < 4; ++edge) {
        const std::size_t k = static_cast<std::size_t>(4 * face + edge);
        const std::array<int, 3> first = neighbour(face, edge, 0), second = neighbour(face, edge, 1);
        t.face[k] = static_cast<float>(first[0]);
        t.xPerAlong[k] = static_cast<float>(second[1] - first[1]);
        t.yPerAlong[k] = static_cast<float>(second[2] - first[2]);
        t.xAtLast[k] = first[1] == kSize - 1 ? 1.0f : 0.0f;
        t.yAtLast[k] = first[2] == kSize - 1 ? 1.0f : 0.0f;
      }
    }
    return t;
  }();
  return table;
}

glm::dvec2 equirectUvFromDirection(const glm::dvec3& r) {
  const double length = std::sqrt(r.x * r.x + r.y * r.y + r.z * r.z);
  if (!(length > 0.0)) return {0.5, 0.5};
  const double longitude = std::atan2(r.x, -r.z);  // 0 towards -Z, pi/2 towards +X
  const double latitude = std::acos(std::clamp(r.y / length, -1.0, 1.0));  // 0 at +Y
  return {0.5 + longitude / (2.0 * std::numbers::pi), latitude / std::numbers::pi};
}

int layerCount(EnvironmentParameterization kind) {
  switch (kind) {
    case EnvironmentParameterization::Sphere: return 1;
    case EnvironmentParameterization::DualParaboloid: return 2;
    case EnvironmentParameterization::Cube: break;
  }
  return kCubeFaces;
}

MapCoord mapCoordFromDirection(EnvironmentParameterization kind, const glm::dvec3& rIn) {
  const double length = std::sqrt(rIn.x * rIn.x + rIn.y * rIn.y + rIn.z * rIn.z);
  const glm::dvec3 r = length > 0.0 ? rIn / length : glm::dvec3(0.0, 0.0, 1.0);
  MapCoord c;
  if (kind == EnvironmentParameterization::Sphere) {
    const double z1 = r.z + 1.0;
    const double m = 2.0 * std::sqrt(r.x * r.x + r.y * r.y + z1 * z1);
    if (m > 0.0) {
      c.u = r.x / m + 0.5;
      c.v = r.y / m + 0.5;
    }
    return c;
  }
  c.layer = r.z < 0.0 ? 1 : 0;
  const double d = 1.0 + std::abs(r.z);
  c.u = r.x / d * 0.5 + 0.5;
  c.v = r.y / d * 0.5 + 0.5;
  return c;
}

glm::dvec3 directionFromMapCoord(EnvironmentParameterization kind, int layer, double u, double v) {
  const double a = 2.0 * u - 1.0, b = 2.0 * v - 1.0;
  const double rho2 = a * a + b * b;
  if (kind == EnvironmentParameterization::Sphere) {
    // The ball's normal at (a, b) reflects the view direction -Z: r = (0, 0, -1) + 2 nz n.
    if (rho2 >= 1.0) return {0.0, 0.0, -1.0};
    const double nz = std::sqrt(1.0 - rho2);
    return {2.0 * nz * a, 2.0 * nz * b, 2.0 * nz * nz - 1.0};
  }
  // The paraboloid z = (1 - rho^2) / 2 reflects +-Z into r = (2a, 2b, 1 - rho^2) / (1 + rho^2).
  const double zSign = layer == 0 ? 1.0 : -1.0;
  return glm::dvec3(2.0 * a, 2.0 * b, zSign * (1.0 - rho2)) / (1.0 + rho2);
}

glm::dvec3 cubeBilinear(const CubeMap& cube, const glm::dvec3& r, int levelIndex) {
  const CubeMapLevel& level = cube.levels[static_cast<std::size_t>(levelIndex)];
  const int size = level.size;
  const CubeCoord c = cubeCoordFromDirection(r);
  // A texel one step past an edge: the neighbour face's texel its centre's direction lands on.
  const auto across = [&](int x, int y) {
    const CubeCoord n = cubeCoordFromDirection(directionFromCubeCoord(c.face, (x + 0.5) / size, (y + 0.5) / size));
    const int nx = std::clamp(static_cast<int>(std::floor(n.s * size)), 0, size - 1);
    const int ny = std::clamp(static_cast<int>(std::floor(n.t * size)), 0, size - 1);
    return glm::dvec3(level.texel(n.face, nx, ny));
  };
  const auto texel = [&](int x, int y) {
    const bool outX = x < 0 || x >= size, outY = y < 0 || y >= size;
    if (!outX && !outY) return glm::dvec3(level.texel(c.face, x, y));
    if (!outX || !outY) return across(x, y);
    // A corner: no such texel; the mean of the three that meet there.
    const int cx = std::clamp(x, 0, size - 1), cy = std::clamp(y, 0, size - 1);
    return (glm::dvec3(level.texel(c.face, cx, cy)) + across(x, cy) + across(cx, y)) / 3.0;
  };
  const double x = c.s * size - 0.5, y = c.t * size - 0.5;
  const double x0 = std::floor(x), y0 = std::floor(y);
  const double ax = x - x0, ay = y - y0;
  const int ix = static_cast<int>(x0), iy = static_cast<int>(y0);
  const glm::dvec3 lower = texel(ix, iy) * (1.0 - ax) + texel(ix + 1, iy) * ax;
  const glm::dvec3 upper = texel(ix, iy + 1) * (1.0 - ax) + texel(ix + 1, iy + 1) * ax;
  return lower * (1.0 - ay) + upper * ay;
}

glm::dvec3 mapBilinear(const ParameterizedMap& map, int level, const MapCoord& c) {
  const CubeMapLevel& lv = map.levels[static_cast<std::size_t>(level)];
  const int size = lv.size;
  const double x = c.u * size - 0.5, y = c.v * size - 0.5;
  const double x0 = std::floor(x), y0 = std::floor(y);
  const double ax = x - x0, ay = y - y0;
  const auto texel = [&](double tx, double ty) {
    const int ix = static_cast<int>(std::clamp(tx, 0.0, size - 1.0)), iy = static_cast<int>(std::clamp(ty, 0.0, size - 1.0));
    return glm::dvec3(lv.texel(c.layer, ix, iy));
  };
  const glm::dvec3 lower = texel(x0, y0) * (1.0 - ax) + texel(x0 + 1.0, y0) * ax;
  const glm::dvec3 upper = texel(x0, y0 + 1.0) * (1.0 - ax) + texel(x0 + 1.0, y0 + 1.0) * ax;
  return lower * (1.0 - ay) + upper * ay;
}

ParameterizedMap parameterizedMapFromCube(const CubeMap& cube, EnvironmentParameterization kind, int size) {
  if (kind == EnvironmentParameterization::Cube || !isPowerOfTwo(size) || size > kMaxCubeFaceSize || cube.levels.empty()) {
    throw InputError(cube.source + ": a " + std::string(toString(kind)) + " map of " + std::to_string(size) +
                     " texels; expected a sphere or dual_paraboloid map with a power-of-two side in [1, " +
                     std::to_string(kMaxCubeFaceSize) + "]");
  }
  ParameterizedMap map;
  map.kind = kind;
  map.layers = layerCount(kind);
  CubeMapLevel level = allocateLevel(size, map.layers);
  for (int layer = 0; layer < map.layers; ++layer) {
    for (int y = 0; y < size; ++y) {
      for (int x = 0; x < size; ++x) {
        const glm::dvec3 c = cubeBilinear(cube, directionFromMapCoord(kind, layer, (x + 0.5) / size, (y + 0.5) / size));
        const std::size_t i = level.index(layer, x, y);
        level.r[i] = static_cast<float>(c.x);
        level.g[i] = static_cast<float>(c.y);
        level.b[i] = static_cast<float>(c.z);
      }
    }
  }
  map.levels.push_back(std::move(level));
  buildMipChain(map.levels, map.layers);
  return map;
}

ParameterizedMap parameterizedMapFromCubeLevels(const CubeMap& cube, EnvironmentParameterization kind, int size) {
  ParameterizedMap map = parameterizedMapFromCube(cube, kind, size);
  // Level l of side size / 2^l from the cube's level l, as level 0 was from its level 0; as
  // many levels as the cube has (GL_TEXTURE_MAX_LEVEL says where the chain stops).
  map.levels.resize(std::min(map.levels.size(), cube.levels.size()));
  for (std::size_t l = 1; l < map.levels.size(); ++l) {
    CubeMapLevel& level = map.levels[l];
    const int side = level.size;
    for (int layer = 0; layer < map.layers; ++layer) {
      for (int y = 0; y < side; ++y) {
        for (int x = 0; x < side; ++x) {
          const glm::dvec3 c = cubeBilinear(cube, directionFromMapCoord(kind, layer, (x + 0.5) / side, (y + 0.5) / side),
                                            static_cast<int>(l));
          const std::size_t i = level.index(layer, x, y);
          level.r[i] = static_cast<float>(c.x);
          level.g[i] = static_cast<float>(c.y);
          level.b[i] = static_cast<float>(c.z);
        }
      }
    }
  }
  return map;
}

}  // namespace twr
