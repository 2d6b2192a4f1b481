// What every HTML page the tool writes shares (the report, a comparison's page, a suite's
// index): one stylesheet, so they look like one product, and the escaping of text into HTML.
// The pages are self-contained: the style goes inline, nothing is fetched from a network.
#pragma once

#include "scene/html_text.h"  // escapeHtml

#include <string>
#include <string_view>

namespace twr {

// The stylesheet, for a <style> element.
std::string_view pageStyleSheet();

// The page's head up to and including <body>: charset, title (escaped) and the stylesheet.
std::string pageHead(std::string_view title);

}  // namespace twr
