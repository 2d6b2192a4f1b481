// libFuzzer entry of target "obj_file" (see targets.h); built only with TWINRASTER_FUZZ=ON.
#include "fuzz/targets.h"

#include <cstddef>
#include <cstdint>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const twr::fuzz::Workspace workspace(twr::fuzz::processWorkspaceDir("obj_file"));
  twr::fuzz::fuzzObjFile(workspace, data, size);
  return 0;
}
