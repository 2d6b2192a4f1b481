#include "scene/camera.h"

#include "scene/errors.h"

#include <cmath>

namespace twr {

namespace {
const vec3 kWorldUp{0.0f, 1.0f, 0.0f};
// |cross(Up, D)| below this (sine of the angle) means P - T is parallel to up.
constexpr float kMinSineToUp = 1e-6f;
}  // namespace

std::string validateCamera(const Camera& camera) {
  if (!(camera.near > 0.0f)) return "near must be > 0";
  if (!(camera.far > camera.near)) return "far must be > near";
  if (!(camera.fovDeg > 0.0f && camera.fovDeg < 180.0f)) return "fov_deg must be in (0, 180)";
  const vec3 toEye = camera.position - camera.target;
  const float length = glm::length(toEye);
  if (!(length > 0.0f) || !std::isfinite(length)) return "position and target must differ";
  if (glm::length(glm::cross(kWorldUp, toEye / length)) < kMinSineToUp) {
    return "position - target must not be parallel to the world up (0,1,0)";
  }
  return {};
}

mat4 viewFromWorld(const Camera& camera) {
  if (std::string error = validateCamera(camera); !error.empty()) throw InputError("camera: " + error);
  const vec3 d = glm::normalize(camera.position - camera.target);
  const vec3 r = glm::normalize(glm::cross(kWorldUp, d));
  const vec3 u = glm::cross(d, r);
  // Rows R, U, D (GLM is column-major: m[column][row]).
  mat4 rotation(1.0f);
  for (int i = 0; i < 3; ++i) {
    rotation[i][0] = r[i];
    rotation[i][1] = u[i];
    rotation[i][2] = d[i];
  }
  mat4 translation(1.0f);
  translation[3] = vec4(-camera.position, 1.0f);
  return rotation * translation;
}

mat4 clipFromView(const Camera& camera, float aspect) {
  if (std::string error = validateCamera(camera); !error.empty()) throw InputError("camera: " + error);
  if (!(aspect > 0.0f) || !std::isfinite(aspect)) throw InputError("camera: aspect must be > 0");
  const float f = 1.0f / std::tan(0.5f * degreesToRadians(camera.fovDeg));
  const float n = camera.near, fa = camera.far;
  mat4 m(0.0f);
  m[0][0] = f / aspect;
  m[1][1] = f;
  m[2][2] = (fa + n) / (n - fa);
  m[2][3] = -1.0f;
  m[3][2] = 2.0f * fa * n / (n - fa);
  return m;
}

}  // namespace twr
