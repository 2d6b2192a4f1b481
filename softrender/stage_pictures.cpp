#include "softrender/stage_pictures.h"

#include "scene/errors.h"
#include "scene/html_text.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace twr {

namespace {

constexpr double kPicturePixels = 480.0;  // the drawing's longer side, SVG pixels
constexpr double kMarginPixels = 28.0;    // around the drawing, for labels
constexpr double kFixedOne = 256.0;       // setup's sub-pixel steps per pixel (8 bits)
constexpr double kNdcViewLimit = 4.0;     // clip pictures show at most |x/w|, |y/w| <= 4
const char* const kCpuBlue = "#1f5fa8";
const char* const kCutRed = "#c0392b";

std::string num(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.6g", v);
  return text;
}

// Maps a world rectangle onto the picture, y up (GL's and NDC's convention) or down.
struct Frame2d {
  double x0 = 0, y0 = 0, x1 = 1, y1 = 1;  // world bounds
  double scale = 1;
  bool yUp = true;
  double width() const { return (x1 - x0) * scale + 2 * kMarginPixels; }
  double height() const { return (y1 - y0) * scale + 2 * kMarginPixels; }
  double px(double x) const { return kMarginPixels + (x - x0) * scale; }
  double py(double y) const { return kMarginPixels + (yUp ? (y1 - y) : (y - y0)) * scale; }
};

Frame2d frameAround(double x0, double y0, double x1, double y1, bool yUp, double size = kPicturePixels) {
  Frame2d f;
  f.x0 = x0, f.y0 = y0, f.x1 = std::max(x1, x0 + 1e-6), f.y1 = std::max(y1, y0 + 1e-6);
  f.scale = size / std::max(f.x1 - f.x0, f.y1 - f.y0);
  f.yUp = yUp;
  return f;
}

std::string svgOpen(double width, double height) {
  return "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" + num(std::ceil(width)) + "\" height=\"" +
         num(std::ceil(height)) + "\" viewBox=\"0 0 " + num(std::ceil(width)) + " " + num(std::ceil(height)) +
         "\" font-family=\"sans-serif\" font-size=\"12\">\n<rect width=\"100%\" height=\"100%\" fill=\"#fff\"/>\n";
}

std::string polygonOf(const Frame2d& f, const std::vector<std::pair<double, double>>& points, const std::string& style) {
  std::string s = "<polygon points=\"";
  for (const auto& [x, y] : points) s += num(f.px(x)) + "," + num(f.py(y)) + " ";
  return s + "\" " + style + "/>\n";
}

std::string textAt(double x, double y, const std::string& text, const std::string& style = "") {
  return "<text x=\"" + num(x) + "\" y=\"" + num(y) + "\" " + style + ">" + text + "</text>\n";
}

// The clipped polygon's vertices at x/w, y/w (every one has w > 0: the near plane kept them).
std::vector<std::pair<double, double>> ndcOf(const std::vector<vec4>& clip) {
  std::vector<std::pair<double, double>> points;
  for (const vec4& p : clip) points.emplace_back(p.x / p.w, p.y / p.w);
  return points;
}

std::string cutPlanesText(const TriangleVisit& visit) {
  if (visit.planesCut == 0) return "no plane cut it";
  if (visit.planesCut & kClipNonFiniteBit) return clipPlaneNames(visit.planesCut);
  return "cut by " + clipPlaneNames(visit.planesCut);
}

std::pair<double, double> pixelNdc(const PixelTrace& trace) {
  return {2.0 * (trace.x + 0.5) / trace.width - 1.0, 2.0 * (trace.yGl + 0.5) / trace.height - 1.0};
}

// The fan triangle's corners in window pixels, from setup's snapped 1/256 values (pixel
// centres at whole steps: a corner at fixed X lies at X / 256 + 0.5).
std::vector<std::pair<double, double>> snappedCorners(const TriangleVisit& visit) {
  std::vector<std::pair<double, double>> corners;
  for (int i = 0; i < 3; ++i) {
    corners.emplace_back(visit.xFixed[i] / kFixedOne + 0.5, visit.yFixed[i] / kFixedOne + 0.5);
  }
  return corners;
}

struct PixelRange {
  int x0 = 0, y0 = 0, x1 = 0, y1 = 0;  // inclusive, GL rows
};

// The pixels around the snapped corners, at most kStageGridPixels across, the traced one inside.
PixelRange gridAround(const PixelTrace& trace, const std::vector<std::pair<double, double>>& corners) {
  double minX = trace.x, maxX = trace.x, minY = trace.yGl, maxY = trace.yGl;
  for (const auto& [x, y] : corners) {
    minX = std::min(minX, x), maxX = std::max(maxX, x), minY = std::min(minY, y), maxY = std::max(maxY, y);
  }
  PixelRange r{static_cast<int>(std::floor(minX)) - 1, static_cast<int>(std::floor(minY)) - 1,
               static_cast<int>(std::floor(maxX)) + 1, static_cast<int>(std::floor(maxY)) + 1};
  const int half = kStageGridPixels / 2;
  r.x0 = std::max({r.x0, trace.x - half, 0}), r.x1 = std::min({r.x1, trace.x + half, trace.width - 1});
  r.y0 = std::max({r.y0, trace.yGl - half, 0}), r.y1 = std::min({r.y1, trace.yGl + half, trace.height - 1});
  return r;
}

std::string pixelCells(const Frame2d& f, const PixelTrace& trace, const TriangleVisit& visit, const PixelRange& r,
                       const std::vector<std::uint32_t>& ids) {
  std::string s;
  for (int y = r.y0; y <= r.y1; ++y) {
    for (int x = r.x0; x <= r.x1; ++x) {
      const std::size_t row = static_cast<std::size_t>(trace.height - 1 - y);  // the frame's rows run top first
      const std::size_t i = row * static_cast<std::size_t>(trace.width) + static_cast<std::size_t>(x);
      const bool won = i < ids.size() && ids[i] == visit.triangleId;
      s += "<rect x=\"" + num(f.px(x)) + "\" y=\"" + num(f.py(y + 1)) + "\" width=\"" + num(f.scale) + "\" height=\"" +
           num(f.scale) + "\" fill=\"" + (won ? "#cfe0f5" : "#fff") + "\" stroke=\"#ddd\"/>\n";
      s += "<circle cx=\"" + num(f.px(x + 0.5)) + "\" cy=\"" + num(f.py(y + 0.5)) + "\" r=\"1.2\" fill=\"#999\"/>\n";
    }
  }
  return s;
}

// Bars in a row, each value in [0, 1] of `full` height, labelled under.
std::string barPair(double x, double baseY, double barWidth, double full, double a, double b, const std::string& label) {
  std::string s;
  s += "<rect x=\"" + num(x) + "\" y=\"" + num(baseY - a * full) + "\" width=\"" + num(barWidth) + "\" height=\"" +
       num(a * full) + "\" fill=\"#9bb8dc\"/>\n";
  s += "<rect x=\"" + num(x + barWidth + 2) + "\" y=\"" + num(baseY - b * full) + "\" width=\"" + num(barWidth) +
       "\" height=\"" + num(b * full) + "\" fill=\"" + kCpuBlue + "\"/>\n";
  s += textAt(x, baseY + 16, label);
  return s;
}

struct Segment {
  double value;
  std::string colour, name;
};

std::vector<Segment> shadeSegments(const ShadeTerms& terms, int channel) {
  std::vector<Segment> segments = {{terms.ambient[channel], "#bbbbbb", "ambient"}};
  static const char* const kDiffuse[] = {"#e6a23c", "#d98b2b", "#c9781f", "#b96a17"};
  static const char* const kSpecular[] = {"#7fb5e8", "#5c9edc", "#3f86cc", "#2a70b5"};
  for (int i = 0; i < terms.lightCount; ++i) {
    // What the light adds to the sum: its terms times its attenuation and both shadows (lightSum).
    const auto& light = terms.lights[static_cast<std::size_t>(i)];
    const double scale = double(light.attenuation) * light.selfShadow * light.shadowVisibility;
    segments.push_back({light.diffuse[channel] * scale, kDiffuse[i % 4], "L" + std::to_string(i) + " diffuse"});
    segments.push_back({light.specular[channel] * scale, kSpecular[i % 4], "L" + std::to_string(i) + " specular"});
  }
  return segments;
}

std::string stackedBar(double x, double baseY, double width, double unit, const std::vector<Segment>& segments) {
  std::string s;
  double top = baseY;
  for (const Segment& segment : segments) {
    const double h = std::max(0.0, segment.value) * unit;
    top -= h;
    s += "<rect x=\"" + num(x) + "\" y=\"" + num(top) + "\" width=\"" + num(width) + "\" height=\"" + num(h) +
         "\" fill=\"" + segment.colour + "\"><title>" + segment.name + " " + num(segment.value) + "</title></rect>\n";
  }
  return s;
}

void writeText(const std::filesystem::path& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary);
  out << text;
  if (!out) throw InputError(path.string() + ": cannot write");
}

std::string indexHtml(const PixelTrace& trace, const TriangleVisit& visit, const std::vector<StagePicture>& pictures) {
  std::ostringstream s;
  s << "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>Pixel (" << trace.x << ", "
    << trace.yTop << ") through the pipeline</title>\n<style>body{font:15px/1.45 system-ui,sans-serif;max-width:1000px;"
       "margin:24px auto;padding:0 18px;color:#1d1d24}figure{margin:18px 0}figcaption{color:#444;font-size:14px}"
       "img{border:1px solid #ddd;max-width:100%}</style></head><body>\n";
  s << "<h1>Pixel (" << trace.x << ", " << trace.yTop << ") through the pipeline</h1>\n<p>Triangle "
    << visit.triangleId << " (" << escapeHtml(visit.nodeName) << ", triangle " << visit.triangleInMesh
    << " of its mesh): " << toString(visit.outcome) << ". Every number is the pixel trace's (`twinraster trace "
    << "--json`), on a " << trace.width << " x " << trace.height << " frame.</p>\n";
  for (const StagePicture& p : pictures) {
    s << "<figure><h2>" << p.title << "</h2><img src=\"" << p.file << "\" alt=\"" << p.title << "\"><figcaption>"
      << escapeHtml(p.caption) << "</figcaption></figure>\n";
  }
  s << "</body></html>\n";
  return s.str();
}

}  // namespace

std::string clipPlaneNames(std::uint32_t planesCut) {
  if (planesCut & kClipNonFiniteBit) return "removed (non-finite clip position)";
  std::string names;
  for (int plane = 0; plane < kClipPlaneCount; ++plane) {
    if (planesCut & (1u << plane)) names += (names.empty() ? "" : ", ") + std::string(clipPlaneName(plane));
  }
  return names;
}

const TriangleVisit* stageVisitOf(const PixelTrace& trace) {
  const TriangleVisit* written = nullptr;
  const TriangleVisit* shaded = nullptr;
  for (const TriangleVisit& visit : trace.visits) {
    if (visit.outcome != TraceOutcome::Shaded) continue;
    shaded = &visit;
    if (visit.triangleId == trace.triangleId) written = &visit;
  }
  if (written) return written;
  if (shaded) return shaded;
  return trace.visits.empty() ? nullptr : &trace.visits.front();
}

namespace {

using Points = std::vector<std::pair<double, double>>;

// A clipped polygon, its fan from v0 (fan triangle `covering`, v0 v_i v_i+1, filled) and its
// vertices named; nothing for fewer than three vertices.
std::string fanDrawing(const Frame2d& f, const Points& polygon, int covering) {
  std::string s;
  if (polygon.size() < 3) return s;
  s += polygonOf(f, polygon, "fill=\"#e3ecf7\" stroke=\"" + std::string(kCpuBlue) + "\" stroke-width=\"2\"");
  for (std::size_t i = 1; i + 1 < polygon.size(); ++i) {
    s += polygonOf(f, {polygon[0], polygon[i], polygon[i + 1]},
                   static_cast<int>(i) == covering ? "fill=\"#9bb8dc\" stroke=\"#1f5fa8\""
                                                   : "fill=\"none\" stroke=\"#1f5fa8\" stroke-opacity=\"0.4\"");
  }
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    s += textAt(f.px(polygon[i].first) + 4, f.py(polygon[i].second) - 4, "v" + std::to_string(i), "fill=\"#1f5fa8\"");
  }
  return s;
}

// One view of the clip stage: the [-1, 1] square, the unclipped triangle, the polygon, its fan
// (triangle i is v0, v_i, v_i+1; the one covering the pixel filled) and the pixel's centre.
std::string clipDrawing(const Frame2d& f, const PixelTrace& trace, const TriangleVisit& visit, const Points& polygon,
                        const Points& triangle, const std::string& title) {
  std::string s = polygonOf(f, {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}}, "fill=\"#f4f6fa\" stroke=\"#888\" stroke-dasharray=\"4 3\"");
  if (triangle.size() == 3) s += polygonOf(f, triangle, "fill=\"none\" stroke=\"#aaa\" stroke-width=\"1.5\"");
  s += fanDrawing(f, polygon, visit.fanTriangle);
  const auto [px, py] = pixelNdc(trace);
  s += "<circle cx=\"" + num(f.px(px)) + "\" cy=\"" + num(f.py(py)) + "\" r=\"4\" fill=\"" + kCutRed + "\"/>\n";
  return s + textAt(6, 16, title, "fill=\"#444\"");
}

// A drawing in a box of its own at `left`, what falls outside it hidden.
std::string panelAt(double left, const Frame2d& f, const std::string& drawing) {
  return "<svg x=\"" + num(left) + "\" y=\"0\" width=\"" + num(f.width()) + "\" height=\"" + num(f.height()) +
         "\" overflow=\"hidden\">" + drawing + "<rect width=\"100%\" height=\"100%\" fill=\"none\" stroke=\"#ddd\"/></svg>\n";
}

// The bounds of `points` (and `extra`), a tenth wider on each side, within the NDC view limit.
Frame2d frameOfPoints(const std::vector<Points>& sets, double minSize) {
  double x0 = 1e30, y0 = 1e30, x1 = -1e30, y1 = -1e30;
  for (const Points& points : sets) {
    for (const auto& [x, y] : points) x0 = std::min(x0, x), x1 = std::max(x1, x), y0 = std::min(y0, y), y1 = std::max(y1, y);
  }
  const double pad = std::max({0.1 * (x1 - x0), 0.1 * (y1 - y0), minSize});
  return frameAround(std::max(x0 - pad, -kNdcViewLimit), std::max(y0 - pad, -kNdcViewLimit),
                     std::min(x1 + pad, kNdcViewLimit), std::min(y1 + pad, kNdcViewLimit), true);
}

constexpr double kStepPanelPixels = 190.0;  // one clip step's drawing, SVG pixels
constexpr int kStepPanelsPerRow = 4;

// The axes a plane is a line in: (x, w) for right, left and the rest, (y, w) for top and
// bottom, (z, w) for near and far; the plane is then coordinate = +/- w.
int axisOf(int plane) {
  if (plane == kClipPlaneTop || plane == kClipPlaneBottom) return 1;
  if (plane == kClipPlaneNear || plane == kClipPlaneFar) return 2;
  return 0;
}

// One pass of the clipper in the plane's own axes: the polygon before (grey), what it left
// (blue), the plane's line and each vertex it made with its t.
std::string clipStepDrawing(const ClipStep& step) {
  const int axis = axisOf(step.plane);
  const auto project = [axis](const std::vector<vec4>& polygon) {
    Points points;
    for (const vec4& p : polygon) points.emplace_back(p[axis], p.w);
    return points;
  };
  const Points before = project(step.before), after = project(step.after);
  double lo = 1e30, hi = -1e30;
  for (const auto& [a, w] : before) lo = std::min({lo, a, w}), hi = std::max({hi, a, w});
  const double pad = 0.1 * std::max(hi - lo, 1e-6);
  Frame2d f = frameAround(lo - pad, lo - pad, hi + pad, hi + pad, true, kStepPanelPixels);
  const bool plus = step.plane == kClipPlaneRight || step.plane == kClipPlaneTop || step.plane == kClipPlaneFar;
  const double sign = plus ? 1.0 : -1.0;  // the plane: coordinate = sign * w (side, near and far planes)
  std::string s;
  if (step.plane <= kClipPlaneFar) {
    s += "<line x1=\"" + num(f.px(sign * (lo - pad))) + "\" y1=\"" + num(f.py(lo - pad)) + "\" x2=\"" +
         num(f.px(sign * (hi + pad))) + "\" y2=\"" + num(f.py(hi + pad)) + "\" stroke=\"" + kCutRed +
         "\" stroke-dasharray=\"5 3\"/>\n";
  }
  if (before.size() >= 3) s += polygonOf(f, before, "fill=\"none\" stroke=\"#999\" stroke-width=\"1.5\"");
  if (after.size() >= 3) s += polygonOf(f, after, "fill=\"#cfe0f5\" fill-opacity=\"0.8\" stroke=\"#1f5fa8\"");
  for (const ClipCut& cut : step.cuts) {
    if (cut.index < 0 || static_cast<std::size_t>(cut.index) >= after.size()) continue;  // the polygon was removed
    const auto [a, w] = after[static_cast<std::size_t>(cut.index)];
    s += "<circle cx=\"" + num(f.px(a)) + "\" cy=\"" + num(f.py(w)) + "\" r=\"3.5\" fill=\"" + kCutRed + "\"/>\n" +
         textAt(f.px(a) + 5, f.py(w) - 4, "t " + num(cut.t), "fill=\"#c0392b\"");
  }
  const char* const axisNames[] = {"x", "y", "z"};
  s += textAt(6, 16, std::string(clipPlaneName(step.plane)) + ": " + std::to_string(step.before.size()) + " -> " +
                         std::to_string(step.after.size()) + " vertices",
              "font-weight=\"600\"");
  s += textAt(6, f.height() - 6, std::string("horizontal ") + axisNames[axis] + ", vertical w", "fill=\"#666\"");
  return panelAt(0, f, s);
}

}  // namespace

std::string clipStageSvg(const PixelTrace& trace, const TriangleVisit& visit) {
  const Points polygon = ndcOf(visit.clippedPolygon);
  Points triangle;  // the vertices in front of the eye (w > 0)
  for (const vec4& p : visit.posClip) {
    if (p.w > 0.0f) triangle.emplace_back(p.x / p.w, p.y / p.w);
  }
  const Points square = {{-1, -1}, {1, 1}};
  const Frame2d whole = frameOfPoints({square, polygon, triangle}, 0.05);
  const auto [px, py] = pixelNdc(trace);
  const Frame2d zoom = frameOfPoints({polygon.empty() ? triangle : polygon, {{px, py}}}, 1e-4);
  // Below the two views, the clipper's passes in order, kStepPanelsPerRow to a row.
  const double top = std::max(whole.height(), zoom.height());
  const double step = kStepPanelPixels + 2 * kMarginPixels;
  const int rows = (static_cast<int>(visit.clipSteps.size()) + kStepPanelsPerRow - 1) / kStepPanelsPerRow;
  std::string s = svgOpen(std::max(whole.width() + zoom.width(), kStepPanelsPerRow * step), top + rows * step);
  s += panelAt(0, whole, clipDrawing(whole, trace, visit, polygon, triangle, "x/w, y/w: the view volume's [-1, 1] square"));
  s += panelAt(whole.width(), zoom, clipDrawing(zoom, trace, visit, polygon, triangle, "zoomed to the polygon"));
  for (std::size_t i = 0; i < visit.clipSteps.size(); ++i) {
    const double x = static_cast<double>(i % kStepPanelsPerRow) * step;
    const double y = top + static_cast<double>(i / kStepPanelsPerRow) * step;
    s += "<g transform=\"translate(" + num(x) + "," + num(y) + ")\">" + clipStepDrawing(visit.clipSteps[i]) + "</g>\n";
  }
  return s + "</svg>\n";
}

std::string vertexStageSvg(const PixelTrace& trace, const TriangleVisit& visit) {
  Points triangle;  // the corners in front of the eye (w > 0)
  std::vector<std::size_t> corner;  // ... and which vertex each one is
  for (std::size_t k = 0; k < 3; ++k) {
    const vec4& p = visit.posClip[k];
    if (!(p.w > 0.0f)) continue;
    triangle.emplace_back(p.x / p.w, p.y / p.w);
    corner.push_back(k);
  }
  const Frame2d f = frameOfPoints({{{-1, -1}, {1, 1}}, triangle}, 0.05);
  constexpr double kLine = 18.0;  // SVG pixels per text line
  const double tableTop = f.height() + 8.0;
  std::string s = svgOpen(std::max(f.width(), 760.0), tableTop + 4 * kLine + kMarginPixels);
  s += panelAt(0, f, clipDrawing(f, trace, visit, {}, triangle, "the corners at x/w, y/w (w > 0)"));
  for (std::size_t i = 0; i < triangle.size(); ++i) {
    s += textAt(f.px(triangle[i].first) + 4, f.py(triangle[i].second) + 14, "v" + std::to_string(corner[i]), "fill=\"#666\"");
  }
  for (std::size_t i = 0; i < 3; ++i) {
    const vec3& m = visit.posModel[i];
    const vec4& c = visit.posClip[i];
    std::string outside;
    const std::pair<bool, const char*> planes[] = {{c.x > c.w, "right"}, {c.x < -c.w, "left"}, {c.y > c.w, "top"},
                                                   {c.y < -c.w, "bottom"}, {c.z < -c.w, "near"}, {c.z > c.w, "far"}};
    for (const auto& [out, name] : planes) {
      if (out) outside += (outside.empty() ? "; outside " : ", ") + std::string(name);
    }
    s += textAt(kMarginPixels, tableTop + static_cast<double>(i + 1) * kLine,
                "v" + std::to_string(i) + " (" + num(m.x) + ", " + num(m.y) + ", " + num(m.z) + ") -> clip (" +
                    num(c.x) + ", " + num(c.y) + ", " + num(c.z) + ", " + num(c.w) + ")" + outside);
  }
  return s + "</svg>\n";
}

std::string divideStageSvg(const PixelTrace& trace, const TriangleVisit& visit) {
  const Viewport viewport{trace.width, trace.height};
  Points polygon;
  for (const vec4& p : visit.clippedPolygon) {
    const bool input = std::find(visit.posClip.begin(), visit.posClip.end(), p) != visit.posClip.end();
    const WindowVertex w = windowFromClip(p, viewport, input);
    polygon.emplace_back(w.x, w.y);
  }
  const double w = trace.width, h = trace.height;
  const double pad = 0.08 * std::max(w, h);
  const Frame2d f = frameAround(-pad, -pad, w + pad, h + pad, true);
  const std::string drawing = fanDrawing(f, polygon, visit.fanTriangle);
  constexpr double kLine = 18.0;  // SVG pixels per text line
  std::string s = svgOpen(std::max(f.width(), 520.0), f.height() + (static_cast<double>(polygon.size()) + 1) * kLine);
  s += polygonOf(f, {{0, 0}, {w, 0}, {w, h}, {0, h}}, "fill=\"#f4f6fa\" stroke=\"#888\" stroke-dasharray=\"4 3\"");
  s += "<svg x=\"0\" y=\"0\" width=\"" + num(f.width()) + "\" height=\"" + num(f.height()) + "\" overflow=\"hidden\">" +
       drawing + "</svg>\n";
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    s += textAt(kMarginPixels, f.height() + static_cast<double>(i + 1) * kLine,
                "v" + std::to_string(i) + " window (" + num(polygon[i].first) + ", " + num(polygon[i].second) + ")");
  }
  s += "<circle cx=\"" + num(f.px(trace.x + 0.5)) + "\" cy=\"" + num(f.py(trace.yGl + 0.5)) + "\" r=\"4\" fill=\"" + kCutRed + "\"/>\n";
  s += textAt(6, 16, "window pixels, y up from the image's bottom edge: the " + std::to_string(trace.width) + " x " +
                         std::to_string(trace.height) + " image dashed", "fill=\"#444\"");
  return s + "</svg>\n";
}

std::string setupStageSvg(const PixelTrace& trace, const TriangleVisit& visit) {
  const std::vector<std::pair<double, double>> corners = snappedCorners(visit);
  const PixelRange r = gridAround(trace, corners);
  const Frame2d f = frameAround(r.x0, r.y0, r.x1 + 1, r.y1 + 1, true);
  constexpr double kLine = 18.0;  // SVG pixels per text line
  std::string s = svgOpen(std::max(f.width(), 560.0), f.height() + 5 * kLine);
  s += pixelCells(f, trace, visit, r, {});
  TriangleSetup setup;
  const bool ready = setupSnappedTriangle(visit.xFixed, visit.yFixed, CullMode::None, FrontFace::Ccw,
                                          Viewport{trace.width, trace.height}, setup) == SetupResult::Ready;
  std::string inside = polygonOf(f, corners, "fill=\"none\" stroke=\"" + std::string(kCpuBlue) + "\" stroke-width=\"2\"");
  if (ready) {
    inside += "<rect x=\"" + num(f.px(setup.x0)) + "\" y=\"" + num(f.py(setup.y1 + 1)) + "\" width=\"" +
              num((setup.x1 + 1 - setup.x0) * f.scale) + "\" height=\"" + num((setup.y1 + 1 - setup.y0) * f.scale) +
              "\" fill=\"none\" stroke=\"#888\" stroke-width=\"1.5\" stroke-dasharray=\"6 3\"/>\n";
    for (std::size_t i = 0; i < 3; ++i) {  // edge i runs from corner i to corner i + 1
      const auto& [ax, ay] = corners[i];
      const auto& [bx, by] = corners[(i + 1) % 3];
      inside += textAt(f.px(0.5 * (ax + bx)) + 4, f.py(0.5 * (ay + by)) + 4, "E" + std::to_string(i), "fill=\"#c0392b\"");
      s += textAt(kMarginPixels, f.height() + static_cast<double>(i + 1) * kLine,
                  "E" + std::to_string(i) + " (c" + std::to_string(i) + " to c" + std::to_string((i + 1) % 3) + "): " +
                      (setup.edges[i].ownsPixelsOnIt ? "a left or bottom edge: owns its centres"
                                                     : "a right or top edge: leaves them to its neighbour") +
                      "; E at the pixel " + std::to_string(visit.edgeValue[i]));
    }
    s += textAt(kMarginPixels, f.height() + 4 * kLine, "dashed: the box, x " + std::to_string(setup.x0) + ".." + std::to_string(setup.x1) + ", y " +
                                             std::to_string(setup.y0) + ".." + std::to_string(setup.y1) + " (GL rows)");
  }
  s += "<clipPath id=\"grid\"><rect x=\"" + num(f.px(r.x0)) + "\" y=\"" + num(f.py(r.y1 + 1)) + "\" width=\"" +
       num((r.x1 + 1 - r.x0) * f.scale) + "\" height=\"" + num((r.y1 + 1 - r.y0) * f.scale) + "\"/></clipPath>\n";
  s += "<g clip-path=\"url(#grid)\">" + inside + "</g>\n";
  s += "<rect x=\"" + num(f.px(trace.x)) + "\" y=\"" + num(f.py(trace.yGl + 1)) + "\" width=\"" + num(f.scale) +
       "\" height=\"" + num(f.scale) + "\" fill=\"none\" stroke=\"" + kCutRed + "\" stroke-width=\"2.5\"/>\n";
  for (int i = 0; i < 3; ++i) {
    const auto [x, y] = corners[static_cast<std::size_t>(i)];
    if (x < r.x0 || x > r.x1 + 1 || y < r.y0 || y > r.y1 + 1) continue;
    s += textAt(f.px(x) + 4, f.py(y) - 4, "c" + std::to_string(i), "fill=\"#1f5fa8\" font-weight=\"600\"");
  }
  return s + "</svg>\n";
}

std::string rasterStageSvg(const PixelTrace& trace, const TriangleVisit& visit,
                           const std::vector<std::uint32_t>& triangleIds) {
  const std::vector<std::pair<double, double>> corners = snappedCorners(visit);
  const PixelRange r = gridAround(trace, corners);
  const Frame2d f = frameAround(r.x0, r.y0, r.x1 + 1, r.y1 + 1, true);
  std::string s = svgOpen(f.width(), f.height());
  s += pixelCells(f, trace, visit, r, triangleIds);
  s += "<clipPath id=\"grid\"><rect x=\"" + num(f.px(r.x0)) + "\" y=\"" + num(f.py(r.y1 + 1)) + "\" width=\"" +
       num((r.x1 + 1 - r.x0) * f.scale) + "\" height=\"" + num((r.y1 + 1 - r.y0) * f.scale) + "\"/></clipPath>\n";
  s += "<g clip-path=\"url(#grid)\">" +
       polygonOf(f, corners, "fill=\"none\" stroke=\"" + std::string(kCpuBlue) + "\" stroke-width=\"2\"") + "</g>\n";
  s += "<rect x=\"" + num(f.px(trace.x)) + "\" y=\"" + num(f.py(trace.yGl + 1)) + "\" width=\"" + num(f.scale) +
       "\" height=\"" + num(f.scale) + "\" fill=\"none\" stroke=\"" + kCutRed + "\" stroke-width=\"2.5\"/>\n";
  for (int i = 0; i < 3; ++i) {
    const auto [x, y] = corners[static_cast<std::size_t>(i)];
    if (x < r.x0 || x > r.x1 + 1 || y < r.y0 || y > r.y1 + 1) continue;
    s += textAt(f.px(x) + 4, f.py(y) - 4, "c" + std::to_string(i), "fill=\"#1f5fa8\" font-weight=\"600\"");
  }
  return s + "</svg>\n";
}

std::string interpolateStageSvg(const TriangleVisit& visit) {
  constexpr double kFull = 200, kBar = 28, kGap = 60, kBase = 240;
  std::string s = svgOpen(3 * (2 * kBar + kGap) + 2 * kMarginPixels, kBase + 60);
  for (int i = 0; i < 3; ++i) {
    const double x = kMarginPixels + i * (2 * kBar + kGap);
    s += barPair(x, kBase, kBar, kFull, visit.weights.screen[static_cast<std::size_t>(i)],
                 visit.weights.perspective[static_cast<std::size_t>(i)], "corner " + std::to_string(i));
  }
  s += textAt(kMarginPixels, 18, "light: screen lambda_i");
  s += textAt(kMarginPixels, 34, "dark: perspective p_i");
  return s + "</svg>\n";
}

std::string shadeStageSvg(const TriangleVisit& visit) {
  constexpr double kUnit = 220, kBar = 46, kGap = 40, kBase = 260;
  const char* const names[] = {"R", "G", "B"};
  std::string s = svgOpen(4 * (kBar + kGap) + 2 * kMarginPixels + 120, kBase + 50);
  for (int c = 0; c < 3; ++c) {
    const double x = kMarginPixels + c * (kBar + kGap);
    s += stackedBar(x, kBase, kBar, kUnit, shadeSegments(visit.terms, c));
    s += "<line x1=\"" + num(x - 4) + "\" x2=\"" + num(x + kBar + 4) + "\" y1=\"" +
         num(kBase - std::clamp<double>(visit.terms.colour[c], 0, 2) * kUnit) + "\" y2=\"" +
         num(kBase - std::clamp<double>(visit.terms.colour[c], 0, 2) * kUnit) + "\" stroke=\"#000\"/>\n";
    s += textAt(x + kBar / 2 - 4, kBase + 16, names[c]);
  }
  const double x = kMarginPixels + 3 * (kBar + kGap);
  char colour[64];
  std::snprintf(colour, sizeof colour, "rgb(%d,%d,%d)", static_cast<int>(std::lround(std::clamp(visit.terms.colour.r, 0.0f, 1.0f) * 255)),
                static_cast<int>(std::lround(std::clamp(visit.terms.colour.g, 0.0f, 1.0f) * 255)),
                static_cast<int>(std::lround(std::clamp(visit.terms.colour.b, 0.0f, 1.0f) * 255)));
  s += "<rect x=\"" + num(x) + "\" y=\"" + num(kBase - kUnit) + "\" width=\"" + num(kBar) + "\" height=\"" + num(kUnit) +
       "\" fill=\"" + colour + "\" stroke=\"#888\"/>\n" + textAt(x, kBase + 16, "written");
  s += "<line x1=\"" + num(kMarginPixels - 8) + "\" x2=\"" + num(x + kBar) + "\" y1=\"" + num(kBase - kUnit) + "\" y2=\"" +
       num(kBase - kUnit) + "\" stroke=\"#bbb\" stroke-dasharray=\"3 3\"/>\n" + textAt(x + kBar + 6, kBase - kUnit + 4, "1.0");
  return s + "</svg>\n";
}

namespace {

std::string triple(double a, double b, double c) { return "(" + num(a) + ", " + num(b) + ", " + num(c) + ")"; }

std::string clipCaption(const PixelTrace& trace, const TriangleVisit& visit) {
  const auto [px, py] = pixelNdc(trace);
  std::string text = "The vertex stage's clip positions divided by w: " + cutPlanesText(visit) + ", " +
                     std::to_string(visit.clippedPolygon.size()) + " vertices after clipping (blue, v0 first).";
  if (visit.fanTriangle >= 0) {
    text += " The rasteriser draws the polygon as a fan from v0; fan triangle " + std::to_string(visit.fanTriangle) +
            " (v0, v" + std::to_string(visit.fanTriangle) + ", v" + std::to_string(visit.fanTriangle + 1) +
            ", filled) covers the pixel, the red dot at x/w, y/w = (" + num(px) + ", " + num(py) + ").";
  }
  if (!visit.clipSteps.empty()) {
    text += " Below, the clipper's passes in its order, each in the two axes its plane is a line in (x = +/-w, "
            "y = +/-w, z = +/-w, dashed red): the polygon before it in grey, what it left in blue, the vertices it "
            "made in red with t along the edge from the endpoint nearer the plane. A plane the triangle straddled "
            "may find nothing left outside it after the earlier cuts (n -> n).";
  }
  return text + " Grey: the unclipped triangle, where all three vertices lie in front of the eye (w > 0). A side "
                "plane only moves an edge onto the image's border, beyond which no pixel lies: switched off "
                "(settings.clip), the clipper cuts at the guard band 16384 pixels out instead and the same pixels "
                "are covered. The near and far planes decide which pixels are drawn.";
}

std::string rasterCaption(const TriangleVisit& visit) {
  std::string corners;
  for (int i = 0; i < 3; ++i) {
    corners += (i ? ", c" : "c") + std::to_string(i) + " (" + std::to_string(visit.xFixed[i]) + ", " +
               std::to_string(visit.yFixed[i]) + ")";
  }
  return "Setup snaps the fan triangle's corners to 1/256 pixel (GL window coordinates, pixel centres at whole "
         "steps): " + corners + ". Edge functions at the pixel's centre: " +
         triple(static_cast<double>(visit.edgeValue[0]), static_cast<double>(visit.edgeValue[1]),
                static_cast<double>(visit.edgeValue[2])) +
         ", all > 0 inside (a 0 counts only on a top or left edge, the fill rule). Blue cells: the pixels the "
         "frame shows this triangle in (its triangle id, from every fan triangle of its clipped polygon); red: the "
         "traced pixel.";
}

std::string vertexCaption(const TriangleVisit& visit) {
  const bool behind = std::any_of(visit.posClip.begin(), visit.posClip.end(), [](const vec4& p) { return !(p.w > 0.0f); });
  return "The vertex stage takes each corner from model space to clip space, clip = P V M p; a corner is inside "
         "the view volume when -w <= x, y, z <= w, and the list gives the planes it lies outside of (" +
         cutPlanesText(visit) + "). The drawing divides by w to show where the corners land against the [-1, 1] "
         "square" + (behind ? "; a corner with w <= 0 lies behind the eye, has no place there and is left out." : ".");
}

std::string divideCaption(const PixelTrace& trace, const TriangleVisit& visit) {
  std::string text = "The divide (x/w, y/w, z/w) and the viewport, window = (ndc + 1) / 2 * size: the clipped "
                     "polygon's " + std::to_string(visit.clippedPolygon.size()) + " vertices in window pixels, GL's "
                     "rows counting up from the image's bottom edge. ";
  if (visit.fanTriangle >= 0) {
    text += "Fan triangle " + std::to_string(visit.fanTriangle) + " (filled) covers the pixel (red, window " +
            num(trace.x + 0.5) + ", " + num(trace.yGl + 0.5) + ").";
  }
  return text;
}

std::string setupCaption(const TriangleVisit& visit) {
  return "Setup snaps the fan triangle's corners to 1/256 pixel (c0, c1, c2, clockwise once setup has ordered them), "
         "bounds the pixels to test with the dashed box, and makes one edge function per edge, E = c + stepX x + "
         "stepY y, positive inside. At the pixel (red): E = " +
         triple(static_cast<double>(visit.edgeValue[0]), static_cast<double>(visit.edgeValue[1]),
                static_cast<double>(visit.edgeValue[2])) +
         ". An edge that owns its centres is a left or bottom edge: a pixel centre exactly on an edge two "
         "triangles share goes to the one whose edge owns it (the fill rule).";
}

std::string interpolateCaption(const TriangleVisit& visit) {
  const PixelWeights& w = visit.weights;
  return "Screen barycentrics lambda = " + triple(w.screen[0], w.screen[1], w.screen[2]) +
         " (the edge values normalised); perspective-correct weights p = " +
         triple(w.perspective[0], w.perspective[1], w.perspective[2]) +
         " (lambda_i / w_i, normalised), which the varyings use: uv = (" + num(w.uv.x) + ", " + num(w.uv.y) +
         "), window depth " + num(w.depth) + ". Depth alone is interpolated with lambda (it is linear on the screen).";
}

std::string shadeCaption(const TriangleVisit& visit) {
  const ShadeTerms& t = visit.terms;
  std::string text = "Phong's terms per channel, stacked: ambient (grey), then each light's diffuse (orange) and "
                     "specular (blue) times its attenuation and shadows, as the light loop sums them. Ambient " +
                     triple(t.ambient.r, t.ambient.g, t.ambient.b);
  for (int i = 0; i < t.lightCount; ++i) {
    const auto& light = t.lights[static_cast<std::size_t>(i)];
    text += "; L" + std::to_string(i) + " diffuse " + triple(light.diffuse.r, light.diffuse.g, light.diffuse.b) +
            ", specular " + triple(light.specular.r, light.specular.g, light.specular.b) + " (N.L " +
            num(light.nDotL) + ", attenuation " + num(light.attenuation) + ", shadow " +
            num(double(light.selfShadow) * light.shadowVisibility) + ")";
  }
  text += ". Colour written " + triple(t.colour.r, t.colour.g, t.colour.b) + " (black lines)";
  if (t.environmentOn) text += ", mixed with the environment (share " + num(t.environmentShare) + ")";
  return text + ".";
}

}  // namespace

std::vector<StagePicture> writeStagePictures(const std::string& dir, const PixelTrace& trace,
                                             const RenderOutput& frame) {
  const TriangleVisit* visit = stageVisitOf(trace);
  if (!visit) {
    throw InputError("trace --stages: no triangle reaches pixel (" + std::to_string(trace.x) + ", " +
                     std::to_string(trace.yTop) + "); pick a pixel on a surface");
  }
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (!std::filesystem::is_directory(dir)) throw InputError(dir + ": cannot create the folder");
  const std::filesystem::path folder(dir);
  // One per stage, in the pipeline's order (the numbers keep the names earlier versions wrote).
  std::vector<StagePicture> pictures = {
      {"0_vertex.svg", "Vertex", vertexCaption(*visit)},
      {"1_clip.svg", "Clip", clipCaption(trace, *visit)},
      {"1_divide.svg", "Divide and viewport", divideCaption(trace, *visit)},
      {"2_setup.svg", "Setup", setupCaption(*visit)},
      {"2_raster.svg", "Raster", rasterCaption(*visit)},
      {"3_interpolate.svg", "Interpolate", interpolateCaption(*visit)},
      {"4_shade.svg", "Shade", shadeCaption(*visit)},
  };
  const std::string svgs[] = {vertexStageSvg(trace, *visit),
                              clipStageSvg(trace, *visit),
                              divideStageSvg(trace, *visit),
                              setupStageSvg(trace, *visit),
                              rasterStageSvg(trace, *visit, frame.triangleId),
                              interpolateStageSvg(*visit),
                              shadeStageSvg(*visit)};
  for (std::size_t i = 0; i < pictures.size(); ++i) writeText(folder / pictures[i].file, svgs[i]);
  if (visit->outcome != TraceOutcome::Shaded) pictures.back().caption = "Not shaded: " + std::string(toString(visit->outcome)) + ".";
  writeText(folder / "index.html", indexHtml(trace, *visit, pictures));
  return pictures;
}

}  // namespace twr
