// Whole-file reads with a size limit, for every file a user hands us (scene, OBJ, MTL, image):
// a huge or endless file (/dev/zero, a FIFO, a multi-gigabyte OBJ) is refused with a clear
// error before memory runs out.
#pragma once

#include <cstdint>
#include <string>

namespace twr {

// Reads the regular file `path` whole. Throws InputError "<path>: ..." naming `what` (e.g.
// "scene file") when it is missing, a directory, not a regular file, unreadable, or holds
// more than maxBytes bytes (inclusive bound; checked before reading and again while
// reading, since /proc files report size 0).
std::string readFileCapped(const std::string& path, std::uintmax_t maxBytes, const std::string& what);

// "300 bytes", "32 MiB", "33554433 bytes (32.0 MiB)": sizes in messages, exact where it matters.
std::string describeBytes(std::uintmax_t bytes);

}  // namespace twr
