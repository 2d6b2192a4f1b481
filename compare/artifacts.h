// Writes the files of one comparison into a folder (the CLI's --out-dir, a failing test's
// artefacts): cpu.png, gl.png, side_by_side.png, diff.png, classes.png, metrics.json.
#pragma once

#include "compare/heatmap.h"
#include "compare/metrics.h"
#include "compare/side_by_side.h"

#include <nlohmann/json_fwd.hpp>  // declarations only: json.hpp costs 4 s per source that includes it

#include <string>
#include <vector>

namespace twr {

struct ArtifactOptions {
  HeatMapOptions heatMap;
  ClassMapOptions classMap;
  SideBySideOptions sideBySide;
};

struct ArtifactPaths {
  std::string cpu;         // rawImage(cpu): the background's alpha where nothing was drawn
  std::string gl;          // rawImage(gl)
  std::string sideBySide;  // makeSideBySide
  std::string diff;        // makeHeatMap
  std::string classes;     // makeClassMap
  std::string metrics;     // `metricsJson` as given (metricsToJson plus any merged keys)

  std::vector<std::string> all() const { return {cpu, gl, sideBySide, diff, classes, metrics}; }
};

// Creates `dir` if needed and writes every file, replacing old ones. `result` must come from
// compareDetailed(cpu, gl, ...). Throws InputError naming the file that cannot be written.
ArtifactPaths writeCompareArtifacts(const std::string& dir, const RenderOutput& cpu, const RenderOutput& gl,
                                    const CompareResult& result, const nlohmann::json& metricsJson,
                                    const ArtifactOptions& options = {});

}  // namespace twr
