// The deferred pipeline's CPU pieces that are not per pixel (deferred.h).
#include "softrender/deferred.h"

#include "scene/camera.h"
#include "softrender/draw_loop.h"
#include "softrender/framebuffer.h"
#include "softrender/output_merge.h"

#include <cstddef>

namespace twr {

void resizeGBuffer(GBuffer& g, int width, int height, bool clear, bool position) {
  const std::size_t pixels = static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
  g.width = width;
  g.height = height;
  if (!position) g.position = {};
  for (std::vector<vec4>* target : {&g.normal, &g.geometric, &g.albedo, &g.specular, &g.emission, &g.position}) {
    if (target == &g.position && !position) continue;
    if (clear) {
      target->assign(pixels, vec4(0.0f));
    } else {
      target->resize(pixels);
    }
  }
}

DeferredUniforms makeDeferredUniforms(const Scene& scene, const RenderSettings& settings, int width, int height,
                                      const ShadowMaps& shadows) {
  DeferredUniforms u;
  // The lights and eye as any material's uniforms hold them (the material's own values are
  // in the G-buffer).
  RenderSettings shaded = settings;
  shaded.view = View::Shaded;
  u.lighting = makeShadeUniforms<float>(Material{}, scene, shaded);
  setShadowUniforms(u.lighting, shadows);
  u.worldFromClip = worldFromClipOf(clipFromWorldFor(scene.camera, width, height));
  u.viewportSize = vec2(static_cast<float>(width), static_cast<float>(height));
  u.positionStored = storesGBufferPosition(settings);
  return u;
}

void lightGBufferTeaching(const GBuffer& g, const DeferredUniforms& u, int threads, Framebuffer& fb) {
  RenderStats unused;
  drawInBands(
      threads, fb.height, false,
      [&](const RowBand& band, RenderStats&) {
        for (int py = band.rowBegin; py < band.rowEnd; ++py) {
          for (int px = 0; px < fb.width; ++px) {
            const std::size_t i = fb.index(px, py);
            const float depth = fb.depth[i];
            if (!(depth < kClearDepth)) continue;  // nothing drawn: the background stays
            const vec3 posWorld =
                u.positionStored ? vec3(g.position[i])
                                 : lanes::worldFromWindow<float>(u.worldFromClip, u.viewportSize, static_cast<float>(px),
                                                                 static_cast<float>(py), depth);
            const lanes::GBufferTexelL<float> surface{vec3(g.normal[i]),   g.normal[i].w,       vec3(g.geometric[i]),
                                               vec3(g.albedo[i]),   vec3(g.specular[i]), vec3(g.emission[i]),
                                               posWorld,            g.specular[i].w};
            writeFragment(fb, px, py, lanes::deferredLighting<float>(surface, u.lighting), depth,
                          fb.triangleId[i]);
          }
        }
      },
      unused);
}

}  // namespace twr
