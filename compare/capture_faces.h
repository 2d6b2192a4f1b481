// The captured environment's six faces (scene/environment_capture.h) compared between the
// renderers: each renderer drew its own cube from the scene, so before the frames are compared
// the faces are, with the same metrics and limits. Where a frame's reflection differs, this
// says whether the difference was born in the capture or in the lookup.
#pragma once

#include "compare/metrics.h"
#include "compare/thresholds.h"
#include "scene/image.h"
#include "scene/renderer.h"

#include <nlohmann/json_fwd.hpp>  // declarations only: json.hpp costs 4 s per source that includes it

#include <array>
#include <string>
#include <vector>

namespace twr {

struct CapturedFacesComparison {
  std::array<CompareResult, 6> faces;  // GL order
};

// Each face's CPU render against its GL render; the pixels no triangle covers (the output's
// background, what the probe sees of no geometry) are compared too.
CapturedFacesComparison compareCapturedFaces(const CapturedFaces& cpu, const CapturedFaces& gl);

// `limits` checked on every face; each violation's message starts "capture face +X: ".
std::vector<ThresholdViolation> checkCapturedFaces(const CapturedFacesComparison& comparison, const Thresholds& limits);

// metrics.json's "capture_faces": one object per face, {"face": "+X", ...metricsToJson}.
nlohmann::json capturedFacesToJson(const CapturedFacesComparison& comparison);

// The faces as a cube cross (compare/cube_cross.h), and the heat maps of their differences as
// one (no legend: diff.png's ramp holds).
Image capturedFacesCross(const CapturedFaces& faces);
Image capturedFacesDiffCross(const CapturedFacesComparison& comparison);

struct CaptureArtifactPaths {
  std::string cpu, gl, diff;  // capture_cpu.png, capture_gl.png, capture_diff.png
};
// Writes the three crosses into `dir` (which exists). Throws InputError naming a file that
// cannot be written.
CaptureArtifactPaths writeCaptureArtifacts(const std::string& dir, const CapturedFaces& cpu, const CapturedFaces& gl,
                                           const CapturedFacesComparison& comparison);

}  // namespace twr
