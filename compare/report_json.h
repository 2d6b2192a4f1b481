// metrics.json: the CompareMetrics as snake_case keys, plus what the CLI knows (timings, GL
// strings, thresholds) merged in. Key meanings: docs/compare.md.
#pragma once

#include "compare/metrics.h"
#include "compare/thresholds.h"

#include <nlohmann/json_fwd.hpp>  // declarations only: json.hpp costs 4 s per source that includes it

#include <optional>
#include <string>
#include <vector>

namespace twr {

// width, height, compared_pixels, excluded_line_pixels, covered_cpu, covered_gl, both_covered,
// background_compared, background_max_abs_diff, background_over_1, background_over_1_pct (the sky
// box's pixels, CompareOptions::compareBackground), coverage_cpu_only, coverage_gl_only, coverage_mismatch, coverage_mismatch_per_10k,
// max_abs_diff, max_abs_diff_at ([x, y] top-left origin, null when max_abs_diff is 0),
// mean_abs_diff, rmse, psnr, over_1, over_3, over_12, over_1_pct, depth_available,
// depth_max_diff, nan_pixels, triangle_ids_available, class_coverage, class_depth,
// class_shading, class_decision, differ_min_levels, depth_tolerance.
nlohmann::json metricsToJson(const CompareMetrics& metrics);

// What the CLI adds about the run. Unset optionals and empty strings are left out.
struct CompareRunInfo {
  std::optional<double> cpuMs;  // milliseconds, median of `repeat` renders
  std::optional<double> glMs;   // milliseconds, median of `repeat` renders
  std::optional<int> repeat;    // renders per backend
  std::string glRenderer;       // GL_RENDERER
  std::string glVersion;        // GL_VERSION
  std::string glSampling;       // "precise" or "fast" (llvmpipe texture sampling mode)
};
// cpu_ms, gl_ms, repeat, gl_renderer, gl_version, gl_sampling.
nlohmann::json runInfoToJson(const CompareRunInfo& info);

// {"limits": {"max_over_1_pct": 0.1, ...}, "violations": [{"key", "value", "limit",
// "message"}, ...], "passed": true|false}; merge it in under the key "thresholds".
nlohmann::json thresholdsToJson(const Thresholds& thresholds, const std::vector<ThresholdViolation>& violations);

// Adds every key of the object `extra` to the object `target`. Throws std::invalid_argument
// (a programming error, not bad input) when either is not an object or a key already exists,
// so extras can never silently overwrite a metric.
void mergeExtraKeys(nlohmann::json& target, const nlohmann::json& extra);

// Writes `json` with 2-space indentation and a final newline, creating parent folders.
// Throws InputError naming the file when it cannot be written.
void writeJsonFile(const std::string& path, const nlohmann::json& json);

}  // namespace twr
