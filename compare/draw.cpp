#include "compare/draw.h"

#include <stb_easy_font.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <string>
#include <vector>

namespace twr {
namespace {

constexpr char kFirstPrintable = ' ';   // inclusive; stb_easy_font covers ' '..'~'
constexpr char kLastPrintable = '~';    // inclusive
constexpr char kReplacement = '?';
// stb_easy_font vertex: x, y, z floats then 4 colour bytes; 4 vertices per quad.
constexpr int kVertexBytes = 16;
constexpr int kVerticesPerQuad = 4;
// Generous upper bound on quads per glyph (the densest glyphs use fewer than 20).
constexpr int kMaxQuadsPerGlyph = 32;
constexpr int kTileLabelScaleStepPx = 160;  // tile width per step of caption text scale
constexpr int kMaxTileLabelScale = 3;

std::string printable(std::string_view text) {
  std::string out(text);
  for (char& c : out) {
    if (c < kFirstPrintable || c > kLastPrintable) c = kReplacement;
  }
  return out;
}

}  // namespace

void setPixel(Image& image, int x, int y, Rgb8 colour) {
  if (x < 0 || y < 0 || x >= image.width || y >= image.height) return;
  std::uint8_t* p = image.pixel(x, y);
  p[0] = colour.r;
  p[1] = colour.g;
  p[2] = colour.b;
  p[3] = 255;
}

void fillRect(Image& image, int x0, int y0, int x1, int y1, Rgb8 colour) {
  x0 = std::max(x0, 0);
  y0 = std::max(y0, 0);
  x1 = std::min(x1, image.width);
  y1 = std::min(y1, image.height);
  for (int y = y0; y < y1; ++y) {
    for (int x = x0; x < x1; ++x) setPixel(image, x, y, colour);
  }
}

int tileLabelScale(int tileWidth) { return std::clamp(tileWidth / kTileLabelScaleStepPx, 1, kMaxTileLabelScale); }

int tileLabelHeight(int tileWidth) {
  return (kFontGlyphHeightUnits + 2 * kTileLabelPadUnits) * tileLabelScale(tileWidth);
}

int textWidth(std::string_view text, int scale) {
  std::string line = printable(text);
  return stb_easy_font_width(line.data()) * std::max(scale, 1);
}

void drawText(Image& image, int x, int y, std::string_view text, Rgb8 colour, int scale) {
  scale = std::max(scale, 1);
  std::string line = printable(text);
  std::vector<char> vertices(line.size() * kMaxQuadsPerGlyph * kVerticesPerQuad * kVertexBytes + kVertexBytes);
  const int quadCount =
      stb_easy_font_print(0.0f, 0.0f, line.data(), nullptr, vertices.data(), static_cast<int>(vertices.size()));
  for (int q = 0; q < quadCount; ++q) {
    // Every quad is an axis-aligned rectangle with integer corners (spacing is never changed).
    constexpr float kHuge = std::numeric_limits<float>::max();
    float xMin = kHuge, yMin = kHuge, xMax = -kHuge, yMax = -kHuge;
    for (int v = 0; v < kVerticesPerQuad; ++v) {
      float vx = 0.0f, vy = 0.0f;
      const char* vertex = &vertices[static_cast<std::size_t>(q * kVerticesPerQuad + v) * kVertexBytes];
      std::memcpy(&vx, vertex, sizeof vx);
      std::memcpy(&vy, vertex + sizeof vx, sizeof vy);
      xMin = std::min(xMin, vx);
      xMax = std::max(xMax, vx);
      yMin = std::min(yMin, vy);
      yMax = std::max(yMax, vy);
    }
    fillRect(image, x + static_cast<int>(std::lround(xMin)) * scale, y + static_cast<int>(std::lround(yMin)) * scale,
             x + static_cast<int>(std::lround(xMax)) * scale, y + static_cast<int>(std::lround(yMax)) * scale,
             colour);
  }
}

}  // namespace twr
