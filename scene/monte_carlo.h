// Monte Carlo references for the environment's prefiltered light (scene/environment_light.h,
// scene/environment_specular.h): estimates of lobe integrals over the source itself, with a
// fixed, portable random sequence, so every run of a measurement draws the same samples.
#pragma once

#include "scene/conventions.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <numbers>

namespace twr {

// splitmix64: a fixed, portable sequence (the same numbers on every compiler and CPU).
inline std::uint64_t splitMix64(std::uint64_t& state) {
  std::uint64_t z = (state += 0x9E3779B97F4A7C15ull);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  return z ^ (z >> 31);
}
// A uniform double in [0, 1) from the top 53 bits.
inline double uniform01(std::uint64_t& state) { return static_cast<double>(splitMix64(state) >> 11) * 0x1.0p-53; }

// Duff et al.'s orthonormal basis around unit n (scene/orthonormal_basis.h), in double.
struct BasisD {
  glm::dvec3 b1, b2;
};
inline BasisD duffBasis(const glm::dvec3& n) {
  const double s = std::copysign(1.0, n.z);
  const double a = -1.0 / (s + n.z);
  const double b = n.x * n.y * a;
  return {glm::dvec3(1.0 + s * n.x * n.x * a, s * b, -s * n.x), glm::dvec3(b, s + n.y * n.y * a, -n.y)};
}

// A mean and its standard error (the samples' standard deviation over sqrt(samples)).
struct MonteCarloEstimate {
  glm::dvec3 mean{0.0}, standardError{0.0};
};

// The mean of radiance(w) over `samples` directions w drawn from the normalised lobe
// max(axis.w, 0)^exponent: cos(theta) = (1 - u1)^(1 / (exponent + 1)), phi = 2 pi u2 around
// unit `axis`. Exponent 1 is the cosine-weighted hemisphere (irradiance), a Phong exponent the
// glossy lobe. Since the lobe is the samples' density, the mean is the lobe-weighted average.
template <typename Radiance>
MonteCarloEstimate lobeMonteCarlo(const glm::dvec3& axisIn, double exponent, std::size_t samples, std::uint64_t seed,
                                  const Radiance& radiance) {
  MonteCarloEstimate result;
  if (samples == 0) return result;
  const glm::dvec3 axis = glm::normalize(axisIn);
  const BasisD basis = duffBasis(axis);
  const double power = 1.0 / (exponent + 1.0);
  std::uint64_t state = seed;
  glm::dvec3 sum(0.0), sumSquares(0.0);
  for (std::size_t k = 0; k < samples; ++k) {
    const double u1 = uniform01(state), u2 = uniform01(state);
    const double z = std::pow(1.0 - u1, power);
    const double radius = std::sqrt(std::max(0.0, 1.0 - z * z)), phi = 2.0 * std::numbers::pi * u2;
    const glm::dvec3 w = basis.b1 * (radius * std::cos(phi)) + basis.b2 * (radius * std::sin(phi)) + axis * z;
    const glm::dvec3 c = radiance(w);
    sum += c;
    sumSquares += c * c;
  }
  const double count = static_cast<double>(samples);
  result.mean = sum / count;
  const glm::dvec3 variance = glm::max(sumSquares / count - result.mean * result.mean, glm::dvec3(0.0));
  result.standardError = glm::sqrt(variance / count);
  return result;
}

}  // namespace twr
