// `twinraster bench`: the JSON object's keys and their consistency, the precise-sampling
// child process, the text summary, and exit 2 on bad input. Tiny images and two frames:
// timings are never asserted, only that they are there and ordered.
#include "cli_run.h"

#include <nlohmann/json.hpp>

#include <string>

namespace twr::testcli {
namespace {

const std::string kDefaultScene = kSource + "/assets/scenes/default.json";
const std::string kTiny = " --width 48 --height 32 --frames 2 --warmup 1";

RunResult runCli(const std::string& args) { return runProgram(TWINRASTER_CLI, args, testDir("cli_bench")); }

nlohmann::json parseJson(const RunResult& r) {
  nlohmann::json j;
  EXPECT_NO_THROW(j = nlohmann::json::parse(r.out)) << r.out;
  return j;
}

void expectTimingKeys(const nlohmann::json& j, const std::string& prefix, std::size_t frames) {
  for (const char* key : {"_ms_median", "_ms_min", "_ms_max", "_ms_q1", "_ms_q3", "_ms_frames",
                          "_process_cpu_ms_median"}) {
    ASSERT_TRUE(j.contains(prefix + key)) << prefix + key;
  }
  EXPECT_EQ(j[prefix + "_ms_frames"].size(), frames);
  const double min = j[prefix + "_ms_min"], median = j[prefix + "_ms_median"], max = j[prefix + "_ms_max"];
  EXPECT_GT(min, 0.0);
  EXPECT_LE(min, median);
  EXPECT_LE(median, max);
}

TEST(CliBench, JsonHasTheDocumentedKeys) {
  const RunResult r = runCli("bench \"" + kDefaultScene + "\"" + kTiny + " --threads 1 --json");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const nlohmann::json j = parseJson(r);
  for (const char* key : {"cpu_ms_median", "gl_ms_median", "cpu_ms_min", "gl_ms_min", "ratio_cpu_over_gl",
                          "covered_pixels", "triangles", "threads"}) {
    EXPECT_TRUE(j.contains(key)) << key;
  }
  expectTimingKeys(j, "cpu", 2);
  expectTimingKeys(j, "gl", 2);
  EXPECT_EQ(j["threads"], 1);
  EXPECT_EQ(j["width"], 48);
  EXPECT_EQ(j["height"], 32);
  EXPECT_EQ(j["frames"], 2);
  EXPECT_EQ(j["triangles"], 3982);  // hand-counted in test_cli_info.cpp
  // The floor fills the lower part of the view: something, not everything, is covered, and
  // both backends cover the same pixels.
  EXPECT_GT(j["covered_pixels"].get<int>(), 0);
  EXPECT_LT(j["covered_pixels"].get<int>(), 48 * 32);
  EXPECT_EQ(j["covered_pixels"], j["covered_pixels_gl"]);
  EXPECT_DOUBLE_EQ(j["ratio_cpu_over_gl"].get<double>(),
                   j["cpu_ms_median"].get<double>() / j["gl_ms_median"].get<double>());
  EXPECT_EQ(j["gl_sampling"], "fast") << "bench times llvmpipe as a user gets it";
  EXPECT_FALSE(j.contains("gl_precise_ms_median"));
  const std::string path = j["cpu_path"];
  EXPECT_TRUE(path == "fast (avx512)" || path == "fast (scalar)") << path;
}

TEST(CliBench, CpuPathOptionsPickTheTraversal) {
  const RunResult teaching = runCli("bench \"" + kDefaultScene + "\"" + kTiny + " --cpu-path teaching --json");
  ASSERT_EQ(teaching.exitCode, 0) << teaching.err;
  EXPECT_EQ(parseJson(teaching)["cpu_path"], "teaching");
  const RunResult scalar = runCli("bench \"" + kDefaultScene + "\"" + kTiny + " --cpu-scalar --json");
  ASSERT_EQ(scalar.exitCode, 0) << scalar.err;
  const nlohmann::json j = parseJson(scalar);
  EXPECT_EQ(j["cpu_path"], "fast (scalar)");
  // The traversal changes the time, never the picture.
  EXPECT_EQ(j["covered_pixels"], parseJson(teaching)["covered_pixels"]);
}

TEST(CliBench, GlPreciseRunsAChildProcessAndMergesItsFigures) {
  const RunResult r = runCli("bench \"" + kDefaultScene + "\"" + kTiny + " --threads 2 --gl-precise --json");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const nlohmann::json j = parseJson(r);
  expectTimingKeys(j, "gl_precise", 2);
  ASSERT_TRUE(j.contains("ratio_cpu_over_gl_precise"));
  EXPECT_DOUBLE_EQ(j["ratio_cpu_over_gl_precise"].get<double>(),
                   j["cpu_ms_median"].get<double>() / j["gl_precise_ms_median"].get<double>());
  EXPECT_EQ(j["gl_sampling"], "fast");
  EXPECT_EQ(j["threads"], 2);
}

TEST(CliBench, TextSummaryNamesBothBackendsAndTheRatio) {
  const RunResult r = runCli("bench \"" + kDefaultScene + "\"" + kTiny);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  expectContains(r.out, "at 48x32: 3982 triangles");
  expectContains(r.out, "  cpu ");
  expectContains(r.out, "  gl (fast) ");
  expectContains(r.out, "ratio cpu/gl ");
}

TEST(CliBench, BadInputExitsTwo) {
  struct Case {
    std::string args, message;
  };
  const Case cases[] = {
      {"bench \"" + kDefaultScene + "\" --frames 0", "--frames"},
      {"bench \"" + kDefaultScene + "\" --warmup -1", "--warmup"},
      {"bench \"" + kDefaultScene + "\" --threads 0", "--threads"},
      {"bench \"" + kDefaultScene + "\" --threads 65", "--threads"},
      {"bench \"" + kDefaultScene + "\" --view nonsense", "--view"},
      {"bench \"" + kDefaultScene + "\" --cpu-path quick", "--cpu-path"},
      {"bench \"" + kDefaultScene + "\" --width 0", "--width"},
      {"bench \"" + kSource + "/assets/scenes/no_such_scene.json\"", "no_such_scene.json"},
      {"bench", "scene"},
  };
  for (const Case& c : cases) {
    const RunResult r = runCli(c.args);
    EXPECT_EQ(r.exitCode, 2) << c.args << "\n" << r.err;
    expectContains(r.err, c.message);
    EXPECT_EQ(r.out.find("ratio"), std::string::npos) << c.args;
  }
}

}  // namespace
}  // namespace twr::testcli
