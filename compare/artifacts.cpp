#include "compare/artifacts.h"

#include "compare/report_json.h"
#include "scene/errors.h"

#include <filesystem>
#include <nlohmann/json.hpp>

namespace twr {

ArtifactPaths writeCompareArtifacts(const std::string& dir, const RenderOutput& cpu, const RenderOutput& gl,
                                    const CompareResult& result, const nlohmann::json& metricsJson,
                                    const ArtifactOptions& options) {
  if (result.pixels.width != cpu.width || result.pixels.height != cpu.height) {
    throw InputError("compare: the pixel analysis is " + std::to_string(result.pixels.width) + "x" +
                     std::to_string(result.pixels.height) + " but the CPU output is " + std::to_string(cpu.width) +
                     "x" + std::to_string(cpu.height) + ", expected the result of compareDetailed on these outputs");
  }
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (!std::filesystem::is_directory(dir)) throw InputError(dir + ": cannot create the output folder");

  const std::filesystem::path folder(dir);
  ArtifactPaths paths;
  paths.cpu = (folder / "cpu.png").string();
  paths.gl = (folder / "gl.png").string();
  paths.sideBySide = (folder / "side_by_side.png").string();
  paths.diff = (folder / "diff.png").string();
  paths.classes = (folder / "classes.png").string();
  paths.metrics = (folder / "metrics.json").string();

  savePng(paths.cpu, rawImage(cpu));
  savePng(paths.gl, rawImage(gl));
  savePng(paths.sideBySide, makeSideBySide(cpu, gl, options.sideBySide));
  savePng(paths.diff, makeHeatMap(result.pixels, options.heatMap));
  savePng(paths.classes, makeClassMap(result.pixels, options.classMap));
  writeJsonFile(paths.metrics, metricsJson);
  return paths;
}

}  // namespace twr
