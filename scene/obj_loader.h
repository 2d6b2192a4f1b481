// Wavefront OBJ through tinyobjloader: positions, normals, uvs; MTL Kd/Ks/Ka/Ns and the
// diffuse (map_Kd), normal (norm / map_Bump / bump) and specular (map_Ks) maps.
#pragma once

#include "scene/mesh.h"
#include "scene/scene.h"

#include <string>
#include <vector>

namespace twr {

struct ObjModel {
  // One mesh per material used in the file (a file without materials gives one mesh).
  std::vector<Mesh> meshes;
  std::vector<Material> materials;  // parallel to meshes; name "" where the OBJ has none
  std::vector<bool> hasMaterial;    // false where the OBJ gave no material for that part
};

// Throws InputError naming the file (and line when tinyobjloader reports one).
ObjModel loadObj(const std::string& path);

}  // namespace twr
