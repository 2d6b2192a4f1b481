// The parameterization error (scene/environment_error.h): nothing to lose on a flat cube, less
// with every doubling of the map on a smooth one, and the sphere map's worst loss at its rim
// (-Z), where a texel spans the most directions.
#include "scene/environment_error.h"

#include <gtest/gtest.h>

#include <cmath>

namespace twr {
namespace {

// A cube of side `size` whose texel at direction r holds colour(r).
template <typename Colour>
CubeMap cubeOf(int size, Colour colour) {
  std::array<FaceImage, kCubeFaces> faces;
  for (int f = 0; f < kCubeFaces; ++f) {
    FaceImage& face = faces[static_cast<std::size_t>(f)];
    face.width = face.height = size;
    for (int y = 0; y < size; ++y) {
      for (int x = 0; x < size; ++x) {
        const glm::dvec3 c = colour(glm::normalize(directionFromCubeCoord(f, (x + 0.5) / size, (y + 0.5) / size)), x, y);
        face.rgb.insert(face.rgb.end(), {static_cast<float>(c.x), static_cast<float>(c.y), static_cast<float>(c.z)});
      }
    }
  }
  std::vector<std::string> warnings;
  return cubeMapFromFaces(faces, {"a", "b", "c", "d", "e", "f"}, warnings);
}

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
