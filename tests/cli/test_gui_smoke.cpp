// twinraster-gui under Xvfb: the app starts, draws the UI and the scene in each view mode,
// saves a screenshot of the whole window, remembers its settings, survives a bad scene
// path, and quits after --frames. Skipped (with the reason) when xvfb-run or the GUI
// binary is missing. The GUI binary sits next to the CLI (build/app/), so its path comes
// from TWINRASTER_CLI at run time.
#include "scene/image.h"
#include "tests/missing_dependency.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <set>
#include <sstream>
#include <string>

namespace {

namespace fs = std::filesystem;

const std::string kSource = TWINRASTER_SOURCE_DIR;
const std::string kDefaultScene = kSource + "/assets/scenes/default.json";
// The window the smoke runs open, screen coordinates (the app's default size).
constexpr int kWindowWidth = 1280;
constexpr int kWindowHeight = 800;
// Frames per run: enough for ImGui to lay out its windows (it sizes them on frame 2).
constexpr int kFrames = 30;

// Colours the app draws, 8-bit, as set in app/gui (hand-converted: round(f * 255)).
struct Rgb {
  int r, g, b;
};
constexpr Rgb kPanelBackground{28, 28, 33};   // ImGuiCol_WindowBg (0.11, 0.11, 0.13)
constexpr Rgb kErrorBanner{89, 20, 20};       // the scene error banner (0.35, 0.08, 0.08)
constexpr Rgb kPinMarker{255, 230, 40};       // the pinned-pixel marker
constexpr Rgb kCheckerDark{40, 40, 40};       // compare/colours.h: empty pixels in the diff map
constexpr Rgb kCheckerLight{64, 64, 64};

fs::path guiBinary() { return fs::path(TWINRASTER_CLI).parent_path() / "twinraster-gui"; }

bool haveXvfbRun() { return std::system("command -v xvfb-run >/dev/null 2>&1") == 0; }

std::string readFile(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

struct RunResult {
  int exitCode = -1;
  std::string out, err;
  fs::path dir;  // this test's folder: config/, shot.png, out, err
};

std::string testName() {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  return std::string(info->test_suite_name()) + "_" + info->name();
}

// The current test's folder (kept between runs: tests that need a clean config pass --reset).
fs::path testDir() {
  const fs::path dir = fs::path(TWINRASTER_TEST_OUT) / "gui_smoke" / testName();
  return dir;
}

// Runs `prefix` XDG_CONFIG_HOME=<the test's folder> [xvfb-run ...] twinraster-gui `args`.
RunResult runGui(const std::string& args, bool underXvfb = true, const std::string& prefix = "") {
  RunResult result;
  result.dir = testDir();
  fs::create_directories(result.dir);
  const fs::path out = result.dir / "out.txt", err = result.dir / "err.txt";
  std::string command = prefix + "XDG_CONFIG_HOME=\"" + (result.dir / "config").string() + "\" ";
  if (underXvfb) command += "xvfb-run -a -s \"-screen 0 " + std::to_string(kWindowWidth) + "x" +
                            std::to_string(kWindowHeight) + "x24\" ";
  command += "\"" + guiBinary().string() + "\" " + args + " >\"" + out.string() + "\" 2>\"" + err.string() + "\"";
  const int status = std::system(command.c_str());
  result.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  result.out = readFile(out);
  result.err = readFile(err);
  return result;
}

#define REQUIRE_GUI_AND_XVFB()                                                                        \
  do {                                                                                                \
    if (!fs::exists(guiBinary())) TWR_MISSING_DEPENDENCY("twinraster-gui") << "it was not built (TWINRASTER_BUILD_GUI=OFF): " << guiBinary(); \
    if (!haveXvfbRun()) TWR_MISSING_DEPENDENCY("xvfb-run") << "Debian packages xvfb and xauth: no X server to open a window on"; \
  } while (false)

bool near(const std::uint8_t* p, Rgb c, int tolerance) {
  return std::abs(p[0] - c.r) <= tolerance && std::abs(p[1] - c.g) <= tolerance && std::abs(p[2] - c.b) <= tolerance;
}

// Pixels in [x0, x1) x [y0, y1) for which `test` holds.
int countPixels(const twr::Image& image, int x0, int y0, int x1, int y1,
                const std::function<bool(const std::uint8_t*)>& test) {
  int count = 0;
  for (int y = y0; y < y1; ++y) {
    for (int x = x0; x < x1; ++x) count += test(image.pixel(x, y)) ? 1 : 0;
  }
  return count;
}

std::size_t distinctColours(const twr::Image& image) {
  std::set<std::uint32_t> colours;
  for (std::size_t i = 0; i < image.rgba.size(); i += 4) {
    colours.insert(image.rgba[i] << 16 | image.rgba[i + 1] << 8 | image.rgba[i + 2]);
  }
  return colours.size();
}

// Brick red: the default scene's diffuse map, lit. Red clearly above green and blue.
bool brickRed(const std::uint8_t* p) { return p[0] > 60 && p[0] > p[1] + 25 && p[0] > p[2] + 25; }

// The window shot: right size, many colours (not one flat fill).
twr::Image loadShot(const fs::path& path) {
  EXPECT_TRUE(fs::exists(path)) << path;
  twr::Image image = twr::loadPng(path.string());
  EXPECT_EQ(image.width, kWindowWidth);
  EXPECT_EQ(image.height, kWindowHeight);
  EXPECT_GT(distinctColours(image), 200u) << "the screenshot is nearly flat";
  return image;
}

// The controls panel is on the left, the view on the right (app/gui/panel_layout.cpp); these
// spans are inside them at the default size whatever the fonts: the panel is >= 280 points.
constexpr int kPanelX1 = 270;
constexpr int kViewX0 = 420;
// Rows inside the image area of the view at the default size (below the toolbar rows,
// above the stats panel of 270 points).
constexpr int kImageBandY0 = 200;
constexpr int kImageBandY1 = 480;

TEST(GuiSmoke, SideBySideShowsTheUiAndBothImages) {
  REQUIRE_GUI_AND_XVFB();
  const fs::path shot = testDir() / "side.png";
  fs::remove(shot);
  const RunResult r = runGui("\"" + kDefaultScene + "\" --reset --frames " + std::to_string(kFrames) +
                             " --view-mode side --screenshot \"" + shot.string() + "\"");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const twr::Image image = loadShot(shot);
  // The UI: much of the controls panel is its background colour.
  const int panelPixels = countPixels(image, 0, 0, kPanelX1, kWindowHeight, [](const std::uint8_t* p) {
    return near(p, kPanelBackground, 1);
  });
  EXPECT_GT(panelPixels, kPanelX1 * kWindowHeight / 4) << "the controls panel is not there";
  // The scene: brick-red pixels in both halves of the view (CPU left, GL right).
  const int middle = (kViewX0 + kWindowWidth) / 2;
  EXPECT_GT(countPixels(image, kViewX0, 0, middle, kWindowHeight, brickRed), 5000) << "no CPU image";
  EXPECT_GT(countPixels(image, middle, 0, kWindowWidth, kWindowHeight, brickRed), 5000) << "no GL image";
}

TEST(GuiSmoke, DiffViewShowsTheHeatMap) {
  REQUIRE_GUI_AND_XVFB();
  const fs::path shot = testDir() / "diff.png";
  fs::remove(shot);
  const RunResult r = runGui("\"" + kDefaultScene + "\" --reset --frames " + std::to_string(kFrames) +
                             " --view-mode diff --screenshot \"" + shot.string() + "\"");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const twr::Image image = loadShot(shot);
  // The sky is empty in both renders, so the heat map shows it as the dark checker; the
  // bricks are gone from the image (where the renders agree the heat map is black). The
  // band checked lies below the toolbar and its heat-ramp legend, above the stats panel.
  const auto checker = [](const std::uint8_t* p) { return near(p, kCheckerDark, 0) || near(p, kCheckerLight, 0); };
  EXPECT_GT(countPixels(image, kViewX0, 0, kWindowWidth, kWindowHeight, checker), 10000);
  EXPECT_LT(countPixels(image, kViewX0, kImageBandY0, kWindowWidth, kImageBandY1, brickRed), 500);
}

TEST(GuiSmoke, SplitViewWithAPinnedPixel) {
  REQUIRE_GUI_AND_XVFB();
  const fs::path shot = testDir() / "split.png";
  fs::remove(shot);
  const RunResult r = runGui("\"" + kDefaultScene + "\" --reset --frames " + std::to_string(kFrames) +
                             " --view-mode split --pin 320,300 --screenshot \"" + shot.string() + "\"");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const twr::Image image = loadShot(shot);
  EXPECT_GT(countPixels(image, kViewX0, 0, kWindowWidth, kWindowHeight, brickRed), 5000);
  // The marker is drawn around the pinned pixel in the view.
  EXPECT_GT(countPixels(image, kViewX0, 0, kWindowWidth, kWindowHeight,
                        [](const std::uint8_t* p) { return near(p, kPinMarker, 2); }),
            8);
}

// GL renders on a worker in its own headless context (docs/gui.md): immediate-mode lines get a
// compatibility context there, and the window is never recreated for them.
TEST(GuiSmoke, ImmediateModeLinesDrawOnTheGlWorker) {
  REQUIRE_GUI_AND_XVFB();
  // assets/scenes/tbn_lines.json with the lines in immediate mode, its texture paths made absolute.
  std::string json = readFile(kSource + "/assets/scenes/tbn_lines.json");
  const auto replaceAll = [&json](const std::string& from, const std::string& to) {
    for (std::size_t at = json.find(from); at != std::string::npos; at = json.find(from, at + to.size())) {
      json.replace(at, from.size(), to);
    }
  };
  replaceAll("\"mode\": \"core\"", "\"mode\": \"immediate\"");
  replaceAll("\"../textures/", "\"" + kSource + "/assets/textures/");
  ASSERT_NE(json.find("\"immediate\""), std::string::npos) << "tbn_lines.json no longer sets the line mode";
  fs::create_directories(testDir());
  const fs::path scene = testDir() / "tbn_immediate.json";
  std::ofstream(scene) << json;
  const fs::path shot = testDir() / "immediate.png";
  fs::remove(shot);
  const RunResult r = runGui("\"" + scene.string() + "\" --reset --frames " + std::to_string(kFrames) +
                             " --view-mode gl --screenshot \"" + shot.string() + "\"");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(r.err.find("recreated the window"), std::string::npos) << r.err;
  const twr::Image image = loadShot(shot);
  // The GL image shows the lines: saturated red T, green B and blue N pixels.
  const auto pure = [](int channel) {
    return [channel](const std::uint8_t* p) {
      for (int c = 0; c < 3; ++c) {
        if (c == channel ? p[c] < 200 : p[c] > 60) return false;
      }
      return true;
    };
  };
  for (int channel = 0; channel < 3; ++channel) {
    EXPECT_GT(countPixels(image, kViewX0, kImageBandY0 - 100, kWindowWidth, kImageBandY1, pure(channel)), 50)
        << "no lines of channel " << channel;
  }
}

TEST(GuiSmoke, TeachingPathAndTargetComeFromTheCommandLineAndAreRemembered) {
  REQUIRE_GUI_AND_XVFB();
  const fs::path prefs = testDir() / "config" / "twinraster" / "gui.json";
  const fs::path shot = testDir() / "teaching.png";
  fs::remove(shot);
  // The teaching path draws the CPU image (left) as the fast one does.
  RunResult r = runGui("\"" + kDefaultScene + "\" --reset --frames " + std::to_string(kFrames) +
                       " --view-mode side --cpu-path teaching --screenshot \"" + shot.string() + "\"");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const twr::Image image = loadShot(shot);
  const int middle = (kViewX0 + kWindowWidth) / 2;
  EXPECT_GT(countPixels(image, kViewX0, 0, middle, kWindowHeight, brickRed), 5000) << "no CPU image";
  nlohmann::json saved = nlohmann::json::parse(readFile(prefs));
  EXPECT_EQ(saved.at("cpu_path"), "teaching");
  EXPECT_EQ(saved.at("cpu_isa"), "auto");
  // The next run starts from the remembered path; --cpu-isa picks the fast path's target.
  r = runGui("\"" + kDefaultScene + "\" --frames 3 --cpu-isa scalar");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  saved = nlohmann::json::parse(readFile(prefs));
  EXPECT_EQ(saved.at("cpu_path"), "teaching");
  EXPECT_EQ(saved.at("cpu_isa"), "scalar");
}

TEST(GuiSmoke, BadScenePathShowsAnErrorAndKeepsRunning) {
  REQUIRE_GUI_AND_XVFB();
  const fs::path shot = testDir() / "bad.png";
  fs::remove(shot);
  const std::string missing = (testDir() / "no_such_scene.json").string();
  const RunResult r = runGui("\"" + missing + "\" --reset --frames 10 --screenshot \"" + shot.string() + "\"");
  ASSERT_EQ(r.exitCode, 0) << "a bad scene is shown in the window, not fatal:\n" << r.err;
  EXPECT_NE(r.err.find(missing), std::string::npos) << r.err;
  const twr::Image image = twr::loadPng(shot.string());
  EXPECT_GT(countPixels(image, kViewX0, 0, kWindowWidth, kWindowHeight / 4,
                        [](const std::uint8_t* p) { return near(p, kErrorBanner, 2); }),
            2000)
      << "no error banner over the view";
}

TEST(GuiSmoke, SettingsPersistAndResetClearsThem) {
  REQUIRE_GUI_AND_XVFB();
  const fs::path prefs = testDir() / "config" / "twinraster" / "gui.json";
  const std::string common = "\"" + kDefaultScene + "\" --frames 3";
  ASSERT_EQ(runGui(common + " --reset --view-mode flicker").exitCode, 0);
  ASSERT_TRUE(fs::exists(prefs));
  EXPECT_EQ(nlohmann::json::parse(readFile(prefs)).at("view_mode"), "flicker");
  // A second run without --view-mode starts from (and saves again) the remembered mode.
  ASSERT_EQ(runGui(common).exitCode, 0);
  EXPECT_EQ(nlohmann::json::parse(readFile(prefs)).at("view_mode"), "flicker");
  EXPECT_TRUE(fs::exists(testDir() / "config" / "twinraster" / "imgui.ini"));
  // --reset forgets it: the run saves the default (side by side) again.
  const RunResult reset = runGui(common + " --reset");
  ASSERT_EQ(reset.exitCode, 0) << reset.err;
  EXPECT_NE(reset.err.find("--reset: removed"), std::string::npos) << reset.err;
  EXPECT_EQ(nlohmann::json::parse(readFile(prefs)).at("view_mode"), "side");
}

TEST(GuiSmoke, HelpAndBadOptionsNeedNoDisplay) {
  if (!fs::exists(guiBinary())) TWR_MISSING_DEPENDENCY("twinraster-gui") << "it was not built (TWINRASTER_BUILD_GUI=OFF)";
  const RunResult help = runGui("--help", false);
  EXPECT_EQ(help.exitCode, 0);
  for (const char* option :
       {"SCENE", "--frames", "--screenshot", "--view-mode", "--reset", "--pin", "--cpu-path", "--cpu-isa"}) {
    EXPECT_NE(help.out.find(option), std::string::npos) << option << " missing from --help:\n" << help.out;
  }
  EXPECT_EQ(runGui("--view-mode sideways", false).exitCode, 2);
  EXPECT_EQ(runGui("--screenshot x.png", false).exitCode, 2) << "--screenshot needs --frames";
  EXPECT_EQ(runGui("--pin 3", false).exitCode, 2);
  EXPECT_EQ(runGui("--cpu-path quick", false).exitCode, 2);
  const RunResult unknown = runGui("--cpu-isa avx9000", false);
  EXPECT_EQ(unknown.exitCode, 2);
  EXPECT_NE(unknown.err.find("avx9000"), std::string::npos) << unknown.err;
}

TEST(GuiSmoke, NoDisplayIsACleanError) {
  if (!fs::exists(guiBinary())) TWR_MISSING_DEPENDENCY("twinraster-gui") << "it was not built (TWINRASTER_BUILD_GUI=OFF)";
  const RunResult r = runGui("--frames 1", false, "env -u DISPLAY -u WAYLAND_DISPLAY ");
  EXPECT_EQ(r.exitCode, 2) << r.err;
  EXPECT_NE(r.err.find("display"), std::string::npos) << r.err;
}

}  // namespace
