// twinraster-gui driven as a user would, with xdotool under Xvfb (issue 20): typing an
// invalid camera must not end the app (defect 1), the diff widgets and messages must not
// change the render size (defect 3), the Controls panel must come back after the window
// shrinks and grows (defect 4), and the hover line must not diff images of different edits
// (defect 5). The app writes its state (widget rectangles, render size, hover line) to the
// file named by TWINRASTER_GUI_TEST_STATE every frame (app/gui/test_probe.h); the test clicks
// widgets where that file says they are and waits for conditions in it, never for fixed
// times. Runs under xvfb-run (tests/CMakeLists.txt); skipped with the reason when there is no
// display or no xdotool (Debian packages xvfb, xauth, xdotool), failed where every dependency is
// required (tests/missing_dependency.h: CI).
#include "tests/missing_dependency.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>
#include <string>
#include <thread>
#include <utility>
#include <vector>

namespace {

namespace fs = std::filesystem;
using nlohmann::json;
using Clock = std::chrono::steady_clock;

const std::string kDefaultScene = std::string(TWINRASTER_SOURCE_DIR) + "/assets/scenes/default.json";
// Longest wait for any one condition, seconds: generous for a loaded 2-core machine with
// llvmpipe; a passing run waits far less (each wait ends as soon as its condition holds).
constexpr double kWaitSeconds = 60.0;
// How often the state file is read while waiting, milliseconds.
constexpr int kPollMs = 15;

bool haveCommand(const char* name) { return std::system((std::string("command -v ") + name + " >/dev/null 2>&1").c_str()) == 0; }

std::string readFile(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

// Runs a shell command, returns its stdout.
std::string capture(const std::string& command) {
  std::string out;
  FILE* pipe = popen(command.c_str(), "r");
  if (!pipe) return out;
  char buffer[256];
  while (std::fgets(buffer, sizeof buffer, pipe)) out += buffer;
  pclose(pipe);
  return out;
}

#define REQUIRE_DISPLAY_AND_XDOTOOL()                                                                     \
  do {                                                                                                    \
    if (!fs::exists(TWINRASTER_GUI)) TWR_MISSING_DEPENDENCY("twinraster-gui") << "it was not built: " << TWINRASTER_GUI;  \
    const char* display = std::getenv("DISPLAY");                                                         \
    if (!display || !*display)                                                                            \
      TWR_MISSING_DEPENDENCY("xvfb-run") << "no DISPLAY: xvfb-run is missing (Debian packages xvfb and xauth), so there is no X " \
                      "server to open the window on";                                                     \
    if (!haveCommand("xdotool")) TWR_MISSING_DEPENDENCY("xdotool") << "Debian package xdotool: nothing can drive the window"; \
  } while (false)

// One running twinraster-gui with its own settings folder and state file.
class GuiProcess {
 public:
  GuiProcess(const std::string& name, const std::vector<std::string>& args, const json& prefs = nullptr,
             const std::string& imguiIni = "") {
    dir_ = fs::path(TWINRASTER_TEST_OUT) / "gui_scripted" / name;
    fs::remove_all(dir_);
    fs::create_directories(dir_ / "config" / "twinraster");
    if (!prefs.is_null()) std::ofstream(dir_ / "config" / "twinraster" / "gui.json") << prefs.dump(2);
    if (!imguiIni.empty()) std::ofstream(dir_ / "config" / "twinraster" / "imgui.ini") << imguiIni;
    statePath_ = dir_ / "state.json";
    pid_ = fork();
    if (pid_ == 0) {
      if (chdir(dir_.c_str()) != 0) _exit(127);
      setenv("XDG_CONFIG_HOME", (dir_ / "config").c_str(), 1);
      setenv("TWINRASTER_GUI_TEST_STATE", statePath_.c_str(), 1);
      if (!std::freopen((dir_ / "out.txt").c_str(), "w", stdout) || !std::freopen((dir_ / "err.txt").c_str(), "w", stderr)) _exit(127);
      std::vector<std::string> all = {TWINRASTER_GUI};
      all.insert(all.end(), args.begin(), args.end());
      std::vector<char*> argv;
      for (std::string& arg : all) argv.push_back(arg.data());
      argv.push_back(nullptr);
      execv(argv[0], argv.data());
      _exit(127);
    }
  }
  ~GuiProcess() {
    if (running()) {
      kill(pid_, SIGKILL);
      waitpid(pid_, nullptr, 0);
    }
  }
  GuiProcess(const GuiProcess&) = delete;
  GuiProcess& operator=(const GuiProcess&) = delete;

  const fs::path& dir() const { return dir_; }
  std::string err() const { return readFile(dir_ / "err.txt"); }

  bool running() {
    if (exited_) return false;
    int status = 0;
    if (waitpid(pid_, &status, WNOHANG) == pid_) {
      exited_ = true;
      exitCode_ = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
      return false;
    }
    return true;
  }
  int exitCode() const { return exitCode_; }

  // SIGTERM: the app closes its window as if the user had, saving its settings.
  int quit() {
    kill(pid_, SIGTERM);
    const auto until = Clock::now() + std::chrono::seconds(20);
    while (running() && Clock::now() < until) std::this_thread::sleep_for(std::chrono::milliseconds(kPollMs));
    return running() ? -1 : exitCode_;
  }

  json state() const {
    const std::string text = readFile(statePath_);
    if (text.empty()) return nullptr;
    try {
      return json::parse(text);
    } catch (const json::exception&) {
      return nullptr;
    }
  }

  // Waits until `condition` holds for the state; fails (and returns the last state) when the
  // app exits or the time runs out.
  json waitFor(const std::string& what, const std::function<bool(const json&)>& condition) {
    const auto until = Clock::now() + std::chrono::duration<double>(kWaitSeconds);
    json last;
    while (Clock::now() < until) {
      if (!running()) {
        ADD_FAILURE() << "the app exited with code " << exitCode_ << " while waiting for " << what << "; stderr:\n" << err();
        return last;
      }
      json now = state();
      if (!now.is_null()) {
        last = now;
        if (condition(now)) return now;
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(kPollMs));
    }
    ADD_FAILURE() << "timed out waiting for " << what << "; last state:\n" << last.dump(1);
    return last;
  }
  // Waits until the app has drawn `frames` more frames (input reaches ImGui a frame later).
  json waitFrames(int frames) {
    const json now = waitFor("a frame", [](const json& s) { return s.contains("frames"); });
    const long start = now.value("frames", 0L);
    return waitFor("frames to pass", [&](const json& s) { return s.value("frames", 0L) >= start + frames; });
  }
  json waitForItem(const std::string& name) {
    return waitFor("widget " + name, [&](const json& s) { return s.contains("items") && s["items"].contains(name); });
  }
  // Both backends done with the current edit (and the diff, the probes).
  json waitSettled() {
    return waitFor("the renders to settle", [](const json& s) { return s.value("settled", false); });
  }

  // The app's X window, mapped and focused (keys go to the focused window; with no window
  // manager under Xvfb nobody else gives it the focus).
  std::string window() {
    if (window_.empty()) {
      waitFrames(1);  // drawn once: the window is mapped
      const auto until = Clock::now() + std::chrono::duration<double>(kWaitSeconds);
      while (Clock::now() < until && running()) {
        std::istringstream ids(capture("xdotool search --onlyvisible --pid " + std::to_string(pid_) + " 2>/dev/null"));
        std::string id;
        while (ids >> id) window_ = id;  // the last match: GLFW's window
        if (!window_.empty() && std::system(("xdotool windowfocus --sync " + window_ + " >/dev/null 2>&1").c_str()) == 0) {
          break;
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(50));
      }
      EXPECT_FALSE(window_.empty()) << "no X window for the app";
    }
    return window_;
  }

  void xdotool(const std::string& arguments) {
    const std::string command = "xdotool " + arguments + " >/dev/null 2>&1";
    EXPECT_EQ(std::system(command.c_str()), 0) << command;
  }
  void moveTo(float x, float y) {
    xdotool("mousemove --window " + window() + " " + std::to_string(static_cast<int>(x)) + " " +
            std::to_string(static_cast<int>(y)));
  }
  // Moves over a widget (its centre), lets ImGui see the mouse there, then clicks it. The
  // panel's layout can move while the mouse travels (a worker's result adds or drops a line
  // above the widget; on a loaded CI machine that happened, and the click landed on an entry
  // of an open list instead): the widget's rectangle is read again once the mouse is there,
  // and the mouse follows it until it stays put under the mouse.
  void click(const std::string& item, bool withCtrl = false) {
    json s = waitForItem(item);
    if (!s.contains("items") || !s["items"].contains(item)) return;
    const auto centre = [&](const json& r) {
      return std::pair<int, int>(static_cast<int>(0.5f * (r[0].get<float>() + r[2].get<float>())),
                                 static_cast<int>(0.5f * (r[1].get<float>() + r[3].get<float>())));
    };
    const auto inside = [](const json& r, std::pair<int, int> p) {
      return p.first >= r[0].get<float>() && p.first <= r[2].get<float>() && p.second >= r[1].get<float>() &&
             p.second <= r[3].get<float>();
    };
    std::pair<int, int> at = centre(s["items"][item]);
    moveTo(static_cast<float>(at.first), static_cast<float>(at.second));
    constexpr int kMaxFollows = 20;  // layout changes in a row a click follows, at most
    for (int follow = 0;; ++follow) {
      s = waitFrames(2);
      if (!s.contains("items") || !s["items"].contains(item)) {
        s = waitForItem(item);
        if (!s.contains("items") || !s["items"].contains(item)) return;
      }
      const json& r = s["items"][item];
      if (inside(r, at)) break;
      if (follow == kMaxFollows) {
        ADD_FAILURE() << item << " kept moving away from the mouse; last rectangle " << r.dump();
        return;
      }
      at = centre(r);
      moveTo(static_cast<float>(at.first), static_cast<float>(at.second));
    }
    if (withCtrl) {
      xdotool("keydown ctrl");
      waitFrames(2);
    }
    xdotool("mousedown 1");
    waitFrames(2);
    xdotool("mouseup 1");
    waitFrames(2);
    if (withCtrl) {
      xdotool("keyup ctrl");
      waitFrames(1);
    }
  }
  // A key held for a couple of frames, as a person presses it.
  void key(const std::string& name) {
    xdotool("keydown " + name);
    waitFrames(2);
    xdotool("keyup " + name);
    waitFrames(2);
  }
  void type(const std::string& text) {
    xdotool("type --delay 40 '" + text + "'");
    waitFrames(2);
  }
  // Scrolls the Controls panel (the mouse wheel over it) until `item` lies inside the window.
  void scrollTo(const std::string& item) {
    for (int attempt = 0; attempt < 60; ++attempt) {
      const json s = waitForItem(item);
      if (!s.contains("items") || !s["items"].contains(item) || !s.contains("window")) return;
      const float windowHeight = s["window"][1].get<float>();
      const float top = s["items"][item][1].get<float>(), bottom = s["items"][item][3].get<float>();
      // Clear of the panel's title bar at the top and of the window's bottom edge.
      if (top >= 24.0f && bottom <= windowHeight - 24.0f) return;
      moveTo(0.5f * s.value("controls_width", 200.0f), 0.5f * windowHeight);
      waitFrames(1);
      xdotool(bottom > windowHeight - 24.0f ? "click 5" : "click 4");  // wheel down, up
      waitFrames(3);
    }
    ADD_FAILURE() << "could not scroll " << item << " into the window";
  }
  // Scrolls the inspector (the mouse wheel over it, under `item`'s column near the bottom of
  // what the screen shows) until `item` lies on the screen: a window taller than Xvfb's screen
  // has rows no pointer reaches.
  void scrollInspectorTo(const std::string& item) {
    std::istringstream geometry(capture("xdotool getdisplaygeometry 2>/dev/null"));
    float screenWidth = 0.0f, screenHeight = 0.0f;
    geometry >> screenWidth >> screenHeight;
    for (int attempt = 0; attempt < 60; ++attempt) {
      const json s = waitForItem(item);
      if (!s.contains("items") || !s["items"].contains(item) || !s.contains("window")) return;
      const float shown = screenHeight > 0.0f ? std::min(s["window"][1].get<float>(), screenHeight) : s["window"][1].get<float>();
      const json& r = s["items"][item];
      const float top = r[1].get<float>(), bottom = r[3].get<float>();
      if (top >= 24.0f && bottom <= shown - 24.0f) return;
      moveTo(0.5f * (r[0].get<float>() + r[2].get<float>()), shown - 40.0f);
      waitFrames(1);
      xdotool(bottom > shown - 24.0f ? "click 5" : "click 4");  // wheel down, up
      waitFrames(3);
    }
    ADD_FAILURE() << "could not scroll " << item << " onto the screen";
  }
  // Opens a combo box and picks one of its entries (each entry is a widget of its own).
  void pick(const std::string& combo, const std::string& entry) {
    scrollTo(combo);
    click(combo);
    click(entry);
  }
  // Ctrl+click a drag field into a text field and type a value into it, key by key (every
  // key applies what is typed so far, as for a user), then Enter.
  void typeInto(const std::string& item, const std::string& value) {
    click(item, true);
    key("ctrl+a");
    type(value);
    key("Return");
  }

 private:
  fs::path dir_, statePath_;
  pid_t pid_ = -1;
  bool exited_ = false;
  int exitCode_ = -1;
  std::string window_;
};

std::string testName() {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  return std::string(info->test_suite_name()) + "_" + info->name();
}

// Runs twinraster-gui with `arguments` (shell words) and its stderr captured; the exit code.
// A folder per test: ctest runs these tests at once, and a shared err.txt mixed their messages.
int runGui(const std::string& arguments, std::string& err) {
  const fs::path dir = fs::path(TWINRASTER_TEST_OUT) / "gui_scripted" / ("command_line_" + testName());
  fs::create_directories(dir);
  const std::string command = "XDG_CONFIG_HOME=\"" + (dir / "config").string() + "\" \"" + TWINRASTER_GUI + "\" " +
                              arguments + " >/dev/null 2>\"" + (dir / "err.txt").string() + "\"";
  const int status = std::system(command.c_str());
  err = readFile(dir / "err.txt");
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

// Defect 10: `--frames 0` printed a range with a 300-digit bound; now one short line.
TEST(GuiCommandLine, FramesOutOfRangeSaysTheRangeBriefly) {
  if (!fs::exists(TWINRASTER_GUI)) TWR_MISSING_DEPENDENCY("twinraster-gui") << "it was not built";
  std::string err;
  EXPECT_EQ(runGui("--frames 0", err), 2);
  EXPECT_NE(err.find("expected an integer in [1, 5184000], got '0'"), std::string::npos) << err;
  EXPECT_LT(err.size(), 200u) << err;
  EXPECT_EQ(runGui("--frames 99999999999", err), 2);
  EXPECT_LT(err.size(), 200u) << err;
}

// Defect 10: `--pin 9999,9999` was dropped silently; now it is reported.
TEST(GuiCommandLine, PinOutsideTheRenderIsReported) {
  if (!fs::exists(TWINRASTER_GUI)) TWR_MISSING_DEPENDENCY("twinraster-gui") << "it was not built";
  const char* display = std::getenv("DISPLAY");
  if (!display || !*display) TWR_MISSING_DEPENDENCY("xvfb-run") << "no DISPLAY: xvfb-run is missing (Debian packages xvfb and xauth)";
  std::string err;
  EXPECT_EQ(runGui("\"" + kDefaultScene + "\" --reset --frames 3 --pin 9999,9999", err), 0) << err;
  EXPECT_NE(err.find("--pin 9999,9999 is outside the 640 x 480 px render"), std::string::npos) << err;
}

// Defect 1: typing far = 0.05 passes through far = 0 (< near) and dragging near past 0 made
// the camera invalid while the light markers (on by default) projected with it: the app
// exited with code 2. Now the camera tab shows the red message and the app keeps running.
TEST(GuiScripted, InvalidCameraEditsNeverEndTheApp) {
  REQUIRE_DISPLAY_AND_XDOTOOL();
  GuiProcess app(testName(), {kDefaultScene, "--reset", "--view-mode", "side"});
  app.window();
  app.waitSettled();
  app.click("tab_camera");
  app.waitForItem("far");

  app.typeInto("far", "0.05");
  json s = app.waitFor("far = 0.05", [](const json& st) { return std::abs(st["camera"]["far"].get<double>() - 0.05) < 1e-6; });
  ASSERT_TRUE(app.running()) << app.err();
  EXPECT_NE(s.value("render_blocker", "").find("far must be > near"), std::string::npos) << s.dump(1);
  EXPECT_FALSE(s.contains("panel_faults")) << "a panel threw: " << s.dump(1);

  // Back to a valid far: both backends render again.
  app.typeInto("far", "50");
  s = app.waitFor("a valid camera again", [](const json& st) { return st.value("render_blocker", "x").empty(); });
  s = app.waitSettled();
  EXPECT_EQ(s["gl_edit"], s["edit"]);

  // Drag near to the left, well past 0.
  const json far = app.waitForItem("near")["items"]["near"];
  const float y = 0.5f * (far[1].get<float>() + far[3].get<float>());
  float x = 0.5f * (far[0].get<float>() + far[2].get<float>());
  app.moveTo(x, y);
  app.waitFrames(2);
  app.xdotool("mousedown 1");
  app.waitFrames(2);
  // DragFloat moves near by 0.001 per pixel: 0.1 needs 100 pixels; the field starts farther right.
  for (int step = 0; step < 12 && x > 30.0f; ++step) {
    x = std::max(2.0f, x - 25.0f);
    app.moveTo(x, y);
    app.waitFrames(1);
  }
  app.xdotool("mouseup 1");
  s = app.waitFor("near <= 0", [](const json& st) { return st["camera"]["near"].get<double>() <= 0.0; });
  ASSERT_TRUE(app.running()) << app.err();
  EXPECT_NE(s.value("render_blocker", "").find("near must be > 0"), std::string::npos) << s.dump(1);
  app.waitFrames(5);
  ASSERT_TRUE(app.running()) << app.err();
  EXPECT_EQ(app.quit(), 0) << app.err();
}

// Issue 22, class 9 in the app: a near plane so small that depth rounds to the cleared 1.0
// draws what GL draws (nothing) and the Camera tab says why, as the CLI's warning does; a
// sane near clears it.
TEST(GuiScripted, CameraTabWarnsWhenDepthRoundsToTheClearValue) {
  REQUIRE_DISPLAY_AND_XDOTOOL();
  GuiProcess app(testName(), {kDefaultScene, "--reset", "--view-mode", "side"});
  app.window();
  json s = app.waitSettled();
  EXPECT_TRUE(s["projection_warnings"].empty()) << s.dump(1);
  app.click("tab_camera");
  app.waitForItem("near");
  app.typeInto("near", "1e-8");
  s = app.waitFor("a depth warning", [](const json& st) {
    return !st["projection_warnings"].empty() &&
           st["projection_warnings"][0].get<std::string>().find("window depth 1.0") != std::string::npos;
  });
  EXPECT_TRUE(s.value("render_blocker", "x").empty()) << "drawn as GL draws it, not refused: " << s.dump(1);
  app.typeInto("near", "0.1");
  s = app.waitFor("no warning", [](const json& st) { return st["projection_warnings"].empty(); });
  EXPECT_EQ(app.quit(), 0) << app.err();
}

// Defect 3: in "fit view", the diff view's heat / class map switch, a status message and an
// error banner changed the image area, so the render size, and both backends re-rendered.
TEST(GuiScripted, FitViewSizeDependsOnlyOnWhatTheUserSizes) {
  REQUIRE_DISPLAY_AND_XDOTOOL();
  const json prefs = {{"resolution", "fit_view"}, {"view_mode", "diff"}, {"diff_show_classes", false}};
  GuiProcess app(testName(), {kDefaultScene}, prefs);
  app.window();
  json s = app.waitFor("the diff of the current edit", [](const json& st) {
    return st.value("settled", false) && st["diff_edit"] == st["edit"] && st["diff_edit"].get<long>() > 0;
  });
  const json render = s["render"];
  const json edit = s["edit"];
  const auto unchanged = [&](const char* after) {
    const json now = app.waitFrames(3);
    EXPECT_EQ(now["render"], render) << "after " << after;
    EXPECT_EQ(now["edit"], edit) << "after " << after << ": the backends were asked to render again";
  };

  app.click("diff_class");
  unchanged("switching to the class map");
  app.click("diff_heat");
  unchanged("switching back to the heat map");

  app.click("screenshot");
  app.waitFor("the screenshot message", [](const json& st) { return !st.value("screenshot_message", "").empty(); });
  unchanged("a status message");

  app.click("tab_scene");
  app.click("scene_path");
  app.key("ctrl+a");
  app.type("no_such_scene.json");
  app.key("Return");
  app.waitFor("the scene error banner", [](const json& st) { return !st.value("scene_error", "").empty(); });
  unchanged("an error banner");
  EXPECT_EQ(app.quit(), 0) << app.err();
}

// Defect 4: after shrinking the window to 300 x 200 and growing it back, the Controls panel
// stayed squeezed (labels cut), and imgui.ini kept it so across restarts.
TEST(GuiScripted, PanelsComeBackAfterTheWindowShrinksAndGrows) {
  REQUIRE_DISPLAY_AND_XDOTOOL();
  {
    GuiProcess app(testName(), {kDefaultScene, "--reset"});
    const std::string window = app.window();
    const json before = app.waitFor("the layout", [](const json& st) { return st.contains("controls_width"); });
    app.xdotool("windowsize " + window + " 300 200");
    app.waitFor("a 300 x 200 window", [](const json& st) { return st["window"] == json{300.0, 200.0}; });
    app.waitFrames(3);
    app.xdotool("windowsize " + window + " 1280 800");
    json after = app.waitFor("a 1280 x 800 window", [](const json& st) { return st["window"] == json{1280.0, 800.0}; });
    after = app.waitFrames(3);
    EXPECT_EQ(after["controls_width"], before["controls_width"]);
    EXPECT_EQ(after["stats_height"], before["stats_height"]);
    ASSERT_EQ(app.quit(), 0) << app.err();
    const std::string ini = readFile(app.dir() / "config" / "twinraster" / "imgui.ini");
    EXPECT_EQ(ini.find("[Window][Controls]"), std::string::npos) << "imgui.ini keeps the panel size:\n" << ini;
  }
  // A too-narrow width saved by an older version (imgui.ini) or by hand (gui.json) does not come back.
  const json prefs = {{"controls_width", 120.0}};
  GuiProcess app(testName() + "_saved", {kDefaultScene}, prefs, "[Window][Controls]\nPos=0,0\nSize=120,800\nCollapsed=0\n");
  app.window();
  const json s = app.waitFrames(3);
  EXPECT_GE(s["controls_width"].get<double>(), 300.0) << s.dump(1);
  EXPECT_EQ(app.quit(), 0) << app.err();
}

// Defect 5: while orbiting, the hover line said "diff 0 (same)" next to CPU and GL values
// of different edits. Now a diff is only shown when both images and the diff are of the
// same edit; otherwise the line says the images are from different edits.
TEST(GuiScripted, HoverLineNeverDiffsImagesOfDifferentEdits) {
  REQUIRE_DISPLAY_AND_XDOTOOL();
  // The teaching path at twice the scene's size: the CPU lags GL by several edits.
  const json prefs = {{"resolution_scale", 2.0}, {"cpu_path", "teaching"}, {"view_mode", "side"}};
  GuiProcess app(testName(), {kDefaultScene}, prefs);
  app.window();
  json s = app.waitSettled();
  const json image = app.waitForItem("view_images")["items"]["view_images"];
  // The middle of the left (CPU) half of the image area.
  float x = image[0].get<float>() + 0.25f * (image[2].get<float>() - image[0].get<float>());
  const float y = 0.5f * (image[1].get<float>() + image[3].get<float>());
  app.moveTo(x, y);
  app.waitFor("a hover line", [](const json& st) { return st.contains("hover") && !st["hover"].is_null(); });

  std::vector<json> lines;
  const auto record = [&] {
    const json now = app.state();
    if (!now.is_null() && now.contains("hover") && !now["hover"].is_null()) lines.push_back(now["hover"]);
  };
  // Drag until the CPU has been seen lagging a few times: how soon depends on the machine's
  // load (GL renders on a worker too, so a busy machine slows both), hence no fixed count.
  const auto lagging = [](const json& line) {
    return line["cpu_edit"] != line["gl_edit"] && line["cpu_edit"].get<long>() != 0;
  };
  app.xdotool("mousedown 1");
  app.waitFrames(1);
  int lagsSeen = 0;
  for (int step = 0; step < 60 && (step < 10 || lagsSeen < 3); ++step) {
    x += step % 20 < 10 ? 6.0f : -6.0f;  // back and forth, staying on the image
    app.moveTo(x, y);
    app.waitFrames(1);
    record();
    if (!lines.empty() && lagging(lines.back())) ++lagsSeen;
  }
  app.xdotool("mouseup 1");
  // GL has the last edit at once; the CPU follows. Read the line until they meet again.
  const auto until = Clock::now() + std::chrono::duration<double>(kWaitSeconds);
  while (Clock::now() < until && app.running()) {
    record();
    const json& last = lines.empty() ? json() : lines.back();
    if (!last.is_null() && last["cpu_edit"] == last["gl_edit"] && last["diff_shown"].get<bool>()) break;
    std::this_thread::sleep_for(std::chrono::milliseconds(kPollMs));
  }
  ASSERT_TRUE(app.running()) << app.err();

  int differentEdits = 0;
  for (const json& line : lines) {
    const bool same = line["cpu_edit"] == line["gl_edit"] && line["gl_edit"] == line["diff_edit"];
    if (line["diff_shown"].get<bool>()) {
      EXPECT_TRUE(same) << "a diff next to images of different edits: " << line.dump();
    }
    if (lagging(line)) {
      ++differentEdits;
      EXPECT_NE(line["text"].get<std::string>().find("different edits"), std::string::npos) << line.dump();
    }
  }
  EXPECT_GT(differentEdits, 0) << "the CPU never lagged: the situation of defect 5 was not reproduced";
  ASSERT_FALSE(lines.empty());
  EXPECT_TRUE(lines.back()["diff_shown"].get<bool>()) << "once the CPU caught up the diff should show: "
                                                      << lines.back().dump();
  EXPECT_EQ(app.quit(), 0) << app.err();
}

// Issue 15, item 6: a map option edited in the Scene tab re-renders both backends from a new
// texture (a stale GL upload or tiled CPU copy would show as a large CPU-vs-GL difference), and
// the anisotropy control and every debug view are there in the Rendering tab.
TEST(GuiScripted, TextureOptionEditsRedrawBothBackends) {
  REQUIRE_DISPLAY_AND_XDOTOOL();
  GuiProcess app(testName(), {kDefaultScene, "--reset", "--view-mode", "side"});
  app.window();
  json s = app.waitSettled();
  ASSERT_TRUE(s.contains("maps") && !s["maps"].empty()) << s.dump(1);
  const json before = s["maps"][0];
  ASSERT_EQ(before["slot"], "diffuse map");
  ASSERT_FALSE(before["flip_v"].get<bool>());
  const std::string prefix = "material" + std::to_string(before["material"].get<int>()) + "_diffuse";
  const auto withinTargets = [](const json& st) {
    return st.value("settled", false) && st["diff_edit"] == st["edit"] && st.contains("diff") &&
           st["diff"]["max_abs_diff"].get<int>() <= 3;
  };
  EXPECT_TRUE(withinTargets(s)) << s.dump(1);

  app.click("tab_scene");
  app.click("material" + std::to_string(before["material"].get<int>()));  // open the material's tree node
  app.click(prefix + "_flip_v");
  s = app.waitFor("flip_v on the diffuse map", [&](const json& st) {
    return st["maps"][0]["flip_v"].get<bool>() && st["maps"][0]["object"] != before["object"];
  });
  EXPECT_EQ(s["maps"][0]["message"], "") << "a PNG read again says nothing";
  s = app.waitFor("both backends on the flipped texture, within the targets", [&](const json& st) {
    return st.value("settled", false) && st["diff_edit"] == st["edit"] && st["edit"].get<long>() > 0;
  });
  EXPECT_TRUE(withinTargets(s)) << s.dump(1);
  app.xdotool("key F12");  // the window as the user sees it, for a person to look at
  app.waitFor("the window screenshot", [](const json& st) { return !st.value("screenshot_message", "").empty(); });

  // sRGB on the normal map: done as asked, with the loader's warning under the map.
  app.click(prefix.substr(0, prefix.size() - std::string("diffuse").size()) + "normal_srgb");
  s = app.waitFor("srgb on the normal map", [](const json& st) {
    for (const json& map : st["maps"]) {
      if (map["slot"] == "normal map" && map["srgb"].get<bool>()) return true;
    }
    return false;
  });
  bool warned = false;
  for (const json& map : s["maps"]) {
    if (map["slot"] == "normal map" && map["srgb"].get<bool>()) {
      warned = map["message"].get<std::string>().find("directions") != std::string::npos;
    }
  }
  EXPECT_TRUE(warned) << s.dump(1);
  s = app.waitFor("both backends on the sRGB normal map", [&](const json& st) {
    return st.value("settled", false) && st["diff_edit"] == st["edit"];
  });
  EXPECT_TRUE(withinTargets(s)) << s.dump(1);

  app.click("tab_rendering");
  app.waitForItem("anisotropy");
  EXPECT_FALSE(s.contains("panel_faults")) << s.dump(1);
  EXPECT_EQ(app.quit(), 0) << app.err();
}

// The Interpolation switch in the Rendering tab: affine redraws both backends, which still agree
// within the targets (that the picture changes is CpuRenderer.AffineInterpolation...'s).
TEST(GuiScripted, AffineInterpolationRedrawsBothBackendsWithinTheTargets) {
  REQUIRE_DISPLAY_AND_XDOTOOL();
  GuiProcess app(testName(), {kDefaultScene, "--reset", "--view-mode", "side"});
  app.window();
  json s = app.waitSettled();
  ASSERT_EQ(s["interpolation"], "perspective") << s.dump(1);
  const long editBefore = s["edit"].get<long>();
  app.click("tab_rendering");
  app.click("interpolation_affine");
  s = app.waitFor("affine, drawn by both backends and diffed", [&](const json& st) {
    return st["interpolation"] == "affine" && st.value("settled", false) && st["diff_edit"] == st["edit"] &&
           st["edit"].get<long>() > editBefore && st.contains("diff");
  });
  EXPECT_LE(s["diff"]["max_abs_diff"].get<int>(), 3) << s.dump(1);
  EXPECT_FALSE(s.contains("panel_faults")) << s.dump(1);
  EXPECT_EQ(app.quit(), 0) << app.err();
}

// Issue 17: the environment's keys are live controls. On the mirror-sphere scene the chrome
// material's reflectivity is typed, fresnel switched to schlick, refraction turned on, and the
// sky box turned off; after each edit both backends draw it and agree within the targets (the
// sky pixels are compared too while the sky box is on).
TEST(GuiScripted, EnvironmentControlsRedrawBothBackends) {
  REQUIRE_DISPLAY_AND_XDOTOOL();
  GuiProcess app(testName(), {std::string(TWINRASTER_SOURCE_DIR) + "/assets/scenes/env_mirror_sphere.json", "--reset",
                              "--view-mode", "side"});
  app.window();
  json s = app.waitSettled();
  ASSERT_TRUE(s.contains("environment") && !s["environment"].is_null()) << s.dump(1);
  EXPECT_TRUE(s["environment"]["background"].get<bool>());
  ASSERT_EQ(s["materials"][0]["name"], "chrome");
  EXPECT_EQ(s["materials"][0]["environment_specular"], "mirror");
  const auto settledWithin = [](const json& st) {
    return st.value("settled", false) && st["diff_edit"] == st["edit"] && st.contains("diff") &&
           st["diff"]["max_abs_diff"].get<int>() <= 3;
  };
  EXPECT_TRUE(settledWithin(s)) << s.dump(1);
  // Does `action`, then waits for its edit (a later edit counter than before it, the state
  // `edited` names) drawn by both backends, and checks the diff.
  const auto afterEdit = [&](const std::string& what, const std::function<void()>& action,
                             const std::function<bool(const json&)>& edited) {
    const long edit = app.state().value("edit", 0L);
    action();
    json st = app.waitFor(what, [&](const json& now) {
      return edited(now) && now.value("edit", 0L) > edit && now.value("settled", false) && now["diff_edit"] == now["edit"];
    });
    EXPECT_TRUE(settledWithin(st)) << what << "\n" << st.dump(1);
    return st;
  };

  app.click("tab_scene");
  app.scrollTo("material0");
  app.click("material0");  // open chrome's tree node
  app.scrollTo("material0_reflectivity");
  afterEdit(
      "reflectivity 0.5", [&] { app.typeInto("material0_reflectivity", "0.5"); },
      [](const json& st) { return std::abs(st["materials"][0]["reflectivity"].get<double>() - 0.5) < 1e-6; });
  app.scrollTo("material0_fresnel");
  afterEdit(
      "fresnel schlick", [&] { app.pick("material0_fresnel", "material0_fresnel_schlick"); },
      [](const json& st) { return st["materials"][0]["fresnel"] == "schlick"; });
  app.scrollTo("material0_refracts");
  afterEdit(
      "refraction on", [&] { app.click("material0_refracts"); },
      [](const json& st) { return st["materials"][0]["refraction_index"].get<double>() > 0.0; });
  app.xdotool("key F12");  // the window as the user sees it, for a person to look at
  app.waitFor("the window screenshot", [](const json& st) { return !st.value("screenshot_message", "").empty(); });

  app.scrollTo("environment_background");
  s = afterEdit(
      "the sky box off", [&] { app.click("environment_background"); },
      [](const json& st) { return !st["environment"]["background"].get<bool>(); });
  // The sky back on, read from a dual-paraboloid map built on the spot: both backends agree.
  afterEdit(
      "the sky box on", [&] { app.click("environment_background"); },
      [](const json& st) { return st["environment"]["background"].get<bool>(); });
  app.scrollTo("environment_parameterization");
  s = afterEdit(
      "dual paraboloid",
      [&] { app.pick("environment_parameterization", "environment_parameterization_dual_paraboloid"); },
      [](const json& st) { return st["environment"]["parameterization"] == "dual_paraboloid"; });
  EXPECT_EQ(s["environment"]["map_size"].get<int>(), 512) << s.dump(1);  // twice the 256-texel faces
  // The diffuse light, built on first use under the paraboloid, then SH9: both backends agree.
  app.scrollTo("material0_environment_diffuse");
  s = afterEdit(
      "diffuse irradiance_map",
      [&] { app.pick("material0_environment_diffuse", "material0_environment_diffuse_irradiance_map"); },
      [](const json& st) { return st["materials"][0]["environment_diffuse"] == "irradiance_map"; });
  EXPECT_TRUE(s["environment"]["irradiance_layers"].get<bool>()) << s.dump(1);
  s = afterEdit(
      "diffuse sh9", [&] { app.pick("material0_environment_diffuse", "material0_environment_diffuse_sh9"); },
      [](const json& st) { return st["materials"][0]["environment_diffuse"] == "sh9"; });
  EXPECT_TRUE(s["environment"]["sh9"].get<bool>()) << s.dump(1);
  EXPECT_FALSE(s.contains("panel_faults")) << s.dump(1);
  EXPECT_EQ(app.quit(), 0) << app.err();
}

// Issue 16: every height-field key of the selected material is a live control in the Scene
// tab. A bricks floor with a height map starts as bump_blinn; surface_detail is switched to
// parallax_occlusion through the combo box, self_shadow to horizon_map (built on a worker,
// then both backends draw it), horizon_directions to 16 and height_scale typed (each rebuilds
// the map); a material without a height map cannot pick a height method; and the parallax_steps
// view's legend counts the selected material's layers.
TEST(GuiScripted, HeightFieldControlsRedrawBothBackends) {
  REQUIRE_DISPLAY_AND_XDOTOOL();
  const fs::path scene = fs::path(TWINRASTER_TEST_OUT) / "gui_scripted" / (testName() + "_scene");
  fs::remove_all(scene);
  fs::create_directories(scene);
  const fs::path textures = fs::path(TWINRASTER_SOURCE_DIR) / "assets" / "textures";
  fs::copy_file(textures / "bricks_diffuse.png", scene / "diffuse.png");
  fs::copy_file(textures / "bricks_height.png", scene / "height.png");
  std::ofstream(scene / "scene.json") << R"({
    "camera": {"position": [0, 1.7, 1.7], "target": [0, 0, 0]},
    "lights": [{"position": [1.6, 0.8, 0.4]}],
    "materials": {"bricks": {"ks": [0.3, 0.3, 0.3], "diffuse_map": "diffuse.png", "height_map": "height.png",
                             "height_scale": 0.05, "surface_detail": "bump_blinn"},
                  "plain": {"kd": [0.7, 0.7, 0.7]}},
    "nodes": [{"name": "floor", "material": "bricks", "mesh": {"type": "plane", "size": [2.4, 2.4], "uv_scale": 2}},
              {"name": "box", "material": "plain", "mesh": {"type": "cube", "size": 0.3}, "translate": [0.8, 0.15, 0.8]}]
  })";
  GuiProcess app(testName(), {(scene / "scene.json").string(), "--reset", "--view-mode", "side"});
  app.window();
  json s = app.waitSettled();
  ASSERT_TRUE(s.contains("materials") && s["materials"].size() == 2) << s.dump(1);
  EXPECT_EQ(s["materials"][0]["surface_detail"], "bump_blinn");
  EXPECT_TRUE(s["materials"][0]["horizon_map"].is_null());
  EXPECT_EQ(s["selected_material"], 0) << "the material with the height map";
  // Both backends done with the current edit, compared, and no horizon map waiting.
  const auto caughtUp = [](const json& st) {
    return st.value("settled", false) && st["cpu_edit"] == st["edit"] && st["gl_edit"] == st["edit"] &&
           st["diff_edit"] == st["edit"];
  };
  const auto withinTargets = [](const json& st) { return st["diff"]["max_abs_diff"].get<int>() <= 3; };
  EXPECT_TRUE(withinTargets(s)) << s.dump(1);

  app.click("tab_scene");
  app.scrollTo("material0");
  app.click("material0");  // open the material's tree node
  long edit = s["edit"].get<long>();
  app.pick("material0_surface_detail", "material0_surface_detail_parallax_occlusion");
  s = app.waitFor("surface_detail parallax_occlusion", [](const json& st) {
    return st["materials"][0]["surface_detail"] == "parallax_occlusion";
  });
  s = app.waitFor("both backends on parallax_occlusion", [&](const json& st) {
    return caughtUp(st) && st["edit"].get<long>() > edit;
  });
  EXPECT_EQ(s["materials"][0]["surface_detail"], "parallax_occlusion");
  EXPECT_TRUE(withinTargets(s)) << s.dump(1);
  EXPECT_EQ(s["materials"][0]["error"], "");

  // Self-shadowing by a horizon map: built on a worker, then drawn by both.
  edit = s["edit"].get<long>();
  app.pick("material0_self_shadow", "material0_self_shadow_horizon_map");
  s = app.waitFor("the horizon map built and drawn", [&](const json& st) {
    const json& m = st["materials"][0];
    return m["self_shadow"] == "horizon_map" && !m["horizon_map"].is_null() && !m["horizon_stale"].get<bool>() &&
           st["horizon_building"].is_null() && caughtUp(st) && st["edit"].get<long>() > edit + 1;
  });
  EXPECT_EQ(s["materials"][0]["horizon_map"]["directions"], 8);
  EXPECT_NE(s["horizon_last_build"].get<std::string>().find("8 directions"), std::string::npos) << s.dump(1);
  EXPECT_TRUE(withinTargets(s)) << s.dump(1);

  json horizon = s["materials"][0]["horizon_map"];
  app.scrollTo("material0_horizon_directions_16");
  app.click("material0_horizon_directions_16");
  s = app.waitFor("16 directions built and drawn", [&](const json& st) {
    const json& m = st["materials"][0];
    return m["horizon_directions"] == 16 && !m["horizon_map"].is_null() && m["horizon_map"]["directions"] == 16 &&
           !m["horizon_stale"].get<bool>() && caughtUp(st);
  });
  EXPECT_TRUE(withinTargets(s)) << s.dump(1);

  horizon = s["materials"][0]["horizon_map"];
  app.scrollTo("material0_height_scale");
  app.typeInto("material0_height_scale", "0.08");
  s = app.waitFor("height_scale 0.08 with its horizon map", [&](const json& st) {
    const json& m = st["materials"][0];
    return std::abs(m["height_scale"].get<double>() - 0.08) < 1e-6 && !m["horizon_map"].is_null() &&
           m["horizon_map"]["object"] != horizon["object"] && !m["horizon_stale"].get<bool>() && caughtUp(st);
  });
  EXPECT_TRUE(withinTargets(s)) << s.dump(1);
  app.xdotool("key F12");  // the window as the user sees it, for a person to look at
  app.waitFor("the window screenshot", [](const json& st) { return !st.value("screenshot_message", "").empty(); });

  // "plain" has no height map: its height methods are greyed, a click on one does nothing.
  app.scrollTo("material1");
  app.click("material1");
  app.pick("material1_surface_detail", "material1_surface_detail_parallax");
  s = app.waitFrames(5);
  EXPECT_EQ(s["materials"][1]["surface_detail"], "normal_map") << s.dump(1);
  EXPECT_EQ(s["materials"][1]["error"], "");
  // The disabled entry left the list open: a click on the combo closes it (Escape does not:
  // keyboard navigation is off).
  app.click("material1_surface_detail");
  s = app.waitFor("the list closed", [](const json& st) { return !st["items"].contains("material1_surface_detail_parallax"); });

  // The view picker lists the height views; parallax_steps' legend counts the selected
  // material's layers (re-select the bricks).
  app.scrollTo("material0");
  app.click("material0");
  s = app.waitFor("bricks selected", [](const json& st) { return st["selected_material"] == 0; });
  app.scrollTo("tab_rendering");  // the tab bar scrolls with the panel
  app.click("tab_rendering");
  app.click("view");
  s = app.waitForItem("view_parallax_steps");
  for (const char* view : {"view_height", "view_parallax_offset", "view_parallax_steps", "view_self_shadow"}) {
    EXPECT_TRUE(s["items"].contains(view)) << view << " is not in the view picker";
  }
  app.click("view_parallax_steps");
  s = app.waitFor("the parallax_steps legend", [&](const json& st) {
    return st["view"] == "parallax_steps" && st.contains("parallax_steps_legend") && caughtUp(st);
  });
  EXPECT_EQ(s["parallax_steps_legend"]["material"], 0);
  EXPECT_EQ(s["parallax_steps_legend"]["most"], 32) << "parallax_layers' max, no refinement for POM";
  EXPECT_EQ(s["parallax_steps_legend"]["ticks"], json({"0", "8", "16", "24", "32"}));
  EXPECT_TRUE(withinTargets(s)) << s.dump(1);
  EXPECT_FALSE(s.contains("panel_faults")) << s.dump(1);
  EXPECT_EQ(app.quit(), 0) << app.err();
}

// An idle window was drawn about 10 times a second, each frame 0.2 s of CPU on llvmpipe under
// Xvfb at the UI's priority, so the workers (at a lower one) starved behind it. Now it is drawn
// only for an event, a worker's result or a timed change (the tags' ages, coarser as they age),
// and an expose draws it again. Frames are still laid out, not drawn, for this test's probe, so
// "presented" (frames drawn on screen) and "frames" (laid out) part while the app is idle.
// Issue 18: a deferred scene's G-buffer in the buffer picker. Both backends hand over their
// G-buffer; picking gbuffer_normal re-diffs the same frames as that buffer, within the targets;
// final again shows the frame.
TEST(GuiScripted, BufferPickerShowsTheDeferredGBuffer) {
  REQUIRE_DISPLAY_AND_XDOTOOL();
  const fs::path dir = fs::path(TWINRASTER_TEST_OUT) / "gui_scripted" / (testName() + "_scene");
  fs::remove_all(dir);
  fs::create_directories(dir);
  std::ofstream(dir / "scene.json") << R"({
    "camera": {"position": [0, 1.5, 3], "target": [0, 0.3, 0]},
    "lights": [{"type": "directional", "direction": [-0.4, -1, -0.3], "shadow": {"size": 512}}],
    "materials": {"plain": {"kd": [0.7, 0.6, 0.5], "ks": [0.3, 0.3, 0.3]}},
    "settings": {"pipeline": "deferred"},
    "nodes": [{"name": "floor", "material": "plain", "mesh": {"type": "plane", "size": [4, 4]}},
              {"name": "ball", "material": "plain", "mesh": {"type": "sphere", "radius": 0.4}, "translate": [0, 0.4, 0]}]
  })";
  GuiProcess app(testName(), {(dir / "scene.json").string(), "--reset", "--view-mode", "diff"});
  app.window();
  json s = app.waitSettled();
  EXPECT_EQ(s["pipeline"], "deferred") << s.dump(1);
  EXPECT_TRUE(s["cpu_gbuffer"].get<bool>()) << s.dump(1);
  EXPECT_TRUE(s["gl_gbuffer"].get<bool>()) << s.dump(1);
  ASSERT_TRUE(s.contains("diff")) << s.dump(1);
  EXPECT_LE(s["diff"]["max_abs_diff"].get<int>(), 3) << s.dump(1);

  app.click("buffer");
  app.click("buffer_gbuffer_normal");
  s = app.waitFor("the diff of the G-buffer's normals", [](const json& st) {
    return st["buffer"] == "gbuffer_normal" && st["diff_buffer"] == "gbuffer_normal" && st.contains("diff");
  });
  EXPECT_LE(s["diff"]["max_abs_diff"].get<int>(), 1) << s.dump(1);
  app.xdotool("key F12");  // the window as the user sees it
  app.waitFor("the window screenshot", [](const json& st) { return !st.value("screenshot_message", "").empty(); });

  app.click("buffer");
  app.click("buffer_final");
  s = app.waitFor("the frame again", [](const json& st) { return st["diff_buffer"] == "final"; });
  EXPECT_FALSE(s.contains("panel_faults")) << s.dump(1);
  EXPECT_EQ(app.quit(), 0) << app.err();
}

TEST(GuiScripted, AnIdleWindowIsDrawnOnlyWhenSomethingHappens) {
  REQUIRE_DISPLAY_AND_XDOTOOL();
  GuiProcess app(testName(), {kDefaultScene, "--reset", "--view-mode", "side"});
  const std::string window = app.window();
  app.waitSettled();
  // Idle: five frames laid out in a row and none drawn.
  const auto waitIdle = [&] {
    long baseFrames = -1, basePresented = -1;
    return app.waitFor("the loop to go idle", [&](const json& st) {
      const long frames = st.value("frames", 0L), presented = st.value("presented", -1L);
      if (presented != basePresented) {
        basePresented = presented;
        baseFrames = frames;
        return false;
      }
      return frames >= baseFrames + 5;
    });
  };
  json s = waitIdle();
  ASSERT_TRUE(s.contains("presented")) << s.dump(1);
  // Over the app's own clock (the state's "clock", glfwGetTime()), which its redraw policy
  // reads: how fast this machine lays frames out does not enter.
  const double clock0 = s["clock"].get<double>();
  const long frames0 = s["frames"].get<long>(), presented0 = s["presented"].get<long>();
  s = app.waitFor("20 frames laid out while idle", [&](const json& st) { return st.value("frames", 0L) >= frames0 + 20; });
  const double seconds = s["clock"].get<double>() - clock0;
  // Drawn only when a tag's age changes: once a second at most while the frames are under 10 s
  // old (the old loop drew about 8 times a second).
  EXPECT_LE(static_cast<double>(s["presented"].get<long>() - presented0), seconds + 1.0)
      << "drawn " << s["presented"].get<long>() - presented0 << " times in " << seconds << " s of idling";

  // The mouse over the image: drawn, with the hover line where the mouse is.
  const json image = s["items"]["view_images"];
  const float x = image[0].get<float>() + 0.25f * (image[2].get<float>() - image[0].get<float>());
  const float y = 0.5f * (image[1].get<float>() + image[3].get<float>());
  for (const float dx : {0.0f, 40.0f}) {
    const long before = app.state().value("presented", 0L);
    const std::string oldLine = s.contains("hover") && !s["hover"].is_null() ? s["hover"]["text"].get<std::string>() : "";
    app.moveTo(x + dx, y);
    s = app.waitFor("the hover line drawn at the mouse", [&](const json& st) {
      return st.value("presented", 0L) > before && st.contains("hover") && !st["hover"].is_null() &&
             st["hover"]["text"].get<std::string>() != oldLine;
    });
  }

  // An expose (the window unmapped and mapped again: X drops its pixels) draws it again, as it was.
  s = waitIdle();
  const fs::path dir = app.dir();
  const bool haveImport = haveCommand("import");
  if (haveImport) {
    EXPECT_EQ(std::system(("import -window " + window + " '" + (dir / "before.png").string() + "'").c_str()), 0);
  }
  const long beforeExpose = app.state().value("presented", 0L);
  app.xdotool("windowunmap --sync " + window);
  app.xdotool("windowmap --sync " + window);
  s = app.waitFor("a frame after the expose", [&](const json& st) { return st.value("presented", 0L) > beforeExpose; });
  s = waitIdle();
  if (!haveImport) {
    std::cerr << "ImageMagick's import is missing (Debian package imagemagick): the window's pixels after the expose are not compared\n";
    EXPECT_FALSE(twr::test::everyDependencyRequired()) << "missing dependency ImageMagick (import, compare)";
  } else {
    EXPECT_EQ(std::system(("import -window " + window + " '" + (dir / "after.png").string() + "'").c_str()), 0);
    // The same window but for the tags' ages and the mouse: a few hundred pixels at most.
    const std::string differing = capture("compare -metric AE '" + (dir / "before.png").string() + "' '" +
                                          (dir / "after.png").string() + "' null: 2>&1");
    // compare prints the count alone ("123", or "1.2e+03"); anything else is an error message.
    char* end = nullptr;
    const double count = std::strtod(differing.c_str(), &end);
    ASSERT_TRUE(end != differing.c_str() && std::string(end).find_first_not_of(" \n") == std::string::npos)
        << "compare did not print a pixel count: " << differing;
    EXPECT_LT(count, 5000.0) << "pixels differing after the expose: " << differing;
  }
  EXPECT_EQ(app.quit(), 0) << app.err();
}

// A tooltip on a disabled control (the Rendering tab's March with SSR off) was drawn with the
// disabled items' dimmed alpha: see-through and unreadable over the panel. Its text must be
// drawn at full alpha and its brightest pixels (the text's) must be near white.
TEST(GuiScripted, TooltipOfADisabledControlIsOpaque) {
  REQUIRE_DISPLAY_AND_XDOTOOL();
  if (!haveCommand("import") || !haveCommand("convert")) {
    TWR_MISSING_DEPENDENCY("imagemagick") << "import and convert read the tooltip's pixels";
  }
  GuiProcess app(testName(), {kDefaultScene, "--reset"});
  const std::string window = app.window();
  app.waitSettled();
  app.click("tab_rendering");
  app.scrollTo("ssr_march");
  json s = app.waitForItem("ssr_march");
  ASSERT_TRUE(s.value("ssr_march_disabled", false)) << "the default scene has SSR off, so March is disabled";
  const json r = s["items"]["ssr_march"];
  app.moveTo(0.5f * (r[0].get<float>() + r[2].get<float>()), 0.5f * (r[1].get<float>() + r[3].get<float>()));
  s = app.waitFor("the March tooltip", [](const json& st) {
    return st.contains("tooltip") && st["tooltip"].is_object() &&
           st["tooltip"]["text"].get<std::string>().find("linear_world") != std::string::npos;
  });
  s = app.waitFrames(3);  // drawn, at its final size
  ASSERT_TRUE(s["tooltip"].is_object()) << s.dump(1);
  EXPECT_FLOAT_EQ(s["tooltip"]["alpha"].get<float>(), 1.0f);
  const json rect = s["tooltip"]["rect"];
  const int x0 = static_cast<int>(rect[0].get<float>()), y0 = static_cast<int>(rect[1].get<float>());
  const int w = static_cast<int>(rect[2].get<float>()) - x0, h = static_cast<int>(rect[3].get<float>()) - y0;
  const fs::path shot = app.dir() / "tooltip.png";
  ASSERT_EQ(std::system(("import -window " + window + " '" + shot.string() + "'").c_str()), 0);
  // Text is white (ImGuiCol_Text ~ 1.0): its brightest pixel is above 0.85 at full alpha; dimmed
  // by DisabledAlpha (0.6) over the dark panel it stays under 0.7.
  const std::string brightest =
      capture("convert '" + shot.string() + "' -crop " + std::to_string(w) + "x" + std::to_string(h) + "+" +
              std::to_string(x0) + "+" + std::to_string(y0) + " -colorspace Gray -format '%[fx:maxima]' info:");
  EXPECT_GT(std::strtod(brightest.c_str(), nullptr), 0.85) << "brightest tooltip pixel: " << brightest << " in " << shot;
  EXPECT_EQ(app.quit(), 0) << app.err();
}

// True when rectangle `inner` [x0, y0, x1, y1] lies inside `outer` (to a pixel).
bool insideRect(const json& inner, const json& outer) {
  constexpr float kSlackPixels = 1.0f;
  return inner[0].get<float>() >= outer[0].get<float>() - kSlackPixels &&
         inner[1].get<float>() >= outer[1].get<float>() - kSlackPixels &&
         inner[2].get<float>() <= outer[2].get<float>() + kSlackPixels &&
         inner[3].get<float>() <= outer[3].get<float>() + kSlackPixels;
}

// At 800x500 the View toolbar's second row ran past the window's edge and "Checker bg" and
// "Lights" were cut off; now the row wraps and the header makes room for the rows it takes.
TEST(GuiScripted, ViewToolbarWrapsInANarrowWindowInsteadOfCuttingControls) {
  REQUIRE_DISPLAY_AND_XDOTOOL();
  GuiProcess app(testName(), {kDefaultScene, "--reset", "--window-size", "800", "500"});
  app.window();
  app.waitSettled();
  json s = app.waitFor("the toolbar's checkboxes", [](const json& st) {
    return st.contains("items") && st["items"].contains("checker_bg") && st["items"].contains("show_lights") &&
           st["items"].contains("view_images");
  });
  s = app.waitFrames(3);  // the header sized for the rows the toolbar took
  ASSERT_TRUE(s.contains("window") && s["items"].contains("show_lights")) << s.dump(1);
  const json window = {0.0f, 0.0f, s["window"][0], s["window"][1]};
  for (const char* item : {"checker_bg", "show_lights", "screenshot"}) {
    EXPECT_TRUE(insideRect(s["items"][item], window)) << item << " " << s["items"][item].dump() << " in " << window.dump();
    EXPECT_LE(s["items"][item][3].get<float>(), s["items"]["view_images"][1].get<float>())
        << item << " overlaps the images";
  }
  EXPECT_GT(s.value("toolbar_rows", 0), 2) << "800 px is too narrow for one row of resolution controls";
  EXPECT_EQ(app.quit(), 0) << app.err();
}

// The Stats panel's line "UI N redraws/s ... GL frames: context, version, renderer" ran past
// the column and was cut; now it wraps inside it.
TEST(GuiScripted, StatsLineWrapsInsideItsColumn) {
  REQUIRE_DISPLAY_AND_XDOTOOL();
  GuiProcess app(testName(), {kDefaultScene, "--reset"});
  app.window();
  app.waitSettled();
  const json s = app.waitFor("the stats line", [](const json& st) {
    return st.contains("items") && st["items"].contains("stats_gl_line") && st["items"].contains("stats_panel");
  });
  ASSERT_TRUE(s.contains("items") && s["items"].contains("stats_gl_line")) << s.dump(1);
  const json& line = s["items"]["stats_gl_line"];
  const json& column = s["items"]["stats_panel"];
  // Across only: the column scrolls, so the line may lie below what is in view.
  EXPECT_TRUE(insideRect(json{line[0], column[1], line[2], column[3]}, column))
      << line.dump() << " sticks out of the stats column " << column.dump();
  EXPECT_EQ(app.quit(), 0) << app.err();
}

// "Lights off screen" was drawn over the image from the first frame of the default scene (its
// lights lie outside the view), hiding part of it; the hint now sits in the caption above.
TEST(GuiScripted, LightsOffScreenHintIsInTheCaptionNotOverTheImage) {
  REQUIRE_DISPLAY_AND_XDOTOOL();
  GuiProcess app(testName(), {kDefaultScene, "--reset"});
  app.window();
  app.waitSettled();
  const json s = app.waitFor("the lights hint in the caption", [](const json& st) {
    return !st.value("lights_hint", "").empty() && st.value("caption", "").find("outside the image") != std::string::npos;
  });
  EXPECT_NE(s.value("caption", "").find(s.value("lights_hint", "?")), std::string::npos) << s.dump(1);
  EXPECT_EQ(app.quit(), 0) << app.err();
}

// The stage explorer on a triangle the near plane and side planes both cut: inside_near.json at
// pixel (600, 50) of the 640 x 480 render, triangle 3 of the cube around the camera (cut by
// right, top, bottom and near). What the window shows is held to `twinraster trace --json`.
const std::string kInsideNearScene = std::string(TWINRASTER_SOURCE_DIR) + "/assets/scenes/inside_near.json";
constexpr int kExplorerX = 600, kExplorerY = 50;

// The CLI's trace of the explorer's pixel: the shaded visit that wrote it.
json explorerTraceVisit(int width, int height) {
  const std::string text = capture("\"" + std::string(TWINRASTER_CLI) + "\" trace \"" + kInsideNearScene + "\" " +
                                   std::to_string(kExplorerX) + " " + std::to_string(kExplorerY) + " --width " +
                                   std::to_string(width) + " --height " + std::to_string(height) + " --json 2>/dev/null");
  json visit;
  try {
    const json trace = json::parse(text);
    for (const json& t : trace["triangles"]) {
      if (t["outcome"] == "shaded") visit = t;
    }
  } catch (const json::exception& e) {
    ADD_FAILURE() << "trace --json did not parse: " << e.what() << "\n" << text;
  }
  return visit;
}

std::string sixDigits(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.6g", v);
  return text;
}

bool anyLineHas(const json& explorer, const std::string& text) {
  for (const json& line : explorer["lines"]) {
    if (line.get<std::string>().find(text) != std::string::npos) return true;
  }
  return false;
}

// Starts the app pinned on the explorer's pixel and waits for the explorer to show.
json openExplorer(GuiProcess& app) {
  app.window();
  app.waitSettled();
  return app.waitFor("the stage explorer", [](const json& s) { return s.contains("explorer") && s.contains("render"); });
}

// Shows `stage` with its button and returns what the explorer then shows.
json explorerStage(GuiProcess& app, const std::string& stage) {
  app.click("explorer_stage_" + stage);
  const json s = app.waitFor("the explorer at " + stage, [&](const json& st) {
    return st.contains("explorer") && st["explorer"]["stage"] == stage;
  });
  return s.value("explorer", json::object());
}

std::vector<std::string> guiArgs() {
  return {kInsideNearScene, "--reset", "--window-size", "1400", "900", "--pin",
          std::to_string(kExplorerX) + "," + std::to_string(kExplorerY)};
}

// The app pinned on the explorer's pixel, showing the explorer, and the CLI's trace of that
// pixel at the app's render size.
struct ExplorerSession {
  GuiProcess app{testName(), guiArgs()};
  json state = openExplorer(app);
  int width = state.contains("render") ? state["render"][0].get<int>() : 0;
  int height = state.contains("render") ? state["render"][1].get<int>() : 0;
  json visit = explorerTraceVisit(width, height);
};

TEST(GuiScripted, StageExplorerStepsEveryStageWithNextAndPrevious) {
  REQUIRE_DISPLAY_AND_XDOTOOL();
  GuiProcess app(testName(), guiArgs());
  const json first = openExplorer(app);
  EXPECT_EQ(first["explorer"]["stage"], "vertex") << first["explorer"].dump(1);
  for (const char* stage : {"clip", "divide", "setup", "raster", "interpolate", "shade"}) {
    app.click("explorer_next");
    const json s = app.waitFor(std::string("next to ") + stage, [&](const json& st) { return st["explorer"]["stage"] == stage; });
    EXPECT_FALSE(s["explorer"]["lines"].empty()) << stage;
  }
  app.click("explorer_next");  // held at the last stage
  EXPECT_EQ(app.waitFrames(2)["explorer"]["stage"], "shade");
  app.click("explorer_previous");
  app.waitFor("back to interpolate", [](const json& st) { return st["explorer"]["stage"] == "interpolate"; });
  EXPECT_EQ(app.quit(), 0) << app.err();
}

TEST(GuiScripted, StageExplorerClipShowsTheTracesPlanesAndIntersections) {
  REQUIRE_DISPLAY_AND_XDOTOOL();
  ExplorerSession session;
  ASSERT_FALSE(session.visit.is_null());
  std::vector<std::string> planes;
  for (const json& step : session.visit["clip_steps"]) planes.push_back(step["plane"].get<std::string>());
  ASSERT_NE(std::find(planes.begin(), planes.end(), "near"), planes.end()) << "the scene no longer has the near cut";
  ASSERT_NE(std::find(planes.begin(), planes.end(), "right"), planes.end()) << "the scene no longer has the side cut";
  const json clip = explorerStage(session.app, "clip");
  for (const json& step : session.visit["clip_steps"]) {
    EXPECT_TRUE(anyLineHas(clip, step["plane"].get<std::string>() + ": ")) << step["plane"] << clip.dump(1);
    for (const json& cut : step["new_vertices"]) {
      EXPECT_TRUE(anyLineHas(clip, " at t " + sixDigits(cut["t"].get<double>()))) << cut.dump() << clip.dump(1);
    }
  }
  EXPECT_EQ(clip["overlay"]["polygon"].size(), session.visit["clipped_polygon"].size());
  EXPECT_EQ(clip["overlay"]["triangle"].size(), 3u) << "every corner lies in front of the eye";
  // The first pass alone: the triangle before the plane, what the plane left after it.
  session.app.click("explorer_pass_next");
  const json first = session.app.waitFor("the first pass", [](const json& st) {
    return st.contains("explorer") && st["explorer"]["clip_pass"] == 0;
  })["explorer"];
  const json& step = session.visit["clip_steps"][0];
  EXPECT_EQ(first["overlay"]["polygon_before"].size(), 3u) << first.dump(1);
  EXPECT_EQ(first["overlay"]["polygon"].size(), step["polygon"].size()) << first.dump(1);
  EXPECT_TRUE(anyLineHas(first, "> " + step["plane"].get<std::string>() + ": ")) << first.dump(1);
  // The pass in clip space: z against w holds the trace's positions after it, each (z, w).
  session.app.scrollInspectorTo("explorer_axes_z-w");
  session.app.click("explorer_axes_z-w");
  const json plot = session.app.waitFor("the z-w plot", [](const json& st) {
    return st.contains("explorer") && st["explorer"].contains("clip_plot") && st["explorer"]["clip_plot"]["axes"] == "z-w";
  })["explorer"]["clip_plot"];
  ASSERT_EQ(plot["after"].size(), step["polygon"].size()) << plot.dump(1);
  for (std::size_t k = 0; k < plot["after"].size(); ++k) {
    EXPECT_EQ(plot["after"][k][0], step["polygon"][k][2]) << k;
    EXPECT_EQ(plot["after"][k][1], step["polygon"][k][3]) << k;
  }
  ASSERT_EQ(plot["cut_t"].size(), step["new_vertices"].size());
  for (std::size_t k = 0; k < plot["cut_t"].size(); ++k) EXPECT_EQ(plot["cut_t"][k], step["new_vertices"][k]["t"]);
  EXPECT_EQ(session.app.quit(), 0) << session.app.err();
}

// The point is inside the triangle (either winding, edges included).
bool insideTriangle(const json& t, double x, double y) {
  const auto side = [&](const json& a, const json& b) {
    return (b[0].get<double>() - a[0].get<double>()) * (y - a[1].get<double>()) -
           (b[1].get<double>() - a[1].get<double>()) * (x - a[0].get<double>());
  };
  const double d0 = side(t[0], t[1]), d1 = side(t[1], t[2]), d2 = side(t[2], t[0]);
  return (d0 >= 0 && d1 >= 0 && d2 >= 0) || (d0 <= 0 && d1 <= 0 && d2 <= 0);
}

TEST(GuiScripted, StageExplorerOverlayDrawsTheTracedFanOnTheImage) {
  REQUIRE_DISPLAY_AND_XDOTOOL();
  ExplorerSession session;
  ASSERT_FALSE(session.visit.is_null());
  const json divide = explorerStage(session.app, "divide");
  const json& overlay = divide["overlay"];
  ASSERT_EQ(overlay["fan"].size(), session.visit["clipped_polygon"].size() - 2);
  // The trace's fan triangle i is (0, i, i + 1), the overlay's fan[i - 1].
  ASSERT_EQ(overlay["fan_triangle"].get<int>(), session.visit["fan_triangle"].get<int>() - 1);
  const json& covering = overlay["fan"][overlay["fan_triangle"].get<std::size_t>()];
  EXPECT_TRUE(insideTriangle(covering, kExplorerX + 0.5, kExplorerY + 0.5)) << covering.dump();
  // Each corner setup received (window x, y; GL rows) is a corner of the covering fan triangle.
  for (const json& corner : session.visit["window_xyz_invw"]) {
    const double x = corner[0].get<double>(), y = session.height - corner[1].get<double>();
    bool found = false;
    for (const json& p : covering) found = found || (std::abs(p[0].get<double>() - x) < 1e-3 && std::abs(p[1].get<double>() - y) < 1e-3);
    EXPECT_TRUE(found) << corner.dump() << " not among " << covering.dump();
  }
  EXPECT_EQ(session.app.quit(), 0) << session.app.err();
}

TEST(GuiScripted, StageExplorerSetupRasterAndShadeShowTheTracesNumbers) {
  REQUIRE_DISPLAY_AND_XDOTOOL();
  ExplorerSession session;
  ASSERT_FALSE(session.visit.is_null());
  const json setup = explorerStage(session.app, "setup");
  const json& snapped = setup["overlay"]["snapped"];
  ASSERT_EQ(snapped.size(), 3u);
  for (std::size_t i = 0; i < 3; ++i) {
    const json& fixed = session.visit["snapped_fixed_8"][i];
    EXPECT_DOUBLE_EQ(snapped[i][0].get<double>(), fixed[0].get<double>() / 256.0 + 0.5);
    EXPECT_DOUBLE_EQ(snapped[i][1].get<double>(), session.height - (fixed[1].get<double>() / 256.0 + 0.5));
    EXPECT_TRUE(anyLineHas(setup, "E " + std::to_string(session.visit["edge_values"][i].get<long long>()))) << setup.dump(1);
  }
  const json& box = setup["overlay"]["bounding_box"];
  EXPECT_TRUE(box[0].get<int>() <= kExplorerX && kExplorerX <= box[2].get<int>() && box[1].get<int>() <= kExplorerY &&
              kExplorerY <= box[3].get<int>())
      << box.dump();
  const json raster = explorerStage(session.app, "raster");
  EXPECT_GT(raster["overlay"]["covered"].get<int>(), 0) << raster.dump(1);
  // GL's image marks the pixels GL's frame gave the triangle: the same ones on this scene.
  EXPECT_EQ(raster["overlay"].value("covered_gl", -1), raster["overlay"]["covered"].get<int>()) << raster.dump(1);
  const json interpolate = explorerStage(session.app, "interpolate");
  EXPECT_TRUE(anyLineHas(interpolate, "screen barycentrics (" + sixDigits(session.visit["barycentrics"][0].get<double>())))
      << interpolate.dump(1);
  const json shade = explorerStage(session.app, "shade");
  EXPECT_TRUE(anyLineHas(shade, "colour (" + sixDigits(session.visit["shading"]["colour"][0].get<double>()))) << shade.dump(1);
  EXPECT_EQ(session.app.quit(), 0) << session.app.err();
}

// The raster's visit order stepped with the buttons, the Interpolate stage's two maps and the
// Shade stage's frame, each held to `twinraster trace --json` at the pixel.
TEST(GuiScripted, StageExplorerVisitOrderWeightMapsAndFrameFollowTheTrace) {
  REQUIRE_DISPLAY_AND_XDOTOOL();
  ExplorerSession session;
  ASSERT_FALSE(session.visit.is_null());
  GuiProcess& app = session.app;
  const json raster = explorerStage(app, "raster");
  EXPECT_EQ(raster["raster_step"], -1) << "no step until one is asked for";
  const int steps = raster["raster_steps"].get<int>();
  EXPECT_GT(steps, 0) << raster.dump(1);
  // The fill rule along the edge the two fan triangles share: each pixel near it drawn once.
  const json& shared = raster["overlay"]["shared_edge"];
  EXPECT_GT(shared.value("mine", 0), 0) << raster.dump(1);
  EXPECT_GT(shared.value("theirs", 0), 0) << raster.dump(1);
  EXPECT_EQ(shared.value("both", -1), 0) << raster.dump(1);
  EXPECT_TRUE(anyLineHas(raster, "fill rule at the edge shared with fan triangle")) << raster.dump(1);
  EXPECT_TRUE(anyLineHas(raster, "visit order of fan triangle " + std::to_string(session.visit["fan_triangle"].get<int>()) +
                                     ": " + std::to_string(steps) + " pixels"))
      << raster.dump(1);
  const auto stepShown = [&](const std::string& button, const std::string& what, const std::function<bool(const json&)>& done) {
    app.click(button);
    return app.waitFor(what, [&](const json& st) { return st.contains("explorer") && done(st["explorer"]); })["explorer"];
  };
  const json first = stepShown("explorer_pixel_next", "the first step", [](const json& e) { return e["raster_step"] == 0; });
  const int firstRow = first["overlay"]["visit_pixel"][1].get<int>();
  EXPECT_LE(firstRow, first["overlay"]["bounding_box"][3].get<int>());
  EXPECT_GE(firstRow, kExplorerY) << "the bottom rows come first";
  EXPECT_EQ(first["overlay"]["visited"], 1);
  const json next = stepShown("explorer_span_next", "the next span", [](const json& e) { return e["raster_step"].get<int>() > 0; });
  EXPECT_EQ(next["overlay"]["visit_pixel"][1].get<int>(), firstRow - 1) << "one row up";
  const json traced = stepShown("explorer_step_traced", "the traced pixel's step", [&](const json& e) {
    return e["overlay"].contains("visit_pixel") && e["overlay"]["visit_pixel"] == json::array({kExplorerX, kExplorerY});
  });
  EXPECT_EQ(traced["overlay"]["visited"].get<int>(), traced["raster_step"].get<int>() + 1);
  // Interpolate: the map's weights at the pixel are the trace's, screen then perspective.
  const json screen = explorerStage(app, "interpolate");
  ASSERT_TRUE(screen["overlay"].contains("weight_map")) << screen.dump(1);
  EXPECT_EQ(screen["overlay"]["weight_map"]["covered"].get<int>(), steps);
  EXPECT_EQ(screen["overlay"]["weight_map"]["at_pixel"], session.visit["barycentrics"]) << screen.dump(1);
  const json perspective = stepShown("explorer_weights_perspective", "the perspective map",
                                     [](const json& e) { return e["weights"] == "perspective"; });
  EXPECT_EQ(perspective["overlay"]["weight_map"]["at_pixel"], session.visit["perspective_weights"]);
  // Shade: the frame's arrows start at the fragment, the pixel's centre.
  const json shade = explorerStage(app, "shade");
  const json& frame = shade["overlay"]["frame"];
  for (const char* axis : {"N", "L"}) {
    ASSERT_TRUE(frame.contains(axis)) << shade.dump(1);
    EXPECT_NEAR(frame[axis][0][0].get<double>(), kExplorerX + 0.5, 0.05) << axis;
    EXPECT_NEAR(frame[axis][0][1].get<double>(), kExplorerY + 0.5, 0.05) << axis;
  }
  EXPECT_TRUE(anyLineHas(shade, "N (" + sixDigits(session.visit["shading"]["N"][0].get<double>()))) << shade.dump(1);
  EXPECT_EQ(app.quit(), 0) << app.err();
}

}  // namespace
