// The height-field section's reading (report/reading.cpp, compiled into this test):
// written from the numbers it is given, so made-up numbers must give the matching sentences:
// POM against plain parallax, the pick per view, the stair-steps, the layers POM needs to
// match and beat relief, the 720p ratio against the 2x target, and "not measured"; SSR's steps to
// linear_world's best error, its thickness leaks and its noise against samples.
#include "report/reading.h"

#include <gtest/gtest.h>

#include <string>

namespace twr::report {
namespace {

void expectContains(const std::string& text, const std::string& part) {
  EXPECT_NE(text.find(part), std::string::npos) << "expected \"" << part << "\" in:\n" << text;
}

ReportPoint point(const std::string& method, int lo, int hi, double rmse, double msMin, const std::string& backend = "cpu") {
  ReportPoint p;
  p.setting = method;
  if (lo > 0) {
    p.setting += ' ';
    p.setting += std::to_string(lo);
    p.setting += '-';
    p.setting += std::to_string(hi);
  }
  p.backend = backend;
  p.msMin = p.msMedian = msMin;
  p.frames = 3;
  p.vsReference.rmse = rmse;
  HeightFieldPointInfo info;
  info.method = method;
  info.layersMin = lo;
  info.layersMax = hi;
  info.interiorPixels = 1000;
  info.silhouetteApproxOnly = 12;
  info.silhouetteReferenceOnly = 34;
  p.heightField = info;
  return p;
}

// One view: the mesh, normal_map, parallax, and steep / relief / POM at 8-32 and 32-128 with
// the errors given.
HeightFieldView view(const std::string& field, int angle, double parallax, double steep8, double relief8, double pom8,
                     double steep32, double relief32, double pom32) {
  HeightFieldView v;
  v.field = field;
  v.angleDeg = angle;
  v.result.id = "height_fields_" + field + "_" + std::to_string(angle);
  auto& pts = v.result.points;
  pts.push_back(point(kTrueGeometry, 0, 0, 3.0, 100.0));
  pts.push_back(point("normal_map", 0, 0, 40.0, 1.0));
  pts.push_back(point("parallax", 0, 0, parallax, 1.2));
  pts.push_back(point("steep_parallax", 8, 32, steep8, 3.0));
  pts.push_back(point("relief", 8, 32, relief8, 4.0));
  pts.push_back(point("parallax_occlusion", 8, 32, pom8, 3.2));
  pts.push_back(point("steep_parallax", 32, 128, steep32, 8.0));
  pts.push_back(point("relief", 32, 128, relief32, 9.0));
  pts.push_back(point("parallax_occlusion", 32, 128, pom32, 8.2));
  return v;
}

HeightFieldSection section() {
  HeightFieldSection s;
  s.measured = true;
  s.referenceSamplesPerAxis = 4;
  //                            parallax steep8 relief8 pom8  steep32 relief32 pom32
  s.views.push_back(view("bricks", 45, 30.0, 12.0, 10.0, 10.1, 10.5, 9.9, 9.8));
  s.views.push_back(view("bricks", 70, 30.0, 20.0, 15.0, 16.0, 15.2, 14.9, 14.8));
  s.views.push_back(view("bricks", 85, 20.0, 25.0, 24.0, 24.5, 24.1, 24.0, 24.2));
  s.cost720p.measured = true;
  s.cost720p.scene = "bricks at 45 degrees";
  s.cost720p.cpuPath = "fast (avx2), 1 thread";
  s.cost720p.pomSetting = "parallax_occlusion 8-32";
  s.cost720p.normalMapMs = 10.0;
  s.cost720p.pomMs = 30.0;
  s.cost720p.frames = 9;
  return s;
}

TEST(ReportReadingHeightFields, PomAgainstParallaxFromTheNumbers) {
  const KnobReading r = readHeightFields(section());
  // 45: 10.1 < 30, 70: 16 < 30, 85: 24.5 > 20.
  expectContains(r.summary, "below plain parallax's in 2 of 3 views");
  expectContains(r.summary, "not at bricks 85");
  expectContains(r.detail, "bricks 85\xC2\xB0 24.50 vs 20.00 (not lower)");
}

TEST(ReportReadingHeightFields, PickIsTheFastestNearTheBest) {
  const KnobReading r = readHeightFields(section());
  // 45: best POM 32-128 9.8; within 9.8 * 1.1 + 0.25 = 11.03: relief 8-32 (4 ms), POM 8-32
  // (3.2 ms), steep 32-128, relief 32-128: the fastest is POM 8-32.
  expectContains(r.detail, "bricks 45\xC2\xB0: parallax_occlusion 8-32 (10.10 levels, 3.20 ms; best parallax_occlusion 32-128");
  // 85: parallax is best (20) and fastest among those near it.
  expectContains(r.detail, "bricks 85\xC2\xB0: parallax (20.00 levels");
}

TEST(ReportReadingHeightFields, StairStepsAndLayersToBeatRelief) {
  const KnobReading r = readHeightFields(section());
  // Steep minus POM: 45: +1.90 / +0.70, 70: +4.00 / +0.40, 85: +0.50 / -0.10.
  expectContains(r.detail, "bricks 70\xC2\xB0 +4.00/+0.40");
  expectContains(r.detail, "bricks: at 45\xC2\xB0, 70\xC2\xB0, 85\xC2\xB0 (most: 4.00 levels at 70\xC2\xB0 8-32)");
  // 45: POM 8-32 (10.1) within 0.25 of relief 8-32 (10.0), below it at 32-128 (9.8).
  expectContains(r.detail, "bricks 45\xC2\xB0 (relief 10.00 levels, 4.00 ms): within 0.25 levels at 8-32");
  expectContains(r.detail, "below it at 32-128 (9.80 levels");
  // 85: relief 24.0; POM 24.5 then 24.2: never below.
  expectContains(r.detail, "not below it up to 32-128");
}

TEST(ReportReadingHeightFields, CostAgainstTheTwoTimesTarget) {
  HeightFieldSection s = section();
  expectContains(readHeightFields(s).detail, "3.00x, beyond the issue's 2.00x");
  s.cost720p.pomMs = 15.0;
  expectContains(readHeightFields(s).detail, "1.50x, within the issue's 2.00x");
  expectContains(readHeightFields(s).summary, "POM at 720p costs 1.50x a normal-mapped frame");
}

TEST(ReportReadingHeightFields, SilhouettesAndFloorAreReported) {
  const KnobReading r = readHeightFields(section());
  expectContains(r.detail, "Parallax does not move silhouettes");
  expectContains(r.detail, "bricks 45\xC2\xB0 12/34 (interior 1000)");
  expectContains(r.detail, "bricks 45\xC2\xB0 3.00 (100.0 ms)");
  HeightFieldSection one = section();
  one.referenceSamplesPerAxis = 1;
  expectContains(readHeightFields(one).detail, "float against double only");
}

TEST(ReportReadingHeightFields, NotMeasured) {
  HeightFieldSection s;
  s.skipped = "no GL";
  EXPECT_EQ(readHeightFields(s).summary, "Not measured: no GL");
}

SsrMarchRow marchRow(const std::string& march, int steps, double ms, double mean) {
  SsrMarchRow r;
  r.march = march;
  r.maxSteps = steps;
  r.thickness = 0.1;
  r.msMedian = ms;
  r.meanAbs = mean;
  return r;
}

TEST(ReportReadingSsr, StepsToLinearsBestLeaksAndNoiseFromTheNumbers) {
  SsrSection s;
  s.reflecting = 5000;
  s.blindRays = 400;
  s.blindErrorShare = 0.6;
  s.referenceSamples = 256;
  s.steps = {marchRow("linear_world", 16, 10.0, 9.0), marchRow("linear_world", 64, 20.0, 4.0),
             marchRow("linear_world", 256, 60.0, 3.0), marchRow("hiz", 8, 5.0, 6.0), marchRow("hiz", 16, 6.0, 3.1),
             marchRow("hiz", 64, 8.0, 2.0), marchRow("dda_screen", 64, 30.0, 5.0)};
  SsrMarchRow thin = marchRow("linear_world", 64, 20.0, 5.0), thick = marchRow("linear_world", 64, 20.0, 6.0);
  thin.thickness = 0.02;
  thin.missedVisible = 300;
  thick.thickness = 0.8;
  thick.falseHits = 120;
  s.thickness = {thin, thick};
  SsrSamplesRow one, many;
  one.samples = 1;
  one.msMedian = 10.0;
  one.meanAbs = 16.0;
  many.samples = 64;
  many.msMedian = 400.0;
  many.meanAbs = 2.0;  // 16 -> 2 over 6 doublings: 0.5^(1/2) each = 0.71
  many.marchMeanAbs = 1.25;
  s.samples = {one, many};
  const KnobReading r = readSsr(s);
  expectContains(r.summary, "linear_world's best error is 3.00 levels");
  expectContains(r.summary, "hiz reaches it in 16 steps (6.0 ms a frame) where linear_world needs 256 (60.0 ms)");
  expectContains(r.summary, "60 % of the best march's error");
  expectContains(r.detail, "dda_screen not within the steps tried");
  expectContains(r.detail, "linear_world at 0.80 lights 120 pixels");
  expectContains(r.detail, "linear_world at 0.02 leaves 300 pixels");
  expectContains(r.detail, "scales the error by 0.71");
  expectContains(r.detail, "the march alone is 1.25 levels off at 64 samples");
  expectContains(r.detail, "hiz 8: 6.00, 16: 3.10, 64: 2.00");
}

TEST(ReportReadingSsr, NotMeasured) {
  SsrSection s;
  s.skipped = "this build has no ray tracer";
  EXPECT_EQ(readSsr(s).summary, "Not measured: this build has no ray tracer");
}

}  // namespace
}  // namespace twr::report
