// The view area's geometry (gui/view_layout.h).
#include "gui/view_layout.h"

#include <algorithm>
#include <cmath>

namespace twr::gui {

ScreenRect fitRect(const ScreenRect& slot, int imageWidth, int imageHeight) {
  if (imageWidth < 1 || imageHeight < 1 || slot.width() <= 0.0f || slot.height() <= 0.0f) return ScreenRect{slot.min, slot.min};
  const float scale = std::min(slot.width() / static_cast<float>(imageWidth), slot.height() / static_cast<float>(imageHeight));
  const float width = scale * static_cast<float>(imageWidth), height = scale * static_cast<float>(imageHeight);
  const ScreenPoint min{std::floor(slot.min.x + 0.5f * (slot.width() - width)),
                        std::floor(slot.min.y + 0.5f * (slot.height() - height))};
  return ScreenRect{min, ScreenPoint{min.x + width, min.y + height}};
}

std::vector<ScreenRect> slotsFor(ViewMode mode, ScreenPoint regionMin, ScreenPoint regionSize, float gapPoints) {
  const ScreenPoint regionMax{regionMin.x + regionSize.x, regionMin.y + regionSize.y};
  if (mode != ViewMode::SideBySide) return {ScreenRect{regionMin, regionMax}};
  const float half = std::max(1.0f, 0.5f * (regionSize.x - gapPoints));
  return {ScreenRect{regionMin, ScreenPoint{regionMin.x + half, regionMax.y}},
          ScreenRect{ScreenPoint{regionMin.x + half + gapPoints, regionMin.y},
                     ScreenPoint{regionMin.x + 2.0f * half + gapPoints, regionMax.y}}};
}

std::optional<PixelPos> pixelAt(const std::vector<ScreenRect>& slots, ScreenPoint point, int width, int height) {
  for (const ScreenRect& slot : slots) {
    const ScreenRect rect = fitRect(slot, width, height);
    if (!rect.contains(point)) continue;
    PixelPos pixel;
    pixel.x = std::clamp(static_cast<int>((point.x - rect.min.x) / rect.width() * static_cast<float>(width)), 0, width - 1);
    pixel.yTop =
        std::clamp(static_cast<int>((point.y - rect.min.y) / rect.height() * static_cast<float>(height)), 0, height - 1);
    return pixel;
  }
  return std::nullopt;
}

std::optional<ScreenPoint> projectToRect(const Camera& camera, const vec3& posWorld, const ScreenRect& rect, int width,
                                         int height) {
  if (width < 1 || height < 1 || !validateCamera(camera).empty()) return std::nullopt;
  const mat4 clipFromWorld =
      clipFromView(camera, static_cast<float>(width) / static_cast<float>(height)) * viewFromWorld(camera);
  const vec4 posClip = clipFromWorld * vec4(posWorld, 1.0f);
  if (!(posClip.w > 0.0f)) return std::nullopt;
  const float xNdc = posClip.x / posClip.w, yNdc = posClip.y / posClip.w;
  return ScreenPoint{rect.min.x + (0.5f * xNdc + 0.5f) * rect.width(), rect.min.y + (0.5f - 0.5f * yNdc) * rect.height()};
}

}  // namespace twr::gui
