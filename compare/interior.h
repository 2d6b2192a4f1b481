// Where an approximation that does not move silhouettes (parallax mapping) is measured against
// a reference that does (the displaced mesh): on interior pixels, those both images cover
// wholly, with the silhouette pixels (covered by one image only) counted apart.
//
// Which pixel is which (one class each):
// - excluded: a TBN debug line on either side (lineMask), as compare() skips them;
// - silhouette: covered (coveredAt: a triangle id, or alpha > 0 without ids) by exactly one
//   side; approxOnly and referenceOnly count them;
// - partial: covered by both, but alpha below 255 on either side. A supersampled reference
//   rendered over a transparent background (alpha 0) holds its coverage fraction in alpha
//   (softrender/reference_renderer.h), so these are its edge pixels, whose colour blends the
//   background in and measures the edge rather than the surface. Over an opaque background
//   every alpha is 255 and no pixel is partial;
// - interior: covered by both, alpha 255 on both;
// - empty: covered by neither.
#pragma once

#include "compare/metrics.h"

#include <cstdint>
#include <vector>

namespace twr {

struct InteriorSplit {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> interior;  // width * height, top row first: 1 on interior pixels
  std::uint64_t interiorPixels = 0;
  std::uint64_t approxOnly = 0;       // silhouette: covered by the approximation alone
  std::uint64_t referenceOnly = 0;    // silhouette: covered by the reference alone
  std::uint64_t partial = 0;          // both cover it, one only partly (alpha < 255)
  std::uint64_t excludedLines = 0;    // a TBN debug line on either side

  std::uint64_t silhouette() const { return approxOnly + referenceOnly; }
};

// Throws InputError when the outputs differ in size or a buffer has the wrong length (as
// compare()).
InteriorSplit splitInterior(const RenderOutput& approx, const RenderOutput& reference);

struct InteriorComparison {
  // compare(approx, reference) over the interior pixels alone: every other pixel is excluded
  // the way compare() excludes a TBN line, so bothCovered == split.interiorPixels, the colour
  // metrics are over those, and coverageMismatch is 0 (the silhouettes are in split).
  CompareMetrics interior;
  InteriorSplit split;
};

InteriorComparison compareInterior(const RenderOutput& approx, const RenderOutput& reference,
                                   const CompareOptions& options = {});

}  // namespace twr
