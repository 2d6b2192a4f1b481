#include "compare/empty_frame.h"

#include "scene/shadow_map.h"

#include <cstdint>
#include <cstdio>
#include <string>

namespace twr {
namespace {

std::string vecText(const vec3& v) {
  char buffer[96];
  std::snprintf(buffer, sizeof buffer, "(%g, %g, %g)", static_cast<double>(v.x), static_cast<double>(v.y),
                static_cast<double>(v.z));
  return buffer;
}

// Where the scene is and where the camera looks.
std::string whereText(const Scene& scene) {
  const WorldBounds bounds = worldBoundsOf(scene);
  const Camera& c = scene.camera;
  char camera[160];
  std::snprintf(camera, sizeof camera, ", fov %g deg, near %g, far %g", static_cast<double>(c.fovDeg),
                static_cast<double>(c.near), static_cast<double>(c.far));
  const std::string where = bounds.empty() ? "the scene has no vertex"
                                           : "the scene spans " + vecText(bounds.lo) + " to " + vecText(bounds.hi);
  return where + "; the camera at " + vecText(c.position) + " looks at " + vecText(c.target) + camera;
}

bool anyCovered(const RenderOutput& frame) {
  const std::size_t pixels = static_cast<std::size_t>(frame.width) * static_cast<std::size_t>(frame.height);
  for (std::size_t i = 0; i < pixels; ++i) {
    if (coveredAt(frame, i)) return true;
  }
  return false;
}

}  // namespace

std::string emptyFrameReason(const Scene& scene, const RenderOutput& frame, bool clipStats) {
  if (anyCovered(frame)) return "";
  const RenderStats& s = frame.stats;
  const auto triangles = [](std::uint64_t n) { return std::to_string(n) + (n == 1 ? " triangle" : " triangles"); };
  std::string why;
  if (s.trianglesIn == 0) {
    why = "the scene has no triangle to draw";
  } else if (!clipStats) {
    why = "none of its " + triangles(s.trianglesIn) + " covers a pixel (culled, outside the view or too small: the CPU "
          "renderer's statistics tell which)";
  } else if (s.trianglesProduced > 0) {
    why = triangles(s.trianglesProduced) + " reached the rasterizer and none covers a pixel centre "
          "(too small or too thin at this size)";
  } else if (s.trianglesCulled >= s.trianglesIn) {
    why = (s.trianglesIn == 1 ? "its one triangle was" : "all its " + triangles(s.trianglesIn) + " were") +
          " culled (turned away under settings.cull, or of zero area)";
  } else if (s.trianglesCulled > 0) {
    why = "none of its " + triangles(s.trianglesIn) + " was drawn: " + std::to_string(s.trianglesCulled) +
          " were culled (turned away under settings.cull, or of zero area) and the rest lie outside the view";
  } else {
    why = (s.trianglesIn == 1 ? "its one triangle lies" : "all its " + triangles(s.trianglesIn) + " lie") +
          " outside the view (clipped away)";
  }
  return "nothing was drawn: " + why + "; " + whereText(scene);
}

}  // namespace twr
