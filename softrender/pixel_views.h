// A pixel in every debug view from one pixel trace, instead of one full render per view
// (the GUI's inspector pins a pixel and reads it in all eleven views). Which fragment wins
// the pixel does not depend on the view: clipping, culling and the depth test see only
// positions, and the varyings depend on the lighting space, not on the view. So the winning
// visit's fragment, shaded once with each view's shader permutation and written as the
// output merge writes it, is the pixel of that view's full render, bit for bit
// (tests/softrender/test_pixel_views.cpp holds it to that).
#pragma once

#include "softrender/pixel_trace.h"

#include <array>
#include <cstdint>

namespace twr {

// One pixel as RenderOutput holds it.
struct ViewPixel {
  std::array<std::uint8_t, 4> rgba{};
  float depth = 1.0f;                      // window depth; 1 where nothing was drawn
  std::uint32_t triangleId = kNoTriangle;  // the triangle drawn there, kNoTriangle for the background
};

// Pixel (trace.x, trace.yTop) as the CPU renderer draws `scene` with `settings` in `view`
// with TBN lines off (they could cover the pixel). `trace` comes from tracePixelVisits (or
// tracePixel) for the same scene, size and lighting space; its own view does not matter.
// Throws InputError when the trace's lighting space differs from settings'.
ViewPixel shadeTracedPixel(const Scene& scene, const RenderSettings& settings, const PixelTrace& trace, View view);

}  // namespace twr
