#include "scene/read_file.h"

#include "scene/errors.h"

#include <cstdio>
#include <filesystem>
#include <fstream>

namespace twr {

namespace {

// Bytes read per call while reading (64 KiB).
constexpr std::size_t kChunkBytes = 64 * 1024;

}  // namespace

std::string describeBytes(std::uintmax_t bytes) {
  constexpr std::uintmax_t kMiB = 1024 * 1024;
  if (bytes < kMiB) return std::to_string(bytes) + " bytes";
  if (bytes % kMiB == 0) return std::to_string(bytes / kMiB) + " MiB";
  char mebibytes[32];
  std::snprintf(mebibytes, sizeof mebibytes, "%.1f", static_cast<double>(bytes) / static_cast<double>(kMiB));
  return std::to_string(bytes) + " bytes (" + mebibytes + " MiB)";
}

std::string readFileCapped(const std::string& path, std::uintmax_t maxBytes, const std::string& what) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::file_status status = fs::status(path, ec);
  // A symlink loop or a name too long is not "no such file": say what the system said.
  if (ec && ec != std::errc::no_such_file_or_directory) {
    throw InputError(path + ": cannot open " + what + " (" + ec.message() + ")");
  }
  if (!fs::exists(status)) throw InputError(path + ": cannot open " + what + " (no such file)");
  if (fs::is_directory(status)) throw InputError(path + ": cannot open " + what + " (it is a directory)");
  if (!fs::is_regular_file(status)) throw InputError(path + ": cannot open " + what + " (not a regular file)");
  const std::uintmax_t declared = fs::file_size(path, ec);
  const std::string limit = "larger than the limit of " + describeBytes(maxBytes) + " for a " + what;
  if (!ec && declared > maxBytes) throw InputError(path + ": " + what + " is " + describeBytes(declared) + ", " + limit);
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path + ": cannot open " + what + " (not readable)");
  std::string bytes;
  if (!ec) bytes.reserve(static_cast<std::size_t>(declared));
  char chunk[kChunkBytes];
  while (in.read(chunk, sizeof chunk) || in.gcount() > 0) {
    bytes.append(chunk, static_cast<std::size_t>(in.gcount()));
    if (bytes.size() > maxBytes) throw InputError(path + ": " + what + " is " + limit);
  }
  if (in.bad()) throw InputError(path + ": cannot read " + what);
  return bytes;
}

}  // namespace twr
