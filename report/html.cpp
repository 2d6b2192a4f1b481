#include "report/html.h"

#include "compare/page_style.h"

#include "scene/errors.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iomanip>
#include <sstream>
#include <string>
#include <vector>

namespace twr::report {

namespace {

// Chart geometry, SVG user units (pixels at 100 % zoom).
constexpr double kChartWidth = 760.0, kChartHeight = 380.0;
constexpr double kMarginLeft = 70.0, kMarginRight = 150.0, kMarginTop = 24.0, kMarginBottom = 52.0;
constexpr double kPointRadius = 5.0;
// A time axis spanning more than this ratio (max / min) is drawn logarithmic.
constexpr double kLogAxisRatio = 8.0;
constexpr int kTargetTicks = 6;

std::string escape(const std::string& text) { return escapeHtml(text); }

std::string num(double value, int decimals) {
  if (!std::isfinite(value)) return value > 0 ? "inf" : (value < 0 ? "-inf" : "nan");
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.*f", decimals, value);
  return buffer;
}
std::string sci(double value) {
  if (!std::isfinite(value)) return value > 0 ? "inf" : "nan";
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.2e", value);
  return buffer;
}
// Milliseconds with sensible precision for a cell.
std::string msText(double ms) { return num(ms, ms < 1.0 ? 3 : (ms < 10.0 ? 2 : 1)); }
// A tick value without trailing zeros ("0", "0.5", "2", "250").
std::string tickText(double v) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%g", v);
  return buffer;
}

// Label boxes already placed in a chart, so a new label can avoid them.
struct LabelBox {
  double x0, y0, x1, y1;
  bool overlaps(const LabelBox& o) const { return x0 < o.x1 && o.x0 < x1 && y0 < o.y1 && o.y0 < y1; }
};
constexpr double kLabelCharWidth = 6.2;  // SVG units per character at font-size 11 (approximate)
constexpr double kLabelHeight = 12.0;

struct Axis {
  double lo = 0.0, hi = 1.0;  // data range shown
  bool log = false;
  std::vector<double> ticks;

  double fraction(double v) const {
    if (log) return (std::log10(v) - std::log10(lo)) / (std::log10(hi) - std::log10(lo));
    return (v - lo) / (hi - lo);
  }
};

// "Nice" linear ticks (1, 2, 5 x 10^k) covering [lo, hi].
Axis linearAxis(double lo, double hi) {
  Axis a;
  if (!(hi > lo)) hi = lo + 1.0;
  const double rawStep = (hi - lo) / kTargetTicks;
  const double magnitude = std::pow(10.0, std::floor(std::log10(rawStep)));
  double step = magnitude;
  for (double m : {1.0, 2.0, 5.0, 10.0}) {
    step = m * magnitude;
    if (step >= rawStep) break;
  }
  a.lo = std::floor(lo / step) * step;
  a.hi = std::ceil(hi / step) * step;
  for (double t = a.lo; t <= a.hi + 0.5 * step; t += step) a.ticks.push_back(std::fabs(t) < 1e-12 ? 0.0 : t);
  return a;
}

// Log ticks at 1, 2, 5 x 10^k covering [lo, hi] (lo > 0).
Axis logAxis(double lo, double hi) {
  Axis a;
  a.log = true;
  a.lo = std::pow(10.0, std::floor(std::log10(lo)));
  a.hi = std::pow(10.0, std::ceil(std::log10(hi)));
  for (double decade = a.lo; decade < a.hi * 1.01; decade *= 10.0) {
    for (double m : {1.0, 2.0, 5.0}) {
      const double t = m * decade;
      if (t >= a.lo * 0.999 && t <= a.hi * 1.001) a.ticks.push_back(t);
    }
  }
  return a;
}

const char* colourOf(const std::string& backend) { return backend == "gl" ? "#c0392b" : "#1f5fa8"; }

// The short name a height-field view's chart writes beside a point ("POM 8-32").
std::string shortHeightLabel(const ReportPoint& p) {
  if (!p.heightField) return p.setting;
  const HeightFieldPointInfo& h = *p.heightField;
  std::string name = h.method;
  if (h.method == kTrueGeometry) name = "mesh";
  else if (h.method == "normal_map") name = "normal";
  else if (h.method == "bump_blinn") name = "blinn";
  else if (h.method == "bump_emboss") name = "emboss";
  else if (h.method == "parallax_offset_limited") name = "offset-limited";
  else if (h.method == "steep_parallax") name = "steep";
  else if (h.method == "parallax_occlusion") name = "POM";
  if (h.layersMin > 0) name += " " + std::to_string(h.layersMin) + "-" + std::to_string(h.layersMax);
  return name;
}

// heightView: a height-field view, whose points are methods rather than steps of one knob:
// no lines between them, short labels on the CPU points only (GL's sit beside them; every
// point names itself in its tooltip), and a label with no free spot is left out.
std::string chartSvg(const KnobResult& knob, bool heightView = false) {
  std::vector<const ReportPoint*> points;
  for (const ReportPoint& p : knob.points) points.push_back(&p);
  if (points.empty()) return "";
  double tMin = points[0]->msMin, tMax = tMin, eMax = 0.0;
  for (const ReportPoint* p : points) {
    tMin = std::min(tMin, p->msMin);
    tMax = std::max(tMax, p->msMin);
    if (std::isfinite(p->vsReference.rmse)) eMax = std::max(eMax, p->vsReference.rmse);
  }
  tMin = std::max(tMin, 1e-3);
  const Axis x = (tMax / tMin > kLogAxisRatio) ? logAxis(tMin, tMax) : linearAxis(0.0, tMax * 1.05);
  const Axis y = linearAxis(0.0, std::max(eMax * 1.1, 0.5));
  const double plotW = kChartWidth - kMarginLeft - kMarginRight;
  const double plotH = kChartHeight - kMarginTop - kMarginBottom;
  auto px = [&](double v) { return kMarginLeft + plotW * x.fraction(std::max(v, x.log ? x.lo : v)); };
  auto py = [&](double v) { return kMarginTop + plotH * (1.0 - y.fraction(v)); };

  std::ostringstream s;
  s << "<svg class=\"chart\" viewBox=\"0 0 " << kChartWidth << " " << kChartHeight << "\" width=\"" << kChartWidth
    << "\" height=\"" << kChartHeight << "\" role=\"img\" aria-label=\"" << escape(knob.title)
    << ": time per frame against error\">\n";
  s << "<rect x=\"" << kMarginLeft << "\" y=\"" << kMarginTop << "\" width=\"" << plotW << "\" height=\"" << plotH
    << "\" fill=\"#fbfbfd\" stroke=\"#999\"/>\n";
  for (double t : x.ticks) {
    const double X = px(t);
    s << "<line x1=\"" << X << "\" y1=\"" << kMarginTop << "\" x2=\"" << X << "\" y2=\"" << kMarginTop + plotH
      << "\" stroke=\"#e3e3ea\"/>";
    s << "<text x=\"" << X << "\" y=\"" << kMarginTop + plotH + 16 << "\" class=\"tick\" text-anchor=\"middle\">"
      << tickText(t) << "</text>\n";
  }
  for (double t : y.ticks) {
    const double Y = py(t);
    s << "<line x1=\"" << kMarginLeft << "\" y1=\"" << Y << "\" x2=\"" << kMarginLeft + plotW << "\" y2=\"" << Y
      << "\" stroke=\"#e3e3ea\"/>";
    s << "<text x=\"" << kMarginLeft - 6 << "\" y=\"" << Y + 4 << "\" class=\"tick\" text-anchor=\"end\">"
      << tickText(t) << "</text>\n";
  }
  s << "<text x=\"" << kMarginLeft + plotW / 2 << "\" y=\"" << kChartHeight - 10
    << "\" class=\"axis\" text-anchor=\"middle\">time per frame, ms (fastest frame" << (x.log ? ", log scale" : "")
    << ")</text>\n";
  s << "<text transform=\"translate(16," << kMarginTop + plotH / 2
    << ") rotate(-90)\" class=\"axis\" text-anchor=\"middle\">RMSE vs reference, levels</text>\n";

  // One polyline per backend in sweep order, then the points with their labels.
  for (const std::string backend : {"cpu", "gl"}) {
    if (heightView) break;
    std::string path;
    for (const ReportPoint* p : points) {
      if (p->backend != backend) continue;
      path += (path.empty() ? "M" : " L") + num(px(p->msMin), 1) + " " + num(py(p->vsReference.rmse), 1);
    }
    if (!path.empty()) {
      s << "<path d=\"" << path << "\" fill=\"none\" stroke=\"" << colourOf(backend)
        << "\" stroke-width=\"1.5\" stroke-opacity=\"0.6\"/>\n";
    }
  }
  // Point markers first, so every label can avoid every point.
  std::vector<LabelBox> placed;
  for (const ReportPoint* p : points) {
    const double X = px(p->msMin), Y = py(p->vsReference.rmse);
    placed.push_back({X - kPointRadius, Y - kPointRadius, X + kPointRadius, Y + kPointRadius});
  }
  for (const ReportPoint* p : points) {
    const double X = px(p->msMin), Y = py(p->vsReference.rmse);
    const bool gl = p->backend == "gl";
    if (gl) {
      s << "<rect x=\"" << X - kPointRadius << "\" y=\"" << Y - kPointRadius << "\" width=\"" << 2 * kPointRadius
        << "\" height=\"" << 2 * kPointRadius << "\" fill=\"" << colourOf(p->backend) << "\">";
    } else {
      s << "<circle cx=\"" << X << "\" cy=\"" << Y << "\" r=\"" << kPointRadius << "\" fill=\""
        << colourOf(p->backend) << "\">";
    }
    s << "<title>" << escape(p->backend + " " + p->setting) << ": " << msText(p->msMin) << " ms, RMSE "
      << num(p->vsReference.rmse, 2) << "</title>" << (gl ? "</rect>" : "</circle>") << "\n";
    if (heightView && gl) continue;
    const std::string label = heightView ? shortHeightLabel(*p) : p->setting;
    // The first free spot for the label (baseline positions): right of the point above it,
    // below it, then further out, then the same on the left; CPU tries above first, GL below.
    const double w = kLabelCharWidth * static_cast<double>(label.size());
    const double above = Y - 8, below = Y + 16, farAbove = Y - 8 - kLabelHeight, farBelow = Y + 16 + kLabelHeight;
    const double first = gl ? below : above, second = gl ? above : below;
    const double third = gl ? farBelow : farAbove, fourth = gl ? farAbove : farBelow;
    const std::pair<double, double> spots[] = {{X + 8, first},     {X + 8, second},     {X + 8, third},
                                               {X + 8, fourth},    {X - 8 - w, first},  {X - 8 - w, second},
                                               {X - 8 - w, third}, {X - 8 - w, fourth}};
    auto boxAt = [&](double left, double baseline) {
      return LabelBox{left, baseline - kLabelHeight + 2, left + w, baseline + 2};
    };
    LabelBox chosen = boxAt(spots[0].first, spots[0].second);
    bool free = false;
    for (const auto& [left, baseline] : spots) {
      const LabelBox box = boxAt(left, baseline);
      if (std::none_of(placed.begin(), placed.end(), [&](const LabelBox& b) { return b.overlaps(box); })) {
        chosen = box;
        free = true;
        break;
      }
    }
    if (heightView && !free) continue;
    placed.push_back(chosen);
    s << "<text x=\"" << num(chosen.x0, 1) << "\" y=\"" << num(chosen.y1 - 2, 1) << "\" class=\"label\" fill=\""
      << colourOf(p->backend) << "\">" << escape(label) << "</text>\n";
  }
  // Legend.
  const double lx = kChartWidth - kMarginRight + 16, ly = kMarginTop + 10;
  s << "<circle cx=\"" << lx << "\" cy=\"" << ly << "\" r=\"" << kPointRadius << "\" fill=\"" << colourOf("cpu")
    << "\"/><text x=\"" << lx + 12 << "\" y=\"" << ly + 4 << "\" class=\"legend\">CPU pipeline</text>\n";
  s << "<rect x=\"" << lx - kPointRadius << "\" y=\"" << ly + 20 - kPointRadius << "\" width=\"" << 2 * kPointRadius
    << "\" height=\"" << 2 * kPointRadius << "\" fill=\"" << colourOf("gl") << "\"/><text x=\"" << lx + 12
    << "\" y=\"" << ly + 24 << "\" class=\"legend\">GL (llvmpipe)</text>\n";
  s << "</svg>\n";
  return s.str();
}

// A point's first cells in every points table: setting, backend, ms median, ms min, frames.
std::string timingCells(const ReportPoint& p) {
  std::ostringstream s;
  s << "<td>" << escape(p.setting) << "</td><td class=\"" << (p.backend == "gl" ? "gl" : "cpu") << "\">"
    << escape(p.backend) << "</td><td>" << msText(p.msMedian) << "</td><td>" << msText(p.msMin) << "</td><td>"
    << p.frames << "</td>";
  return s.str();
}

std::string pointsTable(const KnobResult& knob) {
  std::ostringstream s;
  s << "<table>\n<thead><tr><th>setting</th><th>backend</th><th>ms median</th><th>ms min</th><th>frames</th>"
       "<th>RMSE</th><th>PSNR dB</th><th>max diff</th><th>&gt;1 level %</th><th>coverage mismatch</th>"
       "<th>vs exact setting RMSE</th><th>vs exact setting max</th>"
       "<th>CPU vs GL RMSE</th><th>CPU vs GL max</th><th>CPU vs GL coverage</th></tr></thead>\n<tbody>\n";
  for (const ReportPoint& p : knob.points) {
    const CompareMetrics& m = p.vsReference;
    s << "<tr>" << timingCells(p) << "<td>" << num(m.rmse, 2) << "</td><td>" << num(m.psnr, 1) << "</td><td>" << m.maxAbsDiff
      << "</td><td>" << num(m.over1Pct(), 2) << "</td><td>" << m.coverageMismatch << "</td>";
    if (p.vsExactSetting) {
      s << "<td title=\"against " << escape(p.backend + " " + p.exactSetting) << "\">" << num(p.vsExactSetting->rmse, 2)
        << "</td><td>" << p.vsExactSetting->maxAbsDiff << "</td>";
    } else {
      s << "<td></td><td></td>";
    }
    if (p.cpuVsGl) {
      s << "<td>" << num(p.cpuVsGl->rmse, 2) << "</td><td>" << p.cpuVsGl->maxAbsDiff << "</td><td>"
        << p.cpuVsGl->coverageMismatch << "</td>";
    } else {
      s << "<td></td><td></td><td></td>";
    }
    s << "</tr>\n";
  }
  s << "</tbody></table>\n";
  return s.str();
}

std::string basisTable(const ReportData& data) {
  std::ostringstream s;
  s << "<table>\n<thead><tr><th>construction</th><th>max error, all directions</th>"
       "<th>max error within 1e-3 rad of -Z</th><th>max error for n.z &gt; 0</th>"
       "<th>non-finite bases</th><th>worst normal</th><th>ns per basis</th></tr></thead>\n<tbody>\n";
  for (const BasisRow& r : data.bases) {
    const BasisErrorStats& st = r.stats;
    const bool bad = !(st.maxError < 1e-3);
    s << "<tr><td>" << toString(r.method) << "</td><td" << (bad ? " class=\"bad\"" : "") << ">" << sci(st.maxError)
      << "</td><td" << (st.maxErrorNearMinusZ < 1e-3 ? "" : " class=\"bad\"") << ">" << sci(st.maxErrorNearMinusZ)
      << "</td><td>" << sci(st.maxErrorAwayFromMinusZ) << "</td><td>" << st.nonFinite << "</td><td>("
      << num(st.worstNormal.x, 6) << ", " << num(st.worstNormal.y, 6) << ", " << num(st.worstNormal.z, 9)
      << ")</td><td>" << num(r.nsPerBasis, 2) << "</td></tr>\n";
  }
  s << "</tbody></table>\n";
  return s.str();
}

// Paragraphs of a reading written with "\n" between them.
std::string paragraphs(const std::string& text) {
  std::string out;
  std::size_t start = 0;
  while (start <= text.size()) {
    const std::size_t end = std::min(text.find('\n', start), text.size());
    const std::string part = text.substr(start, end - start);
    if (!part.empty()) out += "<p>" + escape(part) + "</p>";
    start = end + 1;
  }
  return out;
}

// One view's points: interior error, silhouettes apart, CPU against GL.
std::string heightPointsTable(const KnobResult& knob) {
  std::ostringstream s;
  s << "<table>\n<thead><tr><th>setting</th><th>backend</th><th>ms median</th><th>ms min</th><th>frames</th>"
       "<th>interior RMSE</th><th>mean abs</th><th>max diff</th><th>&gt;1 level %</th><th>interior px</th>"
       "<th>silhouette: this only</th><th>silhouette: reference only</th><th>partial px</th>"
       "<th>CPU vs GL RMSE</th><th>CPU vs GL max</th></tr></thead>\n<tbody>\n";
  for (const ReportPoint& p : knob.points) {
    const CompareMetrics& m = p.vsReference;
    s << "<tr>" << timingCells(p) << "<td>" << num(m.rmse, 2) << "</td><td>" << num(m.meanAbsDiff, 2) << "</td><td>"
      << m.maxAbsDiff << "</td><td>" << num(m.over1Pct(), 2) << "</td>";
    if (p.heightField) {
      s << "<td>" << p.heightField->interiorPixels << "</td><td>" << p.heightField->silhouetteApproxOnly << "</td><td>"
        << p.heightField->silhouetteReferenceOnly << "</td><td>" << p.heightField->partialPixels << "</td>";
    } else {
      s << "<td></td><td></td><td></td><td></td>";
    }
    if (p.cpuVsGl) {
      s << "<td>" << num(p.cpuVsGl->rmse, 2) << "</td><td>" << p.cpuVsGl->maxAbsDiff << "</td>";
    } else {
      s << "<td></td><td></td>";
    }
    s << "</tr>\n";
  }
  s << "</tbody></table>\n";
  return s.str();
}

// One field at a glance: a row per setting, a column per angle, each cell the CPU's interior
// RMSE and fastest frame; the best RMSE of each column in bold.
std::string heightOverviewTable(const HeightFieldSection& section, const std::string& field) {
  std::vector<const HeightFieldView*> views;
  for (const HeightFieldView& v : section.views)
    if (v.field == field) views.push_back(&v);
  if (views.empty()) return "";
  std::vector<std::string> settings;
  for (const ReportPoint& p : views.front()->result.points)
    if (p.backend == "cpu") settings.push_back(p.setting);
  std::vector<double> best(views.size(), -1.0);
  for (std::size_t c = 0; c < views.size(); ++c) {
    for (const ReportPoint& p : views[c]->result.points) {
      if (p.backend != "cpu" || !p.heightField || p.heightField->method == kTrueGeometry) continue;
      if (best[c] < 0.0 || p.vsReference.rmse < best[c]) best[c] = p.vsReference.rmse;
    }
  }
  std::ostringstream s;
  s << "<table>\n<thead><tr><th>" << escape(field) << ": CPU interior RMSE (levels) / fastest frame (ms)</th>";
  for (const HeightFieldView* v : views) s << "<th>" << v->angleDeg << "&deg;</th>";
  s << "</tr></thead>\n<tbody>\n";
  for (const std::string& setting : settings) {
    s << "<tr><td>" << escape(setting) << "</td>";
    for (std::size_t c = 0; c < views.size(); ++c) {
      const ReportPoint* found = nullptr;
      for (const ReportPoint& p : views[c]->result.points)
        if (p.backend == "cpu" && p.setting == setting) found = &p;
      if (!found) {
        s << "<td></td>";
        continue;
      }
      const bool isBest = found->heightField && found->heightField->method != kTrueGeometry &&
                          found->vsReference.rmse == best[c];
      s << "<td>" << (isBest ? "<b>" : "") << num(found->vsReference.rmse, 2) << (isBest ? "</b>" : "") << " / "
        << msText(found->msMin) << "</td>";
    }
    s << "</tr>\n";
  }
  s << "</tbody></table>\n";
  return s.str();
}

// RMSE and worst error against the map's side (log2 axis), one line per parameterization.
std::string parameterizationChartSvg(const ParameterizationSection& section) {
  constexpr int kWidth = 560, kHeight = 260, kLeft = 60, kRight = 20, kTop = 20, kBottom = 40;
  double top = 0.0;
  int minLog = 99, maxLog = 0;
  for (const ParameterizationRow& r : section.rows) {
    top = std::max(top, r.error.p99);
    const int l = static_cast<int>(std::lround(std::log2(r.size)));
    minLog = std::min(minLog, l);
    maxLog = std::max(maxLog, l);
  }
  if (section.rows.empty() || top <= 0.0 || maxLog <= minLog) return "";
  const auto x = [&](int size) {
    return kLeft + (std::log2(size) - minLog) / (maxLog - minLog) * (kWidth - kLeft - kRight);
  };
  const auto y = [&](double v) { return kTop + (1.0 - v / top) * (kHeight - kTop - kBottom); };
  std::ostringstream s;
  s << "<svg width=\"" << kWidth << "\" height=\"" << kHeight << "\" font-size=\"11\" font-family=\"sans-serif\">\n";
  s << "<line x1=\"" << kLeft << "\" y1=\"" << y(0) << "\" x2=\"" << kWidth - kRight << "\" y2=\"" << y(0)
    << "\" stroke=\"#888\"/>\n<line x1=\"" << kLeft << "\" y1=\"" << kTop << "\" x2=\"" << kLeft << "\" y2=\"" << y(0)
    << "\" stroke=\"#888\"/>\n";
  for (int l = minLog; l <= maxLog; ++l) {
    s << "<text x=\"" << x(1 << l) << "\" y=\"" << kHeight - 22 << "\" text-anchor=\"middle\">" << (1 << l) << "</text>\n";
  }
  s << "<text x=\"" << (kWidth + kLeft) / 2 << "\" y=\"" << kHeight - 6 << "\" text-anchor=\"middle\">map side (texels)</text>\n";
  for (int k = 0; k <= 4; ++k) {
    const double v = top * k / 4.0;
    s << "<text x=\"" << kLeft - 6 << "\" y=\"" << y(v) + 4 << "\" text-anchor=\"end\">" << std::fixed
      << std::setprecision(1) << v << "</text>\n";
  }
  s << "<text x=\"12\" y=\"" << kTop + 60 << "\" transform=\"rotate(-90 12 " << kTop + 60
    << ")\" text-anchor=\"middle\">levels</text>\n";
  const struct {
    EnvironmentParameterization kind;
    const char* colour;
  } lines[] = {{EnvironmentParameterization::Sphere, "#c0392b"}, {EnvironmentParameterization::DualParaboloid, "#2471a3"}};
  int legendY = kTop;
  for (const auto& line : lines) {
    for (const bool p99 : {false, true}) {
      s << "<polyline fill=\"none\" stroke=\"" << line.colour << "\" stroke-width=\"2\""
        << (p99 ? " stroke-dasharray=\"5 3\"" : "") << " points=\"";
      for (const ParameterizationRow& r : section.rows) {
        if (r.kind == line.kind) s << x(r.size) << "," << y(p99 ? r.error.p99 : r.error.rmse) << " ";
      }
      s << "\"/>\n";
      s << "<text x=\"" << kWidth - kRight - 150 << "\" y=\"" << legendY + 10 << "\" fill=\"" << line.colour << "\">"
        << toString(line.kind) << (p99 ? " 99th percentile" : " RMSE") << "</text>\n";
      legendY += 14;
    }
  }
  s << "</svg>\n";
  return s.str();
}

// Pictures beside report.html, each with its caption.
std::string figuresHtml(const std::vector<std::string>& pictures, const std::vector<std::string>& captions) {
  std::ostringstream s;
  for (std::size_t i = 0; i < pictures.size() && i < captions.size(); ++i) {
    s << "<figure><img src=\"" << escape(pictures[i]) << "\" alt=\"" << escape(captions[i]) << "\"><figcaption>"
      << escape(captions[i]) << "</figcaption></figure>\n";
  }
  return s.str();
}

std::string parameterizationsHtml(const ParameterizationSection& section) {
  std::ostringstream s;
  s << "<h2 id=\"environment_parameterizations\">Environment parameterizations</h2>\n";
  s << "<p>A sphere map and a dual-paraboloid map built from " << escape(section.source)
    << " at each size, read at level 0 with bilinear filtering, against the cube read exactly in the same direction, "
       "over directions spread evenly on the sphere. The error of a direction is its largest channel's difference in "
       "8-bit levels (both clamped to [0, 1]). Source: scene/environment_error.cpp; docs/environment.md.</p>\n";
  s << "<div class=\"reading\"><b>" << escape(section.summary) << "</b><br>" << escape(section.reading) << "</div>\n";
  if (!section.skipped.empty()) return s.str();
  s << parameterizationChartSvg(section);
  s << "<table><thead><tr><th>mapping</th><th>side</th><th>directions</th><th>RMSE</th><th>99th percentile</th>"
       "<th>worst</th><th>worst direction</th><th>build ms</th></tr></thead>\n<tbody>\n";
  for (const ParameterizationRow& r : section.rows) {
    const glm::dvec3& w = r.error.worstDirection;
    s << "<tr><td>" << toString(r.kind) << "</td><td>" << r.size << "</td><td>" << r.error.directions << "</td><td>"
      << std::fixed << std::setprecision(2) << r.error.rmse << "</td><td>" << r.error.p99 << "</td><td>" << r.error.maxError
      << "</td><td>(" << w.x << ", " << w.y << ", " << w.z << ")</td><td>" << std::setprecision(1) << r.buildMs
      << "</td></tr>\n";
  }
  s << "</tbody></table>\n";
  s << figuresHtml(section.pictures, section.captions);
  return s.str();
}

std::string diffuseLightHtml(const DiffuseLightSection& section) {
  std::ostringstream s;
  s << "<h2 id=\"environment_diffuse\">Environment diffuse light</h2>\n";
  s << "<p>What a white Lambertian surface reflects of " << escape(section.source)
    << ", D(n) = E(n) / &pi;, from the 32-texel irradiance cube (bilinear at the normal) and from nine spherical-harmonic "
       "coefficients, each against a Monte Carlo estimate over the source itself (cosine-weighted samples, a fixed seed, "
       "the source read exactly), at normals spread evenly on the sphere; and SH9 against the cube. A normal's error is "
       "its largest channel's difference in 8-bit levels. Source: scene/environment_light.cpp, "
       "scene/environment_error.cpp; docs/environment.md.</p>\n";
  s << "<div class=\"reading\"><b>" << escape(section.summary) << "</b><br>" << escape(section.reading) << "</div>\n";
  if (!section.skipped.empty()) return s.str();
  const DiffuseLightError& e = section.error;
  s << "<table><thead><tr><th>comparison</th><th>normals</th><th>RMSE</th><th>99th percentile</th><th>worst</th>"
       "<th>worst normal</th></tr></thead>\n<tbody>\n";
  const struct {
    const char* name;
    const DiffuseLightComparison& c;
  } rows[] = {{"irradiance cube vs Monte Carlo", e.mapVsReference},
              {"SH9 vs Monte Carlo", e.sh9VsReference},
              {"SH9 vs irradiance cube", e.sh9VsMap}};
  for (const auto& row : rows) {
    const glm::dvec3& w = row.c.worstNormal;
    s << "<tr><td>" << row.name << "</td><td>" << e.normals << "</td><td>" << std::fixed << std::setprecision(2)
      << row.c.rmse << "</td><td>" << row.c.p99 << "</td><td>" << row.c.maxError << "</td><td>(" << w.x << ", " << w.y
      << ", " << w.z << ")</td></tr>\n";
  }
  s << "</tbody></table>\n";
  s << "<p class=\"small\">Monte Carlo: " << e.samples << " samples per normal, its own noise " << std::fixed
    << std::setprecision(2) << e.referenceNoise << " levels RMS. Building: irradiance cube " << std::setprecision(1)
    << section.irradianceMs << " ms, SH9 " << section.sh9Ms << " ms.</p>\n";
  s << figuresHtml(section.pictures, section.captions);
  return s.str();
}

std::string glossyHtml(const GlossySection& section) {
  std::ostringstream s;
  s << "<h2 id=\"environment_glossy\">Environment glossy reflection</h2>\n";
  s << "<p>What a Phong lobe of exponent s around the reflected direction gathers of " << escape(section.source)
    << ", from the prefiltered cube (a lobe per level, e<sub>l</sub> = (N<sub>l</sub> / 2)&sup2;) read as textureLod "
       "reads it at LOD = 0.5 log<sub>2</sub>(e<sub>0</sub> / s), against a Monte Carlo estimate of that lobe over "
       "the source itself (samples drawn from the lobe, a fixed seed, the source read exactly), at directions spread "
       "evenly on the sphere; and the unfiltered source in the mirror direction against the same estimate. Whole "
       "LODs are a level's own lobe; the rows between fall halfway, where two lobes are blended. Source: "
       "scene/environment_specular.cpp, scene/environment_error.cpp; docs/environment.md.</p>\n";
  s << "<div class=\"reading\"><b>" << escape(section.summary) << "</b><br>" << escape(section.reading) << "</div>\n";
  if (!section.skipped.empty()) return s.str();
  const GlossyError& e = section.error;
  s << "<table><thead><tr><th>shininess</th><th>LOD</th><th>prefiltered RMSE</th><th>99th percentile</th>"
       "<th>worst</th><th>mirror read RMSE</th><th>reference noise</th></tr></thead>\n<tbody>\n";
  for (const GlossyRow& row : e.rows) {
    s << "<tr><td>" << std::fixed << std::setprecision(0) << row.shininess << "</td><td>" << std::setprecision(2)
      << row.lod << "</td><td>" << row.prefiltered.rmse << "</td><td>" << row.prefiltered.p99 << "</td><td>"
      << row.prefiltered.maxError << "</td><td>" << row.mirror.rmse << "</td><td>" << row.referenceNoise
      << "</td></tr>\n";
  }
  s << "</tbody></table>\n";
  s << "<p class=\"small\">" << e.directions << " directions, " << e.samples << " Monte Carlo samples each; levels "
    << "of 1/255. Building the cube: " << std::fixed << std::setprecision(0) << section.buildMs << " ms.</p>\n";
  s << figuresHtml(section.pictures, section.captions);
  return s.str();
}

std::string shadowsHtml(const ShadowSection& section) {
  std::ostringstream s;
  s << "<h2 id=\"shadows\">Shadow maps against a ray tracer</h2>\n";
  s << "<p>The map's side and PCF kernel on " << escape(section.scene)
    << ": for every pixel showing a surface turned to the light, the visibility the map gives that point (the "
       "shading's own test, in double) against a shadow ray traced in double against the scene's triangles from the "
       "same point (the ray through the pixel centre met with the plane of the triangle the frame shows there). "
       "Wrong: the map's visibility is more than half away from the traced 0 or 1. Times: the whole CPU frame (fast "
       "path, one thread) and its shadow pass. Source: softrender/shadow_reference.cpp, scene/triangle_bvh.cpp; "
       "docs/shadows.md.</p>\n";
  s << "<div class=\"reading\"><b>" << escape(section.summary) << "</b><br>" << escape(section.reading) << "</div>\n";
  if (!section.skipped.empty()) return s.str();
  s << "<table><thead><tr><th>map side</th><th>PCF</th><th>frame ms</th><th>x unshadowed</th><th>shadow pass ms</th>"
       "<th>wrong %</th><th>between %</th><th>mean |error|</th></tr></thead>\n<tbody>\n";
  for (const ShadowRow& row : section.rows) {
    s << "<tr><td>" << row.size << "</td><td>" << row.pcf << "</td><td>" << std::fixed << std::setprecision(1)
      << row.msMedian << "</td><td>" << std::setprecision(2)
      << (section.unshadowedMs > 0.0 ? row.msMedian / section.unshadowedMs : 0.0) << "</td><td>"
      << std::setprecision(1) << row.shadowPassMs << "</td><td>" << std::setprecision(2) << row.wrongPercent
      << "</td><td>" << row.partialPercent << "</td><td>" << std::setprecision(4) << row.meanAbsError << "</td></tr>\n";
  }
  s << "</tbody></table>\n";
  s << "<p class=\"small\">Unshadowed frame: " << std::fixed << std::setprecision(1) << section.unshadowedMs
    << " ms. " << section.measured << " pixels measured.</p>\n";
  s << figuresHtml(section.pictures, section.captions);
  return s.str();
}

// Time per frame against error, one line per march (its step counts in order), the x axis
// logarithmic: a point further left and lower is cheaper and nearer the ray tracer.
std::string ssrChartSvg(const SsrSection& section) {
  constexpr int kWidth = 620, kHeight = 300, kLeft = 60, kRight = 150, kTop = 20, kBottom = 40;
  double top = 0.0, lo = 0.0, hi = 0.0;
  for (const SsrMarchRow& r : section.steps) {
    top = std::max(top, r.meanAbs);
    lo = lo > 0.0 ? std::min(lo, r.msMedian) : r.msMedian;
    hi = std::max(hi, r.msMedian);
  }
  if (section.steps.empty() || top <= 0.0 || lo <= 0.0 || hi <= lo) return "";
  const double l0 = std::floor(std::log10(lo) * 4.0) / 4.0, l1 = std::ceil(std::log10(hi) * 4.0) / 4.0;
  const auto x = [&](double ms) { return kLeft + (std::log10(ms) - l0) / (l1 - l0) * (kWidth - kLeft - kRight); };
  const auto y = [&](double v) { return kTop + (1.0 - v / top) * (kHeight - kTop - kBottom); };
  std::ostringstream s;
  s << std::fixed << std::setprecision(1);
  s << "<svg width=\"" << kWidth << "\" height=\"" << kHeight << "\" font-size=\"11\" font-family=\"sans-serif\">\n";
  s << "<line x1=\"" << kLeft << "\" y1=\"" << y(0) << "\" x2=\"" << kWidth - kRight << "\" y2=\"" << y(0)
    << "\" stroke=\"#888\"/>\n<line x1=\"" << kLeft << "\" y1=\"" << kTop << "\" x2=\"" << kLeft << "\" y2=\"" << y(0)
    << "\" stroke=\"#888\"/>\n";
  for (double e = std::floor(l0); e <= std::ceil(l1); e += 1.0) {
    for (const double m : {1.0, 1.5, 2.0, 3.0, 5.0, 7.0}) {
      const double ms = m * std::pow(10.0, e);
      if (std::log10(ms) < l0 || std::log10(ms) > l1) continue;
      s << "<text x=\"" << x(ms) << "\" y=\"" << kHeight - 22 << "\" text-anchor=\"middle\">" << tickText(ms) << "</text>\n";
    }
  }
  s << "<text x=\"" << (kWidth - kRight + kLeft) / 2 << "\" y=\"" << kHeight - 6
    << "\" text-anchor=\"middle\">CPU frame, ms (log)</text>\n";
  for (int k = 0; k <= 4; ++k) {
    const double v = top * k / 4.0;
    s << "<text x=\"" << kLeft - 6 << "\" y=\"" << y(v) + 4 << "\" text-anchor=\"end\">" << std::setprecision(1) << v
      << "</text>\n";
  }
  s << "<text x=\"12\" y=\"" << kTop + 90 << "\" transform=\"rotate(-90 12 " << kTop + 90
    << ")\" text-anchor=\"middle\">mean error vs traced, levels</text>\n";
  const struct {
    const char* march;
    const char* colour;
  } lines[] = {{"linear_world", "#c0392b"}, {"adaptive_world", "#d68910"}, {"dda_screen", "#2471a3"}, {"hiz", "#1e8449"}};
  int legendY = kTop;
  for (const auto& line : lines) {
    s << "<polyline fill=\"none\" stroke=\"" << line.colour << "\" stroke-width=\"2\" points=\"";
    for (const SsrMarchRow& r : section.steps) {
      if (r.march == line.march) s << x(r.msMedian) << "," << y(r.meanAbs) << " ";
    }
    s << "\"/>\n";
    for (const SsrMarchRow& r : section.steps) {
      if (r.march != line.march) continue;
      s << "<circle cx=\"" << x(r.msMedian) << "\" cy=\"" << y(r.meanAbs) << "\" r=\"3\" fill=\"" << line.colour
        << "\"><title>" << r.march << ", " << r.maxSteps << " steps: " << r.msMedian << " ms, " << r.meanAbs
        << " levels</title></circle>\n<text x=\"" << x(r.msMedian) + 4 << "\" y=\"" << y(r.meanAbs) - 4
        << "\" fill=\"" << line.colour << "\" font-size=\"9\">" << r.maxSteps << "</text>\n";
    }
    s << "<text x=\"" << kWidth - kRight + 10 << "\" y=\"" << legendY + 10 << "\" fill=\"" << line.colour << "\">"
      << line.march << "</text>\n";
    legendY += 14;
  }
  s << "</svg>\n";
  return s.str();
}

std::string ssrMarchTable(const std::vector<SsrMarchRow>& rows, double baseMs) {
  std::ostringstream s;
  s << "<table><thead><tr><th>march</th><th>max_steps</th><th>thickness</th><th>frame ms</th><th>x no SSR</th>"
       "<th>SSR pass ms</th><th>mean error</th><th>visible: mean</th><th>visible: over 3</th>"
       "<th>false hits (sky, over 3)</th></tr></thead>\n<tbody>\n";
  for (const SsrMarchRow& r : rows) {
    s << "<tr><td>" << escape(r.march) << "</td><td>" << r.maxSteps << "</td><td>" << num(r.thickness, 2) << "</td><td>"
      << msText(r.msMedian) << "</td><td>" << num(baseMs > 0.0 ? r.msMedian / baseMs : 0.0, 2) << "</td><td>"
      << msText(r.ssrMs) << "</td><td>" << num(r.meanAbs, 2) << "</td><td>" << num(r.visibleMeanAbs, 2) << "</td><td>"
      << r.missedVisible << "</td><td>" << r.falseHits << "</td></tr>\n";
  }
  s << "</tbody></table>\n";
  return s.str();
}

std::string ssrHtml(const SsrSection& section) {
  std::ostringstream s;
  s << "<h2 id=\"ssr\">Screen-space reflections against a ray tracer</h2>\n";
  s << "<p>Every march of settings.ssr at several max_steps and thicknesses on " << escape(section.scene)
    << ", and the indirect light at several sample counts on " << escape(section.indirectScene)
    << ". The reference traces the same rays (the mirror ray and the indirect samples, from the same G-buffer point "
       "and normal) against the scene's own triangles with "
    << escape(section.tracer.empty() ? std::string("Embree") : section.tracer)
    << " and adds the light they bring to the same lit frame: surfaces the frame shows bring its colour there, "
       "surfaces off the screen or hidden are lit by the frame's own shading. Error: the largest channel difference "
       "in levels, over the pixels that reflect. Visible: pixels whose mirror ray meets a surface the frame shows, "
       "where the error is the march's own; false hits: pixels whose mirror ray meets nothing that the march lit "
       "anyway. Times: the whole CPU frame (fast path, every core). Source: raytrace/ssr_reference.cpp; docs/ssr.md."
       "</p>\n";
  s << "<div class=\"reading\"><b>" << escape(section.summary) << "</b><br>" << escape(section.reading) << "</div>\n";
  if (!section.skipped.empty()) return s.str();
  s << ssrChartSvg(section);
  s << "<h3>Step counts (thickness " << num(section.steps.empty() ? 0.0 : section.steps.front().thickness, 2)
    << ")</h3>\n" << ssrMarchTable(section.steps, section.baseMs);
  s << "<h3>Thickness (64 steps)</h3>\n" << ssrMarchTable(section.thickness, section.baseMs);
  s << "<h3>Indirect light: samples</h3>\n<table><thead><tr><th>samples</th><th>frame ms</th><th>SSR pass ms</th>"
       "<th>mean error vs " << section.referenceSamples << " traced rays</th><th>vs the same rays traced (march alone)</th>"
       "</tr></thead>\n<tbody>\n";
  for (const SsrSamplesRow& r : section.samples) {
    s << "<tr><td>" << r.samples << "</td><td>" << msText(r.msMedian) << "</td><td>" << msText(r.ssrMs) << "</td><td>"
      << num(r.meanAbs, 2) << "</td><td>" << num(r.marchMeanAbs, 2) << "</td></tr>\n";
  }
  s << "</tbody></table>\n";
  s << "<p class=\"small\">The mirror floor without reflections: " << msText(section.baseMs) << " ms. Its reference "
    << "took " << num(section.traceMs, 0) << " ms, the cave's (" << section.referenceSamples << " rays per pixel) "
    << num(section.indirectTraceMs, 0) << " ms.</p>\n";
  s << figuresHtml(section.pictures, section.captions);
  return s.str();
}

std::string heightFieldsHtml(const HeightFieldSection& section) {
  std::ostringstream s;
  s << "<h2 id=\"height_fields\">Height fields: each method against the displaced surface</h2>\n";
  s << "<dl><dt>Trade</dt><dd>" << escape(section.question) << "</dd><dt>Reference</dt><dd>"
    << escape(section.reference) << "</dd><dt>Scene</dt><dd>" << escape(section.scene) << "</dd></dl>\n";
  s << "<div class=\"reading\"><b>" << escape(section.summary) << "</b>" << paragraphs(section.reading) << "</div>\n";
  if (!section.measured) return s.str();
  for (const std::string& image : section.images) {
    s << "<figure><img src=\"" << escape(image) << "\" alt=\"" << escape(image)
      << "\" style=\"max-width:100%\"><figcaption class=\"small\">" << escape(image) << ": "
      << escape(section.imagesCaption) << "</figcaption></figure>\n";
  }
  std::vector<std::string> fields;
  for (const HeightFieldView& v : section.views)
    if (std::find(fields.begin(), fields.end(), v.field) == fields.end()) fields.push_back(v.field);
  for (const std::string& field : fields) s << heightOverviewTable(section, field);
  for (const HeightFieldView& v : section.views) {
    s << "<h3 id=\"" << v.result.id << "\">" << escape(v.result.title) << "</h3>\n";
    s << chartSvg(v.result, true) << heightPointsTable(v.result);
  }
  return s.str();
}

}  // namespace

void writeReportHtml(const std::string& path, const ReportData& data) {
  std::ostringstream s;
  s << pageHead("twinraster report: speed against error");
  s << "<h1>Speed against error</h1>\n<p class=\"meta\">Generated " << escape(data.generatedAt) << " in "
    << num(data.seconds, 0) << " s" << (data.quick ? " (--quick: smaller images, fewer points and frames)" : "")
    << ". " << escape(data.machine) << ".</p>\n";
  s << "<p>Each chart puts one quality knob on the table: every point is one backend at one setting, placed by its "
       "time per frame (x, the fastest of the timed frames: the machine may be shared, and the fastest frame is the "
       "steadiest measure of what the work itself costs; the table adds the median) and its error against the knob's reference (y, RMSE in 8-bit levels over pixels "
       "both cover, as <code>twinraster compare</code> measures it). Lower and further left is better. The reference "
       "is the CPU pipeline's own stages in double precision with "
    << data.referenceSamplesPerAxis << "x" << data.referenceSamplesPerAxis
    << " samples per pixel, box-filtered (a pixel counts as covered when any sample is, so edge pixels carry "
       "their aliasing error in the colour metrics), unless a knob says otherwise. "
       "The tables add the worst pixel, the share of pixels off by more than one level, the coverage mismatch and "
       "how far the CPU and GL images are from each other.</p>\n";
  s << "<h2>Readings</h2>\n<ul class=\"summary\">\n";
  for (const KnobResult& knob : data.knobs) {
    s << "<li><a href=\"#" << knob.id << "\"><b>" << escape(knob.title) << "</b></a>: " << escape(knob.summary)
      << "</li>\n";
  }
  s << "<li><a href=\"#height_fields\"><b>Height fields</b></a>: " << escape(data.heightFields.summary) << "</li>\n";
  s << "<li><a href=\"#environment_parameterizations\"><b>Environment parameterizations</b></a>: "
    << escape(data.parameterizations.summary) << "</li>\n";
  s << "<li><a href=\"#environment_diffuse\"><b>Environment diffuse light</b></a>: "
    << escape(data.diffuseLight.summary) << "</li>\n";
  s << "<li><a href=\"#environment_glossy\"><b>Environment glossy reflection</b></a>: "
    << escape(data.glossy.summary) << "</li>\n";
  s << "<li><a href=\"#shadows\"><b>Shadow maps against a ray tracer</b></a>: " << escape(data.shadows.summary)
    << "</li>\n";
  s << "<li><a href=\"#ssr\"><b>Screen-space reflections against a ray tracer</b></a>: " << escape(data.ssr.summary)
    << "</li>\n";
  s << "<li><a href=\"#orthonormal_basis\"><b>Orthonormal bases</b></a>: " << escape(data.basisSummary) << "</li>\n";
  s << "</ul>\n";

  for (const KnobResult& knob : data.knobs) {
    s << "<h2 id=\"" << knob.id << "\">" << escape(knob.title) << "</h2>\n";
    s << "<dl><dt>Trade</dt><dd>" << escape(knob.question) << "</dd><dt>Reference</dt><dd>" << escape(knob.reference)
      << "</dd><dt>Scene</dt><dd>" << escape(knob.scene) << "</dd></dl>\n";
    s << "<div class=\"reading\"><b>" << escape(knob.summary) << "</b><br>" << escape(knob.reading) << "</div>\n";
    s << chartSvg(knob) << pointsTable(knob);
  }

  s << heightFieldsHtml(data.heightFields);
  s << parameterizationsHtml(data.parameterizations);
  s << diffuseLightHtml(data.diffuseLight);
  s << glossyHtml(data.glossy);
  s << shadowsHtml(data.shadows);
  s << ssrHtml(data.ssr);

  s << "<h2 id=\"orthonormal_basis\">Orthonormal bases from a normal</h2>\n";
  s << "<p>Four ways to build two unit vectors b1, b2 with b1 x b2 = n from a unit normal alone, in float as a shader "
       "would. Error: the largest of | |b|&sup2; - 1 |, |b.n|, |b1.b2| and the components of |b1 x b2 - n|, over "
    << data.basisDirections
    << " directions (a Fibonacci sphere, the six axes, and directions within 1e-3 rad of -Z, +Z, +Y and -Y at "
       "angles down to 1e-8 rad). Cells above 1e-3 are marked.</p>\n";
  s << "<div class=\"reading\"><b>" << escape(data.basisSummary) << "</b><br>" << escape(data.basisReading)
    << "</div>\n" << basisTable(data);
  s << "<p class=\"small\">naive_fixed_helper: normalize(cross(+Y, n)); naive_best_helper: the same with +X when "
       "|n.x| &lt; |n.y|; frisvad_2012: J. R. Frisvad, Building an orthonormal basis from a 3D unit vector without "
       "normalization (2012); duff_2017: T. Duff et al., Building an Orthonormal Basis, Revisited (JCGT 2017). "
       "Source: scene/orthonormal_basis.cpp.</p>\n";
  s << "<p class=\"small\">The numbers are in results.csv next to this file. See docs/report.md for how each knob is "
       "measured.</p>\n</body></html>\n";

  std::ofstream file(path, std::ios::binary);
  file << s.str();
  if (!file) throw InputError("report: cannot write '" + path + "'");
}

void writeResultsCsv(const std::string& path, const ReportData& data) {
  std::ostringstream s;
  s << "knob,setting,backend,ms_median,ms_min,frames,rmse_levels,psnr_db,max_abs_diff,mean_abs_diff,over1_pct,"
       "coverage_mismatch,covered_backend,covered_reference,cpu_vs_gl_rmse,cpu_vs_gl_max_abs_diff,"
       "cpu_vs_gl_coverage_mismatch,vs_exact_setting,vs_exact_rmse,vs_exact_max_abs_diff,basis_max_error,"
       "basis_max_error_near_minus_z,basis_non_finite,ns_per_basis,height_method,height_layers_min,"
       "height_layers_max,interior_pixels,silhouette_backend_only,silhouette_reference_only,partial_pixels\n";
  constexpr int kHeightColumns = 7;  // height_method .. partial_pixels
  auto quoted = [](const std::string& text) {
    std::string out = "\"";
    for (char c : text) out += c == '"' ? std::string("\"\"") : std::string(1, c);
    return out + "\"";
  };
  auto pointRow = [&](const std::string& knobId, const ReportPoint& p) {
    const CompareMetrics& m = p.vsReference;
    s << knobId << "," << quoted(p.setting) << "," << quoted(p.backend) << "," << num(p.msMedian, 4) << ","
      << num(p.msMin, 4) << "," << p.frames << "," << num(m.rmse, 4) << "," << num(m.psnr, 3) << ","
      << m.maxAbsDiff << "," << num(m.meanAbsDiff, 4) << "," << num(m.over1Pct(), 4) << "," << m.coverageMismatch
      << "," << m.coveredCpu << "," << m.coveredGl << ",";
    if (p.cpuVsGl) {
      s << num(p.cpuVsGl->rmse, 4) << "," << p.cpuVsGl->maxAbsDiff << "," << p.cpuVsGl->coverageMismatch;
    } else {
      s << ",,";
    }
    if (p.vsExactSetting) {
      s << "," << quoted(p.exactSetting) << "," << num(p.vsExactSetting->rmse, 4) << ","
        << p.vsExactSetting->maxAbsDiff;
    } else {
      s << ",,,";
    }
    s << ",,,,";
    if (p.heightField) {
      const HeightFieldPointInfo& h = *p.heightField;
      s << "," << quoted(h.method) << "," << h.layersMin << "," << h.layersMax << "," << h.interiorPixels << ","
        << h.silhouetteApproxOnly << "," << h.silhouetteReferenceOnly << "," << h.partialPixels;
    } else {
      s << std::string(kHeightColumns, ',');
    }
    s << "\n";
  };
  for (const KnobResult& knob : data.knobs)
    for (const ReportPoint& p : knob.points) pointRow(knob.id, p);
  for (const HeightFieldView& view : data.heightFields.views)
    for (const ReportPoint& p : view.result.points) pointRow(view.result.id, p);
  const HeightFieldCost& cost = data.heightFields.cost720p;
  if (cost.measured) {
    // Timing only (no reference at 720p): every metric cell empty.
    s << "height_fields_cost_720p,\"normal_map\",\"cpu\"," << num(cost.normalMapMsMedian, 4) << ","
      << num(cost.normalMapMs, 4) << "," << cost.frames << std::string(18 + kHeightColumns, ',') << "\n";
    s << "height_fields_cost_720p," << quoted(cost.pomSetting) << ",\"cpu\"," << num(cost.pomMsMedian, 4) << ","
      << num(cost.pomMs, 4) << "," << cost.frames << std::string(18 + kHeightColumns, ',') << "\n";
  }
  // SSR: time and mean error against the ray tracer (mean_abs_diff); every other cell empty.
  const auto ssrRow = [&](const std::string& id, const std::string& setting, double ms, double meanAbs) {
    s << id << "," << quoted(setting) << ",\"cpu\"," << num(ms, 4) << ",,,,,," << num(meanAbs, 4)
      << std::string(21, ',') << "\n";
  };
  for (const std::vector<SsrMarchRow>* rows : {&data.ssr.steps, &data.ssr.thickness}) {
    for (const SsrMarchRow& r : *rows) {
      ssrRow("ssr_march", r.march + " " + std::to_string(r.maxSteps) + " steps, thickness " + num(r.thickness, 2),
             r.msMedian, r.meanAbs);
    }
  }
  for (const SsrSamplesRow& r : data.ssr.samples) {
    ssrRow("ssr_indirect", std::to_string(r.samples) + " samples", r.msMedian, r.meanAbs);
  }
  for (const BasisRow& r : data.bases) {
    // 17 empty cells: ms_median .. vs_exact_max_abs_diff; kHeightColumns more at the end.
    s << "orthonormal_basis," << toString(r.method) << ",cpu" << std::string(17, ',') << "," << sci(r.stats.maxError) << ","
      << sci(r.stats.maxErrorNearMinusZ) << "," << r.stats.nonFinite << "," << num(r.nsPerBasis, 3)
      << std::string(kHeightColumns, ',') << "\n";
  }
  std::ofstream file(path, std::ios::binary);
  file << s.str();
  if (!file) throw InputError("report: cannot write '" + path + "'");
}

}  // namespace twr::report
