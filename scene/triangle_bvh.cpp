#include "scene/triangle_bvh.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace twr {

namespace {

// Most triangles in a leaf.
constexpr std::uint32_t kLeafTriangles = 4;
// Deepest traversal stack: a median split halves the triangles per level, so 64 levels hold
// far more triangles than a scene may have.
constexpr int kMaxStack = 64;

// Moller-Trumbore, both faces: the segment parameter t in (tMin, tMax) where the ray crosses
// the triangle, or false.
bool crosses(const glm::dvec3& from, const glm::dvec3& dir, double tMin, double tMax,
             const std::array<glm::dvec3, 3>& v) {
  const glm::dvec3 e1 = v[1] - v[0], e2 = v[2] - v[0];
  const glm::dvec3 p = glm::cross(dir, e2);
  const double det = glm::dot(e1, p);
  if (det == 0.0 || !std::isfinite(det)) return false;  // parallel or degenerate
  const double inv = 1.0 / det;
  const glm::dvec3 s = from - v[0];
  const double u = glm::dot(s, p) * inv;
  if (u < 0.0 || u > 1.0) return false;
  const glm::dvec3 q = glm::cross(s, e1);
  const double w = glm::dot(dir, q) * inv;
  if (w < 0.0 || u + w > 1.0) return false;
  const double t = glm::dot(e2, q) * inv;
  return t > tMin && t < tMax;
}

// The slab test: whether the ray enters the box within (tMin, tMax).
bool hitsBox(const glm::dvec3& from, const glm::dvec3& invDir, double tMin, double tMax, const glm::dvec3& lo,
             const glm::dvec3& hi) {
  for (int a = 0; a < 3; ++a) {
    double t0 = (lo[a] - from[a]) * invDir[a], t1 = (hi[a] - from[a]) * invDir[a];
    if (t0 > t1) std::swap(t0, t1);
    if (std::isnan(t0) || std::isnan(t1)) continue;  // 0 * inf: the ray lies in the slab's plane
    tMin = std::max(tMin, t0);
    tMax = std::min(tMax, t1);
    if (tMin > tMax) return false;
  }
  return true;
}

}  // namespace

TriangleBvh::TriangleBvh(const Scene& scene) {
  for (const DrawItem& item : flattenScene(scene)) {
    const glm::dmat4 worldFromModel(item.worldFromModel);
    const Mesh& mesh = *item.mesh;
    triangles_.resize(std::max<std::size_t>(triangles_.size(), item.firstTriangleId + mesh.triangleCount()));
    for (std::size_t t = 0; t < mesh.triangleCount(); ++t) {
      std::array<glm::dvec3, 3>& tri = triangles_[item.firstTriangleId + t];
      for (std::size_t k = 0; k < 3; ++k) {
        const std::uint32_t index = mesh.indices[3 * t + k];
        const glm::dvec3 p = index < mesh.vertices.size() ? glm::dvec3(mesh.vertices[index].posModel) : glm::dvec3(0.0);
        tri[k] = glm::dvec3(worldFromModel * glm::dvec4(p, 1.0));
      }
    }
  }
  order_.resize(triangles_.size());
  for (std::uint32_t i = 0; i < order_.size(); ++i) order_[i] = i;
  if (!triangles_.empty()) {
    nodes_.reserve(2 * triangles_.size() / kLeafTriangles + 2);
    build(0, static_cast<std::uint32_t>(triangles_.size()));
  }
}

std::uint32_t TriangleBvh::build(std::uint32_t first, std::uint32_t count) {
  const std::uint32_t index = static_cast<std::uint32_t>(nodes_.size());
  nodes_.emplace_back();
  glm::dvec3 lo(std::numeric_limits<double>::max()), hi(std::numeric_limits<double>::lowest());
  glm::dvec3 centreLo = lo, centreHi = hi;
  for (std::uint32_t i = first; i < first + count; ++i) {
    const auto& t = triangles_[order_[i]];
    for (const glm::dvec3& v : t) {
      lo = glm::min(lo, v);
      hi = glm::max(hi, v);
    }
    const glm::dvec3 c = (t[0] + t[1] + t[2]) / 3.0;
    centreLo = glm::min(centreLo, c);
    centreHi = glm::max(centreHi, c);
  }
  nodes_[index].lo = lo;
  nodes_[index].hi = hi;
  const glm::dvec3 extent = centreHi - centreLo;
  if (count <= kLeafTriangles || !(std::max(extent.x, std::max(extent.y, extent.z)) > 0.0)) {
    nodes_[index].first = first;
    nodes_[index].count = count;
    return index;
  }
  // The median along the centres' longest axis.
  const int axis = extent.x >= extent.y && extent.x >= extent.z ? 0 : (extent.y >= extent.z ? 1 : 2);
  const std::uint32_t middle = first + count / 2;
  std::nth_element(order_.begin() + first, order_.begin() + middle, order_.begin() + first + count,
                   [&](std::uint32_t a, std::uint32_t b) {
                     const auto& ta = triangles_[a];
                     const auto& tb = triangles_[b];
                     return ta[0][axis] + ta[1][axis] + ta[2][axis] < tb[0][axis] + tb[1][axis] + tb[2][axis];
                   });
  const std::uint32_t left = build(first, middle - first);
  const std::uint32_t right = build(middle, first + count - middle);
  nodes_[index].left = left;
  nodes_[index].right = right;
  return index;
}

bool TriangleBvh::occluded(const glm::dvec3& from, const glm::dvec3& dir, double tMin, double tMax,
                           std::uint32_t ignore) const {
  if (nodes_.empty()) return false;
  const glm::dvec3 invDir = 1.0 / dir;
  std::uint32_t stack[kMaxStack];
  int top = 0;
  stack[top++] = 0;
  while (top > 0) {
    const Node& node = nodes_[stack[--top]];
    if (!hitsBox(from, invDir, tMin, tMax, node.lo, node.hi)) continue;
    if (node.count > 0) {
      for (std::uint32_t i = node.first; i < node.first + node.count; ++i) {
        if (order_[i] != ignore && crosses(from, dir, tMin, tMax, triangles_[order_[i]])) return true;
      }
    } else if (top + 2 <= kMaxStack) {
      stack[top++] = node.left;
      stack[top++] = node.right;
    }
  }
  return false;
}

double rayPlaneParameter(const glm::dvec3& origin, const glm::dvec3& dir, const std::array<glm::dvec3, 3>& t) {
  const glm::dvec3 n = glm::cross(t[1] - t[0], t[2] - t[0]);
  const double denominator = glm::dot(n, dir);
  if (denominator == 0.0) return std::numeric_limits<double>::quiet_NaN();
  return glm::dot(n, t[0] - origin) / denominator;
}

}  // namespace twr
