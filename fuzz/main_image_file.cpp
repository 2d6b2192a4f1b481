// libFuzzer entry of target "image_file" (see targets.h); built only with TWINRASTER_FUZZ=ON.
#include "fuzz/targets.h"

#include <cstddef>
#include <cstdint>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const twr::fuzz::Workspace workspace(twr::fuzz::processWorkspaceDir("image_file"));
  twr::fuzz::fuzzImageFile(workspace, data, size);
  return 0;
}
