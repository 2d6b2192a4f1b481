// Screen-space reflections' CPU pieces that are not per pixel (ssr.h).
#include "softrender/ssr.h"

#include "scene/camera.h"
#include "scene/scene.h"
#include "softrender/deferred.h"
#include "softrender/draw_loop.h"
#include "softrender/framebuffer.h"
#include "softrender/output_merge.h"

#include <cstddef>

namespace twr {

SsrUniforms makeSsrUniforms(const Scene& scene, const RenderSettings& settings, int width, int height) {
  SsrUniforms u;
  u.clipFromWorld = clipFromWorldFor(scene.camera, width, height);
  u.viewportSize = vec2(static_cast<float>(width), static_cast<float>(height));
  const double n = scene.camera.near, f = scene.camera.far;
  u.distanceNumerator = static_cast<float>(2.0 * n * f);
  u.distanceSum = static_cast<float>(f + n);
  u.distanceDifference = static_cast<float>(f - n);
  u.eyePosWorld = scene.camera.position;
  const SsrSettings& s = settings.ssr;
  u.march = s.march;
  u.maxSteps = s.maxSteps;
  u.step = s.step;
  u.minStep = s.step * kSsrAdaptiveMinStepRatio;
  u.thickness = s.thickness;
  u.reflectStrength = s.reflectStrength;
  return u;
}

void ssrPlanesOf(const Framebuffer& fb, const GBuffer& g, bool positionStored, const SsrUniforms& u,
                 SsrPlanes& planes) {
  const std::size_t pixels = static_cast<std::size_t>(fb.width) * static_cast<std::size_t>(fb.height);
  for (std::size_t c = 0; c < 3; ++c) {
    std::vector<float>& plane = planes.rgb[c];
    plane.resize(pixels);
    for (std::size_t i = 0; i < pixels; ++i) plane[i] = static_cast<float>(fb.rgba[4 * i + c]) / 255.0f;
  }
  planes.surfaceDistance.resize(pixels);
  const float far = ssrDistanceOfDepthLanes<float>(u, kClearDepth);
  for (std::size_t i = 0; i < pixels; ++i) {
    const bool drawn = fb.depth[i] < kClearDepth;
    planes.surfaceDistance[i] = !drawn         ? far
                                : positionStored ? ssrDistanceOfPointLanes<float>(u, vec3(g.position[i]))
                                                 : ssrDistanceOfDepthLanes<float>(u, fb.depth[i]);
  }
}

void reflectTeaching(const GBuffer& g, SsrUniforms u, const Mat4T<float>& worldFromClip, bool positionStored,
                     int threads, Framebuffer& fb) {
  SsrPlanes planes;
  ssrPlanesOf(fb, g, positionStored, u, planes);
  u.surfaceDistance = planes.surfaceDistance.data();
  for (std::size_t c = 0; c < 3; ++c) u.colour[c] = planes.rgb[c].data();
  RenderStats unused;
  drawInBands(
      threads, fb.height, false,
      [&](const RowBand& band, RenderStats&) {
        for (int py = band.rowBegin; py < band.rowEnd; ++py) {
          for (int px = 0; px < fb.width; ++px) {
            const std::size_t i = fb.index(px, py);
            const float depth = fb.depth[i];
            const bool drawn = depth < kClearDepth;
            if (!drawn || !(g.specular[i].w > 0.0f)) continue;
            const vec3 posWorld = positionStored ? vec3(g.position[i])
                                                 : worldFromWindowLanes<float>(worldFromClip, u.viewportSize,
                                                                               static_cast<float>(px),
                                                                               static_cast<float>(py), depth);
            vec3 colour(planes.rgb[0][i], planes.rgb[1][i], planes.rgb[2][i]);
            const SsrMarchL<float> m = ssrPixelLanes<float>(u, vec3(g.normal[i]), posWorld, g.specular[i].w, drawn, colour);
            if (m.result == ssrResultLane<float>(SsrResult::Hit)) {
              writeFragment(fb, px, py, vec4(colour, 1.0f), depth, fb.triangleId[i]);
            }
          }
        }
      },
      unused);
}

}  // namespace twr
