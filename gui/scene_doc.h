// The scene the app shows and edits, with what editing needs beside it: the camera the file
// gave (for "reset"), material maps switched off in the UI, and an edit counter.
#pragma once

#include "scene/scene.h"

#include <array>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace twr::gui {

// A material's maps in the order diffuse, normal, specular, height.
using MaterialMaps = std::array<std::shared_ptr<const Texture>, 4>;

// What a material's horizon map was built from (material_maps.h): the height map (weak: a
// height map that is gone cannot match a new one at the same address), its depth and the
// number of directions.
struct HorizonSource {
  std::weak_ptr<const Texture> heightMap;
  float heightScale = 0.0f;
  int directions = 0;
};

struct SceneDoc {
  Scene scene;
  Camera fileCamera;                      // the camera as loaded, for "reset"
  std::vector<MaterialMaps> loadedMaps;   // per material, the maps as loaded
  std::vector<HorizonSource> horizonSources;  // per material, what its horizonMap was built from
  std::uint64_t revision = 1;             // bumped by every edit that changes a render

  void touch() { ++revision; }
};

// Loads `path` into a new document (throws InputError with the loader's message).
SceneDoc loadSceneDoc(const std::string& path);
// A document with no nodes, for when no scene could be opened.
SceneDoc emptySceneDoc();

// The scene to open when none is given: `remembered` when that file exists, else
// assets/scenes/default.json under the working folder, else the one beside the source tree
// the binary was built in (<exe>/../../assets/...); empty when none exists.
std::string findStartupScene(const std::string& remembered);

}  // namespace twr::gui
