#include "gui/scene_doc.h"

#include "scene/scene_file.h"

#include <filesystem>
#include <system_error>

namespace twr::gui {
namespace {

const char* const kDefaultSceneRelative = "assets/scenes/default.json";

bool isFile(const std::filesystem::path& path) {
  std::error_code code;
  return std::filesystem::is_regular_file(path, code);
}

}  // namespace

SceneDoc loadSceneDoc(const std::string& path) {
  SceneDoc doc;
  doc.scene = loadSceneFile(path);
  doc.fileCamera = doc.scene.camera;
  for (const Material& material : doc.scene.materials) {
    doc.loadedMaps.push_back({material.diffuseMap, material.normalMap, material.specularMap, material.heightMap});
    // The loader builds the horizon map from the keys it read.
    HorizonSource source;
    if (material.horizonMap) source = {material.heightMap, material.heightScale, material.horizonDirections};
    doc.horizonSources.push_back(source);
  }
  return doc;
}

SceneDoc emptySceneDoc() {
  SceneDoc doc;
  doc.fileCamera = doc.scene.camera;
  return doc;
}

std::string findStartupScene(const std::string& remembered) {
  if (!remembered.empty() && isFile(remembered)) return remembered;
  if (isFile(kDefaultSceneRelative)) return kDefaultSceneRelative;
  std::error_code code;
  const std::filesystem::path exe = std::filesystem::read_symlink("/proc/self/exe", code);
  if (!code) {
    // build/app/twinraster-gui -> <source>/assets/...
    const std::filesystem::path beside = exe.parent_path().parent_path().parent_path() / kDefaultSceneRelative;
    if (isFile(beside)) return beside.lexically_normal().string();
  }
  return "";
}

}  // namespace twr::gui
