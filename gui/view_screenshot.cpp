// The screenshot key's images (gui/view_screenshot.h).
#include "gui/view_screenshot.h"

#include "compare/heatmap.h"
#include "compare/side_by_side.h"
#include "scene/errors.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>

namespace twr::gui {

ViewMode shownViewMode(ViewMode mode, double secondsSinceStart, double hz) {
  if (mode != ViewMode::Flicker) return mode;
  const double phase = secondsSinceStart * hz;
  return static_cast<long long>(std::floor(phase)) % 2 == 0 ? ViewMode::Cpu : ViewMode::Gl;
}

Image composeSplit(const Image& cpu, const Image& gl, float fraction) {
  Image out = cpu;
  const int splitX = std::clamp(static_cast<int>(std::lround(fraction * static_cast<float>(cpu.width))), 0, cpu.width);
  for (int y = 0; y < out.height; ++y) {
    for (int x = splitX; x < out.width; ++x) std::memcpy(out.pixel(x, y), gl.pixel(x, y), 4);
    if (splitX < out.width) {
      std::uint8_t* divider = out.pixel(splitX, y);
      divider[0] = divider[1] = divider[2] = divider[3] = 255;
    }
  }
  return out;
}

namespace {

Image diffScreenshotOf(const GuiPrefs& prefs, const std::optional<CompareResult>& diff) {
  if (!diff) throw InputError("no diff yet: the CPU frame is still being rendered");
  if (prefs.diffShowClasses) return makeClassMap(diff->pixels);
  HeatMapOptions heatOptions;
  heatOptions.ramp = HeatRamp{prefs.heatMaxLevels, prefs.heatScale};
  return makeHeatMap(diff->pixels, heatOptions);
}

}  // namespace

Image viewScreenshotOf(const RenderOutput& cpu, const RenderOutput& gl, ViewMode shown, const GuiPrefs& prefs,
                       const std::optional<CompareResult>& diff) {
  const BackgroundMode background = prefs.checkerBackground ? BackgroundMode::Checker : BackgroundMode::RendererColour;
  switch (shown) {
    case ViewMode::Cpu:
    case ViewMode::Flicker:  // a caller that skipped shownViewMode gets the phase's first backend
      return viewImage(cpu, background);
    case ViewMode::Gl:
      return viewImage(gl, background);
    case ViewMode::SideBySide: {
      SideBySideOptions sideOptions;
      sideOptions.background = background;
      return makeSideBySide(cpu, gl, sideOptions);
    }
    case ViewMode::Split:
      if (cpu.width != gl.width || cpu.height != gl.height) {
        throw InputError("the CPU frame is still being rendered at the new size; try again in a moment");
      }
      return composeSplit(viewImage(cpu, background), viewImage(gl, background), prefs.splitFraction);
    case ViewMode::Diff:
      break;
  }
  return diffScreenshotOf(prefs, diff);
}

std::string screenshotStem(const std::string& dir, std::time_t when) {
  std::tm local{};
  localtime_r(&when, &local);
  char stamp[32];
  std::strftime(stamp, sizeof stamp, "%Y%m%d-%H%M%S", &local);
  const std::filesystem::path folder = dir.empty() ? std::filesystem::path(".") : std::filesystem::path(dir);
  return (folder / (std::string("twinraster-") + stamp)).string();
}

Image imageFromBottomRows(int width, int height, const std::vector<std::uint8_t>& bottomFirst) {
  Image image = makeImage(width, height);
  const std::size_t rowBytes = static_cast<std::size_t>(width) * 4;
  if (bottomFirst.size() < rowBytes * static_cast<std::size_t>(height)) {
    throw InputError("window read-back holds " + std::to_string(bottomFirst.size()) + " bytes, a " + std::to_string(width) +
                     "x" + std::to_string(height) + " RGBA image needs " +
                     std::to_string(rowBytes * static_cast<std::size_t>(height)));
  }
  for (int y = 0; y < height; ++y) {
    std::memcpy(image.pixel(0, y), bottomFirst.data() + static_cast<std::size_t>(height - 1 - y) * rowBytes, rowBytes);
  }
  for (std::size_t i = 3; i < image.rgba.size(); i += 4) image.rgba[i] = 255;  // the window is opaque
  return image;
}

}  // namespace twr::gui
