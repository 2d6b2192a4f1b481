// The shadow pass (docs/shadows.md): each shadowed light's map, drawn by the CPU pipeline's
// own stages (vertex, clip, setup, raster, depth test: the same traversal the frame uses) from
// the light, layer by layer, before the frame that samples it.
#pragma once

#include "scene/renderer.h"
#include "scene/shadow_map.h"
#include "softrender/draw_list.h"
#include "softrender/framebuffer.h"

#include <functional>
#include <memory>
#include <vector>

namespace twr {

// Draws `items` into a size x size framebuffer it clears first, with the teaching or the fast
// traversal, and returns it (its depth becomes the layer; the callee keeps it). The
// framebuffer stores DepthFormat::Float32, as GL's maps are GL_DEPTH_COMPONENT32F
// (makeShadowFramebuffer); renderShadowMaps refuses any other.
using DepthDraw = std::function<const Framebuffer&(const std::vector<ItemState>& items, int size)>;

// A cleared size x size framebuffer for one layer of a map: makeFramebuffer's, storing float depth.
Framebuffer makeShadowFramebuffer(int size, vec4 background);

// The settings a shadow pass draws with: the frame's culling and winding, every frustum plane
// on, no user clip planes (a plane cutting the view does not cut the light's), the depth view
// (the cheapest permutation: the colour is thrown away), no TBN lines.
RenderSettings shadowPassSettings(const RenderSettings& frame);

// Maps kept across frames by one renderer: a map no frame's output holds any more is written
// again instead of allocated and filled anew (a 2048^2 map is 16 MB of fresh pages per frame
// otherwise). Outputs keep their own maps for as long as their holders keep them.
class ShadowMapPool {
 public:
  // A map with `texels` depth values whose other fields are reset; shared with nobody.
  std::shared_ptr<ShadowMap> acquire(std::size_t texels);

 private:
  static constexpr std::size_t kMaxKept = 8;  // maps, every light's of the last frames
  std::vector<std::shared_ptr<ShadowMap>> maps_;
};

// The maps of every light with "shadow" (per light index; null for the others), each layer
// drawn with `draw`. Empty when no light casts a shadow. `milliseconds` receives the pass's
// wall time. `pool`: where the maps' storage comes from (null: allocated for this call).
ShadowMaps renderShadowMaps(const Scene& scene, const RenderSettings& settings, const DepthDraw& draw,
                            double& milliseconds, ShadowMapPool* pool = nullptr);

// The teaching traversal (cpu_renderer.cpp): the vertex stage per item, then one band of rows
// per thread, each walking every triangle (draw_loop.h).
void drawTeachingItems(const std::vector<ItemState>& items, int threads, Framebuffer& fb, RenderStats& stats);

}  // namespace twr
