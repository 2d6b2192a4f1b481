// The parameterization error (scene/environment_error.h): nothing to lose on a flat cube, less
// with every doubling of the map on a smooth one, and the sphere map's worst loss at its rim
// (-Z), where a texel spans the most directions.
#include "scene/environment_error.h"
#include "tests/scene/support_cubes.h"

#include <gtest/gtest.h>

#include <cmath>

namespace twr {
namespace {

constexpr EnvironmentParameterization kBuilt[] = {EnvironmentParameterization::Sphere,
                                                  EnvironmentParameterization::DualParaboloid};

TEST(ParameterizationError, AFlatCubeLosesNothing) {
  const CubeMap flat = cubeOf(8, [](const glm::dvec3&, int, int) { return glm::dvec3(0.25, 0.5, 0.75); });
  for (EnvironmentParameterization kind : kBuilt) {
    const ParameterizationError e = measureParameterizationError(flat, parameterizedMapFromCube(flat, kind, 16), 4000);
    EXPECT_EQ(e.directions, 4000u);
    EXPECT_LT(e.maxError, 1e-4) << toString(kind);
  }
}

TEST(ParameterizationError, ShrinksAsTheMapGrowsOnASmoothCube) {
  const CubeMap smooth = cubeOf(64, [](const glm::dvec3& r, int, int) {
    return glm::dvec3(0.5 + 0.5 * std::sin(3.0 * r.x), 0.5 + 0.5 * std::cos(2.0 * r.y), 0.5 + 0.4 * r.z * r.x);
  });
  for (EnvironmentParameterization kind : kBuilt) {
    const ParameterizationError small = measureParameterizationError(smooth, parameterizedMapFromCube(smooth, kind, 32), 20000);
    const ParameterizationError large = measureParameterizationError(smooth, parameterizedMapFromCube(smooth, kind, 256), 20000);
    EXPECT_GT(small.rmse, 0.0) << toString(kind);
    EXPECT_LT(large.rmse, small.rmse) << toString(kind);
    EXPECT_LE(large.p99, large.maxError) << toString(kind);
    EXPECT_LE(large.rmse, large.maxError) << toString(kind);
  }
}

// A checkerboard of 4-texel squares: fine detail everywhere. The sphere map's worst direction
// is within the rim's cap around -Z; the paraboloid's error is far lower at the same size, and
// in the error picture (-Z at its centre) the sphere map's centre is worse than its +Z edge.
TEST(ParameterizationError, TheSphereMapLosesMostAtItsRim) {
  const CubeMap checker = cubeOf(64, [](const glm::dvec3&, int x, int y) {
    const double c = ((x / 4 + y / 4) % 2) ? 1.0 : 0.0;
    return glm::dvec3(c);
  });
  const ParameterizedMap sphere = parameterizedMapFromCube(checker, EnvironmentParameterization::Sphere, 256);
  const ParameterizedMap paraboloid = parameterizedMapFromCube(checker, EnvironmentParameterization::DualParaboloid, 256);
  const ParameterizationError s = measureParameterizationError(checker, sphere, 20000);
  const ParameterizationError p = measureParameterizationError(checker, paraboloid, 20000);
  EXPECT_LT(s.worstDirection.z, -0.5);
  EXPECT_LT(p.rmse, s.rmse);
  const int width = 64, height = 32;
  const std::vector<double> image = parameterizationErrorImage(checker, sphere, width, height);
  ASSERT_EQ(image.size(), static_cast<std::size_t>(width * height));
  // Mean error of the columns around -Z (the centre) against those around +Z (the edges).
  double centre = 0.0, edge = 0.0;
  for (int y = 4; y < height - 4; ++y) {
    for (int dx = 0; dx < 4; ++dx) {
      centre += image[static_cast<std::size_t>(y * width + width / 2 - 2 + dx)];
      edge += image[static_cast<std::size_t>(y * width + dx)] + image[static_cast<std::size_t>(y * width + width - 1 - dx)];
    }
  }
  EXPECT_GT(centre, edge / 2.0);
}

}  // namespace
}  // namespace twr

namespace twr {
namespace {

// The diffuse light's measurement: nothing on a constant sky (the reference has no noise
// there), and on a sky lit on its upper half, whose D = (1 + n.y) / 2 lies in bands 0 and 1,
// SH9 and the cube agree within a level while both stay within the reference's noise.
TEST(DiffuseLightError, ConstantAndHalfLitSkies) {
  const CubeMap flat = cubeOf(16, [](const glm::dvec3&, int, int) { return glm::dvec3(0.5, 0.25, 1.0); });
  const DiffuseLightError none =
      measureDiffuseLightError(flat, irradianceCubeFromCube(flat, 8), sh9IrradianceFromCube(flat), 100, 64, 3);
  EXPECT_EQ(none.normals, 100u);
  EXPECT_EQ(none.samples, 64u);
  EXPECT_LT(none.referenceNoise, 1e-6);
  EXPECT_LT(none.mapVsReference.maxError, 1e-3);
  EXPECT_LT(none.sh9VsReference.maxError, 1e-3);
  EXPECT_LT(none.sh9VsMap.maxError, 1e-3);

  const CubeMap half = cubeOf(32, [](const glm::dvec3& r, int, int) { return glm::dvec3(r.y > 0.0 ? 1.0 : 0.0); });
  const DiffuseLightError e =
      measureDiffuseLightError(half, irradianceCubeFromCube(half), sh9IrradianceFromCube(half), 400, 1024, 11);
  // A 0/1 radiance: standard error at most 0.5 / 32 = 4 levels.
  EXPECT_GT(e.referenceNoise, 1.0);
  EXPECT_LT(e.referenceNoise, 4.0);
  EXPECT_LT(e.sh9VsMap.maxError, 1.0);
  EXPECT_LT(e.mapVsReference.rmse, 1.5 * e.referenceNoise);
  EXPECT_LT(e.sh9VsReference.rmse, 1.5 * e.referenceNoise);
  EXPECT_LE(e.mapVsReference.p99, e.mapVsReference.maxError);
}

TEST(DiffuseLightError, PicturesFollowTheEquirectConvention) {
  const CubeMap half = cubeOf(16, [](const glm::dvec3& r, int, int) { return glm::dvec3(r.y > 0.0 ? 1.0 : 0.0); });
  const std::vector<glm::dvec3> map = irradianceCubeImage(irradianceCubeFromCube(half, 16), 32, 16);
  const std::vector<glm::dvec3> sh = sh9Image(sh9IrradianceFromCube(half), 32, 16);
  ASSERT_EQ(map.size(), 32u * 16u);
  ASSERT_EQ(sh.size(), map.size());
  // The top row looks up (+Y, D near 1), the bottom row down (D near 0).
  EXPECT_GT(map[16].r, 0.95);
  EXPECT_LT(map[15 * 32 + 16].r, 0.05);
  EXPECT_GT(sh[16].r, 0.95);
  EXPECT_LT(sh[15 * 32 + 16].r, 0.05);
}

}  // namespace
}  // namespace twr
