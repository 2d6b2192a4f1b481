#include "compare/capture_faces.h"

#include "compare/cube_cross.h"
#include "compare/heatmap.h"
#include "compare/report_json.h"
#include "compare/side_by_side.h"
#include "scene/environment.h"

#include <filesystem>
#include <nlohmann/json.hpp>

namespace twr {

CapturedFacesComparison compareCapturedFaces(const CapturedFaces& cpu, const CapturedFaces& gl) {
  CapturedFacesComparison out;
  CompareOptions options;
  options.compareBackground = true;
  for (std::size_t f = 0; f < out.faces.size(); ++f) out.faces[f] = compareDetailed(cpu.faces[f], gl.faces[f], options);
  return out;
}

std::vector<ThresholdViolation> checkCapturedFaces(const CapturedFacesComparison& comparison, const Thresholds& limits) {
  std::vector<ThresholdViolation> out;
  for (std::size_t f = 0; f < comparison.faces.size(); ++f) {
    for (ThresholdViolation v : checkThresholds(comparison.faces[f].metrics, limits)) {
      v.message = std::string("capture face ") + kCubeFaceNames[f] + ": " + v.message;
      out.push_back(std::move(v));
    }
  }
  return out;
}

nlohmann::json capturedFacesToJson(const CapturedFacesComparison& comparison) {
  nlohmann::json faces = nlohmann::json::array();
  for (std::size_t f = 0; f < comparison.faces.size(); ++f) {
    nlohmann::json face = {{"face", kCubeFaceNames[f]}};
    mergeExtraKeys(face, metricsToJson(comparison.faces[f].metrics));
    faces.push_back(std::move(face));
  }
  return faces;
}

Image capturedFacesCross(const CapturedFaces& faces) {
  std::array<Image, 6> images;
  for (std::size_t f = 0; f < images.size(); ++f) images[f] = rawImage(faces.faces[f]);
  return cubeCrossFromFaces(images);
}

Image capturedFacesDiffCross(const CapturedFacesComparison& comparison) {
  std::array<Image, 6> images;
  HeatMapOptions options;
  options.legend = false;
  for (std::size_t f = 0; f < images.size(); ++f) images[f] = makeHeatMap(comparison.faces[f].pixels, options);
  return cubeCrossFromFaces(images);
}

CaptureArtifactPaths writeCaptureArtifacts(const std::string& dir, const CapturedFaces& cpu, const CapturedFaces& gl,
                                           const CapturedFacesComparison& comparison) {
  const std::filesystem::path base(dir);
  CaptureArtifactPaths paths{(base / "capture_cpu.png").string(), (base / "capture_gl.png").string(),
                             (base / "capture_diff.png").string()};
  savePng(paths.cpu, capturedFacesCross(cpu));
  savePng(paths.gl, capturedFacesCross(gl));
  savePng(paths.diff, capturedFacesDiffCross(comparison));
  return paths;
}

}  // namespace twr
