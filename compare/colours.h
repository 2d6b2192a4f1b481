// Colours of the comparison images: the heat ramp and the fixed class colours. The GUI uses
// the same values so its legends match the PNGs.
#pragma once

#include <cstdint>

namespace twr {

struct Rgb8 {
  std::uint8_t r = 0, g = 0, b = 0;
  friend bool operator==(const Rgb8&, const Rgb8&) = default;
};

inline constexpr Rgb8 kColourBlack{0, 0, 0};
inline constexpr Rgb8 kColourWhite{255, 255, 255};
inline constexpr Rgb8 kColourCpuOnly{255, 0, 255};       // magenta: covered by the CPU only
inline constexpr Rgb8 kColourGlOnly{0, 255, 255};        // cyan: covered by GL only
inline constexpr Rgb8 kColourExcludedLine{128, 128, 128};  // grey: TBN line pixels, not compared
inline constexpr Rgb8 kColourSame{0, 0, 0};              // class map: both covered, no difference
inline constexpr Rgb8 kColourDepth{255, 96, 0};          // class map: a different surface won
inline constexpr Rgb8 kColourShading{255, 224, 0};       // class map: same surface, other colour
inline constexpr Rgb8 kColourDecision{64, 160, 255};     // class map: same surface, a decision went the other way
// Empty pixels (neither backend covered) are a checker of these, kCheckerCellPx square.
inline constexpr Rgb8 kColourCheckerDark{40, 40, 40};
inline constexpr Rgb8 kColourCheckerLight{64, 64, 64};
inline constexpr int kCheckerCellPx = 8;
// Legend and label panels.
inline constexpr Rgb8 kColourPanel{24, 24, 24};

// Checker colour at pixel (x, y), top-left origin; cell (0, 0) is dark.
inline Rgb8 checkerColour(int x, int y) {
  return ((x / kCheckerCellPx + y / kCheckerCellPx) % 2 == 0) ? kColourCheckerDark : kColourCheckerLight;
}

// Matplotlib's perceptually uniform "inferno" ramp at t in [0, 1] (clamped; NaN gives 0):
// linear interpolation between its 11 samples at t = k / 10, rounded to the nearest level.
Rgb8 infernoColour(double t);

enum class HeatScale {
  Linear,  // t = d / maxLevels
  Log,     // t = log2(1 + d) / log2(1 + maxLevels): 1, 3 and 12 levels stay visible
};

struct HeatRamp {
  int maxLevels = 255;  // differences >= this get the top colour; in [1, 255]
  HeatScale scale = HeatScale::Log;
};

// Ramp position of a difference of `levels` (clamped to [0, maxLevels]), in [0, 1].
double heatPosition(int levels, const HeatRamp& ramp);
// Black for 0, else infernoColour(heatPosition(levels)).
Rgb8 heatColour(int levels, const HeatRamp& ramp);

}  // namespace twr
