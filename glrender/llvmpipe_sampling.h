// llvmpipe's texture-sampling mode, shared by every headless context (OSMesa and EGL): both
// load an llvmpipe that reads GALLIVM_PERF once, when it initialises (issue 5).
#pragma once

#include <string>

namespace twr {

// Sets GALLIVM_PERF for the requested mode before the first headless context of the process
// (precise: adds no_aos_sampling,no_quad_lod to whatever it holds; fast: leaves it alone), and
// checks later requests against that first one. Throws InputError when the environment or an
// earlier context already fixed the other mode. Harmless for a driver that is not llvmpipe.
void prepareLlvmpipeSampling(bool fastSampling);

// "precise", "fast", or "" before the first headless context of this process.
std::string llvmpipeSamplingMode();

}  // namespace twr
