// Heat map, class map, legend, side by side, text and the artefact writer of compare/.
#include "compare/artifacts.h"
#include "compare/colours.h"
#include "compare/draw.h"
#include "compare/heatmap.h"
#include "compare/report_json.h"
#include "compare/side_by_side.h"
#include "scene/errors.h"
#include "synthetic_outputs.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>

namespace twr {
namespace {

using testing::clearPixel;
using testing::makeSolidOutput;
using testing::rgbaAt;

Rgb8 rgbAt(const Image& image, int x, int y) {
  const std::uint8_t* p = image.pixel(x, y);
  return {p[0], p[1], p[2]};
}

bool anyPixelIs(const Image& image, int x0, int y0, int x1, int y1, Rgb8 colour) {
  for (int y = y0; y < y1; ++y)
    for (int x = x0; x < x1; ++x)
      if (rgbAt(image, x, y) == colour) return true;
  return false;
}

::testing::AssertionResult sameRgb(Rgb8 actual, Rgb8 expected) {
  if (actual == expected) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << "got (" << int(actual.r) << ", " << int(actual.g) << ", " << int(actual.b)
                                       << "), expected (" << int(expected.r) << ", " << int(expected.g) << ", "
                                       << int(expected.b) << ")";
}

TEST(HeatRampColours, BlackForZeroAndInfernoSamplesAtKnownDifferences) {
  const HeatRamp logRamp;  // log scale, 255 levels
  EXPECT_TRUE(sameRgb(heatColour(0, logRamp), {0, 0, 0}));
  // log2(1 + 255) / log2(256) = 1: inferno's last sample.
  EXPECT_TRUE(sameRgb(heatColour(255, logRamp), {252, 255, 164}));
  // log2(16) / 8 = 0.5: inferno's middle sample #bc3754.
  EXPECT_TRUE(sameRgb(heatColour(15, logRamp), {188, 55, 84}));
  // log2(2) / 8 = 0.125: a quarter of the way from sample 1 (22, 11, 57) to sample 2 (66, 10, 104)
  // = (33, 10.75, 68.75), rounded.
  EXPECT_TRUE(sameRgb(heatColour(1, logRamp), {33, 11, 69}));
  HeatRamp linear;
  linear.scale = HeatScale::Linear;
  linear.maxLevels = 10;
  EXPECT_TRUE(sameRgb(heatColour(5, linear), {188, 55, 84}));     // 5 / 10
  EXPECT_TRUE(sameRgb(heatColour(200, linear), {252, 255, 164}));  // clamped to the top
  EXPECT_TRUE(sameRgb(infernoColour(std::nan("")), {0, 0, 4}));
}

// A 6 x 4 pair exercising every class: (1,1) off by 15 on the same triangle (shading), (2,1)
// off by 255 on another triangle (depth), (0,0) CPU only, (5,0) GL only, (3,3) a TBN line,
// (5,3) empty; everything else identical.
struct ClassPair {
  RenderOutput cpu = makeSolidOutput(6, 4, 100, 100, 100);
  RenderOutput gl = makeSolidOutput(6, 4, 100, 100, 100);
  ClassPair() {
    rgbaAt(gl, 1, 1)[0] = 115;
    rgbaAt(gl, 2, 1)[1] = 0;
    rgbaAt(cpu, 2, 1)[1] = 255;
    gl.triangleId[testing::pixelIndex(gl, 2, 1)] = 4;
    clearPixel(gl, 0, 0);
    clearPixel(cpu, 5, 0);
    gl.lineMask[testing::pixelIndex(gl, 3, 3)] = 1;
    clearPixel(cpu, 5, 3);
    clearPixel(gl, 5, 3);
  }
};

TEST(HeatMap, PixelColoursFollowTheDifferenceAndTheCoverage) {
  const ClassPair pair;
  const CompareResult r = compareDetailed(pair.cpu, pair.gl);
  HeatMapOptions options;
  options.legend = false;
  const Image heat = makeHeatMap(r.pixels, options);
  ASSERT_EQ(heat.width, 6);
  ASSERT_EQ(heat.height, 4);
  EXPECT_TRUE(sameRgb(rgbAt(heat, 1, 1), {188, 55, 84}));    // 15 levels
  EXPECT_TRUE(sameRgb(rgbAt(heat, 2, 1), {252, 255, 164}));  // 255 levels
  EXPECT_TRUE(sameRgb(rgbAt(heat, 4, 2), kColourBlack));     // identical
  EXPECT_TRUE(sameRgb(rgbAt(heat, 0, 0), kColourCpuOnly));
  EXPECT_TRUE(sameRgb(rgbAt(heat, 5, 0), kColourGlOnly));
  EXPECT_TRUE(sameRgb(rgbAt(heat, 3, 3), kColourExcludedLine));
  EXPECT_TRUE(sameRgb(rgbAt(heat, 5, 3), checkerColour(5, 3)));
  EXPECT_EQ(heat.pixel(5, 3)[3], 255);
}

TEST(HeatMap, LegendIsDrawnBelowWithTheRampAndText) {
  const ClassPair pair;
  const CompareResult r = compareDetailed(pair.cpu, pair.gl);
  const Image heat = makeHeatMap(r.pixels);
  // The 6-pixel map is narrower than the legend: the canvas widens to the legend's minimum.
  ASSERT_EQ(heat.width, kLegendMinWidthPx);
  ASSERT_GT(heat.height, 4 + kFontLineHeightUnits * 3);
  EXPECT_TRUE(sameRgb(rgbAt(heat, 1, 1), {188, 55, 84}));  // the map is unchanged at the top-left
  EXPECT_TRUE(sameRgb(rgbAt(heat, 6, 0), kColourPanel));    // right of the map: panel
  const int legendTop = 4;
  EXPECT_TRUE(anyPixelIs(heat, 0, legendTop, heat.width, heat.height, {252, 255, 164}));  // ramp top
  EXPECT_TRUE(anyPixelIs(heat, 0, legendTop, heat.width, heat.height, {188, 55, 84}));    // 15 levels is on it
  EXPECT_TRUE(anyPixelIs(heat, 0, legendTop, heat.width, heat.height, kColourWhite));     // labels
  EXPECT_TRUE(anyPixelIs(heat, 0, legendTop, heat.width, heat.height, kColourCpuOnly));   // swatches
  EXPECT_TRUE(anyPixelIs(heat, 0, legendTop, heat.width, heat.height, kColourGlOnly));
  EXPECT_TRUE(anyPixelIs(heat, 0, legendTop, heat.width, heat.height, kColourExcludedLine));

  // A map wider than the minimum keeps its width.
  const RenderOutput wide = makeSolidOutput(400, 8, 0, 0, 0);
  EXPECT_EQ(makeHeatMap(compareDetailed(wide, wide).pixels).width, 400);

  HeatMapOptions bad;
  bad.ramp.maxLevels = 0;
  EXPECT_THROW(makeHeatMap(r.pixels, bad), InputError);
}

TEST(ClassMap, EachClassHasItsColour) {
  const ClassPair pair;
  const CompareResult r = compareDetailed(pair.cpu, pair.gl);
  ClassMapOptions options;
  options.legend = false;
  const Image classes = makeClassMap(r.pixels, options);
  EXPECT_TRUE(sameRgb(rgbAt(classes, 1, 1), kColourShading));
  EXPECT_TRUE(sameRgb(rgbAt(classes, 2, 1), kColourDepth));
  EXPECT_TRUE(sameRgb(rgbAt(classes, 4, 2), kColourSame));
  EXPECT_TRUE(sameRgb(rgbAt(classes, 0, 0), kColourCpuOnly));
  EXPECT_TRUE(sameRgb(rgbAt(classes, 5, 0), kColourGlOnly));
  EXPECT_TRUE(sameRgb(rgbAt(classes, 3, 3), kColourExcludedLine));
  EXPECT_TRUE(sameRgb(rgbAt(classes, 5, 3), checkerColour(5, 3)));

  const Image withLegend = makeClassMap(r.pixels);
  EXPECT_GT(withLegend.height, 4);
  EXPECT_TRUE(anyPixelIs(withLegend, 0, 4, withLegend.width, withLegend.height, kColourDepth));
  EXPECT_TRUE(anyPixelIs(withLegend, 0, 4, withLegend.width, withLegend.height, kColourShading));
}

TEST(SideBySide, DimensionsAndBothHalvesEqualTheInputs) {
  RenderOutput cpu = makeSolidOutput(40, 30, 200, 10, 10);
  RenderOutput gl = makeSolidOutput(40, 30, 10, 200, 10);
  rgbaAt(cpu, 7, 5)[2] = 99;
  clearPixel(cpu, 0, 0);  // background keeps the RGB the renderer wrote
  const Image sbs = makeSideBySide(cpu, gl);
  // 40 px wide: label scale 1, strip (10 + 2 * 3) * 1 = 16 px; 2 px gap.
  const int labelHeight = 16;
  ASSERT_EQ(sideBySideLabelHeight(40, {}), labelHeight);
  ASSERT_EQ(sbs.width, 2 * 40 + 2);
  ASSERT_EQ(sbs.height, labelHeight + 30);
  for (int y = 0; y < 30; ++y) {
    for (int x = 0; x < 40; ++x) {
      const std::uint8_t* c = rgbaAt(cpu, x, y);
      const std::uint8_t* g = rgbaAt(gl, x, y);
      ASSERT_TRUE(sameRgb(rgbAt(sbs, x, labelHeight + y), {c[0], c[1], c[2]})) << x << "," << y;
      ASSERT_TRUE(sameRgb(rgbAt(sbs, 42 + x, labelHeight + y), {g[0], g[1], g[2]})) << x << "," << y;
      ASSERT_EQ(sbs.pixel(x, labelHeight + y)[3], 255);
    }
  }
  EXPECT_TRUE(anyPixelIs(sbs, 0, 0, 40, labelHeight, kColourWhite));    // "CPU"
  EXPECT_TRUE(anyPixelIs(sbs, 42, 0, 82, labelHeight, kColourWhite));   // "GL"
  EXPECT_TRUE(sameRgb(rgbAt(sbs, 40, labelHeight + 3), kColourPanel));  // the gap

  SideBySideOptions bare;
  bare.labels = false;
  bare.gapPx = 0;
  const Image plain = makeSideBySide(cpu, gl, bare);
  EXPECT_EQ(plain.width, 80);
  EXPECT_EQ(plain.height, 30);
  EXPECT_TRUE(sameRgb(rgbAt(plain, 40, 0), {10, 200, 10}));
  EXPECT_THROW(makeSideBySide(cpu, makeSolidOutput(40, 31, 0, 0, 0)), InputError);
}

TEST(SideBySide, CheckerBackgroundCompositesByAlpha) {
  RenderOutput out = makeSolidOutput(16, 16, 200, 100, 50);
  clearPixel(out, 9, 2);                // alpha 0: the checker
  clearPixel(out, 10, 2);               // nothing drawn under an opaque background: the checker too
  rgbaAt(out, 10, 2)[3] = 255;
  rgbaAt(out, 3, 4)[3] = 128;           // half covered: blended
  const Image view = viewImage(out, BackgroundMode::Checker);
  EXPECT_TRUE(sameRgb(rgbAt(view, 9, 2), checkerColour(9, 2)));
  EXPECT_TRUE(sameRgb(rgbAt(view, 10, 2), checkerColour(10, 2)));
  EXPECT_TRUE(sameRgb(rgbAt(viewImage(out, BackgroundMode::RendererColour), 10, 2), {200, 100, 50}));
  EXPECT_TRUE(sameRgb(rgbAt(view, 0, 0), {200, 100, 50}));
  // (3, 4) is in checker cell (0, 0), dark 40: (200 * 128 + 40 * 127 + 127) / 255 = 120, etc.
  EXPECT_TRUE(sameRgb(rgbAt(view, 3, 4), {120, 70, 45}));
  EXPECT_EQ(view.pixel(9, 2)[3], 255);
  EXPECT_EQ(rawImage(out).pixel(9, 2)[3], 0);  // the raw image keeps the coverage
}

TEST(TextDrawing, StaysInsideItsBoxAndScales) {
  Image image = makeImage(100, 40);
  const int width = textWidth("CPU", 2);
  EXPECT_EQ(width, 2 * textWidth("CPU", 1));
  drawText(image, 10, 5, "CPU", kColourWhite, 2);
  int drawn = 0;
  for (int y = 0; y < image.height; ++y) {
    for (int x = 0; x < image.width; ++x) {
      if (!(rgbAt(image, x, y) == kColourWhite)) continue;
      ++drawn;
      EXPECT_TRUE(x >= 10 && x < 10 + width && y >= 5 && y < 5 + kFontGlyphHeightUnits * 2) << x << "," << y;
    }
  }
  EXPECT_GT(drawn, 20);
  drawText(image, 90, 35, "\x01\x7f clipped", kColourWhite, 3);  // odd bytes and clipping are safe
}

TEST(Artifacts, WritesEveryFileAndTheRawImagesReloadExactly) {
  const ClassPair pair;
  const CompareResult r = compareDetailed(pair.cpu, pair.gl);
  const std::string dir = std::string(TWINRASTER_TEST_OUT) + "/compare/artifacts";
  const ArtifactPaths paths = writeCompareArtifacts(dir, pair.cpu, pair.gl, r, metricsToJson(r.metrics));
  for (const std::string& path : paths.all()) EXPECT_TRUE(std::filesystem::is_regular_file(path)) << path;
  const Image cpuPng = loadPng(paths.cpu);
  EXPECT_EQ(cpuPng.rgba, pair.cpu.rgba);
  const Image diffPng = loadPng(paths.diff);
  EXPECT_TRUE(sameRgb(rgbAt(diffPng, 1, 1), {188, 55, 84}));
}

}  // namespace
}  // namespace twr
