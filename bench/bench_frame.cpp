// Whole frames: the CPU pipeline's teaching path, its fast path on the scalar Highway target
// and on the best one this CPU runs (auto), and llvmpipe, on the default scene and the OBJ
// scene (a house whose MTL gives the walls all three maps and the roof a normal map) at 720p;
// the default scene in debug colour views; and the fast path with an untimed llvmpipe frame before
// each of its frames, as `twinraster bench` alternates them.
// `twinraster bench` is the side-by-side measurement the docs quote; this one isolates each
// variant (and runs under perf or callgrind without the other backend in the profile).
#include "glrender/gl_renderer.h"
#include "scene/scene_file.h"
#include "softrender/cpu_renderer.h"

#include <benchmark/benchmark.h>

#include <cstdint>
#include <cstdlib>
#include <functional>
#include <string>

namespace {

using namespace twr;

constexpr int kWidth = 1280;   // pixels
constexpr int kHeight = 720;   // pixels

// "default", "obj" (assets/scenes/obj_model.json) or "1m" (bench/scenes/bench_1m.json).
const Scene& sceneNamed(const std::string& name) {
  const std::string root = TWINRASTER_SOURCE_DIR;
  static const Scene defaultScene = loadSceneFile(root + "/assets/scenes/default.json");
  static const Scene objScene = loadSceneFile(root + "/assets/scenes/obj_model.json");
  if (name == "default") return defaultScene;
  if (name == "obj") return objScene;
  static const Scene millionScene = loadSceneFile(root + "/bench/scenes/bench_1m.json");
  return millionScene;
}

// Each frame drawn into the last one's buffers (Renderer::renderInto, as `twinraster bench`).
// `between`, if any, runs untimed before each frame.
void runFrames(benchmark::State& state, Renderer& renderer, const Scene& scene, const RenderSettings& settings,
               const std::function<void()>& between = {}) {
  std::uint64_t shaded = 0;
  RenderOutput out;
  for (auto _ : state) {
    if (between) {
      state.PauseTiming();
      between();
      state.ResumeTiming();
    }
    renderer.renderInto(scene, settings, kWidth, kHeight, out);
    shaded = out.stats.pixelsShaded;
    benchmark::DoNotOptimize(out.rgba.data());
  }
  state.counters["pixels_shaded"] = static_cast<double>(shaded);
  state.counters["ns_per_pixel"] =
      benchmark::Counter(static_cast<double>(shaded), benchmark::Counter::kIsIterationInvariantRate |
                                                           benchmark::Counter::kInvert);
}

// Args: threads.
// `best`: the fast path on the best Highway target this CPU runs (auto), else its scalar one.
void BM_CpuFrame(benchmark::State& state, std::string file, CpuPath path, bool best) {
  const auto renderer =
      makeCpuRenderer(CpuOptions{static_cast<int>(state.range(0)), path, best ? CpuIsa::Auto : CpuIsa::Scalar});
  const Scene& scene = sceneNamed(file);
  runFrames(state, *renderer, scene, scene.settings);
}

// The same with a lean llvmpipe frame of the scene drawn (untimed) before each, as `twinraster
// bench` alternates them: the CPU frame then finds its textures, buffers and code evicted from
// the caches by llvmpipe's. LP_NUM_THREADS as for BM_GlFrame.
void BM_CpuFrameAfterGl(benchmark::State& state, std::string file) {
  const auto renderer = makeCpuRenderer(CpuOptions{static_cast<int>(state.range(0)), CpuPath::Fast, CpuIsa::Auto});
  GlOptions options;
  options.fastSampling = true;
  options.frame = GlFrame::Lean;
  const auto gl = makeGlRenderer(options);
  const Scene& scene = sceneNamed(file);
  RenderOutput glOut;
  runFrames(state, *renderer, scene, scene.settings,
            [&] { gl->renderInto(scene, scene.settings, kWidth, kHeight, glOut); });
}

// The default scene in one debug colour view (what the GUI shows beside the lit image).
// Args: threads.
void BM_CpuViewFrame(benchmark::State& state, View view, CpuPath path, bool best) {
  const auto renderer =
      makeCpuRenderer(CpuOptions{static_cast<int>(state.range(0)), path, best ? CpuIsa::Auto : CpuIsa::Scalar});
  const Scene& scene = sceneNamed("default");
  RenderSettings settings = scene.settings;
  settings.view = view;
  runFrames(state, *renderer, scene, settings);
}

// llvmpipe in its default (fast) sampling; LP_NUM_THREADS is read once per process, so the
// GL benchmark runs with the thread count given by the environment (default: the CPUs).
void BM_GlFrame(benchmark::State& state, std::string file) {
  GlOptions options;
  options.fastSampling = true;
  const auto renderer = makeGlRenderer(options);
  const Scene& scene = sceneNamed(file);
  renderer->render(scene, scene.settings, kWidth, kHeight);  // shader compilation
  runFrames(state, *renderer, scene, scene.settings);
}

BENCHMARK_CAPTURE(BM_CpuFrame, default_teaching, std::string("default"), CpuPath::Teaching, false)
    ->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(BM_CpuFrame, default_fast_scalar, std::string("default"), CpuPath::Fast, false)
    ->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(BM_CpuFrame, default_fast_auto, std::string("default"), CpuPath::Fast, true)
    ->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(BM_CpuFrame, obj_fast_auto, std::string("obj"), CpuPath::Fast, true)
    ->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(BM_CpuFrame, 1m_fast_auto, std::string("1m"), CpuPath::Fast, true)
    ->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(BM_CpuFrameAfterGl, default_fast_auto, std::string("default"))
    ->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(BM_CpuFrameAfterGl, 1m_fast_auto, std::string("1m"))
    ->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(BM_CpuViewFrame, albedo_teaching, View::Albedo, CpuPath::Teaching, false)
    ->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(BM_CpuViewFrame, albedo_fast_auto, View::Albedo, CpuPath::Fast, true)
    ->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(BM_CpuViewFrame, normal_fast_auto, View::Normal, CpuPath::Fast, true)
    ->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(BM_CpuViewFrame, light_tangent_fast_auto, View::LightTangent, CpuPath::Fast, true)
    ->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(BM_CpuViewFrame, depth_fast_auto, View::Depth, CpuPath::Fast, true)
    ->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(BM_GlFrame, default_llvmpipe, std::string("default"))->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(BM_GlFrame, obj_llvmpipe, std::string("obj"))->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(BM_GlFrame, 1m_llvmpipe, std::string("1m"))->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
