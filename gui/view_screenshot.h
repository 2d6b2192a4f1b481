// The images the screenshot key saves, made from the two frames on the CPU: the view as the
// window shows it (one backend, side by side, split at the divider, or the diff), and the
// window's own read-back turned top row first. No ImGui or GL here, so tests/gui checks them.
#pragma once

#include "compare/metrics.h"
#include "gui/prefs.h"
#include "gui/view_mode.h"
#include "scene/image.h"

#include <cstdint>
#include <ctime>
#include <optional>
#include <string>
#include <vector>

namespace twr::gui {

// What the view area shows at a moment: the mode itself, but for flicker the backend its phase
// shows (CPU first), `secondsSinceStart` into a flicker of `hz` swaps per second.
ViewMode shownViewMode(ViewMode mode, double secondsSinceStart, double hz);

// A split-view image: CPU columns left of the divider at `fraction` of the width, GL columns
// from it on, and a white one-pixel divider column, as on screen. The images share one size.
Image composeSplit(const Image& cpu, const Image& gl, float fraction);

// The view `shown` (never Flicker: shownViewMode first) as the window draws it with `prefs`'
// background, divider and diff settings. Throws InputError when the frames cannot make it yet:
// a split of two sizes (a resize in flight), a diff not yet computed.
Image viewScreenshotOf(const RenderOutput& cpu, const RenderOutput& gl, ViewMode shown, const GuiPrefs& prefs,
                       const std::optional<CompareResult>& diff);

// "<dir>/twinraster-YYYYmmdd-HHMMSS" in local time; dir "" is the working folder.
std::string screenshotStem(const std::string& dir, std::time_t when);

// glReadPixels' rows (bottom row first, RGBA8, tightly packed) as an opaque image, top row first.
Image imageFromBottomRows(int width, int height, const std::vector<std::uint8_t>& bottomFirst);

}  // namespace twr::gui
