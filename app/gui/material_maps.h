// Editing a material's maps from the UI (issue 15, item 6): switching a map off and on, and
// changing the options a scene file gives a map (flip_v, wrap, srgb, green). No ImGui here, so
// tests/gui/test_material_maps.cpp drives it without a window.
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

#include "app/gui/scene_doc.h"
#include "scene/texture.h"

#include <cstddef>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace twr::gui {

// The maps the Materials section lists, in MaterialMaps order.
enum class MapSlot { Diffuse, Normal, Specular };
inline constexpr MapSlot kMapSlots[] = {MapSlot::Diffuse, MapSlot::Normal, MapSlot::Specular};

// "diffuse map", "normal map", "specular map".
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
// on a normal map), each a line naming the file. Throws InputError (the material or map does
// not exist, the file is gone or no longer reads, the scene's texel budget,
// kMaxSceneTextureBytes, would be exceeded) and then leaves the document as it was.
std::vector<std::string> setMapOptions(SceneDoc& doc, std::size_t material, MapSlot slot, const TextureOptions& options);

// Texel bytes of every distinct texture the document holds (loaded maps, drawn maps, height
// maps), each counted once: what the budget of setMapOptions is measured against.
std::uintmax_t documentTextureBytes(const SceneDoc& doc);

}  // namespace twr::gui
