// Stage 1, vertex: runVertexStage per vertex of the default scene's sphere, world and tangent
// lighting space (the latter adds the per-light tangent-space directions).
#include "bench_stage_common.h"

#include <benchmark/benchmark.h>

namespace {

using namespace twr;

void BM_VertexStage(benchmark::State& state, LightingSpace space) {
  const benchstage::Frame& frame = benchstage::defaultFrame();
  const ItemState& sphere = frame.items[1];
  RenderSettings settings = frame.scene.settings;
  settings.lightingSpace = space;
  const VertexUniforms& base = sphere.vertexUniforms;
  const VertexUniforms uniforms = makeVertexUniforms(base.worldFromModel, base.clipFromWorld, frame.scene, settings);
  const std::vector<Vertex>& vertices = sphere.item->mesh->vertices;
  for (auto _ : state) {
    for (const Vertex& v : vertices) {
      ClipVertex out = runVertexStage(v, uniforms);
      benchmark::DoNotOptimize(out);
    }
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(vertices.size()));
}
BENCHMARK_CAPTURE(BM_VertexStage, world, LightingSpace::World);
BENCHMARK_CAPTURE(BM_VertexStage, tangent, LightingSpace::Tangent);

}  // namespace

BENCHMARK_MAIN();
