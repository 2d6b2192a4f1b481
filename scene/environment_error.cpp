#include "scene/environment_error.h"

#include <algorithm>
#include <cmath>
#include <numbers>

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
  const double golden = std::numbers::pi * (3.0 - std::sqrt(5.0));  // radians between neighbours
  double sumSquares = 0.0;
  for (std::size_t i = 0; i < count; ++i) {
    const double z = 1.0 - (2.0 * static_cast<double>(i) + 1.0) / static_cast<double>(count);
    const double radius = std::sqrt(std::max(0.0, 1.0 - z * z));
    const double phi = golden * static_cast<double>(i);
    const glm::dvec3 r(radius * std::cos(phi), radius * std::sin(phi), z);
    const double error = parameterizationErrorAt(cube, map, r);
    errors[i] = error;
    sumSquares += error * error;
    if (error > e.maxError) {
      e.maxError = error;
      e.worstDirection = r;
    }
  }
  e.rmse = std::sqrt(sumSquares / static_cast<double>(count));
  const std::size_t rank = std::min(count - 1, static_cast<std::size_t>(std::ceil(0.99 * static_cast<double>(count))) - 1);
  std::nth_element(errors.begin(), errors.begin() + static_cast<std::ptrdiff_t>(rank), errors.end());
  e.p99 = errors[rank];
  return e;
}

std::vector<double> parameterizationErrorImage(const CubeMap& cube, const ParameterizedMap& map, int width, int height) {
  std::vector<double> image(static_cast<std::size_t>(std::max(width, 0)) * static_cast<std::size_t>(std::max(height, 0)));
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      const glm::dvec3 r = directionFromEquirect((x + 0.5) / width, (y + 0.5) / height);
      image[static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x)] =
          parameterizationErrorAt(cube, map, r);
    }
  }
  return image;
}

}  // namespace twr
