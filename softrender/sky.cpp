#include "softrender/sky.h"

#include "softrender/draw_loop.h"
#include "softrender/sky-inl.h"

namespace twr {

vec3 skyColour(const SkyUniformsT<float>& sky, int px, int py) {
  return lanes::skyColour<float>(sky, static_cast<float>(px), static_cast<float>(py));
}

void drawSkyRows(const SkyUniformsT<float>& sky, Framebuffer& fb, int rowBegin, int rowEnd) {
  if (!sky.cube) return;
  for (int py = rowBegin; py < rowEnd; ++py) {
    for (int px = 0; px < fb.width; ++px) {
      const std::size_t i = fb.index(px, py);
      if (fb.triangleId[i] != kNoTriangle) continue;
      const vec3 c = skyColour(sky, px, py);
      // The output merge's byte conversion, alpha 1 (the sky is opaque).
      fb.rgba[i * 4 + 0] = unitToByte(c.x);
      fb.rgba[i * 4 + 1] = unitToByte(c.y);
      fb.rgba[i * 4 + 2] = unitToByte(c.z);
      fb.rgba[i * 4 + 3] = 255;
    }
  }
}

void drawSky(const SkyUniformsT<float>& sky, Framebuffer& fb, int threads) {
  if (!sky.cube) return;
  RenderStats unused;
  drawInBands(
      threads, fb.height, false, [&](const RowBand& band, RenderStats&) { drawSkyRows(sky, fb, band.rowBegin, band.rowEnd); },
      unused);
}

}  // namespace twr
