// Between the CpuIsa names of cpu_renderer.h and Highway's target bits (softrender only).
#pragma once

#include "softrender/cpu_renderer.h"

#include <cstdint>

namespace twr {

// Highway's target bit for `isa` (HWY_AVX3, HWY_AVX2, ...); 0 for Auto.
std::int64_t highwayTargetOf(CpuIsa isa);
// True when Highway compiled the kernels for `isa` into this binary.
bool cpuIsaCompiled(CpuIsa isa);

}  // namespace twr
