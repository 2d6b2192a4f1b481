// Stage 5, interpolation: pixelWeights (double barycentrics, depth, perspective weights; the
// pixel trace's), the varying planes' setup per triangle, and interpolateFragment (the
// varyings from their planes) at every pixel of a 64 x 64 patch inside the default scene's
// floor, scalar, as the teaching path runs them.
#include "bench_stage_common.h"
#include "softrender/clip.h"
#include "softrender/interpolate.h"
#include "softrender/raster.h"
#include "softrender/setup.h"

#include <benchmark/benchmark.h>

namespace {

using namespace twr;

constexpr int kPatch = 64;  // pixels per side, from (600, 40) in GL window coordinates
constexpr int kPatchX = 600, kPatchY = 40;

struct Floor {
  std::array<ClipVertex, 3> v;
  std::array<WindowVertex, 3> window;
  TriangleSetup setup;
  InterpolationSetup interpolation;
  VaryingPlanes varyings;
};

// The floor's fan triangle holding the patch.
const Floor& floorTriangle() {
  static const Floor floor = [] {
    const benchstage::Frame& frame = benchstage::defaultFrame();
    const ItemState& s = frame.items[0];
    const Mesh& mesh = *s.item->mesh;
    ClipPolygon polygon, scratch;
    for (std::size_t t = 0; t < mesh.triangleCount(); ++t) {
      clipTriangle(frame.vertices[0][mesh.indices[3 * t]], frame.vertices[0][mesh.indices[3 * t + 1]],
                   frame.vertices[0][mesh.indices[3 * t + 2]], s.clip, polygon, scratch);
      for (int i = 1; i + 1 < polygon.count; ++i) {
        Floor f;
        f.v = {polygon.v[0], polygon.v[static_cast<std::size_t>(i)], polygon.v[static_cast<std::size_t>(i + 1)]};
        const std::array<WindowVertex, 3> window{windowFromClip(f.v[0], s.viewport), windowFromClip(f.v[1], s.viewport),
                                                 windowFromClip(f.v[2], s.viewport)};
        TriangleSetup setup;
        if (setupTriangle(window, s.cull, s.frontFace, s.viewport, setup) != SetupResult::Ready) continue;
        if (!coversPixel(setup, kPatchX, kPatchY) || !coversPixel(setup, kPatchX + kPatch, kPatchY + kPatch)) continue;
        f.window = window;
        f.setup = setup;
        f.interpolation = makeInterpolationSetup(window, {f.v[0].uv, f.v[1].uv, f.v[2].uv}, setup);
        f.varyings = makeVaryingPlanes(window, f.v[0], f.v[1], f.v[2], false, 0, setup);
        return f;
      }
    }
    return Floor{};
  }();
  return floor;
}

void BM_PixelWeights(benchmark::State& state) {
  const Floor& f = floorTriangle();
  for (auto _ : state) {
    for (int y = kPatchY; y < kPatchY + kPatch; ++y) {
      for (int x = kPatchX; x < kPatchX + kPatch; ++x) benchmark::DoNotOptimize(pixelWeights(f.interpolation, x, y));
    }
  }
  state.SetItemsProcessed(state.iterations() * kPatch * kPatch);
}
BENCHMARK(BM_PixelWeights);

void BM_VaryingPlanes(benchmark::State& state) {
  const Floor& f = floorTriangle();
  for (auto _ : state) benchmark::DoNotOptimize(makeVaryingPlanes(f.window, f.v[0], f.v[1], f.v[2], false, 0, f.setup));
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_VaryingPlanes);

void BM_InterpolateFragment(benchmark::State& state) {
  const Floor& f = floorTriangle();
  for (auto _ : state) {
    for (int y = kPatchY; y < kPatchY + kPatch; ++y) {
      for (int x = kPatchX; x < kPatchX + kPatch; ++x) {
        benchmark::DoNotOptimize(interpolateFragment(f.varyings, x, y, 0.5f));
      }
    }
  }
  state.SetItemsProcessed(state.iterations() * kPatch * kPatch);
}
BENCHMARK(BM_InterpolateFragment);

}  // namespace

BENCHMARK_MAIN();
