// The environment's diffuse light (scene/environment_light.h) against what is known exactly:
// texel solid angles that tile the sphere, a constant sky that every form returns unchanged,
// and a sky lit on its upper half, whose D(n) = (1 + n.y) / 2 lies in bands 0 and 1, so the
// irradiance cube and SH9 must both find it; Monte Carlo within its statistics of the same.
#include "scene/environment_light.h"
#include "scene/image.h"
#include "scene/scene.h"
#include "tests/scene/support_cubes.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace twr {
namespace {

// The irradiance cube in direction n (level 0, bilinear), as both renderers read it.
glm::dvec3 irradianceAt(const CubeMap& irradiance, const glm::dvec3& n) { return cubeBilinear(irradiance, n); }

// An upper half lit with 1, the lower dark; the cube's equator runs between texel rows.
CubeMap upperHalfSky(int size) {
  return cubeOf(size, [](const glm::dvec3& r, int, int) { return glm::dvec3(r.y > 0.0 ? 1.0 : 0.0); });
}

TEST(EnvironmentLight, TexelSolidAnglesTileTheSphere) {
  for (int size : {1, 2, 7, 32}) {
    double sum = 0.0;
    for (int y = 0; y < size; ++y) {
      for (int x = 0; x < size; ++x) sum += cubeTexelSolidAngle(x, y, size);
    }
    EXPECT_NEAR(kCubeFaces * sum, 4.0 * kPi, 1e-12) << size;
  }
  // A corner texel subtends less than a centre one (the face is flat, the sphere is not).
  EXPECT_LT(cubeTexelSolidAngle(0, 0, 8), cubeTexelSolidAngle(3, 3, 8));
}

TEST(EnvironmentLight, AConstantSkyGivesItsOwnRadianceEverywhere) {
  const glm::dvec3 colour(0.25, 0.5, 2.0);
  const CubeMap sky = cubeOf(16, [&](const glm::dvec3&, int, int) { return colour; });
  const CubeMap irradiance = irradianceCubeFromCube(sky, 8);
  const Sh9Irradiance sh = sh9IrradianceFromCube(sky);
  for (std::size_t i = 0; i < 64; ++i) {
    const glm::dvec3 n = fibonacciSphereDirection(i, 64);
    EXPECT_NEAR(glm::length(irradianceAt(irradiance, n) - colour), 0.0, 1e-5) << i;
    EXPECT_NEAR(glm::length(irradianceFromSh9(sh, n) - colour), 0.0, 1e-6) << i;
    EXPECT_NEAR(glm::length(irradianceMonteCarlo(sky, n, 16, 7) - colour), 0.0, 1e-6) << i;
  }
  // Bands 1 and 2 of a constant are zero.
  for (std::size_t i = 1; i < 9; ++i) EXPECT_NEAR(glm::length(sh.c[i]), 0.0, 1e-9) << i;
}

TEST(EnvironmentLight, AnUpperHalfSkyGivesOnePlusNyOverTwo) {
  const CubeMap sky = upperHalfSky(32);
  const CubeMap irradiance = irradianceCubeFromCube(sky);
  const Sh9Irradiance sh = sh9IrradianceFromCube(sky);
  for (std::size_t i = 0; i < 200; ++i) {
    const glm::dvec3 n = fibonacciSphereDirection(i, 200);
    const double exact = (1.0 + n.y) / 2.0;
    // The sums over 2.8-degree texels, then bilinear between 32 texels a face: within 1/255.
    EXPECT_NEAR(irradianceAt(irradiance, n).r, exact, 1.0 / 255.0) << n.x << " " << n.y << " " << n.z;
    EXPECT_NEAR(irradianceFromSh9(sh, n).r, exact, 2e-3) << n.x << " " << n.y << " " << n.z;
  }
  // Monte Carlo: 4096 samples of a 0/1 radiance, standard deviation at most 0.5 / 64.
  for (const glm::dvec3& n : {glm::dvec3(0, 1, 0), glm::dvec3(0, -1, 0), glm::dvec3(1, 0, 0), glm::dvec3(0.6, 0.0, -0.8)}) {
    EXPECT_NEAR(irradianceMonteCarlo(sky, n, 4096, 1).r, (1.0 + n.y) / 2.0, 4.0 * 0.5 / 64.0) << n.x << " " << n.z;
  }
}

TEST(EnvironmentLight, MonteCarloIsDeterministicAndConvergesOnTheIrradianceCube) {
  // A sky with a bright spot: the part SH9's three bands cannot hold.
  const glm::dvec3 sun = glm::normalize(glm::dvec3(0.3, 0.8, -0.5));
  const CubeMap sky = cubeOf(32, [&](const glm::dvec3& r, int, int) {
    return glm::dvec3(0.2, 0.3, 0.5) + glm::dvec3(std::pow(std::max(glm::dot(r, sun), 0.0), 64.0) * 20.0);
  });
  const CubeMap irradiance = irradianceCubeFromCube(sky);
  const Sh9Irradiance sh = sh9IrradianceFromCube(sky);
  const glm::dvec3 n = glm::normalize(glm::dvec3(0.2, 0.9, -0.1));
  EXPECT_EQ(irradianceMonteCarlo(sky, n, 256, 42), irradianceMonteCarlo(sky, n, 256, 42));
  EXPECT_NE(irradianceMonteCarlo(sky, n, 256, 42), irradianceMonteCarlo(sky, n, 256, 43));
  const glm::dvec3 reference = irradianceMonteCarlo(sky, n, 200000, 1);
  EXPECT_NEAR(irradianceAt(irradiance, n).r, reference.r, 0.02 * reference.r);
  // SH9 is close where the sun shines.
  EXPECT_NEAR(irradianceFromSh9(sh, n).r, reference.r, 0.1 * reference.r);
}

TEST(EnvironmentLight, FibonacciDirectionsAreUnitAndBalanced) {
  glm::dvec3 sum(0.0);
  for (std::size_t i = 0; i < 1000; ++i) {
    const glm::dvec3 r = fibonacciSphereDirection(i, 1000);
    EXPECT_NEAR(glm::length(r), 1.0, 1e-12);
    sum += r;
  }
  EXPECT_LT(glm::length(sum / 1000.0), 1e-2);
}

TEST(EnvironmentLight, PrefilterBuildsWhatMaterialsAskForAndFollowsTheParameterization) {
  Scene scene;
  Environment environment;
  environment.cube = std::make_shared<CubeMap>(upperHalfSky(8));
  scene.environment = environment;
  scene.materials.resize(2);
  prefilterEnvironmentLight(scene);
  EXPECT_FALSE(scene.environment->irradiance);
  EXPECT_FALSE(scene.environment->sh9);
  EXPECT_EQ(environmentDiffuseOf(scene.materials[0], *scene.environment), EnvironmentDiffuse::None);
  scene.materials[1].environmentDiffuse = EnvironmentDiffuse::IrradianceMap;
  EXPECT_TRUE(materialReadsEnvironment(scene.materials[1], scene));
  EXPECT_FALSE(materialReadsEnvironmentDirections(scene.materials[1]));
  // Asked for but not built yet: read as none by both renderers.
  EXPECT_EQ(environmentDiffuseOf(scene.materials[1], *scene.environment), EnvironmentDiffuse::None);
  prefilterEnvironmentLight(scene);
  ASSERT_TRUE(scene.environment->irradiance);
  EXPECT_FALSE(scene.environment->irradianceLayers);
  EXPECT_EQ(environmentDiffuseOf(scene.materials[1], *scene.environment), EnvironmentDiffuse::IrradianceMap);
  scene.environment->parameterization = EnvironmentParameterization::DualParaboloid;
  prefilterEnvironmentLight(scene);
  ASSERT_TRUE(scene.environment->irradianceLayers);
  EXPECT_EQ(scene.environment->irradianceLayers->kind, EnvironmentParameterization::DualParaboloid);
  EXPECT_EQ(scene.environment->irradianceLayers->layers, 2);
  scene.environment->parameterization = EnvironmentParameterization::Cube;
  prefilterEnvironmentLight(scene);
  EXPECT_FALSE(scene.environment->irradianceLayers);
  EXPECT_FALSE(scene.environment->sh9);
}

}  // namespace
}  // namespace twr
