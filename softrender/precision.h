// The scalar type of the pipeline stages. Every stage is a template on T: float for the
// normal pipeline (the one that matches GL on llvmpipe), double for the reference
// (docs/reference.md). The float instantiation is the code a reader follows; double only
// changes the precision of the same operations, in the same order.
#pragma once

#include "scene/conventions.h"

#include <cmath>

namespace twr {

template <typename T>
using Vec2T = glm::vec<2, T>;
template <typename T>
using Vec3T = glm::vec<3, T>;
template <typename T>
using Vec4T = glm::vec<4, T>;
template <typename T>
using Mat3T = glm::mat<3, 3, T>;
template <typename T>
using Mat4T = glm::mat<4, 4, T>;

// safeNormalize (scene/conventions.h) for the double pipeline: the same threshold and the
// same operations, so a vector usable in float is usable in double.
inline glm::dvec3 safeNormalize(glm::dvec3 v, glm::dvec3 fallback = glm::dvec3(0.0, 0.0, 1.0)) {
  const double lengthSquared = glm::dot(v, v);
  if (!(lengthSquared > static_cast<double>(kMinLengthSquared)) || !std::isfinite(lengthSquared)) return fallback;
  return v / std::sqrt(lengthSquared);
}

}  // namespace twr
