// The diff heat map and the class map, each with an optional legend drawn into the image.
//
// Layout of both: the width x height map sits at the top-left (pixel (x, y) of the map is
// pixel (x, y) of the analysis). With a legend, a panel is appended below; when the legend
// needs more room than the map is wide (kLegendMinWidthPx), the canvas widens and the strip
// right of the map is panel colour. Without a legend the image is exactly width x height.
//
// Heat map pixels: both covered -> heatColour(diffLevels) (black for 0, inferno ramp above);
// CPU only -> magenta; GL only -> cyan; TBN line -> grey; neither covered -> dark checker.
// Class map pixels: same -> black; CPU only -> magenta; GL only -> cyan; depth -> orange;
// shading -> yellow; decision -> blue; TBN line -> grey; neither -> dark checker.
#pragma once

#include "compare/colours.h"
#include "compare/metrics.h"
#include "scene/image.h"

namespace twr {

// Narrowest legend panel, pixels; the canvas is at least this wide when a legend is drawn.
inline constexpr int kLegendMinWidthPx = 360;

struct HeatMapOptions {
  HeatRamp ramp;
  bool legend = true;
};

struct ClassMapOptions {
  bool legend = true;
};

Image makeHeatMap(const PixelAnalysis& pixels, const HeatMapOptions& options = {});
Image makeClassMap(const PixelAnalysis& pixels, const ClassMapOptions& options = {});

// The colour a map gives a pixel of class `pixelClass` at (x, y) (the checker needs x, y).
Rgb8 heatMapColour(PixelClass pixelClass, int diffLevels, int x, int y, const HeatRamp& ramp);
Rgb8 classMapColour(PixelClass pixelClass, int x, int y);

}  // namespace twr
