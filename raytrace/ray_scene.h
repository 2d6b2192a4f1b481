// The scene's own triangles under Intel Embree (Debian's libembree-dev): the ray tracer the
// ground truths trace against (docs/ssr.md, "Against a ray tracer"). Embree is optional: a
// build without it still has this interface, rayTracerAvailable() says false and RayScene's
// constructor throws an InputError that says how to get it.
#pragma once

#include "scene/scene.h"

#include <glm/glm.hpp>

#include <cstdint>
#include <memory>
#include <string>

namespace twr {

// Whether this build traces rays (Embree was found when it was configured).
bool rayTracerAvailable();
// "Embree 3.13.5", or what is missing and how to get it.
std::string rayTracerDescription();

struct RayHit {
  bool hit = false;
  std::uint32_t triangleId = 0;  // the frame's global id (DrawItem::firstTriangleId + i)
  double t = 0.0;                // along the ray's direction (world units for a unit direction)
  // Barycentrics of the triangle's second and third corners (index order): the point is
  // (1 - u - v) p0 + u p1 + v p2.
  double u = 0.0, v = 0.0;
};

class RayScene {
 public:
  // Every triangle of every draw item in world space (worldFromModel widened to double, then
  // stored as Embree's floats). Throws InputError when the build has no Embree.
  explicit RayScene(const Scene& scene);
  ~RayScene();
  RayScene(const RayScene&) = delete;
  RayScene& operator=(const RayScene&) = delete;

  // The nearest triangle (either face) the ray meets with t in [tMin, tMax]. Safe to call from
  // several threads at once.
  RayHit intersect(const glm::dvec3& origin, const glm::dvec3& dir, double tMin, double tMax) const;
  // The length of the scene bounds' diagonal (world units; 0 for an empty scene): the scale a
  // ray's start offset is taken from.
  double extent() const { return extent_; }
  std::size_t triangleCount() const { return triangles_; }

 private:
  struct Device;
  std::unique_ptr<Device> device_;
  double extent_ = 0.0;
  std::size_t triangles_ = 0;
};

}  // namespace twr
