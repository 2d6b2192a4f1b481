// What `twinraster report` measures and writes: per knob, per setting, per backend, the time
// per frame and the error against the knob's reference (and CPU against GL), plus the
// orthonormal-basis table. Plain data; report_sweeps.cpp fills it, report_html.cpp and
// report_csv write it.
#pragma once

#include "compare/metrics.h"
#include "scene/orthonormal_basis.h"

#include <optional>
#include <string>
#include <vector>

namespace twr::cli {

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

struct BasisRow {
  BasisMethod method = BasisMethod::Duff2017;
  BasisErrorStats stats;
  double nsPerBasis = 0.0;  // nanoseconds per basis (float, one thread)
};

struct ReportData {
  std::string generatedAt;  // local time
  std::string machine;      // CPU model, core count, GL renderer
  bool quick = false;
  int referenceSamplesPerAxis = 4;
  int width = 0, height = 0;  // the size most knobs use
  double seconds = 0.0;       // how long the whole run took
  std::vector<KnobResult> knobs;
  std::vector<BasisRow> bases;
  std::size_t basisDirections = 0;
  std::string basisSummary;
  std::string basisReading;
};

}  // namespace twr::cli
