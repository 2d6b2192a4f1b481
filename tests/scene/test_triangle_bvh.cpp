// The ground truth's triangles (scene/triangle_bvh.h): ids as the frame numbers them, and
// segment queries against a brute-force loop over every triangle on random segments.
#include "scene/triangle_bvh.h"

#include "scene/scene_file.h"

#include <gtest/gtest.h>

#include <random>

namespace twr {
namespace {

Scene boxesOnAFloor() {
  return parseScene(R"({"nodes": [
      {"name": "floor", "mesh": {"type": "plane", "size": [6, 6]}},
      {"name": "box", "translate": [0, 0.5, 0], "rotate_deg": [0, 30, 0], "mesh": {"type": "cube", "size": 1}},
      {"name": "ball", "translate": [1.5, 0.6, -1], "mesh": {"type": "sphere", "radius": 0.5}}]})",
                    "inline.json", ".");
}

TEST(TriangleBvh, HoldsEveryTriangleUnderItsFrameId) {
  const Scene scene = boxesOnAFloor();
  const TriangleBvh bvh(scene);
  EXPECT_EQ(bvh.size(), countTriangles(scene));
  // The box is the second item: its first triangle's corners lie on its faces (|x|, |z| <= 0.71
  // around its centre, y in [0, 1]).
  const std::vector<DrawItem> items = flattenScene(scene);
  const auto& t = bvh.triangle(items[1].firstTriangleId);
  for (const glm::dvec3& v : t) {
    EXPECT_GE(v.y, -1e-9);
    EXPECT_LE(v.y, 1.0 + 1e-9);
    EXPECT_LE(std::hypot(v.x, v.z), std::sqrt(0.5) + 1e-6);
  }
}

TEST(TriangleBvh, AgreesWithEveryTriangleTestedInTurn) {
  const Scene scene = boxesOnAFloor();
  const TriangleBvh bvh(scene);
  std::mt19937 random(7);
  std::uniform_real_distribution<double> coord(-3.0, 3.0), height(-0.5, 3.0);
  int hits = 0;
  for (int i = 0; i < 2000; ++i) {
    const glm::dvec3 a(coord(random), height(random), coord(random)), b(coord(random), height(random), coord(random));
    const glm::dvec3 dir = b - a;
    bool brute = false;
    for (std::uint32_t k = 0; k < bvh.size() && !brute; ++k) {
      const auto& t = bvh.triangle(k);
      // Both faces, t in (0, 1): the segment a..b.
      const glm::dvec3 e1 = t[1] - t[0], e2 = t[2] - t[0], p = glm::cross(dir, e2);
      const double det = glm::dot(e1, p);
      if (det == 0.0) continue;
      const glm::dvec3 s = a - t[0];
      const double u = glm::dot(s, p) / det;
      const glm::dvec3 q = glm::cross(s, e1);
      const double w = glm::dot(dir, q) / det, tt = glm::dot(e2, q) / det;
      brute = u >= 0.0 && w >= 0.0 && u + w <= 1.0 && tt > 0.0 && tt < 1.0;
    }
    hits += brute;
    EXPECT_EQ(bvh.occluded(a, dir, 0.0, 1.0, kNoTriangleId), brute) << i;
  }
  EXPECT_GT(hits, 200);  // both answers are exercised
  EXPECT_LT(hits, 1800);
}

TEST(TriangleBvh, IgnoresTheTriangleAskedAndAnEmptyScene) {
  const Scene scene = parseScene(R"({"nodes": [{"name": "floor", "mesh": {"type": "plane", "size": [2, 2]}}]})",
                                 "inline.json", ".");
  const TriangleBvh bvh(scene);
  ASSERT_EQ(bvh.size(), 2u);
  const glm::dvec3 from(0.2, 1.0, 0.3), down(0.0, -2.0, 0.0);
  EXPECT_TRUE(bvh.occluded(from, down, 0.0, 1.0, kNoTriangleId));
  const bool first = bvh.occluded(from, down, 0.0, 1.0, 0), second = bvh.occluded(from, down, 0.0, 1.0, 1);
  EXPECT_NE(first, second);  // the point lies over one of the two triangles
  EXPECT_FALSE(bvh.occluded(from, down, 0.0, 0.4, kNoTriangleId));  // the segment stops above the floor
  EXPECT_FALSE(TriangleBvh(Scene{}).occluded(from, down, 0.0, 1.0, kNoTriangleId));
  EXPECT_NEAR(rayPlaneParameter(from, down, bvh.triangle(0)), 0.5, 1e-12);
}

}  // namespace
}  // namespace twr
