// The CPU software pipeline behind the Renderer interface.
#pragma once

#include "scene/renderer.h"

#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace twr {

// Two traversals of the same stages, giving the same image, depth, triangle ids and
// statistics bit for bit (tests/softrender/test_fast_path.cpp checks the whole suite):
//   Teaching  one stage after the other as docs/pipeline.md draws them (cpu_renderer.cpp):
//             every thread takes a band of rows and walks every triangle, one pixel at a
//             time, with the shading source instantiated for float;
//   Fast      the stages reorganised for speed (softrender/fast_pipeline.h): vertex
//             results reused per triangle, triangles binned once, a visibility pass, then the
//             same shading source instantiated for Highway vectors (docs/performance.md).
enum class CpuPath { Teaching, Fast };

// The Highway target the fast path's kernels run on (names as Highway's targets; Avx512 is
// Highway's AVX3). Auto: the best target compiled in that this CPU runs.
enum class CpuIsa { Auto, Avx512, Avx2, Sse4, Neon, Scalar };

struct CpuOptions {
  // Worker threads (values below 1 mean 1). The image and the statistics are the same for
  // any count.
  int threads = 1;
  CpuPath path = CpuPath::Fast;
  // Fast path only: which target's kernels run. Every target draws the same bits.
  CpuIsa isa = CpuIsa::Auto;
};

// Throws InputError when options.isa is a target this binary or this CPU cannot run.
std::unique_ptr<Renderer> makeCpuRenderer(const CpuOptions& options = {});

// "auto", "avx512", "avx2", "sse4", "neon", "scalar".
std::string_view toString(CpuIsa isa);
// False for an unknown name.
bool parse(std::string_view name, CpuIsa& out);
// "auto|avx512|avx2|sse4|neon|scalar" for help texts and error messages.
std::string allCpuIsaNames();
// The targets compiled into this binary that this CPU runs, best first (never Auto; Scalar
// is always there).
std::vector<CpuIsa> supportedCpuIsas();
// True for Auto and for every target supportedCpuIsas() lists.
bool cpuIsaSupported(CpuIsa isa);
// The target a render with `isa` runs: `isa` itself, or for Auto the best supported one.
CpuIsa resolveCpuIsa(CpuIsa isa);
// Why `isa` cannot run here (empty when it can): "avx512: this CPU lacks it (it runs
// avx2, sse4, scalar)" or "neon: not compiled into this binary (x86-64)".
std::string cpuIsaUnsupportedReason(CpuIsa isa);

// The path's name for reports: "teaching" or "fast (avx2)" (the resolved target).
std::string cpuPathName(const CpuOptions& options);

}  // namespace twr
