// The report's writers (report/html.cpp) on made-up data: report.html carries every knob, its
// chart and its table, the sections and the skipped knob's reason, escaped, with no script;
// results.csv has one row per point with as many cells as its header. Fast enough for the
// sanitizer run, which leaves out the full `twinraster report` (Makefile, SANITIZE_SLOW).
#include "report/html.h"
#include "report/reading.h"
#include "scene/errors.h"
#include "scene/read_file.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

namespace twr::report {
namespace {

// A page or table the test wrote, read whole (a missing one is an InputError naming it).
std::string readFile(const std::filesystem::path& path) {
  constexpr std::uintmax_t kMaxBytes = 1u << 20;  // bytes; the made-up report is a few KiB
  return readFileCapped(path.string(), kMaxBytes, "report page");
}

// Cells of one CSV line, double-quoted cells holding commas and "" for a quote.
std::vector<std::string> csvCells(const std::string& line) {
  std::vector<std::string> cells(1);
  bool quoted = false;
  for (std::size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (quoted && c == '"' && i + 1 < line.size() && line[i + 1] == '"') {
      cells.back() += '"';
      ++i;
    } else if (c == '"') {
      quoted = !quoted;
    } else if (c == ',' && !quoted) {
      cells.emplace_back();
    } else {
      cells.back() += c;
    }
  }
  return cells;
}

ReportPoint point(const std::string& setting, const std::string& backend, double ms, double rmse) {
  ReportPoint p;
  p.setting = setting;
  p.backend = backend;
  p.msMedian = ms;
  p.msMin = 0.9 * ms;
  p.frames = 3;
  p.vsReference.rmse = rmse;
  p.vsReference.maxAbsDiff = 7;
  return p;
}

ReportData madeUpData() {
  ReportData d;
  d.generatedAt = "2026-12-05 12:00";
  d.machine = "a test machine";
  d.quick = true;
  d.width = 64;
  d.height = 48;
  KnobResult filter;
  filter.id = "texture_filter";
  filter.title = "Texture filter <&> \"quoted\"";
  filter.question = "what filtering costs";
  filter.reference = "the double pipeline";
  filter.scene = "default.json at 64x48";
  filter.summary = "bilinear, sentence one";
  filter.reading = "the numbers";
  filter.points.push_back(point("nearest", "cpu", 2.0, 9.0));
  ReportPoint gl = point("nearest, \"fast\"", "gl", 3.0, 8.5);
  CompareMetrics cpuVsGl;
  cpuVsGl.rmse = 0.25;
  gl.cpuVsGl = cpuVsGl;
  filter.points.push_back(gl);
  ReportPoint shortcut = point("bilinear", "cpu", 2.5, 4.0);
  shortcut.vsExactSetting = cpuVsGl;
  shortcut.exactSetting = "nearest";
  filter.points.push_back(shortcut);
  d.knobs.push_back(filter);
  KnobResult skipped;
  skipped.id = "threads";
  skipped.title = "Threads";
  skipped.skipped = "one core only";
  // The report command writes a knob's reading before its page; a skipped knob's says why.
  const KnobReading skippedReading = readKnob(skipped);
  skipped.summary = skippedReading.summary;
  skipped.reading = skippedReading.detail;
  d.knobs.push_back(skipped);
  BasisRow basis;
  basis.method = BasisMethod::Frisvad2012;
  basis.nsPerBasis = 3.5;
  d.bases.push_back(basis);
  d.basisDirections = 1000;
  d.basisSummary = "duff_2017 is exact";
  SsrMarchRow march;
  march.march = "hiz";
  march.maxSteps = 64;
  march.thickness = 0.1;
  march.msMedian = 5.0;
  march.meanAbs = 1.5;
  d.ssr.steps.push_back(march);
  d.ssr.summary = "hiz wins";
  return d;
}

std::filesystem::path outDir() {
  const std::filesystem::path dir = std::filesystem::path(TWINRASTER_TEST_OUT) / "report_pages";
  std::filesystem::create_directories(dir);
  return dir;
}

TEST(ReportPages, HtmlCarriesEveryKnobEscapedWithItsChartAndNoScript) {
  const std::filesystem::path path = outDir() / "report.html";
  writeReportHtml(path.string(), madeUpData());
  const std::string html = readFile(path);
  EXPECT_NE(html.find("<h2 id=\"texture_filter\">Texture filter &lt;&amp;&gt; &quot;quoted&quot;</h2>"),
            std::string::npos)
      << html.substr(0, 2000);
  EXPECT_NE(html.find("<svg"), std::string::npos) << "the knob's chart";
  EXPECT_NE(html.find("one core only"), std::string::npos) << "the skipped knob says why";
  EXPECT_NE(html.find("a test machine"), std::string::npos);
  EXPECT_NE(html.find("--quick"), std::string::npos);
  EXPECT_NE(html.find("id=\"orthonormal_basis\""), std::string::npos);
  EXPECT_NE(html.find("id=\"ssr\""), std::string::npos);
  EXPECT_EQ(html.find("<script"), std::string::npos) << "self-contained, no scripts";
  EXPECT_EQ(html.find("Texture filter <&>"), std::string::npos) << "titles are escaped";
  EXPECT_NE(html.rfind("</html>"), std::string::npos);
}

TEST(ReportPages, CsvHasARowPerPointWithTheHeadersCells) {
  const std::filesystem::path path = outDir() / "results.csv";
  writeResultsCsv(path.string(), madeUpData());
  std::istringstream lines(readFile(path));
  std::string header;
  ASSERT_TRUE(std::getline(lines, header));
  const std::vector<std::string> columns = csvCells(header);
  ASSERT_GE(columns.size(), 10u);
  EXPECT_EQ(columns[0], "knob");
  EXPECT_EQ(columns[3], "ms_median");
  std::vector<std::vector<std::string>> rows;
  for (std::string line; std::getline(lines, line);) {
    rows.push_back(csvCells(line));
    EXPECT_EQ(rows.back().size(), columns.size()) << line;
  }
  const auto rowsOf = [&](const std::string& knob) {
    int n = 0;
    for (const auto& row : rows) n += row[0] == knob;
    return n;
  };
  EXPECT_EQ(rowsOf("texture_filter"), 3) << "one per point";
  EXPECT_EQ(rowsOf("threads"), 0) << "a skipped knob has no points";
  EXPECT_EQ(rowsOf("ssr_march"), 1);
  for (const auto& row : rows) {
    if (row[0] == "texture_filter" && row[2] == "gl") {
      EXPECT_EQ(row[1], "nearest, \"fast\"") << "quoted, not split";
    }
  }
}

TEST(ReportPages, AnUnwritablePathIsAnInputError) {
  const std::string path = (outDir() / "no_such_folder" / "report.html").string();
  EXPECT_THROW(writeReportHtml(path, madeUpData()), InputError);
  EXPECT_THROW(writeResultsCsv(path, madeUpData()), InputError);
}

}  // namespace
}  // namespace twr::report
