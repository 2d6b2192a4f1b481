// The CPU software pipeline behind the Renderer interface.
#pragma once

#include "scene/renderer.h"

#include <memory>
#include <string>

namespace twr {

// Two traversals of the same stages, giving the same image, depth, triangle ids and
// statistics bit for bit (tests/softrender/test_fast_path.cpp checks the whole suite):
//   Teaching  one stage after the other as docs/pipeline.md draws them (cpu_renderer.cpp):
//             every thread takes a band of rows and walks every triangle;
//   Fast      the stages reorganised for speed (softrender/fast_pipeline.h): vertex
//             results reused per triangle, triangles binned once, an AVX-512 kernel shading
//             4 x 4 pixel blocks (docs/performance.md).
enum class CpuPath { Teaching, Fast };

struct CpuOptions {
  // Worker threads (values below 1 mean 1). The image and the statistics are the same for
  // any count.
  int threads = 1;
  CpuPath path = CpuPath::Fast;
  // Fast path: shade with the AVX-512 kernel when the CPU has it; false runs the scalar
  // kernel everywhere (to test and measure it on any machine).
  bool simd = true;
};

std::unique_ptr<Renderer> makeCpuRenderer(const CpuOptions& options = {});

// The path's name for reports: "teaching", "fast (avx512)" or "fast (scalar)".
std::string cpuPathName(const CpuOptions& options);

}  // namespace twr
