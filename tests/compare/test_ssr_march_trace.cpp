// One pixel's SSR march on both renderers (scene/ssr_trace.h): the CPU's teaching march and
// GL's ssr.frag probe record the same steps, step for step, for pixels all over the mirror
// floor under every march; the probe leaves the frame it ran after untouched.
#include "glrender/gl_renderer.h"
#include "scene/errors.h"
#include "scene/scene_file.h"
#include "softrender/cpu_renderer.h"
#include "softrender/ssr.h"

#include <gtest/gtest.h>

#include <string>

namespace twr {
namespace {

constexpr int kWidth = 160, kHeight = 120;

Scene mirrorFloor() {
  return loadSceneFile(std::string(TWINRASTER_SOURCE_DIR) + "/assets/scenes/ssr_mirror_floor.json");
}

class SsrMarchTraceBoth : public ::testing::TestWithParam<SsrMarch> {};

TEST_P(SsrMarchTraceBoth, GlRecordsTheCpusStepsPixelByPixel) {
  Scene scene = mirrorFloor();
  scene.settings.ssr.march = GetParam();
  std::unique_ptr<Renderer> gl = makeGlRenderer();
  const RenderOutput cpuFrame = makeCpuRenderer()->render(scene, scene.settings, kWidth, kHeight);
  const RenderOutput glFrame = gl->render(scene, scene.settings, kWidth, kHeight);
  int traced = 0, parted = 0, hits = 0, steps = 0;
  for (int y = 3; y < kHeight; y += 13) {  // every trace draws a GL frame: a coarse grid
    for (int x = 2; x < kWidth; x += 13) {
      const SsrMarchTrace cpu = traceSsrMarch(scene, scene.settings, cpuFrame, x, y);
      const SsrMarchTrace glTrace = traceGlSsrMarch(*gl, scene, scene.settings, kWidth, kHeight, x, y);
      ASSERT_EQ(cpu.marched, glTrace.marched) << x << ", " << y;
      if (!cpu.marched) continue;
      ++traced;
      steps += static_cast<int>(cpu.steps.size());
      EXPECT_NEAR(glm::length(cpu.origin - glTrace.origin), 0.0f, 1e-5f) << x << ", " << y;
      if (firstDifferingStep(cpu, glTrace)) {
        ++parted;
        ADD_FAILURE() << "pixel " << x << ", " << y << " parts at step " << *firstDifferingStep(cpu, glTrace) + 1;
      }
      hits += !cpu.steps.empty() && cpu.steps.back().kind == SsrStepKind::Hit;
    }
  }
  EXPECT_GT(traced, 40);
  EXPECT_GT(hits, 2) << "the box and the ball in the floor";
  EXPECT_GT(steps, 2 * traced);
  // The frame drawn with the probe is the frame drawn without it.
  const RenderOutput again = gl->render(scene, scene.settings, kWidth, kHeight);
  EXPECT_EQ(again.rgba, glFrame.rgba);
}

INSTANTIATE_TEST_SUITE_P(Marches, SsrMarchTraceBoth,
                         ::testing::Values(SsrMarch::LinearWorld, SsrMarch::AdaptiveWorld, SsrMarch::DdaScreen,
                                           SsrMarch::Hiz),
                         [](const auto& info) { return std::string(toString(info.param)); });

TEST(SsrMarchTrace, GlRefusesAFrameWithoutReflections) {
  Scene scene = mirrorFloor();
  scene.settings.ssr.enabled = false;
  std::unique_ptr<Renderer> gl = makeGlRenderer();
  EXPECT_THROW(traceGlSsrMarch(*gl, scene, scene.settings, kWidth, kHeight, 10, 10), InputError);
  scene.settings.ssr.enabled = true;
  EXPECT_THROW(traceGlSsrMarch(*gl, scene, scene.settings, kWidth, kHeight, kWidth, 10), InputError);
}

}  // namespace
}  // namespace twr
