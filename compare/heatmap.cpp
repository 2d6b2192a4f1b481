#include "compare/heatmap.h"

#include "compare/draw.h"
#include "scene/errors.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace twr {
namespace {

// Legend geometry in font units (pixels = units * text scale).
constexpr int kPadUnits = 6;
constexpr int kBarHeightUnits = 12;
constexpr int kTickLengthUnits = 3;
constexpr int kSwatchUnits = 8;
constexpr int kSwatchTextGapUnits = 3;
constexpr int kItemGapUnits = 12;
constexpr Rgb8 kColourSwatchBorder{160, 160, 160};
// From this canvas width (pixels, inclusive) the legend text is drawn at scale 2.
constexpr int kLegendDoubleScaleWidthPx = 720;

struct LegendItem {
  Rgb8 colour;
  bool checker;  // drawn as the empty-pixel checker instead of `colour`
  std::string label;
};

void validateAnalysis(const PixelAnalysis& pixels) {
  const std::size_t count = static_cast<std::size_t>(std::max(pixels.width, 0)) * std::max(pixels.height, 0);
  if (pixels.width <= 0 || pixels.height <= 0 || pixels.diffLevels.size() != count ||
      pixels.pixelClass.size() != count) {
    throw InputError("compare: pixel analysis of " + std::to_string(pixels.width) + "x" +
                     std::to_string(pixels.height) + " has inconsistent buffers");
  }
}

int legendScale(int canvasWidth) { return canvasWidth >= kLegendDoubleScaleWidthPx ? 2 : 1; }

void drawSwatch(Image& image, int x, int y, int size, const LegendItem& item) {
  fillRect(image, x, y, x + size, y + size, kColourSwatchBorder);
  const int half = std::max(size / 2, 1);
  for (int py = y + 1; py < y + size - 1; ++py) {
    for (int px = x + 1; px < x + size - 1; ++px) {
      const bool dark = ((px - x) / half + (py - y) / half) % 2 == 0;
      setPixel(image, px, py, item.checker ? (dark ? kColourCheckerDark : kColourCheckerLight) : item.colour);
    }
  }
}

// Draws swatch + label items left to right from y, wrapping at the panel width; returns the
// y just below the last row.
int drawItems(Image& panel, int y, const std::vector<LegendItem>& items, int scale) {
  const int pad = kPadUnits * scale;
  const int swatch = kSwatchUnits * scale;
  const int rowHeight = kFontLineHeightUnits * scale;
  int x = pad;
  for (const LegendItem& item : items) {
    const int itemWidth = swatch + kSwatchTextGapUnits * scale + textWidth(item.label, scale);
    if (x > pad && x + itemWidth > panel.width - pad) {
      x = pad;
      y += rowHeight;
    }
    drawSwatch(panel, x, y, swatch, item);
    drawText(panel, x + swatch + kSwatchTextGapUnits * scale, y, item.label, kColourWhite, scale);
    x += itemWidth + kItemGapUnits * scale;
  }
  return y + rowHeight;
}

// The heat ramp as a bar with labelled ticks (0, 1, 3, 12 and the maximum on the log scale,
// the thresholds of over_1/3/12); returns the y below the labels.
int drawRampBar(Image& panel, int y, const HeatRamp& ramp, int scale) {
  const int pad = kPadUnits * scale;
  const int barX0 = pad, barX1 = panel.width - pad;  // [barX0, barX1)
  const int barWidth = std::max(barX1 - barX0, 2);
  const int maxLevels = std::max(ramp.maxLevels, 1);
  const double logRange = std::log2(1.0 + maxLevels);
  for (int x = barX0; x < barX1; ++x) {
    const double t = double(x - barX0) / double(barWidth - 1);
    // The level whose ramp position is t, so the bar shows exactly the colours the map uses.
    const double level = ramp.scale == HeatScale::Linear ? t * maxLevels : std::exp2(t * logRange) - 1.0;
    fillRect(panel, x, y, x + 1, y + kBarHeightUnits * scale, heatColour(int(std::lround(level)), ramp));
  }
  y += kBarHeightUnits * scale;

  std::vector<int> ticks = ramp.scale == HeatScale::Linear ? std::vector<int>{0, maxLevels / 2, maxLevels}
                                                           : std::vector<int>{0, 1, 3, 12, maxLevels};
  ticks.erase(std::remove_if(ticks.begin(), ticks.end(), [&](int t) { return t > maxLevels; }), ticks.end());
  ticks.erase(std::unique(ticks.begin(), ticks.end()), ticks.end());
  for (int level : ticks) {
    const int x = barX0 + int(std::lround(heatPosition(level, ramp) * (barWidth - 1)));
    fillRect(panel, x, y, x + scale, y + kTickLengthUnits * scale, kColourWhite);
    const std::string label = std::to_string(level);
    const int labelX = std::clamp(x - textWidth(label, scale) / 2, 0, panel.width - textWidth(label, scale));
    drawText(panel, labelX, y + kTickLengthUnits * scale, label, kColourWhite, scale);
  }
  return y + kTickLengthUnits * scale + kFontLineHeightUnits * scale;
}

// Panel with an optional title, optional ramp and the items; cropped to what was drawn.
Image drawLegendPanel(int width, const std::string& title, const HeatRamp* ramp, const std::vector<LegendItem>& items) {
  const int scale = legendScale(width);
  const int pad = kPadUnits * scale;
  // Tallest possible: title, bar, ticks, one row per item, paddings.
  const int maxHeight = pad * 3 + kFontLineHeightUnits * scale * (3 + int(items.size())) +
                        (kBarHeightUnits + kTickLengthUnits) * scale;
  Image panel = makeImage(width, maxHeight);
  fillRect(panel, 0, 0, width, maxHeight, kColourPanel);
  int y = pad;
  drawText(panel, pad, y, title, kColourWhite, scale);
  y += kFontLineHeightUnits * scale;
  if (ramp) y = drawRampBar(panel, y, *ramp, scale) + pad / 2;
  y = drawItems(panel, y, items, scale) + pad / 2;
  panel.height = std::min(y, maxHeight);
  panel.rgba.resize(static_cast<std::size_t>(panel.width) * panel.height * 4);
  return panel;
}

// The map at the top-left of a canvas at least kLegendMinWidthPx wide, legend below.
Image composeWithLegend(const Image& map, const Image& legendPanel) {
  Image canvas = makeImage(legendPanel.width, map.height + legendPanel.height);
  fillRect(canvas, 0, 0, canvas.width, canvas.height, kColourPanel);
  for (int y = 0; y < map.height; ++y) {
    std::copy_n(map.pixel(0, y), static_cast<std::size_t>(map.width) * 4, canvas.pixel(0, y));
  }
  for (int y = 0; y < legendPanel.height; ++y) {
    std::copy_n(legendPanel.pixel(0, y), static_cast<std::size_t>(legendPanel.width) * 4,
                canvas.pixel(0, map.height + y));
  }
  return canvas;
}

std::string rampTitle(const HeatRamp& ramp) {
  return "|CPU - GL|, max of R,G,B, levels (" + std::string(ramp.scale == HeatScale::Log ? "log" : "linear") +
         " scale)";
}

template <typename ColourAt>
Image paintMap(const PixelAnalysis& pixels, ColourAt colourAt) {
  Image map = makeImage(pixels.width, pixels.height);
  for (int y = 0; y < pixels.height; ++y) {
    for (int x = 0; x < pixels.width; ++x) setPixel(map, x, y, colourAt(x, y, pixels.index(x, y)));
  }
  return map;
}

}  // namespace

Rgb8 heatMapColour(PixelClass pixelClass, int diffLevels, int x, int y, const HeatRamp& ramp) {
  switch (pixelClass) {
    case PixelClass::Empty: return checkerColour(x, y);
    case PixelClass::CoverageCpu: return kColourCpuOnly;
    case PixelClass::CoverageGl: return kColourGlOnly;
    case PixelClass::ExcludedLine: return kColourExcludedLine;
    case PixelClass::Same:
    case PixelClass::Depth:
    case PixelClass::Shading:
    case PixelClass::Decision: return heatColour(diffLevels, ramp);
  }
  return kColourBlack;
}

Rgb8 classMapColour(PixelClass pixelClass, int x, int y) {
  switch (pixelClass) {
    case PixelClass::Empty: return checkerColour(x, y);
    case PixelClass::Same: return kColourSame;
    case PixelClass::CoverageCpu: return kColourCpuOnly;
    case PixelClass::CoverageGl: return kColourGlOnly;
    case PixelClass::Depth: return kColourDepth;
    case PixelClass::Shading: return kColourShading;
    case PixelClass::Decision: return kColourDecision;
    case PixelClass::ExcludedLine: return kColourExcludedLine;
  }
  return kColourBlack;
}

Image makeHeatMap(const PixelAnalysis& pixels, const HeatMapOptions& options) {
  validateAnalysis(pixels);
  if (options.ramp.maxLevels < 1 || options.ramp.maxLevels > int(kMaxChannelLevel)) {
    throw InputError("compare: heat map maximum is " + std::to_string(options.ramp.maxLevels) +
                     " levels, expected an integer in [1, 255]");
  }
  Image map = paintMap(pixels, [&](int x, int y, std::size_t i) {
    return heatMapColour(pixels.pixelClass[i], pixels.diffLevels[i], x, y, options.ramp);
  });
  if (!options.legend) return map;
  const std::vector<LegendItem> items = {
      {kColourCpuOnly, false, "CPU only"},
      {kColourGlOnly, false, "GL only"},
      {kColourExcludedLine, false, "TBN line (not compared)"},
      {kColourCheckerDark, true, "neither covered"},
  };
  const Image legend =
      drawLegendPanel(std::max(map.width, kLegendMinWidthPx), rampTitle(options.ramp), &options.ramp, items);
  return composeWithLegend(map, legend);
}

Image makeClassMap(const PixelAnalysis& pixels, const ClassMapOptions& options) {
  validateAnalysis(pixels);
  Image map = paintMap(pixels, [&](int x, int y, std::size_t i) { return classMapColour(pixels.pixelClass[i], x, y); });
  if (!options.legend) return map;
  const std::vector<LegendItem> items = {
      {kColourSame, false, "same colour"},
      {kColourCpuOnly, false, "coverage: CPU only"},
      {kColourGlOnly, false, "coverage: GL only"},
      {kColourDepth, false, "depth: other surface won"},
      {kColourShading, false, "shading: same surface"},
      {kColourDecision, false, "decision: a tap, hit or step flipped"},
      {kColourExcludedLine, false, "TBN line (not compared)"},
      {kColourCheckerDark, true, "neither covered"},
  };
  const Image legend = drawLegendPanel(std::max(map.width, kLegendMinWidthPx), "pixel classes", nullptr, items);
  return composeWithLegend(map, legend);
}

}  // namespace twr
