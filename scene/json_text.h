// JSON text for output files and stdout. Names come from users' files (scene files, OBJ and
// MTL material names) and need not be UTF-8; nlohmann's dump() would throw on them, leaving a
// half-written file. Invalid bytes are replaced by U+FFFD instead.
#pragma once

#include <nlohmann/json.hpp>

#include <string>

namespace twr {

inline std::string jsonText(const nlohmann::json& json, int indent = -1) {
  return json.dump(indent, ' ', false, nlohmann::json::error_handler_t::replace);
}

}  // namespace twr
