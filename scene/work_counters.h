// Counts of the work the loaders have done in this process. Tests guard complexity with them
// (a file refused "before decoding" decodes nothing; a scene's JSON is built one value at a
// time, each value once) rather than with the clock, which a loaded machine or a sanitizer
// slows by any factor; timings belong in benchmarks.
#pragma once

#include <atomic>
#include <cstdint>

namespace twr {

struct WorkCounters {
  std::atomic<std::uint64_t> imagesDecoded{0};    // images handed to stb's pixel decoder (PNG, JPEG, TGA, BMP, HDR)
  std::atomic<std::uint64_t> jsonValuesBuilt{0};  // values the scene file's JSON builder stored
  std::atomic<std::uint64_t> meshesBuilt{0};      // meshes built from a scene file's mesh description
};

// The process's counters (relaxed atomics: loaders on several threads add to them).
WorkCounters& workCounters();

}  // namespace twr
