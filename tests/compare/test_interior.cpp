// compareInterior / splitInterior: each pixel lands in one class (interior, silhouette on
// either side, partial, excluded line, empty), worked out by hand on small outputs, and the
// colour metrics cover the interior alone.
#include "compare/interior.h"
#include "scene/errors.h"
#include "synthetic_outputs.h"

#include <gtest/gtest.h>

#include <string>

namespace twr {
namespace {

using testing::clearPixel;
using testing::makeSolidOutput;
using testing::pixelIndex;
using testing::rgbaAt;

// 4 x 2. Approximation grey 100 everywhere, reference grey 110, except:
//   (0, 0) covered by the approximation only      -> silhouette (approxOnly)
//   (1, 0) covered by the reference only          -> silhouette (referenceOnly)
//   (2, 0) reference alpha 128 (half its samples) -> partial, colour 0 (would be 100 levels off)
//   (3, 0) a TBN line on the approximation        -> excluded
//   (0, 1) covered by neither                     -> empty
//   (1, 1), (2, 1), (3, 1)                        -> interior, 10 levels off each
TEST(Interior, EachPixelInOneClassByHand) {
  RenderOutput approx = makeSolidOutput(4, 2, 100, 100, 100);
  RenderOutput reference = makeSolidOutput(4, 2, 110, 110, 110);
  clearPixel(reference, 0, 0);
  clearPixel(approx, 1, 0);
  rgbaAt(reference, 2, 0)[0] = rgbaAt(reference, 2, 0)[1] = rgbaAt(reference, 2, 0)[2] = 0;
  rgbaAt(reference, 2, 0)[3] = 128;
  approx.lineMask[pixelIndex(approx, 3, 0)] = 1;
  clearPixel(approx, 0, 1);
  clearPixel(reference, 0, 1);

  const InteriorComparison c = compareInterior(approx, reference);
  const InteriorSplit& s = c.split;
  EXPECT_EQ(s.interiorPixels, 3u);
  EXPECT_EQ(s.approxOnly, 1u);
  EXPECT_EQ(s.referenceOnly, 1u);
  EXPECT_EQ(s.silhouette(), 2u);
  EXPECT_EQ(s.partial, 1u);
  EXPECT_EQ(s.excludedLines, 1u);
  const std::vector<std::uint8_t> expected = {0, 0, 0, 0, 0, 1, 1, 1};
  EXPECT_EQ(s.interior, expected);

  // Metrics over the three interior pixels: 10 levels in every channel.
  EXPECT_EQ(c.interior.bothCovered, 3u);
  EXPECT_EQ(c.interior.coverageMismatch, 0u);
  EXPECT_DOUBLE_EQ(c.interior.rmse, 10.0);
  EXPECT_DOUBLE_EQ(c.interior.meanAbsDiff, 10.0);
  EXPECT_EQ(c.interior.maxAbsDiff, 10);
  EXPECT_EQ(c.interior.over1, 3u);
  // Plain compare() over the same pair sees the partial pixel, 100 levels off.
  EXPECT_EQ(compare(approx, reference).maxAbsDiff, 100);
}

// Without triangle ids, coverage is alpha > 0 (coveredAt); over an opaque background nothing
// is partial.
TEST(Interior, CoverageFromAlphaWithoutIds) {
  RenderOutput approx = makeSolidOutput(2, 1, 50, 50, 50);
  RenderOutput reference = makeSolidOutput(2, 1, 50, 50, 50);
  reference.triangleId.clear();
  rgbaAt(reference, 1, 0)[3] = 0;  // not covered
  const InteriorSplit s = splitInterior(approx, reference);
  EXPECT_EQ(s.interiorPixels, 1u);
  EXPECT_EQ(s.approxOnly, 1u);
  EXPECT_EQ(s.partial, 0u);
}

TEST(Interior, IdenticalImagesAreExact) {
  const RenderOutput a = makeSolidOutput(3, 3, 7, 8, 9);
  const InteriorComparison c = compareInterior(a, a);
  EXPECT_EQ(c.split.interiorPixels, 9u);
  EXPECT_EQ(c.split.silhouette(), 0u);
  EXPECT_EQ(c.interior.rmse, 0.0);
  EXPECT_EQ(c.interior.psnr, kPsnrCapDb);
}

TEST(Interior, RefusesMismatchedOutputs) {
  EXPECT_THROW(splitInterior(makeSolidOutput(2, 2, 0, 0, 0), makeSolidOutput(3, 2, 0, 0, 0)), InputError);
  RenderOutput shortIds = makeSolidOutput(2, 2, 0, 0, 0);
  shortIds.triangleId.resize(3);
  EXPECT_THROW(splitInterior(shortIds, makeSolidOutput(2, 2, 0, 0, 0)), InputError);
  EXPECT_THROW(splitInterior(RenderOutput{}, RenderOutput{}), InputError);
  // Depth is optional (empty), but when present it has one entry per pixel, as compare() asks.
  RenderOutput shortDepth = makeSolidOutput(2, 2, 0, 0, 0);
  shortDepth.depth.resize(3);
  try {
    splitInterior(makeSolidOutput(2, 2, 0, 0, 0), shortDepth);
    ADD_FAILURE() << "a depth buffer of 3 entries for 4 pixels was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("interior comparison: reference depth buffer has 3 entries, expected 0 or 4"),
              std::string::npos)
        << e.what();
  }
  RenderOutput noDepth = makeSolidOutput(2, 2, 0, 0, 0);
  noDepth.depth.clear();
  EXPECT_NO_THROW(splitInterior(noDepth, makeSolidOutput(2, 2, 0, 0, 0)));
}

}  // namespace
}  // namespace twr
