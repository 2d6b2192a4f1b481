// The decision class (compare/decisions.h): a differing pixel of the same surface whose
// decision views differ is "decision", every other one keeps its class; on hand-made outputs
// and on a real shadow map whose compare is moved by a hair on one side.
#include "compare/decisions.h"

#include "compare/colours.h"
#include "compare/heatmap.h"
#include "compare/metrics.h"
#include "compare/report_json.h"
#include "compare/synthetic_outputs.h"
#include "glrender/gl_renderer.h"
#include "scene/errors.h"
#include "scene/scene_file.h"
#include "softrender/cpu_renderer.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <string>

namespace twr {
namespace {

using testing::makeSolidOutput;
using testing::rgbaAt;

DecisionViews oneView(const RenderOutput& view) {
  DecisionViews d;
  d.width = view.width;
  d.height = view.height;
  d.views = {View::Shadow};
  d.outputs = {view};
  return d;
}

TEST(Decisions, AShadingPixelWhoseDecisionViewDiffersIsADecision) {
  // Three pixels differ by 5 levels on the same surface; the shadow view differs at the first
  // (a flipped tap: 20 levels), by one level at the second (rounding, not a decision), not at all
  // at the third.
  const RenderOutput cpu = makeSolidOutput(3, 1, 100, 100, 100);
  const RenderOutput gl = makeSolidOutput(3, 1, 105, 100, 100);
  RenderOutput cpuView = makeSolidOutput(3, 1, 50, 50, 50), glView = cpuView;
  rgbaAt(glView, 0, 0)[1] = 70;
  rgbaAt(glView, 1, 0)[2] = 51;
  CompareResult result = compareDetailed(cpu, gl);
  ASSERT_EQ(result.metrics.classShading, 3u);
  EXPECT_EQ(classifyDecisions(result, oneView(cpuView), oneView(glView)), 1u);
  EXPECT_EQ(result.metrics.classDecision, 1u);
  EXPECT_EQ(result.metrics.classShading, 2u);
  EXPECT_EQ(result.pixels.pixelClass[0], PixelClass::Decision);
  EXPECT_EQ(result.pixels.pixelClass[1], PixelClass::Shading);
  EXPECT_EQ(result.pixels.pixelClass[2], PixelClass::Shading);
  EXPECT_EQ(metricsToJson(result.metrics)["class_decision"], 1);
  EXPECT_EQ(toString(PixelClass::Decision), "decision");
  // classes.png gives it its own colour.
  const Image classes = makeClassMap(result.pixels, ClassMapOptions{false});
  const std::uint8_t* p = classes.pixel(0, 0);
  EXPECT_EQ((Rgb8{p[0], p[1], p[2]}), kColourDecision);
  EXPECT_NE(kColourDecision, kColourShading);
}

TEST(Decisions, OnlyShadingPixelsMove) {
  // A pixel one side covers alone stays coverage, a pixel of another surface stays depth, even
  // where the decision views differ.
  RenderOutput cpu = makeSolidOutput(2, 1, 100, 100, 100);
  RenderOutput gl = makeSolidOutput(2, 1, 120, 100, 100);
  testing::clearPixel(gl, 0, 0);
  gl.triangleId[1] = 7;
  RenderOutput cpuView = makeSolidOutput(2, 1, 0, 0, 0), glView = makeSolidOutput(2, 1, 200, 200, 200);
  CompareResult result = compareDetailed(cpu, gl);
  EXPECT_EQ(classifyDecisions(result, oneView(cpuView), oneView(glView)), 0u);
  EXPECT_EQ(result.pixels.pixelClass[0], PixelClass::CoverageCpu);
  EXPECT_EQ(result.pixels.pixelClass[1], PixelClass::Depth);
}

TEST(Decisions, ViewsOfAnotherSizeAreRefused) {
  const RenderOutput frame = makeSolidOutput(2, 2, 0, 0, 0);
  CompareResult result = compareDetailed(frame, frame);
  const RenderOutput small = makeSolidOutput(1, 1, 0, 0, 0);
  EXPECT_THROW(classifyDecisions(result, oneView(small), oneView(small)), InputError);
  // A view without its image, or an image of another size, is refused before any pixel is read.
  DecisionViews missing = oneView(frame);
  missing.outputs.clear();
  EXPECT_THROW(classifyDecisions(result, oneView(frame), missing), InputError);
  DecisionViews shrunk = oneView(frame);
  shrunk.outputs[0] = small;
  EXPECT_THROW(classifyDecisions(result, oneView(frame), shrunk), InputError);
  EXPECT_THROW(decisionDiffersAt(oneView(frame), oneView(frame), 4), InputError);
}

TEST(Decisions, TheViewsFollowWhatTheSceneTurnsOn) {
  const std::string dir = std::string(TWINRASTER_SOURCE_DIR) + "/assets/scenes/";
  const Scene shadowed = loadSceneFile(dir + "shadow_directional.json");
  EXPECT_EQ(decisionViewsFor(shadowed, shadowed.settings), std::vector<View>{View::Shadow});
  const Scene reflecting = loadSceneFile(dir + "ssr_mirror_floor.json");
  EXPECT_EQ(decisionViewsFor(reflecting, reflecting.settings), (std::vector<View>{View::Shadow, View::SsrHit}));
  const Scene steep = loadSceneFile(dir + "height_steep_parallax.json");
  const std::vector<View> steepViews = decisionViewsFor(steep, steep.settings);
  EXPECT_NE(std::find(steepViews.begin(), steepViews.end(), View::ParallaxSteps), steepViews.end());
  RenderSettings trilinear = steep.settings;
  trilinear.textureFilter = TextureFilter::Trilinear;
  const std::vector<View> mip = decisionViewsFor(steep, trilinear);
  EXPECT_NE(std::find(mip.begin(), mip.end(), View::MipLevel), mip.end());
  const Scene plain = loadSceneFile(dir + "default.json");
  RenderSettings bilinear = plain.settings;
  bilinear.textureFilter = TextureFilter::Bilinear;
  EXPECT_TRUE(decisionViewsFor(plain, bilinear).empty());
  // A debug view's frame shows one quantity already: nothing to draw beside it.
  RenderSettings view = shadowed.settings;
  view.view = View::Normal;
  EXPECT_TRUE(decisionViewsFor(shadowed, view).empty());
}

// A directional light's map with no bias: acne everywhere, the same on both renderers. Moving
// GL's compare by 1e-6 world units (a deliberately rounded compare on one side) flips taps
// where a fragment's depth sits that close to the map's: those pixels are decisions, and the
// same frames drawn alike have none.
TEST(Decisions, AFlippedShadowTapIsCountedAsADecision) {
  Scene cpuScene = loadSceneFile(std::string(TWINRASTER_SOURCE_DIR) + "/assets/scenes/shadow_directional.json");
  ASSERT_TRUE(cpuScene.lights[0].shadow);
  cpuScene.lights[0].shadow->bias = vec2(0.0f);
  cpuScene.lights[0].shadow->pcf = 3;
  Scene glScene = cpuScene;
  glScene.lights[0].shadow->bias = vec2(1e-6f, 0.0f);
  const int width = 320, height = 240;
  auto cpu = makeCpuRenderer();
  auto gl = makeGlRenderer();
  const std::vector<View> views = decisionViewsFor(cpuScene, cpuScene.settings);
  ASSERT_EQ(views, std::vector<View>{View::Shadow});

  CompareResult moved = compareDetailed(cpu->render(cpuScene, cpuScene.settings, width, height),
                                        gl->render(glScene, glScene.settings, width, height));
  const std::uint64_t differing = moved.metrics.classShading;
  ASSERT_GT(differing, 0u) << "the moved compare changed no pixel: the test would prove nothing";
  const std::uint64_t decisions =
      classifyDecisions(moved, renderDecisionViews(*cpu, cpuScene, cpuScene.settings, views, width, height),
                        renderDecisionViews(*gl, glScene, glScene.settings, views, width, height));
  EXPECT_GT(decisions, 0u);
  EXPECT_EQ(moved.metrics.classDecision + moved.metrics.classShading, differing);
  EXPECT_EQ(moved.metrics.classDepth, 0u);
  EXPECT_EQ(moved.metrics.classCoverage, 0u);
  // Most of what moved is the flipped taps, not colour.
  EXPECT_GE(static_cast<double>(decisions), 0.9 * static_cast<double>(differing));

  // The same scene on both sides: every tap decided on the same bits.
  CompareResult same = compareDetailed(cpu->render(cpuScene, cpuScene.settings, width, height),
                                       gl->render(cpuScene, cpuScene.settings, width, height));
  classifyDecisions(same, renderDecisionViews(*cpu, cpuScene, cpuScene.settings, views, width, height),
                    renderDecisionViews(*gl, cpuScene, cpuScene.settings, views, width, height));
  EXPECT_EQ(same.metrics.classDecision, 0u);
  EXPECT_EQ(same.metrics.over1, 0u);
}

}  // namespace
}  // namespace twr
