// Stage 3, setup: the divide by w, viewport and snap of three vertices plus setupTriangle (the
// teaching path per triangle); setupSnappedTriangle alone on pre-snapped corners (the fast
// path, which snaps each vertex once); and the barycentric planes of makeInterpolationSetup.
#include "bench_stage_common.h"
#include "softrender/interpolate.h"
#include "softrender/setup.h"

#include <benchmark/benchmark.h>

namespace {

using namespace twr;

struct Corners {
  std::array<WindowVertex, 3> window;
  std::array<std::int32_t, 3> x, y;
};

// Every triangle of the default scene's sphere, in window space.
const std::vector<Corners>& sphereTriangles() {
  static const std::vector<Corners> corners = [] {
    const benchstage::Frame& frame = benchstage::defaultFrame();
    const Mesh& mesh = *frame.items[1].item->mesh;
    std::vector<Corners> out;
    for (std::size_t t = 0; t < mesh.triangleCount(); ++t) {
      Corners c;
      for (std::size_t i = 0; i < 3; ++i) {
        c.window[i] = windowFromClip(frame.vertices[1][mesh.indices[3 * t + i]], frame.items[1].viewport);
        c.x[i] = snapToSubpixel(c.window[i].x);
        c.y[i] = snapToSubpixel(c.window[i].y);
      }
      out.push_back(c);
    }
    return out;
  }();
  return corners;
}

void BM_WindowAndSetup(benchmark::State& state) {
  const benchstage::Frame& frame = benchstage::defaultFrame();
  const ItemState& s = frame.items[1];
  const Mesh& mesh = *s.item->mesh;
  for (auto _ : state) {
    for (std::size_t t = 0; t < mesh.triangleCount(); ++t) {
      const std::array<WindowVertex, 3> window{windowFromClip(frame.vertices[1][mesh.indices[3 * t]], s.viewport),
                                               windowFromClip(frame.vertices[1][mesh.indices[3 * t + 1]], s.viewport),
                                               windowFromClip(frame.vertices[1][mesh.indices[3 * t + 2]], s.viewport)};
      TriangleSetup setup;
      benchmark::DoNotOptimize(setupTriangle(window, s.cull, s.frontFace, s.viewport, setup));
    }
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(mesh.triangleCount()));
}
BENCHMARK(BM_WindowAndSetup);

void BM_SetupSnapped(benchmark::State& state) {
  const ItemState& s = benchstage::defaultFrame().items[1];
  const std::vector<Corners>& triangles = sphereTriangles();
  for (auto _ : state) {
    for (const Corners& c : triangles) {
      TriangleSetup setup;
      benchmark::DoNotOptimize(setupSnappedTriangle(c.x, c.y, s.cull, s.frontFace, s.viewport, setup));
    }
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(triangles.size()));
}
BENCHMARK(BM_SetupSnapped);

// Any uvs: the uv planes cost the same for all.
const std::array<vec2, 3> kCornerUvs{vec2(0.0f, 0.0f), vec2(1.0f, 0.0f), vec2(0.0f, 1.0f)};

void BM_InterpolationSetup(benchmark::State& state) {
  const ItemState& s = benchstage::defaultFrame().items[1];
  std::vector<std::pair<Corners, TriangleSetup>> accepted;
  for (const Corners& c : sphereTriangles()) {
    TriangleSetup setup;
    if (setupSnappedTriangle(c.x, c.y, s.cull, s.frontFace, s.viewport, setup) == SetupResult::Ready) {
      accepted.emplace_back(c, setup);
    }
  }
  for (auto _ : state) {
    for (const auto& [c, setup] : accepted) benchmark::DoNotOptimize(makeInterpolationSetup(c.window, kCornerUvs, setup));
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(accepted.size()));
}
BENCHMARK(BM_InterpolationSetup);

}  // namespace

BENCHMARK_MAIN();
