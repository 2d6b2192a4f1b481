// Editing a material from the UI: its maps (issue 15, item 6: switching a map off and on, and
// changing the options a scene file gives a map: flip_v, wrap, srgb, green) and its height
// field (issue 16: surface_detail and its knobs, self-shadowing, and when the horizon map must be
// built again). No ImGui here, so tests/gui/test_material_maps.cpp drives it without a window.
//
// An edit never changes a Texture in place. It makes a new one and points the material at it:
//   - the CPU worker may be rendering the old one on its thread right now (a job shares the
//     scene's textures read-only);
//   - another material may share the old one (the loader shares a file read with the same
//     options), and an option belongs to one use of a file, as in the scene file;
//   - GL's upload cache and the fast path's tiled copies are keyed by the Texture object, so a
//     new object is uploaded and tiled afresh, and the old entries are dropped by the first
//     frame that no longer uses them: neither backend can keep a stale copy.
#pragma once

#include "gui/scene_doc.h"
#include "scene/horizon_map.h"
#include "scene/texture.h"

#include <cstddef>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace twr::gui {

// The maps the Materials section lists, in MaterialMaps order.
enum class MapSlot { Diffuse, Normal, Specular, Height };
inline constexpr MapSlot kMapSlots[] = {MapSlot::Diffuse, MapSlot::Normal, MapSlot::Specular, MapSlot::Height};

// "diffuse map", "normal map", "specular map", "height map".
std::string_view toString(MapSlot slot);
// The material's pointer for `slot` (null when the map is off or the material has none).
std::shared_ptr<const Texture>& mapOf(Material& material, MapSlot slot);
const std::shared_ptr<const Texture>& mapOf(const Material& material, MapSlot slot);
// Whether the scene file offers the `green` option on this map (normal maps only).
constexpr bool offersGreen(MapSlot slot) { return slot == MapSlot::Normal; }
// Whether going from `before` to `after` changes texels (flip_v turns the rows around; srgb
// changes how a built mip chain averages), so the file must be read again; wrap and green
// are sampling state only.
bool optionsChangeTexels(const TextureOptions& before, const TextureOptions& after);

// The map as loaded (kept while it is switched off), or null when the file gave none.
std::shared_ptr<const Texture> loadedMap(const SceneDoc& doc, std::size_t material, MapSlot slot);
// Whether the map is on (drawn); false when there is none.
bool mapOn(const SceneDoc& doc, std::size_t material, MapSlot slot);
// Switches a loaded map off (the material draws without it) or back on. Bumps the revision
// when that changes what is drawn; false (nothing done) when the file gave no such map.
bool setMapOn(SceneDoc& doc, std::size_t material, MapSlot slot, bool on);

// Gives the map `options`: a new Texture, read from its file again when optionsChangeTexels,
// else a copy of the loaded one with the new options. It replaces the loaded map, and the
// drawn one when the map is on (then the revision is bumped). Every other material keeps its
// textures. Returns the warnings of the new texture (e.g. srgb ignored on a BC4/BC5 file, srgb
// on a normal or a height map), each a line naming the file. A new height map makes the
// material's horizon map stale (horizonMapStale). Throws InputError (the material or map does
// not exist, the file is gone or no longer reads, the scene's texel budget,
// kMaxSceneTextureBytes, would be exceeded) and then leaves the document as it was.
std::vector<std::string> setMapOptions(SceneDoc& doc, std::size_t material, MapSlot slot, const TextureOptions& options);

// Texel bytes of every distinct texture the document holds (loaded maps, drawn maps), each
// counted once: what the budget of setMapOptions is measured against.
std::uintmax_t documentTextureBytes(const SceneDoc& doc);

// ---- The height field (issue 16, docs/parallax.md) ----

// The height-field keys of a material the Scene tab edits (the height map itself is a MapSlot).
struct HeightFieldSettings {
  SurfaceDetail surfaceDetail = SurfaceDetail::NormalMap;
  float heightScale = kDefaultHeightScale;  // texture-space depth, [0, kMaxHeightScale]
  ivec2 parallaxLayers{8, 32};              // [min, max], each in [1, kMaxParallaxLayers], min <= max
  int reliefRefinementSteps = 5;            // [0, kMaxReliefRefinementSteps]
  SelfShadow selfShadow = SelfShadow::None;
  int horizonDirections = 8;  // a multiple of 4 in [kMinHorizonDirections, kMaxHorizonDirections]
  bool operator==(const HeightFieldSettings&) const = default;
};
HeightFieldSettings heightFieldOf(const Material& material);

// Whether the method reads a height map: every one but normal_map (the scene file refuses the
// others on a material without "height_map").
constexpr bool readsHeightMap(SurfaceDetail method) { return method != SurfaceDetail::NormalMap; }
// Whether the parallax_layers range is read: by the methods that march layers, and by the height
// march of self-shadowing (towards the light, layer by layer), whatever the method.
constexpr bool readsParallaxLayers(const HeightFieldSettings& s) {
  return marchesLayers(s.surfaceDetail) || (readsHeightMap(s.surfaceDetail) && s.selfShadow == SelfShadow::HeightMarch);
}
// The horizon_directions the UI offers, every multiple of 4 in [kMinHorizonDirections,
// kMaxHorizonDirections].
inline constexpr int kHorizonDirectionChoices[] = {4, 8, 12, 16};

// `wanted` brought into the scene file's ranges: height_scale clamped to [0, kMaxHeightScale]
// (NaN: the value of `before`), each layer count to [1, kMaxParallaxLayers] and min <= max kept
// by moving the bound the user did not edit (`before` says which one was), refinement steps to
// [0, kMaxReliefRefinementSteps], horizon_directions to the nearest multiple of 4 in range.
HeightFieldSettings clampHeightField(HeightFieldSettings wanted, const HeightFieldSettings& before);

// What setHeightField did.
struct HeightFieldEdit {
  bool changed = false;          // the material changed: the revision was bumped, both renderers draw it again
  bool horizonMapStale = false;  // the material's horizon map no longer matches (rebuild: staleHorizonMap)
};
// Gives material `material` clampHeightField(wanted). Throws InputError and changes nothing
// where the scene file refuses: the material does not exist, or a method or self-shadowing that
// reads a height map on a material whose file gave none. (A height map switched off in the UI
// still counts: the material draws as normal_map until it is on again.)
HeightFieldEdit setHeightField(SceneDoc& doc, std::size_t material, const HeightFieldSettings& wanted);

// The horizon map (scene/horizon_map.h) is computed from the height map, its depth and the
// number of directions, so any of them changing makes it stale. It takes 0.1 s to 1 s on a
// 512 x 512 map: the app builds it on a worker when an edit ends (horizon_worker.h) and the
// material keeps drawing with the stale one (both renderers alike) until the new one is in.

// Whether the material draws with a horizon map: self_shadow horizon_map, a height-field method
// and a usable height map.
bool wantsHorizonMap(const Material& material);
// What a horizon map is built from.
struct HorizonRequest {
  std::size_t material = 0;
  std::shared_ptr<const Texture> heightMap;  // kept alive for the build
  float heightScale = 0.0f;
  int directions = 0;
};
// Whether material `material` wants a horizon map and has none built from its current height map,
// height_scale and horizon_directions.
bool horizonMapStale(const SceneDoc& doc, std::size_t material);
// The first material whose horizon map is stale, as a request to build it; nullopt when none is.
std::optional<HorizonRequest> staleHorizonMap(const SceneDoc& doc);
// Gives the material `map`, built for `request`, when the material still asks for exactly that
// (same height map object, depth and directions); then bumps the revision and returns true.
// False (nothing done) for a result an edit made meanwhile has outdated.
bool installHorizonMap(SceneDoc& doc, const HorizonRequest& request, std::shared_ptr<const HorizonMap> map);

}  // namespace twr::gui
