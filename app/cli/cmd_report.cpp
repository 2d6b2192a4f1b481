// `twinraster report [--out DIR] [--quick]`: sweeps the quality knobs and the height-field
// methods on both backends, times them and measures their error against a reference, and
// writes DIR/report.html, DIR/results.csv and the height-field pictures (docs/report.md). Also registers the hidden `report-gl-child` subcommand the
// sweeps run in child processes when a knob needs a fresh llvmpipe.
#include "app/cli/commands.h"
#include "app/cli/common.h"
#include "report/html.h"
#include "report/sweeps.h"
#include "scene/errors.h"
#include "scene/image.h"

#include <filesystem>
#include <iostream>
#include <memory>
#include <system_error>

namespace twr::cli {
namespace {

using report::ReportOptions;
using report::ReportData;
using report::runReportSweeps;
using report::runGlChild;
using report::writeReportHtml;
using report::writeResultsCsv;

struct ReportArgs {
  std::string outDir = "out/report";
  std::string assetsDir;  // empty: found next to the working directory or the executable
  bool quick = false;
  GlRequest gl;
};

struct ChildArgs {
  std::string scenePath;
  int width = 0, height = 0;
  int frames = 1;
  bool fastSampling = false;
  GlRequest gl;
  std::string outPath;
};

// The folder holding scenes/default.json: ./assets, or assets beside a parent of the executable
// (a build folder inside the repository).
std::string findAssets(const std::string& requested) {
  namespace fs = std::filesystem;
  auto usable = [](const fs::path& dir) { return fs::exists(dir / "scenes" / "default.json"); };
  if (!requested.empty()) {
    if (!usable(requested)) {
      throw InputError("--assets: '" + requested + "' has no scenes/default.json (expected the repository's assets/)");
    }
    return requested;
  }
  std::vector<fs::path> candidates = {fs::current_path() / "assets"};
  std::error_code error;
  const fs::path exe = fs::read_symlink("/proc/self/exe", error);
  if (!error) {
    for (fs::path dir = exe.parent_path(); !dir.empty() && dir != dir.root_path(); dir = dir.parent_path()) {
      candidates.push_back(dir / "assets");
    }
  }
  for (const fs::path& dir : candidates) {
    if (usable(dir)) return dir.string();
  }
  throw InputError("report: cannot find assets/scenes/default.json in the working directory or above the "
                   "executable; run from the repository root or pass --assets DIR");
}

void runReport(const ReportArgs& args) {
  namespace fs = std::filesystem;
  ReportOptions options;
  options.quick = args.quick;
  options.gl = requestedGlOptions(args.gl);  // a bad combination exits 2 before any sweep runs
  options.glChildArguments = glRequestArguments(args.gl);
  options.assetsDir = findAssets(args.assetsDir);
  options.selfExecutable = "/proc/self/exe";
  std::error_code error;
  fs::create_directories(args.outDir, error);
  if (error || !fs::is_directory(args.outDir)) {
    throw InputError("--out: cannot create the folder '" + args.outDir + "': " + error.message());
  }
  options.outDir = args.outDir;
  options.workDir = (fs::path(args.outDir) / "work").string();
  fs::create_directories(options.workDir, error);
  if (error) throw InputError("--out: cannot create '" + options.workDir + "': " + error.message());

  const ReportData data = runReportSweeps(options, std::cerr);
  const std::string html = (fs::path(args.outDir) / "report.html").string();
  const std::string csv = (fs::path(args.outDir) / "results.csv").string();
  writeReportHtml(html, data);
  writeResultsCsv(csv, data);
  fs::remove_all(options.workDir, error);  // only child outputs, already read
  std::cout << "wrote " << html << "\n      " << csv << "\n";
}

const bool reportRegistered = registerCommand(60, [](CLI::App& app) {
  auto args = std::make_shared<ReportArgs>();
  CLI::App* cmd = app.add_subcommand(
      "report",
      "Sweep the quality knobs (sphere tessellation, texture filter, lighting space, tangent transform, llvmpipe "
      "sampling, resolution, threads, float vs double) on both backends; time each point and measure its error "
      "against a double-precision supersampled reference. Height fields: every surface_detail method (marching "
      "ones at several parallax_layers) on a brick and a steep-walled height field at 0, 45, 70 and 85 degrees, "
      "against the displaced heightfield mesh on interior pixels (silhouettes counted apart), and a "
      "parallax_occlusion frame at 1280x720 against the normal-mapped one. Environment maps against Monte Carlo. "
      "Shadow maps: the map's side and PCF kernel against shadow rays traced in double against the scene's "
      "triangles. Screen-space reflections: every march at several step counts and thicknesses, and the indirect "
      "light at 1 to 64 samples, against the same rays traced with Embree (skipped, and said, in a build without it). "
      "Writes DIR/report.html (charts, tables, readings), DIR/results.csv and the pictures (height "
      "fields, environment, DIR/shadow_vs_traced.png, DIR/ssr_vs_traced.png). Progress on "
      "stderr. Two to three minutes by default, about 20 seconds with --quick.");
  cmd->add_option("--out,-o", args->outDir, "Output folder (created)")->capture_default_str();
  cmd->add_flag("--quick", args->quick,
                 "Smaller images, fewer settings and frames (height fields: two layer counts, a one-sample reference)");
  cmd->add_option("--assets", args->assetsDir,
                  "The repository's assets/ folder (default: ./assets or one above the executable)");
  addGlOptions(*cmd, args->gl);
  cmd->callback([args] { runReport(*args); });

  auto child = std::make_shared<ChildArgs>();
  CLI::App* childCmd = app.add_subcommand("report-gl-child", "Internal: one GL sweep point for `report`");
  childCmd->group("");  // hidden from --help
  childCmd->add_option("scene", child->scenePath)->required();
  childCmd->add_option("--width", child->width)->required()->check(CLI::Range(1, kMaxImageSide));
  childCmd->add_option("--height", child->height)->required()->check(CLI::Range(1, kMaxImageSide));
  childCmd->add_option("--frames", child->frames)->check(CLI::Range(1, 1000));
  childCmd->add_flag("--fast-sampling", child->fastSampling);
  childCmd->add_option("--out", child->outPath)->required();
  addGlOptions(*childCmd, child->gl);
  childCmd->callback([child] {
    runGlChild(child->scenePath, child->width, child->height, child->frames, child->fastSampling,
               requestedGlOptions(child->gl),
               child->outPath);
  });
});

}  // namespace
}  // namespace twr::cli
