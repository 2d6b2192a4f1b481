#include "scene/projection_checks.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

namespace twr {

namespace {

// One float ulp at magnitude M is at most 2^-23 M.
constexpr double kFloatRelativeStep = 0x1p-23;
// Largest clip-space coordinate accepted (unitless, clip space). The clipper and the
// viewport transform subtract and scale coordinates: 2^-4 of float's range keeps their
// intermediate sums finite.
constexpr double kMaxClipCoordinate = std::numeric_limits<float>::max() / 16.0;
// A depth step (one float step of window depth just below 1.0, 2^-24) wider than this part of
// the distance lets surfaces that far apart fight (unitless fraction of the distance).
constexpr double kDepthFightFraction = 0.01;
// The shaders square world-space distances (normalize, the attenuation's d^2): a sum of three
// squares overflows float beyond sqrt(float max / 3) (world units).
const double kMaxShadingDistance = std::sqrt(std::numeric_limits<float>::max() / 3.0);
// near is suggested this much below the nearest geometry's distance (unitless).
constexpr double kSuggestedNearFraction = 1e-3;

std::string number(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g", v);
  return text;
}

double length(const glm::dvec3& v) { return std::sqrt(glm::dot(v, v)); }

// Window depth at distance d in front of the eye, in float and in the pipeline's order
// (clip z, times 1 / w, then the viewport's 0.5 * z + 0.5).
float windowDepthAt(const mat4& clipFromViewMatrix, float d) {
  const float zClip = clipFromViewMatrix[2][2] * -d + clipFromViewMatrix[3][2];
  const float zNdc = zClip * (1.0f / d);
  return zNdc * 0.5f + 0.5f;
}

bool finite(const mat4& m) {
  for (int col = 0; col < 4; ++col) {
    for (int row = 0; row < 4; ++row) {
      if (!std::isfinite(m[col][row])) return false;
    }
  }
  return true;
}

// One draw item as the checks see it: its bounding box through its transforms (in double;
// the renderers' matrices are float, and their entries are what is checked) and its vertices'
// depths.
struct ItemExtent {
  std::string node;
  double maxClip = 0.0;  // largest |clip coordinate| of the box's corners (infinity if one overflows)
  glm::dvec3 worldLo{0.0}, worldHi{0.0};  // world-space box of the corners
  std::size_t verticesInView = 0;  // between near and far (along the view axis)
  std::size_t verticesAtClearDepth = 0;  // of those, window depth rounds to 1.0
  double nearestInView = std::numeric_limits<double>::infinity();  // world units
  double farthestInView = 0.0;
};

ItemExtent extentOf(const DrawItem& item, const Camera& camera, const mat4& viewFromWorld, const mat4& clipFromView) {
  ItemExtent e;
  e.node = item.nodeName;
  if (item.mesh->vertices.empty()) return e;
  const glm::dmat4 worldFromModel(item.worldFromModel);
  const glm::dmat4 viewFromModel = glm::dmat4(viewFromWorld) * worldFromModel;
  const glm::dmat4 clip(clipFromView);
  glm::dvec3 lo(std::numeric_limits<double>::infinity()), hi(-std::numeric_limits<double>::infinity());
  for (const Vertex& v : item.mesh->vertices) {
    const glm::dvec3 model(v.posModel);
    if (!std::isfinite(model.x) || !std::isfinite(model.y) || !std::isfinite(model.z)) continue;  // dropped by both
    lo = glm::min(lo, model);
    hi = glm::max(hi, model);
    const double d = -(viewFromModel * glm::dvec4(model, 1.0)).z;
    if (!(d >= camera.near && d <= camera.far)) continue;
    ++e.verticesInView;
    e.nearestInView = std::min(e.nearestInView, d);
    e.farthestInView = std::max(e.farthestInView, d);
    if (windowDepthAt(clipFromView, static_cast<float>(d)) >= 1.0f) ++e.verticesAtClearDepth;
  }
  e.worldLo = glm::dvec3(std::numeric_limits<double>::infinity());
  e.worldHi = -e.worldLo;
  if (!(lo.x <= hi.x)) return e;  // no finite vertex
  for (int corner = 0; corner < 8; ++corner) {
    const glm::dvec4 model((corner & 1) ? hi.x : lo.x, (corner & 2) ? hi.y : lo.y, (corner & 4) ? hi.z : lo.z, 1.0);
    const glm::dvec4 view = viewFromModel * model;
    const glm::dvec3 world(worldFromModel * model);
    e.worldLo = glm::min(e.worldLo, world);
    e.worldHi = glm::max(e.worldHi, world);
    const glm::dvec4 c = clip * view;
    for (int i = 0; i < 4; ++i) {
      const double magnitude = std::isfinite(c[i]) ? std::fabs(c[i]) : std::numeric_limits<double>::infinity();
      e.maxClip = std::max(e.maxClip, magnitude);
    }
  }
  return e;
}

std::vector<ItemExtent> extentsOf(const Scene& scene, int width, int height) {
  const mat4 viewFromWorldMatrix = viewFromWorld(scene.camera);
  const mat4 clipFromViewMatrix = clipFromView(scene.camera, static_cast<float>(width) / static_cast<float>(height));
  std::vector<ItemExtent> extents;
  for (const DrawItem& item : flattenScene(scene)) {
    extents.push_back(extentOf(item, scene.camera, viewFromWorldMatrix, clipFromViewMatrix));
  }
  return extents;
}

}  // namespace

double floatStepInPixels(const Camera& camera, int height) {
  const glm::dvec3 position(camera.position), target(camera.target);
  const double distance = length(target - position);
  const double magnitude = std::max(length(position), length(target));
  const double halfFov = 0.5 * static_cast<double>(camera.fovDeg) * (M_PI / 180.0);
  const double pixel = 2.0 * std::tan(halfFov) * distance / static_cast<double>(height);  // world units
  const double step = kFloatRelativeStep * magnitude;                                       // world units
  return step / pixel;
}

std::string projectionProblem(const Scene& scene, int width, int height) {
  const Camera& camera = scene.camera;
  if (std::string error = validateCamera(camera); !error.empty()) return "camera: " + error;
  const double steps = floatStepInPixels(camera, height);
  if (!(steps < static_cast<double>(height))) {
    const glm::dvec3 position(camera.position), target(camera.target);
    const double distance = length(target - position);
    const double magnitude = std::max(length(position), length(target));
    const double step = kFloatRelativeStep * magnitude;
    const double minFovDeg = 2.0 * std::atan(0.5 * step * height / distance) * (180.0 / M_PI);
    return "camera: fov_deg " + number(camera.fovDeg) + " on an image " + std::to_string(height) +
           " pixels high: the whole view is narrower at the target (" + number(distance) +
           " away) than one float step of the coordinates there (" + number(step) + " at magnitude " +
           number(magnitude) + "), so no picture can be drawn from them (each renderer would show a "
           "different piece of rounding). Use fov_deg >= " + number(minFovDeg) +
           " (one float step per pixel), or move the camera and target nearer the origin";
  }
  const mat4 m = clipFromView(camera, static_cast<float>(width) / static_cast<float>(height));
  for (int col = 0; col < 4; ++col) {
    for (int row = 0; row < 4; ++row) {
      if (!std::isfinite(m[col][row])) {
        return "camera: near " + number(camera.near) + " and far " + number(camera.far) +
               ": the projection's depth term 2 * far * near / (near - far) is beyond float's range "
               "(3.4e38); bring near and far nearer zero";
      }
    }
  }
  for (const DrawItem& item : flattenScene(scene)) {
    if (!finite(item.worldFromModel)) {
      return "node '" + item.nodeName + "': its transform (translate, rotate_deg, scale, times its parents') overflows "
             "float, so none of its vertices has a position; scale the scene down";
    }
  }
  return {};
}

std::vector<std::string> projectionWarnings(const Scene& scene, int width, int height) {
  std::vector<std::string> warnings;
  const Camera& camera = scene.camera;
  const double steps = floatStepInPixels(camera, height);
  if (steps > 1.0) {
    warnings.push_back("camera: float positions resolve only to about " + number(steps) +
                       " pixels here (fov_deg " + number(camera.fovDeg) + ", coordinates of magnitude " +
                       number(std::max(glm::length(camera.position), glm::length(camera.target))) +
                       "): edges stair-step in steps that wide on both renderers; widen fov_deg or move the "
                       "camera and target nearer the origin");
  }

  const std::vector<ItemExtent> extents = extentsOf(scene, width, height);
  std::string lost;  // nodes with vertices whose depth rounds to the cleared 1.0
  std::size_t inView = 0, atClearDepth = 0;
  double nearestInView = std::numeric_limits<double>::infinity(), farthestDrawn = 0.0;
  for (const ItemExtent& e : extents) {
    inView += e.verticesInView;
    atClearDepth += e.verticesAtClearDepth;
    nearestInView = std::min(nearestInView, e.nearestInView);
    if (e.verticesAtClearDepth < e.verticesInView) farthestDrawn = std::max(farthestDrawn, e.farthestInView);
    if (e.verticesAtClearDepth > 0) {
      lost += (lost.empty() ? "" : ", ") + std::string("'") + e.node + "' " +
              number(100.0 * static_cast<double>(e.verticesAtClearDepth) / static_cast<double>(e.verticesInView)) + " %";
    }
  }
  if (atClearDepth > 0) {
    const std::string what = atClearDepth == inView ? "every vertex in view" : "vertices in view";
    warnings.push_back("camera.near " + number(camera.near) + ": " + what + " (" + lost +
                       ") get window depth 1.0 after rounding to float, equal to the cleared depth, so the depth "
                       "test (less) discards triangles made of them and " +
                       (atClearDepth == inView ? std::string("nothing is drawn") : std::string("they are not drawn")) +
                       ", on both renderers as in OpenGL; raise near to about " +
                       number(kSuggestedNearFraction * nearestInView));
  }
  for (const ItemExtent& e : extents) {
    if (e.maxClip > kMaxClipCoordinate) {
      warnings.push_back("node '" + e.node + "': its vertices reach " +
                         (std::isfinite(e.maxClip) ? number(e.maxClip) : std::string("beyond 3.4e38")) +
                         " in clip space, past " + number(kMaxClipCoordinate) +
                         ", where clipping and setup overflow float: triangles through such vertices may be "
                         "dropped or cut differently than the scene describes; scale the scene down");
    }
  }
  // The farthest any geometry lies from a light or the eye, in world units.
  double farthestFromViewer = 0.0, farthestFromLight = 0.0;
  for (const ItemExtent& e : extents) {
    for (int corner = 0; corner < 8; ++corner) {
      const glm::dvec3 p((corner & 1) ? e.worldHi.x : e.worldLo.x, (corner & 2) ? e.worldHi.y : e.worldLo.y,
                         (corner & 4) ? e.worldHi.z : e.worldLo.z);
      farthestFromViewer = std::max(farthestFromViewer, length(p - glm::dvec3(camera.position)));
      for (const Light& light : scene.lights) {
        if (light.type == LightType::Directional) continue;  // no position: its vectors are unit length
        farthestFromLight = std::max(farthestFromLight, length(p - glm::dvec3(light.posWorld)));
      }
    }
  }
  const double farthestShaded = std::max(farthestFromViewer, farthestFromLight);
  if (farthestShaded > kMaxShadingDistance) {
    warnings.push_back(std::string("lighting: geometry lies ") + number(farthestShaded) + " world units from " +
                       (farthestFromLight >= farthestFromViewer ? "a light" : "the camera") +
                       "; the shaders square such distances (normalize, attenuation), which overflows float beyond " +
                       number(kMaxShadingDistance) + ", so shading comes out as infinity or NaN on both renderers, "
                       "as in OpenGL; scale the scene down");
  }
  if (farthestDrawn > 0.0) {
    // One window-depth step (2^-24 just below 1.0) in world units at distance d:
    // depth = f / (f - n) * (1 - n / d), so d(depth)/dd = f n / ((f - n) d^2).
    const double n = camera.near, f = camera.far, d = farthestDrawn;
    const double depthStep = 0x1p-24 * d * d * (f - n) / (f * n);
    if (depthStep > kDepthFightFraction * d) {
      warnings.push_back("camera.near " + number(n) + ": one step of float depth spans " + number(depthStep) +
                         " world units at the farthest geometry drawn (" + number(d) +
                         " away), so surfaces nearer each other than that fight in the depth test; raise near");
    }
  }
  return warnings;
}

}  // namespace twr
