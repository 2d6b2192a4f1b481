// Screen-space reflections on the CPU (softrender/ssr.h): the march's four outcomes against a
// depth buffer made here, where every answer is known; the pass on a scene: off changes
// nothing, on reflects, the teaching and fast paths give the same bits (the suite compares the
// renderers, tests/compare/test_scene_suite.cpp).
#include "softrender/ssr.h"

#include "scene/camera.h"
#include "scene/scene_file.h"
#include "softrender/cpu_renderer.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <string>
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
    depth.assign(kSide * kSide, ssrDistanceOfDepthLanes<float>(u, 0.5f * (clip.z / clip.w) + 0.5f));
    plane.assign(kSide * kSide, 0.0f);
    u.surfaceDistance = depth.data();
    for (auto& c : u.colour) c = plane.data();
  }
};

template <typename L>
SsrMarchL<L> marchFrom(const SsrUniformsT<ScalarOf<L>>& u, vec3 origin, vec3 dir) {
  return ssrMarchLanes<L>(u, Vec3L<L>(origin), Vec3L<L>(glm::normalize(dir)), MaskOf<L>(true));
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
  EXPECT_NEAR(double(ssrBufferDistanceLanes<L>(u, L(S(0)))), kWall, 1e-3);
  // Straight at the wall from 1 in front of it: twenty steps of 0.05 (one more as the sums
  // round), a hit at the screen's middle.
  const SsrMarchL<L> hit = marchFrom<L>(u, vec3(0.0f, 0.0f, -9.0f), vec3(0.0f, 0.0f, -1.0f));
  EXPECT_EQ(hit.result, ssrResultLane<L>(SsrResult::Hit));
  EXPECT_GE(hit.steps, L(S(20)));
  EXPECT_LE(hit.steps, L(S(21)));
  EXPECT_EQ(hit.hitIndex, L(S((kSide / 2 - 1) * kSide + kSide / 2)));  // pixel (4, 4), rows from the top
  // Towards the eye, off the centre: out of the frustum's side before it reaches the eye.
  EXPECT_EQ(marchFrom<L>(u, vec3(0.1f, 0.0f, -1.5f), vec3(0.0f, 0.0f, 1.0f)).result,
            ssrResultLane<L>(SsrResult::OffScreen));
  // Sideways out of the frustum.
  EXPECT_EQ(marchFrom<L>(u, vec3(4.5f, 0.0f, -5.0f), vec3(1.0f, 0.0f, 0.0f)).result,
            ssrResultLane<L>(SsrResult::OffScreen));
  // Steps of 3 jump from 2 in front of the wall to 1 behind it: more than the thickness.
  u.step = S(3);
  EXPECT_EQ(marchFrom<L>(u, vec3(0.0f, 0.0f, -2.0f), vec3(0.0f, 0.0f, -1.0f)).result,
            ssrResultLane<L>(SsrResult::Behind));
  // adaptive_world halves the step at each overshoot down to 3 / 16, then decides: the crossing
  // at 9.875 to 10.0625 is within a thickness of 0.2 on both sides.
  u.march = SsrMarch::AdaptiveWorld;
  u.minStep = S(3) * S(kSsrAdaptiveMinStepRatio);
  u.thickness = S(0.2);
  const SsrMarchL<L> adaptive = marchFrom<L>(u, vec3(0.0f, 0.0f, -2.0f), vec3(0.0f, 0.0f, -1.0f));
  EXPECT_EQ(adaptive.result, ssrResultLane<L>(SsrResult::Hit));
  EXPECT_EQ(adaptive.steps, L(S(9)));
  // Out of steps before anything: a miss.
  u.march = SsrMarch::LinearWorld;
  u.step = S(0.05);
  u.thickness = S(0.1);
  u.maxSteps = 2;
  EXPECT_EQ(marchFrom<L>(u, vec3(0.0f, 0.0f, -5.0f), vec3(0.0f, 0.0f, -1.0f)).result,
            ssrResultLane<L>(SsrResult::Miss));
  // A lane not marched stays so.
  EXPECT_EQ(ssrMarchLanes<L>(u, Vec3L<L>(L(S(0))), Vec3L<L>(L(S(0)), L(S(0)), L(S(-1))), MaskOf<L>(false)).result,
            ssrResultLane<L>(SsrResult::NotMarched));
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
  const SsrMarchL<float> back =
      ssrPixelLanes<float>(view.u, vec3(0.0f, 0.0f, 1.0f), vec3(0.0f, 0.0f, -9.5f), 0.8f, true, colour);
  EXPECT_EQ(back.result, ssrResultLane<float>(SsrResult::OffScreen));
  EXPECT_EQ(colour, vec3(0.25f, 0.0f, 0.0f));
  // Tilted up (normal (0, 1, 0.2)): the ray r = 2 (n.wo) n - wo goes on to the wall, rising 0.2
  // by then: pixel (4, 4).
  const SsrMarchL<float> toWall = ssrPixelLanes<float>(view.u, glm::normalize(vec3(0.0f, 1.0f, 0.2f)),
                                                       vec3(0.0f, 0.0f, -9.5f), 0.8f, true, colour);
  EXPECT_EQ(toWall.result, ssrResultLane<float>(SsrResult::Hit));
  EXPECT_FLOAT_EQ(colour.r, 0.25f + 0.5f * (0.5f * 0.8f));
  EXPECT_EQ(colour.g, 0.0f);
  // ssr_reflect 0: not marched, the colour kept.
  vec3 kept(0.3f);
  EXPECT_EQ(ssrPixelLanes<float>(view.u, vec3(0.0f, 0.0f, -1.0f), vec3(0.0f, 0.0f, -5.0f), 0.0f, true, kept).result,
            ssrResultLane<float>(SsrResult::NotMarched));
  EXPECT_EQ(kept, vec3(0.3f));
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
}
INSTANTIATE_TEST_SUITE_P(Marches, SsrPaths, ::testing::Values(SsrMarch::LinearWorld, SsrMarch::AdaptiveWorld));

TEST(Ssr, FramesPastTheLaneIndexRangeAreRefused) {
  EXPECT_EQ(ssrSizeProblem(4096, 4096), "");
  EXPECT_NE(ssrSizeProblem(4097, 4096).find("at most 16777216 pixels"), std::string::npos);
}

}  // namespace
}  // namespace twr
