// Where the view area puts its images, in screen points (ImGui's units, y down): the slots of a
// view mode, an image fitted in a slot, which image pixel a point falls on, and where a world
// point lands. No ImGui here (the app converts its ImVec2), so tests/gui checks the geometry.
#pragma once

#include "gui/pixel_probe.h"
#include "gui/view_mode.h"
#include "scene/camera.h"

#include <optional>
#include <vector>

namespace twr::gui {

struct ScreenPoint {
  float x = 0.0f, y = 0.0f;
};

// min inclusive, max exclusive.
struct ScreenRect {
  ScreenPoint min, max;
  float width() const { return max.x - min.x; }
  float height() const { return max.y - min.y; }
  bool contains(ScreenPoint p) const { return p.x >= min.x && p.x < max.x && p.y >= min.y && p.y < max.y; }
};

// The largest rect of aspect imageWidth:imageHeight centred in the slot, its corner on whole
// points; an empty rect at the slot's corner for an empty image or slot.
ScreenRect fitRect(const ScreenRect& slot, int imageWidth, int imageHeight);

// The slots images go in for a mode: two halves `gapPoints` apart for side by side, the whole
// region otherwise.
std::vector<ScreenRect> slotsFor(ViewMode mode, ScreenPoint regionMin, ScreenPoint regionSize, float gapPoints);

// The pixel (of a width x height image fitted in each slot) under `point`, in the first slot
// whose image holds it; none outside every image.
std::optional<PixelPos> pixelAt(const std::vector<ScreenRect>& slots, ScreenPoint point, int width, int height);

// Where a world point lands on an image rect, or nothing behind the camera or for a camera
// that validateCamera rejects (one still being typed into a field).
std::optional<ScreenPoint> projectToRect(const Camera& camera, const vec3& posWorld, const ScreenRect& rect, int width,
                                         int height);

}  // namespace twr::gui
