// The scene's triangles in world space, in double, under a bounding-volume hierarchy: the
// ground truth's geometry for visibility (docs/shadows.md, "Against a ray tracer"). Triangle k
// is the frame's global triangle id k (flattenScene order, DrawItem::firstTriangleId + i), so a
// pixel's id names the triangle it shows.
#pragma once

#include "scene/scene.h"

#include <glm/glm.hpp>

#include <array>
#include <cstdint>
#include <vector>

namespace twr {

// An id no triangle has (occluded's `ignore` when nothing is to be skipped).
inline constexpr std::uint32_t kNoTriangleId = 0xFFFFFFFFu;

class TriangleBvh {
 public:
  // Every triangle of every draw item, moved to world space in double (worldFromModel widened).
  explicit TriangleBvh(const Scene& scene);

  std::size_t size() const { return triangles_.size(); }
  const std::array<glm::dvec3, 3>& triangle(std::uint32_t id) const { return triangles_[id]; }

  // Whether any triangle but `ignore` crosses the segment from + t dir, t in (tMin, tMax)
  // (exclusive). Both faces count: a shadow is cast by a triangle's back as well.
  bool occluded(const glm::dvec3& from, const glm::dvec3& dir, double tMin, double tMax, std::uint32_t ignore) const;

 private:
  struct Node {
    glm::dvec3 lo{0.0}, hi{0.0};
    std::uint32_t first = 0, count = 0;  // a leaf: its triangles in order_[first, first + count)
    std::uint32_t left = 0, right = 0;   // an inner node (count 0): its children
  };
  std::uint32_t build(std::uint32_t first, std::uint32_t count);

  std::vector<std::array<glm::dvec3, 3>> triangles_;
  std::vector<std::uint32_t> order_;  // triangle ids, grouped by leaf
  std::vector<Node> nodes_;           // nodes_[0] is the root (when there is a triangle)
};

// Where a ray from `origin` along `dir` meets the plane of triangle `t`, as a parameter along
// dir (NaN when the ray runs parallel to it).
double rayPlaneParameter(const glm::dvec3& origin, const glm::dvec3& dir, const std::array<glm::dvec3, 3>& t);

}  // namespace twr
