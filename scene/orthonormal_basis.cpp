#include "scene/orthonormal_basis.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace twr {

namespace {

// Frisvad's switch to a fixed frame: below this n.z the formula is not used (his constant).
constexpr float kFrisvadMinusZThreshold = -0.9999999f;
// Golden angle, radians: successive Fibonacci-sphere points turn by it.
const double kGoldenAngle = kPi * (3.0 - std::sqrt(5.0));
// Smallest angle from an axis the near-axis directions use, radians.
constexpr double kNearAxisMinRadians = 1e-8;
// "Away from -Z" in the statistics: more than this from -Z, radians (exclusive): the upper
// hemisphere n.z > 0, where 1 + n.z > 1 cannot cancel.
constexpr double kAwayFromMinusZRadians = kPi / 2.0;

OrthonormalBasis naiveFromHelper(vec3 n, vec3 helper) {
  OrthonormalBasis basis;
  basis.b1 = glm::normalize(glm::cross(helper, n));  // NaN when helper is parallel to n: on purpose
  basis.b2 = glm::cross(n, basis.b1);
  return basis;
}

// Direction at `angle` from `axis` (a unit axis vector), turned by `azimuth` around it.
glm::dvec3 nearAxis(glm::dvec3 axis, double angle, double azimuth) {
  const glm::dvec3 u = std::fabs(axis.x) < 0.5 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
  const glm::dvec3 e1 = glm::normalize(glm::cross(u, axis));
  const glm::dvec3 e2 = glm::cross(axis, e1);
  return std::cos(angle) * axis + std::sin(angle) * (std::cos(azimuth) * e1 + std::sin(azimuth) * e2);
}

double angleBetween(vec3 a, glm::dvec3 b) {
  const glm::dvec3 ad = glm::normalize(glm::dvec3(a));
  return std::atan2(glm::length(glm::cross(ad, b)), glm::dot(ad, b));
}

}  // namespace

std::string_view toString(BasisMethod method) {
  switch (method) {
    case BasisMethod::NaiveFixedHelper: return "naive_fixed_helper";
    case BasisMethod::NaiveBestHelper: return "naive_best_helper";
    case BasisMethod::Frisvad2012: return "frisvad_2012";
    case BasisMethod::Duff2017: return "duff_2017";
  }
  return "?";
}

OrthonormalBasis basisFromNormal(vec3 n, BasisMethod method) {
  switch (method) {
    case BasisMethod::NaiveFixedHelper: return naiveFromHelper(n, vec3(0.0f, 1.0f, 0.0f));
    case BasisMethod::NaiveBestHelper:
      return naiveFromHelper(n, std::fabs(n.x) < std::fabs(n.y) ? vec3(1.0f, 0.0f, 0.0f) : vec3(0.0f, 1.0f, 0.0f));
    case BasisMethod::Frisvad2012: {
      if (n.z < kFrisvadMinusZThreshold) return {vec3(0.0f, -1.0f, 0.0f), vec3(-1.0f, 0.0f, 0.0f)};
      const float a = 1.0f / (1.0f + n.z);
      const float b = -n.x * n.y * a;
      return {vec3(1.0f - n.x * n.x * a, b, -n.x), vec3(b, 1.0f - n.y * n.y * a, -n.y)};
    }
    case BasisMethod::Duff2017: {
      const float s = std::copysign(1.0f, n.z);
      const float a = -1.0f / (s + n.z);
      const float b = n.x * n.y * a;
      return {vec3(1.0f + s * n.x * n.x * a, s * b, -s * n.x), vec3(b, s + n.y * n.y * a, -n.y)};
    }
  }
  return {};
}

double orthonormalityError(vec3 n, const OrthonormalBasis& basis) {
  const glm::dvec3 nd(n), b1(basis.b1), b2(basis.b2);
  for (int i = 0; i < 3; ++i) {
    if (!std::isfinite(b1[i]) || !std::isfinite(b2[i])) return std::numeric_limits<double>::infinity();
  }
  const glm::dvec3 handedness = glm::abs(glm::cross(b1, b2) - nd);
  return std::max({std::fabs(glm::dot(b1, b1) - 1.0), std::fabs(glm::dot(b2, b2) - 1.0), std::fabs(glm::dot(b1, nd)),
                   std::fabs(glm::dot(b2, nd)), std::fabs(glm::dot(b1, b2)), handedness.x, handedness.y,
                   handedness.z});
}

std::vector<vec3> basisTestDirections(std::size_t sphereCount, std::size_t nearAxisCount) {
  std::vector<vec3> out;
  // Fibonacci sphere: z evenly spaced in (-1, 1) (exclusive), longitude turning by the golden angle.
  for (std::size_t i = 0; i < sphereCount; ++i) {
    const double z = 1.0 - (2.0 * static_cast<double>(i) + 1.0) / static_cast<double>(sphereCount);
    const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
    const double phi = kGoldenAngle * static_cast<double>(i);
    out.push_back(vec3(glm::dvec3(r * std::cos(phi), r * std::sin(phi), z)));
  }
  for (const vec3 axis : {vec3(1, 0, 0), vec3(-1, 0, 0), vec3(0, 1, 0), vec3(0, -1, 0), vec3(0, 0, 1), vec3(0, 0, -1)}) {
    out.push_back(axis);
  }
  const glm::dvec3 nearAxes[] = {{0, 0, -1}, {0, 0, 1}, {0, 1, 0}, {0, -1, 0}};
  for (const glm::dvec3& axis : nearAxes) {
    for (std::size_t i = 0; i < nearAxisCount; ++i) {
      // Log-spaced angles from kNearAxisMinRadians to kNearAxisRadians (inclusive).
      const double t = nearAxisCount > 1 ? static_cast<double>(i) / static_cast<double>(nearAxisCount - 1) : 1.0;
      const double angle = kNearAxisMinRadians * std::pow(kNearAxisRadians / kNearAxisMinRadians, t);
      const double azimuth = kGoldenAngle * static_cast<double>(i);
      // Rounded to float and renormalised in float, as a shader's normalize() would hand it over.
      out.push_back(glm::normalize(vec3(nearAxis(axis, angle, azimuth))));
    }
  }
  return out;
}

BasisErrorStats measureBasisError(BasisMethod method, const std::vector<vec3>& directions) {
  BasisErrorStats stats;
  stats.directions = directions.size();
  const glm::dvec3 minusZ(0, 0, -1);
  for (const vec3& n : directions) {
    const OrthonormalBasis basis = basisFromNormal(n, method);
    const double error = orthonormalityError(n, basis);
    if (!std::isfinite(error)) ++stats.nonFinite;
    if (error > stats.maxError) {
      stats.maxError = error;
      stats.worstNormal = n;
    }
    const double angle = angleBetween(n, minusZ);
    if (angle <= kNearAxisRadians) stats.maxErrorNearMinusZ = std::max(stats.maxErrorNearMinusZ, error);
    if (angle > kAwayFromMinusZRadians) stats.maxErrorAwayFromMinusZ = std::max(stats.maxErrorAwayFromMinusZ, error);
  }
  return stats;
}

}  // namespace twr
