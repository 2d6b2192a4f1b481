#include "softrender/pixel_views.h"

#include "scene/errors.h"
#include "scene/mip_level_view.h"
#include "softrender/framebuffer.h"
#include "softrender/sky.h"

#include <algorithm>
#include <cstring>

namespace twr {

ViewPixel shadeTracedPixel(const Scene& scene, const RenderSettings& settings, const PixelTrace& trace, View view) {
  if (trace.lightingSpace != settings.lightingSpace) {
    throw InputError("pixel views: the trace was taken in another lighting space (its varyings differ)");
  }
  ViewPixel pixel;
  const std::uint32_t background = backgroundWord(scene.output.background);
  std::memcpy(pixel.rgba.data(), &background, sizeof background);
  // Visits are in draw order and each shaded one passed GL_LESS against the ones before it:
  // the last shaded visit is the fragment the pixel keeps.
  const auto winner = std::find_if(trace.visits.rbegin(), trace.visits.rend(),
                                   [](const TriangleVisit& visit) { return visit.outcome == TraceOutcome::Shaded; });
  if (winner == trace.visits.rend()) {
    // No triangle: the sky box where the scene has one (sky.h), else the clear colour.
    const SkyUniformsT<float> sky = makeSkyUniforms(scene, trace.width, trace.height, view);
    if (sky.cube) {
      const vec3 c = skyColour(sky, trace.x, trace.yGl);
      pixel.rgba = {unitToByte(c.r), unitToByte(c.g), unitToByte(c.b), 255};
    }
    return pixel;
  }

  RenderSettings viewSettings = settings;
  viewSettings.view = view;
  viewSettings.tbnLines.enabled = false;
  std::vector<DrawItem> items = flattenScene(scene);
  const MipLevelView mipLevelView = applyMipLevelView(items, viewSettings);  // owns stand-ins while shaded
  const auto item = std::find_if(items.begin(), items.end(), [&winner](const DrawItem& candidate) {
    return winner->triangleId >= candidate.firstTriangleId &&
           winner->triangleId - candidate.firstTriangleId < candidate.mesh->triangleCount();
  });
  if (item == items.end()) throw InputError("pixel views: the trace does not belong to this scene");

  ShadeUniforms uniforms = makeShadeUniforms(*item->material, scene, viewSettings);
  setShadowUniforms(uniforms, trace.shadowMaps);
  const ShaderKey key = shaderKeyFor(uniforms, viewSettings);
  // The environment's quad differences as this view's shading finds them (the trace was taken
  // in its own view, whose surface may differ).
  Fragment fragment = winner->fragment;
  setEnvironmentDifferencesDynamic(key, winner->varyings, trace.x, trace.yGl, uniforms, fragment);
  const vec4 colour = shadeFragmentDynamic(key, fragment, uniforms, nullptr);
  // As writeFragment (output_merge.h) stores a surface fragment: opaque, with its depth and id.
  pixel.rgba = {unitToByte(colour.r), unitToByte(colour.g), unitToByte(colour.b), 255};
  pixel.depth = winner->weights.depth;
  pixel.triangleId = winner->triangleId;
  return pixel;
}

}  // namespace twr
