// Pass/fail limits on CompareMetrics: the CLI exits 1 when any is violated, tests assert none is.
// Every limit is inclusive: a maximum fails when the metric is > the limit, the minimum
// (min_psnr) when the metric is < the limit. Unset limits are not checked. max_abs_diff and
// max_over_1_pct also hold the sky box's pixels, as their own population, when they were compared.
#pragma once

#include "compare/metrics.h"

#include <optional>
#include <string>
#include <vector>

namespace twr {

struct Thresholds {
  std::optional<double> maxOver1Pct;                // over_1 as % of both_covered
  std::optional<double> maxOver1;                   // pixels
  std::optional<double> maxOver3;                   // pixels
  std::optional<double> maxOver12;                  // pixels
  std::optional<double> maxAbsDiff;                 // levels 0..255
  std::optional<double> maxMeanAbsDiff;             // levels
  std::optional<double> maxRmse;                    // levels
  std::optional<double> minPsnr;                    // dB
  std::optional<double> maxCoverageMismatch;        // pixels
  std::optional<double> maxCoverageMismatchPer10k;  // per 10,000 pixels covered by either backend
  std::optional<double> maxDepthMaxDiff;            // window depth units
  std::optional<double> maxNanPixels;               // pixels
  std::optional<double> maxClassDepth;              // pixels
  std::optional<double> maxExcludedLinePct;         // debug-line pixels, % of the frame
  std::optional<double> maxLineMismatchPct;         // line pixels only one side drew, % of line pixels
};

// One limit as written in JSON and, with '-' for '_', on the command line (--max-over-1-pct).
struct ThresholdLimit {
  std::string key;        // "max_over_1_pct"
  std::string metricKey;  // "over_1_pct": the metrics JSON key it checks
  bool isMinimum = false;
  double limit = 0.0;
};

struct ThresholdViolation {
  std::string key;  // the limit's key, "max_abs_diff"
  double value = 0.0;
  double limit = 0.0;
  std::string message;  // "max_abs_diff: 7 levels at (12, 40) > limit 3"
};

// The set limits, in a fixed order (the order of the struct).
std::vector<ThresholdLimit> setLimits(const Thresholds& thresholds);

// Throws InputError naming the limit when one is NaN, infinite or negative.
void validateThresholds(const Thresholds& thresholds);

// Violated limits, in the order of setLimits(); empty when everything passes.
std::vector<ThresholdViolation> checkThresholds(const CompareMetrics& metrics, const Thresholds& thresholds);

// The targets of issue 5 for CPU versus llvmpipe in precise mode: over_1 <= 0.1 %,
// max_abs_diff <= 3, nan_pixels = 0, and coverage_mismatch = 0, or at most 1 per 10,000
// covered pixels when `trianglesClipped` (the scene clips triangles); and for the debug lines
// left out of those, excluded_line_pct <= 10 % and line_mismatch_pct <= 15 %.
Thresholds issueTargets(bool trianglesClipped);

}  // namespace twr
