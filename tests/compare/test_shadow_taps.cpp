// One pixel's shadow test tap by tap on both renderers (scene/shadow_trace.h): the CPU's from
// its pixel trace, GL's from phong.frag's SHADOW_PROBE. At bias 0, where every tap sits on a
// knife edge, both take every tap on the same bits; a compare moved by a hair on one side shows
// up as a first differing tap.
#include "glrender/gl_renderer.h"
#include "scene/scene_file.h"
#include "scene/shadow_trace.h"
#include "softrender/cpu_renderer.h"
#include "softrender/pixel_trace.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <string>

namespace twr {
namespace {

Scene shadowScene(const char* file, float biasConstant, int pcf) {
  Scene scene = loadSceneFile(std::string(TWINRASTER_SOURCE_DIR) + "/assets/scenes/" + file);
  for (Light& light : scene.lights) {
    if (!light.shadow) continue;
    light.shadow->bias = vec2(biasConstant, 0.0f);
    light.shadow->pcf = pcf;
  }
  return scene;
}

void expectSameTaps(const ShadowTapTrace& cpu, const ShadowTapTrace& gl, const std::string& where) {
  SCOPED_TRACE(where);
  ASSERT_EQ(cpu.tested, gl.tested);
  if (!cpu.tested) return;
  EXPECT_EQ(cpu.inside, gl.inside);
  EXPECT_EQ(cpu.texel, gl.texel);
  EXPECT_EQ(cpu.depth, gl.depth);
  EXPECT_EQ(cpu.bias, gl.bias);
  EXPECT_EQ(cpu.reference, gl.reference);
  EXPECT_EQ(cpu.visibility, gl.visibility);
  EXPECT_EQ(cpu.stored, gl.stored);
  EXPECT_TRUE(tapsMatchTest(cpu));  // the taps read from the map say what the test said
  EXPECT_TRUE(tapsMatchTest(gl));
  EXPECT_TRUE(testsPartBeforeTaps("cpu", cpu, "gl", gl).empty());
  ASSERT_EQ(cpu.taps.size(), gl.taps.size());
  EXPECT_FALSE(firstDifferingTap(cpu, gl).has_value());
}

// Pixels on the floor, the cube and the sphere of each scene, inside and at the map's edges.
TEST(ShadowTaps, BothRenderersTakeEveryTapOnTheSameBits) {
  const int width = 160, height = 120;
  struct Case {
    const char* scene;
    int pcf;
  };
  for (const Case c : {Case{"shadow_directional.json", 3}, Case{"shadow_directional.json", 5},
                       Case{"shadow_point_cube.json", 3}, Case{"shadow_spot.json", 1}}) {
    const Scene scene = shadowScene(c.scene, 0.0f, c.pcf);
    auto gl = makeGlRenderer();
    int testedInside = 0;
    for (const auto& [x, y] : {std::pair{80, 90}, std::pair{80, 60}, std::pair{40, 100}, std::pair{120, 70},
                               std::pair{10, 115}, std::pair{150, 20}}) {
      const PixelTrace trace = tracePixel(scene, scene.settings, width, height, x, y);
      const std::vector<ShadowTapTrace> cpu = shadowTapTracesOf(trace, scene);
      const std::vector<ShadowTapTrace> glTaps = traceGlShadowTaps(*gl, scene, scene.settings, width, height, x, y);
      ASSERT_EQ(cpu.size(), glTaps.size());
      for (std::size_t i = 0; i < cpu.size(); ++i) {
        EXPECT_EQ(cpu[i].light, glTaps[i].light);
        EXPECT_EQ(cpu[i].taps.size(), cpu[i].inside ? static_cast<std::size_t>(c.pcf * c.pcf) : 0u);
        expectSameTaps(cpu[i], glTaps[i], std::string(c.scene) + " at " + std::to_string(x) + ", " + std::to_string(y));
        testedInside += cpu[i].tested && cpu[i].inside;
      }
    }
    EXPECT_GE(testedInside, 3) << c.scene << ": too few pixels inside a map, the test would prove little";
  }
}

// GL's constant bias moved by 1e-6 world units: on the acne-covered floor some taps flip. The
// frames find such a pixel; its traces name the tap.
TEST(ShadowTaps, AMovedCompareShowsAsTheFirstDifferingTap) {
  const int width = 320, height = 240;
  const Scene cpuScene = shadowScene("shadow_directional.json", 0.0f, 3);
  const Scene glScene = shadowScene("shadow_directional.json", 1e-6f, 3);
  auto gl = makeGlRenderer();
  const RenderOutput cpuFrame = makeCpuRenderer()->render(cpuScene, cpuScene.settings, width, height);
  const RenderOutput glFrame = gl->render(glScene, glScene.settings, width, height);
  int x = -1, y = -1;
  for (std::size_t i = 0; i < cpuFrame.rgba.size() / 4 && x < 0; ++i) {
    for (std::size_t c = 0; c < 3; ++c) {
      if (std::abs(int(cpuFrame.rgba[i * 4 + c]) - int(glFrame.rgba[i * 4 + c])) <= 1) continue;
      x = static_cast<int>(i % width);
      y = static_cast<int>(i / width);
      break;
    }
  }
  ASSERT_GE(x, 0) << "the moved compare changed no pixel: the test would prove nothing";
  const std::vector<ShadowTapTrace> cpu = shadowTapTracesOf(tracePixel(cpuScene, cpuScene.settings, width, height, x, y), cpuScene);
  const std::vector<ShadowTapTrace> glTaps = traceGlShadowTaps(*gl, glScene, glScene.settings, width, height, x, y);
  ASSERT_EQ(cpu.size(), 1u);
  ASSERT_EQ(glTaps.size(), 1u);
  ASSERT_TRUE(cpu[0].tested && cpu[0].inside);
  EXPECT_NE(cpu[0].reference, glTaps[0].reference);  // the moved compare, seen in the bits
  const std::optional<std::size_t> k = firstDifferingTap(cpu[0], glTaps[0]);
  ASSERT_TRUE(k.has_value()) << "pixel " << x << ", " << y << " differs but no tap does";
  EXPECT_NE(cpu[0].taps[*k].lit, glTaps[0].taps[*k].lit);
  EXPECT_EQ(cpu[0].taps[*k].stored, glTaps[0].taps[*k].stored);  // the same map, another outcome
  const std::string text = formatShadowTapTraces("cpu", cpu[0], "gl", &glTaps[0]);
  EXPECT_NE(text.find("first tap where they part: " + std::to_string(*k + 1)), std::string::npos) << text;
}

}  // namespace
}  // namespace twr
