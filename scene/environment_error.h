// How far a sphere or dual-paraboloid map is from the cube it was built from
// (docs/environment.md, "Which mapping distorts where"): the map read at level 0, bilinear, in
// double (mapBilinear), against the cube read exactly in the same direction (cubeBilinear).
// Both are clamped to [0, 1] (what a pixel shows) and the error of a direction is the largest
// channel's difference in 8-bit levels (1 level = 1/255).
#pragma once

#include "scene/environment.h"
#include "scene/environment_light.h"
#include "scene/environment_specular.h"

#include <cstddef>
#include <cstdint>
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

// ---- The diffuse light (scene/environment_light.h, docs/environment.md "Diffuse light") ----
// D(n) from the irradiance cube (read at level 0, bilinear) and from SH9, each against a
// Monte Carlo estimate over the source itself (irradianceMonteCarlo), and SH9 against the
// cube; a normal's error is the largest channel's difference in levels (1/255 of the source's
// unit, unclamped: D may exceed 1 under an HDR sky).
struct DiffuseLightComparison {
  double rmse = 0.0, p99 = 0.0, maxError = 0.0;  // levels, over the normals
  glm::dvec3 worstNormal{0.0, 0.0, 1.0};
};
struct DiffuseLightError {
  std::size_t normals = 0, samples = 0;  // normals on a Fibonacci sphere, Monte Carlo samples each
  // The reference's own noise: the root mean square over the normals of its standard error
  // (the samples' standard deviation over sqrt(samples), largest channel), levels. A
  // comparison against the reference cannot resolve errors well below it.
  double referenceNoise = 0.0;
  DiffuseLightComparison mapVsReference, sh9VsReference, sh9VsMap;
};
DiffuseLightError measureDiffuseLightError(const CubeMap& cube, const CubeMap& irradiance, const Sh9Irradiance& sh,
                                           std::size_t normals, std::size_t samples, std::uint64_t seed);

// D at the centre of each pixel of a width x height equirect grid (the convention above), row
// 0 first: from the irradiance cube, and from SH9.
std::vector<glm::dvec3> irradianceCubeImage(const CubeMap& irradiance, int width, int height);
std::vector<glm::dvec3> sh9Image(const Sh9Irradiance& sh, int width, int height);

// ---- The glossy reflection (scene/environment_specular.h, docs/environment.md "Glossy
// reflection") ----
// G_s(r) from the prefiltered cube read at the shininess's LOD as textureLod reads it
// (cubeTrilinear), against a Monte Carlo estimate of the lobe of exponent s over the source
// itself (specularMonteCarlo); and, to show what prefiltering buys, the source read in the
// mirror direction alone (cubeBilinear at level 0) against the same estimate. Levels as above.
struct GlossyRow {
  double shininess = 0.0;
  double lod = 0.0;            // specularLodFromShininess
  double referenceNoise = 0.0;  // the estimate's own noise, RMS over the directions (levels)
  DiffuseLightComparison prefiltered, mirror;
};
struct GlossyError {
  std::size_t directions = 0, samples = 0;  // directions on a Fibonacci sphere, Monte Carlo samples each
  std::vector<GlossyRow> rows;              // one per shininess, in the order given
};
// Directions are shared out over the machine's cores; the result does not depend on how many.
GlossyError measureGlossyError(const CubeMap& cube, const CubeMap& specular, const std::vector<double>& shininesses,
                               std::size_t directions, std::size_t samples, std::uint64_t seed);

// G at the centre of each pixel of an equirect grid (the convention above), read from the
// prefiltered cube at `lod`, row 0 first.
std::vector<glm::dvec3> glossyImage(const CubeMap& specular, double lod, int width, int height);

}  // namespace twr
