// The course's camera: position P, target T, up vector Up (the world's (0,1,0) unless a scene
// gives another: a captured cube map's faces look along +-Y, scene/environment_capture.h).
//   D = normalize(P - T), R = normalize(cross(Up, D)), U = cross(D, R)
//   viewFromWorld = [R; U; D] * translate(-P)
//   clipFromView  = perspective(fov, aspect, near, far), z mapped to [-1, 1]
#pragma once

#include "scene/conventions.h"

#include <string>

namespace twr {

struct Camera {
  vec3 position{0.0f, 1.0f, 4.0f};  // P, world units
  vec3 target{0.0f, 0.0f, 0.0f};    // T, world units
  vec3 up{0.0f, 1.0f, 0.0f};        // Up, any length > 0, not parallel to P - T
  float fovDeg = 60.0f;             // vertical field of view, degrees, in (0, 180) exclusive
  float near = 0.1f;                // world units, > 0
  float far = 100.0f;               // world units, > near
};

// Empty when the camera is usable, else what is wrong (no file context; callers add it).
std::string validateCamera(const Camera& camera);

// Both throw InputError for an invalid camera.
mat4 viewFromWorld(const Camera& camera);
mat4 clipFromView(const Camera& camera, float aspect);
// The inverse of a clipFromWorld, computed in double and rounded once (the deferred lighting
// pass's position from depth on both renderers: one matrix, the same floats).
mat4 worldFromClipOf(const mat4& clipFromWorld);

}  // namespace twr
