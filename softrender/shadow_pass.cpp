#include "softrender/shadow_pass.h"

#include <chrono>
#include <cstring>
#include <stdexcept>

namespace twr {

RenderSettings shadowPassSettings(const RenderSettings& frame) {
  RenderSettings s;
  s.cull = frame.cull;
  s.frontFace = frame.frontFace;
  s.view = View::Depth;
  return s;
}

Framebuffer makeShadowFramebuffer(int size, vec4 background) {
  Framebuffer fb = makeFramebuffer(size, size, background);
  fb.depthFormat = DepthFormat::Float32;
  return fb;
}

std::shared_ptr<ShadowMap> ShadowMapPool::acquire(std::size_t texels) {
  for (std::shared_ptr<ShadowMap>& map : maps_) {
    if (map.use_count() != 1 || map->depth.size() != texels) continue;
    map->projection = ShadowProjection{};
    map->milliseconds = 0.0;
    return map;  // every texel is written by the pass
  }
  // None free: drop the free ones of other sizes beyond the cap, then make one.
  if (maps_.size() >= kMaxKept) {
    std::erase_if(maps_, [](const std::shared_ptr<ShadowMap>& m) { return m.use_count() == 1; });
  }
  auto map = std::make_shared<ShadowMap>();
  map->depth.resize(texels);
  if (maps_.size() < kMaxKept) maps_.push_back(map);
  return map;
}

ShadowMaps renderShadowMaps(const Scene& scene, const RenderSettings& settings, const DepthDraw& draw,
                            double& milliseconds, ShadowMapPool* pool) {
  milliseconds = 0.0;
  if (!sceneHasShadows(scene)) return {};
  const auto start = std::chrono::steady_clock::now();
  const RenderSettings passSettings = shadowPassSettings(settings);
  const std::vector<DrawItem> drawItems = flattenScene(scene);
  for (const DrawItem& item : drawItems) validateIndices(item);
  const WorldBounds bounds = worldBoundsOf(scene);
  ShadowMaps maps(scene.lights.size());
  std::vector<ItemState> items;
  for (std::size_t i = 0; i < scene.lights.size() && i < static_cast<std::size_t>(kMaxLights); ++i) {
    const Light& light = scene.lights[i];
    if (!light.shadow) continue;
    const auto lightStart = std::chrono::steady_clock::now();
    const ShadowProjection projection = shadowProjectionFor(light, bounds);
    const int size = projection.size;
    const std::size_t layerTexels = static_cast<std::size_t>(size) * static_cast<std::size_t>(size);
    const std::size_t texels = layerTexels * static_cast<std::size_t>(projection.layers);
    std::shared_ptr<ShadowMap> map;
    if (pool) {
      map = pool->acquire(texels);
    } else {
      map = std::make_shared<ShadowMap>();
      map->depth.resize(texels);
    }
    map->projection = projection;
    for (int layer = 0; layer < map->projection.layers; ++layer) {
      items.clear();
      for (const DrawItem& item : drawItems) {
        items.push_back(makeItemState(item, map->projection.clipFromWorld[static_cast<std::size_t>(layer)], scene,
                                      passSettings, size, size));
      }
      const Framebuffer& fb = draw(items, size);
      // A 24-bit map would part from GL's wherever its depths lie below 0.5 (framebuffer.h).
      if (fb.depthFormat != DepthFormat::Float32) throw std::logic_error("shadow pass: the map's framebuffer stores 24-bit depth");
      // The framebuffer is stored top row first; the map holds rows bottom first.
      float* out = map->depth.data() + static_cast<std::size_t>(layer) * layerTexels;
      for (int y = 0; y < size; ++y) {
        std::memcpy(out + static_cast<std::size_t>(y) * static_cast<std::size_t>(size), &fb.depth[fb.index(0, y)],
                    static_cast<std::size_t>(size) * sizeof(float));
      }
    }
    map->milliseconds =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - lightStart).count();
    maps[i] = std::move(map);
  }
  milliseconds = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  return maps;
}

}  // namespace twr
