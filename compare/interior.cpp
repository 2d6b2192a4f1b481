#include "compare/interior.h"

#include "scene/errors.h"

#include <string>

namespace twr {

namespace {

constexpr std::uint8_t kOpaque = 255;  // alpha of a wholly covered pixel

}  // namespace

InteriorSplit splitInterior(const RenderOutput& approx, const RenderOutput& reference) {
  if (approx.width != reference.width || approx.height != reference.height || approx.width <= 0 ||
      approx.height <= 0) {
    throw InputError("interior comparison: the approximation is " + std::to_string(approx.width) + "x" +
                     std::to_string(approx.height) + " and the reference " + std::to_string(reference.width) + "x" +
                     std::to_string(reference.height) + ", expected the same non-empty size");
  }
  const std::size_t pixelCount = static_cast<std::size_t>(approx.width) * static_cast<std::size_t>(approx.height);
  checkOutputBuffers("interior comparison", approx, "approximation", pixelCount);
  checkOutputBuffers("interior comparison", reference, "reference", pixelCount);
  InteriorSplit split;
  split.width = approx.width;
  split.height = approx.height;
  split.interior.assign(pixelCount, 0);
  for (std::size_t i = 0; i < pixelCount; ++i) {
    if (lineAt(approx, i) || lineAt(reference, i)) {
      ++split.excludedLines;
      continue;
    }
    const bool a = coveredAt(approx, i), r = coveredAt(reference, i);
    if (a != r) {
      ++(a ? split.approxOnly : split.referenceOnly);
    } else if (a) {
      if (approx.rgba[4 * i + 3] == kOpaque && reference.rgba[4 * i + 3] == kOpaque) {
        split.interior[i] = 1;
        ++split.interiorPixels;
      } else {
        ++split.partial;
      }
    }
  }
  return split;
}

InteriorComparison compareInterior(const RenderOutput& approx, const RenderOutput& reference,
                                   const CompareOptions& options) {
  InteriorComparison result;
  result.split = splitInterior(approx, reference);
  // compare() skips a pixel where either side's lineMask is set: mark every pixel but the
  // interior on a copy of the approximation, and it measures the interior alone.
  RenderOutput masked = approx;
  masked.lineMask.assign(result.split.interior.size(), 0);
  for (std::size_t i = 0; i < masked.lineMask.size(); ++i) masked.lineMask[i] = result.split.interior[i] ? 0 : 1;
  result.interior = compare(masked, reference, options);
  return result;
}

}  // namespace twr
