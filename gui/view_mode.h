// What the view area shows: one backend, both, or how they differ.
#pragma once

#include <string>
#include <string_view>

namespace twr::gui {

enum class ViewMode {
  Cpu,         // the CPU image alone
  Gl,          // the GL image alone
  SideBySide,  // CPU left, GL right, same camera
  Split,       // one image, CPU left of a draggable divider, GL right of it
  Diff,        // the heat map of |CPU - GL| with the per-class counts
  Flicker,     // CPU and GL alternating at a chosen rate
};

inline constexpr ViewMode kAllViewModes[] = {ViewMode::Cpu,   ViewMode::Gl,   ViewMode::SideBySide,
                                             ViewMode::Split, ViewMode::Diff, ViewMode::Flicker};

// "cpu", "gl", "side", "split", "diff", "flicker" (command line and settings file).
std::string_view toString(ViewMode mode);
// Short labels for the toolbar.
const char* label(ViewMode mode);
// False for an unknown name.
bool parse(std::string_view name, ViewMode& out);
// "cpu|gl|side|split|diff|flicker" for help texts.
std::string allViewModeNames();

}  // namespace twr::gui
