// Raster, interpolation, early depth test, shading and output merge for one triangle that
// setup accepted, pixel by pixel along the rasterizer's spans. The teaching path's inner loop;
// the fast path runs the same function when it has no SIMD kernel for a triangle.
#pragma once

#include "softrender/framebuffer.h"
#include "softrender/interpolate.h"
#include "softrender/output_merge.h"
#include "softrender/raster.h"
#include "softrender/setup.h"
#include "softrender/shade.h"
#include "softrender/vertex.h"

#include <cstdint>

namespace twr {

// Draws the pixels of rows [rowBegin, rowEnd) (exclusive end) that the triangle covers and
// that pass GL_LESS; v0, v1, v2 are its vertices in submission (fan) order. Returns how many
// fragments were shaded.
template <typename Features>
std::uint64_t shadeTriangleRows(const TriangleSetup& setup, const InterpolationSetup& interpolation,
                                const ClipVertex& v0, const ClipVertex& v1, const ClipVertex& v2,
                                const ShadeUniforms& shade, bool tangentLighting, std::uint32_t triangleId,
                                int rowBegin, int rowEnd, Framebuffer& fb) {
  const int tangentLights = tangentLighting ? shade.lightCount : 0;
  std::uint64_t shaded = 0;
  rasterizeTriangle(setup, rowBegin, rowEnd, [&](int py, Span span) {
    for (int px = span.xBegin; px < span.xEnd; ++px) {
      const PixelWeights weights = pixelWeights(interpolation, px, py);
      if (!depthTestLess(weights.depth, fb.depth[fb.index(px, py)])) continue;
      const Fragment fragment = interpolateFragment(v0, v1, v2, weights, tangentLighting, tangentLights);
      const vec4 colour = shadeFragment<Features>(fragment, shade, nullptr);
      writeFragment(fb, px, py, colour, weights.depth, triangleId);
      ++shaded;
    }
  });
  return shaded;
}

}  // namespace twr
