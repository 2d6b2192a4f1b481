// twinraster-gui: the desktop app. See `twinraster-gui --help` and docs/gui.md.
#include "app/gui/app.h"
#include "gui/gui_options.h"
#include "scene/errors.h"

#include <CLI/CLI.hpp>

#include <cstdlib>
#include <iostream>
#include <sstream>

namespace {

// llvmpipe's precise texture path (per-pixel LOD, float bilinear weights), as the CLI's
// OSMesa contexts use, so the window's GL images match `twinraster compare`. llvmpipe reads
// GALLIVM_PERF once, when the first context is created: this runs before the window exists.
constexpr const char* kPerfVariable = "GALLIVM_PERF";
constexpr const char* kPreciseSamplingFlags[] = {"no_aos_sampling", "no_quad_lod"};

void requestPreciseSampling() {
  const char* existing = std::getenv(kPerfVariable);
  std::string flags = existing ? existing : "";
  for (const char* flag : kPreciseSamplingFlags) {
    std::stringstream list(flags);
    std::string item;
    bool present = false;
    while (std::getline(list, item, ',')) present = present || item == flag;
    if (present) continue;
    if (!flags.empty()) flags += ",";
    flags += flag;
  }
  setenv(kPerfVariable, flags.c_str(), 1);
}

}  // namespace

int main(int argc, char** argv) {
  using namespace twr;
  gui::GuiOptions options;
  std::string viewMode, pin, cpuPath, cpuIsa;
  CLI::App app{
      "twinraster-gui: the desktop app. Renders SCENE with the CPU software pipeline (on a worker thread) and "
      "with OpenGL 3.3 (in a headless EGL context on a second worker thread), and shows them side by side, split, flickering or diffed, "
      "with panels for every render setting, the scene, the camera, stats and a pixel inspector.\n"
      "Remembers its view settings in $XDG_CONFIG_HOME/twinraster (else ~/.config/twinraster): gui.json and "
      "imgui.ini.\nIn the window: drag to orbit, right-drag to pan, wheel to zoom, click to pin a pixel, F12 to save the "
      "whole window (the Screenshot button saves the view and both images).\nExit codes: 0 ok, 2 bad command line, no display or no usable OpenGL 3.3, or the screenshot "
      "could not be written. A scene file that does not load is shown as an error in the window (exit 0)."};
  app.add_option("SCENE", options.scenePath,
                 "Scene file (JSON, docs/scene-format.md). Default: the last scene opened, else "
                 "assets/scenes/default.json");
  app.add_flag("--reset", options.reset, "Forget the remembered settings and window layout before starting");
  app.add_option("--frames", options.frames,
                 "Quit after N frames (for tests and scripts); the last frame waits until the CPU frame, the diff "
                 "and any pinned pixel's probes for the final settings are done (at most 120 s)")
      ->check(CLI::Validator(
          [](std::string& text) -> std::string {
            int frames = 0;
            if (CLI::detail::lexical_cast(text, frames) && frames >= 1 && frames <= gui::kMaxFrames) return "";
            return "expected an integer in [1, " + std::to_string(gui::kMaxFrames) + "], got '" + text + "'";
          },
          "", "frame count"))
      ->type_name("N");
  app.add_option("--screenshot", options.screenshotPath,
                 "With --frames: save the whole window as this PNG on the last frame")
      ->type_name("FILE.png");
  app.add_option("--view-mode", viewMode, "Start in this view: " + gui::allViewModeNames())
      ->check(CLI::IsMember({"cpu", "gl", "side", "split", "diff", "flicker"}));
  app.add_option("--pin", pin,
                 "Pin the pixel X,Y (from the top-left, at the render size) in the inspector; a pixel outside "
                 "the render is reported on stderr and in the window, and nothing is pinned")
      ->type_name("X,Y");
  app.add_option("--window-size", [&options](const CLI::results_t& values) {
                   const bool ok = CLI::detail::lexical_cast(values[0], options.width) &&
                                   CLI::detail::lexical_cast(values[1], options.height) && options.width > 0 &&
                                   options.height > 0;
                   return ok;
                 },
                 "Window size W H in screen coordinates (default 1280 800)")
      ->expected(2)
      ->type_name("W H");
  app.add_option("--cpu-path", cpuPath,
                 "Start the CPU renderer on this traversal: fast or teaching (default: the remembered one; the "
                 "Rendering tab switches it)")
      ->check(CLI::IsMember({"fast", "teaching"}));
  app.add_option("--cpu-isa", cpuIsa,
                 "Start the CPU fast path on this target: " + allCpuIsaNames() +
                     " (default: the remembered one). A target this CPU cannot run exits 2.")
      ->check(CLI::Validator(
          [](std::string& text) -> std::string {
            CpuIsa isa = CpuIsa::Auto;
            if (!parse(text, isa)) return "expected one of " + allCpuIsaNames() + ", got '" + text + "'";
            return cpuIsaSupported(isa) ? std::string() : cpuIsaUnsupportedReason(isa);
          },
          "", "CPU target"));
  app.add_flag("--gl-fast-sampling", options.glFastSampling,
               "Let llvmpipe use its fast 8-bit bilinear path (default: the precise mode, as `twinraster compare`)");

  try {
    app.parse(argc, argv);
    if (!options.screenshotPath.empty() && options.frames <= 0) {
      throw CLI::ValidationError("--screenshot", "needs --frames N (the screenshot is taken on the last frame)");
    }
    if (!viewMode.empty()) {
      gui::ViewMode mode{};
      gui::parse(viewMode, mode);
      options.viewMode = mode;
    }
    if (!cpuPath.empty()) options.cpuPath = cpuPath == "teaching" ? CpuPath::Teaching : CpuPath::Fast;
    if (!cpuIsa.empty()) {
      CpuIsa isa = CpuIsa::Auto;
      parse(cpuIsa, isa);
      options.cpuIsa = isa;
    }
    if (!pin.empty()) {
      gui::PixelPos pixel;
      char comma = 0;
      std::istringstream in(pin);
      if (!(in >> pixel.x >> comma >> pixel.yTop) || comma != ',' || pixel.x < 0 || pixel.yTop < 0 || !in.eof()) {
        throw CLI::ValidationError("--pin", "expected X,Y with X, Y >= 0, got '" + pin + "'");
      }
      options.pin = pixel;
    }
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    return code == 0 ? kExitOk : kExitBadInput;
  }

  if (!options.glFastSampling) requestPreciseSampling();
  try {
    gui::GuiApp gui(options);
    return gui.run();
  } catch (const InputError& e) {
    std::cerr << "twinraster-gui: error: " << e.what() << "\n";
    return kExitBadInput;
  } catch (const std::exception& e) {
    std::cerr << "twinraster-gui: error: " << e.what() << "\n";
    return kExitBadInput;
  }
}
