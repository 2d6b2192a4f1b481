// The prefiltered glossy cube (scene/environment_specular.h) against what is known exactly:
// a constant sky comes back unchanged at every level; a sky linear in the direction,
// L(w) = a + b.w, has the lobe average a + (b.r) (e + 1) / (e + 2) (the mean cosine of the
// normalised lobe cos^e); the tiles the sum skips hold nothing the lobe weighs; the LOD lands
// on level l where the shininess is e_l; Monte Carlo agrees within its statistics.
#include "scene/environment_light.h"
#include "scene/environment_specular.h"
#include "tests/scene/support_cubes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <tuple>

namespace twr {
namespace {

// A sky linear in the direction: a + b.w per channel.
const glm::dvec3 kA(0.5, 0.4, 0.3);
const glm::dvec3 kB(0.3, -0.2, 0.1);
glm::dvec3 linearSky(const glm::dvec3& w) { return kA + glm::dvec3(glm::dot(kB, w)); }

TEST(EnvironmentSpecular, LevelsFollowTheTexelSpread) {
  EXPECT_EQ(specularExponentOfSide(128), 4096.0);
  EXPECT_EQ(specularExponentOfSide(64), 1024.0);
  EXPECT_EQ(specularExponentOfSide(2), 1.0);
  EXPECT_EQ(specularExponentOfSide(1), 0.25);
  const CubeMap sky = cubeOf(256, [](const glm::dvec3& w, int, int) { return linearSky(w); });
  const CubeMap glossy = specularCubeFromCube(sky);
  ASSERT_EQ(glossy.size(), kSpecularCubeMaxSize);  // a larger source is capped
  ASSERT_EQ(glossy.levelCount(), 7);               // 64 down to 1
  for (int l = 0; l < glossy.levelCount(); ++l) EXPECT_EQ(glossy.levels[static_cast<std::size_t>(l)].size, 64 >> l);
  // A smaller source keeps its side.
  EXPECT_EQ(specularCubeFromCube(cubeOf(16, [](const glm::dvec3&, int, int) { return glm::dvec3(1.0); })).size(), 16);
}

TEST(EnvironmentSpecular, TheLodLandsOnTheLevelWhoseLobeIsTheShininess) {
  const CubeMap glossy = specularCubeFromCube(cubeOf(64, [](const glm::dvec3&, int, int) { return glm::dvec3(1.0); }));
  for (int l = 0; l < glossy.levelCount(); ++l) {
    const double e = specularExponentOfSide(glossy.levels[static_cast<std::size_t>(l)].size);
    EXPECT_DOUBLE_EQ(specularLodFromShininess(glossy, e), l) << e;
  }
  EXPECT_DOUBLE_EQ(specularLodFromShininess(glossy, 512.0), 0.5);           // between the first two lobes
  EXPECT_DOUBLE_EQ(specularLodFromShininess(glossy, 1e6), 0.0);             // sharper than level 0: level 0
  EXPECT_DOUBLE_EQ(specularLodFromShininess(glossy, 0.01), 6.0);            // wider than the last: the last
  EXPECT_DOUBLE_EQ(specularLodFromShininess(glossy, 0.0), 6.0);             // no lobe at all
  EXPECT_DOUBLE_EQ(specularLodFromShininess(glossy, std::nan("")), 6.0);
}

TEST(EnvironmentSpecular, AConstantSkyComesBackAtEveryLevel) {
  const glm::dvec3 colour(0.25, 0.5, 2.0);
  const CubeMap glossy = specularCubeFromCube(cubeOf(32, [&](const glm::dvec3&, int, int) { return colour; }));
  for (const CubeMapLevel& level : glossy.levels) {
    for (std::size_t i = 0; i < level.r.size(); ++i) {
      ASSERT_NEAR(level.r[i], colour.r, 1e-6) << level.size;
      ASSERT_NEAR(level.g[i], colour.g, 1e-6) << level.size;
      ASSERT_NEAR(level.b[i], colour.b, 2e-6) << level.size;
    }
  }
}

TEST(EnvironmentSpecular, ALinearSkyGivesItsLobeAverage) {
  const CubeMap sky = cubeOf(64, [](const glm::dvec3& w, int, int) { return linearSky(w); });
  const CubeMap glossy = specularCubeFromCube(sky);
  for (int l = 0; l < glossy.levelCount(); ++l) {
    const CubeMapLevel& level = glossy.levels[static_cast<std::size_t>(l)];
    const double e = specularExponentOfSide(level.size);
    const double meanCosine = (e + 1.0) / (e + 2.0);
    double worst = 0.0;
    for (int face = 0; face < kCubeFaces; ++face) {
      for (int y = 0; y < level.size; ++y) {
        for (int x = 0; x < level.size; ++x) {
          const glm::dvec3 r = cubeTexelDirection(face, x, y, level.size);
          const glm::dvec3 exact = kA + glm::dvec3(glm::dot(kB, r) * meanCosine);
          worst = std::max(worst, glm::length(glm::dvec3(level.texel(face, x, y)) - exact));
        }
      }
    }
    // The midpoint rule over texels about half a lobe wide, and the cut tail: well within a
    // 1/255 level of an 8-bit image at every level.
    EXPECT_LT(worst, 0.5 / 255.0) << "level " << l << " (e = " << e << ")";
  }
}

TEST(EnvironmentSpecular, TheTilesSkippedHoldNothingTheLobeWeighs) {
  // A noisy sky: every texel its own value, so a texel missed by the tile test shows.
  const CubeMap sky = cubeOf(64, [](const glm::dvec3&, int x, int y) {
    const unsigned h = (static_cast<unsigned>(x) * 73856093u) ^ (static_cast<unsigned>(y) * 19349663u);
    return glm::dvec3((h % 1000u) / 1000.0, ((h / 1000u) % 1000u) / 1000.0, 1.0);
  });
  const CubeMap glossy = specularCubeFromCube(sky);
  for (int l = 0; l < 4; ++l) {
    const CubeMapLevel& level = glossy.levels[static_cast<std::size_t>(l)];
    // The source level the build sums: side max(2 N_l, kSpecularMinSourceSize), at most the top.
    const int sourceSide = std::min(sky.size(), std::max(2 * level.size, kSpecularMinSourceSize));
    const CubeMapLevel& source = *std::find_if(sky.levels.begin(), sky.levels.end(),
                                               [&](const CubeMapLevel& s) { return s.size == sourceSide; });
    const double e = specularExponentOfSide(level.size);
    const double cosCutoff = std::cos(std::acos(std::pow(kSpecularLobeCutoff, 1.0 / e)));
    // Texels at a face's centre, edge and corner, where tiles of several faces meet.
    for (const auto& [face, x, y] : {std::tuple{0, 0, 0}, std::tuple{2, level.size / 2, level.size - 1},
                                      std::tuple{5, level.size - 1, level.size / 3}, std::tuple{3, 1, level.size / 2}}) {
      const glm::dvec3 r = cubeTexelDirection(face, x, y, level.size);
      glm::dvec3 sum(0.0);
      double weights = 0.0;
      for (int f = 0; f < kCubeFaces; ++f) {
        for (int sy = 0; sy < source.size; ++sy) {
          for (int sx = 0; sx < source.size; ++sx) {
            const double c = glm::dot(r, cubeTexelDirection(f, sx, sy, source.size));
            if (c <= cosCutoff) continue;
            const double w = std::pow(c, e) * cubeTexelSolidAngle(sx, sy, source.size);
            sum += glm::dvec3(source.texel(f, sx, sy)) * w;
            weights += w;
          }
        }
      }
      const glm::dvec3 everyTexel = sum / weights;
      EXPECT_NEAR(glm::length(glm::dvec3(level.texel(face, x, y)) - everyTexel), 0.0, 1e-6)
          << "level " << l << " face " << face << " (" << x << ", " << y << ")";
    }
  }
}

TEST(EnvironmentSpecular, MonteCarloAgreesWithinItsStatistics) {
  const CubeMap sky = cubeOf(64, [](const glm::dvec3& w, int, int) { return linearSky(w); });
  const glm::dvec3 r = glm::normalize(glm::dvec3(0.3, 0.8, -0.5));
  for (double e : {1.0, 16.0, 400.0}) {
    const MonteCarloEstimate estimate = specularMonteCarlo(sky, r, e, 20000, 3);
    const glm::dvec3 exact = kA + glm::dvec3(glm::dot(kB, r) * (e + 1.0) / (e + 2.0));
    for (int c = 0; c < 3; ++c) {
      // Four standard errors, and the cube's bilinear reads of a linear sky (about 1e-3).
      EXPECT_NEAR(estimate.mean[c], exact[c], 4.0 * estimate.standardError[c] + 2e-3) << "e " << e << " channel " << c;
    }
  }
  // The same seed draws the same samples; another seed others.
  EXPECT_EQ(specularMonteCarlo(sky, r, 8.0, 64, 5).mean, specularMonteCarlo(sky, r, 8.0, 64, 5).mean);
  EXPECT_NE(specularMonteCarlo(sky, r, 8.0, 64, 5).mean, specularMonteCarlo(sky, r, 8.0, 64, 6).mean);
}

TEST(EnvironmentSpecular, TrilinearReadsBlendTheTwoLevels) {
  const CubeMap glossy = specularCubeFromCube(cubeOf(32, [](const glm::dvec3& w, int, int) { return linearSky(w); }));
  const glm::dvec3 r = glm::normalize(glm::dvec3(-0.2, 0.1, 0.9));
  const glm::dvec3 at1 = cubeBilinear(glossy, r, 1), at2 = cubeBilinear(glossy, r, 2);
  EXPECT_EQ(cubeTrilinear(glossy, r, 1.0), at1);
  EXPECT_NEAR(glm::length(cubeTrilinear(glossy, r, 1.25) - (at1 * 0.75 + at2 * 0.25)), 0.0, 1e-12);
  EXPECT_EQ(cubeTrilinear(glossy, r, -3.0), cubeBilinear(glossy, r, 0));
  EXPECT_EQ(cubeTrilinear(glossy, r, 99.0), cubeBilinear(glossy, r, glossy.levelCount() - 1));
}

}  // namespace
}  // namespace twr
