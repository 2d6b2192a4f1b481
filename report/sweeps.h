// The sweeps behind `twinraster report`: every knob, every setting, both backends, timed and
// measured against the knob's reference (docs/report.md). GL knobs that need a fresh
// llvmpipe (sampling mode, thread count) run in child processes of this executable.
#pragma once

#include "glrender/gl_renderer.h"
#include "report/model.h"

#include <ostream>
#include <string>
#include <vector>

namespace twr::report {

struct ReportOptions {
  bool quick = false;          // smaller images, fewer settings and frames (well under a minute)
  std::string assetsDir;       // folder holding scenes/ and textures/
  std::string outDir;          // the output folder: pictures are written beside report.html
  std::string workDir;         // scratch folder for child-process outputs (inside the output folder)
  std::string selfExecutable;  // this program, for child processes ("/proc/self/exe")
  GlOptions gl;                // the GL context (--gl-context / --gl-device) for this process
  std::vector<std::string> glChildArguments;  // the same context as arguments for a GL child
};

// Runs every sweep, printing progress lines on `progress` (which knob, which point, elapsed).
ReportData runReportSweeps(const ReportOptions& options, std::ostream& progress);

// The child side of a GL sweep point: renders `scenePath` with GL (fast or precise sampling,
// whatever LP_NUM_THREADS the parent set), one warm-up and `frames` timed frames, and writes
// the last image and the timings to `outPath` (read back by the parent). Throws InputError.
void runGlChild(const std::string& scenePath, int width, int height, int frames, bool fastSampling,
                GlOptions gl, const std::string& outPath);

}  // namespace twr::report
