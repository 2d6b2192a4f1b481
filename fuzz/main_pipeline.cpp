// libFuzzer entry of target "pipeline" (see targets.h); built only with TWINRASTER_FUZZ=ON.
#include "fuzz/targets.h"

#include <cstddef>
#include <cstdint>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  twr::fuzz::fuzzPipeline(data, size);
  return 0;
}
