// Hand-built RenderOutputs for the compare tests: every pixel is set explicitly, so each
// expected metric can be worked out on paper.
#pragma once

#include "scene/renderer.h"

#include <cstdint>

namespace twr::testing {

// width x height, every pixel covered (alpha 255) with colour (r, g, b), depth `depth`,
// triangle id 0 and no lines. Buffers are top row first like every RenderOutput.
inline RenderOutput makeSolidOutput(int width, int height, std::uint8_t r, std::uint8_t g, std::uint8_t b,
                                    float depth = 0.5f) {
  RenderOutput out;
  out.width = width;
  out.height = height;
  const std::size_t count = static_cast<std::size_t>(width) * height;
  out.rgba.resize(count * 4);
  for (std::size_t i = 0; i < count; ++i) {
    out.rgba[i * 4 + 0] = r;
    out.rgba[i * 4 + 1] = g;
    out.rgba[i * 4 + 2] = b;
    out.rgba[i * 4 + 3] = 255;
  }
  out.depth.assign(count, depth);
  out.triangleId.assign(count, 0u);
  out.lineMask.assign(count, 0);
  return out;
}

inline std::size_t pixelIndex(const RenderOutput& out, int x, int y) {
  return static_cast<std::size_t>(y) * out.width + x;  // (x, y) top-left origin
}

inline std::uint8_t* rgbaAt(RenderOutput& out, int x, int y) { return &out.rgba[pixelIndex(out, x, y) * 4]; }

// Marks (x, y) as background: alpha 0, depth 1, no triangle, keeping the RGB.
inline void clearPixel(RenderOutput& out, int x, int y) {
  rgbaAt(out, x, y)[3] = 0;
  out.depth[pixelIndex(out, x, y)] = 1.0f;
  out.triangleId[pixelIndex(out, x, y)] = kNoTriangle;
}

}  // namespace twr::testing
