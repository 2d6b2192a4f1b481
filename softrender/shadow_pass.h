// The shadow pass (docs/shadows.md): each shadowed light's map, drawn by the CPU pipeline's
// own stages (vertex, clip, setup, raster, depth test: the same traversal the frame uses) from
// the light, layer by layer, before the frame that samples it.
#pragma once

#include "scene/renderer.h"
#include "scene/shadow_map.h"
#include "softrender/draw_list.h"
#include "softrender/framebuffer.h"

#include <functional>
#include <vector>

namespace twr {

// Draws `items` into a size x size framebuffer it clears first, with the teaching or the fast
// traversal, and returns it (its depth becomes the layer; the callee keeps it).
using DepthDraw = std::function<const Framebuffer&(const std::vector<ItemState>& items, int size)>;

// The settings a shadow pass draws with: the frame's culling and winding, every frustum plane
// on, no user clip planes (a plane cutting the view does not cut the light's), the depth view
// (the cheapest permutation: the colour is thrown away), no TBN lines.
RenderSettings shadowPassSettings(const RenderSettings& frame);

// The maps of every light with "shadow" (per light index; null for the others), each layer
// drawn with `draw`. Empty when no light casts a shadow. `milliseconds` receives the pass's
// wall time.
ShadowMaps renderShadowMaps(const Scene& scene, const RenderSettings& settings, const DepthDraw& draw,
                            double& milliseconds);

// The teaching traversal (cpu_renderer.cpp): the vertex stage per item, then one band of rows
// per thread, each walking every triangle (draw_loop.h).
void drawTeachingItems(const std::vector<ItemState>& items, int threads, Framebuffer& fb, RenderStats& stats);

}  // namespace twr
