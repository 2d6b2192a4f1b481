// Small scenes built in code for the GL tests, and pixel helpers (RenderOutput rows are
// top row first; x to the right).
#pragma once

#include "scene/primitives.h"
#include "scene/renderer.h"
#include "scene/scene.h"

#include <cstdint>
#include <vector>

namespace twr::gltest {

inline constexpr int kSide = 64;  // test image side, pixels

// Camera at the origin looking down -Z, 90 degree vertical fov, near 1, far 10: at view
// depth z the visible square is [-|z|, |z|]^2.
inline Camera frontCamera() {
  Camera camera;
  camera.position = vec3(0.0f);
  camera.target = vec3(0.0f, 0.0f, -1.0f);
  camera.fovDeg = 90.0f;
  camera.near = 1.0f;
  camera.far = 10.0f;
  return camera;
}

inline Scene emptyScene() {
  Scene scene;
  scene.output.width = kSide;
  scene.output.height = kSide;
  scene.output.background = vec4(0.2f, 0.4f, 0.6f, 1.0f);
  scene.camera = frontCamera();
  scene.lights.push_back(Light{vec3(0.0f, 0.0f, 0.0f), vec3(1.0f), vec3(1.0f), vec3(1.0f, 0.0f, 0.0f),
                               LightType::Point, vec3(0.0f, -1.0f, 0.0f), std::nullopt, std::nullopt});
  return scene;
}

inline int addNode(Scene& scene, Mesh mesh, const std::string& name, int materialIndex = -1) {
  scene.meshes.push_back(std::move(mesh));
  scene.meshDescs.push_back(MeshDesc{});
  Node node;
  node.name = name;
  node.meshIndex = static_cast<int>(scene.meshes.size()) - 1;
  node.materialIndex = materialIndex;
  scene.nodes.push_back(node);
  return node.meshIndex;
}

// An axis-aligned quad at view depth z (z < 0) spanning [x0, x1] x [y0, y1], facing +Z
// (counter-clockwise seen from the camera), uv (0,0) at (x0, y0) and (1,1) at (x1, y1).
inline Mesh quadAt(float z, float x0, float y0, float x1, float y1) {
  return makeTriangles({{x0, y0, z}, {x1, y0, z}, {x1, y1, z}, {x0, y0, z}, {x1, y1, z}, {x0, y1, z}},
                       {{0, 0}, {1, 0}, {1, 1}, {0, 0}, {1, 1}, {0, 1}}, {});
}

inline std::size_t index(const RenderOutput& out, int x, int y) {
  return static_cast<std::size_t>(y) * static_cast<std::size_t>(out.width) + static_cast<std::size_t>(x);
}
inline const std::uint8_t* pixel(const RenderOutput& out, int x, int y) { return &out.rgba[index(out, x, y) * 4]; }
// A triangle covers (x, y): its id (coveredAt); a lean frame, without ids, says it in alpha only
// when its scene's background alpha is 0.
inline bool covered(const RenderOutput& out, int x, int y) { return coveredAt(out, index(out, x, y)); }

inline std::size_t coveredCount(const RenderOutput& out) {
  std::size_t count = 0;
  for (int y = 0; y < out.height; ++y)
    for (int x = 0; x < out.width; ++x) count += covered(out, x, y) ? 1 : 0;
  return count;
}

}  // namespace twr::gltest
