// A window on the app's state for scripted GUI tests (tests/gui): with the environment
// variable TWINRASTER_GUI_TEST_STATE=FILE set, every frame writes FILE as JSON: where named
// widgets are on screen (window coordinates, so xdotool can click them wherever the fonts
// put them), the render size, the panel sizes, the hover line, the edit counters and the
// errors on screen. Off, and free, when the variable is unset. An idle app draws no frames
// (redraw_policy.h); for this file it still lays one out now and then, not drawn, so a test
// waiting for frames sees them come ("presented" counts the frames drawn on screen).
#pragma once

#include <imgui.h>
#include <nlohmann/json.hpp>

#include <string>

namespace twr::gui {

inline constexpr const char* kTestStateVariable = "TWINRASTER_GUI_TEST_STATE";

class TestProbe {
 public:
  TestProbe();
  bool enabled() const { return !path_.empty(); }
  // Forgets last frame's widgets (a widget not drawn this frame is not clickable).
  void beginFrame();
  // Records the last ImGui item's rectangle under `name` as [x0, y0, x1, y1].
  void item(const char* name);
  // Any other value: state()["render"] = {w, h}.
  nlohmann::json& state() { return state_; }
  // Writes the file when its text changed (written beside it and renamed, so a reader never
  // sees half a file).
  void endFrame();

 private:
  std::string path_;
  nlohmann::json state_;
  std::string lastWritten_;
};

}  // namespace twr::gui
