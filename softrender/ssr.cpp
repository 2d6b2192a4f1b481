// Screen-space reflections' CPU pieces that are not per pixel (ssr.h).
#include "softrender/ssr.h"

#include "scene/camera.h"
#include "scene/scene.h"
#include "softrender/deferred.h"
#include "softrender/draw_loop.h"
#include "softrender/framebuffer.h"
#include "softrender/output_merge.h"
#include "scene/errors.h"

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>

namespace twr {

SsrUniforms makeSsrUniforms(const Scene& scene, const RenderSettings& settings, int width, int height) {
  SsrUniforms u;
  u.clipFromWorld = clipFromWorldFor(scene.camera, width, height);
  u.viewportSize = vec2(static_cast<float>(width), static_cast<float>(height));
  const double n = scene.camera.near, f = scene.camera.far;
  u.distanceNumerator = static_cast<float>(2.0 * n * f);
  u.distanceSum = static_cast<float>(f + n);
  u.distanceDifference = static_cast<float>(f - n);
  u.nearDistance = static_cast<float>(n);
  u.farDistance = static_cast<float>(f);
  u.skyDistance = lanes::distanceOfDepth<float>(u, kClearDepth);
  u.eyePosWorld = scene.camera.position;
  const SsrSettings& s = settings.ssr;
  u.march = s.march;
  u.maxSteps = s.maxSteps;
  u.step = s.step;
  u.minStep = s.step * kSsrAdaptiveMinStepRatio;
  u.thickness = s.thickness;
  u.reflectStrength = s.reflectStrength;
  u.hizLevels = s.march == SsrMarch::Hiz ? hizLevelsOf(width, height) : 0;
  u.indirectSamples = s.indirectSamples;
  u.distribution = s.sampleDistribution;
  u.indirectScale = s.indirectSamples > 0 ? 1.0f / static_cast<float>(s.indirectSamples) : 1.0f;
  u.view = isSsrView(settings.view) ? settings.view : View::Shaded;
  return u;
}

std::uint32_t pcgHash(std::uint32_t v) {
  const std::uint32_t state = v * 747796405u + 2891336453u;
  const std::uint32_t word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
  return (word >> 22u) ^ word;
}

vec2 ssrRandomPairOf(std::uint32_t x, std::uint32_t y, std::uint32_t k) {
  const std::uint32_t seed = pcgHash(x ^ pcgHash(y ^ pcgHash(k)));
  const std::uint32_t second = pcgHash(seed);
  constexpr float kUnit = 1.0f / 16777216.0f;  // 2^-24: 24 bits, exact in a float
  return vec2(static_cast<float>(seed >> 8u) * kUnit, static_cast<float>(second >> 8u) * kUnit);
}

void hizChainOf(const std::vector<float>& surfaceDistance, int width, int height, SsrPlanes& planes) {
  planes.hizLevels = hizLevelsOf(width, height);
  std::size_t total = 0;
  for (int k = 1; k <= planes.hizLevels; ++k) {
    planes.hizOffset[static_cast<std::size_t>(k)] = static_cast<float>(total);
    total += static_cast<std::size_t>(width >> k) * static_cast<std::size_t>(height >> k);
  }
  planes.hizCells.resize(total);
  // The level below, read by column and row from the bottom: the frame's plane is top row first.
  int belowWidth = width, belowHeight = height;
  const auto below = [&](int k, int x, int y) {
    if (k == 1) return surfaceDistance[static_cast<std::size_t>(height - 1 - y) * static_cast<std::size_t>(width) +
                                       static_cast<std::size_t>(x)];
    const std::size_t at = static_cast<std::size_t>(planes.hizOffset[static_cast<std::size_t>(k - 1)]);
    return planes.hizCells[at + static_cast<std::size_t>(y) * static_cast<std::size_t>(belowWidth) +
                           static_cast<std::size_t>(x)];
  };
  for (int k = 1; k <= planes.hizLevels; ++k) {
    const int levelWidth = width >> k, levelHeight = height >> k;
    float* cells = planes.hizCells.data() + static_cast<std::size_t>(planes.hizOffset[static_cast<std::size_t>(k)]);
    for (int y = 0; y < levelHeight; ++y) {
      // The last row (column) also covers the odd row (column) the halving drops.
      const int yEnd = y == levelHeight - 1 ? belowHeight : 2 * y + 2;
      for (int x = 0; x < levelWidth; ++x) {
        const int xEnd = x == levelWidth - 1 ? belowWidth : 2 * x + 2;
        float least = below(k, 2 * x, 2 * y);
        for (int by = 2 * y; by < yEnd; ++by) {
          for (int bx = 2 * x; bx < xEnd; ++bx) least = std::min(least, below(k, bx, by));
        }
        cells[static_cast<std::size_t>(y) * static_cast<std::size_t>(levelWidth) + static_cast<std::size_t>(x)] = least;
      }
    }
    belowWidth = levelWidth;
    belowHeight = levelHeight;
  }
}

void useSsrPlanes(const SsrPlanes& planes, SsrUniforms& u) {
  u.surfaceDistance = planes.surfaceDistance.data();
  for (std::size_t c = 0; c < 3; ++c) u.colour[c] = planes.rgb[c].data();
  u.hizCells = planes.hizCells.data();
  u.hizOffset = planes.hizOffset;
  u.hizLevels = std::min(u.hizLevels, planes.hizLevels);
}

void ssrPlanesOf(const Framebuffer& fb, const GBuffer& g, bool positionStored, const SsrUniforms& u,
                 SsrPlanes& planes) {
  const std::size_t pixels = static_cast<std::size_t>(fb.width) * static_cast<std::size_t>(fb.height);
  for (std::size_t c = 0; c < 3; ++c) {
    std::vector<float>& plane = planes.rgb[c];
    plane.resize(pixels);
    for (std::size_t i = 0; i < pixels; ++i) plane[i] = static_cast<float>(fb.rgba[4 * i + c]) / 255.0f;
  }
  ssrDistancesOf(fb.depth, fb.width, fb.height, g, positionStored, u, planes);
}

void ssrDistancesOf(const std::vector<float>& depth, int width, int height, const GBuffer& g, bool positionStored,
                    const SsrUniforms& u, SsrPlanes& planes) {
  const std::size_t pixels = static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
  planes.surfaceDistance.resize(pixels);
  const float far = u.skyDistance;
  for (std::size_t i = 0; i < pixels; ++i) {
    const bool drawn = depth[i] < kClearDepth;
    planes.surfaceDistance[i] = !drawn         ? far
                                : positionStored ? lanes::distanceOfPoint<float>(u, vec3(g.position[i]))
                                                 : lanes::distanceOfDepth<float>(u, depth[i]);
  }
  planes.hizLevels = 0;
  if (u.march == SsrMarch::Hiz) hizChainOf(planes.surfaceDistance, width, height, planes);
}

SsrMarchTrace traceSsrMarch(const Scene& scene, const RenderSettings& settings, const RenderOutput& frame, int x,
                            int yTop, int ray) {
  const int width = frame.width, height = frame.height;
  if (x < 0 || x >= width || yTop < 0 || yTop >= height) {
    throw InputError("SSR march trace: pixel (" + std::to_string(x) + ", " + std::to_string(yTop) +
                     ") is outside the " + std::to_string(width) + " x " + std::to_string(height) + " frame");
  }
  const std::size_t pixels = static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
  if (!drawsSsr(settings) || !frame.gbuffer || frame.gbuffer->normal.size() != pixels || frame.depth.size() != pixels) {
    throw InputError("SSR march trace: the frame draws no screen-space reflections (settings.ssr on, or an SSR "
                     "view, gives it the G-buffer the march reads)");
  }
  const GBuffer& g = *frame.gbuffer;
  const bool positionStored = !g.position.empty();
  checkSsrRay(settings, ray);
  SsrUniforms u = makeSsrUniforms(scene, settings, width, height);
  SsrPlanes planes;
  ssrDistancesOf(frame.depth, width, height, g, positionStored, u, planes);
  useSsrPlanes(planes, u);  // the march reads no colour
  SsrMarchTrace trace;
  trace.ray = ray;
  const std::size_t i = static_cast<std::size_t>(yTop) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x);
  const float depth = frame.depth[i];
  trace.marched = depth < kClearDepth;
  if (!trace.marched) return trace;
  // As reflectTeaching and ssrPixel: the ray's origin and direction (the mirror's, or the
  // sample's over the hemisphere from the pixel's random pair).
  const int yGl = height - 1 - yTop;
  const vec3 posWorld = positionStored
                            ? vec3(g.position[i])
                            : lanes::worldFromWindow<float>(worldFromClipOf(u.clipFromWorld), u.viewportSize,
                                                            static_cast<float>(x), static_cast<float>(yGl), depth);
  const vec3 nl(g.normal[i]);
  const vec3 wo = lanes::safeNormalize<float>(u.eyePosWorld - posWorld);
  vec3 r = lanes::safeNormalize<float>((2.0f * lanes::dot3<float>(nl, wo)) * nl - wo);
  if (ray != kSsrMirrorRay) {
    const vec2 xi = ssrRandomPairOf(static_cast<std::uint32_t>(x), static_cast<std::uint32_t>(yGl),
                                    static_cast<std::uint32_t>(ray));
    r = lanes::hemisphere<float>(u, nl, xi, trace.weight);
  }
  trace.origin = posWorld;
  trace.direction = r;
  lanes::marchOf<float>(u, posWorld, r, true, &trace.steps);
  return trace;
}

void reflectTeaching(const GBuffer& g, SsrUniforms u, const Mat4T<float>& worldFromClip, bool positionStored,
                     int threads, Framebuffer& fb) {
  SsrPlanes planes;
  ssrPlanesOf(fb, g, positionStored, u, planes);
  useSsrPlanes(planes, u);
  RenderStats unused;
  drawInBands(
      threads, fb.height, false,
      [&](const RowBand& band, RenderStats&) {
        for (int py = band.rowBegin; py < band.rowEnd; ++py) {
          for (int px = 0; px < fb.width; ++px) {
            const std::size_t i = fb.index(px, py);
            const float depth = fb.depth[i];
            const bool drawn = depth < kClearDepth;
            if (!drawn || !(g.specular[i].w > 0.0f || u.indirectSamples > 0 || isSsrView(u.view))) continue;
            const vec3 posWorld = positionStored ? vec3(g.position[i])
                                                 : lanes::worldFromWindow<float>(worldFromClip, u.viewportSize,
                                                                                 static_cast<float>(px),
                                                                                 static_cast<float>(py), depth);
            std::array<vec2, kMaxSsrIndirectSamples> samples;
            for (int k = 0; k < u.indirectSamples; ++k) {
              samples[static_cast<std::size_t>(k)] =
                  ssrRandomPairOf(static_cast<std::uint32_t>(px), static_cast<std::uint32_t>(py), static_cast<std::uint32_t>(k));
            }
            vec3 colour(planes.rgb[0][i], planes.rgb[1][i], planes.rgb[2][i]);
            const lanes::SsrPixelL<float> p = lanes::ssrPixel<float>(u, vec3(g.normal[i]), posWorld, g.specular[i].w,
                                                                     vec3(g.albedo[i]), samples.data(), drawn, colour);
            if (p.changed) writeFragment(fb, px, py, vec4(colour, 1.0f), depth, fb.triangleId[i]);
          }
        }
      },
      unused);
}

}  // namespace twr
