// One pinned pixel read in every debug view, per backend: the inspector's table.
#pragma once

#include "scene/settings.h"

#include <array>
#include <cstddef>
#include <cstdint>
#include <iterator>
#include <optional>

namespace twr::gui {

// A pixel in top-left image coordinates, as in the PNG files and RenderOutput.
struct PixelPos {
  int x = 0;
  int yTop = 0;
  friend bool operator==(const PixelPos&, const PixelPos&) = default;
};

inline constexpr std::size_t kViewCount = std::size(kAllViews);

struct PixelSample {
  std::array<std::uint8_t, 4> rgba{};
  float depth = 1.0f;  // window depth
  bool drawn = false;  // a triangle or line was drawn there (drawnAt; not alpha, which is the background's)
};

// Indexed like kAllViews; empty until that view has been read.
using ViewSamples = std::array<std::optional<PixelSample>, kViewCount>;

}  // namespace twr::gui
