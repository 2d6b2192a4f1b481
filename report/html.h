// Writers for `twinraster report`: DIR/report.html (self-contained: inline CSS and SVG charts,
// no scripts, no network) and DIR/results.csv (one row per knob, setting and backend, plus
// one row per orthonormal-basis construction).
#pragma once

#include "report/model.h"

#include <string>

namespace twr::report {

// Both throw InputError when the file cannot be written.
void writeReportHtml(const std::string& path, const ReportData& data);
void writeResultsCsv(const std::string& path, const ReportData& data);

}  // namespace twr::report
