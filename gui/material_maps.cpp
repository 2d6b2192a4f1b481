#include "gui/material_maps.h"

#include "gui/text_concat.h"
#include "scene/errors.h"
#include "scene/surface_detail.h"

#include <algorithm>
#include <cmath>
#include <set>

namespace twr::gui {
namespace {

std::size_t slotIndex(MapSlot slot) { return static_cast<std::size_t>(slot); }

void checkMaterial(const SceneDoc& doc, std::size_t material) {
  if (material >= doc.scene.materials.size()) {
    throw InputError(concat("material ", material, " does not exist (the scene has ", doc.scene.materials.size(), ")"));
  }
}

// Texel bytes of the distinct textures the document keeps, leaving out the loaded and the
// drawn map of (skipMaterial, skipSlot) unless another use holds the same object.
std::uintmax_t texelBytes(const SceneDoc& doc, std::size_t skipMaterial, MapSlot skipSlot, bool skip) {
  std::set<const Texture*> seen;
  std::uintmax_t total = 0;
  const auto add = [&](const Texture* texture) {
    if (texture && seen.insert(texture).second) total += textureTexelBytes(*texture);
  };
  for (std::size_t m = 0; m < doc.scene.materials.size(); ++m) {
    const Material& material = doc.scene.materials[m];
    for (const MapSlot slot : kMapSlots) {
      if (skip && m == skipMaterial && slot == skipSlot) continue;
      add(mapOf(material, slot).get());
      if (m < doc.loadedMaps.size()) add(doc.loadedMaps[m][slotIndex(slot)].get());
    }
  }
  return total;
}

}  // namespace

std::string_view toString(MapSlot slot) {
  switch (slot) {
    case MapSlot::Diffuse: return "diffuse map";
    case MapSlot::Normal: return "normal map";
    case MapSlot::Specular: return "specular map";
    case MapSlot::Height: return "height map";
  }
  return "map";
}

std::shared_ptr<const Texture>& mapOf(Material& material, MapSlot slot) {
  switch (slot) {
    case MapSlot::Diffuse: return material.diffuseMap;
    case MapSlot::Normal: return material.normalMap;
    case MapSlot::Height: return material.heightMap;
    case MapSlot::Specular: break;
  }
  return material.specularMap;
}

const std::shared_ptr<const Texture>& mapOf(const Material& material, MapSlot slot) {
  return mapOf(const_cast<Material&>(material), slot);  // the same member, read only
}

bool optionsChangeTexels(const TextureOptions& before, const TextureOptions& after) {
  return before.flipV != after.flipV || before.srgb != after.srgb;
}

std::shared_ptr<const Texture> loadedMap(const SceneDoc& doc, std::size_t material, MapSlot slot) {
  if (material >= doc.loadedMaps.size()) return nullptr;
  return doc.loadedMaps[material][slotIndex(slot)];
}

bool mapOn(const SceneDoc& doc, std::size_t material, MapSlot slot) {
  if (material >= doc.scene.materials.size()) return false;
  return mapOf(doc.scene.materials[material], slot) != nullptr;
}

bool setMapOn(SceneDoc& doc, std::size_t material, MapSlot slot, bool on) {
  const std::shared_ptr<const Texture> loaded = loadedMap(doc, material, slot);
  if (!loaded || material >= doc.scene.materials.size()) return false;
  std::shared_ptr<const Texture>& drawn = mapOf(doc.scene.materials[material], slot);
  if ((drawn != nullptr) == on) return true;
  drawn = on ? loaded : nullptr;
  doc.touch();
  return true;
}

std::vector<std::string> setMapOptions(SceneDoc& doc, std::size_t material, MapSlot slot,
                                       const TextureOptions& options) {
  checkMaterial(doc, material);
  const std::string name = concat(doc.scene.materials[material].name, ' ', toString(slot));
  const std::shared_ptr<const Texture> old = loadedMap(doc, material, slot);
  if (!old) throw InputError(concat("material ", name, ": the scene file gives no such map"));
  if (!offersGreen(slot) && options.green != GreenAxis::Up) {
    throw InputError(concat("material ", name, ": green is an option of normal maps only"));
  }
  if (options == old->options) return old->warnings;

  // What the scene may still load: the budget less every texture kept beside this map's.
  const std::uintmax_t kept = texelBytes(doc, material, slot, true);
  std::uintmax_t budget = kMaxSceneTextureBytes - std::min(kept, kMaxSceneTextureBytes);
  std::shared_ptr<Texture> made;
  if (optionsChangeTexels(old->options, options)) {
    if (old->path.empty()) throw InputError(concat("material ", name, ": built in code, no file to read again"));
    made = std::make_shared<Texture>(loadTexture(old->path, options, budget));
  } else {
    if (textureTexelBytes(*old) > budget) {
      throw InputError(concat(old->path, ": another copy of the texture would exceed the scene's ",
                              kMaxSceneTextureBytes >> 20, " MiB of texels"));
    }
    made = std::make_shared<Texture>(*old);
    made->options = options;
  }
  if ((slot == MapSlot::Normal || slot == MapSlot::Height) && made->options.srgb) {
    // As the scene loader says it (scene_file.cpp); done as asked.
    const std::string warning =
        slot == MapSlot::Normal
            ? concat(made->path, ": a normal map holds directions, not colours; decoding it as sRGB bends every "
                                 "normal (done as asked)")
            : concat(made->path, ": a height map holds heights, not colours; decoding it as sRGB bends every slope "
                                 "(done as asked)");
    if (std::find(made->warnings.begin(), made->warnings.end(), warning) == made->warnings.end()) {
      made->warnings.push_back(warning);
    }
  }

  std::shared_ptr<const Texture> replacement = std::move(made);
  std::shared_ptr<const Texture>& drawn = mapOf(doc.scene.materials[material], slot);
  if (material >= doc.loadedMaps.size()) doc.loadedMaps.resize(material + 1);
  doc.loadedMaps[material][slotIndex(slot)] = replacement;
  if (drawn) {
    drawn = replacement;
    doc.touch();
  }
  return replacement->warnings;
}

std::uintmax_t documentTextureBytes(const SceneDoc& doc) { return texelBytes(doc, 0, MapSlot::Diffuse, false); }

HeightFieldSettings heightFieldOf(const Material& material) {
  return {material.surfaceDetail,         material.heightScale, material.parallaxLayers,
          material.reliefRefinementSteps, material.selfShadow,  material.horizonDirections};
}

HeightFieldSettings clampHeightField(HeightFieldSettings wanted, const HeightFieldSettings& before) {
  HeightFieldSettings s = wanted;
  s.heightScale = std::isnan(s.heightScale) ? before.heightScale : std::clamp(s.heightScale, 0.0f, kMaxHeightScale);
  s.parallaxLayers.x = std::clamp(s.parallaxLayers.x, 1, kMaxParallaxLayers);
  s.parallaxLayers.y = std::clamp(s.parallaxLayers.y, 1, kMaxParallaxLayers);
  if (s.parallaxLayers.x > s.parallaxLayers.y) {
    // The bound the user moved wins; the other follows it.
    if (s.parallaxLayers.y != before.parallaxLayers.y) s.parallaxLayers.x = s.parallaxLayers.y;
    else s.parallaxLayers.y = s.parallaxLayers.x;
  }
  s.reliefRefinementSteps = std::clamp(s.reliefRefinementSteps, 0, kMaxReliefRefinementSteps);
  // Nearest multiple of 4 (halves round up), then into range.
  const int rounded = (std::max(s.horizonDirections, 0) + 2) / 4 * 4;
  s.horizonDirections = std::clamp(rounded, kMinHorizonDirections, kMaxHorizonDirections);
  return s;
}

HeightFieldEdit setHeightField(SceneDoc& doc, std::size_t material, const HeightFieldSettings& wanted) {
  checkMaterial(doc, material);
  Material& m = doc.scene.materials[material];
  const HeightFieldSettings before = heightFieldOf(m);
  const HeightFieldSettings s = clampHeightField(wanted, before);
  const bool hasHeightMap = loadedMap(doc, material, MapSlot::Height) != nullptr || m.heightMap != nullptr;
  if (!hasHeightMap && readsHeightMap(s.surfaceDetail)) {
    throw InputError(concat("material ", m.name, ": \"", toString(s.surfaceDetail),
                            "\" reads a height map, and the scene file gives this material none (\"height_map\")"));
  }
  if (!hasHeightMap && s.selfShadow != SelfShadow::None) {
    throw InputError(concat("material ", m.name, ": self-shadowing reads a height map, and the scene file gives this "
                                                 "material none (\"height_map\")"));
  }
  HeightFieldEdit edit;
  if (s == before) return edit;
  m.surfaceDetail = s.surfaceDetail;
  m.heightScale = s.heightScale;
  m.parallaxLayers = s.parallaxLayers;
  m.reliefRefinementSteps = s.reliefRefinementSteps;
  m.selfShadow = s.selfShadow;
  m.horizonDirections = s.horizonDirections;
  doc.touch();
  edit.changed = true;
  edit.horizonMapStale = horizonMapStale(doc, material);
  return edit;
}

bool wantsHorizonMap(const Material& material) {
  return material.selfShadow == SelfShadow::HorizonMap && readsHeightMap(material.surfaceDetail) &&
         usableTexture(material.heightMap.get());
}

bool horizonMapStale(const SceneDoc& doc, std::size_t material) {
  if (material >= doc.scene.materials.size()) return false;
  const Material& m = doc.scene.materials[material];
  if (!wantsHorizonMap(m)) return false;
  if (!m.horizonMap || material >= doc.horizonSources.size()) return true;
  const HorizonSource& source = doc.horizonSources[material];
  const std::shared_ptr<const Texture> builtFrom = source.heightMap.lock();
  return builtFrom != m.heightMap || source.heightScale != m.heightScale || source.directions != m.horizonDirections;
}

std::optional<HorizonRequest> staleHorizonMap(const SceneDoc& doc) {
  for (std::size_t i = 0; i < doc.scene.materials.size(); ++i) {
    if (!horizonMapStale(doc, i)) continue;
    const Material& m = doc.scene.materials[i];
    return HorizonRequest{i, m.heightMap, m.heightScale, m.horizonDirections};
  }
  return std::nullopt;
}

bool installHorizonMap(SceneDoc& doc, const HorizonRequest& request, std::shared_ptr<const HorizonMap> map) {
  if (!map || request.material >= doc.scene.materials.size()) return false;
  Material& m = doc.scene.materials[request.material];
  if (!wantsHorizonMap(m) || m.heightMap != request.heightMap || m.heightScale != request.heightScale ||
      m.horizonDirections != request.directions) {
    return false;
  }
  m.horizonMap = std::move(map);
  if (doc.horizonSources.size() < doc.scene.materials.size()) doc.horizonSources.resize(doc.scene.materials.size());
  doc.horizonSources[request.material] = {request.heightMap, request.heightScale, request.directions};
  doc.touch();
  return true;
}

}  // namespace twr::gui
