// `twinraster bench SCENE [--frames N] [--width W --height H] [--json] [--threads T] [--gl-precise]
// [--cpu-path P] [--cpu-isa I] [--all-isas]`: times the CPU pipeline and llvmpipe in one
// process, frame by frame alternating, after a warm-up, and reports the median and spread of
// each and their ratio. Each time is the wall time of one Renderer::renderInto() call into the
// renderer's previous output (its buffers reused, as an application keeps its framebuffer): for
// GL that includes glFinish and the read-back into the RenderOutput, for the CPU the same
// buffers; neither includes writing a PNG.
//
// Two llvmpipe frames, interleaved with the CPU frames:
//   gl       glrender's full frame (GlFrame::Full): colour, depth, triangle ids and the
//            TBN-line mask, all four read back, plus an occlusion query; what compare uses;
//   gl_lean  the fair reference (GlFrame::Lean): the same programs and draws into colour +
//            depth only, the colour read back with one glReadPixels, as an OpenGL user draws
//            it. The CPU pipeline produces colour + depth (and its ids) in the same call.
// --all-isas adds one CPU fast-path renderer per target this machine runs (per_isa), each
// timed in the same loop with the same warm-up, divided by the same lean GL frames.
//
// Threads: llvmpipe gets as many rasterizer threads as the CPU pipeline gets workers
// (LP_NUM_THREADS, which llvmpipe reads when the first context is created, so it is set
// before the first GL render). The default is std::thread::hardware_concurrency(), the
// online CPUs, which is also llvmpipe's own default, so `bench` without --threads times both
// as a user gets them.
//
// Sampling: llvmpipe in its default (fast) texture sampling, what a user gets. It reads
// GALLIVM_PERF once per process, so --gl-precise re-runs this command in a child process of
// /proc/self/exe that times only the precise mode, and merges its figures (gl_precise_*).
#include "app/cli/commands.h"
#include "scene/json_text.h"
#include "app/cli/common.h"
#include "compare/timing.h"
#include "glrender/gl_renderer.h"
#include "scene/errors.h"
#include "scene/scene.h"
#include "scene/statistics.h"
#include "softrender/cpu_renderer.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <iomanip>
#include <iostream>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <thread>
#include <vector>


namespace twr::cli {
namespace {

using Json = nlohmann::ordered_json;
using Clock = std::chrono::steady_clock;

// Most worker threads bench accepts (inclusive); the CPU renderer caps at the same count.
constexpr int kMaxBenchThreads = 64;
// Most timed frames (inclusive) and warm-up frames (inclusive).
constexpr int kMaxFrames = 100000;
constexpr int kMaxWarmup = 1000;
// Progress lines on stderr start once a run has taken this long (seconds), one per interval.
constexpr double kProgressAfterSeconds = 2.0;
constexpr double kProgressIntervalSeconds = 1.0;
// The environment variable llvmpipe reads its rasterizer thread count from.
constexpr const char* kLlvmpipeThreadsVariable = "LP_NUM_THREADS";

struct BenchArgs {
  RenderRequest request;
  int frames = 20;
  int warmup = 2;
  std::optional<int> threads;  // default: hardware_concurrency()
  CpuRequest cpu;
  GlRequest gl;
  bool cpuScalar = false;  // the old spelling of --cpu-isa scalar
  bool allIsas = false;    // also time the fast path on every supported target
  bool json = false;
  bool glPrecise = false;
  bool preciseChild = false;  // internal: time GL in precise sampling only, print JSON (see --gl-precise)
};

// Summary of one backend's frame times (compare/timing.h), milliseconds, and the median CPU time
// all threads of the process used per frame: close to the wall time times the threads when
// they all work and nothing else runs; it stays put when other processes take the cores, which
// the wall time does not.
struct Timing : FrameTimes {
  double processMedian = 0.0;
};

Timing summarise(std::vector<double> frames, std::vector<double> processMs) {
  Timing t;
  static_cast<FrameTimes&>(t) = summariseFrameTimes(std::move(frames));
  t.processMedian = medianOf(std::move(processMs));
  return t;
}

void addTiming(Json& json, const std::string& prefix, const Timing& t) {
  json[prefix + "_ms_median"] = t.median;
  json[prefix + "_ms_min"] = t.min;
  json[prefix + "_ms_max"] = t.max;
  json[prefix + "_ms_q1"] = t.q1;
  json[prefix + "_ms_q3"] = t.q3;
  json[prefix + "_ms_frames"] = t.frames;
  json[prefix + "_process_cpu_ms_median"] = t.processMedian;
}

Timing timingFromJson(const Json& json, const std::string& prefix) {
  Timing t;
  t.median = json.at(prefix + "_ms_median").get<double>();
  t.min = json.at(prefix + "_ms_min").get<double>();
  t.max = json.at(prefix + "_ms_max").get<double>();
  t.q1 = json.at(prefix + "_ms_q1").get<double>();
  t.q3 = json.at(prefix + "_ms_q3").get<double>();
  t.frames = json.at(prefix + "_ms_frames").get<std::vector<double>>();
  t.processMedian = json.at(prefix + "_process_cpu_ms_median").get<double>();
  return t;
}

// One frame: its wall time, and the CPU time of the whole process meanwhile, milliseconds.
struct FrameTime {
  double wallMs = 0.0, processMs = 0.0;
  double readbackMs = 0.0;  // of wallMs: the renderer's copy of finished buffers (RenderStats)
};
FrameTime renderTimed(Renderer& renderer, const Scene& scene, int width, int height, RenderOutput& out) {
  const double processStart = processCpuMilliseconds();
  const auto start = Clock::now();
  renderer.renderInto(scene, scene.settings, width, height, out);
  const double wall = std::chrono::duration<double, std::milli>(Clock::now() - start).count();
  return {wall, processCpuMilliseconds() - processStart, out.stats.readbackMilliseconds};
}

// Pixels a triangle covers (coveredAt). The lean GL frame reads back colour alone, so its
// coverage is its alpha: the bench clears the background with alpha 0 (see runBench).
std::uint64_t coveredPixels(const RenderOutput& out) {
  std::uint64_t covered = 0;
  const std::size_t pixels = out.rgba.size() / 4;
  for (std::size_t i = 0; i < pixels; ++i) covered += coveredAt(out, i) ? 1 : 0;
  return covered;
}

int defaultThreads() {
  const unsigned online = std::thread::hardware_concurrency();  // 0 when unknown
  return std::clamp(static_cast<int>(online), 1, kMaxBenchThreads);
}

// Sets LP_NUM_THREADS unless the environment already asks for the same count; returns a note
// for the report when it replaced a different value.
std::string setLlvmpipeThreads(int threads) {
  const std::string wanted = std::to_string(threads);
  const char* existing = std::getenv(kLlvmpipeThreadsVariable);
  std::string note;
  if (existing && wanted != existing) {
    note = std::string(kLlvmpipeThreadsVariable) + " was " + existing + ", set to " + wanted +
           " to match the CPU pipeline";
  }
  setenv(kLlvmpipeThreadsVariable, wanted.c_str(), 1);
  return note;
}

// Prints "bench: frame i/N ..." on stderr once a run is long, at most once per interval.
class Progress {
 public:
  explicit Progress(int total) : total_(total), start_(Clock::now()), last_(start_) {}
  void frame(int done, const char* what) {
    const auto now = Clock::now();
    const double sinceStart = std::chrono::duration<double>(now - start_).count();
    const double sinceLast = std::chrono::duration<double>(now - last_).count();
    if (sinceStart < kProgressAfterSeconds || (printed_ && sinceLast < kProgressIntervalSeconds)) return;
    std::cerr << "bench: " << what << " frame " << done << "/" << total_ << " (" << std::fixed << std::setprecision(1)
              << sinceStart << " s)\n";
    last_ = now;
    printed_ = true;
  }

 private:
  int total_;
  Clock::time_point start_, last_;
  bool printed_ = false;
};

// The arguments that make a child `bench` see the same scene, size, settings and threads.
std::vector<std::string> childArguments(const BenchArgs& args, int width, int height, int threads) {
  const RenderRequest& r = args.request;
  std::vector<std::string> argv = {"twinraster", "bench", r.scenePath,
                                   "--width", std::to_string(width),
                                   "--height", std::to_string(height),
                                   "--frames", std::to_string(args.frames),
                                   "--warmup", std::to_string(args.warmup),
                                   "--threads", std::to_string(threads),
                                   "--gl-precise-child"};
  for (const std::string& argument : glRequestArguments(args.gl)) argv.push_back(argument);
  for (const std::string& argument : overrideArguments(r)) argv.push_back(argument);
  return argv;
}

// Runs /proc/self/exe with `arguments`, its stdout captured (stderr shared, so its progress
// shows); returns the stdout text. Throws InputError when it cannot start or fails.
std::string runSelf(std::vector<std::string> arguments) {
  ChildProcess child;
  child.program = "/proc/self/exe";
  child.argv = std::move(arguments);
  child.captureStdout = true;
  const ChildResult result = runChildProcess(child);
  if (result.spawnError != 0) {
    throw InputError("bench --gl-precise: cannot start /proc/self/exe (error " + std::to_string(result.spawnError) + ")");
  }
  if (result.exitCode != 0) {
    throw InputError("bench --gl-precise: the child process timing llvmpipe's precise sampling failed (status " +
                     std::to_string(result.waitStatus) + ")");
  }
  return result.stdoutText;
}

std::string fixed(double v, int digits) {
  std::ostringstream out;
  out << std::fixed << std::setprecision(digits) << v;
  return out.str();
}

void printTimingLine(const std::string& label, const Timing& t) {
  std::cout << "  " << std::left << std::setw(20) << label << std::right << " median " << std::setw(8)
            << fixed(t.median, 2) << " ms  min " << std::setw(8) << fixed(t.min, 2) << "  max " << std::setw(8)
            << fixed(t.max, 2) << "  iqr " << std::setw(6) << fixed(t.q3 - t.q1, 2) << "  process cpu "
            << std::setw(8) << fixed(t.processMedian, 2) << " ms\n";
}

// Every --cpu-isa this machine runs, best first, and the same as "a, b, c".
Json supportedIsaNames() {
  Json names = Json::array();
  for (const CpuIsa isa : supportedCpuIsas()) names.push_back(std::string(toString(isa)));
  return names;
}

std::string joined(const Json& names) {
  std::string list;
  for (const Json& name : names) list += (list.empty() ? "" : ", ") + name.get<std::string>();
  return list;
}

void printText(const Json& j, const Timing& cpu, const Timing& gl, const Timing& glLean,
               const std::optional<Timing>& glPrecise) {
  std::cout << "bench " << j["scene"].get<std::string>() << " at " << j["width"] << "x" << j["height"] << ": "
            << j["triangles"] << " triangles, " << j["covered_pixels"] << " covered pixels, " << j["threads"]
            << " threads, " << j["frames"] << " frames after " << j["warmup"] << " warm-up\n";
  std::cout << "  cpu target: "
            << (j["cpu_isa"].is_null() ? std::string("none (the teaching path runs no SIMD kernels)")
                                       : j["cpu_isa"].get<std::string>())
            << "; this machine runs " << joined(j["cpu_isas_supported"]) << "\n";
  printTimingLine("cpu " + j["cpu_path"].get<std::string>(), cpu);
  printTimingLine("gl (fast)", gl);
  printTimingLine("gl lean (fast)", glLean);
  if (glPrecise) printTimingLine("gl (precise)", *glPrecise);
  std::cout << "  gl (fast) of which glReadPixels " << fixed(j["gl_readback_ms_median"].get<double>(), 2)
            << " ms (median); drawing alone " << fixed(j["gl_draw_ms_median"].get<double>(), 2) << " ms\n";
  std::cout << "  gl lean: colour + depth, one glReadPixels of the colour ("
            << fixed(j["gl_lean_readback_ms_median"].get<double>(), 2) << " ms median), no occlusion query\n";
  std::cout << "  ratio cpu/gl " << fixed(j["ratio_cpu_over_gl"].get<double>(), 3) << ", cpu/gl drawing "
            << fixed(j["ratio_cpu_over_gl_draw"].get<double>(), 3) << ", cpu/gl lean "
            << fixed(j["ratio_cpu_over_gl_lean"].get<double>(), 3);
  if (glPrecise) std::cout << ", cpu/gl precise " << fixed(j["ratio_cpu_over_gl_precise"].get<double>(), 3);
  std::cout << " (medians); cpu " << fixed(j["cpu_ns_per_covered_pixel"].get<double>(), 1)
            << " ns per covered pixel, gl lean " << fixed(j["gl_lean_ns_per_covered_pixel"].get<double>(), 1)
            << " ns\n";
  if (j.contains("per_isa")) {
    std::cout << "  fast path per target (each its own renderer, same frames; ratio over gl lean):\n";
    for (const Json& entry : j["per_isa"]) {
      std::cout << "    " << std::left << std::setw(8) << entry["cpu_isa"].get<std::string>() << std::right
                << " median " << std::setw(8) << fixed(entry["cpu_ms_median"].get<double>(), 2)
                << " ms  cpu/gl lean " << fixed(entry["ratio_cpu_over_gl_lean"].get<double>(), 3) << "\n";
    }
  }
  std::cout << "  gl: " << j["gl_renderer"].get<std::string>() << ", " << j["gl_version"].get<std::string>() << "; "
            << j["gl_context"].get<std::string>() << "\n";
  if (j.contains("note")) std::cout << "  note: " << j["note"].get<std::string>() << "\n";
}

void validate(const BenchArgs& args) {
  if (args.frames < 1 || args.frames > kMaxFrames) {
    throw InputError("bench --frames: expected an integer in [1, " + std::to_string(kMaxFrames) + "], got " +
                     std::to_string(args.frames));
  }
  if (args.warmup < 0 || args.warmup > kMaxWarmup) {
    throw InputError("bench --warmup: expected an integer in [0, " + std::to_string(kMaxWarmup) + "], got " +
                     std::to_string(args.warmup));
  }
  if (args.threads && (*args.threads < 1 || *args.threads > kMaxBenchThreads)) {
    throw InputError("bench --threads: expected an integer in [1, " + std::to_string(kMaxBenchThreads) + "], got " +
                     std::to_string(*args.threads));
  }
}

// The child of --gl-precise: GL only, precise sampling, JSON on stdout.
void runPreciseChild(const BenchArgs& args, const Scene& scene, int width, int height) {
  GlOptions options = requestedGlOptions(args.gl);
  options.fastSampling = false;
  const std::unique_ptr<Renderer> gl = makeGlRenderer(options);
  RenderOutput out;
  for (int i = 0; i < args.warmup; ++i) renderTimed(*gl, scene, width, height, out);
  std::vector<double> ms, processMs;
  Progress progress(args.frames);
  for (int i = 0; i < args.frames; ++i) {
    const FrameTime t = renderTimed(*gl, scene, width, height, out);
    ms.push_back(t.wallMs);
    processMs.push_back(t.processMs);
    progress.frame(i + 1, "gl precise");
  }
  Json json;
  addTiming(json, "gl_precise", summarise(ms, processMs));
  json["gl_sampling"] = glSamplingMode();
  std::cout << jsonText(json) << "\n";
}

// One fast-path renderer of --all-isas and its frame times (milliseconds).
struct IsaRun {
  CpuIsa isa = CpuIsa::Auto;
  std::unique_ptr<Renderer> renderer;
  std::vector<double> ms, processMs;
  RenderOutput out;  // this target's frames, each drawn into the last one's buffers
};

void runBench(BenchArgs args) {
  validate(args);
  if (args.cpuScalar) args.cpu.isa = "scalar";  // --cpu-scalar is --cpu-isa scalar (they exclude each other)
  const int threads = args.threads.value_or(defaultThreads());
  const CpuOptions cpuOptions = requestedCpuOptions(args.cpu, threads);
  GlOptions glOptions = requestedGlOptions(args.gl);
  // Background alpha 0, whatever the file says: the lean GL frame has no triangle ids, so only
  // alpha can count its covered pixels. The clear costs the same with any alpha.
  Scene scene = loadRequestedScene(args.request);
  scene.output.background.a = 0.0f;
  const int width = requestedWidth(args.request, scene);
  const int height = requestedHeight(args.request, scene);
  const std::string note = setLlvmpipeThreads(threads);
  if (args.preciseChild) {
    runPreciseChild(args, scene, width, height);
    return;
  }

  glOptions.verbose = args.request.verbose;
  glOptions.fastSampling = true;  // llvmpipe's default, what a user gets
  const std::unique_ptr<Renderer> gl = makeGlRenderer(glOptions);
  GlOptions glLeanOptions = glOptions;
  glLeanOptions.frame = GlFrame::Lean;
  const std::unique_ptr<Renderer> glLean = makeGlRenderer(glLeanOptions);
  const std::unique_ptr<Renderer> cpu = makeCpuRenderer(cpuOptions);
  std::vector<IsaRun> isaRuns;
  if (args.allIsas) {
    for (const CpuIsa isa : supportedCpuIsas()) {
      CpuOptions options;
      options.threads = threads;
      options.path = CpuPath::Fast;
      options.isa = isa;
      isaRuns.push_back({isa, makeCpuRenderer(options), {}, {}, {}});
    }
  }

  RenderOutput cpuOut, glOut, glLeanOut;
  for (int i = 0; i < args.warmup; ++i) {
    renderTimed(*cpu, scene, width, height, cpuOut);
    renderTimed(*gl, scene, width, height, glOut);
    renderTimed(*glLean, scene, width, height, glLeanOut);
    for (IsaRun& run : isaRuns) renderTimed(*run.renderer, scene, width, height, run.out);
  }
  std::vector<double> cpuMs, glMs, cpuProcessMs, glProcessMs, glReadbackMs, glDrawMs;
  std::vector<double> glLeanMs, glLeanProcessMs, glLeanReadbackMs;
  Progress progress(args.frames);
  const char* progressLabel = isaRuns.empty() ? "cpu + gl + gl lean" : "cpu + gl + gl lean + every target";
  for (int i = 0; i < args.frames; ++i) {
    const FrameTime c = renderTimed(*cpu, scene, width, height, cpuOut);
    const FrameTime g = renderTimed(*gl, scene, width, height, glOut);
    const FrameTime l = renderTimed(*glLean, scene, width, height, glLeanOut);
    cpuMs.push_back(c.wallMs);
    cpuProcessMs.push_back(c.processMs);
    glMs.push_back(g.wallMs);
    glProcessMs.push_back(g.processMs);
    glReadbackMs.push_back(g.readbackMs);
    glDrawMs.push_back(g.wallMs - g.readbackMs);
    glLeanMs.push_back(l.wallMs);
    glLeanProcessMs.push_back(l.processMs);
    glLeanReadbackMs.push_back(l.readbackMs);
    for (IsaRun& run : isaRuns) {
      const FrameTime t = renderTimed(*run.renderer, scene, width, height, run.out);
      run.ms.push_back(t.wallMs);
      run.processMs.push_back(t.processMs);
    }
    progress.frame(i + 1, progressLabel);
  }
  const Timing cpuTiming = summarise(cpuMs, cpuProcessMs);
  const Timing glTiming = summarise(glMs, glProcessMs);
  const Timing glLeanTiming = summarise(glLeanMs, glLeanProcessMs);
  std::optional<Timing> glPreciseTiming;
  if (args.glPrecise) {
    const std::string text = runSelf(childArguments(args, width, height, threads));
    try {
      glPreciseTiming = timingFromJson(Json::parse(text), "gl_precise");
    } catch (const nlohmann::json::exception& e) {
      throw InputError(std::string("bench --gl-precise: unexpected output from the child process: ") + e.what());
    }
  }

  const std::uint64_t covered = coveredPixels(cpuOut);
  warnIfEmpty(scene, cpuOut, true);  // timing an empty frame measures the clipper, not the pipeline
  Json json;
  json["scene"] = args.request.scenePath;
  json["width"] = width;
  json["height"] = height;
  json["frames"] = args.frames;
  json["warmup"] = args.warmup;
  json["threads"] = threads;
  json["threads_source"] = args.threads ? "--threads" : "default: hardware_concurrency(), as llvmpipe";
  json["cpu_path"] = cpuPathName(cpuOptions);
  // The fast path's target actually run; null on the teaching path (no SIMD kernels there).
  const std::string isaName = resolvedCpuIsaName(cpuOptions);
  json["cpu_isa"] = isaName.empty() ? Json(nullptr) : Json(isaName);
  json["cpu_isas_supported"] = supportedIsaNames();
  json["triangles"] = countTriangles(scene);
  json["covered_pixels"] = covered;
  json["covered_pixels_gl"] = coveredPixels(glOut);
  json["covered_pixels_gl_lean"] = coveredPixels(glLeanOut);
  addTiming(json, "cpu", cpuTiming);
  addTiming(json, "gl", glTiming);
  addTiming(json, "gl_lean", glLeanTiming);
  json["ratio_cpu_over_gl"] = cpuTiming.median / glTiming.median;
  json["ratio_cpu_over_gl_lean"] = cpuTiming.median / glLeanTiming.median;
  json["gl_lean_readback_ms_median"] = medianOf(glLeanReadbackMs);
  // llvmpipe's frame without glReadPixels (the CPU pipeline has no such copy: it draws into
  // the output's buffers): the strictest comparison, drawing against drawing.
  const double glDrawMedian = medianOf(glDrawMs);
  json["gl_draw_ms_median"] = glDrawMedian;
  json["gl_readback_ms_median"] = medianOf(glReadbackMs);
  json["ratio_cpu_over_gl_draw"] = cpuTiming.median / glDrawMedian;
  json["cpu_ns_per_covered_pixel"] = covered > 0 ? cpuTiming.median * 1e6 / static_cast<double>(covered) : 0.0;
  json["gl_ns_per_covered_pixel"] = covered > 0 ? glTiming.median * 1e6 / static_cast<double>(covered) : 0.0;
  json["gl_lean_ns_per_covered_pixel"] =
      covered > 0 ? glLeanTiming.median * 1e6 / static_cast<double>(covered) : 0.0;
  json["gl_sampling"] = glSamplingMode();
  json["gl_renderer"] = glRendererString();
  json["gl_version"] = glVersionString();
  json["gl_context"] = glContextString();
  if (glPreciseTiming) {
    addTiming(json, "gl_precise", *glPreciseTiming);
    json["ratio_cpu_over_gl_precise"] = cpuTiming.median / glPreciseTiming->median;
  }
  if (args.allIsas) {
    Json perIsa = Json::array();
    for (const IsaRun& run : isaRuns) {
      const double runMedian = medianOf(run.ms);
      perIsa.push_back(Json{{"cpu_isa", std::string(toString(run.isa))},
                            {"cpu_ms_median", runMedian},
                            {"ratio_cpu_over_gl_lean", runMedian / glLeanTiming.median}});
    }
    json["per_isa"] = std::move(perIsa);
  }
  if (!note.empty()) json["note"] = note;

  if (args.json) {
    std::cout << jsonText(json, 2) << "\n";
  } else {
    printText(json, cpuTiming, glTiming, glLeanTiming, glPreciseTiming);
  }
}

const bool benchRegistered = registerCommand(50, [](CLI::App& app) {
  auto args = std::make_shared<BenchArgs>();
  CLI::App* cmd = app.add_subcommand(
      "bench",
      "Time the CPU pipeline against llvmpipe in one process: frames alternate between the backends after a "
      "warm-up; prints the median and spread of each, ratio_cpu_over_gl (glrender's full frame: colour, depth, "
      "triangle ids, line mask, all read back) and ratio_cpu_over_gl_lean (the same draws into colour + depth, "
      "the colour read back: the frame an OpenGL user draws). Each renderer draws every frame into its previous "
      "output, whose buffers it reuses, as an application keeps its framebuffer. Both use the same thread count; "
      "llvmpipe samples textures in its default (fast) mode. Prints cpu_isa, the fast path's target actually run.");
  addRenderOptions(*cmd, args->request);
  cmd->add_option("--frames,-n", args->frames, "Timed frames per backend")->capture_default_str();
  cmd->add_option("--warmup", args->warmup, "Untimed frames per backend first (shader compilation, caches)")
      ->capture_default_str();
  CLI::Option* cpuIsa = addCpuOptions(*cmd, args->cpu);
  addGlOptions(*cmd, args->gl);
  cmd->add_flag("--cpu-scalar", args->cpuScalar, "Same as --cpu-isa scalar (kept for scripts that use it)")
      ->excludes(cpuIsa);
  cmd->add_flag("--all-isas", args->allIsas,
                "Also time the fast path on every target this machine runs (" + joined(supportedIsaNames()) +
                    "), each with its own renderer in the same loop: per_isa [{cpu_isa, cpu_ms_median, "
                    "ratio_cpu_over_gl_lean}]");
  cmd->add_option("--threads,-t", args->threads,
                  "Worker threads of the CPU pipeline and llvmpipe's LP_NUM_THREADS (default: the online CPUs, "
                  "llvmpipe's own default)");
  cmd->add_flag("--json", args->json, "Print one JSON object on stdout instead of the summary");
  cmd->add_flag("--gl-precise", args->glPrecise,
                "Also time llvmpipe's precise sampling (in a child process: llvmpipe fixes the mode per process)");
  cmd->add_flag("--gl-precise-child", args->preciseChild, "internal: the child process of --gl-precise")->group("");
  cmd->callback([args] { runBench(*args); });
});

}  // namespace
}  // namespace twr::cli
