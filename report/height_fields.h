// The scenes of the report's height-field section (docs/report.md, "Height fields"): a plane
// whose material carries a height map, drawn by each surface_detail method, and the same view
// of the true displaced surface (makeHeightfield) that the methods are measured against.
//
// The view: a 2 x 2 plane (uv 0..1 across, one copy of the texture) turned 30 degrees about its
// normal, so no wall of the height field lines up with the view, then tilted so the camera,
// fixed on +Z looking at the plane's centre, sees it at `angleDeg` from its normal. The point
// light is fixed to the plane (it turns and tilts with it), so every angle is lit alike.
#pragma once

#include "scene/scene.h"

#include <memory>
#include <string>

namespace twr::report {

// Depth of both height fields, texture-space units (Material::heightScale's default).
inline constexpr float kHeightFieldScale = 0.05f;

// A height field as the section uses it: its diffuse map, its height map, and the normal map
// of the same surface at kHeightFieldScale (normalMapFromHeight), so a method that finds the
// right uv also lights like the displaced mesh.
struct HeightFieldAsset {
  std::string name;  // "bricks", "blocks"
  std::shared_ptr<const Texture> diffuse, height, normal;
};

// Loads textures/<name>_diffuse.png and textures/<name>_height.png under `assetsDir`.
// Throws InputError.
HeightFieldAsset loadHeightFieldAsset(const std::string& assetsDir, const std::string& name);

// What a plane point draws: a method and, for the marching ones, its parallax_layers.
struct HeightFieldMethod {
  SurfaceDetail method = SurfaceDetail::NormalMap;
  ivec2 layers{8, 32};  // read only by steep_parallax, relief and parallax_occlusion
};

// "parallax", "parallax_occlusion 8-32": the setting's name in the report.
std::string methodSetting(const HeightFieldMethod& m);

// The view in words, from the constants that build it: "a 2 x 2 plane ... seen from 2.4 units".
std::string heightFieldViewText();

// The plane with the parallax material: diffuse, height and normal maps, diffuse only (ks 0:
// bump_emboss draws no specular, so every method is measured on the same terms), no
// self-shadowing (the rasterised mesh casts none), trilinear filtering.
Scene heightFieldPlaneScene(const HeightFieldAsset& asset, int angleDeg, const HeightFieldMethod& method);

// The reference view: the plane replaced by makeHeightfield of the same size, uv_scale, height
// map and kHeightFieldScale, one vertex per texel; its material is the plane's without the
// height and normal maps (surface_detail normal_map with no normal map), so the mesh's own
// normals light it and nothing shifts its uv a second time. `mesh` is built once per asset
// (heightFieldMesh) and copied in.
Mesh heightFieldMesh(const HeightFieldAsset& asset);
Scene heightFieldMeshScene(const HeightFieldAsset& asset, const Mesh& mesh, int angleDeg);

}  // namespace twr::report
