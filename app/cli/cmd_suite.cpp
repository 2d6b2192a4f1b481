// `twinraster suite SCENE... --out-dir DIR`: `compare --html` on every scene, each in a process of
// its own, N at once; writes DIR/<scene>/ (the scene's page and images), DIR/index.html,
// DIR/suite.json and, with --junit, a JUnit XML file (compare/suite.h, compare/suite_page.h).
#include "app/cli/commands.h"
#include "app/cli/common.h"
#include "compare/suite.h"
#include "compare/suite_page.h"
#include "scene/errors.h"

#include <chrono>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <memory>
#include <thread>

namespace twr::cli {
namespace {

struct SuiteArgs {
  std::vector<std::string> scenes;
  std::string outDir;
  std::string junitPath;
  int jobs = 0;  // 0: the core count
  bool targets = false;
  std::optional<int> width, height;
  std::optional<int> repeat;
  std::vector<std::string> compareArgs;  // passed to every compare as they are
  CpuRequest cpu;
  GlRequest gl;
};

void writeText(const std::string& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary);
  out << text;
  if (!out) throw InputError(path + ": cannot write");
}

// What every compare child gets after SCENE --out-dir DIR --html.
std::vector<std::string> childArguments(const SuiteArgs& args) {
  std::vector<std::string> out;
  if (args.targets) out.push_back("--targets");
  if (args.width) out.insert(out.end(), {"--width", std::to_string(*args.width)});
  if (args.height) out.insert(out.end(), {"--height", std::to_string(*args.height)});
  if (args.repeat) out.insert(out.end(), {"--repeat", std::to_string(*args.repeat)});
  out.insert(out.end(), {"--cpu-path", args.cpu.path});
  if (args.cpu.isa) out.insert(out.end(), {"--cpu-isa", *args.cpu.isa});
  const std::vector<std::string> gl = glRequestArguments(args.gl);
  out.insert(out.end(), gl.begin(), gl.end());
  out.insert(out.end(), args.compareArgs.begin(), args.compareArgs.end());
  return out;
}

void printProgress(const SuiteCase& c, int ended, int total) {
  char line[64];
  std::snprintf(line, sizeof line, "[%d/%d] %-6s %6.1f s  ", ended, total, toString(c.outcome), c.seconds);
  // compare's own messages mostly start with the scene's path: not twice on a line.
  if (c.message.rfind(c.scene, 0) == 0) {
    std::cerr << line << c.message << "\n";
  } else {
    std::cerr << line << c.scene << (c.message.empty() ? "" : ": ") << c.message << "\n";
  }
}

void runSuiteCommand(const SuiteArgs& args) {
  requestedGlOptions(args.gl);  // --gl-device with osmesa: one error now, not one per scene
  std::vector<std::string> warnings;
  const std::vector<std::string> scenes = suiteScenesFrom(args.scenes, warnings);
  for (const std::string& w : warnings) std::cerr << "twinraster: warning: " << w << "\n";
  if (scenes.empty()) throw InputError("suite: no scene to compare");
  SuiteOptions options;
  options.outDir = args.outDir;
  options.jobs = args.jobs > 0 ? args.jobs : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  options.compareArgs = childArguments(args);
  std::cerr << "twinraster: suite: " << scenes.size() << " scenes, " << options.jobs << " at once, into "
            << args.outDir << "\n";
  const auto start = std::chrono::steady_clock::now();
  const std::vector<SuiteCase> cases = runSuite(scenes, options, printProgress);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  const std::string index = args.outDir + "/index.html";
  writeText(index, suiteIndexHtml(cases, seconds));
  const nlohmann::json summary = suiteJson(cases, seconds);
  writeText(args.outDir + "/suite.json", summary.dump(2) + "\n");
  if (!args.junitPath.empty()) writeText(args.junitPath, junitXml(cases, seconds));

  std::printf("%d scenes in %.1f s: %d within targets, %d over them, %d bad input\n", static_cast<int>(cases.size()),
              seconds, summary["passed"].get<int>(), summary["failed"].get<int>(), summary["errors"].get<int>());
  std::printf("wrote %s (open it in a browser), %s/suite.json%s%s\n", index.c_str(), args.outDir.c_str(),
              args.junitPath.empty() ? "" : ", ", args.junitPath.c_str());
  exitCode() = suiteExitCode(cases);
}

const bool suiteRegistered = registerCommand(35, [](CLI::App& app) {
  auto args = std::make_shared<SuiteArgs>();
  CLI::App* cmd = app.add_subcommand(
      "suite",
      "Compare many scenes: `compare --html` on each in a process of its own, N at once. Writes DIR/<scene>/ "
      "(each scene's page, images and metrics.json), DIR/index.html (every scene with thumbnails, verdict, "
      "largest difference, over-1 share, coverage mismatch and both times, sortable), DIR/suite.json and, with "
      "--junit, a JUnit XML file (one testcase per scene). A bad scene is an error case and the others still "
      "run. Exit 0 when all are within the thresholds, 1 when any is over, 2 when any is bad input.");
  cmd->add_option("SCENE", args->scenes, "Scene files; a folder stands for the .json files in it")->required();
  cmd->add_option("--out-dir,-o", args->outDir, "Folder for the pages (created)")->required();
  cmd->add_option("--junit", args->junitPath,
                  "Also write a JUnit XML file here: failure = over the thresholds (the threshold lines as "
                  "message), error = bad input or a crash (its message)");
  cmd->add_option("--jobs,-j", args->jobs, "Comparisons at once (default: the core count)")->check(CLI::Range(1, 256));
  cmd->add_flag("--targets", args->targets, "Apply the project's CPU-vs-llvmpipe targets to every scene (see compare)");
  cmd->add_option("--width", args->width, "Image width for every scene (default: each scene's own)")
      ->check(CLI::Range(1, 16384));
  cmd->add_option("--height", args->height, "Image height for every scene (default: each scene's own)")
      ->check(CLI::Range(1, 16384));
  cmd->add_option("--repeat", args->repeat, "Renders per backend in each compare (cpu_ms and gl_ms are the median)")
      ->check(CLI::Range(1, 1000));
  cmd->add_option("--compare-arg", args->compareArgs,
                  "An argument passed to every compare as it is, repeatable; an option's name takes '=': "
                  "--compare-arg=--max-abs-diff --compare-arg=4");
  addCpuOptions(*cmd, args->cpu);
  addGlOptions(*cmd, args->gl);
  cmd->callback([args] { runSuiteCommand(*args); });
});

}  // namespace
}  // namespace twr::cli
