// Screen-space reflections on the CPU (softrender/ssr.h): the march's four outcomes against a
// depth buffer made here, where every answer is known; the pass on a scene: off changes
// nothing, on reflects, the teaching and fast paths give the same bits (the suite compares the
// renderers, tests/compare/test_scene_suite.cpp).
#include "softrender/ssr.h"

#include "scene/camera.h"
#include "scene/errors.h"
#include "scene/scene_file.h"
#include "softrender/cpu_renderer.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <string>
#include <utility>
#include <vector>

namespace twr {
namespace {

constexpr int kSide = 8;
constexpr float kWall = 10.0f;  // the wall's eye distance, world units

// An eye at the origin looking down -Z (90 degrees, square, near 1, far 100) at a wall kWall
// away that fills the screen: every pixel of the depth buffer holds the wall's window depth.
struct WallView {
  Camera camera;
  std::vector<float> depth;  // the wall's eye distance, from its window depth
  std::vector<float> plane;
  SsrUniforms u;
  WallView() {
    camera.position = vec3(0.0f);
    camera.target = vec3(0.0f, 0.0f, -1.0f);
    camera.fovDeg = 90.0f;
    camera.near = 1.0f;
    camera.far = 100.0f;
    Scene scene;
    scene.camera = camera;
    RenderSettings settings;
    settings.ssr.enabled = true;
    settings.ssr.maxSteps = 64;
    settings.ssr.step = 0.05f;
    settings.ssr.thickness = 0.1f;
    u = makeSsrUniforms(scene, settings, kSide, kSide);
    const vec4 clip = u.clipFromWorld * vec4(0.0f, 0.0f, -kWall, 1.0f);
    depth.assign(kSide * kSide, lanes::distanceOfDepth<float>(u, 0.5f * (clip.z / clip.w) + 0.5f));
    plane.assign(kSide * kSide, 0.0f);
    u.surfaceDistance = depth.data();
    for (auto& c : u.colour) c = plane.data();
  }
};

template <typename L>
lanes::SsrMarchL<L> marchFrom(const SsrUniformsT<ScalarOf<L>>& u, vec3 origin, vec3 dir) {
  return lanes::march<L>(u, Vec3L<L>(origin), Vec3L<L>(glm::normalize(dir)), MaskOf<L>(true));
}

lanes::SsrMarchL<float> marchScreen(const SsrUniforms& u, vec3 origin, vec3 dir) {
  return lanes::screenMarch<float>(u, origin, glm::normalize(dir), true);
}

template <typename L>
void expectEveryOutcome() {
  using S = ScalarOf<L>;
  WallView view;
  SsrUniformsT<S> u;
  u.clipFromWorld = Mat4T<S>(view.u.clipFromWorld);
  u.viewportSize = Vec2T<S>(view.u.viewportSize);
  u.distanceNumerator = S(view.u.distanceNumerator);
  u.distanceSum = S(view.u.distanceSum);
  u.distanceDifference = S(view.u.distanceDifference);
  u.eyePosWorld = Vec3T<S>(view.u.eyePosWorld);
  u.maxSteps = view.u.maxSteps;
  u.step = S(view.u.step);
  u.minStep = S(view.u.minStep);
  u.thickness = S(view.u.thickness);
  u.surfaceDistance = view.depth.data();
  // The buffer's eye distance is the wall's, rebuilt from its depth.
  EXPECT_NEAR(double(lanes::bufferDistance<L>(u, L(S(0)))), kWall, 1e-3);
  // Straight at the wall from 1 in front of it: twenty steps of 0.05 (one more as the sums
  // round), a hit at the screen's middle.
  const lanes::SsrMarchL<L> hit = marchFrom<L>(u, vec3(0.0f, 0.0f, -9.0f), vec3(0.0f, 0.0f, -1.0f));
  EXPECT_EQ(hit.result, lanes::ssrResultLane<L>(SsrResult::Hit));
  EXPECT_GE(hit.steps, L(S(20)));
  EXPECT_LE(hit.steps, L(S(21)));
  EXPECT_EQ(hit.hitIndex, L(S((kSide / 2 - 1) * kSide + kSide / 2)));  // pixel (4, 4), rows from the top
  // Towards the eye, off the centre: out of the frustum's side before it reaches the eye.
  EXPECT_EQ(marchFrom<L>(u, vec3(0.1f, 0.0f, -1.5f), vec3(0.0f, 0.0f, 1.0f)).result,
            lanes::ssrResultLane<L>(SsrResult::OffScreen));
  // Sideways out of the frustum.
  EXPECT_EQ(marchFrom<L>(u, vec3(4.5f, 0.0f, -5.0f), vec3(1.0f, 0.0f, 0.0f)).result,
            lanes::ssrResultLane<L>(SsrResult::OffScreen));
  // Steps of 3 jump from 2 in front of the wall to 1 behind it: more than the thickness.
  u.step = S(3);
  EXPECT_EQ(marchFrom<L>(u, vec3(0.0f, 0.0f, -2.0f), vec3(0.0f, 0.0f, -1.0f)).result,
            lanes::ssrResultLane<L>(SsrResult::Behind));
  // adaptive_world halves the step at each overshoot down to 3 / 16, then decides: the crossing
  // at 9.875 to 10.0625 is within a thickness of 0.2 on both sides.
  u.march = SsrMarch::AdaptiveWorld;
  u.minStep = S(3) * S(kSsrAdaptiveMinStepRatio);
  u.thickness = S(0.2);
  const lanes::SsrMarchL<L> adaptive = marchFrom<L>(u, vec3(0.0f, 0.0f, -2.0f), vec3(0.0f, 0.0f, -1.0f));
  EXPECT_EQ(adaptive.result, lanes::ssrResultLane<L>(SsrResult::Hit));
  EXPECT_EQ(adaptive.steps, L(S(9)));
  // Out of steps before anything: a miss.
  u.march = SsrMarch::LinearWorld;
  u.step = S(0.05);
  u.thickness = S(0.1);
  u.maxSteps = 2;
  EXPECT_EQ(marchFrom<L>(u, vec3(0.0f, 0.0f, -5.0f), vec3(0.0f, 0.0f, -1.0f)).result,
            lanes::ssrResultLane<L>(SsrResult::Miss));
  // A lane not marched stays so.
  EXPECT_EQ(lanes::march<L>(u, Vec3L<L>(L(S(0))), Vec3L<L>(L(S(0)), L(S(0)), L(S(-1))), MaskOf<L>(false)).result,
            lanes::ssrResultLane<L>(SsrResult::NotMarched));
}

TEST(Ssr, MarchEndsInEachOutcomeFloat) { expectEveryOutcome<float>(); }
TEST(Ssr, MarchEndsInEachOutcomeDouble) { expectEveryOutcome<double>(); }

TEST(Ssr, HitAddsTheLitColourThereScaled) {
  WallView view;
  std::vector<float> red(kSide * kSide, 0.0f);
  red[(kSide / 2 - 1) * kSide + kSide / 2] = 0.5f;  // the hit pixel is half red
  view.u.colour[0] = red.data();
  view.u.reflectStrength = 0.5f;
  vec3 colour(0.25f, 0.0f, 0.0f);
  // A mirror at z = -9.5 facing the eye sends the eye's ray straight back: off the screen once
  // it passes the eye (190 steps of 0.05).
  view.u.maxSteps = 400;
  const vec3 albedo(1.0f);
  const lanes::SsrMarchL<float> back =
      lanes::ssrPixel<float>(view.u, vec3(0.0f, 0.0f, 1.0f), vec3(0.0f, 0.0f, -9.5f), 0.8f, albedo, nullptr, true, colour)
          .mirror;
  EXPECT_EQ(back.result, lanes::ssrResultLane<float>(SsrResult::OffScreen));
  EXPECT_EQ(colour, vec3(0.25f, 0.0f, 0.0f));
  // Tilted up (normal (0, 1, 0.2)): the ray r = 2 (n.wo) n - wo goes on to the wall, rising 0.2
  // by then: pixel (4, 4).
  const lanes::SsrMarchL<float> toWall = lanes::ssrPixel<float>(view.u, glm::normalize(vec3(0.0f, 1.0f, 0.2f)),
                                                                vec3(0.0f, 0.0f, -9.5f), 0.8f, albedo, nullptr, true, colour)
                                      .mirror;
  EXPECT_EQ(toWall.result, lanes::ssrResultLane<float>(SsrResult::Hit));
  EXPECT_FLOAT_EQ(colour.r, 0.25f + 0.5f * (0.5f * 0.8f));
  EXPECT_EQ(colour.g, 0.0f);
  // ssr_reflect 0: not marched, the colour kept.
  vec3 kept(0.3f);
  const lanes::SsrPixelL<float> none =
      lanes::ssrPixel<float>(view.u, vec3(0.0f, 0.0f, -1.0f), vec3(0.0f, 0.0f, -5.0f), 0.0f, albedo, nullptr, true, kept);
  EXPECT_EQ(none.mirror.result, lanes::ssrResultLane<float>(SsrResult::NotMarched));
  EXPECT_FALSE(none.changed);
  EXPECT_EQ(kept, vec3(0.3f));
}

// Known answers (computed apart from this code): GLSL's randomPair runs the same integers,
// and a change here would change every indirect image.
TEST(Ssr, PcgHashKnownAnswers) {
  EXPECT_EQ(pcgHash(0u), 129708002u);
  EXPECT_EQ(pcgHash(1u), 2831084092u);
  EXPECT_EQ(pcgHash(12345u), 4099845390u);
  EXPECT_EQ(ssrRandomPairOf(3, 4, 0), vec2(16614390.0f / 16777216.0f, 13960342.0f / 16777216.0f));
}

TEST(Ssr, RandomPairsAreFixedPerPixelAndSampleAndSpreadOverTheSquare) {
  EXPECT_EQ(ssrRandomPairOf(3, 4, 0), ssrRandomPairOf(3, 4, 0));
  EXPECT_NE(ssrRandomPairOf(3, 4, 0), ssrRandomPairOf(4, 3, 0));
  EXPECT_NE(ssrRandomPairOf(3, 4, 0), ssrRandomPairOf(3, 4, 1));
  // Over many pixels: in [0, 1), 24 bits, a quarter in each quadrant of the square.
  int quadrants[4] = {};
  double sum = 0.0;
  constexpr int kSideSamples = 64;
  for (std::uint32_t y = 0; y < kSideSamples; ++y) {
    for (std::uint32_t x = 0; x < kSideSamples; ++x) {
      const vec2 xi = ssrRandomPairOf(x, y, 2);
      ASSERT_GE(xi.x, 0.0f);
      ASSERT_LT(xi.x, 1.0f);
      ASSERT_LT(xi.y, 1.0f);
      EXPECT_EQ(xi.x * 16777216.0f, std::floor(xi.x * 16777216.0f));
      ++quadrants[(xi.x < 0.5f ? 0 : 1) + (xi.y < 0.5f ? 0 : 2)];
      sum += static_cast<double>(xi.x) + static_cast<double>(xi.y);
    }
  }
  constexpr double kCount = kSideSamples * kSideSamples;
  for (const int q : quadrants) EXPECT_NEAR(q / kCount, 0.25, 0.03);
  EXPECT_NEAR(sum / (2.0 * kCount), 0.5, 0.02);
}

TEST(Ssr, CircleIsWithinAMillionthOfTheLibrarys) {
  for (int i = 0; i < 4096; ++i) {
    const double turn = i / 4096.0;
    const vec2 c = lanes::circle<float>(static_cast<float>(turn));
    EXPECT_NEAR(c.x, std::cos(2.0 * 3.141592653589793 * turn), 1e-6) << turn;
    EXPECT_NEAR(c.y, std::sin(2.0 * 3.141592653589793 * turn), 1e-6) << turn;
  }
}

// The hemisphere directions: unit, on the normal's side, for normals everywhere (Duff's basis
// has no bad direction, -Z included); each distribution's mean weight is 1, the albedo a white
// sky returns (its estimate of the integral of cos / pi).
TEST(Ssr, HemisphereSamplesEstimateTheCosineIntegral) {
  for (const SampleDistribution distribution : {SampleDistribution::Uniform, SampleDistribution::Cosine}) {
    SsrUniforms u;
    u.distribution = distribution;
    for (const vec3 n : {vec3(0.0f, 0.0f, 1.0f), vec3(0.0f, 0.0f, -1.0f), vec3(0.0f, 1.0f, 0.0f),
                         glm::normalize(vec3(0.3f, -0.5f, -0.8f)), glm::normalize(vec3(1e-4f, 0.0f, -1.0f))}) {
      double weights = 0.0, heights = 0.0;
      constexpr int kSamples = 20000;
      for (int k = 0; k < kSamples; ++k) {
        float weight = 0.0f;
        const vec3 dir = lanes::hemisphere<float>(u, n, ssrRandomPairOf(7, 11, static_cast<std::uint32_t>(k)), weight);
        ASSERT_NEAR(glm::length(dir), 1.0f, 1e-5f);
        ASSERT_GE(glm::dot(dir, n), -1e-5f);
        weights += weight;
        heights += glm::dot(dir, n);
      }
      EXPECT_NEAR(weights / kSamples, 1.0, 0.02) << toString(distribution);
      // The mean height: 1/2 uniform, 2/3 cosine-weighted.
      EXPECT_NEAR(heights / kSamples, distribution == SampleDistribution::Uniform ? 0.5 : 2.0 / 3.0, 0.01)
          << toString(distribution);
    }
  }
}

// The screen marches' view: the WallView's camera over 64 x 64 pixels, the surface distances
// given directly (a wall kWall away unless a test puts something nearer).
constexpr int kScreenSide = 64;
struct ScreenView {
  int side = kScreenSide;
  std::vector<float> plane;  // top row first
  std::vector<float> colour;
  SsrPlanes planes;
  SsrUniforms u;
  explicit ScreenView(SsrMarch march, int sidePixels = kScreenSide) : side(sidePixels) {
    Scene scene;
    scene.camera.position = vec3(0.0f);
    scene.camera.target = vec3(0.0f, 0.0f, -1.0f);
    scene.camera.fovDeg = 90.0f;
    scene.camera.near = 1.0f;
    scene.camera.far = 100.0f;
    RenderSettings settings;
    settings.ssr.enabled = true;
    settings.ssr.march = march;
    settings.ssr.maxSteps = kMaxSsrSteps;
    settings.ssr.thickness = 0.1f;
    u = makeSsrUniforms(scene, settings, side, side);
    plane.assign(static_cast<std::size_t>(side * side), kWall);
    colour.assign(static_cast<std::size_t>(side * side), 0.0f);
  }
  // A column x (from the left) of every row at eye distance d.
  void column(int x, float d) {
    for (int y = 0; y < side; ++y) plane[static_cast<std::size_t>(y * side + x)] = d;
  }
  // Points the uniforms at the plane, with its chain for hiz.
  const SsrUniforms& ready() {
    planes.surfaceDistance = plane;
    for (auto& c : planes.rgb) c = colour;
    planes.hizLevels = 0;
    if (u.march == SsrMarch::Hiz) hizChainOf(plane, side, side, planes);
    useSsrPlanes(planes, u);
    return u;
  }
};

// The pixel (column, row from the bottom) of an element of a top-row-first plane.
std::pair<int, int> pixelOf(float index, int width, int height) {
  const int i = static_cast<int>(index);
  return {i % width, height - 1 - i / width};
}

class SsrScreenMarches : public ::testing::TestWithParam<SsrMarch> {};

TEST_P(SsrScreenMarches, EndInEachOutcome) {
  ScreenView view(GetParam());
  const SsrUniforms& u = view.ready();
  // Right and away from 5 in front of the eye: the wall at x = 5, seen at window x 48.
  const lanes::SsrMarchL<float> hit = marchScreen(u, vec3(0.0f, 0.0f, -5.0f), vec3(1.0f, 0.0f, -1.0f));
  EXPECT_EQ(hit.result, lanes::ssrResultLane<float>(SsrResult::Hit));
  const auto [hitX, hitY] = pixelOf(hit.hitIndex, kScreenSide, kScreenSide);
  EXPECT_NEAR(hitX, 48, 1);
  EXPECT_EQ(hitY, 32);
  // Parallel to the wall, to the right: off the screen at pixel 64, 32 samples on.
  const lanes::SsrMarchL<float> off = marchScreen(u, vec3(0.0f, 0.0f, -5.0f), vec3(1.0f, 0.0f, 0.0f));
  EXPECT_EQ(off.result, lanes::ssrResultLane<float>(SsrResult::OffScreen));
  if (GetParam() == SsrMarch::DdaScreen) {
    EXPECT_EQ(off.steps, 32.0f);
  }
  // Out of steps: a miss.
  ScreenView few(GetParam());
  few.u.maxSteps = 3;
  EXPECT_EQ(marchScreen(few.ready(), vec3(0.0f, 0.0f, -5.0f), vec3(1.0f, 0.0f, -1.0f)).result,
            lanes::ssrResultLane<float>(SsrResult::Miss));
  // Straight away from the eye: under a pixel on the screen, nothing to march.
  EXPECT_EQ(marchScreen(u, vec3(0.0f, 0.0f, -5.0f), vec3(0.0f, 0.0f, -1.0f)).result,
            lanes::ssrResultLane<float>(SsrResult::Miss));
}

TEST_P(SsrScreenMarches, PassBehindANearerSurfaceAndOverTheSky) {
  // A pole at eye distance 6 in columns 40 and 41: the ray reaches those columns at about 6.7,
  // behind it by more than the thickness.
  ScreenView pole(GetParam());
  pole.column(40, 6.0f);
  pole.column(41, 6.0f);
  const lanes::SsrMarchL<float> behind = marchScreen(pole.ready(), vec3(0.0f, 0.0f, -5.0f), vec3(1.0f, 0.0f, -1.0f));
  EXPECT_EQ(behind.result, lanes::ssrResultLane<float>(SsrResult::Behind));
  // The same pole at 6.7 is met within the thickness.
  ScreenView near(GetParam());
  for (int x = 38; x < 44; ++x) near.column(x, 6.69f);
  const lanes::SsrMarchL<float> met = marchScreen(near.ready(), vec3(0.0f, 0.0f, -5.0f), vec3(1.0f, 0.0f, -1.0f));
  EXPECT_EQ(met.result, lanes::ssrResultLane<float>(SsrResult::Hit));
  EXPECT_NEAR(pixelOf(met.hitIndex, kScreenSide, kScreenSide).first, 40, 1);
  // Nothing drawn anywhere (the sky's distance): the ray runs to its end at the far distance.
  ScreenView sky(GetParam());
  sky.plane.assign(sky.plane.size(), sky.u.skyDistance);
  EXPECT_EQ(marchScreen(sky.ready(), vec3(0.0f, 0.0f, -5.0f), vec3(0.2f, 0.0f, -1.0f)).result,
            lanes::ssrResultLane<float>(SsrResult::Miss));
}
INSTANTIATE_TEST_SUITE_P(Marches, SsrScreenMarches, ::testing::Values(SsrMarch::DdaScreen, SsrMarch::Hiz),
                         [](const auto& info) { return std::string(toString(info.param)); });

TEST(Ssr, HizChainHoldsTheLeastOfEachCellsPixels) {
  EXPECT_EQ(hizLevelsOf(1, 1), 0);
  EXPECT_EQ(hizLevelsOf(640, 480), 8);
  EXPECT_EQ(hizLevelsOf(1280, 720), 9);
  EXPECT_EQ(hizLevelsOf(4096, 4096), 12);
  // Odd sides, so the last column and row of a level fold in the one the halving drops.
  const int width = 13, height = 6;
  std::vector<float> plane(static_cast<std::size_t>(width * height));
  std::uint32_t state = 12345u;
  for (float& d : plane) {
    state = state * 1664525u + 1013904223u;
    d = 1.0f + static_cast<float>(state >> 8) / 16777216.0f * 50.0f;
  }
  SsrPlanes planes;
  hizChainOf(plane, width, height, planes);
  ASSERT_EQ(planes.hizLevels, 2);
  for (int k = 1; k <= planes.hizLevels; ++k) {
    const int levelWidth = width >> k, levelHeight = height >> k, side = 1 << k;
    for (int cy = 0; cy < levelHeight; ++cy) {
      for (int cx = 0; cx < levelWidth; ++cx) {
        const int xEnd = cx == levelWidth - 1 ? width : (cx + 1) * side;
        const int yEnd = cy == levelHeight - 1 ? height : (cy + 1) * side;
        float least = 1e30f;
        for (int y = cy * side; y < yEnd; ++y) {  // window rows from the bottom
          for (int x = cx * side; x < xEnd; ++x) least = std::min(least, plane[static_cast<std::size_t>((height - 1 - y) * width + x)]);
        }
        const std::size_t at = static_cast<std::size_t>(planes.hizOffset[static_cast<std::size_t>(k)]) +
                               static_cast<std::size_t>(cy * levelWidth + cx);
        EXPECT_EQ(planes.hizCells[at], least) << "level " << k << " cell " << cx << ", " << cy;
      }
    }
  }
}

// hiz skips only what dda_screen would step over in front: over a field of poles and boxes at
// 256 x 256, every ray ends the same (result and hit pixel), in fewer steps overall (a ray that
// grazes surfaces may take more: each failed skip is a step).
TEST(Ssr, HizEndsEveryRayAsDdaDoesInFewerSteps) {
  constexpr int kFieldSide = 256;
  ScreenView dda(SsrMarch::DdaScreen, kFieldSide), hiz(SsrMarch::Hiz, kFieldSide);
  std::uint32_t state = 7u;
  const auto next = [&] {
    state = state * 1664525u + 1013904223u;
    return static_cast<float>(state >> 8) / 16777216.0f;
  };
  for (int box = 0; box < 12; ++box) {
    const int x0 = static_cast<int>(next() * 240.0f), y0 = static_cast<int>(next() * 240.0f);
    const int w = 1 + static_cast<int>(next() * 32.0f), h = 1 + static_cast<int>(next() * 80.0f);
    const float d = 3.0f + next() * 6.0f;
    for (int y = y0; y < std::min(kFieldSide, y0 + h); ++y) {
      for (int x = x0; x < std::min(kFieldSide, x0 + w); ++x) {
        dda.plane[static_cast<std::size_t>(y * kFieldSide + x)] = d + 0.01f * static_cast<float>(x);
      }
    }
  }
  hiz.plane = dda.plane;
  const SsrUniforms& ud = dda.ready();
  const SsrUniforms& uh = hiz.ready();
  float ddaSteps = 0.0f, hizSteps = 0.0f;
  int hits = 0, kinds[5] = {};
  for (int ray = 0; ray < 400; ++ray) {
    const vec3 origin((next() - 0.5f) * 4.0f, (next() - 0.5f) * 4.0f, -2.0f - next() * 4.0f);
    const vec3 dir(next() - 0.5f, next() - 0.5f, -next());
    if (glm::length(dir) < 0.1f) continue;
    const lanes::SsrMarchL<float> a = marchScreen(ud, origin, dir);
    const lanes::SsrMarchL<float> b = marchScreen(uh, origin, dir);
    ASSERT_EQ(a.result, b.result) << "ray " << ray;
    if (a.result == lanes::ssrResultLane<float>(SsrResult::Hit)) {
      ++hits;
      EXPECT_EQ(a.hitIndex, b.hitIndex) << "ray " << ray;
    }
    ++kinds[static_cast<int>(a.result)];
    ddaSteps += a.steps;
    hizSteps += b.steps;
  }
  EXPECT_GT(hits, 50);
  EXPECT_GT(kinds[static_cast<int>(SsrResult::Behind)], 10);
  EXPECT_GT(kinds[static_cast<int>(SsrResult::OffScreen)], 10);
  EXPECT_LT(hizSteps, 0.5f * ddaSteps) << "hiz " << hizSteps << " steps, dda_screen " << ddaSteps;
}

// The kind a march's last recorded step must have for its result.
bool lastStepFits(const lanes::SsrMarchL<float>& m, const std::vector<SsrMarchStep>& log) {
  if (log.empty()) return false;
  const SsrStepKind last = log.back().kind;
  switch (static_cast<SsrResult>(static_cast<int>(m.result))) {
    case SsrResult::Hit: return last == SsrStepKind::Hit;
    case SsrResult::Behind: return last == SsrStepKind::Behind;
    case SsrResult::OffScreen: return last == SsrStepKind::OffScreen;
    case SsrResult::Miss: return last == SsrStepKind::Ended || !endsMarch(last);  // the ray's end, or out of steps
    case SsrResult::NotMarched: return false;
  }
  return false;
}

TEST(Ssr, TheRecordedStepsAreTheMarchsOwn) {
  // The inspector's record (scene/ssr_trace.h): one step per step the march counts, the last
  // one its outcome, a hit's pixel the hit's, hiz's skips recorded as such; recording changes
  // nothing of the march.
  constexpr int kFieldSide = 128;
  ScreenView dda(SsrMarch::DdaScreen, kFieldSide), hiz(SsrMarch::Hiz, kFieldSide);
  for (int y = 40; y < 90; ++y) {
    for (int x = 30; x < 70; ++x) dda.plane[static_cast<std::size_t>(y * kFieldSide + x)] = 5.0f + 0.02f * static_cast<float>(x);
  }
  hiz.plane = dda.plane;
  std::uint32_t state = 11u;
  const auto next = [&] {
    state = state * 1664525u + 1013904223u;
    return static_cast<float>(state >> 8) / 16777216.0f;
  };
  int skips = 0, hits = 0;
  for (const SsrUniforms* u : {&dda.ready(), &hiz.ready()}) {
    for (int ray = 0; ray < 200; ++ray) {
      const vec3 origin((next() - 0.5f) * 3.0f, (next() - 0.5f) * 3.0f, -2.0f - next() * 2.0f);
      const vec3 dir = glm::normalize(vec3(next() - 0.5f, next() - 0.5f, -0.2f - next()));
      std::vector<SsrMarchStep> log;
      const lanes::SsrMarchL<float> plain = lanes::screenMarch<float>(*u, origin, dir, true);
      const lanes::SsrMarchL<float> logged = lanes::screenMarch<float>(*u, origin, dir, true, &log);
      ASSERT_EQ(std::memcmp(&plain, &logged, sizeof plain), 0) << "ray " << ray;
      ASSERT_EQ(log.size(), static_cast<std::size_t>(plain.steps)) << "ray " << ray;
      EXPECT_TRUE(lastStepFits(plain, log)) << "ray " << ray << ": " << toString(log.back().kind);
      if (plain.result == lanes::ssrResultLane<float>(SsrResult::Hit)) {
        ++hits;
        EXPECT_EQ(log.back().pixel, vec2(plain.hitX, plain.hitY)) << "ray " << ray;
        EXPECT_GE(log.back().rayDistance, log.back().surfaceDistance) << "a hit lies behind the surface";
      }
      for (const SsrMarchStep& step : log) {
        skips += step.kind == SsrStepKind::CellSkipped;
        if (u->hizLevels == 0) {
          EXPECT_EQ(step.level, 0);
        }
      }
    }
  }
  EXPECT_GT(hits, 20);
  EXPECT_GT(skips, 50) << "hiz skips cells";
  // The world marches: every step a sample along the ray, adaptive's halvings as refine steps.
  WallView view;
  SsrUniforms u = view.u;
  u.surfaceDistance = view.depth.data();
  std::vector<SsrMarchStep> log;
  const lanes::SsrMarchL<float> hit =
      lanes::march<float>(u, vec3(0.0f, 0.0f, -9.0f), vec3(0.0f, 0.0f, -1.0f), true, &log);
  ASSERT_EQ(log.size(), static_cast<std::size_t>(hit.steps));
  EXPECT_EQ(log.back().kind, SsrStepKind::Hit);
  EXPECT_NEAR(log.front().along, 0.05f, 1e-6f);
  for (std::size_t k = 0; k + 1 < log.size(); ++k) EXPECT_EQ(log[k].kind, SsrStepKind::InFront) << k;
  u.march = SsrMarch::AdaptiveWorld;
  u.step = 3.0f;
  u.minStep = 3.0f * kSsrAdaptiveMinStepRatio;
  u.thickness = 0.2f;
  log.clear();
  const lanes::SsrMarchL<float> adaptive =
      lanes::march<float>(u, vec3(0.0f, 0.0f, -2.0f), vec3(0.0f, 0.0f, -1.0f), true, &log);
  ASSERT_EQ(log.size(), static_cast<std::size_t>(adaptive.steps));
  EXPECT_EQ(std::count_if(log.begin(), log.end(), [](const SsrMarchStep& s) { return s.kind == SsrStepKind::Refine; }), 4)
      << "3 halves to 3/16 in four steps";
  EXPECT_EQ(log.back().kind, SsrStepKind::Hit);
}

Scene mirrorFloor() {
  return loadSceneFile(std::string(TWINRASTER_SOURCE_DIR) + "/assets/scenes/ssr_mirror_floor.json");
}

RenderOutput renderCpu(const Scene& scene, const RenderSettings& settings, CpuPath path) {
  CpuOptions options;
  options.path = path;
  options.threads = 2;
  return makeCpuRenderer(options)->render(scene, settings, 160, 120);
}

TEST(Ssr, TraceSsrMarchEndsAsTheHitViewShowsEveryPixel) {
  Scene scene = mirrorFloor();
  for (const SsrMarch march : {SsrMarch::LinearWorld, SsrMarch::Hiz}) {
    scene.settings.ssr.march = march;
    const RenderOutput frame = renderCpu(scene, scene.settings, CpuPath::Teaching);
    RenderSettings hitView = scene.settings;
    hitView.view = View::SsrHit;
    const RenderOutput view = renderCpu(scene, hitView, CpuPath::Teaching);
    int checked = 0;
    for (int y = 0; y < 120; y += 5) {
      for (int x = 0; x < 160; x += 5) {
        const SsrMarchTrace trace = traceSsrMarch(scene, scene.settings, frame, x, y);
        const std::size_t i = static_cast<std::size_t>(y) * 160 + static_cast<std::size_t>(x);
        ASSERT_EQ(trace.marched, frame.triangleId[i] != kNoTriangle) << x << ", " << y;
        if (!trace.marched) continue;
        ASSERT_FALSE(trace.steps.empty());
        // ssr_hit's colours: hit green, miss blue, off screen yellow, behind red.
        const std::uint8_t* c = &view.rgba[4 * i];
        const SsrStepKind last = trace.steps.back().kind;
        const bool green = c[1] > 150 && c[0] < 100, blue = c[2] > 150 && c[0] < 100 && c[1] < 150;
        const bool yellow = c[0] > 150 && c[1] > 150, red = c[0] > 150 && c[1] < 100;
        EXPECT_EQ(green, last == SsrStepKind::Hit) << x << ", " << y;
        EXPECT_EQ(yellow, last == SsrStepKind::OffScreen) << x << ", " << y;
        EXPECT_EQ(red, last == SsrStepKind::Behind) << x << ", " << y;
        EXPECT_EQ(blue, last == SsrStepKind::Ended || !endsMarch(last)) << x << ", " << y;
        ++checked;
      }
    }
    EXPECT_GT(checked, 300);
  }
  RenderSettings off = scene.settings;
  off.ssr.enabled = false;
  EXPECT_THROW(traceSsrMarch(scene, off, renderCpu(scene, off, CpuPath::Fast), 10, 10), InputError);
  EXPECT_THROW(traceSsrMarch(scene, scene.settings, renderCpu(scene, scene.settings, CpuPath::Fast), 160, 10),
               InputError);
}

TEST(Ssr, OffChangesNothingOnReflects) {
  const Scene scene = mirrorFloor();
  ASSERT_TRUE(scene.settings.ssr.enabled);
  RenderSettings off = scene.settings;
  off.ssr.enabled = false;
  off.pipeline = Pipeline::Deferred;
  const RenderOutput plain = renderCpu(scene, off, CpuPath::Fast);
  // On, but nothing reflects: the same bits as off.
  Scene matte = scene;
  for (Material& m : matte.materials) m.ssrReflect = 0.0f;
  EXPECT_EQ(renderCpu(matte, scene.settings, CpuPath::Fast).rgba, plain.rgba);
  // On: the floor shows the box and the ball, and only reflecting pixels change.
  const RenderOutput on = renderCpu(scene, scene.settings, CpuPath::Fast);
  EXPECT_GT(on.stats.ssrMilliseconds, 0.0);
  std::size_t changed = 0;
  for (std::size_t i = 0; i < on.depth.size(); ++i) {
    if (std::memcmp(&on.rgba[4 * i], &plain.rgba[4 * i], 4) != 0) ++changed;
  }
  EXPECT_GT(changed, 300u);
  EXPECT_EQ(on.depth, plain.depth);
}

// On the mirror floor, with steps enough for every ray: hiz reflects exactly what dda_screen
// does, and both reflect.
TEST(Ssr, HizDrawsTheDdaFrameOnTheMirrorFloor) {
  const Scene scene = mirrorFloor();
  RenderSettings off = scene.settings;
  off.ssr.enabled = false;
  off.pipeline = Pipeline::Deferred;
  const RenderOutput plain = renderCpu(scene, off, CpuPath::Fast);
  RenderSettings dda = scene.settings;
  dda.ssr.march = SsrMarch::DdaScreen;
  dda.ssr.maxSteps = kMaxSsrSteps;
  RenderSettings hiz = dda;
  hiz.ssr.march = SsrMarch::Hiz;
  const RenderOutput a = renderCpu(scene, dda, CpuPath::Fast);
  const RenderOutput b = renderCpu(scene, hiz, CpuPath::Fast);
  EXPECT_EQ(a.rgba, b.rgba);
  std::size_t changed = 0;
  for (std::size_t i = 0; i < a.depth.size(); ++i) {
    if (std::memcmp(&a.rgba[4 * i], &plain.rgba[4 * i], 4) != 0) ++changed;
  }
  EXPECT_GT(changed, 300u);
}

// Indirect light on the mirror floor: only ever adds light, reaches pixels that reflect
// nothing (the box's sides see the floor), and the teaching and fast paths agree bit for bit.
TEST(Ssr, IndirectLightAddsOnBothPaths) {
  const Scene scene = mirrorFloor();
  RenderSettings mirror = scene.settings;
  mirror.ssr.march = SsrMarch::Hiz;
  const RenderOutput plain = renderCpu(scene, mirror, CpuPath::Fast);
  for (const SampleDistribution distribution : {SampleDistribution::Uniform, SampleDistribution::Cosine}) {
    RenderSettings settings = mirror;
    settings.ssr.indirectSamples = 4;
    settings.ssr.sampleDistribution = distribution;
    const RenderOutput fast = renderCpu(scene, settings, CpuPath::Fast);
    const RenderOutput teaching = renderCpu(scene, settings, CpuPath::Teaching);
    EXPECT_EQ(fast.rgba, teaching.rgba) << toString(distribution);
    std::size_t brighter = 0;
    for (std::size_t i = 0; i < fast.rgba.size(); ++i) {
      ASSERT_GE(fast.rgba[i], plain.rgba[i]) << "byte " << i;
      if (fast.rgba[i] > plain.rgba[i]) ++brighter;
    }
    EXPECT_GT(brighter, 2000u) << toString(distribution);
  }
}

// The reflection views: every drawn pixel marched, its march's value in place of the colour,
// the same bits on both paths; ssr_hit shows hits on the floor and misses and off-screen rays
// elsewhere, hiz_level shows levels above 0 where rays crossed empty floor.
TEST(Ssr, ReflectionViewsShowTheMarch) {
  const Scene scene = mirrorFloor();
  const auto count = [](const RenderOutput& out, std::array<std::uint8_t, 3> rgb) {
    std::size_t n = 0;
    for (std::size_t i = 0; i < out.depth.size(); ++i) {
      if (out.rgba[4 * i] == rgb[0] && out.rgba[4 * i + 1] == rgb[1] && out.rgba[4 * i + 2] == rgb[2]) ++n;
    }
    return n;
  };
  for (const View view : kSsrViews) {
    RenderSettings settings = scene.settings;
    settings.ssr.enabled = false;  // the views march whatever ssr.enabled says
    settings.ssr.march = SsrMarch::Hiz;
    settings.view = view;
    const RenderOutput fast = renderCpu(scene, settings, CpuPath::Fast);
    const RenderOutput teaching = renderCpu(scene, settings, CpuPath::Teaching);
    EXPECT_EQ(fast.rgba, teaching.rgba) << toString(view);
    EXPECT_GT(fast.stats.ssrMilliseconds, 0.0) << toString(view);
    if (view == View::SsrHit) {
      // 0.2, 0.85, 0.2 hit; 0.15, 0.3, 0.9 miss; 0.95, 0.85, 0.1 off screen (8-bit, rounded)
      EXPECT_GT(count(fast, {51, 217, 51}), 300u);
      EXPECT_GT(count(fast, {242, 217, 26}), 300u);
    }
    if (view == View::SsrUv) {
      EXPECT_GT(count(fast, {0, 0, 0}), 300u);  // no hit: black
    }
  }
}

class SsrPaths : public ::testing::TestWithParam<SsrMarch> {};
TEST_P(SsrPaths, FastMatchesTeachingBitForBit) {
  const Scene scene = mirrorFloor();
  for (const GBufferPosition position : {GBufferPosition::Stored, GBufferPosition::Depth}) {
    RenderSettings settings = scene.settings;
    settings.ssr.march = GetParam();
    settings.gbufferPosition = position;
    const RenderOutput teaching = renderCpu(scene, settings, CpuPath::Teaching);
    const RenderOutput fast = renderCpu(scene, settings, CpuPath::Fast);
    EXPECT_EQ(teaching.rgba, fast.rgba) << toString(GetParam()) << ", position " << toString(position);
  }
  // With indirect light: two cosine-weighted samples a pixel.
  RenderSettings indirect = scene.settings;
  indirect.ssr.march = GetParam();
  indirect.ssr.indirectSamples = 2;
  indirect.ssr.sampleDistribution = SampleDistribution::Cosine;
  EXPECT_EQ(renderCpu(scene, indirect, CpuPath::Teaching).rgba, renderCpu(scene, indirect, CpuPath::Fast).rgba)
      << toString(GetParam()) << ", indirect";
}
INSTANTIATE_TEST_SUITE_P(Marches, SsrPaths,
                         ::testing::Values(SsrMarch::LinearWorld, SsrMarch::AdaptiveWorld, SsrMarch::DdaScreen,
                                           SsrMarch::Hiz));

TEST(Ssr, FramesPastTheLaneIndexRangeAreRefused) {
  EXPECT_EQ(ssrSizeProblem(4096, 4096), "");
  EXPECT_NE(ssrSizeProblem(4097, 4096).find("at most 16777216 pixels"), std::string::npos);
}

}  // namespace
}  // namespace twr
