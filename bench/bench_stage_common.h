// Shared inputs of the per-stage micro-benchmarks: the default scene's draw items at 720p and
// their vertex stage output, so each benchmark times one stage on the data a frame feeds it.
#pragma once

#include "scene/scene_file.h"
#include "softrender/draw_list.h"
#include "softrender/vertex.h"

#include <string>
#include <vector>

namespace twr::benchstage {

inline constexpr int kWidth = 1280;  // pixels
inline constexpr int kHeight = 720;  // pixels

struct Frame {
  Scene scene;
  std::vector<DrawItem> drawItems;
  std::vector<ItemState> items;
  std::vector<std::vector<ClipVertex>> vertices;  // per item, the vertex stage's output
};

// The default scene at kWidth x kHeight; item 1 is the normal-mapped sphere.
inline const Frame& defaultFrame() {
  static const Frame frame = [] {
    Frame f;
    f.scene = loadSceneFile(std::string(TWINRASTER_SOURCE_DIR) + "/assets/scenes/default.json");
    f.drawItems = flattenScene(f.scene);
    const mat4 clipFromWorld = clipFromWorldFor(f.scene.camera, kWidth, kHeight);
    for (const DrawItem& item : f.drawItems) {
      f.items.push_back(makeItemState(item, clipFromWorld, f.scene, f.scene.settings, kWidth, kHeight));
    }
    for (const ItemState& s : f.items) {
      std::vector<ClipVertex>& out = f.vertices.emplace_back();
      for (const Vertex& v : s.item->mesh->vertices) out.push_back(runVertexStage(v, s.vertexUniforms));
    }
    return f;
  }();
  return frame;
}

}  // namespace twr::benchstage
