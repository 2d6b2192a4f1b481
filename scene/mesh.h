// Indexed triangle meshes and the descriptions they are built from.
#pragma once

#include "scene/conventions.h"

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace twr {

struct Texture;  // scene/texture.h

struct Vertex {
  vec3 posModel{0.0f};
  vec3 nModel{0.0f, 1.0f, 0.0f};
  // xyz: tangent along +u; w: handedness sign (+1 or -1), bitangent = w * cross(N, T).
  vec4 tangentModel{1.0f, 0.0f, 0.0f, 1.0f};
  vec2 uv{0.0f};
};

struct Mesh {
  std::vector<Vertex> vertices;
  std::vector<std::uint32_t> indices;  // three per triangle, counter-clockwise = front

  std::size_t triangleCount() const { return indices.size() / 3; }
};

enum class MeshType { Cube, Sphere, Plane, Cylinder, Torus, Obj, Triangles, Heightfield };

// What a node's mesh is made from. Kept beside the built Mesh so the GUI can edit the
// parameters and rebuild live. Units: world units; counts are segment counts.
struct MeshDesc {
  MeshType type = MeshType::Cube;
  float size = 1.0f;                // cube: edge length
  float radius = 1.0f;              // sphere, cylinder
  int stacks = 16, slices = 32;     // sphere: along psi, along phi; cylinder uses slices
  vec2 planeSize{1.0f, 1.0f};       // plane, heightfield: width (x) and depth (z)
  float uvScale = 1.0f;             // plane, heightfield: uv repeats across the plane
  float height = 1.0f;              // cylinder
  float major = 1.0f, minor = 0.25f;  // torus radii
  int rings = 32, sides = 16;       // torus segments around the major / minor circle
  std::string path;                 // obj: resolved path
  int objPart = -1;                 // obj: which part (one per material) to build; -1 merges all
  bool objMtl = true;               // obj: read the MTL files its mtllib lines name
  std::vector<vec3> positions;      // triangles: three per triangle
  std::vector<vec2> uvs;            // triangles: optional, one per position
  std::vector<vec3> normals;        // triangles: optional, one per position
  // heightfield: the plane above displaced by its height map (makeHeightfield). The scene
  // file fills the map and depth from the mesh's keys or else the node's material.
  std::shared_ptr<const Texture> heightMap;
  float heightScale = 0.05f;        // relief depth in texture-space units (Material's kDefaultHeightScale)
  ivec2 gridSegments{0, 0};         // along x (u) and z (v); (0, 0): defaultHeightfieldSegments
};

// Largest segment count any primitive accepts (inclusive), and largest triangle count a
// scene may hold (inclusive), so a typo cannot ask the kernel for 100 GB.
inline constexpr int kMaxSegments = 4096;
inline constexpr std::size_t kMaxSceneTriangles = 20'000'000;

}  // namespace twr
