// `twinraster trace SCENE X Y --stages DIR`: the stage pictures of the triangle that wrote the
// pixel, beside the usual trace (text or --json unchanged), and bad input named.
#include "cli_run.h"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

namespace twr::testcli {
namespace {

const std::string kCli = TWINRASTER_CLI;
const std::string kScene = kSource + "/assets/scenes/inside_near.json";

TEST(CliTraceStages, WritesAPicturePerStageForATriangleTheNearAndSidePlanesCut) {
  const auto dir = testDir("trace_stages");
  // Pixel (62, 10) of inside_near at 64x48: the triangle that wrote it is cut by the near, the
  // right, the top and the bottom plane.
  const RunResult r = runProgram(kCli, "trace \"" + kScene + "\" 62 10 --width 64 --height 48 --json --stages \"" +
                                           (dir / "stages").string() + "\"", dir);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const nlohmann::json trace = nlohmann::json::parse(r.out);  // stdout stays the JSON alone
  bool nearAndSide = false;
  for (const auto& visit : trace["triangles"]) {
    if (visit["triangle"] != trace["final"]["triangle"]) continue;
    const auto& planes = visit["clip_planes"];
    const auto has = [&](const char* name) { return std::find(planes.begin(), planes.end(), name) != planes.end(); };
    nearAndSide = has("near") && (has("left") || has("right"));
  }
  EXPECT_TRUE(nearAndSide) << trace["triangles"].dump();
  expectContains(r.err, "wrote " + (dir / "stages").string() + "/index.html and 7 stage pictures");
  // One per stage, listed in the pipeline's order.
  const char* const files[] = {"0_vertex.svg", "1_clip.svg",        "1_divide.svg", "2_setup.svg",
                               "2_raster.svg", "3_interpolate.svg", "4_shade.svg"};
  const std::string index = readFile(dir / "stages" / "index.html");
  std::size_t previous = 0;
  for (const char* file : files) {
    ASSERT_TRUE(std::filesystem::exists(dir / "stages" / file)) << file;
    const std::string svg = readFile(dir / "stages" / file);
    EXPECT_EQ(svg.rfind("<svg ", 0), 0u) << file;
    EXPECT_NE(svg.find("</svg>"), std::string::npos) << file;
    const std::size_t at = index.find(std::string("<img src=\"") + file + "\"");
    ASSERT_NE(at, std::string::npos) << file;
    EXPECT_GE(at, previous) << file << " out of the pipeline's order";
    previous = at;
  }
  // The numbers drawn are the trace's: the clip positions, the window positions, the fill rule.
  const std::string vertex = readFile(dir / "stages" / "0_vertex.svg");
  expectContains(vertex, "outside");
  expectContains(readFile(dir / "stages" / "2_setup.svg"), "owns its centres");
  expectContains(index, "Triangle " + std::to_string(trace["final"]["triangle"].get<int>()) + " (");
  expectContains(index, "<img src=\"2_raster.svg\"");
  expectContains(index, "cut by right, top, bottom, near");
}

TEST(CliTraceStages, APixelNoTriangleReachesSaysSo) {
  const auto dir = testDir("trace_stages");
  // The default scene's top-left corner is background.
  const RunResult r = runProgram(kCli, "trace \"" + kSource + "/assets/scenes/default.json\" 0 0 --width 64 --height 48 "
                                           "--stages \"" + (dir / "stages").string() + "\"", dir);
  EXPECT_EQ(r.exitCode, 2);
  expectContains(r.err, "trace --stages: no triangle reaches pixel (0, 0)");
}

}  // namespace
}  // namespace twr::testcli
