// Wavefront OBJ through tinyobjloader: positions, normals, uvs; MTL Kd/Ks/Ka/Ns and the
// diffuse (map_Kd), normal (norm / map_Bump / bump) and specular (map_Ks) maps.
#pragma once

#include "scene/mesh.h"
#include "scene/scene.h"

#include <cstdint>
#include <string>
#include <vector>

namespace twr {

struct ObjModel {
  // One mesh per material used in the file (a file without materials gives one mesh).
  std::vector<Mesh> meshes;
  std::vector<Material> materials;  // parallel to meshes; name "" where the OBJ has none
  std::vector<bool> hasMaterial;    // false where the OBJ gave no material for that part
};

// Largest OBJ file and MTL file read (inclusive, bytes): 256 MiB of OBJ text is about 5
// million triangles; loading peaks at several times the file size.
inline constexpr std::uintmax_t kMaxObjFileBytes = 256ull * 1024 * 1024;
inline constexpr std::uintmax_t kMaxMtlFileBytes = 16ull * 1024 * 1024;

// What one OBJ may add to a scene (inclusive bounds); the scene loader passes what is left.
struct ObjLimits {
  std::size_t maxTriangles = kMaxSceneTriangles;      // counted from the 'f' lines before building
  std::uintmax_t maxTextureBytes = kMaxSceneTextureBytes;  // texels of the MTL's maps, each file once
};

// Throws InputError naming the file (and line when tinyobjloader reports one). Files may be
// UTF-8 (with or without a byte-order mark) or UTF-16 (with a byte-order mark, or starting
// with an ASCII character), with any line ends; material names may contain spaces; texture
// paths may use '\\'.
ObjModel loadObj(const std::string& path, const ObjLimits& limits = {});

}  // namespace twr
