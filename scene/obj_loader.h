// Wavefront OBJ through tinyobjloader: positions, normals, uvs; MTL colours and maps.
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
  // MTL keywords and texture options read and not used, a height map kept but not drawn, an
  // MTL not read, skin-weight (vw) lines skipped: one line each, "file:line: ...".
  std::vector<std::string> warnings;
};

// What to read besides the geometry.
struct ObjReadOptions {
  bool readMtl = true;   // false: mtllib lines are skipped; every face has no material
  bool loadMaps = true;  // false: materials keep their colours, no map file is opened (and a
                         // missing MTL is a warning): the scene gives the node its own material
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
// MTL: Ka, Kd, Ks, Ns, map_Kd, map_Ks, norm (normal map), map_Bump / bump (a normal map, or a
// height map when its texels are grey), disp (height map); texture options -s and -o (the
// map's uv scale and offset), -clamp (clamp_to_edge), -bm (normal strength or height scale).
// Anything else that changes the picture is named in `warnings`.
ObjModel loadObj(const std::string& path, const ObjLimits& limits = {}, const ObjReadOptions& read = {});

}  // namespace twr
