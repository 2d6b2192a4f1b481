// The stage explorer's model (gui/stage_explorer.h) on a real traced triangle: the near plane
// and side planes cut it, and every stage shows the trace's numbers and the pipeline's own
// positions for them.
#include "gui/stage_explorer.h"

#include "scene/scene_file.h"
#include "softrender/cpu_renderer.h"
#include "softrender/stage_pictures.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <string>

namespace twr::gui {
namespace {

constexpr int kWidth = 640, kHeight = 480, kX = 600, kY = 50;  // inside_near.json's cube, cut by near and right

struct Traced {
  Scene scene;
  PixelTrace trace;
  RenderOutput frame;
};

const Traced& traced() {
  static const Traced t = [] {
    Traced out{loadSceneFile(std::string(TWINRASTER_SOURCE_DIR) + "/assets/scenes/inside_near.json"), {}, {}};
    out.trace = tracePixel(out.scene, out.scene.settings, kWidth, kHeight, kX, kY);
    out.frame = makeCpuRenderer()->render(out.scene, out.scene.settings, kWidth, kHeight);
    return out;
  }();
  return t;
}

bool anyLineHas(const ExplorerView& view, const std::string& text) {
  return std::any_of(view.lines.begin(), view.lines.end(),
                     [&](const std::string& line) { return line.find(text) != std::string::npos; });
}

TEST(StageExplorer, StepsHoldAtBothEnds) {
  EXPECT_EQ(previousStage(ExplorerStage::Vertex), ExplorerStage::Vertex);
  EXPECT_EQ(nextStage(ExplorerStage::Shade), ExplorerStage::Shade);
  ExplorerStage stage = ExplorerStage::Vertex;
  for (std::size_t i = 1; i < std::size(kExplorerStages); ++i) {
    stage = nextStage(stage);
    EXPECT_EQ(stage, kExplorerStages[i]);
    EXPECT_EQ(previousStage(stage), kExplorerStages[i - 1]);
  }
}

TEST(StageExplorer, EveryStageOfACutTriangleHasLinesAndThePixel) {
  const Traced& t = traced();
  const TriangleVisit* visit = stageVisitOf(t.trace);
  ASSERT_NE(visit, nullptr);
  ASSERT_NE(visit->planesCut & (1u << kClipPlaneNear), 0u) << "the scene no longer has the near cut here";
  ASSERT_NE(visit->planesCut & (1u << kClipPlaneRight), 0u) << "nor the right plane's";
  for (const ExplorerStage stage : kExplorerStages) {
    const ExplorerView view = explorerViewOf(t.trace, *visit, stage, &t.frame.triangleId);
    EXPECT_FALSE(view.lines.empty()) << toString(stage);
    EXPECT_EQ(view.overlay.pixelCentre.x, kX + 0.5);
    EXPECT_EQ(view.overlay.pixelCentre.y, kY + 0.5);
    const nlohmann::json j = explorerViewToJson(view);
    EXPECT_EQ(j["stage"], toString(stage));
  }
}

TEST(StageExplorer, ClipAndDivideDrawThePolygonTheClipperLeft) {
  const Traced& t = traced();
  const TriangleVisit& visit = *stageVisitOf(t.trace);
  const ExplorerView clip = explorerViewOf(t.trace, visit, ExplorerStage::Clip, nullptr);
  ASSERT_EQ(clip.overlay.polygon.size(), visit.clippedPolygon.size());
  for (const ClipStep& step : visit.clipSteps) EXPECT_TRUE(anyLineHas(clip, std::string(clipPlaneName(step.plane)) + ": "));
  const ExplorerView divide = explorerViewOf(t.trace, visit, ExplorerStage::Divide, nullptr);
  ASSERT_EQ(divide.overlay.fan.size(), visit.clippedPolygon.size() - 2);
  ASSERT_GE(divide.overlay.fanTriangle, 0);
  // The covering fan triangle's corners are the window corners setup received (y from the top).
  const auto& covering = divide.overlay.fan[static_cast<std::size_t>(divide.overlay.fanTriangle)];
  for (const WindowVertex& w : visit.window) {
    const bool found = std::any_of(covering.begin(), covering.end(), [&](const ImagePoint& p) {
      return std::abs(p.x - w.x) < 1e-4 && std::abs(p.y - (kHeight - w.y)) < 1e-4;
    });
    EXPECT_TRUE(found) << w.x << ", " << w.y;
  }
}

TEST(StageExplorer, OneClipPassDrawsThePolygonBeforeAndAfterItsPlane) {
  const Traced& t = traced();
  const TriangleVisit& visit = *stageVisitOf(t.trace);
  ASSERT_GE(visit.clipSteps.size(), 2u);
  for (int pass = 0; pass < static_cast<int>(visit.clipSteps.size()); ++pass) {
    const ClipStep& step = visit.clipSteps[static_cast<std::size_t>(pass)];
    const ExplorerView view = explorerViewOf(t.trace, visit, ExplorerStage::Clip, nullptr, pass);
    EXPECT_EQ(view.clipPass, pass);
    const auto inFront = [](const std::vector<vec4>& polygon) {
      return static_cast<std::size_t>(std::count_if(polygon.begin(), polygon.end(), [](const vec4& p) { return p.w > 0.0f; }));
    };
    EXPECT_EQ(view.overlay.polygonBefore.size(), inFront(step.before));
    EXPECT_EQ(view.overlay.polygon.size(), inFront(step.after));
    EXPECT_TRUE(anyLineHas(view, std::string("> ") + clipPlaneName(step.plane) + ": "));
  }
  // A pass the triangle does not have shows them all.
  const ExplorerView all = explorerViewOf(t.trace, visit, ExplorerStage::Clip, nullptr, 99);
  EXPECT_EQ(all.clipPass, -1);
  EXPECT_TRUE(all.overlay.polygonBefore.empty());
  EXPECT_EQ(all.overlay.polygon.size(), visit.clippedPolygon.size());
}

TEST(StageExplorer, SetupAndRasterShowTheSnappedCornersBoxAndPixelsWon) {
  const Traced& t = traced();
  const TriangleVisit& visit = *stageVisitOf(t.trace);
  const ExplorerView setup = explorerViewOf(t.trace, visit, ExplorerStage::Setup, nullptr);
  ASSERT_EQ(setup.overlay.snapped.size(), 3u);
  EXPECT_EQ(setup.overlay.snapped[0].x, visit.xFixed[0] / 256.0 + 0.5);
  ASSERT_TRUE(setup.overlay.boundingBox);
  const auto& box = *setup.overlay.boundingBox;
  EXPECT_TRUE(box[0] <= kX && kX <= box[2] && box[1] <= kY && kY <= box[3]);
  EXPECT_TRUE(anyLineHas(setup, "E " + std::to_string(visit.edgeValue[0])));
  EXPECT_TRUE(setup.overlay.covered.empty()) << "pixels are marked at the raster stage";
  const ExplorerView raster = explorerViewOf(t.trace, visit, ExplorerStage::Raster, &t.frame.triangleId);
  ASSERT_FALSE(raster.overlay.covered.empty());
  const std::array<int, 2> pixel{kX, kY};
  EXPECT_NE(std::find(raster.overlay.covered.begin(), raster.overlay.covered.end(), pixel), raster.overlay.covered.end());
  for (const auto& p : raster.overlay.covered) {
    EXPECT_EQ(t.frame.triangleId[static_cast<std::size_t>(p[1]) * kWidth + static_cast<std::size_t>(p[0])], visit.triangleId);
  }
}

}  // namespace
}  // namespace twr::gui
