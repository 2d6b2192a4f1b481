// Per-pixel comparison of two RenderOutputs (CPU and GL): metrics and a per-pixel class.
//
// Which pixels each number is over (see docs/compare.md for the full table):
// - A pixel is "excluded" when either lineMask is 1 there (TBN debug lines); excluded pixels
//   count only in excludedLinePixels, the line counts and nanPixels, nowhere else. How many
//   are excluded, and where the two sides' lines part, have limits of their own (thresholds.h).
// - A pixel is "covered" by a backend when a triangle was drawn there: its triangle id is not
//   kNoTriangle (coveredAt; alpha > 0 for an output without ids, such as the analytic-sphere
//   reference). Alpha is not coverage: the background has the scene's alpha, 1 by default.
// - Colour differences are over RGB only; alpha is never diffed.
//   A pixel's difference is the largest of its three channel differences, in 0..255 levels.
// - Colour and depth metrics are over pixels both backends covered ("bothCovered"). With
//   CompareOptions::compareBackground the pixels neither covered (the sky box) are compared
//   too, into metrics of their own (backgroundCompared, backgroundMaxAbsDiff, backgroundOver1).
// Buffers are top row first, so (x, y) has a top-left origin.
#pragma once

#include "scene/renderer.h"

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace twr {

// PSNR reported for identical images (and the cap for nearly identical ones), decibels.
inline constexpr double kPsnrCapDb = 100.0;
// Largest 8-bit channel value, levels.
inline constexpr double kMaxChannelLevel = 255.0;
// Default depth tolerance for the depth-versus-shading class when triangle ids are not
// available: window depth units (depth in [0, 1]); a pixel is "depth" when
// |depthCpu - depthGl| > tolerance (exclusive). 1e-4 is about 0.1 world units at distance 10
// with near 0.1 and far 100, far above interpolation noise (~1e-6) and 24-bit steps (6e-8).
inline constexpr double kDefaultDepthTolerance = 1e-4;
// Default: a both-covered pixel "differs" (and gets a class) when its difference is > 0 levels.
inline constexpr int kDefaultDifferMinLevels = 0;

struct CompareOptions {
  // A both-covered pixel differs when its difference (levels) is > this (exclusive).
  int differMinLevels = kDefaultDifferMinLevels;
  // Window depth units, exclusive; used only where triangle ids are unavailable.
  double depthTolerance = kDefaultDepthTolerance;
  // Pixels neither backend covered are compared too: the scene draws a sky box there
  // (scene/sky_view.h, drawsSky). They get colour metrics of their own (background*), a
  // diffLevels entry, and the class same or shading.
  bool compareBackground = false;
};

// What happened at one pixel. Every pixel has exactly one class.
enum class PixelClass : std::uint8_t {
  Empty,         // neither backend covered it
  Same,          // both covered, difference <= differMinLevels
  CoverageCpu,   // covered by the CPU only  (class "coverage")
  CoverageGl,    // covered by GL only       (class "coverage")
  Depth,         // both covered, differs, a different surface won
  Shading,       // both covered, differs, the same surface
  ExcludedLine,  // a TBN debug line on either side
  // Both covered, differs, the same surface, and a binary decision went the other way there (a
  // shadow tap, an SSR hit, a parallax layer count, a mip level: compare/decisions.h). Only
  // classifyDecisions gives it; compareDetailed calls such a pixel Shading.
  Decision,
};

// Per-pixel results, width * height entries each, top row first. The GUI's pixel inspector
// and the image builders read these.
struct PixelAnalysis {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> diffLevels;  // max RGB channel |cpu - gl|; 0 unless both covered
  std::vector<PixelClass> pixelClass;

  std::size_t index(int x, int y) const { return static_cast<std::size_t>(y) * width + x; }
};

struct CompareMetrics {
  int width = 0;
  int height = 0;
  std::uint64_t comparedPixels = 0;       // width * height - excludedLinePixels
  std::uint64_t excludedLinePixels = 0;   // lineMask set on either side
  std::uint64_t linePixelsCpu = 0;        // pixels the CPU's lineMask marks
  std::uint64_t linePixelsGl = 0;         // pixels GL's lineMask marks
  std::uint64_t lineMismatch = 0;         // pixels exactly one side's lineMask marks
  std::uint64_t coveredCpu = 0;           // compared pixels the CPU covered (coveredAt)
  std::uint64_t coveredGl = 0;            // compared pixels GL covered
  std::uint64_t bothCovered = 0;          // compared pixels covered by both
  std::uint64_t backgroundCompared = 0;   // compared pixels neither covered, with compareBackground
  int backgroundMaxAbsDiff = 0;           // levels 0..255, over backgroundCompared
  std::uint64_t backgroundOver1 = 0;      // backgroundCompared pixels with difference > 1 level
  std::uint64_t coverageCpuOnly = 0;
  std::uint64_t coverageGlOnly = 0;
  std::uint64_t coverageMismatch = 0;     // coverageCpuOnly + coverageGlOnly
  int maxAbsDiff = 0;                     // levels 0..255, over bothCovered
  int maxAbsDiffX = -1;                   // first pixel (row-major scan) reaching maxAbsDiff;
  int maxAbsDiffY = -1;                   //   -1, -1 when maxAbsDiff == 0
  double meanAbsDiff = 0.0;               // levels, mean over bothCovered pixels x 3 channels
  double rmse = 0.0;                      // levels, same population as meanAbsDiff
  double psnr = kPsnrCapDb;               // dB, 20 log10(255 / rmse), at most kPsnrCapDb
  std::uint64_t over1 = 0;                // bothCovered pixels with difference > 1 level
  std::uint64_t over3 = 0;                // ... > 3 levels
  std::uint64_t over12 = 0;               // ... > 12 levels
  bool depthAvailable = false;            // both depth buffers present
  double depthMaxDiff = 0.0;              // window depth, over bothCovered with finite depths
  std::uint64_t nanPixels = 0;            // all pixels whose CPU depth is NaN or +-Inf
  bool triangleIdsAvailable = false;      // both triangle-id buffers present
  std::uint64_t classCoverage = 0;        // == coverageMismatch
  std::uint64_t classDepth = 0;
  std::uint64_t classShading = 0;
  std::uint64_t classDecision = 0;        // classifyDecisions (compare/decisions.h); 0 before it
  CompareOptions options;                 // what the classification used

  bool hasMaxAbsDiffAt() const { return maxAbsDiffX >= 0; }
  // over1 as a percentage of bothCovered (0 when nothing is covered by both).
  double over1Pct() const;
  // backgroundOver1 as a percentage of backgroundCompared (0 when none was compared).
  double backgroundOver1Pct() const;
  // coverageMismatch per 10,000 pixels covered by either backend (0 when none is covered).
  double coverageMismatchPer10k() const;
  std::uint64_t coveredEither() const { return bothCovered + coverageMismatch; }
  // excludedLinePixels as a percentage of the frame (0 for an empty frame): how much of it
  // no other number looks at.
  double excludedLinePct() const;
  // lineMismatch as a percentage of excludedLinePixels (0 when no line is drawn): where the
  // two renderers' debug lines part.
  double lineMismatchPct() const;
};

struct CompareResult {
  CompareMetrics metrics;
  PixelAnalysis pixels;
};

// Throws InputError when the two outputs differ in size, are empty, or a buffer has the wrong
// length (rgba must be width * height * 4; depth, triangleId and lineMask width * height or
// empty, where empty means "not available").
// Throws InputError ("<context>: <name> depth buffer has N entries, expected 0 or M") unless
// `out` holds four rgba bytes per pixel of `pixelCount` and one depth, triangle id and line
// mask entry per pixel, or none (those three are optional).
void checkOutputBuffers(const std::string& context, const RenderOutput& out, const std::string& name,
                        std::size_t pixelCount);

CompareResult compareDetailed(const RenderOutput& cpu, const RenderOutput& gl, const CompareOptions& options = {});
CompareMetrics compare(const RenderOutput& cpu, const RenderOutput& gl, const CompareOptions& options = {});

// "empty", "same", "coverage_cpu", "coverage_gl", "depth", "shading", "excluded_line", "decision".
std::string_view toString(PixelClass pixelClass);

}  // namespace twr
