// What `twinraster report` measures and writes: per knob, per setting, per backend, the time
// per frame and the error against the knob's reference (and CPU against GL), the height-field
// section and the orthonormal-basis table. Plain data; report_sweeps.cpp fills it,
// report_html.cpp writes the page and the CSV.
#pragma once

#include "compare/metrics.h"
#include "scene/environment_error.h"
#include "scene/orthonormal_basis.h"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace twr::report {

// A point of the height-field section: which method it draws and the pixels its error leaves
// out (compare/interior.h): vsReference is over the interior pixels alone.
struct HeightFieldPointInfo {
  std::string method;              // a surface_detail name, or kTrueGeometry
  int layersMin = 0, layersMax = 0;  // parallax_layers of the marching methods; 0 for the others
  std::uint64_t interiorPixels = 0;
  std::uint64_t silhouetteApproxOnly = 0;     // covered by this image, not by the reference
  std::uint64_t silhouetteReferenceOnly = 0;  // covered by the reference, not by this image
  std::uint64_t partialPixels = 0;            // the reference's edge pixels (part coverage), left out
};
// The method name of the displaced mesh itself, drawn with one sample per pixel.
inline constexpr const char* kTrueGeometry = "heightfield_mesh";

// One backend at one setting of one knob.
struct ReportPoint {
  std::string setting;  // "16x32", "bilinear", "2 threads", ...
  std::string backend;  // "cpu", "gl", "cpu double"
  double msMedian = 0.0;  // wall time of one frame, milliseconds (GL: includes glFinish and readback)
  double msMin = 0.0;
  int frames = 0;       // timed frames after one warm-up
  CompareMetrics vsReference;              // this output against the knob's reference
  std::optional<CompareMetrics> cpuVsGl;   // at this setting, CPU against GL (on the GL row)
  // Knobs with an exact and a shortcut setting: the shortcut against the same backend at the
  // exact setting, i.e. what the shortcut alone changes (on the shortcut's rows).
  std::optional<CompareMetrics> vsExactSetting;
  std::string exactSetting;  // the setting vsExactSetting is measured against
  std::optional<HeightFieldPointInfo> heightField;  // the height-field section's points only
};

struct KnobResult {
  std::string id;         // csv key: "tessellation", "texture_filter", ...
  std::string title;      // chart title
  std::string question;   // what the knob trades, one sentence
  std::string reference;  // what the error is measured against
  std::string scene;      // scene and size
  std::vector<ReportPoint> points;
  std::string summary;    // the verdict in a sentence or two, written from the numbers
  std::string reading;    // the numbers behind the verdict, per backend
  std::string skipped;    // non-empty when the knob could not run (the reason)
};

// One view of the height-field section: one field at one angle, every method on both backends.
struct HeightFieldView {
  std::string field;  // "bricks", "blocks"
  int angleDeg = 0;   // between the view direction at the plane's centre and its normal
  KnobResult result;  // id "height_fields_<field>_<angle>"; every point carries heightField
};

// The speed target: a parallax_occlusion frame at 1280 x 720 against the normal-mapped
// frame, on the CPU fast path.
struct HeightFieldCost {
  bool measured = false;
  std::string scene;     // field and angle
  std::string cpuPath;   // "fast (avx2), 1 thread"
  std::string pomSetting;  // "parallax_occlusion 8-32"
  double normalMapMs = 0.0, pomMs = 0.0;              // fastest frames
  double normalMapMsMedian = 0.0, pomMsMedian = 0.0;  // medians
  int frames = 0;
};

struct HeightFieldSection {
  bool measured = false;
  int referenceSamplesPerAxis = 4;  // N of the displaced mesh's N x N reference
  std::string question, reference, scene;
  std::vector<HeightFieldView> views;  // field by field, angles ascending
  HeightFieldCost cost720p;
  std::vector<std::string> images;     // PNG files written beside report.html, one per field
  std::string imagesCaption;
  std::string summary, reading;        // written from the numbers (report_reading.cpp)
  std::string skipped;                 // non-empty when part of it could not run
};

struct BasisRow {
  BasisMethod method = BasisMethod::Duff2017;
  BasisErrorStats stats;
  double nsPerBasis = 0.0;  // nanoseconds per basis (float, one thread)
};

// The environment section (docs/environment.md): each built parameterization at each size
// against the cube it was built from (scene/environment_error.h).
struct ParameterizationRow {
  EnvironmentParameterization kind = EnvironmentParameterization::Sphere;
  int size = 0;                 // texels per side
  ParameterizationError error;  // levels
  double buildMs = 0.0;         // building the map and its chain, one thread
};
struct ParameterizationSection {
  std::string source;                 // what the cube was read from
  std::vector<ParameterizationRow> rows;
  std::vector<std::string> pictures;  // file names beside report.html, with captions below
  std::vector<std::string> captions;
  std::string summary, reading, skipped;
};

// The environment's diffuse light (docs/environment.md, "Diffuse light"): the irradiance cube
// and SH9 against Monte Carlo over the source, and SH9 against the cube
// (scene/environment_error.h's measureDiffuseLightError).
struct DiffuseLightSection {
  std::string source;
  DiffuseLightError error;
  double irradianceMs = 0.0, sh9Ms = 0.0;  // building each from the cube, one thread
  std::vector<std::string> pictures, captions;  // beside report.html
  std::string summary, reading, skipped;
};

// The environment's glossy reflection (docs/environment.md, "Glossy reflection"): the
// prefiltered cube read at each shininess's LOD, and the unfiltered source in the mirror
// direction, against Monte Carlo over the lobe (scene/environment_error.h's measureGlossyError).
struct GlossySection {
  std::string source;
  GlossyError error;
  int cubeSize = 0, levels = 0;  // the prefiltered cube's side (texels) and level count
  double levelZeroExponent = 0.0;  // e_0, the sharpest lobe it holds
  double buildMs = 0.0;          // building it from the source, every core
  std::vector<std::string> pictures, captions;  // beside report.html
  std::string summary, reading, skipped;
};

// Shadow maps against a ray tracer (docs/shadows.md, "Against a ray tracer"): one scene, the
// map's side and PCF kernel swept, each frame's per-pixel visibility against shadow rays traced
// in double against the scene's triangles (softrender/shadow_reference.h).
struct ShadowRow {
  int size = 0;                  // texels per side
  int pcf = 1;                   // kernel side
  double msMedian = 0.0;         // the whole CPU frame (fast path, one thread), shadow pass included
  double shadowPassMs = 0.0;     // of it, the shadow pass (median)
  double wrongPercent = 0.0;     // pixels whose map visibility is the other answer, % of measured
  double partialPercent = 0.0;   // pixels the map leaves between lit and shadowed (a PCF edge)
  double meanAbsError = 0.0;     // mean |map - traced| visibility
};
struct ShadowSection {
  std::string scene;             // file and size
  double unshadowedMs = 0.0;     // the same frame with no shadow map (median)
  std::uint64_t measured = 0;    // pixels on surfaces turned to the light
  std::uint64_t tracedShadowed = 0;
  double traceMs = 0.0;          // tracing every measured pixel's shadow ray, one thread
  std::vector<ShadowRow> rows;
  std::vector<std::string> pictures, captions;  // beside report.html
  std::string summary, reading, skipped;
};

// Screen-space reflections against a ray tracer (docs/ssr.md, "Against a ray tracer"): each
// march at several step counts and thicknesses on the mirror floor, and the indirect light at
// 1..64 samples in the cave, each CPU frame against the ray-traced reference
// (raytrace/ssr_reference.h). Errors are levels (the largest channel), over the pixels that reflect.
struct SsrMarchRow {
  std::string march;              // settings.ssr.march
  int maxSteps = 0;
  double thickness = 0.0;         // world units
  double msMedian = 0.0;          // the whole CPU frame (fast path, every core)
  double ssrMs = 0.0;             // of it, the reflection pass (median)
  double meanAbs = 0.0;           // mean error against the reference
  double visibleMeanAbs = 0.0;    // over the pixels whose mirror ray meets a surface the frame shows
  std::uint64_t missedVisible = 0;  // of those, more than 3 levels off (a miss or a wrong hit)
  std::uint64_t falseHits = 0;    // pixels whose mirror ray meets nothing, more than 3 levels off
};
struct SsrSamplesRow {
  int samples = 0;                // indirect_samples
  double msMedian = 0.0, ssrMs = 0.0;
  double meanAbs = 0.0;           // against the converged reference: noise and march together
  double marchMeanAbs = 0.0;      // against the reference of the very same rays: the march alone
};
struct SsrSection {
  std::string scene, indirectScene, tracer;
  double baseMs = 0.0;            // the mirror floor's frame without reflections (median)
  std::uint64_t reflecting = 0;   // its pixels that reflect
  std::uint64_t blindRays = 0;    // of their mirror rays, those meeting off-screen or occluded surfaces
  double blindErrorShare = 0.0;   // the part of the best march's error those pixels carry, [0, 1]
  double traceMs = 0.0;           // the mirror floor's reference, every core
  int referenceSamples = 0;       // indirect rays per pixel of the cave's converged reference
  double indirectTraceMs = 0.0;
  std::vector<SsrMarchRow> steps;      // every march at several max_steps, the scene's thickness
  std::vector<SsrMarchRow> thickness;  // two marches at one step count, several thicknesses
  std::vector<SsrSamplesRow> samples;
  std::vector<std::string> pictures, captions;  // beside report.html
  std::string summary, reading, skipped;
};

struct ReportData {
  std::string generatedAt;  // local time
  std::string machine;      // CPU model, core count, GL renderer
  bool quick = false;
  int referenceSamplesPerAxis = 4;
  int width = 0, height = 0;  // the size most knobs use
  double seconds = 0.0;       // how long the whole run took
  std::vector<KnobResult> knobs;
  HeightFieldSection heightFields;
  ParameterizationSection parameterizations;
  DiffuseLightSection diffuseLight;
  GlossySection glossy;
  ShadowSection shadows;
  SsrSection ssr;
  std::vector<BasisRow> bases;
  std::size_t basisDirections = 0;
  std::string basisSummary;
  std::string basisReading;
};

}  // namespace twr::report
