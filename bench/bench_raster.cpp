// Stage 4, raster: the span rasterizer (coveredSpan per row: the teaching path's traversal)
// over the default scene's front-facing triangles, and the fast path's visibility
// pass of each supported target (covered spans, double depth, GL_LESS) over the same triangles into a
// cleared depth buffer. Items are covered pixels.
#include "bench_stage_common.h"
#include "softrender/fast_kernels.h"
#include "softrender/framebuffer.h"
#include "softrender/interpolate.h"
#include "softrender/raster.h"
#include "softrender/setup.h"

#include <benchmark/benchmark.h>

namespace {

using namespace twr;

struct SetUpTriangle {
  std::array<WindowVertex, 3> window;
  TriangleSetup setup;
};

// The triangles of the default scene that setup accepts (no clipping needed for this view
// except the floor, whose two triangles are clipped: they are drawn as their fan).
const std::vector<SetUpTriangle>& acceptedTriangles() {
  static const std::vector<SetUpTriangle> triangles = [] {
    const benchstage::Frame& frame = benchstage::defaultFrame();
    std::vector<SetUpTriangle> out;
    for (std::size_t k = 0; k < frame.items.size(); ++k) {
      const ItemState& s = frame.items[k];
      const Mesh& mesh = *s.item->mesh;
      ClipPolygon polygon, scratch;
      for (std::size_t t = 0; t < mesh.triangleCount(); ++t) {
        clipTriangle(frame.vertices[k][mesh.indices[3 * t]], frame.vertices[k][mesh.indices[3 * t + 1]],
                     frame.vertices[k][mesh.indices[3 * t + 2]], s.clip, polygon, scratch);
        for (int i = 1; i + 1 < polygon.count; ++i) {
          SetUpTriangle u;
          const std::size_t b = static_cast<std::size_t>(i), c = static_cast<std::size_t>(i + 1);
          u.window = {windowFromClip(polygon.v[0], s.viewport), windowFromClip(polygon.v[b], s.viewport),
                      windowFromClip(polygon.v[c], s.viewport)};
          if (setupTriangle(u.window, s.cull, s.frontFace, s.viewport, u.setup) == SetupResult::Ready) out.push_back(u);
        }
      }
    }
    return out;
  }();
  return triangles;
}

void BM_SpanRasterizer(benchmark::State& state) {
  std::int64_t pixels = 0;
  for (auto _ : state) {
    for (const SetUpTriangle& t : acceptedTriangles()) {
      rasterizeTriangle(t.setup, 0, benchstage::kHeight, [&](int, Span span) { pixels += span.xEnd - span.xBegin; });
    }
  }
  state.SetItemsProcessed(pixels);
}
BENCHMARK(BM_SpanRasterizer);

// Argument: index into supportedCpuIsas() (best first); indices past the end are skipped.
void BM_Visibility(benchmark::State& state) {
  const std::vector<CpuIsa> isas = supportedCpuIsas();
  if (static_cast<std::size_t>(state.range(0)) >= isas.size()) {
    state.SkipWithError("no such target on this CPU");
    return;
  }
  const FastKernels kernels = fastKernelsFor(isas[static_cast<std::size_t>(state.range(0))]);
  state.SetLabel(std::string(toString(kernels.isa)));
  Framebuffer fb = makeFramebuffer(benchstage::kWidth, benchstage::kHeight, vec4(0.0f, 0.0f, 0.0f, 1.0f));
  std::vector<std::uint32_t> slots(static_cast<std::size_t>(benchstage::kWidth) * benchstage::kHeight, kNoSlot);
  std::int64_t passed = 0;
  for (auto _ : state) {
    state.PauseTiming();
    std::fill(fb.depth.begin(), fb.depth.end(), kClearDepth);
    state.ResumeTiming();
    std::uint32_t slot = 0;
    for (const SetUpTriangle& t : acceptedTriangles()) {
      bool covered = false;
      passed += static_cast<std::int64_t>(
          kernels.visibility(t.setup, t.window, slot++, 0, benchstage::kHeight, fb, slots.data(), covered));
    }
  }
  state.SetItemsProcessed(passed);
}
BENCHMARK(BM_Visibility)->DenseRange(0, 4);

}  // namespace

BENCHMARK_MAIN();
