// Strings built by appending parts, for the messages the UI shows. Not operator+ chains on
// purpose: GCC 12 reports a false -Wrestrict (an error with TWINRASTER_WERROR) once
// `"literal" + std::string&&` is inlined in Release builds.
#pragma once

#include <string>
#include <string_view>
#include <type_traits>

namespace twr::gui {

inline void appendPart(std::string& out, std::string_view part) { out.append(part); }
inline void appendPart(std::string& out, const char* part) { out.append(part); }
inline void appendPart(std::string& out, char part) { out.push_back(part); }
template <typename Number, std::enable_if_t<std::is_arithmetic_v<Number> && !std::is_same_v<Number, bool> &&
                                                !std::is_same_v<Number, char>,
                                            int> = 0>
void appendPart(std::string& out, Number part) {
  out += std::to_string(part);
}

// concat("edit ", 12, " of ", name) == "edit 12 of " + name; numbers as std::to_string.
template <typename... Parts>
std::string concat(const Parts&... parts) {
  std::string out;
  (appendPart(out, parts), ...);
  return out;
}

}  // namespace twr::gui
