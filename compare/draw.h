// Tiny raster helpers for the comparison images: filled rectangles and text from
// stb_easy_font (vector quads we fill ourselves; no font files). Everything clips to the image,
// writes alpha 255, and uses a top-left origin. Rectangles are [x0, x1) x [y0, y1): min
// inclusive, max exclusive.
#pragma once

#include "compare/colours.h"
#include "scene/image.h"

#include <string_view>

namespace twr {

// stb_easy_font's cell: glyph rows used from the top of a line (caps and descenders fit), and
// the line pitch, both in font units (one unit = `scale` pixels).
inline constexpr int kFontGlyphHeightUnits = 10;
inline constexpr int kFontLineHeightUnits = 12;

// The caption band above an image tile (the side by side, the montage): its text at
// tileLabelScale, kTileLabelPadUnits font units of padding above and below it.
inline constexpr int kTileLabelPadUnits = 3;
// Text scale of a tile's caption: one step per 160 pixels of tile width, from 1 to 3.
int tileLabelScale(int tileWidth);
// Height of a tile's caption band in pixels.
int tileLabelHeight(int tileWidth);

void fillRect(Image& image, int x0, int y0, int x1, int y1, Rgb8 colour);
void setPixel(Image& image, int x, int y, Rgb8 colour);

// Width in pixels of one line of `text` at `scale` (integer pixels per font unit, >= 1).
int textWidth(std::string_view text, int scale);
// Draws `text` (one line; bytes outside printable ASCII are drawn as '?') with its top-left
// at (x, y).
void drawText(Image& image, int x, int y, std::string_view text, Rgb8 colour, int scale);

}  // namespace twr
