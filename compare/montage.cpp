#include "compare/montage.h"

#include "compare/draw.h"
#include "scene/errors.h"

#include <algorithm>
#include <cstdlib>
#include <string>

namespace twr {

namespace {

constexpr int kMaxMontageGapPx = 64;

}  // namespace

int montageLabelHeight(int tileWidth) { return tileLabelHeight(tileWidth); }

Image makeMontage(const std::vector<MontageTile>& tiles, const MontageOptions& options) {
  if (tiles.empty()) throw InputError("montage: no tiles");
  if (options.columns < 1) throw InputError("montage: columns must be >= 1");
  if (options.gapPx < 0 || options.gapPx > kMaxMontageGapPx) {
    throw InputError("montage: gap must be in [0, " + std::to_string(kMaxMontageGapPx) + "] pixels");
  }
  const int w = tiles.front().image.width, h = tiles.front().image.height;
  for (const MontageTile& t : tiles) {
    if (t.image.width != w || t.image.height != h || w <= 0 || h <= 0 ||
        t.image.rgba.size() != static_cast<std::size_t>(w) * static_cast<std::size_t>(h) * 4) {
      throw InputError("montage: tile '" + t.label + "' is " + std::to_string(t.image.width) + "x" +
                       std::to_string(t.image.height) + ", expected every tile " + std::to_string(w) + "x" +
                       std::to_string(h));
    }
  }
  const int count = static_cast<int>(tiles.size());
  const int columns = std::min(options.columns, count);
  const int rows = (count + columns - 1) / columns;
  const int label = montageLabelHeight(w);
  const long long canvasWidth = static_cast<long long>(columns) * w + static_cast<long long>(columns - 1) * options.gapPx;
  const long long canvasHeight =
      static_cast<long long>(rows) * (label + h) + static_cast<long long>(rows - 1) * options.gapPx;
  if (canvasWidth > kMaxImageSide || canvasHeight > kMaxImageSide) {
    throw InputError("montage: " + std::to_string(canvasWidth) + "x" + std::to_string(canvasHeight) +
                     " is larger than " + std::to_string(kMaxImageSide) + " on a side");
  }
  Image canvas = makeImage(static_cast<int>(canvasWidth), static_cast<int>(canvasHeight));
  fillRect(canvas, 0, 0, canvas.width, canvas.height, kColourPanel);
  const int scale = tileLabelScale(w);
  for (int i = 0; i < count; ++i) {
    const int x0 = (i % columns) * (w + options.gapPx);
    const int y0 = (i / columns) * (label + h + options.gapPx);
    const MontageTile& t = tiles[static_cast<std::size_t>(i)];
    drawText(canvas, x0 + std::max(0, (w - textWidth(t.label, scale)) / 2), y0 + kTileLabelPadUnits * scale, t.label,
             kColourWhite, scale);
    for (int y = 0; y < h; ++y) {
      std::copy_n(t.image.pixel(0, y), static_cast<std::size_t>(w) * 4, canvas.pixel(x0, y0 + label + y));
      for (int x = 0; x < w; ++x) canvas.pixel(x0 + x, y0 + label + y)[3] = 255;  // opaque whatever the source
    }
  }
  return canvas;
}

Image makeInteriorHeatMap(const RenderOutput& approx, const RenderOutput& reference, const InteriorSplit& split,
                          const HeatRamp& ramp) {
  const std::size_t pixelCount = static_cast<std::size_t>(std::max(split.width, 0)) * std::max(split.height, 0);
  if (split.width != approx.width || split.height != approx.height || split.width != reference.width ||
      split.height != reference.height || split.interior.size() != pixelCount ||
      approx.rgba.size() != 4 * pixelCount || reference.rgba.size() != 4 * pixelCount) {
    throw InputError("interior heat map: the split and the two outputs differ in size");
  }
  for (const RenderOutput* side : {&approx, &reference}) {
    for (const std::size_t size : {side->triangleId.size(), side->lineMask.size()}) {
      if (size != 0 && size != pixelCount) throw InputError("interior heat map: a triangle-id or line-mask buffer has the wrong length");
    }
  }
  Image image = makeImage(split.width, split.height);
  for (int y = 0; y < split.height; ++y) {
    for (int x = 0; x < split.width; ++x) {
      const std::size_t i = static_cast<std::size_t>(y) * static_cast<std::size_t>(split.width) + static_cast<std::size_t>(x);
      Rgb8 colour = checkerColour(x, y);
      const bool lines = (!approx.lineMask.empty() && approx.lineMask[i]) ||
                         (!reference.lineMask.empty() && reference.lineMask[i]);
      if (split.interior[i]) {
        int levels = 0;
        for (int c = 0; c < 3; ++c) levels = std::max(levels, std::abs(approx.rgba[4 * i + c] - reference.rgba[4 * i + c]));
        colour = heatColour(levels, ramp);
      } else if (!lines && coveredAt(approx, i) != coveredAt(reference, i)) {
        colour = coveredAt(approx, i) ? kColourCpuOnly : kColourGlOnly;
      }
      setPixel(image, x, y, colour);
    }
  }
  return image;
}

}  // namespace twr
