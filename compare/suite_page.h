// What `twinraster suite` writes beside the scenes' own pages: DIR/index.html (every scene with
// a thumbnail, verdict, largest difference, over-1 share, coverage mismatch and both times,
// sortable by each column) and a JUnit XML file (one testcase per scene: failure = over the
// targets, error = bad input), the format CI dashboards read.
#pragma once

#include "compare/suite.h"

#include <string>
#include <vector>

namespace twr {

std::string suiteIndexHtml(const std::vector<SuiteCase>& cases, double seconds);
std::string junitXml(const std::vector<SuiteCase>& cases, double seconds);
// DIR/suite.json: the counts, the exit code and per case its scene, folder, outcome, exit code,
// message, seconds and metrics.json's headline keys (the rest stay in DIR/<dir>/metrics.json).
nlohmann::json suiteJson(const std::vector<SuiteCase>& cases, double seconds);

// `text` escaped for XML character data and attribute values; characters XML 1.0 forbids
// (control characters other than tab, newline, carriage return) become U+FFFD.
std::string escapeXml(const std::string& text);

}  // namespace twr
