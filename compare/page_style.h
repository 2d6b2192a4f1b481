// What every HTML page the tool writes shares (the report, a comparison's page, a suite's
// index): one stylesheet, so they look like one product, and the escaping of text into HTML.
// The pages are self-contained: the style goes inline, nothing is fetched from a network.
#pragma once

#include <string>
#include <string_view>

namespace twr {

// The stylesheet, for a <style> element.
std::string_view pageStyleSheet();

// `text` with &, <, > and " escaped, for element text and quoted attribute values.
std::string escapeHtml(std::string_view text);

// The page's head up to and including <body>: charset, title (escaped) and the stylesheet.
std::string pageHead(std::string_view title);

}  // namespace twr
