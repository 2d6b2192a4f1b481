// Stages 6-8, shade: shadeFragment for the default scene's brick material (diffuse, normal and
// specular maps, two lights, world space), scalar; its texture sampling alone; and the Phong
// exponent three ways: powPositive (scalar, what both paths compute), libm's powf, and the
// fast path's version of it (phongPow over each target's vectors) per value.
#include "bench_stage_common.h"
#include "softrender/fast_kernels.h"
#include "softrender/interpolate.h"
#include "softrender/setup.h"
#include "softrender/phong_pow.h"
#include "softrender/shade.h"
#include "softrender/texture_sample.h"

#include <benchmark/benchmark.h>

#include <cmath>
#include <random>

namespace {

using namespace twr;

constexpr int kSamples = 4096;  // fragments or values per iteration

// Fragments on the sphere: three random vertices' varyings laid on a 64-pixel right triangle
// (their own 1/w), read at a random pixel inside it.
std::vector<Fragment> sphereFragments() {
  constexpr float kSide = 64.0f;  // pixels
  const benchstage::Frame& frame = benchstage::defaultFrame();
  const std::vector<ClipVertex>& v = frame.vertices[1];
  std::mt19937 rng(5);
  std::uniform_int_distribution<std::size_t> pick(0, v.size() - 1);
  std::uniform_int_distribution<int> pixel(0, static_cast<int>(kSide) / 2 - 1);
  std::vector<Fragment> fragments;
  while (fragments.size() < static_cast<std::size_t>(kSamples)) {
    const ClipVertex &a = v[pick(rng)], &b = v[pick(rng)], &c = v[pick(rng)];
    const auto corner = [](float x, float y, const ClipVertex& cv) {
      WindowVertex w;
      w.x = x;
      w.y = y;
      w.invW = 1.0f / cv.posClip.w;
      return w;
    };
    const std::array<WindowVertex, 3> window{corner(0.5f, 0.5f, a), corner(kSide + 0.5f, 0.5f, b),
                                             corner(0.5f, kSide + 0.5f, c)};
    TriangleSetup setup;
    if (setupTriangle(window, CullMode::None, FrontFace::Ccw, Viewport{128, 128}, setup) != SetupResult::Ready) continue;
    fragments.push_back(interpolateFragment(makeVaryingPlanes(window, a, b, c, false, 0, setup), pixel(rng), pixel(rng), 0.5f));
  }
  return fragments;
}

void BM_ShadeFragment(benchmark::State& state) {
  const benchstage::Frame& frame = benchstage::defaultFrame();
  const ItemState& s = frame.items[1];
  const std::vector<Fragment> fragments = sphereFragments();
  for (auto _ : state) {
    for (const Fragment& f : fragments) {
      withShaderFeatures(s.shaderKey, [&]<typename Features>() {
        benchmark::DoNotOptimize(shadeFragment<Features>(f, s.shade, nullptr));
      });
    }
  }
  state.SetItemsProcessed(state.iterations() * kSamples);
}
BENCHMARK(BM_ShadeFragment);

void BM_SampleTexture(benchmark::State& state, TextureFilter filter) {
  const Texture& texture = *benchstage::defaultFrame().items[1].shade.diffuseMap;
  const std::vector<Fragment> fragments = sphereFragments();
  for (auto _ : state) {
    for (const Fragment& f : fragments) benchmark::DoNotOptimize(sampleTexture(texture, f.uv, filter));
  }
  state.SetItemsProcessed(state.iterations() * kSamples);
}
BENCHMARK_CAPTURE(BM_SampleTexture, bilinear, TextureFilter::Bilinear);
BENCHMARK_CAPTURE(BM_SampleTexture, nearest, TextureFilter::Nearest);

std::vector<float> powBases() {
  std::mt19937 rng(9);
  std::uniform_real_distribution<float> base(0.0f, 1.0f);
  std::vector<float> x(kSamples);
  for (float& v : x) v = base(rng);
  return x;
}
constexpr float kShininess = 32.0f;

void BM_PowPositive(benchmark::State& state) {
  const std::vector<float> x = powBases();
  for (auto _ : state) {
    for (float v : x) benchmark::DoNotOptimize(powPositive(v, kShininess));
  }
  state.SetItemsProcessed(state.iterations() * kSamples);
}
BENCHMARK(BM_PowPositive);

void BM_LibmPowf(benchmark::State& state) {
  const std::vector<float> x = powBases();
  for (auto _ : state) {
    for (float v : x) benchmark::DoNotOptimize(std::pow(v, kShininess));
  }
  state.SetItemsProcessed(state.iterations() * kSamples);
}
BENCHMARK(BM_LibmPowf);

// Argument: index into supportedCpuIsas() (best first); indices past the end are skipped.
void BM_PowLanes(benchmark::State& state) {
  const std::vector<CpuIsa> isas = supportedCpuIsas();
  if (static_cast<std::size_t>(state.range(0)) >= isas.size()) {
    state.SkipWithError("no such target on this CPU");
    return;
  }
  const FastKernels kernels = fastKernelsFor(isas[static_cast<std::size_t>(state.range(0))]);
  state.SetLabel(std::string(toString(kernels.isa)));
  const std::vector<float> x = powBases();
  std::vector<float> out(x.size());
  for (auto _ : state) {
    kernels.phongPow(x.data(), kShininess, out.data(), x.size());
    benchmark::DoNotOptimize(out.data());
  }
  state.SetItemsProcessed(state.iterations() * kSamples);
}
BENCHMARK(BM_PowLanes)->DenseRange(0, 4);

}  // namespace

BENCHMARK_MAIN();
