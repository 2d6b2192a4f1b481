#include "scene/camera.h"

#include "scene/errors.h"

#include <glm/matrix.hpp>

#include <cmath>

namespace twr {

namespace {
// |cross(Up, D)| below this (sine of the angle) means P - T is parallel to up.
constexpr float kMinSineToUp = 1e-6f;
}  // namespace

std::string validateCamera(const Camera& camera) {
  if (!(camera.near > 0.0f)) return "near must be > 0";
  if (!(camera.far > camera.near)) return "far must be > near";
  if (!(camera.fovDeg > 0.0f && camera.fovDeg < 180.0f)) return "fov_deg must be in (0, 180)";
  // In double: a float length squares the coordinates, which overflows from about 1.8e19.
  const glm::dvec3 toEye = glm::dvec3(camera.position) - glm::dvec3(camera.target);
  const double length = glm::length(toEye);
  if (!(length > 0.0) || !std::isfinite(length)) return "position and target must differ";
  const glm::dvec3 up(camera.up);
  const double upLength = glm::length(up);
  if (!(upLength > 0.0) || !std::isfinite(upLength)) return "up must be a vector of finite, non-zero length";
  if (glm::length(glm::cross(up / upLength, toEye / length)) < kMinSineToUp) {
    const bool worldUp = camera.up == vec3(0.0f, 1.0f, 0.0f);
    return worldUp ? "position - target must not be parallel to the world up (0,1,0) (give the camera an \"up\")"
                   : "position - target must not be parallel to up";
  }
  return {};
}

mat4 viewFromWorld(const Camera& camera) {
  if (std::string error = validateCamera(camera); !error.empty()) throw InputError("camera: " + error);
  // D and R normalised in double, rounded once: float's squares overflow for a camera more
  // than about 1.8e19 from its target.
  const glm::dvec3 dWide = glm::normalize(glm::dvec3(camera.position) - glm::dvec3(camera.target));
  const vec3 d(dWide);
  const vec3 r(glm::normalize(glm::cross(glm::dvec3(camera.up), glm::dvec3(d))));
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
  // The depth terms in double, rounded once: in float, 2 * far * near overflows for a far
  // plane near float's range (far 3e38, or a scene in units of 1e20) although the term itself,
  // about -2 near, fits. projectionProblem (scene/projection_checks.h) refuses what still
  // does not fit.
  const double n = camera.near, fa = camera.far;
  mat4 m(0.0f);
  m[0][0] = f / aspect;
  m[1][1] = f;
  m[2][2] = static_cast<float>((fa + n) / (n - fa));
  m[2][3] = -1.0f;
  m[3][2] = static_cast<float>(2.0 * fa * n / (n - fa));
  return m;
}

mat4 worldFromClipOf(const mat4& clipFromWorld) { return mat4(glm::inverse(glm::dmat4(clipFromWorld))); }

}  // namespace twr
