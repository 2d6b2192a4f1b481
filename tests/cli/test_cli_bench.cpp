// `twinraster bench`: the JSON object's keys and their consistency, the lean GL frame, the
// CPU target and --all-isas, the precise-sampling child process, the text summary, and exit
// 2 on bad input. Tiny images and two frames: timings are never asserted, only that they
// are there, positive, ordered and that every ratio is the quotient of its medians.
#include "cli_run.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <string>
#include <vector>

namespace twr::testcli {
namespace {

const std::string kDefaultScene = kSource + "/assets/scenes/default.json";
const std::string kTiny = " --width 48 --height 32 --frames 2 --warmup 1";

RunResult runCli(const std::string& args) { return runProgram(TWINRASTER_CLI, args, testDir("cli_bench")); }

// What `info --json` says this machine runs, best first.
std::vector<std::string> supportedTargets() {
  const RunResult r = runCli("info --json \"" + kDefaultScene + "\"");
  EXPECT_EQ(r.exitCode, 0) << r.err;
  return nlohmann::json::parse(r.out).at("cpu_isas_supported").get<std::vector<std::string>>();
}

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
  // The fast path on the best target this machine runs (auto), named in both keys.
  const std::string best = supportedTargets().front();
  EXPECT_EQ(j["cpu_path"], "fast (" + best + ")");
  EXPECT_EQ(j["cpu_isa"], best);
  EXPECT_EQ(j["cpu_isas_supported"].get<std::vector<std::string>>(), supportedTargets());
}

TEST(CliBench, LeanGlFrameIsTimedBesideTheFullOne) {
  const RunResult r = runCli("bench \"" + kDefaultScene + "\"" + kTiny + " --threads 1 --json");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const nlohmann::json j = parseJson(r);
  expectTimingKeys(j, "gl_lean", 2);
  ASSERT_TRUE(j.contains("ratio_cpu_over_gl_lean"));
  EXPECT_DOUBLE_EQ(j["ratio_cpu_over_gl_lean"].get<double>(),
                   j["cpu_ms_median"].get<double>() / j["gl_lean_ms_median"].get<double>());
  EXPECT_GT(j["ratio_cpu_over_gl_lean"].get<double>(), 0.0);
  // The lean frame draws the same picture: the same covered pixels.
  EXPECT_EQ(j["covered_pixels_gl_lean"], j["covered_pixels"]);
  const double leanReadback = j["gl_lean_readback_ms_median"];
  EXPECT_GE(leanReadback, 0.0);
  EXPECT_LE(leanReadback, j["gl_lean_ms_max"].get<double>());
  EXPECT_GT(j["gl_lean_ns_per_covered_pixel"].get<double>(), 0.0);
  EXPECT_FALSE(j.contains("per_isa")) << "only with --all-isas";
}

TEST(CliBench, AllIsasTimesEverySupportedTargetAgainstTheLeanFrame) {
  const RunResult r = runCli("bench \"" + kDefaultScene + "\"" + kTiny + " --threads 1 --all-isas --json");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const nlohmann::json j = parseJson(r);
  const std::vector<std::string> supported = supportedTargets();
  ASSERT_TRUE(j["per_isa"].is_array());
  ASSERT_EQ(j["per_isa"].size(), supported.size());
  const double glLean = j["gl_lean_ms_median"];
  for (std::size_t i = 0; i < supported.size(); ++i) {
    const nlohmann::json& entry = j["per_isa"][i];
    EXPECT_EQ(entry.size(), 3u) << entry.dump();
    EXPECT_EQ(entry["cpu_isa"], supported[i]);
    const double ms = entry["cpu_ms_median"];
    EXPECT_GT(ms, 0.0) << supported[i];
    EXPECT_DOUBLE_EQ(entry["ratio_cpu_over_gl_lean"].get<double>(), ms / glLean) << supported[i];
  }
  // The main CPU timing stays the default path's.
  EXPECT_EQ(j["cpu_isa"], supported.front());

  const RunResult text = runCli("bench \"" + kDefaultScene + "\"" + kTiny + " --threads 1 --all-isas");
  ASSERT_EQ(text.exitCode, 0) << text.err;
  expectContains(text.out, "fast path per target");
  for (const std::string& target : supported) expectContains(text.out, "    " + target + " ");
}

TEST(CliBench, CpuPathOptionsPickTheTraversal) {
  const RunResult teaching = runCli("bench \"" + kDefaultScene + "\"" + kTiny + " --cpu-path teaching --json");
  ASSERT_EQ(teaching.exitCode, 0) << teaching.err;
  EXPECT_EQ(parseJson(teaching)["cpu_path"], "teaching");
  EXPECT_TRUE(parseJson(teaching)["cpu_isa"].is_null()) << "the teaching path runs no SIMD kernels";
  // --cpu-scalar, the old spelling, is --cpu-isa scalar: the same run, or where this build has
  // no scalar kernels (CMake's TWINRASTER_KERNEL_TARGETS, the sanitizer build) the same refusal.
  const RunResult scalar = runCli("bench \"" + kDefaultScene + "\"" + kTiny + " --cpu-scalar --json");
  const RunResult isa = runCli("bench \"" + kDefaultScene + "\"" + kTiny + " --cpu-isa scalar --json");
  const std::vector<std::string> supported = supportedTargets();
  nlohmann::json fast;  // a fast-path run: the scalar one, else the last target this build has
  if (std::find(supported.begin(), supported.end(), "scalar") == supported.end()) {
    EXPECT_EQ(scalar.exitCode, 2) << scalar.out;
    expectContains(scalar.err, "--cpu-isa: scalar: not compiled into this binary");
    EXPECT_EQ(isa.exitCode, 2) << isa.out;
    expectContains(isa.err, "--cpu-isa: scalar: not compiled into this binary");
    const RunResult last = runCli("bench \"" + kDefaultScene + "\"" + kTiny + " --cpu-isa " + supported.back() + " --json");
    ASSERT_EQ(last.exitCode, 0) << last.err;
    fast = parseJson(last);
    EXPECT_EQ(fast["cpu_path"], "fast (" + supported.back() + ")");
  } else {
    ASSERT_EQ(scalar.exitCode, 0) << scalar.err;
    fast = parseJson(scalar);
    EXPECT_EQ(fast["cpu_path"], "fast (scalar)");
    EXPECT_EQ(fast["cpu_isa"], "scalar");
    ASSERT_EQ(isa.exitCode, 0) << isa.err;
    EXPECT_EQ(parseJson(isa)["cpu_path"], "fast (scalar)");
  }
  // The traversal changes the time, never the picture.
  EXPECT_EQ(fast["covered_pixels"], parseJson(teaching)["covered_pixels"]);
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
  expectContains(r.out, "  gl lean (fast) ");
  expectContains(r.out, "ratio cpu/gl ");
  expectContains(r.out, ", cpu/gl lean ");
  expectContains(r.out, "  cpu target: " + supportedTargets().front() + "; this machine runs ");
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
      {"bench \"" + kDefaultScene + "\" --cpu-isa quick", "--cpu-isa"},
      {"bench \"" + kDefaultScene + "\" --cpu-isa " + supportedTargets().front() + " --cpu-scalar", "--cpu-scalar"},
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
