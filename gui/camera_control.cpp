#include "gui/camera_control.h"

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>

namespace twr::gui {
namespace {


float clampDistance(float distance) {
  if (!std::isfinite(distance)) return kMinOrbitDistance;
  return std::clamp(distance, kMinOrbitDistance, kMaxOrbitDistance);
}

}  // namespace

void orbitCamera(Camera& camera, float dxPoints, float dyPoints) {
  const vec3 offsetWorld = camera.position - camera.target;
  const float distance = clampDistance(glm::length(offsetWorld));
  const vec3 dirWorld = safeNormalize(offsetWorld, vec3(0.0f, 0.0f, 1.0f));
  // Yaw around +Y measured from +Z towards +X; pitch above the XZ plane.
  float yaw = std::atan2(dirWorld.x, dirWorld.z);
  float pitch = std::asin(std::clamp(dirWorld.y, -1.0f, 1.0f));
  yaw -= dxPoints * kOrbitRadiansPerPoint;
  pitch = std::clamp(pitch + dyPoints * kOrbitRadiansPerPoint, -kMaxPitchRadians, kMaxPitchRadians);
  const vec3 newDirWorld{std::cos(pitch) * std::sin(yaw), std::sin(pitch), std::cos(pitch) * std::cos(yaw)};
  camera.position = camera.target + distance * newDirWorld;
}

void panCamera(Camera& camera, float dxPoints, float dyPoints, float viewHeightPoints) {
  if (!(viewHeightPoints > 0.0f)) return;
  const vec3 offsetWorld = camera.position - camera.target;
  const float distance = clampDistance(glm::length(offsetWorld));
  const vec3 dWorld = safeNormalize(offsetWorld);
  const vec3 rWorld = safeNormalize(glm::cross(camera.up, dWorld), vec3(1.0f, 0.0f, 0.0f));
  const vec3 uWorld = glm::cross(dWorld, rWorld);
  // The view spans 2 * distance * tan(fov / 2) world units vertically at the target.
  const float worldPerPoint =
      2.0f * distance * std::tan(0.5f * degreesToRadians(camera.fovDeg)) / viewHeightPoints;
  const vec3 moveWorld = (-dxPoints * rWorld + dyPoints * uWorld) * worldPerPoint;
  camera.position += moveWorld;
  camera.target += moveWorld;
}

void zoomCamera(Camera& camera, float wheelSteps) {
  const vec3 offsetWorld = camera.position - camera.target;
  const vec3 dirWorld = safeNormalize(offsetWorld);
  const float distance = clampDistance(glm::length(offsetWorld) * std::pow(kZoomFactorPerWheelStep, wheelSteps));
  camera.position = camera.target + distance * dirWorld;
}

bool dragPointInViewPlane(const Camera& camera, vec3& pointWorld, float dxPoints, float dyPoints,
                          float viewHeightPoints) {
  if (!(viewHeightPoints > 0.0f)) return false;
  const vec3 dWorld = safeNormalize(camera.position - camera.target);
  const vec3 rWorld = safeNormalize(glm::cross(camera.up, dWorld), vec3(1.0f, 0.0f, 0.0f));
  const vec3 uWorld = glm::cross(dWorld, rWorld);
  // The camera looks along -D: the depth of the point in front of it.
  const float depth = glm::dot(pointWorld - camera.position, -dWorld);
  if (!(depth > camera.near)) return false;
  const float worldPerPoint = 2.0f * depth * std::tan(0.5f * degreesToRadians(camera.fovDeg)) / viewHeightPoints;
  pointWorld += (dxPoints * rWorld - dyPoints * uWorld) * worldPerPoint;
  return true;
}

}  // namespace twr::gui
