#include "gui/prefs.h"
#include "scene/json_text.h"
#include "gui/scene_picker.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <sstream>

namespace twr::gui {
namespace {

using nlohmann::json;

std::string_view toString(ResolutionSource source) {
  return source == ResolutionSource::FitView ? "fit_view" : "scene_output";
}

std::string_view toString(HeatScale scale) { return scale == HeatScale::Linear ? "linear" : "log"; }

std::string_view toString(CpuPath path) { return path == CpuPath::Teaching ? "teaching" : "fast"; }

// Each reader keeps `value` and notes the key when the JSON holds something else.
void readString(const json& object, const char* key, std::string& value, std::string& warning) {
  if (!object.contains(key)) return;
  if (object[key].is_string()) {
    value = object[key].get<std::string>();
  } else {
    warning += std::string(warning.empty() ? "" : "; ") + key + ": expected a string";
  }
}

void readFloat(const json& object, const char* key, float minimum, float maximum, float& value,
               std::string& warning) {
  if (!object.contains(key)) return;
  if (object[key].is_number()) {
    const double read = object[key].get<double>();
    if (read >= minimum && read <= maximum) {
      value = static_cast<float>(read);
      return;
    }
  }
  std::ostringstream message;
  message << key << ": expected a number in [" << minimum << ", " << maximum << "]";
  warning += (warning.empty() ? "" : "; ") + message.str();
}

void readBool(const json& object, const char* key, bool& value, std::string& warning) {
  if (!object.contains(key)) return;
  if (object[key].is_boolean()) {
    value = object[key].get<bool>();
  } else {
    warning += std::string(warning.empty() ? "" : "; ") + key + ": expected true or false";
  }
}

}  // namespace

PrefsPaths prefsPaths() {
  PrefsPaths paths;
  const char* xdg = std::getenv("XDG_CONFIG_HOME");
  const char* home = std::getenv("HOME");
  if (xdg && *xdg) {
    paths.dir = std::filesystem::path(xdg) / "twinraster";
  } else if (home && *home) {
    paths.dir = std::filesystem::path(home) / ".config" / "twinraster";
  } else {
    return paths;
  }
  paths.prefs = paths.dir / "gui.json";
  paths.imguiIni = paths.dir / "imgui.ini";
  return paths;
}

GuiPrefs loadPrefs(const std::filesystem::path& path, std::string& warning) {
  GuiPrefs prefs;
  warning.clear();
  if (path.empty() || !std::filesystem::exists(path)) return prefs;
  std::ifstream in(path);
  json object;
  try {
    object = json::parse(in);
  } catch (const json::exception& e) {
    warning = path.string() + ": not valid JSON (" + e.what() + "); using the defaults";
    return prefs;
  }
  if (!object.is_object()) {
    warning = path.string() + ": expected a JSON object; using the defaults";
    return prefs;
  }
  std::string problems;
  readString(object, "last_scene", prefs.lastScene, problems);
  std::string name;
  readString(object, "view_mode", name, problems);
  if (!name.empty() && !parse(name, prefs.viewMode)) problems += "; view_mode: expected " + allViewModeNames();
  name.clear();
  readString(object, "resolution", name, problems);
  if (name == "fit_view") prefs.resolution = ResolutionSource::FitView;
  else if (!name.empty() && name != "scene_output") problems += "; resolution: expected scene_output|fit_view";
  readFloat(object, "resolution_scale", kMinResolutionScale, kMaxResolutionScale, prefs.resolutionScale, problems);
  readFloat(object, "flicker_hz", kMinFlickerHz, kMaxFlickerHz, prefs.flickerHz, problems);
  readFloat(object, "split_fraction", 0.0f, 1.0f, prefs.splitFraction, problems);
  readBool(object, "checker_background", prefs.checkerBackground, problems);
  readBool(object, "diff_show_classes", prefs.diffShowClasses, problems);
  readBool(object, "show_lights", prefs.showLights, problems);
  name.clear();
  readString(object, "heat_scale", name, problems);
  if (name == "linear") prefs.heatScale = HeatScale::Linear;
  else if (!name.empty() && name != "log") problems += "; heat_scale: expected linear|log";
  float maxLevels = static_cast<float>(prefs.heatMaxLevels);
  readFloat(object, "heat_max_levels", 1.0f, 255.0f, maxLevels, problems);
  prefs.heatMaxLevels = static_cast<int>(maxLevels);
  readString(object, "screenshot_dir", prefs.screenshotDir, problems);
  name.clear();
  readString(object, "cpu_path", name, problems);
  if (name == "teaching") prefs.cpuPath = CpuPath::Teaching;
  else if (!name.empty() && name != "fast") problems += "; cpu_path: expected fast|teaching";
  readBool(object, "linear_depth", prefs.linearDepth, problems);
  if (object.contains("recent_scenes")) {
    const json& recent = object["recent_scenes"];
    bool ok = recent.is_array();
    for (std::size_t i = 0; ok && i < recent.size() && prefs.recentScenes.size() < kMaxRecentScenes; ++i) {
      ok = recent[i].is_string();
      if (ok) prefs.recentScenes.push_back(recent[i].get<std::string>());
    }
    if (!ok) problems += "; recent_scenes: expected an array of paths";
  }
  readFloat(object, "controls_width", 0.0f, kMaxSavedPanelPoints, prefs.controlsWidth, problems);
  readFloat(object, "stats_height", 0.0f, kMaxSavedPanelPoints, prefs.statsHeight, problems);
  name.clear();
  readString(object, "cpu_isa", name, problems);
  if (!name.empty()) {
    CpuIsa isa = CpuIsa::Auto;
    if (!parse(name, isa)) problems += "; cpu_isa: expected " + allCpuIsaNames();
    else if (!cpuIsaSupported(isa)) problems += "; cpu_isa: " + cpuIsaUnsupportedReason(isa);
    else prefs.cpuIsa = isa;
  }
  if (!problems.empty()) {
    if (problems.starts_with("; ")) problems.erase(0, 2);
    warning = path.string() + ": " + problems + " (kept the defaults for these)";
  }
  return prefs;
}

bool savePrefs(const std::filesystem::path& path, const GuiPrefs& prefs, std::string& error) {
  if (path.empty()) {
    error = "no settings folder (neither XDG_CONFIG_HOME nor HOME is set)";
    return false;
  }
  const json object = {
      {"last_scene", prefs.lastScene},
      {"view_mode", toString(prefs.viewMode)},
      {"resolution", toString(prefs.resolution)},
      {"resolution_scale", prefs.resolutionScale},
      {"flicker_hz", prefs.flickerHz},
      {"split_fraction", prefs.splitFraction},
      {"checker_background", prefs.checkerBackground},
      {"diff_show_classes", prefs.diffShowClasses},
      {"show_lights", prefs.showLights},
      {"heat_scale", toString(prefs.heatScale)},
      {"heat_max_levels", prefs.heatMaxLevels},
      {"screenshot_dir", prefs.screenshotDir},
      {"cpu_path", toString(prefs.cpuPath)},
      {"cpu_isa", toString(prefs.cpuIsa)},
      {"controls_width", prefs.controlsWidth},
      {"stats_height", prefs.statsHeight},
      {"linear_depth", prefs.linearDepth},
      {"recent_scenes", prefs.recentScenes},
  };
  std::error_code code;
  std::filesystem::create_directories(path.parent_path(), code);
  std::ofstream out(path);
  if (!out) {
    error = path.string() + ": cannot write the settings file";
    return false;
  }
  out << jsonText(object, 2) << "\n";
  return static_cast<bool>(out);
}

std::string resetPrefs(const PrefsPaths& paths) {
  std::string removed;
  for (const std::filesystem::path& file : {paths.prefs, paths.imguiIni}) {
    std::error_code code;
    if (!file.empty() && std::filesystem::remove(file, code)) removed += (removed.empty() ? "" : ", ") + file.string();
  }
  return removed.empty() ? "nothing to remove" : "removed " + removed;
}

}  // namespace twr::gui
