// The size of a docked side panel (the Controls width, the Stats height). What the user
// dragged it to is kept apart from what the window allows right now: a window shrunk to
// 300 x 200 squeezes the panel, and growing it back restores the user's size, instead of
// leaving the squeezed size behind (and saving it). All sizes in ImGui units (points at UI
// scale 1 times the UI scale).
#pragma once

#include <algorithm>

namespace twr::gui {

struct PanelLimits {
  float minimum = 0.0f;   // smallest size the user may drag to, inclusive
  float maxShare = 1.0f;  // largest share of the window the panel may take, inclusive
  float fallback = 0.0f;  // the size before the user chose one
};

// The user's preferred size, sanitised: at least the minimum (a saved size below it, e.g.
// from an older version or a hand-edited file, does not persist), the fallback when unset
// (<= 0) or not a number.
inline float sanitisePreferred(float preferred, const PanelLimits& limits) {
  if (!(preferred > 0.0f)) return std::max(limits.fallback, limits.minimum);
  return std::max(preferred, limits.minimum);
}

// What the panel gets in a window with `available` units: the preferred size, clamped to
// the share of the window, never below the minimum unless the window itself is smaller,
// never more than the window.
inline float shownPanelSize(float preferred, float available, const PanelLimits& limits) {
  const float maximum = std::max(limits.minimum, available * limits.maxShare);
  const float size = std::clamp(sanitisePreferred(preferred, limits), limits.minimum, maximum);
  return std::max(0.0f, std::min(size, available));
}

// After the panel was drawn at `asked`, ImGui reports `shown`. A difference of more than
// `tolerance` units means the user dragged the edge: that becomes the new preference.
// Otherwise the preference stays, even when the window squeezed the panel.
inline float preferredAfterFrame(float preferred, float asked, float shown, const PanelLimits& limits,
                                 float tolerance = 0.5f) {
  if (shown > asked + tolerance || shown < asked - tolerance) return sanitisePreferred(shown, limits);
  return sanitisePreferred(preferred, limits);
}

}  // namespace twr::gui
