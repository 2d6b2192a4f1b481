#include "scene/shadow_map.h"

#include "scene/camera.h"
#include "scene/environment_capture.h"
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
    Camera camera;
    camera.position = centre - dir * (radius * kOrthoDepthMargin);
    camera.target = centre;
    camera.up = std::fabs(dir.y) > kMaxUpAlignment ? vec3(0.0f, 0.0f, -1.0f) : vec3(0.0f, 1.0f, 0.0f);
    p.clipFromWorld[0] = orthographic(halfWidth, 0.0f, 2.0f * radius * kOrthoDepthMargin) * viewFromWorld(camera);
    return p;
  }
  p.kind = ShadowKind::Cube;
  p.layers = kCubeShadowLayers;
  p.lightPosWorld = light.posWorld;
  float far = desc.extent;
  if (!(far > 0.0f)) {
    for (int corner = 0; corner < 8; ++corner) {
      const vec3 c((corner & 1) ? bounds.hi.x : bounds.lo.x, (corner & 2) ? bounds.hi.y : bounds.lo.y,
                   (corner & 4) ? bounds.hi.z : bounds.lo.z);
      far = std::max(far, glm::length(c - light.posWorld) * kCubeFarMargin);
    }
  }
  far = std::max(far, kMinShadowExtent);
  Camera like;
  like.far = far;
  like.near = far * kCubeShadowNearRatio;
  p.near = like.near;
  p.far = like.far;
  for (int face = 0; face < kCubeShadowLayers; ++face) {
    const Camera camera = captureCamera(face, light.posWorld, like);
    const mat4 projection = clipFromView(camera, 1.0f);
    p.depthA = projection[2][2];
    p.depthB = projection[3][2];
    p.clipFromWorld[static_cast<std::size_t>(face)] = projection * viewFromWorld(camera);
  }
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

std::string describeShadow(const ShadowProjection& p) {
  char text[160];
  std::snprintf(text, sizeof text, "%s %d^2%s, bias %g + %g tan, pcf %d",
                p.kind == ShadowKind::Orthographic ? "orthographic" : "cube", p.size,
                p.kind == ShadowKind::Cube ? " x 6" : "", static_cast<double>(p.bias.x), static_cast<double>(p.bias.y),
                p.pcf);
  return text;
}

}  // namespace twr
