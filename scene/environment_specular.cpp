#include "scene/environment_specular.h"

#include "scene/environment_light.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <thread>
#include <vector>

namespace twr {
namespace {

// d projected onto face f's plane, GL's table (scene/environment.h): (s, t) and the signed
// major component, positive on the face's side.
struct FaceProjection {
  double s = 0.5, t = 0.5, major = 0.0;
};
FaceProjection projectOnFace(int face, const glm::dvec3& d) {
  double sc = 0.0, tc = 0.0, ma = 0.0;
  switch (face) {
    case 0: sc = -d.z; tc = -d.y; ma = d.x; break;
    case 1: sc = d.z; tc = -d.y; ma = -d.x; break;
    case 2: sc = d.x; tc = d.z; ma = d.y; break;
    case 3: sc = d.x; tc = -d.z; ma = -d.y; break;
    case 4: sc = d.x; tc = -d.y; ma = d.z; break;
    default: sc = -d.x; tc = -d.y; ma = -d.z; break;
  }
  return {0.5 * (sc / ma + 1.0), 0.5 * (tc / ma + 1.0), ma};
}

// The texels [x0, x1] x [y0, y1] (inclusive) of face `face` (side `side`) that can lie within
// `cutoff` radians of unit r: the bounding box of the cap's projection on the face's plane. A
// cap in the face's open half-space projects to a convex region whose edge is the projection
// of the cap's edge, so the box of kCapEdgePoints points on that edge, widened by a texel and
// by the chords' bulge, holds it; a cap reaching the face's horizon takes the whole face. The
// sum then tests every texel of the box against the cutoff itself, so the box only has to be
// large enough.
struct TexelWindow {
  int x0 = 0, x1 = -1, y0 = 0, y1 = -1;  // empty when x1 < x0
};
constexpr int kCapEdgePoints = 32;
TexelWindow capWindow(const glm::dvec3& r, double cutoff, int face, int side) {
  // Every texel of a face is within acos(1 / sqrt(3)) (54.7 degrees, its corners) of its
  // axis: a cap whose nearest point is farther holds none of them.
  const double faceRadius = std::acos(1.0 / std::sqrt(3.0));
  const double towardsAxis = projectOnFace(face, r).major;  // r . the face's axis
  if (std::acos(std::clamp(towardsAxis, -1.0, 1.0)) - cutoff > faceRadius) return TexelWindow{};
  const TexelWindow whole{0, side - 1, 0, side - 1};
  const BasisD basis = duffBasis(r);
  const double cosC = std::cos(cutoff), sinC = std::sin(cutoff);
  double sMin = 1e300, sMax = -1e300, tMin = 1e300, tMax = -1e300;
  static const std::array<glm::dvec2, kCapEdgePoints> around = [] {
    std::array<glm::dvec2, kCapEdgePoints> a{};
    for (int k = 0; k < kCapEdgePoints; ++k) {
      const double phi = 2.0 * std::numbers::pi * k / kCapEdgePoints;
      a[static_cast<std::size_t>(k)] = glm::dvec2(std::cos(phi), std::sin(phi));
    }
    return a;
  }();
  for (const glm::dvec2& cs : around) {
    const glm::dvec3 p = r * cosC + (basis.b1 * cs.x + basis.b2 * cs.y) * sinC;
    const FaceProjection q = projectOnFace(face, p);
    if (!(q.major > 0.0)) return whole;
    sMin = std::min(sMin, q.s);
    sMax = std::max(sMax, q.s);
    tMin = std::min(tMin, q.t);
    tMax = std::max(tMax, q.t);
  }
  // The chords of kCapEdgePoints points fall short of the curve by under 1 - cos(pi / 32) of
  // the extent (0.5 %); 2 % and a texel each way is ample.
  const double marginS = 0.02 * (sMax - sMin) + 1.0 / side, marginT = 0.02 * (tMax - tMin) + 1.0 / side;
  const auto texel = [side](double c) { return static_cast<int>(std::floor(std::clamp(c, -1.0, 2.0) * side)); };
  TexelWindow w;
  w.x0 = std::max(0, texel(sMin - marginS));
  w.x1 = std::min(side - 1, texel(sMax + marginS));
  w.y0 = std::max(0, texel(tMin - marginT));
  w.y1 = std::min(side - 1, texel(tMax + marginT));
  if (w.x1 < w.x0 || w.y1 < w.y0) return TexelWindow{};
  return w;
}

// The first level of `cube` whose side is at most `side` (the last level when none is).
const CubeMapLevel& levelAtMost(const CubeMap& cube, int side) {
  for (const CubeMapLevel& level : cube.levels) {
    if (level.size <= side) return level;
  }
  return cube.levels.back();
}

// max(c, 0)^e for the exponent of a level of side `side`, e = (side / 2)^2 = 4^(log2(side) - 1):
// c squared 2 (log2(side) - 1) times (12 squarings for 4096, each doubling the relative
// rounding error, so about 4096 ulps at most, 1e-12), or its fourth root for side 1. A tenth
// of pow()'s time, which was most of the build.
double lobeWeight(double c, int side) {
  if (side == 1) return std::sqrt(std::sqrt(c));
  double w = c;
  for (int s = side; s > 2; s /= 2) {
    w *= w;
    w *= w;
  }
  return w;
}

// One level of the prefiltered cube: every texel the lobe-weighted mean of `source` around
// its centre's direction, rows shared out over the machine's cores.
CubeMapLevel convolvedLevel(const CubeLevelTexels& source, int side) {
  const double exponent = specularExponentOfSide(side);
  CubeMapLevel out;
  out.size = side;
  const std::size_t texels = static_cast<std::size_t>(kCubeFaces) * static_cast<std::size_t>(side) * static_cast<std::size_t>(side);
  out.r.resize(texels);
  out.g.resize(texels);
  out.b.resize(texels);
  // The lobe's cutoff angle: where cos^e falls to kSpecularLobeCutoff, at most 90 degrees.
  const double cutoff = std::acos(std::clamp(std::pow(kSpecularLobeCutoff, 1.0 / exponent), 0.0, 1.0));
  const double cosCutoff = std::cos(cutoff);
  const std::size_t sourceSide = static_cast<std::size_t>(source.side);
  const auto rows = [&](int rowBegin, int rowEnd) {  // rows of all six faces: face * side + y
    for (int row = rowBegin; row < rowEnd; ++row) {
      const int face = row / side, y = row % side;
      for (int x = 0; x < side; ++x) {
        const glm::dvec3 r = cubeTexelDirection(face, x, y, side);
        glm::dvec3 sum(0.0);
        double weights = 0.0;
        for (int f = 0; f < kCubeFaces; ++f) {
          const TexelWindow w = capWindow(r, cutoff, f, source.side);
          for (int sy = w.y0; sy <= w.y1; ++sy) {
            const std::size_t first = (static_cast<std::size_t>(f) * sourceSide + static_cast<std::size_t>(sy)) * sourceSide;
            for (int sx = w.x0; sx <= w.x1; ++sx) {
              const std::size_t j = first + static_cast<std::size_t>(sx);
              const double c = glm::dot(r, source.direction[j]);
              if (c <= cosCutoff) continue;
              const double weight = lobeWeight(c, side) * source.solidAngle[j];
              sum += source.radiance[j] * weight;
              weights += weight;
            }
          }
        }
        // The source is at least as fine as this level and the cutoff is over 8 of its texels
        // wide, so some texel is always inside; the guard only keeps 0 / 0 out.
        const glm::dvec3 g = weights > 0.0 ? sum / weights : glm::dvec3(0.0);
        const std::size_t i = out.index(face, x, y);
        out.r[i] = static_cast<float>(g.r);
        out.g[i] = static_cast<float>(g.g);
        out.b[i] = static_cast<float>(g.b);
      }
    }
  };
  const int allRows = kCubeFaces * side;
  const int threads = std::clamp(static_cast<int>(std::thread::hardware_concurrency()), 1, allRows);
  std::vector<std::thread> workers;
  for (int i = 1; i < threads; ++i) workers.emplace_back(rows, allRows * i / threads, allRows * (i + 1) / threads);
  rows(0, allRows / threads);
  for (std::thread& worker : workers) worker.join();
  return out;
}

}  // namespace

double specularExponentOfSide(int side) {
  const double half = 0.5 * side;
  return half * half;
}

CubeMap specularCubeFromCube(const CubeMap& cube) {
  CubeMap out;
  out.source = cube.source + " (prefiltered specular)";
  const int top = cube.size();
  for (int side = std::min(top, kSpecularCubeMaxSize); side >= 1; side /= 2) {
    const CubeLevelTexels source = cubeLevelTexels(levelAtMost(cube, std::min(top, std::max(2 * side, kSpecularMinSourceSize))));
    out.levels.push_back(convolvedLevel(source, side));
  }
  return out;
}

double specularLodFromShininess(const CubeMap& specular, double shininess) {
  const double last = static_cast<double>(specular.levelCount() - 1);
  if (!(shininess > 0.0)) return last;
  const double lod = 0.5 * std::log2(specularExponentOfSide(specular.size()) / shininess);
  return std::clamp(lod, 0.0, last);
}

MonteCarloEstimate specularMonteCarlo(const CubeMap& cube, const glm::dvec3& r, double exponent, std::size_t samples,
                                      std::uint64_t seed) {
  return lobeMonteCarlo(r, exponent, samples, seed, [&](const glm::dvec3& w) { return cubeBilinear(cube, w); });
}

glm::dvec3 cubeTrilinear(const CubeMap& cube, const glm::dvec3& r, double lod) {
  const double clamped = std::clamp(std::isfinite(lod) ? lod : 0.0, 0.0, static_cast<double>(cube.levelCount() - 1));
  const int level0 = static_cast<int>(std::floor(clamped));
  const double fraction = clamped - level0;
  const glm::dvec3 c0 = cubeBilinear(cube, r, level0);
  if (fraction == 0.0) return c0;
  return c0 + (cubeBilinear(cube, r, level0 + 1) - c0) * fraction;
}

}  // namespace twr
