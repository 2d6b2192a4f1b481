// How far a sphere or dual-paraboloid map is from the cube it was built from
// (docs/environment.md, "Which mapping distorts where"): the map read at level 0, bilinear, in
// double (mapBilinear), against the cube read exactly in the same direction (cubeBilinear).
// Both are clamped to [0, 1] (what a pixel shows) and the error of a direction is the largest
// channel's difference in 8-bit levels (1 level = 1/255).
#pragma once

#include "scene/environment.h"

#include <cstddef>
#include <vector>

namespace twr {

struct ParameterizationError {
  std::size_t directions = 0;
  double rmse = 0.0;      // levels, over the directions
  double p99 = 0.0;       // levels: 99 % of the directions are within it
  double maxError = 0.0;  // levels
  glm::dvec3 worstDirection{0.0, 0.0, 1.0};
};

// The error in one direction (levels).
double parameterizationErrorAt(const CubeMap& cube, const ParameterizedMap& map, const glm::dvec3& r);

// Over `count` directions spread evenly over the sphere (a Fibonacci sphere: deterministic, the
// same for every map, so sizes compare point by point).
ParameterizationError measureParameterizationError(const CubeMap& cube, const ParameterizedMap& map, std::size_t count);

// The error at the centre of each pixel of a width x height equirect grid (scene/environment.h's
// convention: -Z at the centre, +X a quarter to the right, +Y along the top row), row 0 first,
// in levels: a picture of where the mapping loses detail.
std::vector<double> parameterizationErrorImage(const CubeMap& cube, const ParameterizedMap& map, int width, int height);

}  // namespace twr
