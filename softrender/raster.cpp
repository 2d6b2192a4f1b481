#include "softrender/raster.h"

#include <algorithm>

namespace twr {

namespace {

// floor(a / b) for b > 0 (C++ division truncates towards zero).
std::int64_t floorDiv(std::int64_t a, std::int64_t b) {
  const std::int64_t q = a / b;
  return (a % b != 0 && a < 0) ? q - 1 : q;
}

// ceil(a / b) for b > 0.
std::int64_t ceilDiv(std::int64_t a, std::int64_t b) { return -floorDiv(-a, b); }

// Bounding boxes at most this wide (pixels) are scanned pixel by pixel: a few multiply-adds per
// pixel cost less than up to three 64-bit divisions per row, and on a million small triangles
// most boxes are a pixel or two wide.
constexpr int kScannedBoxWidth = 4;

// coveredSpan by testing each pixel of the box's row. A row of a triangle is one interval, so
// its first and last covered pixels bound it.
Span scannedSpan(const TriangleSetup& setup, int py) {
  int first = setup.x1 + 1, last = setup.x1;
  for (int px = setup.x0; px <= setup.x1; ++px) {
    const bool covered = setup.edges[0].at(px, py) > 0 && setup.edges[1].at(px, py) > 0 && setup.edges[2].at(px, py) > 0;
    if (!covered) continue;
    first = std::min(first, px);
    last = px;
  }
  return first > last ? Span{} : Span{first, last + 1};
}

}  // namespace

Span coveredSpan(const TriangleSetup& setup, int py) {
  if (setup.x1 - setup.x0 < kScannedBoxWidth) return scannedSpan(setup, py);
  std::int64_t left = setup.x0;   // inclusive
  std::int64_t right = setup.x1;  // inclusive
  for (const EdgeFunction& edge : setup.edges) {
    const std::int64_t k = edge.c + edge.stepY * py;
    if (edge.stepX > 0) {
      left = std::max(left, ceilDiv(1 - k, edge.stepX));
    } else if (edge.stepX < 0) {
      right = std::min(right, floorDiv(k - 1, -edge.stepX));
    } else if (k <= 0) {
      return Span{};
    }
  }
  if (left > right) return Span{};
  return Span{static_cast<int>(left), static_cast<int>(right + 1)};
}

bool coversPixel(const TriangleSetup& setup, int px, int py) {
  if (px < setup.x0 || px > setup.x1 || py < setup.y0 || py > setup.y1) return false;
  for (const EdgeFunction& edge : setup.edges) {
    if (edge.at(px, py) <= 0) return false;
  }
  return true;
}

}  // namespace twr
