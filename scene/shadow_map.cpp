#include "scene/shadow_map.h"

#include "scene/environment.h"
#include "scene/scene.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace twr {

namespace {

// The orthographic box reaches this much past the scene's bounding sphere (unitless ratio),
// so no surface lies exactly on its near or far plane.
constexpr float kOrthoDepthMargin = 1.05f;
// A cube map's auto extent reaches this much past the farthest corner (unitless ratio).
constexpr float kCubeFarMargin = 1.01f;
// The smallest extent used (world units): a scene of one point still gets a valid map.
constexpr float kMinShadowExtent = 1e-3f;
// The farthest a cube map reaches (world units): 2 far near stays finite in float.
constexpr float kMaxShadowFar = 1e18f;
// Above this |y| of the light direction the light camera's up is +Z instead of +Y (unitless).
constexpr float kMaxUpAlignment = 0.99f;

// The glm::ortho of GL's convention (z_ndc in [-1, 1], camera looking down -Z).
mat4 orthographic(float halfWidth, float near, float far) {
  mat4 m(1.0f);
  m[0][0] = 1.0f / halfWidth;
  m[1][1] = 1.0f / halfWidth;
  m[2][2] = -2.0f / (far - near);
  m[3][2] = -(far + near) / (far - near);
  return m;
}

// A square perspective of half-angle atan(tanHalf) (1: a 90-degree cube face), the terms in
// double rounded once (as camera.cpp's clipFromView).
mat4 squarePerspective(double tanHalf, double near, double far) {
  mat4 m(0.0f);
  m[0][0] = static_cast<float>(1.0 / tanHalf);
  m[1][1] = static_cast<float>(1.0 / tanHalf);
  m[2][2] = static_cast<float>((far + near) / (near - far));
  m[2][3] = -1.0f;
  m[3][2] = static_cast<float>(2.0 * far * near / (near - far));
  return m;
}

// The course camera's view matrix (camera.h: rows R, U, D, then translate(-eye)) looking from
// `eye` along `forward` with `up`, in double rounded once. Built here rather than through a
// Camera so that a light far from the scene (eye + forward == eye in float) still gets a map.
mat4 viewAlong(const glm::dvec3& eye, const glm::dvec3& forward, const glm::dvec3& up) {
  const glm::dvec3 d = -glm::normalize(forward);
  const glm::dvec3 r = glm::normalize(glm::cross(up, d));
  const glm::dvec3 u = glm::cross(d, r);
  glm::dmat4 view(1.0);
  for (int i = 0; i < 3; ++i) {
    view[i][0] = r[i];
    view[i][1] = u[i];
    view[i][2] = d[i];
  }
  view[3] = glm::dvec4(-glm::dot(r, eye), -glm::dot(u, eye), -glm::dot(d, eye), 1.0);
  return mat4(view);
}

}  // namespace

WorldBounds worldBoundsOf(const Scene& scene) {
  WorldBounds bounds;
  for (const DrawItem& item : flattenScene(scene)) {
    for (const Vertex& v : item.mesh->vertices) {
      const vec3 p(item.worldFromModel * vec4(v.posModel, 1.0f));
      if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) continue;
      if (bounds.empty()) {
        bounds.lo = bounds.hi = p;
      } else {
        bounds.lo = glm::min(bounds.lo, p);
        bounds.hi = glm::max(bounds.hi, p);
      }
    }
  }
  return bounds;
}

bool sceneHasShadows(const Scene& scene) {
  return std::any_of(scene.lights.begin(), scene.lights.end(), [](const Light& l) { return l.shadow.has_value(); });
}

ShadowProjection shadowProjectionFor(const Light& light, const WorldBounds& boundsIn) {
  const ShadowDesc desc = light.shadow.value_or(ShadowDesc{});
  const WorldBounds bounds = boundsIn.empty() ? WorldBounds{vec3(0.0f), vec3(0.0f)} : boundsIn;
  ShadowProjection p;
  p.size = desc.size;
  p.bias = desc.bias;
  p.pcf = desc.pcf;
  if (light.type == LightType::Directional) {
    p.kind = ShadowKind::Orthographic;
    p.layers = 1;
    const vec3 centre = 0.5f * (bounds.lo + bounds.hi);
    const float radius = std::max(0.5f * glm::length(bounds.hi - bounds.lo), kMinShadowExtent);
    const float halfWidth = desc.extent > 0.0f ? desc.extent : radius;
    const vec3 dir = safeNormalize(light.directionWorld, vec3(0.0f, -1.0f, 0.0f));
    const glm::dvec3 up = std::fabs(dir.y) > kMaxUpAlignment ? glm::dvec3(0.0, 0.0, -1.0) : glm::dvec3(0.0, 1.0, 0.0);
    const glm::dvec3 eye = glm::dvec3(centre) - glm::dvec3(dir) * (static_cast<double>(radius) * kOrthoDepthMargin);
    const float depthRange = 2.0f * radius * kOrthoDepthMargin;
    p.clipFromWorld[0] = orthographic(halfWidth, 0.0f, depthRange) * viewAlong(eye, glm::dvec3(dir), up);
    p.texelWorld = 2.0f * halfWidth / static_cast<float>(p.size);
    p.depthPerWorld = 1.0f / depthRange;  // window depth 0.5 z_ndc + 0.5 spans the range once
    return p;
  }
  const bool spot = isSpotLight(light);
  p.kind = spot ? ShadowKind::Perspective : ShadowKind::Cube;
  p.layers = spot ? 1 : kCubeShadowLayers;
  p.lightPosWorld = light.posWorld;
  float far = desc.extent;
  if (!(far > 0.0f)) {
    for (int corner = 0; corner < 8; ++corner) {
      const vec3 c((corner & 1) ? bounds.hi.x : bounds.lo.x, (corner & 2) ? bounds.hi.y : bounds.lo.y,
                   (corner & 4) ? bounds.hi.z : bounds.lo.z);
      far = std::max(far, glm::length(c - light.posWorld) * kCubeFarMargin);
    }
  }
  // Within float's range, and never below the smallest extent (a light far from a tiny scene
  // still gets a valid, if useless, map).
  far = std::clamp(far, kMinShadowExtent, kMaxShadowFar);
  p.near = far * kCubeShadowNearRatio;
  p.far = far;
  // A spot map's field of view is the cone's: tan of the outer half-angle (double, rounded once).
  const double tanHalf = spot ? std::tan(static_cast<double>(light.spot->outerDeg) * (3.14159265358979323846 / 180.0))
                              : 1.0;
  const mat4 projection = squarePerspective(tanHalf, p.near, p.far);
  p.depthA = projection[2][2];
  p.depthB = projection[3][2];
  if (spot) {
    const glm::dvec3 axis(light.spot->directionWorld);
    const glm::dvec3 up = std::fabs(axis.y) > kMaxUpAlignment ? glm::dvec3(0.0, 0.0, -1.0) : glm::dvec3(0.0, 1.0, 0.0);
    p.clipFromWorld[0] = projection * viewAlong(glm::dvec3(light.posWorld), axis, up);
    // A texel at m along the axis is 2 m tan(outer) / size wide; depth units as a cube face's.
    p.texelWorld = static_cast<float>(2.0 * tanHalf / static_cast<double>(p.size));
    p.depthPerWorld = 0.5f * std::fabs(p.depthB);
    return p;
  }
  for (int face = 0; face < kCubeShadowLayers; ++face) {
    // The face's middle direction and its increasing-t direction (GL's table, exact unit axes),
    // as scene/environment_capture.h's face cameras.
    const glm::dvec3 forward = directionFromCubeCoord(face, 0.5, 0.5);
    const glm::dvec3 towardsT = directionFromCubeCoord(face, 0.5, 1.0) - forward;
    p.clipFromWorld[static_cast<std::size_t>(face)] = projection * viewAlong(glm::dvec3(light.posWorld), forward, towardsT);
  }
  // d(window depth) / dm = 0.5 |depthB| / m^2 (cubeShadowDepth's derivative); a texel at m is
  // 2 m / size wide (a 90-degree face).
  p.texelWorld = 2.0f / static_cast<float>(p.size);
  p.depthPerWorld = 0.5f * std::fabs(p.depthB);
  return p;
}

float cubeShadowDepth(const ShadowProjection& projection, float m) {
  return 0.5f * ((projection.depthB - projection.depthA * m) / m) + 0.5f;
}

int cubeFaceOf(const vec3& d) {
  const float ax = std::fabs(d.x), ay = std::fabs(d.y), az = std::fabs(d.z);
  if (az >= std::max(ax, ay)) return std::signbit(d.z) ? 5 : 4;
  if (ax > ay) return d.x < 0.0f ? 1 : 0;
  return d.y < 0.0f ? 3 : 2;
}

std::string_view toString(ShadowKind kind) {
  switch (kind) {
    case ShadowKind::Orthographic: return "orthographic";
    case ShadowKind::Cube: return "cube";
    case ShadowKind::Perspective: return "perspective";
  }
  return "?";
}

std::string describeShadow(const ShadowProjection& p) {
  char text[160];
  std::snprintf(text, sizeof text, "%s %d^2%s, bias %g + %g texel slope, pcf %d", std::string(toString(p.kind)).c_str(),
                p.size,
                p.kind == ShadowKind::Cube ? " x 6" : "", static_cast<double>(p.bias.x), static_cast<double>(p.bias.y),
                p.pcf);
  return text;
}

}  // namespace twr
