#include "gui/view_mode.h"

namespace twr::gui {

std::string_view toString(ViewMode mode) {
  switch (mode) {
    case ViewMode::Cpu: return "cpu";
    case ViewMode::Gl: return "gl";
    case ViewMode::SideBySide: return "side";
    case ViewMode::Split: return "split";
    case ViewMode::Diff: return "diff";
    case ViewMode::Flicker: return "flicker";
  }
  return "side";
}

const char* label(ViewMode mode) {
  switch (mode) {
    case ViewMode::Cpu: return "CPU";
    case ViewMode::Gl: return "GL";
    case ViewMode::SideBySide: return "Side by side";
    case ViewMode::Split: return "Split";
    case ViewMode::Diff: return "Diff";
    case ViewMode::Flicker: return "Flicker";
  }
  return "?";
}

bool parse(std::string_view name, ViewMode& out) {
  for (ViewMode mode : kAllViewModes) {
    if (toString(mode) == name) {
      out = mode;
      return true;
    }
  }
  return false;
}

std::string allViewModeNames() {
  std::string names;
  for (ViewMode mode : kAllViewModes) {
    if (!names.empty()) names += "|";
    names += toString(mode);
  }
  return names;
}

}  // namespace twr::gui
