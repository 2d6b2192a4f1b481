// The debug-view helpers a student reads the views with (issue 20, "what a student
// misses"): empty pixels are not decoded as vectors, depth linearises to the eye distance,
// every view has a legend; and the scene picker's lists.
#include "gui/debug_views.h"
#include "gui/scene_picker.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>

namespace twr::gui {
namespace {

TEST(DebugViews, EmptyPixelsAreNotDecodedAsVectors) {
  PixelSample background;
  background.rgba = {13, 13, 20, 0};  // the background colour, alpha 0: nothing drawn
  const std::string text = describeViewSample(View::Normal, background);
  EXPECT_NE(text.find("empty"), std::string::npos) << text;
  EXPECT_EQ(text.find("-0.9"), std::string::npos) << text;
}

// The parallax_steps legend: the shaders' heat(t), blue 0 -> cyan -> green -> yellow -> red.
TEST(DebugViews, ParallaxStepsRampIsTheShadersHeat) {
  const auto near = [](vec3 a, vec3 b) { return glm::all(glm::lessThanEqual(glm::abs(a - b), vec3(1e-6f))); };
  EXPECT_TRUE(near(parallaxStepsColour(0.0f), vec3(0.0f, 0.0f, 0.5f)));
  EXPECT_TRUE(near(parallaxStepsColour(0.25f), vec3(0.0f, 0.5f, 1.0f)));   // cyan-ish
  EXPECT_TRUE(near(parallaxStepsColour(0.5f), vec3(0.5f, 1.0f, 0.5f)));    // green
  EXPECT_TRUE(near(parallaxStepsColour(0.75f), vec3(1.0f, 0.5f, 0.0f)));   // yellow-orange
  EXPECT_TRUE(near(parallaxStepsColour(1.0f), vec3(0.5f, 0.0f, 0.0f)));    // red
  EXPECT_TRUE(near(parallaxStepsColour(-3.0f), parallaxStepsColour(0.0f))) << "clamped";
  EXPECT_TRUE(near(parallaxStepsColour(7.0f), parallaxStepsColour(1.0f)));
  EXPECT_TRUE(near(parallaxStepsColour(std::numeric_limits<float>::quiet_NaN()), parallaxStepsColour(0.0f)));
  Material m;
  m.parallaxLayers = {8, 32};
  m.reliefRefinementSteps = 5;
  m.surfaceDetail = SurfaceDetail::ParallaxOcclusion;
  EXPECT_EQ(parallaxStepsMost(m), 32);
  m.surfaceDetail = SurfaceDetail::Relief;
  EXPECT_EQ(parallaxStepsMost(m), 37) << "relief's refinement steps count too";
}

TEST(DebugViews, DrawnPixelsDecodeAsTheirView) {
  PixelSample up;
  up.rgba = {128, 255, 128, 255};
  up.drawn = true;
  EXPECT_EQ(describeViewSample(View::Normal, up), "vector 0.00 1.00 0.00");
  PixelSample uv;
  uv.rgba = {255, 0, 0, 255};
  uv.drawn = true;
  EXPECT_EQ(describeViewSample(View::Uv, uv), "uv 1.000 0.000 (fractional part)");
  PixelSample depth;
  depth.rgba = {250, 250, 250, 255};
  depth.depth = 0.98f;
  depth.drawn = true;
  EXPECT_EQ(describeViewSample(View::Depth, depth), "depth 0.9800000");
}

TEST(DebugViews, ASampleIsDrawnByItsTriangleIdNotItsAlpha) {
  RenderOutput output;
  output.width = 3;
  output.height = 1;
  // An opaque background (alpha 255) at x = 0, a triangle at x = 1, a TBN line at x = 2.
  output.rgba = {13, 13, 20, 255, 128, 255, 128, 255, 255, 0, 0, 255};
  output.depth = {1.0f, 0.5f, 0.4f};
  output.triangleId = {kNoTriangle, 7, kNoTriangle};
  output.lineMask = {0, 0, 1};
  const PixelSample background = sampleAt(output, {0, 0});
  EXPECT_FALSE(background.drawn);
  EXPECT_EQ(background.rgba[3], 255);
  EXPECT_NE(describeViewSample(View::Normal, background).find("empty"), std::string::npos);
  const PixelSample surface = sampleAt(output, {1, 0});
  EXPECT_TRUE(surface.drawn);
  EXPECT_EQ(surface.depth, 0.5f);
  EXPECT_EQ(describeViewSample(View::Normal, surface), "vector 0.00 1.00 0.00");
  EXPECT_TRUE(sampleAt(output, {2, 0}).drawn);
}

TEST(DebugViews, EveryViewHasALegend) {
  for (View view : kAllViews) EXPECT_GT(std::string(viewLegend(view)).size(), 20u) << toString(view);
}

TEST(DebugViews, LinearDepthMapsNearToZeroAndFarToOne) {
  const float near = 0.1f, far = 50.0f;
  EXPECT_NEAR(linearDepth(0.0f, near, far), 0.0f, 1e-6f);
  EXPECT_NEAR(linearDepth(1.0f, near, far), 1.0f, 1e-6f);
  // A point halfway between near and far in eye distance sits at window depth ~0.999 and
  // comes back to about 0.5.
  const float zEye = 0.5f * (near + far);
  const double zNdc = ((far + near) - 2.0 * far * near / zEye) / (far - near);
  const float d = static_cast<float>(0.5 * zNdc + 0.5);
  EXPECT_GT(d, 0.99f);
  EXPECT_NEAR(linearDepth(d, near, far), 0.5f, 1e-3f);
}

TEST(DebugViews, LinearDepthGuardsItsInputs) {
  EXPECT_EQ(linearDepth(std::numeric_limits<float>::quiet_NaN(), 0.1f, 10.0f), 1.0f);
  EXPECT_EQ(linearDepth(2.0f, 0.1f, 10.0f), 1.0f);
  EXPECT_EQ(linearDepth(0.25f, 0.0f, 10.0f), 0.25f);  // no valid camera: unchanged
}

TEST(DebugViews, EyeDistanceInvertsTheProjection) {
  EXPECT_NEAR(eyeDistance(0.0f, 0.1f, 50.0f), 0.1f, 1e-6f);
  EXPECT_NEAR(eyeDistance(1.0f, 0.1f, 50.0f), 50.0f, 1e-4f);
}

TEST(DebugViews, LinearDepthSpansTheDrawnRangeAndKeepsEmptyPixels) {
  const float near = 0.1f, far = 50.0f;
  // Window depth of eye distances 2 and 6: both above 0.95, nearly the same grey raw.
  const auto windowDepth = [&](float zEye) {
    return static_cast<float>(0.5 * (((far + near) - 2.0 * far * near / zEye) / (far - near)) + 0.5);
  };
  RenderOutput output;
  output.width = 3;
  output.height = 1;
  output.rgba = {9, 9, 9, 0, 255, 255, 255, 255, 255, 255, 255, 255};
  output.depth = {1.0f, windowDepth(2.0f), windowDepth(6.0f)};
  const EyeRange range = drawnEyeRange({&output, nullptr}, near, far);
  ASSERT_FALSE(range.empty());
  EXPECT_NEAR(range.nearest, 2.0f, 1e-2f);
  EXPECT_NEAR(range.farthest, 6.0f, 1e-2f);
  const RenderOutput linear = withLinearDepth(output, near, far, range);
  EXPECT_EQ(linear.rgba[0], 9);  // nothing drawn: untouched
  EXPECT_EQ(linear.rgba[3], 0);
  EXPECT_EQ(linear.rgba[4], 0);  // the nearest drawn pixel: black
  EXPECT_EQ(linear.rgba[8], 255);  // the farthest: white
  EXPECT_EQ(linear.rgba[7], 255);
}

TEST(DebugViews, LinearDepthSkipsTheOpaqueBackgroundByTriangleId) {
  RenderOutput output;
  output.width = 2;
  output.height = 1;
  output.rgba = {9, 9, 9, 255, 255, 255, 255, 255};  // the background is opaque: alpha says nothing
  output.depth = {1.0f, 0.99f};
  output.triangleId = {kNoTriangle, 3};
  const EyeRange range = drawnEyeRange({&output}, 0.1f, 50.0f);
  ASSERT_FALSE(range.empty());
  EXPECT_LT(range.farthest, 50.0f) << "the background's depth 1 must not count";
  const RenderOutput linear = withLinearDepth(output, 0.1f, 50.0f, range);
  EXPECT_EQ(linear.rgba[0], 9);  // nothing drawn: untouched
  EXPECT_EQ(linear.rgba[3], 255);
}

TEST(DebugViews, NoDrawnPixelNoRange) {
  RenderOutput output;
  output.width = 1;
  output.height = 1;
  output.rgba = {0, 0, 0, 0};
  output.depth = {1.0f};
  EXPECT_TRUE(drawnEyeRange({&output}, 0.1f, 10.0f).empty());
}

TEST(ScenePicker, ListsTheJsonFilesSorted) {
  const std::filesystem::path folder = std::filesystem::path(TWINRASTER_TEST_OUT) / "scene_picker";
  std::filesystem::remove_all(folder);
  std::filesystem::create_directories(folder);
  for (const char* name : {"b.json", "a.json", "notes.txt"}) std::ofstream(folder / name) << "{}";
  const auto files = sceneFilesIn(folder);
  ASSERT_EQ(files.size(), 2u);
  EXPECT_EQ(files[0].filename(), "a.json");
  EXPECT_EQ(files[1].filename(), "b.json");
  EXPECT_TRUE(sceneFilesIn(folder / "missing").empty());
  EXPECT_GE(sceneFilesIn(std::filesystem::path(TWINRASTER_SOURCE_DIR) / "assets" / "scenes").size(), 10u);
}

TEST(ScenePicker, RecentFilesNewestFirstWithoutDuplicates) {
  std::vector<std::string> recent;
  rememberRecent(recent, "a.json", 3);
  rememberRecent(recent, "b.json", 3);
  rememberRecent(recent, "a.json", 3);
  EXPECT_EQ(recent, (std::vector<std::string>{"a.json", "b.json"}));
  rememberRecent(recent, "c.json", 3);
  rememberRecent(recent, "d.json", 3);
  EXPECT_EQ(recent, (std::vector<std::string>{"d.json", "c.json", "a.json"}));
}

}  // namespace
}  // namespace twr::gui
