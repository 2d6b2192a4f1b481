#include "compare/side_by_side.h"

#include "compare/colours.h"
#include "compare/draw.h"
#include "scene/errors.h"

#include <algorithm>
#include <string>

namespace twr {
namespace {

constexpr int kMaxSideBySideGapPx = 1024;
constexpr int kAlphaOpaque = 255;

void checkOutput(const RenderOutput& output, const char* name) {
  const std::size_t expected = static_cast<std::size_t>(std::max(output.width, 0)) * std::max(output.height, 0) * 4;
  if (output.width <= 0 || output.height <= 0 || output.width > kMaxImageSide || output.height > kMaxImageSide ||
      output.rgba.size() != expected) {
    throw InputError(std::string("compare: ") + name + " output is " + std::to_string(output.width) + "x" +
                     std::to_string(output.height) + " with " + std::to_string(output.rgba.size()) +
                     " rgba bytes, expected a size in [1, " + std::to_string(kMaxImageSide) +
                     "] and width * height * 4 bytes");
  }
  // Coverage (drawnAt) reads these; empty means "not available".
  const std::size_t pixels = expected / 4;
  for (const std::size_t size : {output.triangleId.size(), output.lineMask.size()}) {
    if (size != 0 && size != pixels) {
      throw InputError(std::string("compare: ") + name + " output has a triangle-id or line-mask buffer of " +
                       std::to_string(size) + " entries, expected 0 or " + std::to_string(pixels));
    }
  }
}

void blit(Image& canvas, const Image& source, int x0, int y0) {
  for (int y = 0; y < source.height; ++y) {
    std::copy_n(source.pixel(0, y), static_cast<std::size_t>(source.width) * 4, canvas.pixel(x0, y0 + y));
  }
}

}  // namespace

Image rawImage(const RenderOutput& output) {
  checkOutput(output, "render");
  Image image;
  image.width = output.width;
  image.height = output.height;
  image.rgba = output.rgba;
  return image;
}

Image viewImage(const RenderOutput& output, BackgroundMode mode) {
  Image image = rawImage(output);
  for (int y = 0; y < image.height; ++y) {
    for (int x = 0; x < image.width; ++x) {
      std::uint8_t* p = image.pixel(x, y);
      if (mode == BackgroundMode::Checker) {
        const Rgb8 under = checkerColour(x, y);
        // Nothing drawn: the checker whatever the background's alpha; drawn: over it by alpha.
        const std::size_t i = static_cast<std::size_t>(y) * static_cast<std::size_t>(image.width) +
                              static_cast<std::size_t>(x);
        const int a = drawnAt(output, i) ? p[3] : 0;
        const int underChannels[3] = {under.r, under.g, under.b};
        for (int c = 0; c < 3; ++c) {
          // Rounded integer "over": (rgb * a + under * (255 - a) + 127) / 255.
          p[c] = static_cast<std::uint8_t>((p[c] * a + underChannels[c] * (kAlphaOpaque - a) + kAlphaOpaque / 2) /
                                           kAlphaOpaque);
        }
      }
      p[3] = kAlphaOpaque;
    }
  }
  return image;
}

int sideBySideLabelHeight(int width, const SideBySideOptions& options) {
  if (!options.labels) return 0;
  return tileLabelHeight(width);
}

Image makeSideBySide(const RenderOutput& cpu, const RenderOutput& gl, const SideBySideOptions& options) {
  checkOutput(cpu, "CPU");
  checkOutput(gl, "GL");
  if (cpu.width != gl.width || cpu.height != gl.height) {
    throw InputError("compare: CPU output is " + std::to_string(cpu.width) + "x" + std::to_string(cpu.height) +
                     " but GL output is " + std::to_string(gl.width) + "x" + std::to_string(gl.height) +
                     ", expected the same size");
  }
  if (options.gapPx < 0 || options.gapPx > kMaxSideBySideGapPx) {
    throw InputError("compare: side-by-side gap is " + std::to_string(options.gapPx) + " pixels, expected [0, " +
                     std::to_string(kMaxSideBySideGapPx) + "]");
  }
  const int width = cpu.width;
  const int labelHeight = sideBySideLabelHeight(width, options);
  Image canvas = makeImage(2 * width + options.gapPx, labelHeight + cpu.height);
  fillRect(canvas, 0, 0, canvas.width, canvas.height, kColourPanel);
  blit(canvas, viewImage(cpu, options.background), 0, labelHeight);
  blit(canvas, viewImage(gl, options.background), width + options.gapPx, labelHeight);
  if (options.labels) {
    const int scale = tileLabelScale(width);
    const int textY = kTileLabelPadUnits * scale;
    const int rightX0 = width + options.gapPx;
    drawText(canvas, (width - textWidth("CPU", scale)) / 2, textY, "CPU", kColourWhite, scale);
    drawText(canvas, rightX0 + (width - textWidth("GL", scale)) / 2, textY, "GL", kColourWhite, scale);
  }
  return canvas;
}

}  // namespace twr
