// Errors for bad user input: every message names the file, and the key or line, and what
// was expected. The CLI turns InputError into exit code 2 with the message on stderr.
#pragma once

#include <stdexcept>
#include <string>

namespace twr {

class InputError : public std::runtime_error {
 public:
  explicit InputError(const std::string& message) : std::runtime_error(message) {}
};

// Exit codes shared by every executable.
inline constexpr int kExitOk = 0;
inline constexpr int kExitThreshold = 1;   // a comparison exceeded a requested threshold
inline constexpr int kExitBadInput = 2;    // bad input, missing library, context failure

}  // namespace twr
