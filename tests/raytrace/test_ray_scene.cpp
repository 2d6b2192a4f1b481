// The ray tracer (raytrace/ray_scene.h): hits where the scene's triangles are, with the frame's
// triangle ids and barycentrics that rebuild the hit point; misses, ranges and a build without
// Embree that says what is missing.
#include "raytrace/ray_scene.h"

#include "scene/errors.h"
#include "scene/scene_file.h"
#include "tests/missing_dependency.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <string>

namespace twr {
namespace {

// An 8 x 8 floor at y = 0 and a unit cube standing on it at x = 2.
Scene floorAndCube() {
  return parseScene(R"({
    "camera": {"position": [0, 3, 6], "target": [0, 0, 0]},
    "nodes": [
      {"name": "floor", "mesh": {"type": "plane", "size": [8, 8]}},
      {"name": "cube", "translate": [2, 0.5, 0], "mesh": {"type": "cube", "size": 1}}
    ]})",
                    "floor_and_cube", ".");
}

// Corner k of global triangle `id`, in world space (the draw items' own transform).
glm::dvec3 cornerOf(const Scene& scene, std::uint32_t id, std::size_t k) {
  for (const DrawItem& item : flattenScene(scene)) {
    if (id < item.firstTriangleId || id >= item.firstTriangleId + item.mesh->triangleCount()) continue;
    const std::size_t t = id - item.firstTriangleId;
    const vec3 p = item.mesh->vertices[item.mesh->indices[3 * t + k]].posModel;
    return glm::dvec3(glm::dmat4(item.worldFromModel) * glm::dvec4(glm::dvec3(p), 1.0));
  }
  ADD_FAILURE() << "no triangle " << id;
  return glm::dvec3(0.0);
}

TEST(RayScene, HitsTheFloorAndTheCubeWithTheFramesIdsAndBarycentrics) {
  if (!rayTracerAvailable()) TWR_MISSING_DEPENDENCY("Embree") << rayTracerDescription();
  const Scene scene = floorAndCube();
  const RayScene rays(scene);
  const std::vector<DrawItem> items = flattenScene(scene);
  ASSERT_EQ(items.size(), 2u);
  EXPECT_EQ(rays.triangleCount(), countTriangles(scene));
  EXPECT_NEAR(rays.extent(), std::sqrt(8.0 * 8.0 + 1.0 + 8.0 * 8.0), 1e-5);  // bounds 8 x 1 x 8

  struct Case {
    glm::dvec3 origin, dir, point;
    bool onCube;
  };
  const std::array<Case, 4> cases{{
      {{-1.0, 5.0, 1.5}, {0.0, -1.0, 0.0}, {-1.0, 0.0, 1.5}, false},  // straight down onto the floor
      {{2.2, 5.0, 0.1}, {0.0, -1.0, 0.0}, {2.2, 1.0, 0.1}, true},     // onto the cube's top
      {{-3.0, 0.5, 0.2}, {1.0, 0.0, 0.0}, {1.5, 0.5, 0.2}, true},     // sideways into its -x face
      {{3.0, 2.0, 3.0}, glm::normalize(glm::dvec3(-1.0, -2.0, -3.0)), {13.0 / 6.0, 1.0 / 3.0, 0.5}, true},  // its +z face
  }};
  for (const Case& c : cases) {
    SCOPED_TRACE(c.point.x);
    const RayHit hit = rays.intersect(c.origin, c.dir, 0.0, 100.0);
    ASSERT_TRUE(hit.hit);
    const bool onCube = hit.triangleId >= items[1].firstTriangleId;
    EXPECT_EQ(onCube, c.onCube);
    const glm::dvec3 p = c.origin + c.dir * hit.t;
    EXPECT_NEAR(glm::length(p - c.point), 0.0, 1e-5);
    // The barycentrics rebuild the point from the triangle the id names.
    const glm::dvec3 q = cornerOf(scene, hit.triangleId, 0) * (1.0 - hit.u - hit.v) +
                         cornerOf(scene, hit.triangleId, 1) * hit.u + cornerOf(scene, hit.triangleId, 2) * hit.v;
    EXPECT_NEAR(glm::length(q - p), 0.0, 1e-5);
  }
}

TEST(RayScene, MissesAwayFromTheSceneAndOutsideItsRange) {
  if (!rayTracerAvailable()) TWR_MISSING_DEPENDENCY("Embree") << rayTracerDescription();
  const RayScene rays(floorAndCube());
  EXPECT_FALSE(rays.intersect({0.0, 5.0, 0.0}, {0.0, 1.0, 0.0}, 0.0, 100.0).hit);   // up, into the sky
  EXPECT_FALSE(rays.intersect({0.0, 5.0, 0.0}, {0.0, -1.0, 0.0}, 0.0, 4.9).hit);    // ends above the floor
  EXPECT_FALSE(rays.intersect({0.0, 5.0, 0.0}, {0.0, -1.0, 0.0}, 5.1, 100.0).hit);  // starts below it
  EXPECT_TRUE(rays.intersect({0.0, 5.0, 0.0}, {0.0, -1.0, 0.0}, 4.9, 5.1).hit);
  // Both faces: from under the floor, up through it.
  EXPECT_TRUE(rays.intersect({-1.0, -1.0, 1.0}, {0.0, 1.0, 0.0}, 0.0, 100.0).hit);
  EXPECT_EQ(RayScene(Scene{}).triangleCount(), 0u);
  EXPECT_FALSE(RayScene(Scene{}).intersect({0.0, 0.0, 0.0}, {0.0, -1.0, 0.0}, 0.0, 100.0).hit);
}

TEST(RayScene, ABuildWithoutEmbreeSaysWhatIsMissing) {
  if (rayTracerAvailable()) {
    EXPECT_NE(rayTracerDescription().find("Embree 3."), std::string::npos) << rayTracerDescription();
    return;
  }
  EXPECT_NE(rayTracerDescription().find("libembree-dev"), std::string::npos);
  try {
    RayScene rays(floorAndCube());
    FAIL() << "traced without a ray tracer";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("libembree-dev"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace twr
