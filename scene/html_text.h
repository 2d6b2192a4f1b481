// Text into HTML, for every page and picture index the tool writes: names come from users'
// files and may hold <, & or quotes.
#pragma once

#include <string>
#include <string_view>

namespace twr {

// `text` with &, <, > and " escaped, for element text and quoted attribute values.
inline std::string escapeHtml(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (const char c : text) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      default: out += c;
    }
  }
  return out;
}

}  // namespace twr
