// `twinraster report --quick`: the files exist, the CSV has every knob with both backends,
// the height-field views and their 720p cost rows, and the basis rows, the HTML is
// self-contained but for the height-field pictures written beside it, with an SVG chart per
// knob and per height-field view, progress goes to stderr, and bad options exit 2.
#include "cli_run.h"

#include <gtest/gtest.h>

#include <set>
#include <sstream>

namespace twr::testcli {
namespace {

const std::string kCli = TWINRASTER_CLI;

std::vector<std::string> splitCsvLine(const std::string& line) {
  std::vector<std::string> cells;
  std::string cell;
  bool quoted = false;
  for (char c : line) {
    if (c == '"') {
      quoted = !quoted;
    } else if (c == ',' && !quoted) {
      cells.push_back(cell);
      cell.clear();
    } else {
      cell += c;
    }
  }
  cells.push_back(cell);
  return cells;
}

std::size_t count(const std::string& text, const std::string& part) {
  std::size_t n = 0;
  for (std::size_t at = text.find(part); at != std::string::npos; at = text.find(part, at + part.size())) ++n;
  return n;
}

TEST(CliReport, QuickWritesHtmlAndCsvWithEveryKnob) {
  const std::filesystem::path dir = testDir("cli_report");
  const std::filesystem::path out = dir / "report";
  const RunResult r = runProgram(kCli, "report --quick --assets \"" + kSource + "/assets\" --out \"" + out.string() + "\"", dir);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  ASSERT_TRUE(std::filesystem::exists(out / "report.html"));
  ASSERT_TRUE(std::filesystem::exists(out / "results.csv"));
  EXPECT_FALSE(std::filesystem::exists(out / "work")) << "child-process scratch files are removed";

  // Progress on stderr: which knob, which point, elapsed seconds.
  expectContains(r.err, "[report");
  expectContains(r.err, "tessellation 4x8, cpu:");
  expectContains(r.err, " s] ");
  expectContains(r.out, "report.html");

  const std::string csv = readFile(out / "results.csv");
  std::istringstream lines(csv);
  std::string header;
  std::getline(lines, header);
  const std::vector<std::string> columns = splitCsvLine(header);
  ASSERT_GE(columns.size(), 10u);
  EXPECT_EQ(columns[0], "knob");
  EXPECT_EQ(columns[3], "ms_median");
  EXPECT_EQ(columns[6], "rmse_levels");
  std::set<std::pair<std::string, std::string>> knobBackends;
  std::set<std::string> basisMethods, heightMethods, costSettings, ssrSettings;
  std::string line;
  while (std::getline(lines, line)) {
    const std::vector<std::string> cells = splitCsvLine(line);
    ASSERT_EQ(cells.size(), columns.size()) << line;
    if (cells[0] == "orthonormal_basis") {
      basisMethods.insert(cells[1]);
      continue;
    }
    if (cells[0] == "ssr_march" || cells[0] == "ssr_indirect") {  // time and mean error against the ray tracer
      ssrSettings.insert(cells[0] + " " + cells[1]);
      EXPECT_GT(std::stod(cells[3]), 0.0) << line;
      EXPECT_GE(std::stod(cells[9]), 0.0) << line;
      continue;
    }
    if (cells[0] == "height_fields_cost_720p") {  // timing only
      costSettings.insert(cells[1]);
      EXPECT_GT(std::stod(cells[4]), 0.0) << line;
      continue;
    }
    if (cells[0].rfind("height_fields_", 0) == 0) {
      heightMethods.insert(cells[24]);
      EXPECT_GT(std::stoll(cells[27]), 0) << "interior pixels: " << line;
    }
    knobBackends.insert({cells[0], cells[2]});
    EXPECT_GT(std::stod(cells[3]), 0.0) << "time per frame: " << line;
    EXPECT_GE(std::stod(cells[6]), 0.0) << "rmse: " << line;
  }
  for (const char* knob : {"tessellation", "texture_filter", "minification", "lighting_space", "tangent_transform",
                           "resolution", "threads", "precision"}) {
    EXPECT_TRUE(knobBackends.count({knob, "cpu"})) << knob << " has no cpu row";
    EXPECT_TRUE(knobBackends.count({knob, "gl"})) << knob << " has no gl row";
  }
  EXPECT_TRUE(knobBackends.count({"gl_sampling", "gl"})) << "gl_sampling has no gl row";
  EXPECT_EQ(basisMethods, (std::set<std::string>{"naive_fixed_helper", "naive_best_helper", "frisvad_2012", "duff_2017"}));
  EXPECT_EQ(columns[24], "height_method");
  EXPECT_EQ(columns[27], "interior_pixels");
  for (const char* field : {"bricks", "blocks"}) {
    for (const char* angle : {"0", "45", "70", "85"}) {
      const std::string view = std::string("height_fields_") + field + "_" + angle;
      EXPECT_TRUE(knobBackends.count({view, "cpu"})) << view << " has no cpu row";
      EXPECT_TRUE(knobBackends.count({view, "gl"})) << view << " has no gl row";
    }
    EXPECT_TRUE(std::filesystem::exists(out / (std::string("height_fields_") + field + "_70.png"))) << field;
  }
  EXPECT_EQ(heightMethods, (std::set<std::string>{"heightfield_mesh", "normal_map", "bump_blinn", "bump_emboss",
                                                  "parallax", "parallax_offset_limited", "steep_parallax", "relief",
                                                  "parallax_occlusion"}));
  EXPECT_EQ(costSettings, (std::set<std::string>{"normal_map", "parallax_occlusion 8-32"}));
  expectContains(r.err, "height_fields_bricks_45 parallax_occlusion 8-32, cpu:");
  expectContains(r.err, "height fields 720p:");

  const std::string html = readFile(out / "report.html");
  expectContains(html, "<!DOCTYPE html>");
  // Screen-space reflections against the ray tracer, or why not (a build without Embree).
  expectContains(html, "id=\"ssr\"");
  const bool traced = html.find("this build has no ray tracer") == std::string::npos;
  EXPECT_EQ(count(html, "<svg"), 9u + 8u + 1u + (traced ? 1u : 0u))
      << "one chart per knob, per height-field view, the environment's and SSR's";
  if (traced) {
    for (const char* setting : {"ssr_march linear_world 16 steps, thickness 0.10", "ssr_march hiz 64 steps, thickness 0.10",
                                "ssr_march hiz 64 steps, thickness 0.40", "ssr_march dda_screen 16 steps, thickness 0.10",
                                "ssr_indirect 1 samples", "ssr_indirect 4 samples"}) {
      EXPECT_TRUE(ssrSettings.count(setting)) << setting;
    }
    EXPECT_TRUE(std::filesystem::exists(out / "ssr_vs_traced.png"));
    EXPECT_TRUE(std::filesystem::exists(out / "ssr_indirect_vs_traced.png"));
    expectContains(html, "linear_world's best error is");
    expectContains(html, "mean error vs traced, levels");
  } else {
    EXPECT_TRUE(ssrSettings.empty());
  }
  expectContains(html, "id=\"environment_parameterizations\"");
  expectContains(html, "<img src=\"env_sphere_error.png\"");
  for (const char* picture : {"env_sphere_map.png", "env_sphere_error.png", "env_dual_paraboloid_map.png",
                              "env_dual_paraboloid_error.png", "env_irradiance.png", "env_sh9.png", "env_sh9_error.png"}) {
    EXPECT_TRUE(std::filesystem::exists(out / picture)) << picture;
  }
  expectContains(html, "id=\"environment_diffuse\"");
  expectContains(html, "SH9 vs Monte Carlo");
  expectContains(html, "Monte Carlo: 2048 samples per normal");
  expectContains(html, "id=\"height_fields\"");
  expectContains(html, "Parallax does not move silhouettes");
  expectContains(html, "<img src=\"height_fields_bricks_70.png\"");
  expectContains(html, "time per frame, ms");
  expectContains(html, "RMSE vs reference, levels");
  expectContains(html, "duff_2017");
  EXPECT_EQ(html.find("http://"), std::string::npos) << "self-contained: no links out";
  EXPECT_EQ(html.find("https://"), std::string::npos) << "self-contained: no links out";
  EXPECT_EQ(html.find("<script"), std::string::npos);
}

TEST(CliReport, BadAssetsFolderExitsTwo) {
  const std::filesystem::path dir = testDir("cli_report");
  const RunResult r = runProgram(kCli, "report --quick --assets \"" + dir.string() + "\" --out \"" + (dir / "r").string() + "\"", dir);
  EXPECT_EQ(r.exitCode, 2);
  expectContains(r.err, "--assets");
  expectContains(r.err, "scenes/default.json");
}

}  // namespace
}  // namespace twr::testcli
