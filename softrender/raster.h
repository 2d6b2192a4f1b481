// Stage 4, raster: a scanline rasterizer over setup's integer edge functions.
//
// For each pixel row py of the bounding box, every edge gives a bound on px where
// E(px, py) = K + stepX * px > 0 (K = c + stepY * py):
//   stepX > 0:  px >= ceil((1 - K) / stepX)          (left side of the span)
//   stepX < 0:  px <= floor((K - 1) / -stepX)        (right side of the span)
//   stepX = 0:  the whole row when K > 0, else none  (horizontal edge)
// The span is the intersection, so it covers exactly the pixels whose centres pass all three
// edge tests: the same set as evaluating E at every pixel (raster tests check that), with
// integer division only, so no crack and no double cover along a shared edge.
#pragma once

#include "softrender/setup.h"

namespace twr {

// Covered pixels [xBegin, xEnd) of one row (exclusive end; empty when xBegin >= xEnd).
struct Span {
  int xBegin = 0;
  int xEnd = 0;
};

// The covered span of row py, limited to the setup's bounding box.
Span coveredSpan(const TriangleSetup& setup, int py);

// Per-pixel test of all three edge functions (used by the pixel trace and the tests).
bool coversPixel(const TriangleSetup& setup, int px, int py);

// Calls visit(py, span) for every non-empty row span in rows [rowBegin, rowEnd) (exclusive
// end) of the bounding box. Rows are the unit a future thread or tile split hands out.
template <typename Visitor>
void rasterizeTriangle(const TriangleSetup& setup, int rowBegin, int rowEnd, Visitor&& visit) {
  const int yFirst = setup.y0 > rowBegin ? setup.y0 : rowBegin;
  const int yLast = setup.y1 < rowEnd - 1 ? setup.y1 : rowEnd - 1;
  for (int py = yFirst; py <= yLast; ++py) {
    const Span span = coveredSpan(setup, py);
    if (span.xBegin < span.xEnd) visit(py, span);
  }
}

}  // namespace twr
