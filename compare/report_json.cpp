#include "compare/report_json.h"

#include "scene/json_text.h"

#include "scene/errors.h"

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <stdexcept>

namespace twr {
namespace {
constexpr int kJsonIndent = 2;  // spaces
}  // namespace

nlohmann::json metricsToJson(const CompareMetrics& m) {
  nlohmann::json json = nlohmann::json::object();
  json["width"] = m.width;
  json["height"] = m.height;
  json["compared_pixels"] = m.comparedPixels;
  json["excluded_line_pixels"] = m.excludedLinePixels;
  json["excluded_line_pct"] = m.excludedLinePct();
  json["line_pixels_cpu"] = m.linePixelsCpu;
  json["line_pixels_gl"] = m.linePixelsGl;
  json["line_mismatch"] = m.lineMismatch;
  json["line_mismatch_pct"] = m.lineMismatchPct();
  json["covered_cpu"] = m.coveredCpu;
  json["covered_gl"] = m.coveredGl;
  json["both_covered"] = m.bothCovered;
  json["background_compared"] = m.backgroundCompared;
  json["background_max_abs_diff"] = m.backgroundMaxAbsDiff;
  json["background_over_1"] = m.backgroundOver1;
  json["background_over_1_pct"] = m.backgroundOver1Pct();
  json["coverage_cpu_only"] = m.coverageCpuOnly;
  json["coverage_gl_only"] = m.coverageGlOnly;
  json["coverage_mismatch"] = m.coverageMismatch;
  json["coverage_mismatch_per_10k"] = m.coverageMismatchPer10k();
  json["max_abs_diff"] = m.maxAbsDiff;
  json["max_abs_diff_at"] =
      m.hasMaxAbsDiffAt() ? nlohmann::json::array({m.maxAbsDiffX, m.maxAbsDiffY}) : nlohmann::json(nullptr);
  json["mean_abs_diff"] = m.meanAbsDiff;
  json["rmse"] = m.rmse;
  json["psnr"] = m.psnr;
  json["over_1"] = m.over1;
  json["over_3"] = m.over3;
  json["over_12"] = m.over12;
  json["over_1_pct"] = m.over1Pct();
  json["depth_available"] = m.depthAvailable;
  json["depth_max_diff"] = m.depthMaxDiff;
  json["nan_pixels"] = m.nanPixels;
  json["triangle_ids_available"] = m.triangleIdsAvailable;
  json["class_coverage"] = m.classCoverage;
  json["class_depth"] = m.classDepth;
  json["class_shading"] = m.classShading;
  json["class_decision"] = m.classDecision;
  json["differ_min_levels"] = m.options.differMinLevels;
  json["depth_tolerance"] = m.options.depthTolerance;
  return json;
}

nlohmann::json runInfoToJson(const CompareRunInfo& info) {
  nlohmann::json json = nlohmann::json::object();
  if (info.cpuMs) json["cpu_ms"] = *info.cpuMs;
  if (info.glMs) json["gl_ms"] = *info.glMs;
  if (info.repeat) json["repeat"] = *info.repeat;
  if (!info.glRenderer.empty()) json["gl_renderer"] = info.glRenderer;
  if (!info.glVersion.empty()) json["gl_version"] = info.glVersion;
  if (!info.glSampling.empty()) json["gl_sampling"] = info.glSampling;
  return json;
}

nlohmann::json thresholdsToJson(const Thresholds& thresholds, const std::vector<ThresholdViolation>& violations) {
  nlohmann::json limits = nlohmann::json::object();
  for (const ThresholdLimit& limit : setLimits(thresholds)) limits[limit.key] = limit.limit;
  nlohmann::json violationList = nlohmann::json::array();
  for (const ThresholdViolation& v : violations) {
    violationList.push_back({{"key", v.key}, {"value", v.value}, {"limit", v.limit}, {"message", v.message}});
  }
  return {{"limits", limits}, {"violations", violationList}, {"passed", violations.empty()}};
}

void mergeExtraKeys(nlohmann::json& target, const nlohmann::json& extra) {
  if (!target.is_object() || !extra.is_object()) {
    throw std::invalid_argument("mergeExtraKeys: both arguments must be JSON objects");
  }
  for (const auto& [key, value] : extra.items()) {
    if (target.contains(key)) throw std::invalid_argument("mergeExtraKeys: key \"" + key + "\" already present");
  }
  for (const auto& [key, value] : extra.items()) target[key] = value;
}

void writeJsonFile(const std::string& path, const nlohmann::json& json) {
  const std::filesystem::path parent = std::filesystem::path(path).parent_path();
  std::error_code ec;
  if (!parent.empty()) std::filesystem::create_directories(parent, ec);
  // The whole text first (invalid UTF-8 in names replaced, so it cannot throw half-way), then
  // written beside the target and renamed over it: a failed run leaves no truncated file.
  const std::string text = jsonText(json, kJsonIndent) + "\n";
  const std::string partial = path + ".partial";
  {
    std::ofstream file(partial, std::ios::binary | std::ios::trunc);
    if (!file) throw InputError(path + ": cannot open for writing");
    file << text;
    file.close();
    if (!file) {
      std::filesystem::remove(partial, ec);
      throw InputError(path + ": cannot write JSON");
    }
  }
  std::filesystem::rename(partial, path, ec);
  if (ec) {
    std::filesystem::remove(partial, ec);
    throw InputError(path + ": cannot write JSON");
  }
}

}  // namespace twr
