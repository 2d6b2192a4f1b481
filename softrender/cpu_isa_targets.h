// Between the CpuIsa names of cpu_renderer.h and Highway's target bits (softrender only).
#pragma once

#include "softrender/cpu_renderer.h"

#include <cstdint>

namespace twr {

// Highway's target bit for `isa` (HWY_AVX3, HWY_AVX2, ...); 0 for Auto.
std::int64_t highwayTargetOf(CpuIsa isa);
// Highway's bits of the targets this binary has kernels for: every target Highway compiles,
// or those CMake's TWINRASTER_KERNEL_TARGETS names.
std::int64_t fastKernelTargets();
// True when this binary has the kernels for `isa`.
bool cpuIsaCompiled(CpuIsa isa);

}  // namespace twr
