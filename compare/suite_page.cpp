#include "compare/suite_page.h"

#include "compare/page_style.h"

#include <cstdio>
#include <sstream>

namespace twr {

namespace {

std::string seconds3(double s) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3f", s);
  return text;
}

// A number cell: its sort key in data-value, n/a where the metrics have none.
std::string numberCell(const nlohmann::json& metrics, const char* key) {
  if (!metrics.is_object() || !metrics.contains(key) || !metrics[key].is_number()) {
    return "<td data-value=\"\">n/a</td>";
  }
  const double v = metrics[key].get<double>();
  char sortKey[32], text[32];
  std::snprintf(sortKey, sizeof sortKey, "%.17g", v);
  std::snprintf(text, sizeof text, "%.4g", v);
  return "<td data-value=\"" + std::string(sortKey) + "\">" + text + "</td>";
}

constexpr const char* kSortScript = R"js(
(function () {
  'use strict';
  const table = document.getElementById('scenes');
  table.querySelectorAll('th.sort').forEach((th) => {
    const column = th.cellIndex;
    th.addEventListener('click', () => {
      const ascending = th.getAttribute('aria-sort') !== 'ascending';
      table.querySelectorAll('th.sort').forEach((h) => h.removeAttribute('aria-sort'));
      th.setAttribute('aria-sort', ascending ? 'ascending' : 'descending');
      const numeric = th.dataset.type === 'number';
      const key = (row) => row.cells[column].dataset.value ?? row.cells[column].textContent;
      const rows = Array.from(table.tBodies[0].rows);
      // A scene without the number (n/a: it did not run to a verdict) sorts last either way.
      rows.sort((a, b) => {
        const x = key(a), y = key(b);
        if (numeric && (x === '' || y === '')) return (x === '') - (y === '');
        const order = numeric ? Number(x) - Number(y) : x.localeCompare(y);
        return ascending ? order : -order;
      });
      rows.forEach((row) => table.tBodies[0].appendChild(row));
    });
  });
})();
)js";

}  // namespace

std::string escapeXml(const std::string& text) {
  std::string out;
  for (const char ch : text) {
    const unsigned char u = static_cast<unsigned char>(ch);
    switch (ch) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += "&apos;"; break;
      default:
        if (u < 0x20 && ch != '\t' && ch != '\n' && ch != '\r') {
          out += "\xEF\xBF\xBD";
        } else {
          out += ch;
        }
    }
  }
  return out;
}

std::string suiteIndexHtml(const std::vector<SuiteCase>& cases, double seconds) {
  int passed = 0, failed = 0, errors = 0;
  for (const SuiteCase& c : cases) {
    (c.outcome == SuiteOutcome::Passed ? passed : c.outcome == SuiteOutcome::Failed ? failed : errors) += 1;
  }
  std::ostringstream s;
  s << pageHead("twinraster suite: " + std::to_string(cases.size()) + " scenes");
  s << "<h1>CPU against GL: " << cases.size() << " scenes</h1>\n<p class=\"meta\">" << passed << " within targets, "
    << failed << " over them, " << errors << " bad input; " << seconds3(seconds)
    << " s. Click a column's head to sort by it; a scene's name opens its page.</p>\n";
  s << "<table id=\"scenes\"><thead><tr><th class=\"sort\" data-type=\"text\">scene</th><th>CPU frame</th><th>difference</th>"
       "<th class=\"sort l\" data-type=\"text\">verdict</th><th class=\"sort\" data-type=\"number\">largest difference</th>"
       "<th class=\"sort\" data-type=\"number\">over 1 level, %</th><th class=\"sort\" data-type=\"number\">coverage "
       "mismatch</th><th class=\"sort\" data-type=\"number\">CPU ms</th><th class=\"sort\" data-type=\"number\">GL ms"
       "</th></tr></thead><tbody>\n";
  for (const SuiteCase& c : cases) {
    const std::string verdictClass =
        c.outcome == SuiteOutcome::Passed ? "pass" : c.outcome == SuiteOutcome::Failed ? "fail" : "error";
    // The folder's name to read and sort by, the scene's path as given below it.
    s << "<tr data-scene=\"" << escapeHtml(c.scene) << "\"><td class=\"l\" data-value=\"" << escapeHtml(c.dir) << "\">";
    if (c.outcome == SuiteOutcome::Error) {
      s << "<strong>" << escapeHtml(c.dir) << "</strong>";
    } else {
      s << "<a href=\"" << escapeHtml(c.dir) << "/index.html\">" << escapeHtml(c.dir) << "</a>";
    }
    s << "<div class=\"small wrap\">" << escapeHtml(c.scene) << "</div></td><td>";
    if (c.outcome != SuiteOutcome::Error) {
      s << "<img class=\"thumb\" loading=\"lazy\" src=\"" << escapeHtml(c.dir) << "/cpu.png\" alt=\"\">";
    }
    s << "</td><td>";
    if (c.outcome != SuiteOutcome::Error) {
      s << "<img class=\"thumb\" loading=\"lazy\" src=\"" << escapeHtml(c.dir) << "/page_heat.png\" alt=\"\">";
    }
    s << "</td><td class=\"l\" data-value=\"" << toString(c.outcome) << "\"><span class=\"verdict " << verdictClass << "\">"
      << toString(c.outcome) << "</span>";
    if (!c.message.empty()) s << "<div class=\"small wrap\">" << escapeHtml(c.message) << "</div>";
    s << "</td>" << numberCell(c.metrics, "max_abs_diff") << numberCell(c.metrics, "over_1_pct")
      << numberCell(c.metrics, "coverage_mismatch") << numberCell(c.metrics, "cpu_ms")
      << numberCell(c.metrics, "gl_ms") << "</tr>\n";
  }
  s << "</tbody></table>\n<script>" << kSortScript << "</script>\n</body></html>\n";
  return s.str();
}

std::string junitXml(const std::vector<SuiteCase>& cases, double seconds) {
  int failures = 0, errors = 0;
  for (const SuiteCase& c : cases) {
    failures += c.outcome == SuiteOutcome::Failed;
    errors += c.outcome == SuiteOutcome::Error;
  }
  std::ostringstream s;
  const std::string counts = " tests=\"" + std::to_string(cases.size()) + "\" failures=\"" + std::to_string(failures) +
                             "\" errors=\"" + std::to_string(errors) + "\" time=\"" + seconds3(seconds) + "\"";
  s << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<testsuites name=\"twinraster suite\"" << counts << ">\n";
  s << "  <testsuite name=\"twinraster.compare\"" << counts << " skipped=\"0\">\n";
  for (const SuiteCase& c : cases) {
    s << "    <testcase classname=\"twinraster.compare\" name=\"" << escapeXml(c.scene) << "\" time=\""
      << seconds3(c.seconds) << "\"";
    if (c.outcome == SuiteOutcome::Passed) {
      s << "/>\n";
      continue;
    }
    const char* element = c.outcome == SuiteOutcome::Failed ? "failure" : "error";
    const char* type = c.outcome == SuiteOutcome::Failed ? "threshold" : "bad_input";
    s << ">\n      <" << element << " type=\"" << type << "\" message=\"" << escapeXml(c.message) << "\">"
      << escapeXml(c.stderrText) << "</" << element << ">\n    </testcase>\n";
  }
  s << "  </testsuite>\n</testsuites>\n";
  return s.str();
}

nlohmann::json suiteJson(const std::vector<SuiteCase>& cases, double seconds) {
  static const char* const kHeadline[] = {"max_abs_diff", "over_1_pct", "coverage_mismatch", "cpu_ms", "gl_ms"};
  nlohmann::json rows = nlohmann::json::array();
  int passed = 0, failed = 0, errors = 0;
  for (const SuiteCase& c : cases) {
    (c.outcome == SuiteOutcome::Passed ? passed : c.outcome == SuiteOutcome::Failed ? failed : errors) += 1;
    nlohmann::json row = {{"scene", c.scene},   {"dir", c.dir},         {"outcome", toString(c.outcome)},
                          {"exit_code", c.exitCode}, {"message", c.message}, {"seconds", c.seconds}};
    for (const char* key : kHeadline) {
      row[key] = c.metrics.is_object() && c.metrics.contains(key) ? c.metrics[key] : nlohmann::json(nullptr);
    }
    rows.push_back(row);
  }
  return {{"scenes", cases.size()}, {"passed", passed},  {"failed", failed},         {"errors", errors},
          {"seconds", seconds},     {"cases", rows},     {"exit_code", suiteExitCode(cases)}};
}

}  // namespace twr
