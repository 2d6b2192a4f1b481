// The CPU pipeline's render target: colour, depth, triangle id and line mask, stored in GL
// order (row 0 is the bottom row, window y up). toRenderOutput flips to top row first.
#pragma once

#include "scene/conventions.h"
#include "scene/renderer.h"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace twr {

// Window depth the depth buffer is cleared to (glClearDepth(1)).
inline constexpr float kClearDepth = 1.0f;

struct Framebuffer {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> rgba;         // RGBA8, bottom row first
  std::vector<float> depth;               // window depth, kClearDepth where nothing was drawn
  std::vector<std::uint32_t> triangleId;  // kNoTriangle where nothing was drawn
  std::vector<std::uint8_t> lineMask;     // 1 where a debug line was written

  std::size_t index(int x, int y) const { return static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x); }
};

// round(clamp(c, 0, 1) * 255); NaN gives 0.
std::uint8_t unitToByte(float c);

// Cleared to `background` with alpha 0, depth kClearDepth, no triangle, no line.
Framebuffer makeFramebuffer(int width, int height, vec3 background);

// The buffers top row first, as RenderOutput promises.
RenderOutput toRenderOutput(const Framebuffer& framebuffer);

}  // namespace twr
