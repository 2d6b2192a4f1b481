// What the app remembers between runs (not the scene's render settings: those come from the
// scene file). Stored as JSON in <config>/gui.json beside ImGui's window layout
// <config>/imgui.ini, where <config> is $XDG_CONFIG_HOME/twinraster, else
// $HOME/.config/twinraster. `--reset` deletes both files.
#pragma once

#include "gui/view_mode.h"
#include "compare/colours.h"
#include "softrender/cpu_renderer.h"

#include <filesystem>
#include <string>
#include <vector>

namespace twr::gui {

enum class ResolutionSource {
  SceneOutput,  // the scene's output.width x output.height, times the scale
  FitView,      // the size of one image panel on screen (framebuffer pixels), times the scale
};

// Bounds of the resolution scale, inclusive.
inline constexpr float kMinResolutionScale = 0.125f;
inline constexpr float kMaxResolutionScale = 2.0f;
// Bounds of the flicker rate, in switches per second (Hz), inclusive.
inline constexpr float kMinFlickerHz = 0.25f;
inline constexpr float kMaxFlickerHz = 30.0f;

struct GuiPrefs {
  std::string lastScene;  // opened when no SCENE is given
  ViewMode viewMode = ViewMode::SideBySide;
  ResolutionSource resolution = ResolutionSource::SceneOutput;
  float resolutionScale = 1.0f;
  float flickerHz = 2.0f;
  float splitFraction = 0.5f;  // divider position across the image, 0 = left edge, 1 = right edge
  bool checkerBackground = false;  // background pixels shown as a checker instead of their colour
  bool showLights = true;          // light markers over the images (drag them to move a light)
  bool diffShowClasses = false;    // diff view: class map instead of the heat map
  HeatScale heatScale = HeatScale::Log;
  int heatMaxLevels = 32;  // heat ramp top, levels in [1, 255]
  std::string screenshotDir = "out/screenshots";  // relative to the working folder
  // The CPU renderer: traversal, and the fast path's Highway target (a remembered target this
  // CPU cannot run falls back to auto with a warning).
  CpuPath cpuPath = CpuPath::Fast;
  CpuIsa cpuIsa = CpuIsa::Auto;
  // The panel sizes the user dragged to, points at UI scale 1; 0: the default. Kept here,
  // not in imgui.ini, so a window squeezed for a moment never saves a squeezed panel
  // (panel_sizing.h); a value below the panel's minimum is raised to it when used.
  float controlsWidth = 0.0f;
  float statsHeight = 0.0f;
  bool linearDepth = false;  // the Depth view shows the eye distance between near and far (debug_views.h)
  std::vector<std::string> recentScenes;  // newest first, at most kMaxRecentScenes
};

// Largest panel size the settings file may hold, points (inclusive).
inline constexpr float kMaxSavedPanelPoints = 10000.0f;

struct PrefsPaths {
  std::filesystem::path dir;   // empty when neither XDG_CONFIG_HOME nor HOME is set
  std::filesystem::path prefs;  // <dir>/gui.json
  std::filesystem::path imguiIni;  // <dir>/imgui.ini
};

PrefsPaths prefsPaths();

// Reads the file; a missing file gives the defaults. A malformed file or value is reported
// in `warning` and that value keeps its default (settings are a convenience, never fatal).
GuiPrefs loadPrefs(const std::filesystem::path& path, std::string& warning);
// Writes the file, creating its folder; returns false and fills `error` when it cannot.
bool savePrefs(const std::filesystem::path& path, const GuiPrefs& prefs, std::string& error);
// Deletes both files (--reset); returns what was removed, for the log.
std::string resetPrefs(const PrefsPaths& paths);

}  // namespace twr::gui
