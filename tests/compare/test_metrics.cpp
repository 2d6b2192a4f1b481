// Metrics, classification, thresholds and JSON of compare/, on hand-built outputs whose
// expected numbers are worked out in the comments.
#include "compare/metrics.h"
#include "compare/report_json.h"
#include "compare/thresholds.h"
#include "scene/errors.h"
#include "synthetic_outputs.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>

namespace twr {
namespace {

using testing::clearPixel;
using testing::makeSolidOutput;
using testing::pixelIndex;
using testing::rgbaAt;

TEST(CompareMetrics, IdenticalImagesGiveZerosAndPsnrCap) {
  const RenderOutput cpu = makeSolidOutput(4, 3, 10, 20, 30);
  const CompareResult r = compareDetailed(cpu, cpu);
  const CompareMetrics& m = r.metrics;
  EXPECT_EQ(m.width, 4);
  EXPECT_EQ(m.height, 3);
  EXPECT_EQ(m.comparedPixels, 12u);
  EXPECT_EQ(m.coveredCpu, 12u);
  EXPECT_EQ(m.coveredGl, 12u);
  EXPECT_EQ(m.bothCovered, 12u);
  EXPECT_EQ(m.coverageMismatch, 0u);
  EXPECT_EQ(m.maxAbsDiff, 0);
  EXPECT_FALSE(m.hasMaxAbsDiffAt());
  EXPECT_EQ(m.meanAbsDiff, 0.0);
  EXPECT_EQ(m.rmse, 0.0);
  EXPECT_EQ(m.psnr, 100.0);
  EXPECT_EQ(m.over1 + m.over3 + m.over12, 0u);
  EXPECT_EQ(m.depthMaxDiff, 0.0);
  EXPECT_EQ(m.nanPixels, 0u);
  EXPECT_EQ(m.classCoverage + m.classDepth + m.classShading, 0u);
  for (PixelClass c : r.pixels.pixelClass) EXPECT_EQ(c, PixelClass::Same);
}

TEST(CompareMetrics, CoverageIsTheTriangleIdNotAlpha) {
  RenderOutput cpu = makeSolidOutput(4, 1, 10, 20, 30);
  RenderOutput gl = cpu;
  // Pixel 0: empty on both, under an opaque background (alpha 255). Pixel 1: empty on GL only,
  // under a transparent background. Pixel 2: a triangle drawn with alpha 0 would still count.
  clearPixel(cpu, 0, 0);
  clearPixel(gl, 0, 0);
  rgbaAt(cpu, 0, 0)[3] = rgbaAt(gl, 0, 0)[3] = 255;
  clearPixel(gl, 1, 0);
  rgbaAt(cpu, 2, 0)[3] = 0;
  const CompareResult r = compareDetailed(cpu, gl);
  EXPECT_EQ(r.pixels.pixelClass[0], PixelClass::Empty);
  EXPECT_EQ(r.pixels.pixelClass[1], PixelClass::CoverageCpu);
  EXPECT_EQ(r.pixels.pixelClass[2], PixelClass::Same);
  EXPECT_EQ(r.metrics.coveredCpu, 3u);
  EXPECT_EQ(r.metrics.coveredGl, 2u);

  // Without triangle ids (an analytic reference) alpha > 0 is all there is.
  cpu.triangleId.clear();
  const CompareResult noIds = compareDetailed(cpu, gl);
  EXPECT_EQ(noIds.pixels.pixelClass[0], PixelClass::CoverageCpu);  // alpha 255 reads as covered
  EXPECT_EQ(noIds.pixels.pixelClass[2], PixelClass::CoverageGl);   // alpha 0 reads as empty
  EXPECT_EQ(noIds.metrics.coveredCpu, 3u);
}

TEST(CompareMetrics, OnePixelOffByTwoIsOver1AtItsTopLeftCoordinates) {
  const RenderOutput cpu = makeSolidOutput(5, 4, 100, 100, 100);
  RenderOutput gl = cpu;
  rgbaAt(gl, 3, 1)[1] = 102;  // column 3, second row from the top, green +2
  const CompareResult r = compareDetailed(cpu, gl);
  const CompareMetrics& m = r.metrics;
  EXPECT_EQ(m.maxAbsDiff, 2);
  EXPECT_EQ(m.maxAbsDiffX, 3);
  EXPECT_EQ(m.maxAbsDiffY, 1);
  EXPECT_EQ(m.over1, 1u);
  EXPECT_EQ(m.over3, 0u);
  EXPECT_EQ(m.over12, 0u);
  // 20 pixels x 3 channels = 60 samples, one of them 2: mean 2/60, rmse sqrt(4/60).
  EXPECT_DOUBLE_EQ(m.meanAbsDiff, 2.0 / 60.0);
  EXPECT_DOUBLE_EQ(m.rmse, std::sqrt(4.0 / 60.0));
  EXPECT_DOUBLE_EQ(m.psnr, 20.0 * std::log10(255.0 / std::sqrt(4.0 / 60.0)));  // about 59.89 dB
  EXPECT_DOUBLE_EQ(m.over1Pct(), 5.0);  // 1 of 20
  // Same triangle id on both sides: a shading difference.
  EXPECT_EQ(m.classShading, 1u);
  EXPECT_EQ(m.classDepth, 0u);
  EXPECT_EQ(r.pixels.pixelClass[pixelIndex(cpu, 3, 1)], PixelClass::Shading);
  EXPECT_EQ(r.pixels.diffLevels[pixelIndex(cpu, 3, 1)], 2);
  EXPECT_EQ(r.pixels.diffLevels[pixelIndex(cpu, 1, 3)], 0);
}

TEST(CompareMetrics, OverCountsUseExclusiveBoundsOnTheLargestChannel) {
  const RenderOutput cpu = makeSolidOutput(6, 1, 50, 50, 50);
  RenderOutput gl = cpu;
  const int diffs[6] = {1, 2, 3, 4, 12, 13};
  for (int x = 0; x < 6; ++x) rgbaAt(gl, x, 0)[x % 3] = static_cast<std::uint8_t>(50 + diffs[x]);
  rgbaAt(gl, 5, 0)[0] = 45;  // a smaller second channel difference does not change the max (13)
  const CompareMetrics m = compare(cpu, gl);
  EXPECT_EQ(m.over1, 5u);   // 2, 3, 4, 12, 13
  EXPECT_EQ(m.over3, 3u);   // 4, 12, 13
  EXPECT_EQ(m.over12, 1u);  // 13
  EXPECT_EQ(m.maxAbsDiff, 13);
  EXPECT_EQ(m.maxAbsDiffX, 5);
  EXPECT_EQ(m.maxAbsDiffY, 0);
  // Channel sums: 1 + 2 + 3 + 4 + 12 + 13 + 5 = 40 over 18 samples.
  EXPECT_DOUBLE_EQ(m.meanAbsDiff, 40.0 / 18.0);
  EXPECT_DOUBLE_EQ(m.rmse, std::sqrt((1.0 + 4 + 9 + 16 + 144 + 169 + 25) / 18.0));
}

TEST(CompareMetrics, TiedMaximumReportsTheFirstPixelInRowMajorOrder) {
  const RenderOutput cpu = makeSolidOutput(3, 3, 0, 0, 0);
  RenderOutput gl = cpu;
  rgbaAt(gl, 0, 2)[2] = 7;
  rgbaAt(gl, 2, 1)[0] = 7;  // row 1 comes before row 2
  const CompareMetrics m = compare(cpu, gl);
  EXPECT_EQ(m.maxAbsDiffX, 2);
  EXPECT_EQ(m.maxAbsDiffY, 1);
}

TEST(CompareMetrics, CoverageOnlyPixelsAreCountedApartFromColour) {
  const RenderOutput base = makeSolidOutput(4, 2, 200, 0, 0);
  RenderOutput cpu = base, gl = base;
  clearPixel(gl, 0, 0);  // CPU only
  clearPixel(gl, 1, 1);  // CPU only
  clearPixel(cpu, 3, 0); // GL only
  rgbaAt(gl, 0, 0)[0] = 0;  // a huge colour step under a coverage pixel is not a colour diff
  clearPixel(cpu, 2, 1);
  clearPixel(gl, 2, 1);  // neither
  const CompareResult r = compareDetailed(cpu, gl);
  const CompareMetrics& m = r.metrics;
  EXPECT_EQ(m.coveredCpu, 6u);  // 8 - (3,0) - (2,1)
  EXPECT_EQ(m.coveredGl, 5u);   // 8 - (0,0) - (1,1) - (2,1)
  EXPECT_EQ(m.bothCovered, 4u);
  EXPECT_EQ(m.coverageCpuOnly, 2u);
  EXPECT_EQ(m.coverageGlOnly, 1u);
  EXPECT_EQ(m.coverageMismatch, 3u);
  EXPECT_EQ(m.classCoverage, 3u);
  EXPECT_EQ(m.maxAbsDiff, 0);
  EXPECT_EQ(m.psnr, 100.0);
  EXPECT_EQ(m.coveredEither(), 7u);
  EXPECT_DOUBLE_EQ(m.coverageMismatchPer10k(), 10000.0 * 3.0 / 7.0);
  EXPECT_EQ(r.pixels.pixelClass[pixelIndex(cpu, 0, 0)], PixelClass::CoverageCpu);
  EXPECT_EQ(r.pixels.pixelClass[pixelIndex(cpu, 3, 0)], PixelClass::CoverageGl);
  EXPECT_EQ(r.pixels.pixelClass[pixelIndex(cpu, 2, 1)], PixelClass::Empty);
  EXPECT_EQ(r.pixels.diffLevels[pixelIndex(cpu, 0, 0)], 0);
}

TEST(CompareMetrics, TriangleIdsSeparateDepthFromShading) {
  const RenderOutput cpu = makeSolidOutput(3, 1, 80, 80, 80);
  RenderOutput gl = cpu;
  rgbaAt(gl, 0, 0)[0] = 90;                 // same triangle, other colour: shading
  rgbaAt(gl, 1, 0)[0] = 90;                 // other triangle won: depth
  gl.triangleId[pixelIndex(gl, 1, 0)] = 7;
  gl.triangleId[pixelIndex(gl, 2, 0)] = 9;  // other triangle, same colour: not a differing pixel
  const CompareResult r = compareDetailed(cpu, gl);
  EXPECT_TRUE(r.metrics.triangleIdsAvailable);
  EXPECT_EQ(r.metrics.classShading, 1u);
  EXPECT_EQ(r.metrics.classDepth, 1u);
  EXPECT_EQ(r.pixels.pixelClass[0], PixelClass::Shading);
  EXPECT_EQ(r.pixels.pixelClass[1], PixelClass::Depth);
  EXPECT_EQ(r.pixels.pixelClass[2], PixelClass::Same);
}

TEST(CompareMetrics, DepthToleranceDecidesWhenTriangleIdsAreMissing) {
  RenderOutput cpu = makeSolidOutput(3, 1, 80, 80, 80, 0.5f);
  RenderOutput gl = cpu;
  cpu.triangleId.clear();  // ids unavailable on one side: depth decides everywhere
  for (int x = 0; x < 3; ++x) rgbaAt(gl, x, 0)[2] = 70;
  gl.depth[0] = 0.50005f;  // 5e-5 <= 1e-4: same surface, shading
  gl.depth[1] = 0.6f;      // 0.1 > 1e-4: different surface, depth
  const CompareResult r = compareDetailed(cpu, gl);
  EXPECT_FALSE(r.metrics.triangleIdsAvailable);
  EXPECT_EQ(r.pixels.pixelClass[0], PixelClass::Shading);
  EXPECT_EQ(r.pixels.pixelClass[1], PixelClass::Depth);
  EXPECT_EQ(r.pixels.pixelClass[2], PixelClass::Shading);
  EXPECT_DOUBLE_EQ(r.metrics.depthMaxDiff, double(0.6f) - double(0.5f));

  CompareOptions looser;
  looser.depthTolerance = 0.2;  // now 0.1 is within tolerance
  EXPECT_EQ(compare(cpu, gl, looser).classDepth, 0u);
}

TEST(CompareMetrics, NoTriangleIdsOnOneSideFallsBackToDepth) {
  const RenderOutput cpu = makeSolidOutput(2, 1, 80, 80, 80, 0.25f);
  RenderOutput gl = cpu;
  rgbaAt(gl, 0, 0)[0] = 99;
  rgbaAt(gl, 1, 0)[0] = 99;
  gl.triangleId.clear();  // an output without ids (an analytic reference): covered by alpha
  gl.depth[1] = 0.75f;
  const CompareResult r = compareDetailed(cpu, gl);
  EXPECT_EQ(r.pixels.pixelClass[0], PixelClass::Shading);
  EXPECT_EQ(r.pixels.pixelClass[1], PixelClass::Depth);
}

TEST(CompareMetrics, DifferThresholdKeepsSmallDifferencesOutOfTheClasses) {
  const RenderOutput cpu = makeSolidOutput(2, 1, 80, 80, 80);
  RenderOutput gl = cpu;
  rgbaAt(gl, 0, 0)[0] = 82;  // 2 levels: not > 2
  rgbaAt(gl, 1, 0)[0] = 83;  // 3 levels: > 2
  CompareOptions options;
  options.differMinLevels = 2;
  const CompareResult r = compareDetailed(cpu, gl, options);
  EXPECT_EQ(r.pixels.pixelClass[0], PixelClass::Same);
  EXPECT_EQ(r.pixels.pixelClass[1], PixelClass::Shading);
  EXPECT_EQ(r.metrics.classShading, 1u);
  EXPECT_EQ(r.metrics.over1, 2u);  // the metrics do not depend on the class threshold
}

TEST(CompareMetrics, LinePixelsOnEitherSideAreExcludedFromEverything) {
  const RenderOutput base = makeSolidOutput(3, 2, 10, 10, 10);
  RenderOutput cpu = base, gl = base;
  rgbaAt(gl, 0, 0)[0] = 255;  // would be a 245-level difference
  cpu.lineMask[pixelIndex(cpu, 0, 0)] = 1;
  clearPixel(gl, 2, 1);       // would be a coverage mismatch
  gl.lineMask[pixelIndex(gl, 2, 1)] = 1;
  const CompareResult r = compareDetailed(cpu, gl);
  const CompareMetrics& m = r.metrics;
  EXPECT_EQ(m.excludedLinePixels, 2u);
  EXPECT_EQ(m.comparedPixels, 4u);
  EXPECT_EQ(m.coveredCpu, 4u);
  EXPECT_EQ(m.coveredGl, 4u);
  EXPECT_EQ(m.coverageMismatch, 0u);
  EXPECT_EQ(m.maxAbsDiff, 0);
  EXPECT_EQ(r.pixels.pixelClass[pixelIndex(cpu, 0, 0)], PixelClass::ExcludedLine);
  EXPECT_EQ(r.pixels.pixelClass[pixelIndex(cpu, 2, 1)], PixelClass::ExcludedLine);

  RenderOutput noMask = gl;
  noMask.lineMask.clear();  // an empty mask means "no lines"
  EXPECT_EQ(compare(cpu, noMask).excludedLinePixels, 1u);
}

// The excluded pixels are bounded and the two sides' lines compared: how much of the frame is
// left out, and where only one renderer drew a line.
TEST(CompareMetrics, LinePixelsAreCountedPerSideAndHeldToTheirOwnLimits) {
  const RenderOutput base = makeSolidOutput(4, 5, 10, 10, 10);  // 20 pixels
  RenderOutput cpu = base, gl = base;
  for (const int x : {0, 1, 2}) cpu.lineMask[pixelIndex(cpu, x, 0)] = 1;
  for (const int x : {1, 2, 3}) gl.lineMask[pixelIndex(gl, x, 0)] = 1;
  const CompareMetrics m = compare(cpu, gl);
  EXPECT_EQ(m.linePixelsCpu, 3u);
  EXPECT_EQ(m.linePixelsGl, 3u);
  EXPECT_EQ(m.excludedLinePixels, 4u);
  EXPECT_EQ(m.lineMismatch, 2u);  // x = 0 (CPU only) and x = 3 (GL only)
  EXPECT_DOUBLE_EQ(m.excludedLinePct(), 20.0);
  EXPECT_DOUBLE_EQ(m.lineMismatchPct(), 50.0);

  Thresholds limits;
  limits.maxExcludedLinePct = 20.0;  // inclusive
  limits.maxLineMismatchPct = 50.0;
  EXPECT_TRUE(checkThresholds(m, limits).empty());
  limits.maxExcludedLinePct = 19.0;
  limits.maxLineMismatchPct = 49.0;
  const std::vector<ThresholdViolation> v = checkThresholds(m, limits);
  ASSERT_EQ(v.size(), 2u);
  EXPECT_EQ(v[0].key, "max_excluded_line_pct");
  EXPECT_EQ(v[1].key, "max_line_mismatch_pct");
  EXPECT_NE(v[1].message.find("CPU 3, GL 3"), std::string::npos) << v[1].message;

  const nlohmann::json j = metricsToJson(m);
  EXPECT_EQ(j["line_pixels_cpu"], 3);
  EXPECT_EQ(j["line_pixels_gl"], 3);
  EXPECT_EQ(j["line_mismatch"], 2);
  EXPECT_DOUBLE_EQ(j["line_mismatch_pct"].get<double>(), 50.0);
  EXPECT_DOUBLE_EQ(j["excluded_line_pct"].get<double>(), 20.0);

  const CompareMetrics none = compare(base, base);  // no lines: nothing left out, nothing parts
  EXPECT_EQ(none.excludedLinePct(), 0.0);
  EXPECT_EQ(none.lineMismatchPct(), 0.0);
}

TEST(CompareMetrics, NonFiniteCpuDepthIsCountedEverywhereAndNeverReachesAMetric) {
  RenderOutput cpu = makeSolidOutput(4, 1, 10, 10, 10);
  const RenderOutput gl = cpu;
  cpu.depth[0] = std::numeric_limits<float>::quiet_NaN();
  cpu.depth[1] = std::numeric_limits<float>::infinity();
  cpu.depth[2] = -std::numeric_limits<float>::infinity();
  cpu.lineMask[2] = 1;  // counted even under a line
  const CompareMetrics m = compare(cpu, gl);
  EXPECT_EQ(m.nanPixels, 3u);
  EXPECT_EQ(m.depthMaxDiff, 0.0);
  EXPECT_TRUE(std::isfinite(m.psnr));
}

TEST(CompareMetrics, NothingCoveredGivesZerosNotNaN) {
  RenderOutput cpu = makeSolidOutput(2, 2, 0, 0, 0);
  for (int y = 0; y < 2; ++y)
    for (int x = 0; x < 2; ++x) clearPixel(cpu, x, y);
  const CompareMetrics m = compare(cpu, cpu);
  EXPECT_EQ(m.bothCovered, 0u);
  EXPECT_EQ(m.meanAbsDiff, 0.0);
  EXPECT_EQ(m.psnr, 100.0);
  EXPECT_EQ(m.over1Pct(), 0.0);
  EXPECT_EQ(m.coverageMismatchPer10k(), 0.0);
}

TEST(CompareMetrics, MalformedInputThrowsInputError) {
  const RenderOutput cpu = makeSolidOutput(4, 4, 0, 0, 0);
  EXPECT_THROW(compare(cpu, makeSolidOutput(4, 3, 0, 0, 0)), InputError);
  RenderOutput shortRgba = cpu;
  shortRgba.rgba.pop_back();
  EXPECT_THROW(compare(cpu, shortRgba), InputError);
  RenderOutput badDepth = cpu;
  badDepth.depth.resize(3);
  EXPECT_THROW(compare(badDepth, cpu), InputError);
  EXPECT_THROW(compare(RenderOutput{}, RenderOutput{}), InputError);
  CompareOptions badOptions;
  badOptions.depthTolerance = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(compare(cpu, cpu, badOptions), InputError);
  try {
    compare(cpu, makeSolidOutput(4, 3, 0, 0, 0));
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("4x3"), std::string::npos) << e.what();
  }
}

// One pixel of 20 off by 2 (see OnePixelOffByTwo...), one CPU-only pixel.
CompareMetrics smallDifferenceMetrics() {
  const RenderOutput cpu = makeSolidOutput(5, 4, 100, 100, 100);
  RenderOutput gl = cpu;
  rgbaAt(gl, 3, 1)[1] = 102;
  clearPixel(gl, 0, 3);
  return compare(cpu, gl);
}

TEST(CompareThresholds, ReportsEachViolatedLimitWithItsKey) {
  const CompareMetrics m = smallDifferenceMetrics();  // over_1 = 1 of 19 both covered
  Thresholds t;
  t.maxOver1Pct = 0.1;          // 5.26 % > 0.1: violated
  t.maxAbsDiff = 3.0;           // 2 <= 3: passes
  t.maxCoverageMismatch = 0.0;  // 1 > 0: violated
  t.minPsnr = 80.0;             // 20 log10(255 / sqrt(4 / 57)) = 59.67 < 80: violated
  t.maxNanPixels = 0.0;         // passes
  const std::vector<ThresholdViolation> v = checkThresholds(m, t);
  ASSERT_EQ(v.size(), 3u);
  EXPECT_EQ(v[0].key, "max_over_1_pct");
  EXPECT_DOUBLE_EQ(v[0].value, 100.0 / 19.0);
  EXPECT_EQ(v[1].key, "min_psnr");
  EXPECT_EQ(v[2].key, "max_coverage_mismatch");
  EXPECT_NE(v[2].message.find("1 CPU only"), std::string::npos) << v[2].message;

  Thresholds limitsAtTheValue;  // inclusive: equal to the limit passes
  limitsAtTheValue.maxAbsDiff = 2.0;
  limitsAtTheValue.maxCoverageMismatch = 1.0;
  EXPECT_TRUE(checkThresholds(m, limitsAtTheValue).empty());
  limitsAtTheValue.maxAbsDiff = 1.0;
  const auto tight = checkThresholds(m, limitsAtTheValue);
  ASSERT_EQ(tight.size(), 1u);
  EXPECT_NE(tight[0].message.find("at (3, 1"), std::string::npos) << tight[0].message;
}

TEST(CompareThresholds, IssueTargetsAndValidation) {
  const Thresholds unclipped = issueTargets(false);
  EXPECT_EQ(unclipped.maxCoverageMismatch, 0.0);
  EXPECT_FALSE(unclipped.maxCoverageMismatchPer10k.has_value());
  const Thresholds clipped = issueTargets(true);
  EXPECT_EQ(clipped.maxCoverageMismatchPer10k, 1.0);
  EXPECT_EQ(clipped.maxOver1Pct, 0.1);
  EXPECT_EQ(clipped.maxAbsDiff, 3.0);
  EXPECT_EQ(clipped.maxNanPixels, 0.0);
  EXPECT_EQ(clipped.maxExcludedLinePct, 10.0);
  EXPECT_EQ(unclipped.maxLineMismatchPct, 15.0);
  EXPECT_TRUE(checkThresholds(compare(makeSolidOutput(2, 2, 1, 2, 3), makeSolidOutput(2, 2, 1, 2, 3)), clipped).empty());

  Thresholds negative;
  negative.maxRmse = -1.0;
  EXPECT_THROW(validateThresholds(negative), InputError);
  EXPECT_NO_THROW(validateThresholds(clipped));
}

TEST(CompareJson, HasEveryIssueKeyWithTheMetricValues) {
  const CompareMetrics m = smallDifferenceMetrics();
  const nlohmann::json j = metricsToJson(m);
  for (const char* key : {"width", "height", "covered_cpu", "covered_gl", "coverage_mismatch", "max_abs_diff",
                          "max_abs_diff_at", "mean_abs_diff", "rmse", "psnr", "over_1", "over_3", "over_12",
                          "depth_max_diff", "nan_pixels", "class_coverage", "class_depth", "class_shading", "class_decision",
                          "excluded_line_pixels"}) {
    EXPECT_TRUE(j.contains(key)) << key;
  }
  EXPECT_EQ(j["width"], 5);
  EXPECT_EQ(j["covered_cpu"], 20);
  EXPECT_EQ(j["covered_gl"], 19);
  EXPECT_EQ(j["coverage_mismatch"], 1);
  EXPECT_EQ(j["max_abs_diff"], 2);
  EXPECT_EQ(j["max_abs_diff_at"], nlohmann::json::array({3, 1}));
  EXPECT_EQ(j["over_1"], 1);
  EXPECT_EQ(j["class_shading"], 1);
  EXPECT_EQ(j["class_coverage"], 1);
  EXPECT_TRUE(metricsToJson(compare(makeSolidOutput(1, 1, 0, 0, 0), makeSolidOutput(1, 1, 0, 0, 0)))["max_abs_diff_at"]
                  .is_null());
}

TEST(CompareJson, MergesRunInfoAndThresholdsButNeverOverwritesAMetric) {
  const CompareMetrics m = smallDifferenceMetrics();
  nlohmann::json j = metricsToJson(m);
  CompareRunInfo info;
  info.cpuMs = 12.5;
  info.glMs = 3.25;
  info.glRenderer = "llvmpipe (LLVM 15.0.6, 256 bits)";
  info.glVersion = "3.3 (Core Profile) Mesa 22.3.6";
  mergeExtraKeys(j, runInfoToJson(info));
  Thresholds t;
  t.maxCoverageMismatch = 0.0;
  mergeExtraKeys(j, {{"thresholds", thresholdsToJson(t, checkThresholds(m, t))}});
  EXPECT_EQ(j["cpu_ms"], 12.5);
  EXPECT_EQ(j["gl_ms"], 3.25);
  EXPECT_EQ(j["gl_renderer"], info.glRenderer);
  EXPECT_FALSE(j.contains("repeat"));  // unset optionals are left out
  EXPECT_EQ(j["thresholds"]["limits"]["max_coverage_mismatch"], 0.0);
  EXPECT_EQ(j["thresholds"]["passed"], false);
  EXPECT_EQ(j["thresholds"]["violations"][0]["key"], "max_coverage_mismatch");
  EXPECT_THROW(mergeExtraKeys(j, {{"rmse", 0.0}}), std::invalid_argument);
  EXPECT_EQ(j["rmse"], m.rmse);
}

TEST(CompareJson, WritesAFileThatReadsBack) {
  const std::filesystem::path path = std::filesystem::path(TWINRASTER_TEST_OUT) / "compare" / "json" / "metrics.json";
  const nlohmann::json j = metricsToJson(smallDifferenceMetrics());
  writeJsonFile(path.string(), j);
  std::ifstream file(path);
  EXPECT_EQ(nlohmann::json::parse(file), j);
  EXPECT_THROW(writeJsonFile("/proc/twinraster-not-writable/metrics.json", j), InputError);
}

}  // namespace
}  // namespace twr
