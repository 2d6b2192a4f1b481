#include "scene/environment_light.h"

#include "scene/environment_specular.h"
#include "scene/monte_carlo.h"
#include "scene/scene.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace twr {
namespace {

// Side of the sphere or paraboloid map the irradiance cube is turned into (texels): a layer
// spans 180 to 360 degrees where a cube face spans 90, so twice the cube's side.
constexpr int kIrradianceMapSize = 2 * kIrradianceCubeSize;

// The first level of `cube` whose side is at most `side` (the last level when none is).
const CubeMapLevel& sourceLevel(const CubeMap& cube, int side) {
  for (const CubeMapLevel& level : cube.levels) {
    if (level.size <= side) return level;
  }
  return cube.levels.back();
}

// The area on the unit sphere of the part of a face z = 1 between (0, 0) and (x, y) (the
// integral of (1 + x^2 + y^2)^-3/2): atan2(x y, sqrt(x^2 + y^2 + 1)).
double areaToOrigin(double x, double y) { return std::atan2(x * y, std::sqrt(x * x + y * y + 1.0)); }

// The nine polynomials of the real harmonics (their constants apart), in the order of
// Sh9Irradiance: 1, y, z, x, x y, y z, 3 z^2 - 1, x z, x^2 - y^2.
std::array<double, 9> shPolynomials(const glm::dvec3& n) {
  return {1.0, n.y, n.z, n.x, n.x * n.y, n.y * n.z, 3.0 * n.z * n.z - 1.0, n.x * n.z, n.x * n.x - n.y * n.y};
}
// The constants of the real harmonics Y_lm, band 0, 1, 2, in the same order.
std::array<double, 9> shConstants() {
  const double k0 = 0.5 / std::sqrt(kPi);               // Y00 = 1 / (2 sqrt(pi))
  const double k1 = std::sqrt(3.0 / (4.0 * kPi));       // Y1m
  const double k2 = 0.5 * std::sqrt(15.0 / kPi);        // Y2-2, Y2-1, Y21
  const double k20 = 0.25 * std::sqrt(5.0 / kPi);       // Y20
  const double k22 = 0.25 * std::sqrt(15.0 / kPi);      // Y22
  return {k0, k1, k1, k1, k2, k2, k20, k2, k22};
}
// A_l / pi per coefficient: the cosine lobe's band factors, divided by pi for D = E / pi.
constexpr std::array<double, 9> kBandFactorOverPi = {1.0,        2.0 / 3.0, 2.0 / 3.0, 2.0 / 3.0, 0.25,
                                                     0.25,       0.25,      0.25,      0.25};

}  // namespace

glm::dvec3 cubeTexelDirection(int face, int x, int y, int size) {
  return glm::normalize(directionFromCubeCoord(face, (x + 0.5) / size, (y + 0.5) / size));
}

double cubeTexelSolidAngle(int x, int y, int size) {
  const double step = 2.0 / size;
  const double x0 = -1.0 + x * step, x1 = x0 + step;
  const double y0 = -1.0 + y * step, y1 = y0 + step;
  return areaToOrigin(x1, y1) - areaToOrigin(x0, y1) - areaToOrigin(x1, y0) + areaToOrigin(x0, y0);
}

CubeLevelTexels cubeLevelTexels(const CubeMapLevel& level) {
  CubeLevelTexels s;
  s.side = level.size;
  const std::size_t count = level.r.size();
  s.direction.reserve(count);
  s.radiance.reserve(count);
  s.solidAngle.reserve(count);
  for (int face = 0; face < kCubeFaces; ++face) {
    for (int y = 0; y < level.size; ++y) {
      for (int x = 0; x < level.size; ++x) {
        s.direction.push_back(cubeTexelDirection(face, x, y, level.size));
        s.radiance.emplace_back(level.texel(face, x, y));
        s.solidAngle.push_back(cubeTexelSolidAngle(x, y, level.size));
      }
    }
  }
  return s;
}

CubeMap irradianceCubeFromCube(const CubeMap& cube, int size) {
  const CubeLevelTexels source = cubeLevelTexels(sourceLevel(cube, kIrradianceSourceSize));
  CubeMap out;
  out.source = cube.source + " (irradiance)";
  CubeMapLevel level;
  level.size = size;
  const std::size_t texels = static_cast<std::size_t>(kCubeFaces) * static_cast<std::size_t>(size) * static_cast<std::size_t>(size);
  level.r.resize(texels);
  level.g.resize(texels);
  level.b.resize(texels);
  for (int face = 0; face < kCubeFaces; ++face) {
    for (int y = 0; y < size; ++y) {
      for (int x = 0; x < size; ++x) {
        const glm::dvec3 n = cubeTexelDirection(face, x, y, size);
        glm::dvec3 sum(0.0);
        double weights = 0.0;
        for (std::size_t j = 0; j < source.direction.size(); ++j) {
          const double cosine = glm::dot(n, source.direction[j]);
          if (cosine <= 0.0) continue;
          const double w = cosine * source.solidAngle[j];
          sum += source.radiance[j] * w;
          weights += w;
        }
        // Divided by the weights' sum, which is pi but for the texels the horizon cuts (each
        // counted whole by its centre): a constant sky then comes back exactly.
        const glm::dvec3 d = sum / weights;
        const std::size_t i = level.index(face, x, y);
        level.r[i] = static_cast<float>(d.r);
        level.g[i] = static_cast<float>(d.g);
        level.b[i] = static_cast<float>(d.b);
      }
    }
  }
  out.levels.push_back(std::move(level));
  return out;
}

Sh9Irradiance sh9IrradianceFromCube(const CubeMap& cube) {
  const CubeLevelTexels source = cubeLevelTexels(sourceLevel(cube, kIrradianceSourceSize));
  std::array<glm::dvec3, 9> projection{};  // L_lm without Y's constants
  for (std::size_t j = 0; j < source.direction.size(); ++j) {
    const std::array<double, 9> p = shPolynomials(source.direction[j]);
    for (std::size_t i = 0; i < 9; ++i) projection[i] += source.radiance[j] * (p[i] * source.solidAngle[j]);
  }
  // L_lm = k_lm * projection; D = sum (A_l / pi) L_lm k_lm P_lm(n): k_lm^2 folded in.
  const std::array<double, 9> k = shConstants();
  Sh9Irradiance sh;
  for (std::size_t i = 0; i < 9; ++i) sh.c[i] = projection[i] * (kBandFactorOverPi[i] * k[i] * k[i]);
  return sh;
}

glm::dvec3 irradianceFromSh9(const Sh9Irradiance& sh, const glm::dvec3& n) {
  const std::array<double, 9> p = shPolynomials(n);
  glm::dvec3 d = sh.c[0];
  for (std::size_t i = 1; i < 9; ++i) d += sh.c[i] * p[i];
  return glm::max(d, glm::dvec3(0.0));
}

MonteCarloIrradiance irradianceMonteCarloWithError(const CubeMap& cube, const glm::dvec3& n, std::size_t samples,
                                                   std::uint64_t seed) {
  // Cosine-weighted samples: the lobe of exponent 1 around n.
  return lobeMonteCarlo(n, 1.0, samples, seed, [&](const glm::dvec3& w) { return cubeBilinear(cube, w); });
}

glm::dvec3 irradianceMonteCarlo(const CubeMap& cube, const glm::dvec3& n, std::size_t samples, std::uint64_t seed) {
  return irradianceMonteCarloWithError(cube, n, samples, seed).mean;
}

glm::dvec3 fibonacciSphereDirection(std::size_t i, std::size_t count) {
  const double golden = kPi * (3.0 - std::sqrt(5.0));  // radians between neighbours
  const double z = 1.0 - (2.0 * static_cast<double>(i) + 1.0) / static_cast<double>(count);
  const double radius = std::sqrt(std::max(0.0, 1.0 - z * z));
  const double phi = golden * static_cast<double>(i);
  return glm::dvec3(radius * std::cos(phi), radius * std::sin(phi), z);
}

bool materialReadsEnvironmentDirections(const Material& material) {
  return material.environmentSpecular != EnvironmentSpecular::None || material.refractionIndex > 0.0f;
}

bool materialReadsEnvironment(const Material& material, const Scene& scene) {
  return scene.environment && scene.environment->cube &&
         (materialReadsEnvironmentDirections(material) || material.environmentDiffuse != EnvironmentDiffuse::None);
}

EnvironmentDiffuse environmentDiffuseOf(const Material& material, const Environment& environment) {
  switch (material.environmentDiffuse) {
    case EnvironmentDiffuse::IrradianceMap:
      return environment.irradiance ? EnvironmentDiffuse::IrradianceMap : EnvironmentDiffuse::None;
    case EnvironmentDiffuse::Sh9: return environment.sh9 ? EnvironmentDiffuse::Sh9 : EnvironmentDiffuse::None;
    case EnvironmentDiffuse::None: break;
  }
  return EnvironmentDiffuse::None;
}

EnvironmentSpecular environmentSpecularOf(const Material& material, const Environment& environment) {
  if (material.environmentSpecular == EnvironmentSpecular::Prefiltered && !environment.specular) {
    return EnvironmentSpecular::None;
  }
  return material.environmentSpecular;
}

void prefilterEnvironmentLight(Scene& scene) {
  if (!scene.environment || !scene.environment->cube) return;
  Environment& e = *scene.environment;
  const auto wants = [&](EnvironmentDiffuse kind) {
    return std::any_of(scene.materials.begin(), scene.materials.end(),
                       [&](const Material& m) { return m.environmentDiffuse == kind; });
  };
  if (wants(EnvironmentDiffuse::IrradianceMap)) {
    if (!e.irradiance) e.irradiance = std::make_shared<CubeMap>(irradianceCubeFromCube(*e.cube));
    // Under a sphere or paraboloid parameterization the irradiance is read from a map of the
    // same kind, built from its cube (rebuilt when the parameterization changes).
    if (e.parameterization == EnvironmentParameterization::Cube) {
      e.irradianceLayers.reset();
    } else if (!e.irradianceLayers || e.irradianceLayers->kind != e.parameterization) {
      ParameterizedMap map = parameterizedMapFromCube(*e.irradiance, e.parameterization, kIrradianceMapSize);
      map.levels.resize(1);  // read at level 0 only, as the cube is
      e.irradianceLayers = std::make_shared<ParameterizedMap>(std::move(map));
    }
  }
  if (wants(EnvironmentDiffuse::Sh9) && !e.sh9) e.sh9 = std::make_shared<Sh9Irradiance>(sh9IrradianceFromCube(*e.cube));
  const bool wantsGloss = std::any_of(scene.materials.begin(), scene.materials.end(), [](const Material& m) {
    return m.environmentSpecular == EnvironmentSpecular::Prefiltered;
  });
  if (wantsGloss) {
    if (!e.specular) e.specular = std::make_shared<CubeMap>(specularCubeFromCube(*e.cube));
    if (e.parameterization == EnvironmentParameterization::Cube) {
      e.specularLayers.reset();
    } else if (!e.specularLayers || e.specularLayers->kind != e.parameterization) {
      // Twice the cube's side, as the environment's own map is by default: a layer spans 180
      // to 360 degrees where a face spans 90.
      e.specularLayers = std::make_shared<ParameterizedMap>(
          parameterizedMapFromCubeLevels(*e.specular, e.parameterization, 2 * e.specular->size()));
    }
  }
}

}  // namespace twr
