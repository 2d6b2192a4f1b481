// Orthonormal bases built from a unit normal n alone: two unit vectors b1, b2 with
// b1 x b2 = n (right-handed), the frame a renderer needs when a surface has a normal but no
// tangent. Four constructions, compared by `twinraster report` and tests/scene:
//
//   NaiveFixedHelper  b1 = normalize(cross(h, n)) with the fixed helper h = +Y,
//                     b2 = cross(n, b1). Breaks where n is parallel to h: NaN at n = +-Y
//                     and a large error close to it.
//   NaiveBestHelper   the same with h = +X when |n.x| < |n.y|, else +Y (the usual fix: h is
//                     never within 45 degrees of n). Robust, but a branch, a square root and a
//                     division.
//   Frisvad2012       a = 1 / (1 + n.z), b = -n.x n.y a,
//                     b1 = (1 - n.x^2 a, b, -n.x), b2 = (b, 1 - n.y^2 a, -n.y),
//                     and the fixed frame b1 = (0, -1, 0), b2 = (-1, 0, 0) when n.z < -0.9999999.
//                     1 + n.z cancels near n = -Z: the error grows like 2^-24 / (1 + n.z), so
//                     in float the basis is visibly not orthonormal within about 1e-3 rad of -Z.
//   Duff2017          s = copysign(1, n.z), a = -1 / (s + n.z), b = n.x n.y a,
//                     b1 = (1 + s n.x^2 a, s b, -s n.x), b2 = (b, s + n.y^2 a, -n.y)
//                     (Duff et al., "Building an Orthonormal Basis, Revisited", JCGT 2017):
//                     Frisvad's formula mirrored into the hemisphere of n.z, so s + n.z never
//                     cancels; branch-free and accurate everywhere.
// All four work in float, as a shader would.
#pragma once

#include "scene/conventions.h"

#include <cstddef>
#include <string_view>
#include <vector>

namespace twr {

enum class BasisMethod { NaiveFixedHelper, NaiveBestHelper, Frisvad2012, Duff2017 };
inline constexpr BasisMethod kAllBasisMethods[] = {BasisMethod::NaiveFixedHelper, BasisMethod::NaiveBestHelper,
                                                   BasisMethod::Frisvad2012, BasisMethod::Duff2017};

// "naive_fixed_helper", "naive_best_helper", "frisvad_2012", "duff_2017".
std::string_view toString(BasisMethod method);

struct OrthonormalBasis {
  vec3 b1{1.0f, 0.0f, 0.0f};
  vec3 b2{0.0f, 1.0f, 0.0f};
};

// n must be unit length (the error measure below says how far from orthonormal the result is).
OrthonormalBasis basisFromNormal(vec3 n, BasisMethod method);

// Largest of | |b1|^2 - 1 |, | |b2|^2 - 1 |, |b1.n|, |b2.n|, |b1.b2| and the largest
// component of |b1 x b2 - n| (handedness), evaluated in double from the float vectors; +Inf
// when any component is NaN or Inf. Unitless; 0 for a perfect right-handed basis.
double orthonormalityError(vec3 n, const OrthonormalBasis& basis);

// Angle (radians) within which a direction counts as "near" an axis in the measurements.
inline constexpr double kNearAxisRadians = 1e-3;

// Unit directions for the measurement: `sphereCount` Fibonacci-sphere points spread over all
// directions, the six axes exactly, and `nearAxisCount` directions within kNearAxisRadians of
// each of -Z, +Z, +Y and -Y (angles from 1e-8 to 1e-3 radians on a log scale, azimuths
// spread around). Deterministic.
std::vector<vec3> basisTestDirections(std::size_t sphereCount, std::size_t nearAxisCount);

struct BasisErrorStats {
  double maxError = 0.0;            // over all directions (+Inf if any basis is not finite)
  vec3 worstNormal{0.0f};           // a direction reaching maxError
  double maxErrorNearMinusZ = 0.0;  // over directions within kNearAxisRadians of -Z (inclusive)
  double maxErrorAwayFromMinusZ = 0.0;  // over directions more than 90 degrees from -Z (n.z > 0)
  std::size_t nonFinite = 0;        // bases with a NaN or Inf component
  std::size_t directions = 0;
};

BasisErrorStats measureBasisError(BasisMethod method, const std::vector<vec3>& directions);

}  // namespace twr
