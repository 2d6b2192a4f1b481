#include "softrender/framebuffer.h"

#include <cmath>
#include <cstring>
#include <utility>

namespace twr {

namespace {
constexpr float kByteMax = 255.0f;
}  // namespace

std::uint8_t clearByte(float c) {
  const float clamped = std::fmin(std::fmax(c, 0.0f), 1.0f);  // fmax maps NaN to 0
  return static_cast<std::uint8_t>(std::nearbyint(clamped * kByteMax));  // FE_TONEAREST: ties to even
}

std::uint8_t unitToByte(float c) {
  const float clamped = std::fmin(std::fmax(c, 0.0f), 1.0f);  // fmax maps NaN to 0
  return static_cast<std::uint8_t>(std::lround(clamped * kByteMax));
}

std::uint32_t backgroundWord(vec4 background) {
  const std::uint8_t bytes[4] = {clearByte(background.r), clearByte(background.g), clearByte(background.b),
                                 clearByte(background.a)};
  std::uint32_t word = 0;
  std::memcpy(&word, bytes, sizeof(word));
  return word;
}

Framebuffer makeFramebuffer(int width, int height, vec4 background) {
  Framebuffer fb;
  fb.width = width;
  fb.height = height;
  const std::size_t count = static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
  fb.rgba.resize(count * 4);
  const std::uint32_t word = backgroundWord(background);
  for (std::size_t i = 0; i < count; ++i) std::memcpy(&fb.rgba[i * 4], &word, sizeof(word));
  fb.depth.assign(count, kClearDepth);
  fb.triangleId.assign(count, kNoTriangle);
  fb.lineMask.assign(count, 0);
  return fb;
}

RenderOutput toRenderOutput(Framebuffer&& fb) {
  RenderOutput out;
  out.width = fb.width;
  out.height = fb.height;
  moveImageBuffers(fb, out);
  return out;
}

Framebuffer framebufferFrom(RenderOutput&& out) {
  Framebuffer fb;
  moveImageBuffers(out, fb);
  return fb;
}

}  // namespace twr
