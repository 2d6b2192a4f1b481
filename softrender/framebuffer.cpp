#include "softrender/framebuffer.h"

#include <cmath>

namespace twr {

namespace {
constexpr float kByteMax = 255.0f;
}  // namespace

std::uint8_t unitToByte(float c) {
  const float clamped = std::fmin(std::fmax(c, 0.0f), 1.0f);  // fmax maps NaN to 0
  return static_cast<std::uint8_t>(std::lround(clamped * kByteMax));
}

Framebuffer makeFramebuffer(int width, int height, vec3 background) {
  Framebuffer fb;
  fb.width = width;
  fb.height = height;
  const std::size_t count = static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
  fb.rgba.resize(count * 4);
  const std::uint8_t r = unitToByte(background.r), g = unitToByte(background.g), b = unitToByte(background.b);
  for (std::size_t i = 0; i < count; ++i) {
    fb.rgba[i * 4 + 0] = r;
    fb.rgba[i * 4 + 1] = g;
    fb.rgba[i * 4 + 2] = b;
    fb.rgba[i * 4 + 3] = 0;
  }
  fb.depth.assign(count, kClearDepth);
  fb.triangleId.assign(count, kNoTriangle);
  fb.lineMask.assign(count, 0);
  return fb;
}

RenderOutput toRenderOutput(const Framebuffer& fb) {
  RenderOutput out;
  out.width = fb.width;
  out.height = fb.height;
  out.rgba.resize(fb.rgba.size());
  out.depth.resize(fb.depth.size());
  out.triangleId.resize(fb.triangleId.size());
  out.lineMask.resize(fb.lineMask.size());
  for (int yTop = 0; yTop < fb.height; ++yTop) {
    const int yGl = fb.height - 1 - yTop;
    const std::size_t src = fb.index(0, yGl), dst = fb.index(0, yTop);
    const std::size_t w = static_cast<std::size_t>(fb.width);
    for (std::size_t x = 0; x < w; ++x) {
      for (std::size_t c = 0; c < 4; ++c) out.rgba[(dst + x) * 4 + c] = fb.rgba[(src + x) * 4 + c];
      out.depth[dst + x] = fb.depth[src + x];
      out.triangleId[dst + x] = fb.triangleId[src + x];
      out.lineMask[dst + x] = fb.lineMask[src + x];
    }
  }
  return out;
}

}  // namespace twr
