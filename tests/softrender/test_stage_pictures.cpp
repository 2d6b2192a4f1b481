// The stage pictures (softrender/stage_pictures.h): which visit they follow, that each draws
// the trace's own numbers (the polygon's vertices, the fan triangle that covers the pixel, the
// pixels the frame shows the triangle in, the terms that sum to the colour), and the files
// writeStagePictures leaves for a real scene whose floor the side planes cut.
#include "softrender/stage_pictures.h"

#include "scene/errors.h"
#include "scene/scene_file.h"
#include "softrender/cpu_renderer.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

namespace twr {
namespace {

std::size_t count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

TriangleVisit visitOf(std::uint32_t id, TraceOutcome outcome) {
  TriangleVisit v;
  v.triangleId = id;
  v.outcome = outcome;
  return v;
}

TEST(StagePictures, FollowTheVisitThatWroteThePixel) {
  PixelTrace trace;
  EXPECT_EQ(stageVisitOf(trace), nullptr);
  trace.visits = {visitOf(4, TraceOutcome::CulledBack), visitOf(7, TraceOutcome::Shaded),
                  visitOf(9, TraceOutcome::Shaded), visitOf(2, TraceOutcome::FailedDepthTest)};
  trace.triangleId = 7;
  EXPECT_EQ(stageVisitOf(trace)->triangleId, 7u);
  trace.triangleId = kNoTriangle;  // a debug line or a later pass wrote it: the last shaded
  EXPECT_EQ(stageVisitOf(trace)->triangleId, 9u);
  trace.visits = {visitOf(4, TraceOutcome::CulledBack), visitOf(2, TraceOutcome::ClippedAway)};
  EXPECT_EQ(stageVisitOf(trace)->triangleId, 4u);
}

// A quad-shaped clipped polygon (4 vertices, two fan triangles), the second covering the pixel.
TEST(StagePictures, ClipPictureDrawsThePolygonAndFillsTheCoveringFanTriangle) {
  PixelTrace trace;
  trace.width = 100, trace.height = 100, trace.x = 70, trace.yGl = 60;
  TriangleVisit v = visitOf(1, TraceOutcome::Shaded);
  v.posClip = {vec4(-2, -0.5f, 0, 1), vec4(0.8f, -0.5f, 0, 1), vec4(0.8f, 0.9f, 0, 1)};
  v.clippedPolygon = {vec4(-1, -0.5f, 0, 1), vec4(0.8f, -0.5f, 0, 1), vec4(0.8f, 0.9f, 0, 1), vec4(-1, 0.2f, 0, 1)};
  v.planesCut = 1u;  // one side plane
  v.fanTriangle = 1;
  const std::string svg = clipStageSvg(trace, v);
  EXPECT_EQ(svg.rfind("<svg xmlns=\"http://www.w3.org/2000/svg\"", 0), 0u);
  // Both panels: v0 .. v3 labelled, two fan triangles each, the first filled.
  EXPECT_EQ(count(svg, ">v3</text>"), 2u);
  EXPECT_EQ(count(svg, "fill=\"#9bb8dc\" stroke=\"#1f5fa8\""), 2u);
  EXPECT_EQ(count(svg, "stroke-opacity=\"0.4\""), 2u);
  v.fanTriangle = 2;
  EXPECT_EQ(count(clipStageSvg(trace, v), "stroke-opacity=\"0.4\""), 2u);  // still one filled, one not
}

TEST(StagePictures, RasterPictureMarksThePixelsTheFrameShowsTheTriangleIn) {
  PixelTrace trace;
  trace.width = 8, trace.height = 6, trace.x = 3, trace.yTop = 2, trace.yGl = 3;
  TriangleVisit v = visitOf(5, TraceOutcome::Shaded);
  // Corners at pixel centres (1, 1), (6, 1), (1, 5) in 1/256 steps (a centre at whole steps).
  v.xFixed = {1 * 256, 6 * 256, 1 * 256};
  v.yFixed = {1 * 256, 1 * 256, 5 * 256};
  std::vector<std::uint32_t> ids(8 * 6, kNoTriangle);
  ids[0] = 5;           // top-left pixel: GL row 5
  ids[2 * 8 + 3] = 5;   // the traced pixel
  ids[5 * 8 + 7] = 5;   // bottom-right: GL row 0
  ids[4 * 8 + 4] = 6;   // another triangle
  const std::string svg = rasterStageSvg(trace, v, ids);
  EXPECT_EQ(count(svg, "fill=\"#cfe0f5\""), 3u);
  EXPECT_EQ(count(svg, "<rect x="), 8u * 6u + 2u);  // every cell, the clip box, the traced pixel's outline
  EXPECT_EQ(count(svg, ">c2</text>"), 1u);
}

TEST(StagePictures, RasterGridStaysSmallForAHugeTriangle) {
  PixelTrace trace;
  trace.width = 1000, trace.height = 1000, trace.x = 500, trace.yTop = 500, trace.yGl = 499;
  TriangleVisit v = visitOf(1, TraceOutcome::Shaded);
  v.xFixed = {-100 * 256, 5000 * 256, -100 * 256};
  v.yFixed = {-100 * 256, -100 * 256, 5000 * 256};
  const std::string svg = rasterStageSvg(trace, v, std::vector<std::uint32_t>(1000 * 1000, 1));
  const std::size_t side = kStageGridPixels + 1;
  EXPECT_EQ(count(svg, "fill=\"#cfe0f5\""), side * side);
}

TEST(StagePictures, ShadeBarsStackEachLightsShareOfTheColour) {
  TriangleVisit v = visitOf(1, TraceOutcome::Shaded);
  v.terms.ambient = vec3(0.1f);
  v.terms.lightCount = 1;
  v.terms.lights[0].diffuse = vec3(0.5f);
  v.terms.lights[0].specular = vec3(0.2f);
  v.terms.lights[0].attenuation = 0.5f;
  v.terms.colour = vec4(0.45f, 0.45f, 0.45f, 1.0f);
  const std::string svg = shadeStageSvg(v);
  EXPECT_EQ(count(svg, "<title>ambient 0.1</title>"), 3u);
  EXPECT_EQ(count(svg, "<title>L0 diffuse 0.25</title>"), 3u);  // times its attenuation
  EXPECT_EQ(count(svg, "<title>L0 specular 0.1</title>"), 3u);
  EXPECT_NE(svg.find("fill=\"rgb(115,115,115)\""), std::string::npos);
}

TEST(StagePictures, WritesOnePicturePerStageAndAnIndexForAClippedFloorTriangle) {
  const Scene scene = loadSceneFile(std::string(TWINRASTER_SOURCE_DIR) + "/assets/scenes/default.json");
  const int width = 64, height = 48;
  const PixelTrace trace = tracePixel(scene, scene.settings, width, height, 32, 46);
  const TriangleVisit* visit = stageVisitOf(trace);
  ASSERT_NE(visit, nullptr);
  EXPECT_NE(visit->planesCut, 0u) << "the default scene's floor reaches past the side planes";
  const RenderOutput frame = makeCpuRenderer()->render(scene, scene.settings, width, height);
  const std::filesystem::path dir = std::filesystem::path(testing::TempDir()) / "stage_pictures";
  std::filesystem::remove_all(dir);
  const std::vector<StagePicture> pictures = writeStagePictures(dir.string(), trace, frame);
  ASSERT_EQ(pictures.size(), 7u);
  const char* const titles[] = {"Vertex", "Clip", "Divide and viewport", "Setup", "Raster", "Interpolate", "Shade"};
  for (std::size_t i = 0; i < pictures.size(); ++i) {
    EXPECT_EQ(pictures[i].title, titles[i]);
    EXPECT_TRUE(std::filesystem::exists(dir / pictures[i].file)) << pictures[i].file;
  }
  std::ifstream in(dir / "index.html");
  std::stringstream index;
  index << in.rdbuf();
  EXPECT_NE(index.str().find("Pixel (32, 46) through the pipeline"), std::string::npos);
  EXPECT_NE(index.str().find("cut by "), std::string::npos);
  EXPECT_EQ(count(index.str(), "<img src="), 7u);
}

// The new stages' drawings carry the trace's own numbers.
TEST(StagePictures, VertexDivideAndSetupDrawTheTracesPositionsAndEdges) {
  const Scene scene = loadSceneFile(std::string(TWINRASTER_SOURCE_DIR) + "/assets/scenes/default.json");
  const int width = 64, height = 48;
  const PixelTrace trace = tracePixel(scene, scene.settings, width, height, 32, 46);
  const TriangleVisit& visit = *stageVisitOf(trace);
  const auto six = [](double v) {
    char text[32];
    std::snprintf(text, sizeof text, "%.6g", v);
    return std::string(text);
  };
  const std::string vertex = vertexStageSvg(trace, visit);
  for (const vec4& c : visit.posClip) EXPECT_NE(vertex.find("-> clip (" + six(c.x) + ", " + six(c.y)), std::string::npos);
  const std::string divide = divideStageSvg(trace, visit);
  const WindowVertex w = windowFromClip(visit.clippedPolygon[0], Viewport{width, height},
                                        std::find(visit.posClip.begin(), visit.posClip.end(), visit.clippedPolygon[0]) !=
                                            visit.posClip.end());
  EXPECT_NE(divide.find("v0 window (" + six(w.x) + ", " + six(w.y) + ")"), std::string::npos) << divide;
  const std::string setup = setupStageSvg(trace, visit);
  EXPECT_EQ(count(setup, ": owns its centres") + count(setup, ": leaves them to its neighbour"), 3u) << setup;
  EXPECT_GE(count(setup, ": owns its centres"), 1u) << "a triangle has a left or bottom edge";
}

TEST(StagePictures, APixelNoTriangleReachesIsBadInput) {
  PixelTrace trace;
  trace.width = trace.height = 4;
  EXPECT_THROW(writeStagePictures(testing::TempDir() + "/stage_none", trace, RenderOutput{}), InputError);
}

}  // namespace
}  // namespace twr
