#include "compare/colours.h"

#include <algorithm>
#include <cmath>

namespace twr {
namespace {

// matplotlib inferno sampled at t = 0, 0.1, ..., 1 (the values d3-scale-chromatic lists).
constexpr int kInfernoSamples = 11;
constexpr Rgb8 kInferno[kInfernoSamples] = {
    {0, 0, 4},      {22, 11, 57},   {66, 10, 104},  {106, 23, 110}, {147, 38, 103}, {188, 55, 84},
    {221, 81, 58},  {243, 120, 25}, {252, 165, 10}, {246, 215, 70}, {252, 255, 164},
};

std::uint8_t mix(std::uint8_t a, std::uint8_t b, double f) {
  return static_cast<std::uint8_t>(std::lround(double(a) + (double(b) - double(a)) * f));
}

}  // namespace

Rgb8 infernoColour(double t) {
  if (!(t > 0.0)) return kInferno[0];  // also NaN
  if (t >= 1.0) return kInferno[kInfernoSamples - 1];
  const double scaled = t * (kInfernoSamples - 1);
  const int lower = std::min(static_cast<int>(scaled), kInfernoSamples - 2);
  const double f = scaled - lower;
  const Rgb8 a = kInferno[lower], b = kInferno[lower + 1];
  return {mix(a.r, b.r, f), mix(a.g, b.g, f), mix(a.b, b.b, f)};
}

double heatPosition(int levels, const HeatRamp& ramp) {
  const int maxLevels = std::max(ramp.maxLevels, 1);
  const int clamped = std::clamp(levels, 0, maxLevels);
  if (ramp.scale == HeatScale::Linear) return double(clamped) / maxLevels;
  return std::log2(1.0 + clamped) / std::log2(1.0 + maxLevels);
}

Rgb8 heatColour(int levels, const HeatRamp& ramp) {
  if (levels <= 0) return kColourBlack;
  return infernoColour(heatPosition(levels, ramp));
}

}  // namespace twr
