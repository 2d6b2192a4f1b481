#include "scene/environment_error.h"

#include "scene/statistics.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <thread>
#include <utility>

namespace twr {

namespace {

constexpr double kLevelsPerUnit = 255.0;  // 8-bit levels per unit of linear colour

glm::dvec3 clampedUnit(const glm::dvec3& c) { return glm::clamp(c, glm::dvec3(0.0), glm::dvec3(1.0)); }

// The direction of an equirect pixel centre (inverse of equirectUvFromDirection).
glm::dvec3 directionFromEquirect(double u, double v) {
  const double longitude = (u - 0.5) * 2.0 * std::numbers::pi;
  const double latitude = v * std::numbers::pi;  // 0 at +Y
  return {std::sin(latitude) * std::sin(longitude), std::cos(latitude), -std::sin(latitude) * std::cos(longitude)};
}

// A width x height equirect grid of f(direction), row 0 first.
template <typename T, typename F>
std::vector<T> equirectOf(int width, int height, F f) {
  std::vector<T> image(static_cast<std::size_t>(width) * static_cast<std::size_t>(height));
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      image[static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x)] =
          f(directionFromEquirect((x + 0.5) / width, (y + 0.5) / height));
    }
  }
  return image;
}

// Largest channel's |a - b|, levels.
double levelsApart(const glm::dvec3& a, const glm::dvec3& b) {
  const glm::dvec3 d = glm::abs(a - b);
  return std::max({d.x, d.y, d.z}) * kLevelsPerUnit;
}

// RMSE, 99th percentile and worst of per-normal errors.
DiffuseLightComparison summarise(std::vector<double> errors, const std::vector<glm::dvec3>& normals) {
  DiffuseLightComparison c;
  if (errors.empty()) return c;
  double sumSquares = 0.0;
  for (std::size_t i = 0; i < errors.size(); ++i) {
    sumSquares += errors[i] * errors[i];
    if (errors[i] > c.maxError) {
      c.maxError = errors[i];
      c.worstNormal = normals[i];
    }
  }
  c.rmse = std::sqrt(sumSquares / static_cast<double>(errors.size()));
  c.p99 = quantileOf(std::move(errors), 0.99);
  return c;
}

}  // namespace

double parameterizationErrorAt(const CubeMap& cube, const ParameterizedMap& map, const glm::dvec3& r) {
  const glm::dvec3 fromMap = clampedUnit(mapBilinear(map, 0, mapCoordFromDirection(map.kind, r)));
  const glm::dvec3 exact = clampedUnit(cubeBilinear(cube, r));
  const glm::dvec3 d = glm::abs(fromMap - exact);
  return std::max({d.x, d.y, d.z}) * kLevelsPerUnit;
}

ParameterizationError measureParameterizationError(const CubeMap& cube, const ParameterizedMap& map, std::size_t count) {
  ParameterizationError e;
  e.directions = count;
  if (count == 0) return e;
  std::vector<double> errors(count);
  double sumSquares = 0.0;
  for (std::size_t i = 0; i < count; ++i) {
    const glm::dvec3 r = fibonacciSphereDirection(i, count);
    const double error = parameterizationErrorAt(cube, map, r);
    errors[i] = error;
    sumSquares += error * error;
    if (error > e.maxError) {
      e.maxError = error;
      e.worstDirection = r;
    }
  }
  e.rmse = std::sqrt(sumSquares / static_cast<double>(count));
  e.p99 = quantileOf(std::move(errors), 0.99);
  return e;
}

std::vector<double> parameterizationErrorImage(const CubeMap& cube, const ParameterizedMap& map, int width, int height) {
  return equirectOf<double>(width, height, [&](const glm::dvec3& r) { return parameterizationErrorAt(cube, map, r); });
}

DiffuseLightError measureDiffuseLightError(const CubeMap& cube, const CubeMap& irradiance, const Sh9Irradiance& sh,
                                           std::size_t normals, std::size_t samples, std::uint64_t seed) {
  DiffuseLightError e;
  e.normals = normals;
  e.samples = samples;
  std::vector<glm::dvec3> where(normals);
  std::vector<double> mapError(normals), shError(normals), shMapError(normals);
  double noiseSquares = 0.0;
  for (std::size_t i = 0; i < normals; ++i) {
    const glm::dvec3 n = fibonacciSphereDirection(i, normals);
    where[i] = n;
    const MonteCarloIrradiance reference = irradianceMonteCarloWithError(cube, n, samples, seed + i);
    const glm::dvec3 fromMap = cubeBilinear(irradiance, n);
    const glm::dvec3 fromSh = irradianceFromSh9(sh, n);
    mapError[i] = levelsApart(fromMap, reference.mean);
    shError[i] = levelsApart(fromSh, reference.mean);
    shMapError[i] = levelsApart(fromSh, fromMap);
    const double noise = std::max({reference.standardError.x, reference.standardError.y, reference.standardError.z}) *
                         kLevelsPerUnit;
    noiseSquares += noise * noise;
  }
  if (normals > 0) e.referenceNoise = std::sqrt(noiseSquares / static_cast<double>(normals));
  e.mapVsReference = summarise(std::move(mapError), where);
  e.sh9VsReference = summarise(std::move(shError), where);
  e.sh9VsMap = summarise(std::move(shMapError), where);
  return e;
}

std::vector<glm::dvec3> irradianceCubeImage(const CubeMap& irradiance, int width, int height) {
  return equirectOf<glm::dvec3>(width, height, [&](const glm::dvec3& r) { return cubeBilinear(irradiance, r); });
}

std::vector<glm::dvec3> sh9Image(const Sh9Irradiance& sh, int width, int height) {
  return equirectOf<glm::dvec3>(width, height, [&](const glm::dvec3& r) { return irradianceFromSh9(sh, r); });
}

GlossyError measureGlossyError(const CubeMap& cube, const CubeMap& specular, const std::vector<double>& shininesses,
                               std::size_t directions, std::size_t samples, std::uint64_t seed) {
  GlossyError e;
  e.directions = directions;
  e.samples = samples;
  std::vector<glm::dvec3> where(directions);
  for (std::size_t i = 0; i < directions; ++i) where[i] = fibonacciSphereDirection(i, directions);
  for (double shininess : shininesses) {
    GlossyRow row;
    row.shininess = shininess;
    row.lod = specularLodFromShininess(specular, shininess);
    std::vector<double> prefilteredError(directions), mirrorError(directions), noise(directions);
    // Each direction's seed is its own (seed + i), so the split over threads changes nothing.
    const auto measure = [&](std::size_t begin, std::size_t end) {
      for (std::size_t i = begin; i < end; ++i) {
        const MonteCarloEstimate reference = specularMonteCarlo(cube, where[i], shininess, samples, seed + i);
        prefilteredError[i] = levelsApart(cubeTrilinear(specular, where[i], row.lod), reference.mean);
        mirrorError[i] = levelsApart(cubeBilinear(cube, where[i]), reference.mean);
        const glm::dvec3& se = reference.standardError;
        noise[i] = std::max({se.x, se.y, se.z}) * kLevelsPerUnit;
      }
    };
    const std::size_t threads =
        std::clamp<std::size_t>(std::thread::hardware_concurrency(), 1, std::max<std::size_t>(directions, 1));
    std::vector<std::thread> workers;
    for (std::size_t t = 1; t < threads; ++t) workers.emplace_back(measure, directions * t / threads, directions * (t + 1) / threads);
    measure(0, directions / threads);
    for (std::thread& worker : workers) worker.join();
    double noiseSquares = 0.0;
    for (double n : noise) noiseSquares += n * n;
    if (directions > 0) row.referenceNoise = std::sqrt(noiseSquares / static_cast<double>(directions));
    row.prefiltered = summarise(std::move(prefilteredError), where);
    row.mirror = summarise(std::move(mirrorError), where);
    e.rows.push_back(row);
  }
  return e;
}

std::vector<glm::dvec3> glossyImage(const CubeMap& specular, double lod, int width, int height) {
  return equirectOf<glm::dvec3>(width, height, [&](const glm::dvec3& r) { return cubeTrilinear(specular, r, lod); });
}

}  // namespace twr
