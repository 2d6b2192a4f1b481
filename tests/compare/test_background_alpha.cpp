// The background's alpha (issue 15, item 5): both backends write it where nothing is drawn,
// nothing else moves, and compare() takes coverage from the triangle ids, so its metrics are
// exactly those of the old rule (alpha > 0 with the background cleared to alpha 0).
#include "compare/metrics.h"
#include "compare/side_by_side.h"
#include "glrender/gl_renderer.h"
#include "scene/scene_file.h"
#include "softrender/cpu_renderer.h"
#include "softrender/framebuffer.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <utility>

namespace twr {
namespace {

const std::string kScenes = std::string(TWINRASTER_SOURCE_DIR) + "/assets/scenes/";
constexpr int kWidth = 160, kHeight = 120;  // pixels
constexpr float kAlphas[] = {1.0f, 0.0f, 0.5f};

// One GL renderer for the whole process, never destroyed (see test_stability.cpp: Mesa's exit
// handlers run before static destructors would).
Renderer& glRenderer() {
  static Renderer* const renderer = makeGlRenderer().release();
  return *renderer;
}

Renderer& cpuRenderer() {
  static Renderer* const renderer = makeCpuRenderer().release();
  return *renderer;
}

// The metrics' coverage counts under the rule compare() used before alpha existed: alpha > 0,
// line pixels excluded. Only meaningful on renders whose background alpha is 0.
struct AlphaCoverage {
  std::uint64_t cpu = 0, gl = 0, both = 0;
};
AlphaCoverage coverageByAlpha(const RenderOutput& cpu, const RenderOutput& gl) {
  AlphaCoverage c;
  for (std::size_t i = 0; i < cpu.depth.size(); ++i) {
    if (cpu.lineMask[i] != 0 || gl.lineMask[i] != 0) continue;
    const bool a = cpu.rgba[i * 4 + 3] > 0, b = gl.rgba[i * 4 + 3] > 0;
    c.cpu += a;
    c.gl += b;
    c.both += a && b;
  }
  return c;
}

void expectSameMetrics(const CompareMetrics& a, const CompareMetrics& b) {
  EXPECT_EQ(a.comparedPixels, b.comparedPixels);
  EXPECT_EQ(a.excludedLinePixels, b.excludedLinePixels);
  EXPECT_EQ(a.coveredCpu, b.coveredCpu);
  EXPECT_EQ(a.coveredGl, b.coveredGl);
  EXPECT_EQ(a.bothCovered, b.bothCovered);
  EXPECT_EQ(a.coverageCpuOnly, b.coverageCpuOnly);
  EXPECT_EQ(a.coverageGlOnly, b.coverageGlOnly);
  EXPECT_EQ(a.maxAbsDiff, b.maxAbsDiff);
  EXPECT_EQ(a.rmse, b.rmse);
  EXPECT_EQ(a.over1, b.over1);
  EXPECT_EQ(a.classDepth, b.classDepth);
  EXPECT_EQ(a.classShading, b.classShading);
}

TEST(BackgroundAlpha, BothBackendsWriteItAndCoverageMetricsStayExact) {
  // Clipping (user_clip) and lines (tbn_lines) are where coverage and exclusion matter most.
  for (const char* name : {"default.json", "user_clip.json", "tbn_lines.json"}) {
    SCOPED_TRACE(name);
    Scene scene = loadSceneFile(kScenes + name);
    ASSERT_EQ(scene.output.background.a, 1.0f) << "a file's [r, g, b] background is opaque";
    RenderOutput cpuOpaque, glOpaque;
    CompareMetrics opaqueMetrics;
    for (const float alpha : kAlphas) {
      SCOPED_TRACE("alpha " + std::to_string(alpha));
      scene.output.background.a = alpha;
      const std::uint8_t byte = clearByte(alpha);
      const RenderOutput cpu = cpuRenderer().render(scene, scene.settings, kWidth, kHeight);
      const RenderOutput gl = glRenderer().render(scene, scene.settings, kWidth, kHeight);
      for (const RenderOutput* out : {&cpu, &gl}) {
        std::size_t empty = 0;
        for (std::size_t i = 0; i < out->depth.size(); ++i) {
          const bool drawn = drawnAt(*out, i);
          empty += drawn ? 0 : 1;
          ASSERT_EQ(out->rgba[i * 4 + 3], drawn ? 255 : byte) << (out == &cpu ? "cpu" : "gl") << " pixel " << i;
        }
        EXPECT_GT(empty, 0u) << "every scene shows some background";
      }
      const CompareMetrics metrics = compare(cpu, gl);
      EXPECT_GT(metrics.bothCovered, 0u);
      if (alpha == 1.0f) {
        cpuOpaque = cpu;
        glOpaque = gl;
        opaqueMetrics = metrics;
        continue;
      }
      // Only the empty pixels' alpha moved: colour, depth, ids and lines are the opaque frame's.
      for (const auto& [out, opaque] : {std::pair{&cpu, &cpuOpaque}, std::pair{&gl, &glOpaque}}) {
        for (std::size_t i = 0; i < out->depth.size(); ++i) {
          for (std::size_t c = 0; c < 3; ++c) ASSERT_EQ(out->rgba[i * 4 + c], opaque->rgba[i * 4 + c]) << i;
        }
        EXPECT_EQ(out->depth, opaque->depth);
        EXPECT_EQ(out->triangleId, opaque->triangleId);
        EXPECT_EQ(out->lineMask, opaque->lineMask);
      }
      expectSameMetrics(metrics, opaqueMetrics);
      if (alpha == 0.0f) {
        const AlphaCoverage old = coverageByAlpha(cpu, gl);
        EXPECT_EQ(metrics.coveredCpu, old.cpu);
        EXPECT_EQ(metrics.coveredGl, old.gl);
        EXPECT_EQ(metrics.bothCovered, old.both);
      }
    }
  }
}

// The background bytes themselves, RGB and alpha, on every rounding tie k + 0.5 (0.3f * 255
// = 76.5 is one) and values between: llvmpipe stores a clear colour rounded to nearest with
// ties to even, and so must the CPU (clearByte), though fragments round ties away from zero.
TEST(BackgroundAlpha, ClearBytesAreLlvmpipesOnEveryTie) {
  Scene scene;  // no nodes: every pixel is background
  std::size_t ties = 0;
  for (int k = 0; k < 256; k += 4) {
    vec4 background;
    for (int c = 0; c < 4; ++c) {
      // Channel c: a tie (k + c + 0.5) / 255 on even k, the value just above it on odd ones.
      const float tie = std::min(1.0f, (static_cast<float>(k + c) + 0.5f) / 255.0f);
      background[c] = (k / 4) % 2 == 0 ? tie : std::nextafter(tie, 2.0f);
      ties += clearByte(background[c]) != unitToByte(background[c]) ? 1 : 0;
    }
    scene.output.background = background;
    const RenderOutput cpu = cpuRenderer().render(scene, scene.settings, 4, 4);
    const RenderOutput gl = glRenderer().render(scene, scene.settings, 4, 4);
    const std::uint32_t word = backgroundWord(background);
    for (std::size_t i = 0; i < cpu.rgba.size(); ++i) {
      ASSERT_EQ(int{cpu.rgba[i]}, int{gl.rgba[i]}) << "k " << k << ", channel " << i % 4 << ": "
                                                   << background[static_cast<int>(i % 4)];
      ASSERT_EQ(cpu.rgba[i], reinterpret_cast<const std::uint8_t*>(&word)[i % 4]);
    }
  }
  EXPECT_GT(ties, 10u) << "the values must include ties the two roundings disagree on";
}

TEST(BackgroundAlpha, CheckerViewFollowsCoverageNotAlpha) {
  Scene scene = loadSceneFile(kScenes + "default.json");
  const RenderOutput opaque = cpuRenderer().render(scene, scene.settings, kWidth, kHeight);
  scene.output.background.a = 0.0f;
  const RenderOutput clear = cpuRenderer().render(scene, scene.settings, kWidth, kHeight);
  // The checker shows the same pixels whatever the background's alpha.
  EXPECT_EQ(viewImage(opaque, BackgroundMode::Checker).rgba, viewImage(clear, BackgroundMode::Checker).rgba);
  EXPECT_EQ(viewImage(opaque, BackgroundMode::RendererColour).rgba,
            viewImage(clear, BackgroundMode::RendererColour).rgba);
  EXPECT_NE(viewImage(opaque, BackgroundMode::Checker).rgba, viewImage(opaque, BackgroundMode::RendererColour).rgba);
}

}  // namespace
}  // namespace twr
