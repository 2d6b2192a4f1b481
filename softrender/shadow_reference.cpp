#include "softrender/shadow_reference.h"

#include "scene/camera.h"
#include "scene/errors.h"
#include "softrender/shade.h"

#include <cmath>
#include <limits>

namespace twr {

namespace {

// A shadow ray starts this far along itself (world units per unit of the point's distance from
// the origin, plus one): past the rounding of the point on its own plane, short of any real
// occluder. Its own triangle is skipped by id as well.
constexpr double kShadowRayStart = 1e-9;
// A directional light's shadow ray reaches this far (world units): beyond any scene.
constexpr double kInfiniteDistance = 1e30;

}  // namespace

ShadowVisibility measureShadowVisibility(const Scene& scene, std::size_t lightIndex, const RenderOutput& frame,
                                         const TriangleBvh& bvh) {
  if (lightIndex >= scene.lights.size() || lightIndex >= frame.shadowMaps.size() || !frame.shadowMaps[lightIndex] ||
      frame.shadowMaps[lightIndex]->depth.empty()) {
    throw InputError("shadow reference: light " + std::to_string(lightIndex) + " has no shadow map in the frame");
  }
  const Light& light = scene.lights[lightIndex];
  const ShadowUniformT<double> uniform = makeShadowUniform<double>(frame.shadowMaps[lightIndex].get());
  const int width = frame.width, height = frame.height;
  const glm::dmat4 clipFromWorld = glm::dmat4(clipFromView(scene.camera, static_cast<float>(width) / static_cast<float>(height))) *
                                   glm::dmat4(viewFromWorld(scene.camera));
  const glm::dmat4 worldFromClip = glm::inverse(clipFromWorld);
  const glm::dvec3 eye(scene.camera.position);
  const bool directional = light.type == LightType::Directional;
  const glm::dvec3 toDirectional = -glm::normalize(glm::dvec3(light.directionWorld));

  ShadowVisibility v;
  v.width = width;
  v.height = height;
  const std::size_t pixels = static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
  v.traced.assign(pixels, std::numeric_limits<double>::quiet_NaN());
  v.map = v.traced;
  double sum = 0.0;
  for (int yTop = 0; yTop < height; ++yTop) {
    for (int x = 0; x < width; ++x) {
      const std::size_t i = static_cast<std::size_t>(yTop) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x);
      if (frame.triangleId.empty() || frame.triangleId[i] == kNoTriangle || frame.triangleId[i] >= bvh.size()) continue;
      const std::uint32_t id = frame.triangleId[i];
      // The ray through the pixel centre (GL window y counts from the bottom).
      const double ndcX = 2.0 * (x + 0.5) / width - 1.0;
      const double ndcY = 2.0 * ((height - 1 - yTop) + 0.5) / height - 1.0;
      const glm::dvec4 farPoint = worldFromClip * glm::dvec4(ndcX, ndcY, 1.0, 1.0);
      const glm::dvec3 dir = glm::dvec3(farPoint) / farPoint.w - eye;
      const auto& t = bvh.triangle(id);
      const double along = rayPlaneParameter(eye, dir, t);
      if (!std::isfinite(along)) continue;
      const glm::dvec3 p = eye + along * dir;
      glm::dvec3 n = glm::cross(t[1] - t[0], t[2] - t[0]);
      const double nLength = glm::length(n);
      if (!(nLength > 0.0)) continue;
      n /= nLength;
      if (glm::dot(n, dir) > 0.0) n = -n;  // the face the camera sees
      const glm::dvec3 toLight = directional ? toDirectional : glm::dvec3(light.posWorld) - p;
      const double distance = directional ? kInfiniteDistance : glm::length(toLight);
      if (!(distance > 0.0)) continue;
      const glm::dvec3 l = directional ? toLight : toLight / distance;
      if (!(glm::dot(n, l) > 0.0)) continue;  // turned away: unlit either way
      const double start = kShadowRayStart * (1.0 + glm::length(p));
      const double traced = bvh.occluded(p, l, start, distance, id) ? 0.0 : 1.0;
      const double map = lanes::shadowTest<double>(uniform, p, n, l).visibility;
      v.traced[i] = traced;
      v.map[i] = map;
      ++v.measured;
      if (traced == 0.0) ++v.tracedShadowed;
      const double error = std::fabs(map - traced);
      sum += error;
      if (error > 0.5) ++v.wrong;
      if (map > 0.0 && map < 1.0) ++v.partial;
    }
  }
  v.meanAbsError = v.measured ? sum / static_cast<double>(v.measured) : 0.0;
  return v;
}

}  // namespace twr
