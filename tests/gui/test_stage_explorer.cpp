// The stage explorer's model (gui/stage_explorer.h) on a real traced triangle: the near plane
// and side planes cut it, and every stage shows the trace's numbers and the pipeline's own
// positions for them.
#include "gui/stage_explorer.h"
#include "gui/explorer_cache.h"

#include "scene/scene_file.h"
#include "softrender/cpu_renderer.h"
#include "softrender/raster.h"
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

TEST(StageExplorer, EveryStageSaysWhatItDoesAndNamesItsSource) {
  for (const ExplorerStage stage : kExplorerStages) {
    const std::string hint = stageHintOf(stage);
    EXPECT_GT(hint.size(), 40u) << toString(stage);
  }
  EXPECT_NE(std::string(stageHintOf(ExplorerStage::Clip)).find("softrender/clip.cpp"), std::string::npos);
  EXPECT_NE(std::string(stageHintOf(ExplorerStage::Raster)).find("fill rule"), std::string::npos);
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

TEST(StageExplorer, ClipPlotDrawsEachPassInClipSpaceWhereItsPlaneIsADiagonal) {
  const Traced& t = traced();
  const TriangleVisit& visit = *stageVisitOf(t.trace);
  for (int pass = 0; pass < static_cast<int>(visit.clipSteps.size()); ++pass) {
    const ClipStep& step = visit.clipSteps[static_cast<std::size_t>(pass)];
    for (const ClipPlotAxes axes : kClipPlotAxes) {
      ExplorerChoices choices;
      choices.clipPass = pass;
      choices.clipAxes = axes;
      const ExplorerView view = explorerViewOf(t.trace, visit, ExplorerStage::Clip, nullptr, choices);
      ASSERT_TRUE(view.clipPlot) << toString(axes);
      const ClipPlot& plot = *view.clipPlot;
      EXPECT_EQ(plot.axes, axes);
      const bool ndc = axes == ClipPlotAxes::Ndc;
      // The pass's own clip positions, one coordinate against w, or at x/w, y/w.
      std::size_t shown = 0;
      for (const vec4& p : step.after) {
        if (ndc && !(p.w > 0.0f)) continue;
        ASSERT_LT(shown, plot.after.size());
        const PlotPoint& q = plot.after[shown++];
        const double h = axes == ClipPlotAxes::XW ? p.x : axes == ClipPlotAxes::YW ? p.y : axes == ClipPlotAxes::ZW ? p.z
                                                                                                   : double(p.x) / p.w;
        EXPECT_EQ(q[0], h) << toString(axes);
        EXPECT_EQ(q[1], ndc ? double(p.y) / p.w : double(p.w)) << toString(axes);
      }
      EXPECT_EQ(shown, plot.after.size());
      EXPECT_EQ(plot.cuts.size() + static_cast<std::size_t>(std::count_if(step.cuts.begin(), step.cuts.end(), [&](const ClipCut& c) {
                  return ndc && !(step.after[static_cast<std::size_t>(c.index)].w > 0.0f);
                })),
                step.cuts.size());
      // Every vertex the pass made lies on its plane, which is marked, where that plane is a line here.
      const auto cutting = std::find_if(plot.planes.begin(), plot.planes.end(), [](const ClipPlotLine& l) { return l.cutting; });
      if (cutting == plot.planes.end()) continue;
      EXPECT_NE(cutting->name.find(clipPlaneName(step.plane)), std::string::npos) << cutting->name;
      for (const PlotPoint& c : plot.cuts) {
        const double cross = (cutting->to[0] - cutting->from[0]) * (c[1] - cutting->from[1]) -
                             (cutting->to[1] - cutting->from[1]) * (c[0] - cutting->from[0]);
        const double length = std::hypot(cutting->to[0] - cutting->from[0], cutting->to[1] - cutting->from[1]);
        EXPECT_NEAR(cross / length, 0.0, 1e-5) << cutting->name;
      }
    }
  }
  // The side planes are diagonals in x against w: right is x = w.
  ExplorerChoices choices;
  const ExplorerView all = explorerViewOf(t.trace, visit, ExplorerStage::Clip, nullptr, choices);
  ASSERT_TRUE(all.clipPlot);
  EXPECT_EQ(all.clipPlot->before.size(), 3u) << "all passes: the triangle, then the final polygon";
  EXPECT_EQ(all.clipPlot->after.size(), visit.clippedPolygon.size());
  const ClipPlotLine& right = all.clipPlot->planes[0];
  EXPECT_EQ(right.name, "right: x = w");
  EXPECT_EQ(right.from[0], right.from[1]);
  EXPECT_EQ(right.to[0], right.to[1]);
  EXPECT_FALSE(explorerViewOf(t.trace, visit, ExplorerStage::Divide, nullptr).clipPlot);
}

TEST(StageExplorer, ClipPlotDrawsASidePlaneSwitchedOffAtItsGuardBand) {
  const Traced& t = traced();
  RenderSettings settings = t.scene.settings;
  settings.clip.right = false;
  settings.clip.near = false;
  const PixelTrace trace = tracePixel(t.scene, settings, kWidth, kHeight, kX, kY);
  const TriangleVisit* visit = stageVisitOf(trace);
  ASSERT_NE(visit, nullptr);
  ASSERT_GT(trace.clip.guardBandX, 1.0f);
  ExplorerChoices choices;
  const ExplorerView view = explorerViewOf(trace, *visit, ExplorerStage::Clip, nullptr, choices);
  ASSERT_TRUE(view.clipPlot);
  const auto right = std::find_if(view.clipPlot->planes.begin(), view.clipPlot->planes.end(),
                                  [](const ClipPlotLine& l) { return l.name.rfind("right", 0) == 0; });
  ASSERT_NE(right, view.clipPlot->planes.end());
  EXPECT_NE(right->name.find("(off: the guard band)"), std::string::npos) << right->name;
  EXPECT_NEAR(right->to[0] / right->to[1], trace.clip.guardBandX, 1e-3) << "x = g w";
  // z against w: near off, so no near line, and the clipper's w >= kMinClipW plane instead.
  choices.clipAxes = ClipPlotAxes::ZW;
  const ExplorerView zw = explorerViewOf(trace, *visit, ExplorerStage::Clip, nullptr, choices);
  std::string names;
  for (const ClipPlotLine& l : zw.clipPlot->planes) names += l.name + "; ";
  EXPECT_EQ(names.find("near: "), std::string::npos) << names;
  EXPECT_NE(names.find("(near is off)"), std::string::npos) << names;
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

TEST(StageExplorer, FollowsAnyTriangleReachingThePixelAndTheOneThatWroteItFirst) {
  const Traced& t = traced();
  ASSERT_FALSE(t.trace.visits.empty());
  EXPECT_EQ(explorerVisitOf(t.trace, -1), stageVisitOf(t.trace));
  EXPECT_EQ(explorerVisitOf(t.trace, 0), &t.trace.visits[0]);
  EXPECT_EQ(explorerVisitOf(t.trace, static_cast<int>(t.trace.visits.size())), stageVisitOf(t.trace)) << "past the end";
  const std::string text = visitChoiceText(t.trace, 0);
  EXPECT_NE(text.find("triangle 1 of " + std::to_string(t.trace.visits.size()) + " reaching the pixel (id " +
                      std::to_string(t.trace.visits[0].triangleId) + "): " + toString(t.trace.visits[0].outcome)),
            std::string::npos)
      << text;
  EXPECT_EQ(explorerVisitOf(PixelTrace{}, 0), nullptr);
  EXPECT_EQ(visitChoiceText(PixelTrace{}, -1), "no triangle reaches the pixel");
}

TEST(StageExplorer, VisitOrderStepsThroughTheRasterizersSpansFromTheBottomRow) {
  const Traced& t = traced();
  const TriangleVisit& visit = *stageVisitOf(t.trace);
  ExplorerChoices choices;
  const ExplorerView off = explorerViewOf(t.trace, visit, ExplorerStage::Raster, nullptr, choices);
  EXPECT_EQ(off.rasterStep, -1);
  EXPECT_TRUE(off.overlay.visitedRuns.empty());
  EXPECT_FALSE(off.overlay.visitPixel);
  // Every pixel of the box whose centre the three edge functions pass is one step.
  TriangleSetup setup;
  ASSERT_EQ(setupTriangle(visit.window, CullMode::None, FrontFace::Ccw, Viewport{kWidth, kHeight}, setup),
            SetupResult::Ready);
  EXPECT_EQ(setup.xFixed, visit.xFixed) << "the explorer's setup is the trace's";
  int inside = 0;
  for (int py = setup.y0; py <= setup.y1; ++py) {
    for (int px = setup.x0; px <= setup.x1; ++px) inside += coversPixel(setup, px, py) ? 1 : 0;
  }
  ASSERT_GT(inside, 1);
  EXPECT_EQ(off.rasterSteps, inside);
  // The first step is the leftmost covered pixel of the lowest row with any (GL's row py from
  // the bottom; the box's lowest rows may hold none).
  int lowest = setup.y0;
  while (coveredSpan(setup, lowest).xBegin >= coveredSpan(setup, lowest).xEnd) ++lowest;
  choices.rasterStep = 0;
  const ExplorerView first = explorerViewOf(t.trace, visit, ExplorerStage::Raster, nullptr, choices);
  ASSERT_TRUE(first.overlay.visitPixel);
  EXPECT_EQ((*first.overlay.visitPixel)[1], kHeight - 1 - lowest);
  EXPECT_EQ((*first.overlay.visitPixel)[0], coveredSpan(setup, lowest).xBegin);
  // The traced pixel's step shows the traced pixel, with every pixel before it visited.
  const int traced = visitStepOf(t.trace, visit);
  ASSERT_GE(traced, 0);
  choices.rasterStep = traced;
  const ExplorerView atTraced = explorerViewOf(t.trace, visit, ExplorerStage::Raster, nullptr, choices);
  EXPECT_EQ(atTraced.overlay.visitPixel, (std::array<int, 2>{kX, kY}));
  EXPECT_EQ(visitPixelOf(t.trace, visit, traced), (std::array<int, 2>{kX, kY}));
  int visited = 0;
  for (const auto& run : atTraced.overlay.visitedRuns) {
    visited += run[1] - run[0];
    EXPECT_GE(run[2], kY) << "rows below the pixel come first";
  }
  EXPECT_EQ(visited, traced + 1);
  EXPECT_TRUE(anyLineHas(atTraced, "> step " + std::to_string(traced) + " of "));
  // Past the end holds the last pixel.
  choices.rasterStep = inside + 10;
  EXPECT_EQ(explorerViewOf(t.trace, visit, ExplorerStage::Raster, nullptr, choices).rasterStep, inside - 1);
  EXPECT_FALSE(visitPixelOf(t.trace, visit, inside));
}

TEST(StageExplorer, SpanStepsGoToTheFirstPixelOfTheNextOrPreviousSpan) {
  const Traced& t = traced();
  const TriangleVisit& visit = *stageVisitOf(t.trace);
  ExplorerChoices choices;
  choices.rasterStep = 0;
  EXPECT_EQ(spanStepFrom(t.trace, visit, -1, +1), 0);
  const int second = spanStepFrom(t.trace, visit, 0, +1);
  ASSERT_GT(second, 0);
  choices.rasterStep = second - 1;
  const ExplorerView endOfFirst = explorerViewOf(t.trace, visit, ExplorerStage::Raster, nullptr, choices);
  EXPECT_EQ(endOfFirst.overlay.visitedRuns.size(), 1u) << "the first span ends just before the second starts";
  EXPECT_EQ(spanStepFrom(t.trace, visit, second - 1, +1), second);
  EXPECT_EQ(spanStepFrom(t.trace, visit, second, -1), 0);
  EXPECT_EQ(spanStepFrom(t.trace, visit, 0, -1), 0) << "held at the first span";
  const int last = explorerViewOf(t.trace, visit, ExplorerStage::Raster, nullptr, choices).rasterSteps - 1;
  const int lastSpan = spanStepFrom(t.trace, visit, last, 0);
  EXPECT_EQ(spanStepFrom(t.trace, visit, last, +1), lastSpan) << "held at the last span";
}

TEST(StageExplorer, WeightMapHoldsThePipelinesWeightsAtEveryCoveredPixel) {
  const Traced& t = traced();
  const TriangleVisit& visit = *stageVisitOf(t.trace);
  ExplorerChoices choices;
  const ExplorerView screen = explorerViewOf(t.trace, visit, ExplorerStage::Interpolate, nullptr, choices);
  choices.perspectiveMap = true;
  const ExplorerView perspective = explorerViewOf(t.trace, visit, ExplorerStage::Interpolate, nullptr, choices);
  const ExplorerWeightMap& s = screen.overlay.weightMap;
  const ExplorerWeightMap& p = perspective.overlay.weightMap;
  // At the traced pixel, bit for bit the trace's own weights.
  EXPECT_EQ(weightsAt(s, kX, kY), visit.weights.screen);
  EXPECT_EQ(weightsAt(p, kX, kY), visit.weights.perspective);
  ASSERT_EQ(screen.overlay.weightCorners.size(), 3u);
  const int steps = explorerViewOf(t.trace, visit, ExplorerStage::Raster, nullptr, ExplorerChoices{}).rasterSteps;
  EXPECT_EQ(std::count(s.covered.begin(), s.covered.end(), std::uint8_t{1}), steps);
  // Each sums to 1; the corners' depths differ, so perspective moves the weights somewhere.
  float largestShift = 0.0f;
  for (std::size_t i = 0; i < s.weights.size(); ++i) {
    if (!s.covered[i]) continue;
    EXPECT_NEAR(s.weights[i][0] + s.weights[i][1] + s.weights[i][2], 1.0f, 1e-5f);
    EXPECT_NEAR(p.weights[i][0] + p.weights[i][1] + p.weights[i][2], 1.0f, 1e-5f);
    for (std::size_t c = 0; c < 3; ++c) largestShift = std::max(largestShift, std::abs(s.weights[i][c] - p.weights[i][c]));
  }
  EXPECT_GT(largestShift, 0.05f);
  // The picture: opaque where covered, the weights in its channels, clear elsewhere.
  const Image image = weightMapImage(s);
  ASSERT_EQ(image.width, s.width);
  const std::uint8_t* at = image.pixel(kX - s.x0, kY - s.y0);
  EXPECT_EQ(at[3], 255);
  EXPECT_EQ(at[0], static_cast<std::uint8_t>(std::lround(visit.weights.screen[0] * 255.0f)));
  const auto hole = std::find(s.covered.begin(), s.covered.end(), std::uint8_t{0});
  if (hole != s.covered.end()) {
    EXPECT_EQ(image.rgba[4 * static_cast<std::size_t>(hole - s.covered.begin()) + 3], 0);
  }
  EXPECT_TRUE(anyLineHas(perspective, "map: the perspective weights"));
  EXPECT_FALSE(weightsAt(s, s.x0 - 1, kY)) << "outside the box";
}

TEST(StageExplorer, ShadeDrawsTheSurfaceFrameFromTheFragment) {
  const Traced& t = traced();
  const TriangleVisit& visit = *stageVisitOf(t.trace);
  ASSERT_EQ(visit.outcome, TraceOutcome::Shaded);
  const ExplorerView shade = explorerViewOf(t.trace, visit, ExplorerStage::Shade, nullptr);
  std::string axes;
  for (const ExplorerFrameArrow& a : shade.overlay.frameArrows) {
    axes += a.axis;
    // From the fragment, which is the traced pixel's centre, to a tip some pixels away.
    EXPECT_NEAR(a.from.x, kX + 0.5, 0.05) << a.axis;
    EXPECT_NEAR(a.from.y, kY + 0.5, 0.05) << a.axis;
    EXPECT_GT(std::hypot(a.to.x - a.from.x, a.to.y - a.from.y), 1.0) << a.axis;
  }
  EXPECT_NE(axes.find('N'), std::string::npos) << axes;
  EXPECT_NE(axes.find('L'), std::string::npos) << axes;
  EXPECT_TRUE(anyLineHas(shade, "T ("));
  EXPECT_TRUE(explorerViewOf(t.trace, visit, ExplorerStage::Raster, nullptr).overlay.frameArrows.empty());
}

TEST(StageExplorer, FillRuleAlongAnEdgeTheFanTrianglesShare) {
  const Traced& t = traced();
  const TriangleVisit& visit = *stageVisitOf(t.trace);
  ASSERT_GE(visit.clippedPolygon.size(), 4u) << "the scene no longer clips it into a fan of two or more";
  const ExplorerView raster = explorerViewOf(t.trace, visit, ExplorerStage::Raster, nullptr);
  ASSERT_TRUE(raster.overlay.sharedEdge);
  const ExplorerSharedEdge& e = *raster.overlay.sharedEdge;
  EXPECT_NE(e.with.find("fan triangle"), std::string::npos) << e.with;
  EXPECT_FALSE(e.mine.empty());
  EXPECT_FALSE(e.theirs.empty());
  EXPECT_EQ(e.both, 0) << "no pixel drawn twice";
  EXPECT_TRUE(anyLineHas(raster, "fill rule at the edge shared with " + e.with));
  EXPECT_TRUE(explorerViewOf(t.trace, visit, ExplorerStage::Setup, nullptr).overlay.sharedEdge == std::nullopt);
}

// Two triangles of a square whose diagonal runs through pixel centres: 64 x 64 pixels, a
// 90-degree field of view one unit from the square, so a world x of (2k + 1) / 64 - 1 lands on
// pixel centre k + 0.5; the diagonal joins the centres of pixels 8 and 40 on both axes.
TEST(StageExplorer, FillRuleGivesEachPixelCentreOnASharedMeshEdgeToOneTriangle) {
  constexpr const char* kScene = R"({
    "output": {"width": 64, "height": 64},
    "camera": {"position": [0, 0, 1], "target": [0, 0, 0], "fov_deg": 90, "near": 0.1, "far": 10},
    "materials": {"matte": {"kd": [0.8, 0.8, 0.8]}},
    "nodes": [{"name": "square", "material": "matte", "mesh": {"type": "triangles", "positions": [
      [-0.734375, -0.734375, 0], [0.265625, -0.734375, 0], [0.265625, 0.265625, 0],
      [-0.734375, -0.734375, 0], [0.265625, 0.265625, 0], [-0.734375, 0.265625, 0]]}}]
  })";
  const Scene scene = parseScene(kScene, "diagonal.json", ".");
  constexpr int kSize = 64;
  for (const auto& [x, yGl] : {std::pair{25, 20}, std::pair{20, 25}}) {  // below the diagonal, then above it
    const PixelTrace trace = tracePixel(scene, scene.settings, kSize, kSize, x, kSize - 1 - yGl);
    const TriangleVisit* visit = stageVisitOf(trace);
    ASSERT_NE(visit, nullptr);
    ASSERT_EQ(visit->neighbours.size(), 1u) << "the square's triangles share one edge";
    const ExplorerView raster = explorerViewOf(trace, *visit, ExplorerStage::Raster, nullptr);
    ASSERT_TRUE(raster.overlay.sharedEdge);
    const ExplorerSharedEdge& e = *raster.overlay.sharedEdge;
    EXPECT_NE(e.with.find("of the mesh"), std::string::npos) << e.with;
    EXPECT_EQ(e.onEdge.size(), 33u) << "pixel centres 8.5 .. 40.5 on the diagonal";
    EXPECT_EQ(e.both, 0);
    // Each centre on the edge goes to exactly one of the two: the triangle whose edge owns it
    // (the two ends are the square's corners, which its outer edges decide).
    const auto& owner = e.thisOwns ? e.mine : e.theirs;
    const auto& other = e.thisOwns ? e.theirs : e.mine;
    for (const auto& p : e.onEdge) {
      if (p[0] == 8 || p[0] == 40) continue;
      EXPECT_NE(std::find(owner.begin(), owner.end(), p), owner.end()) << p[0] << ", " << p[1];
      EXPECT_EQ(std::find(other.begin(), other.end(), p), other.end()) << p[0] << ", " << p[1];
    }
  }
}

TEST(ExplorerViewCache, KeepsAViewUntilWhatItWasMadeFromChanges) {
  const auto trace = std::make_shared<const PixelTrace>(traced().trace);
  const auto frame = std::make_shared<const RenderOutput>(traced().frame);
  ExplorerViewCache cache;
  ExplorerPosition position;
  position.stage = ExplorerStage::Interpolate;
  const auto first = cache.viewOf(trace, 7, frame, 7, position);
  ASSERT_TRUE(first);
  EXPECT_EQ(first->stage, ExplorerStage::Interpolate);
  EXPECT_EQ(cache.viewOf(trace, 7, frame, 7, position), first);  // the same object, not rebuilt
  EXPECT_EQ(cache.viewsMade(), 1);
  position.choices.perspectiveMap = true;
  const auto perspective = cache.viewOf(trace, 7, frame, 7, position);
  EXPECT_NE(perspective, first);
  EXPECT_TRUE(perspective->perspectiveMap);
  // A frame of another edit: rebuilt, and its triangle ids are not used for this trace.
  EXPECT_NE(cache.viewOf(trace, 7, frame, 8, position), perspective);
  EXPECT_EQ(cache.viewsMade(), 3);
  // Another trace object of the same pixel is a new key: the cache holds the trace it was made
  // from, not its address.
  const auto again = std::make_shared<const PixelTrace>(traced().trace);
  EXPECT_NE(cache.viewOf(again, 7, frame, 8, position), nullptr);
  EXPECT_EQ(cache.viewsMade(), 4);
}

TEST(ExplorerViewCache, NoViewWithoutATraceOrAVisit) {
  ExplorerViewCache cache;
  EXPECT_EQ(cache.viewOf(nullptr, 1, nullptr, 1, ExplorerPosition{}), nullptr);
  PixelTrace empty;
  EXPECT_EQ(cache.viewOf(std::make_shared<const PixelTrace>(empty), 1, nullptr, 1, ExplorerPosition{}), nullptr);
  EXPECT_EQ(cache.viewsMade(), 0);
}

}  // namespace
}  // namespace twr::gui
