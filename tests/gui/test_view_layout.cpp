// The view area's geometry, the screenshot key's images and the Scene tab's words, without a
// window (gui/view_layout.h, gui/view_screenshot.h, gui/scene_help.h).
#include "gui/scene_help.h"
#include "gui/view_layout.h"
#include "gui/view_screenshot.h"

#include "scene/errors.h"

#include <gtest/gtest.h>

#include <cstring>
#include <string>
#include <vector>

namespace twr::gui {
namespace {

TEST(ViewLayout, FitRectKeepsTheAspectCentredOnWholePoints) {
  const ScreenRect slot{{10.0f, 20.0f}, {410.0f, 220.0f}};  // 400 x 200
  const ScreenRect fitted = fitRect(slot, 640, 480);         // 4:3 in 2:1: the height decides
  EXPECT_FLOAT_EQ(fitted.height(), 200.0f);
  EXPECT_FLOAT_EQ(fitted.width(), 200.0f * 640.0f / 480.0f);
  EXPECT_FLOAT_EQ(fitted.min.y, 20.0f);
  EXPECT_FLOAT_EQ(fitted.min.x, std::floor(10.0f + 0.5f * (400.0f - fitted.width())));
  const ScreenRect empty = fitRect(slot, 0, 480);
  EXPECT_FLOAT_EQ(empty.width(), 0.0f);
  EXPECT_FALSE(empty.contains(slot.min));
}

TEST(ViewLayout, SideBySideHasTwoHalvesAGapApartAndEveryOtherModeOne) {
  const std::vector<ScreenRect> two = slotsFor(ViewMode::SideBySide, {0.0f, 0.0f}, {206.0f, 100.0f}, 6.0f);
  ASSERT_EQ(two.size(), 2u);
  EXPECT_FLOAT_EQ(two[0].width(), 100.0f);
  EXPECT_FLOAT_EQ(two[1].min.x, 106.0f);
  EXPECT_FLOAT_EQ(two[1].max.x, 206.0f);
  for (const ViewMode mode : {ViewMode::Cpu, ViewMode::Gl, ViewMode::Split, ViewMode::Diff, ViewMode::Flicker}) {
    const std::vector<ScreenRect> one = slotsFor(mode, {5.0f, 6.0f}, {100.0f, 50.0f}, 6.0f);
    ASSERT_EQ(one.size(), 1u);
    EXPECT_FLOAT_EQ(one[0].max.x, 105.0f);
    EXPECT_FLOAT_EQ(one[0].max.y, 56.0f);
  }
}

TEST(ViewLayout, PixelAtFindsTheImagePixelInEitherSlotAndNoneOutside) {
  // Two 100 x 100 slots showing a 10 x 10 image: 10 points per pixel.
  const std::vector<ScreenRect> slots = slotsFor(ViewMode::SideBySide, {0.0f, 0.0f}, {206.0f, 100.0f}, 6.0f);
  const auto first = pixelAt(slots, {0.0f, 0.0f}, 10, 10);
  ASSERT_TRUE(first);
  EXPECT_EQ(first->x, 0);
  EXPECT_EQ(first->yTop, 0);
  const auto last = pixelAt(slots, {99.9f, 99.9f}, 10, 10);
  ASSERT_TRUE(last);
  EXPECT_EQ(last->x, 9);
  EXPECT_EQ(last->yTop, 9);
  const auto right = pixelAt(slots, {106.0f + 35.0f, 12.0f}, 10, 10);
  ASSERT_TRUE(right);
  EXPECT_EQ(right->x, 3);
  EXPECT_EQ(right->yTop, 1);
  EXPECT_FALSE(pixelAt(slots, {103.0f, 50.0f}, 10, 10));  // the gap
  EXPECT_FALSE(pixelAt(slots, {50.0f, 100.0f}, 10, 10));  // max is exclusive
}

TEST(ViewLayout, ProjectToRectPutsTheTargetAtTheCentreAndNothingBehindTheCamera) {
  Camera camera;  // looks from (0, 1, 4) at the origin
  const ScreenRect rect{{0.0f, 0.0f}, {200.0f, 100.0f}};
  const auto centre = projectToRect(camera, camera.target, rect, 200, 100);
  ASSERT_TRUE(centre);
  EXPECT_NEAR(centre->x, 100.0f, 1e-3f);
  EXPECT_NEAR(centre->y, 50.0f, 1e-3f);
  const auto above = projectToRect(camera, vec3(0.0f, 0.5f, 0.0f), rect, 200, 100);
  ASSERT_TRUE(above);
  EXPECT_LT(above->y, 50.0f);  // y down on screen
  EXPECT_FALSE(projectToRect(camera, vec3(0.0f, 1.0f, 8.0f), rect, 200, 100));
  Camera broken = camera;
  broken.near = 0.0f;
  EXPECT_FALSE(projectToRect(broken, camera.target, rect, 200, 100));
}

Image filled(int width, int height, std::uint8_t value) {
  Image image = makeImage(width, height);
  std::memset(image.rgba.data(), value, image.rgba.size());
  return image;
}

TEST(ViewScreenshot, SplitTakesGlFromTheDividerOnWithAWhiteDividerColumn) {
  const Image split = composeSplit(filled(10, 2, 10), filled(10, 2, 200), 0.3f);
  EXPECT_EQ(split.pixel(2, 1)[0], 10);   // CPU left of the divider
  EXPECT_EQ(split.pixel(3, 1)[0], 255);  // the divider, at round(0.3 * 10)
  EXPECT_EQ(split.pixel(3, 1)[3], 255);
  EXPECT_EQ(split.pixel(4, 1)[0], 200);  // GL from it on
  const Image allCpu = composeSplit(filled(4, 1, 10), filled(4, 1, 200), 1.0f);
  EXPECT_EQ(allCpu.pixel(3, 0)[0], 10);  // a divider at the right edge leaves no GL column
}

TEST(ViewScreenshot, WindowRowsTurnTopFirstAndOpaque) {
  std::vector<std::uint8_t> bottomFirst(2 * 3 * 4, 0);
  for (int row = 0; row < 3; ++row) bottomFirst[static_cast<std::size_t>(row) * 8] = static_cast<std::uint8_t>(row + 1);
  const Image image = imageFromBottomRows(2, 3, bottomFirst);
  EXPECT_EQ(image.pixel(0, 0)[0], 3);  // the top row is read back last
  EXPECT_EQ(image.pixel(0, 2)[0], 1);
  EXPECT_EQ(image.pixel(1, 1)[3], 255);
  EXPECT_THROW(imageFromBottomRows(2, 4, bottomFirst), InputError);
}

TEST(ViewScreenshot, FlickerShowsTheBackendOfItsPhase) {
  EXPECT_EQ(shownViewMode(ViewMode::Flicker, 0.2, 2.0), ViewMode::Cpu);
  EXPECT_EQ(shownViewMode(ViewMode::Flicker, 0.7, 2.0), ViewMode::Gl);
  EXPECT_EQ(shownViewMode(ViewMode::Flicker, 1.1, 2.0), ViewMode::Cpu);
  EXPECT_EQ(shownViewMode(ViewMode::Split, 0.7, 2.0), ViewMode::Split);
}

TEST(ViewScreenshot, StemNamesTheFolderAndTheLocalTime) {
  const std::string stem = screenshotStem("out/shots", 0);
  EXPECT_EQ(stem.rfind("out/shots/twinraster-", 0), 0u) << stem;
  EXPECT_EQ(stem.size(), std::string("out/shots/twinraster-YYYYmmdd-HHMMSS").size()) << stem;
  EXPECT_EQ(screenshotStem("", 0).rfind("./twinraster-", 0), 0u);
}

TEST(ViewScreenshot, SaysWhyAViewCannotBeMadeYet) {
  RenderOutput small, large;
  small.width = small.height = 2;
  small.rgba.assign(2 * 2 * 4, 0);
  large.width = large.height = 3;
  large.rgba.assign(3 * 3 * 4, 0);
  GuiPrefs prefs;
  EXPECT_THROW(viewScreenshotOf(small, large, ViewMode::Split, prefs, std::nullopt), InputError);
  EXPECT_THROW(viewScreenshotOf(small, small, ViewMode::Diff, prefs, std::nullopt), InputError);
  const Image gl = viewScreenshotOf(small, large, ViewMode::Gl, prefs, std::nullopt);
  EXPECT_EQ(gl.width, 3);
}

TEST(SceneHelp, EveryMethodsTooltipStartsWithItsSceneFileName) {
  for (const SurfaceDetail method : kAllSurfaceDetails) {
    const std::string help = surfaceDetailHelp(method);
    EXPECT_EQ(help.rfind(std::string(toString(method)), 0), 0u) << help;
    EXPECT_GT(help.size(), 60u) << help;
  }
  for (const SelfShadow shadow : {SelfShadow::None, SelfShadow::HeightMarch, SelfShadow::HorizonMap}) {
    const std::string help = selfShadowHelp(shadow);
    EXPECT_EQ(help.rfind(std::string(toString(shadow)), 0), 0u) << help;
  }
}

TEST(SceneHelp, CountsTheNodesDrawingAMeshAtAnyDepth) {
  std::vector<Node> nodes(2);
  nodes[0].meshIndex = 1;
  nodes[1].meshIndex = 0;
  nodes[1].children.resize(2);
  nodes[1].children[0].meshIndex = 1;
  nodes[1].children[1].meshIndex = -1;
  EXPECT_EQ(countNodesUsingMesh(nodes, 1), 2);
  EXPECT_EQ(countNodesUsingMesh(nodes, 0), 1);
  EXPECT_EQ(countNodesUsingMesh(nodes, 5), 0);
}

}  // namespace
}  // namespace twr::gui
