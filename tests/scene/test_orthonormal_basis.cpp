// Orthonormal bases from a normal: exact frames on the axes, the error measure itself, and
// the maximum orthonormality error of each construction over many directions, including
// those within 1e-3 rad of -Z where Frisvad's formula cancels catastrophically in float.
#include "scene/orthonormal_basis.h"

#include <gtest/gtest.h>

#include <cmath>

namespace twr {
namespace {

// Float rounding of a few operations on unit-sized values: a handful of ulps (2^-24 = 6e-8
// each) per component. An accurate construction stays far below this bound.
constexpr double kAccurateBound = 1e-6;
// "Visibly fails": an error a thousand times the accurate bound, large enough to tilt a
// shading frame by more than half a degree (1e-2 rad).
constexpr double kVisibleFailure = 1e-2;

void expectVec(vec3 actual, vec3 expected) {
  EXPECT_EQ(actual.x, expected.x);
  EXPECT_EQ(actual.y, expected.y);
  EXPECT_EQ(actual.z, expected.z);
}

TEST(OrthonormalBasis, ExactFramesOnTheZAxis) {
  // Duff at +Z: s = 1, a = -1/2, b = 0 -> b1 = (1, 0, 0), b2 = (0, 1, 0).
  const OrthonormalBasis plusZ = basisFromNormal(vec3(0, 0, 1), BasisMethod::Duff2017);
  expectVec(plusZ.b1, vec3(1, 0, 0));
  expectVec(plusZ.b2, vec3(0, 1, 0));
  // Duff at -Z: s = -1, a = 1/2, b = 0 -> b1 = (1, 0, 0), b2 = (0, -1, 0); b1 x b2 = -Z.
  const OrthonormalBasis minusZ = basisFromNormal(vec3(0, 0, -1), BasisMethod::Duff2017);
  expectVec(minusZ.b1, vec3(1, 0, 0));
  expectVec(minusZ.b2, vec3(0, -1, 0));
  // Frisvad at +Z: a = 1/2 -> the same frame as Duff; at -Z exactly, his fixed frame.
  const OrthonormalBasis frisvadPlus = basisFromNormal(vec3(0, 0, 1), BasisMethod::Frisvad2012);
  expectVec(frisvadPlus.b1, vec3(1, 0, 0));
  expectVec(frisvadPlus.b2, vec3(0, 1, 0));
  const OrthonormalBasis frisvadMinus = basisFromNormal(vec3(0, 0, -1), BasisMethod::Frisvad2012);
  expectVec(frisvadMinus.b1, vec3(0, -1, 0));
  expectVec(frisvadMinus.b2, vec3(-1, 0, 0));
  for (BasisMethod method : kAllBasisMethods) {
    EXPECT_EQ(orthonormalityError(vec3(0, 0, 1), basisFromNormal(vec3(0, 0, 1), method)), 0.0) << toString(method);
    EXPECT_EQ(orthonormalityError(vec3(0, 0, -1), basisFromNormal(vec3(0, 0, -1), method)), 0.0) << toString(method);
  }
}

TEST(OrthonormalBasis, ErrorMeasureSeesEachDefect) {
  const vec3 n(0, 0, 1);
  EXPECT_EQ(orthonormalityError(n, {vec3(1, 0, 0), vec3(0, 1, 0)}), 0.0);
  EXPECT_DOUBLE_EQ(orthonormalityError(n, {vec3(2, 0, 0), vec3(0, 1, 0)}), 3.0);   // |b1|^2 - 1 = 3
  EXPECT_DOUBLE_EQ(orthonormalityError(n, {vec3(0, 1, 0), vec3(1, 0, 0)}), 2.0);   // left-handed: b1 x b2 = -n
  EXPECT_NEAR(orthonormalityError(n, {vec3(0.6f, 0, 0.8f), vec3(0, 1, 0)}), 0.8, 1e-7);  // b1.n = 0.8
  EXPECT_TRUE(std::isinf(orthonormalityError(n, {vec3(NAN, 0, 0), vec3(0, 1, 0)})));
}

TEST(OrthonormalBasis, NaiveFixedHelperFailsOnItsHelperAxis) {
  const OrthonormalBasis up = basisFromNormal(vec3(0, 1, 0), BasisMethod::NaiveFixedHelper);
  EXPECT_TRUE(std::isinf(orthonormalityError(vec3(0, 1, 0), up)));  // cross(Y, Y) = 0: normalize gives NaN
  const OrthonormalBasis best = basisFromNormal(vec3(0, 1, 0), BasisMethod::NaiveBestHelper);
  EXPECT_LE(orthonormalityError(vec3(0, 1, 0), best), kAccurateBound);
}

TEST(OrthonormalBasis, MaximumErrorOverManyDirections) {
  const std::vector<vec3> directions = basisTestDirections(100000, 2000);
  ASSERT_EQ(directions.size(), 100000u + 6u + 4u * 2000u);
  for (const vec3& n : directions) ASSERT_NEAR(glm::length(glm::dvec3(n)), 1.0, 1e-6);

  const BasisErrorStats duff = measureBasisError(BasisMethod::Duff2017, directions);
  EXPECT_EQ(duff.nonFinite, 0u);
  EXPECT_LE(duff.maxError, kAccurateBound);
  EXPECT_LE(duff.maxErrorNearMinusZ, kAccurateBound);

  const BasisErrorStats best = measureBasisError(BasisMethod::NaiveBestHelper, directions);
  EXPECT_EQ(best.nonFinite, 0u);
  EXPECT_LE(best.maxError, kAccurateBound);

  // Frisvad is as good as Duff in the upper hemisphere (1 + n.z >= 1) and visibly wrong within
  // 1e-3 rad of -Z, where 1 + n.z (about theta^2 / 2 <= 5e-7) is known to ~10 % at best in float.
  const BasisErrorStats frisvad = measureBasisError(BasisMethod::Frisvad2012, directions);
  EXPECT_EQ(frisvad.nonFinite, 0u);
  EXPECT_LE(frisvad.maxErrorAwayFromMinusZ, kAccurateBound);
  EXPECT_GE(frisvad.maxErrorNearMinusZ, kVisibleFailure);
  EXPECT_LT(frisvad.worstNormal.z, -0.999f);

  // The fixed helper: NaN exactly at +Y and -Y (two directions in the set), fine near -Z.
  const BasisErrorStats fixed = measureBasisError(BasisMethod::NaiveFixedHelper, directions);
  EXPECT_EQ(fixed.nonFinite, 2u);
  EXPECT_TRUE(std::isinf(fixed.maxError));
  EXPECT_LE(fixed.maxErrorNearMinusZ, kAccurateBound);
}

}  // namespace
}  // namespace twr
