// `twinraster suite`: over real scenes and bad ones, each compare in a process of its own; the
// index, suite.json and the JUnit file agree with the exit codes, a bad scene is an error case
// and the others still run. In Debian's chromium driven by Playwright
// (tests/browser/check_suite_page.mjs) the index sorts by its columns, shows its thumbnails and
// opens a scene's page, with no console error.
#include "cli_run.h"
#include "missing_dependency.h"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

namespace twr::testcli {
namespace {

const std::string kCli = TWINRASTER_CLI;
const std::string kScenes = kSource + "/assets/scenes/";
const std::string kSmall = " --width 96 --height 72 --jobs 2";

std::size_t count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

// Two shipped scenes, a scene with a syntax error and a file that is not there.
std::string mixedScenes(const std::filesystem::path& dir) {
  std::ofstream(dir / "broken.json") << "{\n  \"camera\": {\n";
  return "\"" + kScenes + "default.json\" \"" + kScenes + "shadow_spot.json\" \"" + (dir / "broken.json").string() +
         "\" \"" + (dir / "missing.json").string() + "\"";
}

TEST(CliSuite, ABadSceneIsAnErrorCaseAndTheOthersStillRun) {
  const auto dir = testDir("suite");
  const RunResult r = runProgram(kCli,
                                 "suite " + mixedScenes(dir) + kSmall + " --targets --out-dir \"" +
                                     (dir / "out").string() + "\" --junit \"" + (dir / "junit.xml").string() + "\"",
                                 dir);
  EXPECT_EQ(r.exitCode, 2) << r.out << r.err;
  expectContains(r.out, "4 scenes in ");
  expectContains(r.out, "2 within targets, 0 over them, 2 bad input");
  // Progress: one line per scene as it ends.
  expectContains(r.err, "twinraster: suite: 4 scenes, 2 at once");
  expectContains(r.err, "/4] passed ");
  EXPECT_EQ(count(r.err, "/4] "), 4u) << r.err;
  for (const char* scene : {"default", "shadow_spot"}) {
    for (const char* file : {"index.html", "pixels.js", "cpu.png", "gl.png", "metrics.json"}) {
      EXPECT_TRUE(std::filesystem::exists(dir / "out" / scene / file)) << scene << "/" << file;
    }
  }
  const nlohmann::json summary = nlohmann::json::parse(readFile(dir / "out" / "suite.json"));
  EXPECT_EQ(summary["exit_code"], 2);
  ASSERT_EQ(summary["cases"].size(), 4u);
  EXPECT_EQ(summary["cases"][0]["outcome"], "passed");
  EXPECT_EQ(summary["cases"][2]["outcome"], "error");
  EXPECT_NE(summary["cases"][2]["message"].get<std::string>().find("broken.json"), std::string::npos)
      << summary["cases"][2]["message"];
  EXPECT_NE(summary["cases"][3]["message"].get<std::string>().find("missing.json"), std::string::npos)
      << summary["cases"][3]["message"];
  const std::string junit = readFile(dir / "junit.xml");
  expectContains(junit, "tests=\"4\" failures=\"0\" errors=\"2\"");
  EXPECT_EQ(count(junit, "<testcase "), 4u);
  EXPECT_EQ(count(junit, "<error type=\"bad_input\""), 2u);
  const std::string index = readFile(dir / "out" / "index.html");
  expectContains(index, "<a href=\"default/index.html\">");
  expectContains(index, "<a href=\"shadow_spot/index.html\">");
}

TEST(CliSuite, OverAThresholdIsAFailureWithTheThresholdLine) {
  const auto dir = testDir("suite");
  // PSNR is capped at 100 dB for identical frames: every scene is under this limit.
  const RunResult r = runProgram(kCli,
                                 "suite \"" + kScenes + "default.json\"" + kSmall +
                                     " --compare-arg=--min-psnr --compare-arg=1000 --out-dir \"" +
                                     (dir / "out").string() + "\" --junit \"" + (dir / "junit.xml").string() + "\"",
                                 dir);
  EXPECT_EQ(r.exitCode, 1) << r.out << r.err;
  const std::string junit = readFile(dir / "junit.xml");
  expectContains(junit, "tests=\"1\" failures=\"1\" errors=\"0\"");
  expectContains(junit, "<failure type=\"threshold\" message=\"");
  expectContains(junit, "psnr");
}

TEST(CliSuite, AFolderStandsForItsScenesAndNoSceneIsBadInput) {
  const auto dir = testDir("suite");
  std::filesystem::create_directories(dir / "empty");
  const RunResult r =
      runProgram(kCli, "suite \"" + (dir / "empty").string() + "\" --out-dir \"" + (dir / "out").string() + "\"", dir);
  EXPECT_EQ(r.exitCode, 2);
  expectContains(r.err, "warning: " + (dir / "empty").string() + ": a folder with no .json scene in it");
  expectContains(r.err, "error: suite: no scene to compare");
}

TEST(BrowserPages, SuitePageSortsShowsThumbnailsAndOpensAScenePage) {
  if (std::system("command -v node >/dev/null 2>&1") != 0) {
    TWR_MISSING_DEPENDENCY("node") << "Debian's nodejs runs the Playwright script";
  }
  if (!std::filesystem::exists("/usr/bin/chromium")) TWR_MISSING_DEPENDENCY("chromium") << "Debian's chromium";
  const std::filesystem::path browserDir = kSource + "/tests/browser";
  if (!std::filesystem::exists(browserDir / "node_modules/playwright-core")) {
    TWR_MISSING_DEPENDENCY("playwright-core") << "npm ci in tests/browser (scripts/install-deps.sh runs it)";
  }
  const auto dir = testDir("suite");
  RunResult r = runProgram(kCli, "suite " + mixedScenes(dir) + " \"" + kScenes + "shadow_directional.json\"" + kSmall +
                                     " --out-dir \"" + (dir / "out").string() + "\"",
                           dir);
  ASSERT_EQ(r.exitCode, 2) << r.out << r.err;
  r = runProgram("node", "\"" + (browserDir / "check_suite_page.mjs").string() + "\" \"" + (dir / "out").string() +
                             "\" \"" + (dir / "suite.png").string() + "\"",
                 dir);
  if (r.exitCode == 77) TWR_MISSING_DEPENDENCY("playwright-core or chromium") << r.out;
  EXPECT_EQ(r.exitCode, 0) << r.out << r.err;
  EXPECT_EQ(r.out.find("FAIL"), std::string::npos) << r.out;
  expectContains(r.out, "ok   sorted by largest difference");
  expectContains(r.out, "ok   opened");
  expectContains(r.out, "ok   no console errors");
}

// scripts/gpu-suite.sh over a pack of this build: on a machine whose only GL is llvmpipe it finds
// no GPU and says so (exit 3) rather than measuring llvmpipe as if it were one.
TEST(GpuSuiteScript, SaysSoWhenNoDeviceButLlvmpipeIsHere) {
  const auto dir = testDir("suite");
  std::filesystem::create_directories(dir / "pack/bin");
  std::filesystem::create_directories(dir / "pack/lib");
  std::filesystem::create_symlink(kCli, dir / "pack/bin/twinraster");
  const RunResult info = runProgram(kCli, "info --gl --json", dir);
  ASSERT_EQ(info.exitCode, 0) << info.err;
  const nlohmann::json contexts = nlohmann::json::parse(info.out)["gl_contexts"];  // kept: the loop reads it
  for (const auto& context : contexts) {
    if (context["error"].is_null() && !context.value("llvmpipe", true)) {
      GTEST_SKIP() << "this machine has a GL that is not llvmpipe: the script would run the whole suite on it";
    }
  }
  const RunResult r = runProgram("bash", "\"" + kSource + "/scripts/gpu-suite.sh\" run \"" + (dir / "pack").string() +
                                             "\" \"" + (dir / "out").string() + "\"",
                                 dir);
  EXPECT_EQ(r.exitCode, 3) << r.out << r.err;
  expectContains(r.err, "gpu-suite: no EGL device other than llvmpipe here");
}

}  // namespace
}  // namespace twr::testcli
