// One pixel's SSR march on both renderers (scene/ssr_trace.h): the CPU's teaching march and
// GL's ssr.frag probe send the same ray, to the last bit, and record the same steps, step for
// step, for pixels all over the mirror floor under every march and for the cave's indirect
// samples; the probe leaves the frame it ran after untouched.
#include "glrender/gl_renderer.h"
#include "scene/errors.h"
#include "scene/scene_file.h"
#include "softrender/cpu_renderer.h"
#include "softrender/ssr.h"

#include <gtest/gtest.h>

#include <optional>
#include <string>
#include <utility>

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
      // Bit for bit: GLSL's dot() summed in llvmpipe's own order once put these an ulp apart.
      EXPECT_EQ(cpu.direction, glTrace.direction) << x << ", " << y;
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

// Indirect light's rays: every sample of pixels over the cave (4 cosine-weighted samples, hiz;
// and adaptive_world, whose halving decisions part on the smallest difference), the same
// direction, weight and steps on both renderers.
TEST(SsrMarchTrace, GlSendsAndMarchesTheCpusIndirectSamples) {
  Scene scene = loadSceneFile(std::string(TWINRASTER_SOURCE_DIR) + "/assets/scenes/ssr_cave.json");
  ASSERT_EQ(scene.settings.ssr.indirectSamples, 4);
  std::unique_ptr<Renderer> gl = makeGlRenderer();
  for (const SsrMarch march : {SsrMarch::Hiz, SsrMarch::AdaptiveWorld}) {
    scene.settings.ssr.march = march;
    const RenderOutput cpuFrame = makeCpuRenderer()->render(scene, scene.settings, kWidth, kHeight);
    int traced = 0, hits = 0;
    for (int y = 5; y < kHeight; y += 41) {  // every trace draws a GL frame: nine pixels
      for (int x = 7; x < kWidth; x += 53) {
        for (int k = 0; k < 4; ++k) {
          const SsrMarchTrace cpu = traceSsrMarch(scene, scene.settings, cpuFrame, x, y, k);
          const SsrMarchTrace glTrace = traceGlSsrMarch(*gl, scene, scene.settings, kWidth, kHeight, x, y, k);
          ASSERT_EQ(cpu.marched, glTrace.marched) << x << ", " << y;
          if (!cpu.marched) continue;
          ++traced;
          EXPECT_EQ(cpu.ray, k);
          EXPECT_EQ(glTrace.ray, k);
          EXPECT_EQ(cpu.direction, glTrace.direction) << x << ", " << y << " sample " << k;
          EXPECT_EQ(cpu.weight, 1.0f) << "cosine-weighted";
          EXPECT_EQ(glTrace.weight, 1.0f);
          EXPECT_GT(dot(cpu.direction, vec3(cpuFrame.gbuffer->normal[static_cast<std::size_t>(y) * kWidth +
                                                                    static_cast<std::size_t>(x)])),
                    0.0f)
              << "over the normal's hemisphere";
          const std::optional<std::size_t> parted = firstDifferingStep(cpu, glTrace);
          EXPECT_FALSE(parted) << x << ", " << y << " sample " << k << " parts at step " << parted.value_or(0) + 1;
          hits += !cpu.steps.empty() && cpu.steps.back().kind == SsrStepKind::Hit;
        }
      }
    }
    EXPECT_GT(traced, 24) << toString(march);
    EXPECT_GT(hits, 6) << toString(march) << ": the samples find the walls";
  }
  // A sample the settings do not have.
  const RenderOutput frame = makeCpuRenderer()->render(scene, scene.settings, kWidth, kHeight);
  EXPECT_THROW(traceSsrMarch(scene, scene.settings, frame, 80, 60, 4), InputError);
  EXPECT_THROW(traceGlSsrMarch(*gl, scene, scene.settings, kWidth, kHeight, 80, 60, 4), InputError);
  EXPECT_THROW(traceSsrMarch(scene, scene.settings, frame, 80, 60, -2), InputError);
}

// Uniform samples weigh 2 cos: each renderer's weight and direction, bit for bit (the cave's
// cosine-weighted samples all weigh 1, the trace's default).
TEST(SsrMarchTrace, GlWeighsUniformSamplesAsTheCpu) {
  Scene scene = mirrorFloor();
  scene.settings.ssr.march = SsrMarch::Hiz;
  scene.settings.ssr.indirectSamples = 4;
  scene.settings.ssr.sampleDistribution = SampleDistribution::Uniform;
  std::unique_ptr<Renderer> gl = makeGlRenderer();
  const RenderOutput cpuFrame = makeCpuRenderer()->render(scene, scene.settings, kWidth, kHeight);
  int weighed = 0, notOne = 0;
  for (const auto& [x, y] : {std::pair{80, 100}, std::pair{30, 110}, std::pair{130, 90}}) {
    for (int k = 0; k < 4; ++k) {
      const SsrMarchTrace cpu = traceSsrMarch(scene, scene.settings, cpuFrame, x, y, k);
      const SsrMarchTrace glTrace = traceGlSsrMarch(*gl, scene, scene.settings, kWidth, kHeight, x, y, k);
      ASSERT_TRUE(cpu.marched && glTrace.marched) << x << ", " << y << ": a floor pixel";
      EXPECT_EQ(cpu.weight, glTrace.weight) << x << ", " << y << " sample " << k;
      EXPECT_EQ(cpu.direction, glTrace.direction) << x << ", " << y << " sample " << k;
      EXPECT_NEAR(cpu.weight, 2.0f * cpu.direction.y, 1e-6f) << "2 cos about the floor's normal, +y";
      EXPECT_FALSE(firstDifferingStep(cpu, glTrace)) << x << ", " << y << " sample " << k;
      ++weighed;
      notOne += cpu.weight != 1.0f;
    }
  }
  EXPECT_EQ(weighed, 12);
  EXPECT_GT(notOne, 8);
}

// An SSR view draws the mirror ray's march only: no indirect sample to trace.
TEST(SsrMarchTrace, AViewTracesTheMirrorRayOnly) {
  Scene scene = loadSceneFile(std::string(TWINRASTER_SOURCE_DIR) + "/assets/scenes/ssr_cave.json");
  scene.settings.view = View::SsrHit;
  const RenderOutput frame = makeCpuRenderer()->render(scene, scene.settings, kWidth, kHeight);
  EXPECT_NO_THROW(traceSsrMarch(scene, scene.settings, frame, 80, 60, kSsrMirrorRay));
  EXPECT_THROW(traceSsrMarch(scene, scene.settings, frame, 80, 60, 0), InputError);
}

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
