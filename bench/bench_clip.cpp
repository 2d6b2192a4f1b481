// Stage 2, clip: clipTriangle on the default scene's triangles as a frame submits them (almost
// all trivially inside), and on triangles the near plane and a user plane cut.
#include "bench_stage_common.h"
#include "softrender/clip.h"

#include <benchmark/benchmark.h>

namespace {

using namespace twr;

void BM_ClipSceneTriangles(benchmark::State& state) {
  const benchstage::Frame& frame = benchstage::defaultFrame();
  ClipPolygon polygon, scratch;
  std::int64_t triangles = 0;
  for (auto _ : state) {
    for (std::size_t k = 0; k < frame.items.size(); ++k) {
      const Mesh& mesh = *frame.items[k].item->mesh;
      const std::vector<ClipVertex>& v = frame.vertices[k];
      for (std::size_t t = 0; t < mesh.triangleCount(); ++t) {
        const std::uint32_t cut = clipTriangle(v[mesh.indices[3 * t]], v[mesh.indices[3 * t + 1]],
                                               v[mesh.indices[3 * t + 2]], frame.items[k].clip, polygon, scratch);
        benchmark::DoNotOptimize(cut);
        ++triangles;
      }
    }
  }
  state.SetItemsProcessed(triangles);
}
BENCHMARK(BM_ClipSceneTriangles);

// One triangle crossing the near plane (w + z changes sign) and, with Arg 1, a user plane.
void BM_ClipCutTriangle(benchmark::State& state) {
  ClipVertex a, b, c;
  a.posClip = vec4(-0.5f, -0.5f, -2.0f, 1.0f);  // behind the near plane: w + z < 0
  b.posClip = vec4(0.5f, -0.5f, 0.5f, 1.0f);
  c.posClip = vec4(0.0f, 0.5f, 0.5f, 1.0f);
  a.clipDistance[0] = 1.0f;
  b.clipDistance[0] = -1.0f;
  c.clipDistance[0] = 0.5f;
  const ClipConfig config = makeClipConfig(ClipSwitches{}, static_cast<int>(state.range(0)), 1280, 720);
  ClipPolygon polygon, scratch;
  for (auto _ : state) {
    const std::uint32_t cut = clipTriangle(a, b, c, config, polygon, scratch);
    benchmark::DoNotOptimize(cut);
    benchmark::DoNotOptimize(polygon.count);
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_ClipCutTriangle)->Arg(0)->Arg(1);

}  // namespace

BENCHMARK_MAIN();
