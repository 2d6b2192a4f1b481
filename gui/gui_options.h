// What the command line asks of the app (main.cpp parses it).
#pragma once

#include "gui/pixel_probe.h"
#include "gui/view_mode.h"
#include "softrender/cpu_renderer.h"

#include <optional>
#include <string>

namespace twr::gui {

// Longest --frames run waits for the CPU frame of the final settings, milliseconds.
inline constexpr int kSettleTimeoutMs = 120'000;
// Most frames --frames accepts (inclusive): a day at 60 frames a second.
inline constexpr int kMaxFrames = 5'184'000;

struct GuiOptions {
  std::string scenePath;              // empty: the remembered scene, else the default one
  int frames = 0;                     // > 0: quit after this many frames (once settled)
  std::string screenshotPath;         // non-empty: save the whole window on the last frame
  std::optional<ViewMode> viewMode;   // overrides the remembered view mode
  std::optional<CpuPath> cpuPath;     // override the remembered CPU path and target
  std::optional<CpuIsa> cpuIsa;
  std::optional<PixelPos> pin;        // a pixel to pin at start
  bool reset = false;                 // delete the remembered settings first
  bool glFastSampling = false;        // let llvmpipe use its fast texture path
  int width = 1280, height = 800;     // window size, screen coordinates
};

}  // namespace twr::gui
