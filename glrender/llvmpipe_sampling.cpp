#include "glrender/llvmpipe_sampling.h"

#include "scene/errors.h"

#include <array>
#include <cstdlib>
#include <mutex>
#include <sstream>

namespace twr {
namespace {

// llvmpipe's precise texture path: per-pixel LOD and float bilinear weights (issue 5).
constexpr const char* kPerfVariable = "GALLIVM_PERF";
constexpr std::array<const char*, 2> kPreciseSamplingFlags = {"no_aos_sampling", "no_quad_lod"};

bool hasFlag(const std::string& list, const std::string& flag) {
  std::stringstream stream(list);
  std::string item;
  while (std::getline(stream, item, ',')) {
    if (item == flag) return true;
  }
  return false;
}

// llvmpipe reads GALLIVM_PERF once per process, when the first context is created, so
// this mirrors that: the first call fixes the mode and later calls must agree with it.
// OSMesa and EGL each load their own llvmpipe, but both read the same, unchanged variable.
// The lock guards the process-wide environment, which is shared state by nature.
struct SamplingState {
  std::mutex mutex;
  std::string mode;  // "" until the first context
};

SamplingState& samplingState() {
  static SamplingState state;
  return state;
}

}  // namespace

void prepareLlvmpipeSampling(bool fastSampling) {
  SamplingState& state = samplingState();
  const std::lock_guard lock(state.mutex);
  const std::string requested = fastSampling ? "fast" : "precise";
  if (state.mode.empty()) {
    const char* existing = std::getenv(kPerfVariable);
    std::string flags = existing ? existing : "";
    if (!fastSampling) {
      for (const char* flag : kPreciseSamplingFlags) {
        if (hasFlag(flags, flag)) continue;
        if (!flags.empty()) flags += ",";
        flags += flag;
      }
      setenv(kPerfVariable, flags.c_str(), 1);
    }
    bool precise = true;
    for (const char* flag : kPreciseSamplingFlags) precise = precise && hasFlag(flags, flag);
    state.mode = precise ? "precise" : "fast";
    if (state.mode != requested) {
      throw InputError("GL: " + requested + " texture sampling was asked for, but the environment sets " +
                       kPerfVariable + "=" + flags + " (llvmpipe " + state.mode +
                       " mode); unset it or drop the request");
    }
    return;
  }
  if (state.mode != requested) {
    throw InputError("GL: llvmpipe already samples textures in " + state.mode +
                     " mode in this process (it reads " + kPerfVariable +
                     " once, at the first context); " + requested + " sampling needs a new process");
  }
}

std::string llvmpipeSamplingMode() {
  SamplingState& state = samplingState();
  const std::lock_guard lock(state.mutex);
  return state.mode;
}

}  // namespace twr
