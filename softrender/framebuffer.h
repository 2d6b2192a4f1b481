// The CPU pipeline's render target: colour, depth, triangle id and line mask. The stages
// address it in GL window coordinates (row 0 at the bottom, y up) through index(); the
// buffers are stored top row first, as RenderOutput hands them on, so finishing a frame
// moves them instead of flipping a copy.
#pragma once

#include "scene/conventions.h"
#include "scene/renderer.h"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace twr {

// Window depth the depth buffer is cleared to (glClearDepth(1)).
inline constexpr float kClearDepth = 1.0f;

// What the depth buffer holds, as the GL attachment it stands for: the frame's
// GL_DEPTH_COMPONENT24 (24-bit unorm: each depth rounded to a multiple of 1 / (2^24 - 1)) or
// the shadow maps' GL_DEPTH_COMPONENT32F (the interpolated float itself). The difference
// matters where depths are small: below 0.5 float keeps more bits than 24-bit unorm, which an
// orthographic map's depths (linear in the distance, spread over [0, 1]) are full of.
enum class DepthFormat { Unorm24, Float32 };

struct Framebuffer {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> rgba;         // RGBA8
  std::vector<float> depth;               // window depth, kClearDepth where nothing was drawn
  std::vector<std::uint32_t> triangleId;  // kNoTriangle where nothing was drawn
  std::vector<std::uint8_t> lineMask;     // 1 where a debug line was written
  DepthFormat depthFormat = DepthFormat::Unorm24;  // how a fragment's depth is stored (and compared)

  // Element of GL window pixel (x, y): row y counts from the bottom, storage from the top.
  std::size_t index(int x, int y) const {
    return static_cast<std::size_t>(height - 1 - y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x);
  }
};

// round(clamp(c, 0, 1) * 255), ties away from zero; NaN gives 0.
std::uint8_t unitToByte(float c);
// A clear colour's channel as llvmpipe stores it in RGBA8: clamp(c, 0, 1) * 255 in float,
// rounded to nearest with ties to even (Mesa's float-to-unorm pack); NaN gives 0. It differs
// from unitToByte only at exact ties: 0.3f * 255 = 76.5 clears to 76, not 77.
std::uint8_t clearByte(float c);

// The RGBA8 word (bytes r, g, b, a in memory order) the background clears colour to, each
// clearByte of `background` (OutputDesc::background: alpha as the scene asks, not coverage,
// which the triangle ids carry).
std::uint32_t backgroundWord(vec4 background);

// Cleared to `background`, depth kClearDepth, no triangle, no line.
Framebuffer makeFramebuffer(int width, int height, vec4 background);

// The buffers, top row first, as RenderOutput promises (moved out of `framebuffer`).
RenderOutput toRenderOutput(Framebuffer&& framebuffer);
// The inverse: an output's four buffers (moved out of `out`), for the next frame to be drawn
// into (Renderer::renderInto). Sizes are the caller's to check; the rest of `out` stays.
Framebuffer framebufferFrom(RenderOutput&& out);

}  // namespace twr
