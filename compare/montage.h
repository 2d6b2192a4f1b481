// A labelled grid of same-sized images (the report's pictures: a reference beside the
// methods, their difference maps below), and the interior difference map it shows.
#pragma once

#include "compare/colours.h"
#include "compare/interior.h"
#include "scene/image.h"

#include <string>
#include <vector>

namespace twr {

struct MontageTile {
  std::string label;  // drawn in a strip above the image, centred
  Image image;
};

struct MontageOptions {
  int columns = 4;  // tiles per row, >= 1
  int gapPx = 2;    // panel-coloured pixels between tiles and rows, in [0, 64]
};

// Height of the label strip above each tile `tileWidth` wide, pixels.
int montageLabelHeight(int tileWidth);

// Tiles left to right, top to bottom, on a panel-coloured canvas of
//   columns * w + (columns - 1) gap  by  rows * (label + h) + (rows - 1) gap
// (w x h the tiles' size; rows = ceil(tiles / columns)). Throws InputError when there are no
// tiles, their sizes differ, or an option is out of range.
Image makeMontage(const std::vector<MontageTile>& tiles, const MontageOptions& options = {});

// The difference between an approximation and its reference where compareInterior measures it:
// interior pixels by heatColour(max RGB channel difference, ramp); silhouette pixels covered
// by the approximation only magenta (kColourCpuOnly), by the reference only cyan
// (kColourGlOnly); partial, line and empty pixels the dark checker. `split` must come from
// splitInterior(approx, reference); throws InputError when its size differs.
Image makeInteriorHeatMap(const RenderOutput& approx, const RenderOutput& reference, const InteriorSplit& split,
                          const HeatRamp& ramp = {});

}  // namespace twr
