// `twinraster compare --html`: the page and its files are written, self-contained (nothing
// fetched from a network), and, in Debian's chromium driven by Playwright
// (tests/browser/check_compare_page.mjs), the readout under the pointer shows the CPU's values
// exactly as `trace --json` reports them at that pixel, the slider, zoom, heat map and buffer
// rows work, and the page logs no error.
#include "cli_run.h"
#include "missing_dependency.h"

#include <gtest/gtest.h>

namespace twr::testcli {
namespace {

const std::string kCli = TWINRASTER_CLI;
const std::string kScene = kSource + "/assets/scenes/default.json";

bool haveCommand(const std::string& name) {
  return std::system(("command -v " + name + " >/dev/null 2>&1").c_str()) == 0;
}

TEST(CliComparePage, WritesASelfContainedPageBesideTheImages) {
  const auto dir = testDir("compare_page");
  const RunResult r = runProgram(kCli, "compare \"" + kScene + "\" --width 160 --height 120 --html --out-dir \"" +
                                           dir.string() + "\"", dir);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  expectContains(r.out, "wrote " + (dir / "index.html").string());
  for (const char* file : {"index.html", "pixels.js", "page_heat.png", "page_classes.png", "cpu.png", "gl.png"}) {
    EXPECT_TRUE(std::filesystem::exists(dir / file)) << file;
  }
  const std::string page = readFile(dir / "index.html");
  // Self-contained: inline style and script, images and pixels.js beside it, no network.
  EXPECT_EQ(page.find("http://"), std::string::npos);
  EXPECT_EQ(page.find("https://"), std::string::npos);
  expectContains(page, "<style>");
  expectContains(page, "<script src=\"pixels.js\"></script>");
  expectContains(page, "src=\"cpu.png\"");
  expectContains(page, "no targets");  // no threshold asked for
  const std::string pixels = readFile(dir / "pixels.js");
  expectContains(pixels, "window.twrPixels = {");
  expectContains(pixels, "\"width\":160");
  expectContains(pixels, "\"no_triangle\":4294967295");
}

TEST(CliComparePage, WithoutHtmlNoPageIsWritten) {
  const auto dir = testDir("compare_page");
  const RunResult r =
      runProgram(kCli, "compare \"" + kScene + "\" --width 64 --height 48 --out-dir \"" + dir.string() + "\"", dir);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "index.html"));
  EXPECT_FALSE(std::filesystem::exists(dir / "pixels.js"));
}

TEST(BrowserPages, ComparePageShowsTheTracedValuesUnderThePointer) {
  if (!haveCommand("node")) TWR_MISSING_DEPENDENCY("node") << "Debian's nodejs runs the Playwright script";
  const std::string chromium = "/usr/bin/chromium";
  if (!std::filesystem::exists(chromium)) TWR_MISSING_DEPENDENCY("chromium") << "Debian's chromium draws the page";
  const std::filesystem::path browserDir = kSource + "/tests/browser";
  if (!std::filesystem::exists(browserDir / "node_modules/playwright-core")) {
    TWR_MISSING_DEPENDENCY("playwright-core") << "npm ci in tests/browser (scripts/install-deps.sh runs it)";
  }
  const auto dir = testDir("compare_page");
  const std::string size = " --width 320 --height 240";
  RunResult r = runProgram(kCli, "compare \"" + kScene + "\"" + size + " --html --targets --all-buffers --out-dir \"" +
                                     (dir / "page").string() + "\"", dir);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  // The traced pixel: on the sphere in the default scene.
  r = runProgram(kCli, "trace \"" + kScene + "\" 130 110" + size + " --json", dir);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  {
    std::ofstream trace(dir / "trace.json");
    trace << r.out;
  }
  r = runProgram("node", "\"" + (browserDir / "check_compare_page.mjs").string() + "\" \"" + (dir / "page").string() +
                             "\" \"" + (dir / "trace.json").string() + "\" \"" + (dir / "page.png").string() + "\"",
                 dir);
  if (r.exitCode == 77) TWR_MISSING_DEPENDENCY("playwright-core or chromium") << r.out;
  EXPECT_EQ(r.exitCode, 0) << r.out << r.err;
  EXPECT_EQ(r.out.find("FAIL"), std::string::npos) << r.out;
  expectContains(r.out, "ok   cpu depth");
  expectContains(r.out, "ok   no console errors");
}

}  // namespace
}  // namespace twr::testcli
