#include "gui/stage_explorer.h"

#include "softrender/clip.h"
#include "softrender/interpolate.h"
#include "softrender/raster.h"
#include "softrender/setup.h"
#include "softrender/stage_pictures.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iterator>

namespace twr::gui {

namespace {

constexpr double kFixedOne = 256.0;  // setup's sub-pixel steps per pixel (8 bits)
// The frame's arrows at Shade, in world units per unit of the fragment's clip w (its depth in
// front of the eye), so they keep one size on the image: about 33 px at 480 rows and a
// 60-degree field of view.
constexpr float kFrameArrowPerDepth = 0.08f;

std::string num(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.6g", v);
  return text;
}
template <typename V>
std::string vec(const V& v, int n) {
  std::string s = "(";
  for (int i = 0; i < n; ++i) s += (i ? ", " : "") + num(static_cast<double>(v[i]));
  return s + ")";
}

// A GL window position (origin bottom-left) on the image (origin top-left).
ImagePoint imageOf(double windowX, double windowY, const PixelTrace& trace) {
  return {windowX, static_cast<double>(trace.height) - windowY};
}

// A clip-space position through the pipeline's divide and viewport; a vertex of the input
// triangle is transformed with the fused multiply-add the vertex stage's corners get.
ImagePoint imageOfClip(const vec4& posClip, bool fromVertexStage, const PixelTrace& trace) {
  const WindowVertex w = windowFromClip(posClip, Viewport{trace.width, trace.height}, fromVertexStage);
  return imageOf(w.x, w.y, trace);
}

bool isInputCorner(const vec4& p, const TriangleVisit& visit) {
  return std::find(visit.posClip.begin(), visit.posClip.end(), p) != visit.posClip.end();
}

std::vector<ImagePoint> triangleOf(const PixelTrace& trace, const TriangleVisit& visit) {
  std::vector<ImagePoint> points;
  for (const vec4& p : visit.posClip) {
    if (p.w > 0.0f) points.push_back(imageOfClip(p, true, trace));
  }
  return points;
}

// A polygon's vertices on the image, those in front of the eye (w > 0): a pass before the
// near plane's may still hold a corner behind it.
std::vector<ImagePoint> polygonOf(const PixelTrace& trace, const TriangleVisit& visit, const std::vector<vec4>& clip) {
  std::vector<ImagePoint> points;
  for (const vec4& p : clip) {
    if (p.w > 0.0f) points.push_back(imageOfClip(p, isInputCorner(p, visit), trace));
  }
  return points;
}
std::vector<ImagePoint> polygonOf(const PixelTrace& trace, const TriangleVisit& visit) {
  return polygonOf(trace, visit, visit.clippedPolygon);
}

std::vector<std::array<ImagePoint, 3>> fanOf(const std::vector<ImagePoint>& polygon) {
  std::vector<std::array<ImagePoint, 3>> fan;
  for (std::size_t i = 1; i + 1 < polygon.size(); ++i) fan.push_back({polygon[0], polygon[i], polygon[i + 1]});
  return fan;
}

// The covering fan triangle's place in fanOf's list: the trace's triangle i is (0, i, i + 1).
int fanIndexOf(const TriangleVisit& visit) { return visit.fanTriangle >= 1 ? visit.fanTriangle - 1 : -1; }

// Pixel centres sit at whole steps of the snapped grid: a corner at X lies at X / 256 + 0.5.
std::vector<ImagePoint> snappedOf(const PixelTrace& trace, const TriangleVisit& visit) {
  std::vector<ImagePoint> points;
  for (int i = 0; i < 3; ++i) {
    points.push_back(imageOf(visit.xFixed[static_cast<std::size_t>(i)] / kFixedOne + 0.5,
                             visit.yFixed[static_cast<std::size_t>(i)] / kFixedOne + 0.5, trace));
  }
  return points;
}

// Setup run again on the covering fan triangle's window corners, as the trace ran it (its
// corner order, box and edge functions; culling is decided after, so none here).
std::optional<TriangleSetup> setupOf(const PixelTrace& trace, const TriangleVisit& visit) {
  if (visit.fanTriangle < 0) return std::nullopt;
  TriangleSetup setup;
  if (setupTriangle(visit.window, CullMode::None, FrontFace::Ccw, Viewport{trace.width, trace.height}, setup) !=
      SetupResult::Ready) {
    return std::nullopt;
  }
  return setup;
}

// The rasterizer's visit order: every row span, in the order rasterizeTriangle hands them out
// (GL rows from the bottom), as {x begin, x end, y from the top}.
std::vector<std::array<int, 3>> visitRunsOf(const TriangleSetup& setup, const PixelTrace& trace) {
  std::vector<std::array<int, 3>> runs;
  rasterizeTriangle(setup, 0, trace.height,
                    [&](int py, Span span) { runs.push_back({span.xBegin, span.xEnd, trace.height - 1 - py}); });
  return runs;
}

int pixelCount(const std::vector<std::array<int, 3>>& runs) {
  int count = 0;
  for (const auto& run : runs) count += run[1] - run[0];
  return count;
}

// The runs visited by step `step` (0: the first pixel), the last one cut after that step's pixel.
std::vector<std::array<int, 3>> runsUpTo(const std::vector<std::array<int, 3>>& runs, int step) {
  std::vector<std::array<int, 3>> visited;
  int left = step + 1;
  for (const auto& run : runs) {
    if (left <= 0) break;
    const int taken = std::min(left, run[1] - run[0]);
    visited.push_back({run[0], run[0] + taken, run[2]});
    left -= taken;
  }
  return visited;
}

// The covering fan triangle's weights at every pixel it covers, from the pipeline's own
// interpolation setup and pixelWeights (the weights do not depend on the uv, left zero).
ExplorerWeightMap weightMapOf(const PixelTrace& trace, const TriangleVisit& visit, const TriangleSetup& setup,
                              bool perspective) {
  ExplorerWeightMap map;
  if (setup.x0 > setup.x1 || setup.y0 > setup.y1) return map;
  const InterpolationSetup interpolation =
      makeInterpolationSetup(visit.window, {vec2(0.0f), vec2(0.0f), vec2(0.0f)}, setup, trace.interpolation);
  map.x0 = setup.x0;
  map.y0 = trace.height - 1 - setup.y1;
  map.width = setup.x1 - setup.x0 + 1;
  map.height = setup.y1 - setup.y0 + 1;
  const std::size_t size = static_cast<std::size_t>(map.width) * static_cast<std::size_t>(map.height);
  map.weights.assign(size, {0.0f, 0.0f, 0.0f});
  map.covered.assign(size, 0);
  rasterizeTriangle(setup, 0, trace.height, [&](int py, Span span) {
    const std::size_t row = static_cast<std::size_t>(trace.height - 1 - py - map.y0) * static_cast<std::size_t>(map.width);
    for (int px = span.xBegin; px < span.xEnd; ++px) {
      const PixelWeights w = pixelWeights(interpolation, px, py);
      const std::size_t at = row + static_cast<std::size_t>(px - map.x0);
      map.weights[at] = perspective ? w.perspective : w.screen;
      map.covered[at] = 1;
    }
  });
  return map;
}

// The window corners of the covering fan triangle on the image, weight i's corner i.
std::vector<ImagePoint> weightCornersOf(const PixelTrace& trace, const TriangleVisit& visit) {
  std::vector<ImagePoint> corners;
  for (const WindowVertex& w : visit.window) corners.push_back(imageOf(w.x, w.y, trace));
  return corners;
}

// A world-space point through the camera, the divide and the viewport.
std::optional<ImagePoint> imageOfWorld(const vec3& p, const PixelTrace& trace) {
  const vec4 clip = trace.clipFromWorld * vec4(p, 1.0f);
  if (!(clip.w > 0.0f)) return std::nullopt;
  return imageOfClip(clip, false, trace);
}

// T, B and N as the shading normalised them, and the normal it lit with: in world lighting
// space that normal itself, in tangent space its components along T, B and N (the frame that
// carried the light and eye into tangent space at the corners).
std::vector<ExplorerFrameArrow> frameArrowsOf(const PixelTrace& trace, const TriangleVisit& visit) {
  std::vector<ExplorerFrameArrow> arrows;
  if (visit.outcome != TraceOutcome::Shaded) return arrows;
  const vec3 p = visit.fragment.posWorld;
  const vec4 clip = trace.clipFromWorld * vec4(p, 1.0f);
  const std::optional<ImagePoint> from = imageOfWorld(p, trace);
  if (!from) return arrows;
  const ShadeTerms& s = visit.terms;
  const vec3 lit = trace.lightingSpace == LightingSpace::World ? s.nl : s.t * s.nl.x + s.b * s.nl.y + s.n * s.nl.z;
  const float length = kFrameArrowPerDepth * clip.w;
  const std::pair<char, vec3> axes[] = {{'T', s.t}, {'B', s.b}, {'N', s.n}, {'L', lit}};
  for (const auto& [axis, direction] : axes) {
    const float norm = glm::length(direction);
    if (!(norm > 0.0f)) continue;
    if (const std::optional<ImagePoint> to = imageOfWorld(p + direction * (length / norm), trace)) {
      arrows.push_back({axis, *from, *to});
    }
  }
  return arrows;
}

// NDC past this is left off the plot's bounds (a corner just in front of the eye lands hundreds
// of units out); NDC units.
constexpr double kNdcPlotReach = 3.0;
constexpr double kPlotMargin = 0.1;  // of the plot's extent, on each side

PlotPoint plotPointOf(const vec4& p, ClipPlotAxes axes) {
  switch (axes) {
    case ClipPlotAxes::XW: return {p.x, p.w};
    case ClipPlotAxes::YW: return {p.y, p.w};
    case ClipPlotAxes::ZW: return {p.z, p.w};
    case ClipPlotAxes::Ndc: break;
  }
  return {static_cast<double>(p.x) / p.w, static_cast<double>(p.y) / p.w};
}

// A polygon on the plot; in NDC a vertex with w <= 0 has no place and is counted off it.
std::vector<PlotPoint> plotPointsOf(const std::vector<vec4>& polygon, ClipPlotAxes axes, int& offPlot) {
  std::vector<PlotPoint> points;
  for (const vec4& p : polygon) {
    if (axes == ClipPlotAxes::Ndc && !(p.w > 0.0f)) {
      ++offPlot;
      continue;
    }
    points.push_back(plotPointOf(p, axes));
  }
  return points;
}

// Every point and the origin (NDC: the frustum's square, within kNdcPlotReach), with a margin.
std::array<double, 4> plotBoundsOf(const ClipPlot& plot) {
  const bool ndc = plot.axes == ClipPlotAxes::Ndc;
  std::array<double, 4> b = ndc ? std::array<double, 4>{-1.0, -1.0, 1.0, 1.0} : std::array<double, 4>{0.0, 0.0, 0.0, 0.0};
  for (const auto* list : {&plot.before, &plot.after}) {
    for (const PlotPoint& p : *list) {
      b = {std::min(b[0], p[0]), std::min(b[1], p[1]), std::max(b[2], p[0]), std::max(b[3], p[1])};
    }
  }
  if (ndc) {
    for (double& v : b) v = std::clamp(v, -kNdcPlotReach, kNdcPlotReach);
  }
  const double margin = kPlotMargin * std::max({b[2] - b[0], b[3] - b[1], 1e-3});
  return {b[0] - margin, b[1] - margin, b[2] + margin, b[3] + margin};
}

// The frustum planes that are lines on the plot: a = -w and a = w through the origin, across
// the bounds (and w = kMinClipW when that plane cut); in NDC the square's sides.
// Where a frustum plane cuts: coordinate = factor * w, the factor 1 when the plane is on and the
// guard band's when a side plane is off; none for near and far switched off.
std::optional<double> planeFactorOf(int plane, const ClipConfig& clip) {
  const ClipSwitches& on = clip.frustum;
  switch (plane) {
    case kClipPlaneRight: return on.right ? 1.0 : clip.guardBandX;
    case kClipPlaneLeft: return on.left ? -1.0 : -clip.guardBandX;
    case kClipPlaneTop: return on.top ? 1.0 : clip.guardBandY;
    case kClipPlaneBottom: return on.bottom ? -1.0 : -clip.guardBandY;
    case kClipPlaneFar: return on.far ? std::optional<double>(1.0) : std::nullopt;
    case kClipPlaneNear: return on.near ? std::optional<double>(-1.0) : std::nullopt;
    default: return std::nullopt;
  }
}

bool planeIsOn(int plane, const ClipConfig& clip) {
  const ClipSwitches& on = clip.frustum;
  const bool switches[] = {on.right, on.left, on.top, on.bottom, on.near, on.far};
  return plane >= 0 && plane <= kClipPlaneFar ? switches[plane] : true;
}

// The frustum planes that are lines on the plot: a = factor * w through the origin, across the
// bounds (and w = kMinClipW when near is off); in NDC the square's sides (or the guard band's).
std::vector<ClipPlotLine> planeLinesOf(const ClipPlot& plot, int cuttingPlane, const ClipConfig& clip) {
  std::vector<ClipPlotLine> lines;
  const std::array<double, 4>& b = plot.bounds;
  const bool ndc = plot.axes == ClipPlotAxes::Ndc;
  const auto add = [&](int plane, const std::string& coordinate) {
    const std::optional<double> factor = planeFactorOf(plane, clip);
    if (!factor) return;
    const std::string off = planeIsOn(plane, clip) ? "" : " (off: the guard band)";
    if (ndc) {  // x/w = factor across y/w in [-1, 1], or y/w = factor across x/w
      const bool vertical = coordinate == "x";
      const PlotPoint from = vertical ? PlotPoint{*factor, -1.0} : PlotPoint{-1.0, *factor};
      const PlotPoint to = vertical ? PlotPoint{*factor, 1.0} : PlotPoint{1.0, *factor};
      lines.push_back({std::string(clipPlaneName(plane)) + off + ": " + coordinate + "/w = " + num(*factor), from, to,
                       plane == cuttingPlane});
      return;
    }
    const double reach = std::max({std::abs(b[0]), std::abs(b[1]), std::abs(b[2]), std::abs(b[3])});
    const std::string name = *factor == 1.0 ? "w" : *factor == -1.0 ? "-w" : num(*factor) + " w";
    lines.push_back({std::string(clipPlaneName(plane)) + off + ": " + coordinate + " = " + name,
                     {-reach * *factor, -reach}, {reach * *factor, reach}, plane == cuttingPlane});
  };
  if (ndc || plot.axes == ClipPlotAxes::XW) {
    add(kClipPlaneRight, "x");
    add(kClipPlaneLeft, "x");
  }
  if (ndc || plot.axes == ClipPlotAxes::YW) {
    add(kClipPlaneTop, "y");
    add(kClipPlaneBottom, "y");
  }
  if (plot.axes == ClipPlotAxes::ZW) {
    add(kClipPlaneFar, "z");
    add(kClipPlaneNear, "z");
  }
  if (!ndc && !clip.frustum.near) {
    lines.push_back({std::string(clipPlaneName(kClipPlaneMinW)) + ": w = " + num(kMinClipW) + " (near is off)",
                     {b[0], kMinClipW}, {b[2], kMinClipW}, cuttingPlane == kClipPlaneMinW});
  }
  return lines;
}

// The pass `pass` (or, -1, the triangle and the final polygon) on the plot `axes`.
ClipPlot clipPlotOf(const PixelTrace& trace, const TriangleVisit& visit, int pass, ClipPlotAxes axes) {
  ClipPlot plot;
  plot.axes = axes;
  const bool ndc = axes == ClipPlotAxes::Ndc;
  plot.horizontal = ndc ? "x/w" : axes == ClipPlotAxes::XW ? "x" : axes == ClipPlotAxes::YW ? "y" : "z";
  plot.vertical = ndc ? "y/w" : "w";
  const ClipStep* step = pass >= 0 ? &visit.clipSteps[static_cast<std::size_t>(pass)] : nullptr;
  plot.before = plotPointsOf(step ? step->before : std::vector<vec4>(visit.posClip.begin(), visit.posClip.end()), axes,
                             plot.offPlot);
  int afterOff = 0;  // counted in `before` already: a pass only adds vertices on its plane
  plot.after = plotPointsOf(step ? step->after : visit.clippedPolygon, axes, afterOff);
  if (step) {
    for (const ClipCut& cut : step->cuts) {
      const vec4& p = step->after[static_cast<std::size_t>(cut.index)];
      if (ndc && !(p.w > 0.0f)) continue;
      plot.cuts.push_back(plotPointOf(p, axes));
      plot.cutTs.push_back(cut.t);
    }
  }
  plot.bounds = plotBoundsOf(plot);
  plot.planes = planeLinesOf(plot, step ? step->plane : -1, trace.clip);
  return plot;
}

// Pixels whose centre lies this close to a shared edge are drawn for the fill rule; pixels.
constexpr double kSharedEdgeReach = 2.0;

// A triangle across an edge of the covering fan triangle: its window corners, and the two
// corners of the fan triangle (its setup inputs, 0..2) the edge joins.
struct EdgeCandidate {
  std::string with;
  std::array<WindowVertex, 3> window{};
  std::array<int, 2> mine{};
};

// The other fan triangles of a polygon that share an edge with the covering one.
std::vector<EdgeCandidate> fanCandidatesOf(const PixelTrace& trace, const TriangleVisit& visit) {
  std::vector<EdgeCandidate> candidates;
  const int count = static_cast<int>(visit.clippedPolygon.size());
  const Viewport viewport{trace.width, trace.height};
  for (int k = 0; k + 3 <= count; ++k) {
    if (k + 1 == visit.fanTriangle) continue;
    const std::array<int, 3> corners = fanTriangleCorners(k, true);
    EdgeCandidate c;
    int shared = 0;
    for (int i = 0; i < 3; ++i) {
      const vec4& p = visit.clippedPolygon[static_cast<std::size_t>(corners[static_cast<std::size_t>(i)])];
      c.window[static_cast<std::size_t>(i)] = windowFromClip(p, viewport, isInputCorner(p, visit));
      for (int m = 0; m < 3; ++m) {
        if (visit.fanCorners[static_cast<std::size_t>(m)] == corners[static_cast<std::size_t>(i)] && shared < 2) {
          c.mine[static_cast<std::size_t>(shared++)] = m;
        }
      }
    }
    if (shared != 2) continue;
    c.with = "fan triangle " + std::to_string(k + 1) + " of the same clipped polygon";
    candidates.push_back(c);
  }
  return candidates;
}

bool insideFrustum(const std::array<vec4, 3>& corners) {
  return std::all_of(corners.begin(), corners.end(), [](const vec4& p) {
    return p.w > 0.0f && std::abs(p.x) <= p.w && std::abs(p.y) <= p.w && std::abs(p.z) <= p.w;
  });
}

// The mesh's triangles across the edges of an unclipped triangle, where those are unclipped too.
std::vector<EdgeCandidate> meshCandidatesOf(const PixelTrace& trace, const TriangleVisit& visit) {
  std::vector<EdgeCandidate> candidates;
  if (visit.planesCut != 0 || visit.fanTriangle < 0) return candidates;
  const Viewport viewport{trace.width, trace.height};
  for (const EdgeNeighbour& n : visit.neighbours) {
    if (!insideFrustum(n.posClip)) continue;
    EdgeCandidate c;
    for (std::size_t i = 0; i < 3; ++i) c.window[i] = windowFromClip(n.posClip[i], viewport, true);
    c.mine = n.sharedCorners;  // an unclipped triangle's setup inputs are its corners in order
    c.with = "triangle " + std::to_string(n.triangleId) + " of the mesh";
    candidates.push_back(c);
  }
  return candidates;
}

// Setup's edge between inputs a and b (its corners are reordered clockwise).
const EdgeFunction& edgeBetween(const TriangleSetup& setup, int a, int b) {
  for (std::size_t i = 0; i < 3; ++i) {
    const int from = setup.corner[i], to = setup.corner[(i + 1) % 3];
    if ((from == a && to == b) || (from == b && to == a)) return setup.edges[i];
  }
  return setup.edges[0];
}

// A snapped corner of input `k` on the image, GL window pixels (centres at + 0.5).
std::array<double, 2> snappedWindowOf(const TriangleSetup& setup, int k) {
  for (std::size_t i = 0; i < 3; ++i) {
    if (setup.corner[i] == k) return {setup.xFixed[i] / kFixedOne + 0.5, setup.yFixed[i] / kFixedOne + 0.5};
  }
  return {0.0, 0.0};
}

// Distance of point p from segment a-b and whether p lies beside it (not past either end).
bool besideSegment(const std::array<double, 2>& p, const std::array<double, 2>& a, const std::array<double, 2>& b,
                   double reach) {
  const double dx = b[0] - a[0], dy = b[1] - a[1];
  const double lengthSquared = dx * dx + dy * dy;
  if (!(lengthSquared > 0.0)) return false;
  const double along = ((p[0] - a[0]) * dx + (p[1] - a[1]) * dy) / lengthSquared;
  const double across = std::abs((p[0] - a[0]) * dy - (p[1] - a[1]) * dx) / std::sqrt(lengthSquared);
  return along >= 0.0 && along <= 1.0 && across <= reach;
}

// Who covers each pixel near the shared edge, both triangles set up by the pipeline.
ExplorerSharedEdge sharedEdgeFrom(const PixelTrace& trace, const TriangleSetup& mine, const EdgeCandidate& c,
                                  const TriangleSetup& theirs) {
  ExplorerSharedEdge e;
  e.with = c.with;
  const std::array<double, 2> a = snappedWindowOf(mine, c.mine[0]), b = snappedWindowOf(mine, c.mine[1]);
  e.from = imageOf(a[0], a[1], trace);
  e.to = imageOf(b[0], b[1], trace);
  const EdgeFunction& edge = edgeBetween(mine, c.mine[0], c.mine[1]);
  e.thisOwns = edge.ownsPixelsOnIt;
  const int x0 = std::max(0, static_cast<int>(std::floor(std::min(a[0], b[0]) - kSharedEdgeReach)));
  const int x1 = std::min(trace.width - 1, static_cast<int>(std::ceil(std::max(a[0], b[0]) + kSharedEdgeReach)));
  const int y0 = std::max(0, static_cast<int>(std::floor(std::min(a[1], b[1]) - kSharedEdgeReach)));
  const int y1 = std::min(trace.height - 1, static_cast<int>(std::ceil(std::max(a[1], b[1]) + kSharedEdgeReach)));
  const double dx = b[0] - a[0], dy = b[1] - a[1];
  const double halfWidth = std::abs(dy) > 0.0 ? kSharedEdgeReach * std::hypot(dx, dy) / std::abs(dy) : 0.0;
  for (int py = y0; py <= y1; ++py) {
    // The row's pixels within reach of the line (all of the rectangle's for a horizontal edge).
    int rowX0 = x0, rowX1 = x1;
    if (std::abs(dy) > 0.0) {
      const double crossing = a[0] + (py + 0.5 - a[1]) * dx / dy;  // the line's x at the row's centres
      rowX0 = std::max(x0, static_cast<int>(std::floor(crossing - halfWidth)) - 1);
      rowX1 = std::min(x1, static_cast<int>(std::ceil(crossing + halfWidth)) + 1);
    }
    for (int px = rowX0; px <= rowX1; ++px) {
      if (!besideSegment({px + 0.5, py + 0.5}, a, b, kSharedEdgeReach)) continue;
      const std::array<int, 2> pixel{px, trace.height - 1 - py};
      const bool byMine = coversPixel(mine, px, py), byTheirs = coversPixel(theirs, px, py);
      if (byMine) e.mine.push_back(pixel);
      if (byTheirs) e.theirs.push_back(pixel);
      if (byMine && byTheirs) ++e.both;
      if (edge.at(px, py) - (edge.ownsPixelsOnIt ? 1 : 0) == 0) e.onEdge.push_back(pixel);
    }
  }
  return e;
}

// The shared edge nearest the traced pixel, of the fan's neighbours or the mesh's.
std::optional<ExplorerSharedEdge> sharedEdgeOf(const PixelTrace& trace, const TriangleVisit& visit,
                                               const TriangleSetup& mine) {
  std::vector<EdgeCandidate> candidates = fanCandidatesOf(trace, visit);
  if (candidates.empty()) candidates = meshCandidatesOf(trace, visit);
  const std::array<double, 2> pixel{trace.x + 0.5, trace.yGl + 0.5};
  std::optional<ExplorerSharedEdge> nearest;
  double nearestDistance = 0.0;
  for (const EdgeCandidate& c : candidates) {
    TriangleSetup theirs;
    if (setupTriangle(c.window, CullMode::None, FrontFace::Ccw, Viewport{trace.width, trace.height}, theirs) !=
        SetupResult::Ready) {
      continue;
    }
    const std::array<double, 2> a = snappedWindowOf(mine, c.mine[0]), b = snappedWindowOf(mine, c.mine[1]);
    const double length = std::hypot(b[0] - a[0], b[1] - a[1]);
    const double distance = std::abs((pixel[0] - a[0]) * (b[1] - a[1]) - (pixel[1] - a[1]) * (b[0] - a[0])) / length;
    if (nearest && distance >= nearestDistance) continue;
    nearest = sharedEdgeFrom(trace, mine, c, theirs);
    nearestDistance = distance;
  }
  return nearest;
}

void sharedEdgeLines(const std::optional<ExplorerSharedEdge>& e, std::vector<std::string>& lines) {
  if (!e) {
    lines.push_back("fill rule: no neighbour across an edge to show it on (not a clipped polygon's fan, and no "
                    "unclipped triangle of the mesh shares an edge)");
    return;
  }
  lines.push_back("fill rule at the edge shared with " + e->with + ": within " + num(kSharedEdgeReach) +
                  " px of it this triangle covers " + std::to_string(e->mine.size()) + " pixels, the other " +
                  std::to_string(e->theirs.size()) + ", both " + std::to_string(e->both));
  const std::string owner = e->thisOwns ? "this triangle (the edge is its left or bottom edge)"
                                        : "the other (the edge is this one's right or top edge)";
  lines.push_back(e->onEdge.empty()
                      ? "no pixel centre lies exactly on it, so the rule decides none here; one that did would go to " + owner
                      : std::to_string(e->onEdge.size()) + " pixel centres lie exactly on it (outlined): they go to " + owner);
}

std::array<int, 4> boxOf(const TriangleSetup& s, const PixelTrace& trace) {
  return {s.x0, trace.height - 1 - s.y1, s.x1, trace.height - 1 - s.y0};  // GL rows to top-left rows
}

std::vector<std::array<int, 2>> coveredOf(const std::array<int, 4>& box, const TriangleVisit& visit,
                                          const PixelTrace& trace, const std::vector<std::uint32_t>& ids) {
  std::vector<std::array<int, 2>> covered;
  if (ids.size() != static_cast<std::size_t>(trace.width) * static_cast<std::size_t>(trace.height)) return covered;
  for (int y = std::max(box[1], 0); y <= std::min(box[3], trace.height - 1); ++y) {
    for (int x = std::max(box[0], 0); x <= std::min(box[2], trace.width - 1); ++x) {
      if (ids[static_cast<std::size_t>(y) * static_cast<std::size_t>(trace.width) + static_cast<std::size_t>(x)] ==
          visit.triangleId) {
        covered.push_back({x, y});
      }
    }
  }
  return covered;
}

// The frustum planes a clip position lies outside of (-w <= x, y, z <= w inside), " outside
// right, near" or "" inside.
std::string outsideText(const vec4& p) {
  const std::pair<bool, const char*> sides[] = {{p.x > p.w, "right"}, {p.x < -p.w, "left"}, {p.y > p.w, "top"},
                                                {p.y < -p.w, "bottom"}, {p.z < -p.w, "near"}, {p.z > p.w, "far"}};
  std::string text;
  for (const auto& [outside, name] : sides) {
    if (outside) text += (text.empty() ? " outside " : ", ") + std::string(name);
  }
  return text;
}

void vertexLines(const TriangleVisit& visit, std::vector<std::string>& lines) {
  lines.push_back("triangle " + std::to_string(visit.triangleId) + " of '" + visit.nodeName + "' (" +
                  std::to_string(visit.triangleInMesh) + " in its mesh): the vertex stage's clip positions");
  bool behind = false;
  for (std::size_t i = 0; i < 3; ++i) {
    lines.push_back("v" + std::to_string(i) + " model " + vec(visit.posModel[i], 3) + " -> clip " +
                    vec(visit.posClip[i], 4) + outsideText(visit.posClip[i]));
    behind = behind || !(visit.posClip[i].w > 0.0f);
  }
  if (behind) lines.push_back("a corner with w <= 0 is behind the eye: it has no place on the image until the near plane cuts it");
}

// Each pass's lines; the chosen pass's marked "> ".
void clipLines(const TriangleVisit& visit, int pass, std::vector<std::string>& lines) {
  if (visit.clipSteps.empty()) {
    lines.push_back("no plane cut it: every corner is inside the frustum (or the triangle was rejected whole)");
  }
  for (std::size_t k = 0; k < visit.clipSteps.size(); ++k) {
    const ClipStep& step = visit.clipSteps[k];
    lines.push_back(std::string(static_cast<int>(k) == pass ? "> " : "") + clipPlaneName(step.plane) + ": " +
                    std::to_string(step.before.size()) + " vertices in, " + std::to_string(step.after.size()) + " out");
    if (step.cuts.empty() && !step.after.empty()) {
      lines.push_back("  made no vertex: a corner lay outside it, but an earlier plane had already cut that part away");
    }
    for (const ClipCut& cut : step.cuts) {
      std::string line = "  new vertex " + std::to_string(cut.index) + " on edge " + std::to_string(cut.nearer) + "-" +
                         std::to_string(cut.farther) + " at t " + num(cut.t);
      if (cut.tVaryings != cut.t) line += " (varyings at t " + num(cut.tVaryings) + ")";
      lines.push_back(line);
    }
  }
  lines.push_back("a side plane switched off moves out to a guard band " + num(kGuardBandPixels) +
                  " px beyond the image: the rasterizer keeps to the viewport anyway, so no pixel changes");
}

void divideLines(const PixelTrace& trace, const TriangleVisit& visit, std::vector<std::string>& lines) {
  for (std::size_t k = 0; k < visit.clippedPolygon.size(); ++k) {
    const vec4& p = visit.clippedPolygon[k];
    const WindowVertex w = windowFromClip(p, Viewport{trace.width, trace.height}, isInputCorner(p, visit));
    lines.push_back("p" + std::to_string(k) + " ndc " + vec(vec3(p) / p.w, 3) + " -> window " +
                    vec(vec3(w.x, w.y, w.z), 3));
  }
  if (visit.fanTriangle >= 0) {
    lines.push_back("fan triangle " + std::to_string(visit.fanTriangle) + " covers the pixel: polygon vertices " +
                    std::to_string(visit.fanCorners[0]) + ", " + std::to_string(visit.fanCorners[1]) + ", " +
                    std::to_string(visit.fanCorners[2]) + " in setup's order");
  }
}

void setupLines(const TriangleVisit& visit, const std::optional<TriangleSetup>& setup, const std::array<int, 4>& box,
                std::vector<std::string>& lines) {
  for (std::size_t i = 0; i < 3; ++i) {
    lines.push_back("corner " + std::to_string(i) + " snapped " + std::to_string(visit.xFixed[i]) + ", " +
                    std::to_string(visit.yFixed[i]) + " (1/256 px) = " + num(visit.xFixed[i] / kFixedOne + 0.5) +
                    ", " + num(visit.yFixed[i] / kFixedOne + 0.5) + " px");
  }
  lines.push_back(std::string("faces ") + (visit.frontFacing ? "front" : "back"));
  if (!setup) return;
  lines.push_back("twice the area " + std::to_string(setup->doubleAreaFixed) + " (1/65536 px^2); bounding box x " +
                  std::to_string(box[0]) + ".." + std::to_string(box[2]) + ", y " + std::to_string(box[1]) + ".." +
                  std::to_string(box[3]) + " (from the top)");
  for (std::size_t i = 0; i < 3; ++i) {
    const double normalised =
        static_cast<double>(visit.edgeValue[i]) / static_cast<double>(setup->doubleAreaFixed);
    lines.push_back("edge " + std::to_string(i) + ": E " + std::to_string(visit.edgeValue[i]) + " at the pixel, / area " +
                    num(normalised) + (setup->edges[i].ownsPixelsOnIt ? "; owns pixels on it (left or bottom edge)"
                                                                       : "; leaves pixels on it to its neighbour"));
  }
}

void rasterLines(const TriangleVisit& visit, const ExplorerView& view, int tracedStep, std::vector<std::string>& lines) {
  const ExplorerOverlay& overlay = view.overlay;
  const bool inside = visit.edgeValue[0] > 0 && visit.edgeValue[1] > 0 && visit.edgeValue[2] > 0;
  lines.push_back("the pixel is inside when E > 0 on all three edges (a pixel exactly on an edge goes to its owner): " +
                  std::string(inside ? "inside" : "outside"));
  if (overlay.boundingBox) {
    const auto& b = *overlay.boundingBox;
    const long long boxPixels = static_cast<long long>(b[2] - b[0] + 1) * static_cast<long long>(b[3] - b[1] + 1);
    lines.push_back("won " + std::to_string(overlay.covered.size()) + " of the " + std::to_string(boxPixels) +
                    " pixels of its box in the frame (its triangle id)");
  }
  if (visit.fanTriangle < 0) {
    lines.push_back("no fan triangle covers the pixel after clipping, so there is no visit order to step");
    return;
  }
  lines.push_back("visit order of fan triangle " + std::to_string(visit.fanTriangle) + ": " +
                  std::to_string(view.rasterSteps) + " pixels covered, row by row from the bottom of the image (GL's rows), each row's span left to "
                  "right; the traced pixel is step " + std::to_string(tracedStep));
  if (view.rasterStep >= 0 && overlay.visitPixel && !overlay.visitedRuns.empty()) {
    const auto& run = overlay.visitedRuns.back();
    lines.push_back("> step " + std::to_string(view.rasterStep) + " of " + std::to_string(view.rasterSteps) +
                    ": pixel (" + std::to_string((*overlay.visitPixel)[0]) + ", " +
                    std::to_string((*overlay.visitPixel)[1]) + "), in row " + std::to_string(run[2]) +
                    "'s span from x " + std::to_string(run[0]));
  }
}

void interpolateLines(const TriangleVisit& visit, const ExplorerView& view, std::vector<std::string>& lines) {
  const PixelWeights& w = visit.weights;
  lines.push_back("screen barycentrics " + vec(w.screen, 3));
  lines.push_back("perspective weights " + vec(w.perspective, 3));
  const auto& map = view.overlay.weightMap;
  const long long covered = std::count(map.covered.begin(), map.covered.end(), std::uint8_t{1});
  lines.push_back(std::string("map: the ") + (view.perspectiveMap ? "perspective weights" : "screen barycentrics") +
                  " at each of the " + std::to_string(covered) +
                  " pixels the fan triangle covers, corner 0 red, 1 green, 2 blue");
  lines.push_back("depth " + num(w.depth) + " against " + num(visit.depthBefore) + " stored: " +
                  toString(visit.outcome));
  lines.push_back("uv " + vec(visit.fragment.uv, 2) + ", posWorld " + vec(visit.fragment.posWorld, 3));
}

void shadeLines(const TriangleVisit& visit, std::vector<std::string>& lines) {
  if (visit.outcome != TraceOutcome::Shaded) {
    lines.push_back(std::string("not shaded: ") + toString(visit.outcome));
    return;
  }
  const ShadeTerms& s = visit.terms;
  lines.push_back("T " + vec(s.t, 3) + ", B " + vec(s.b, 3) + " (world)");
  lines.push_back("N " + vec(s.n, 3) + ", Nl " + vec(s.nl, 3));
  if (s.normalTexel != vec4(0.0f)) {
    lines.push_back("normal-map texel " + vec(s.normalTexel, 3) + " -> tangent-space normal " + vec(s.mappedTangent, 3));
  }
  lines.push_back("albedo " + vec(s.albedo, 3) + ", ambient " + vec(s.ambient, 3));
  for (int l = 0; l < s.lightCount; ++l) {
    const LightTerms& t = s.lights[static_cast<std::size_t>(l)];
    lines.push_back("light " + std::to_string(l) + ": N.L " + num(t.nDotL) + ", R.V " + num(t.rDotV) + ", If " +
                    num(t.attenuation) + ", diffuse " + vec(t.diffuse, 3) + ", specular " + vec(t.specular, 3));
  }
  lines.push_back("colour " + vec(s.colour, 4));
}

// Raster: the box, the pixels won in the frame, and the visit order up to the chosen step.
void rasterStage(const PixelTrace& trace, const TriangleVisit& visit, const std::optional<TriangleSetup>& setup,
                 const std::array<int, 4>& box, const std::vector<std::uint32_t>* triangleIds,
                 const ExplorerChoices& choices, ExplorerView& view) {
  ExplorerOverlay& o = view.overlay;
  o.fan = fanOf(polygonOf(trace, visit));
  o.fanTriangle = fanIndexOf(visit);
  int tracedStep = -1;
  if (setup) {
    o.boundingBox = box;
    if (triangleIds) o.covered = coveredOf(box, visit, trace, *triangleIds);
    const std::vector<std::array<int, 3>> runs = visitRunsOf(*setup, trace);
    view.rasterSteps = pixelCount(runs);
    if (choices.rasterStep >= 0 && view.rasterSteps > 0) {
      view.rasterStep = std::min(choices.rasterStep, view.rasterSteps - 1);
      o.visitedRuns = runsUpTo(runs, view.rasterStep);
      o.visitPixel = std::array<int, 2>{o.visitedRuns.back()[1] - 1, o.visitedRuns.back()[2]};
    }
    tracedStep = visitStepOf(trace, visit);
    o.sharedEdge = sharedEdgeOf(trace, visit, *setup);
  }
  rasterLines(visit, view, tracedStep, view.lines);
  sharedEdgeLines(o.sharedEdge, view.lines);
}

}  // namespace

const char* toString(ExplorerStage stage) {
  switch (stage) {
    case ExplorerStage::Vertex: return "vertex";
    case ExplorerStage::Clip: return "clip";
    case ExplorerStage::Divide: return "divide";
    case ExplorerStage::Setup: return "setup";
    case ExplorerStage::Raster: return "raster";
    case ExplorerStage::Interpolate: return "interpolate";
    case ExplorerStage::Shade: return "shade";
  }
  return "";
}

const char* toString(ClipPlotAxes axes) {
  switch (axes) {
    case ClipPlotAxes::XW: return "x-w";
    case ClipPlotAxes::YW: return "y-w";
    case ClipPlotAxes::ZW: return "z-w";
    case ClipPlotAxes::Ndc: return "ndc";
  }
  return "";
}

const char* stageHintOf(ExplorerStage stage) {
  switch (stage) {
    case ExplorerStage::Vertex:
      return "The vertex stage (shaders/phong.vert, softrender/vertex.cpp) takes each corner from model space to "
             "clip space, clip = P V M p. Dots: the corners in front of the eye (w > 0) on the image.";
    case ExplorerStage::Clip:
      return "Sutherland-Hodgman (softrender/clip.cpp), one plane after another: each keeps the part of the polygon "
             "inside it and makes a vertex where an edge crosses it, at t along that edge. Yellow: the triangle; "
             "cyan: the polygon the last plane left.";
    case ExplorerStage::Divide:
      return "The divide (x/w, y/w, z/w: NDC) and the viewport, window = (ndc + 1) / 2 * size (softrender/setup.cpp). "
             "The polygon goes on as a fan from its first vertex; the fan triangle that covers the pixel is filled.";
    case ExplorerStage::Setup:
      return "Setup snaps the corners to 1/256 pixel (orange), orders them clockwise and makes three edge functions "
             "E = c + stepX x + stepY y, positive inside; the box (grey) bounds the pixels to test.";
    case ExplorerStage::Raster:
      return "Every pixel centre in the box is tested: inside when all three E > 0. A pixel exactly on an edge two "
             "triangles share goes to the one for which it is a left or bottom edge (the fill rule), so it is drawn "
             "once. Green: the pixels this triangle won in the frame. Step through the order the rasterizer visits "
             "them in: row by row from the bottom (GL's rows), each row's span left to right. Along the edge it "
             "shares with a neighbour: blue its pixels, orange the neighbour's, outlined the centres exactly on it.";
    case ExplorerStage::Interpolate:
      return "Screen barycentrics are each E over twice the area; the perspective weights divide each by its "
             "corner's w and sum to 1 again (softrender/interpolate.h), so textures do not swim. The map colours each "
             "pixel of the fan triangle by its three weights (corner c0 red, c1 green, c2 blue): the screen ones "
             "are linear on the image; in the perspective ones the nearer corner's colour reaches further.";
    case ExplorerStage::Shade:
      return "Phong at the pixel (shaders/phong.frag, softrender/shade-inl.h): ambient plus each light's diffuse "
             "and specular, with its attenuation If. Arrows at the fragment: T red, B green, N blue, the frame the "
             "normal map is read in, and Nl (white), the normal the lighting used.";
  }
  return "";
}

const char* titleOf(ExplorerStage stage) {
  switch (stage) {
    case ExplorerStage::Vertex: return "Vertex";
    case ExplorerStage::Clip: return "Clip";
    case ExplorerStage::Divide: return "Divide and viewport";
    case ExplorerStage::Setup: return "Setup";
    case ExplorerStage::Raster: return "Raster";
    case ExplorerStage::Interpolate: return "Interpolate";
    case ExplorerStage::Shade: return "Shade";
  }
  return "";
}

ExplorerStage nextStage(ExplorerStage stage) {
  return stage == ExplorerStage::Shade ? stage : static_cast<ExplorerStage>(static_cast<int>(stage) + 1);
}
ExplorerStage previousStage(ExplorerStage stage) {
  return stage == ExplorerStage::Vertex ? stage : static_cast<ExplorerStage>(static_cast<int>(stage) - 1);
}

ExplorerView explorerViewOf(const PixelTrace& trace, const TriangleVisit& visit, ExplorerStage stage,
                            const std::vector<std::uint32_t>* triangleIds, int clipPass) {
  ExplorerChoices choices;
  choices.clipPass = clipPass;
  return explorerViewOf(trace, visit, stage, triangleIds, choices);
}

ExplorerView explorerViewOf(const PixelTrace& trace, const TriangleVisit& visit, ExplorerStage stage,
                            const std::vector<std::uint32_t>* triangleIds, const ExplorerChoices& choices) {
  ExplorerView view;
  view.stage = stage;
  view.clipPasses = static_cast<int>(visit.clipSteps.size());
  view.clipPass = choices.clipPass >= 0 && choices.clipPass < view.clipPasses ? choices.clipPass : -1;
  view.perspectiveMap = choices.perspectiveMap;
  view.title = titleOf(stage);
  ExplorerOverlay& o = view.overlay;
  o.pixelCentre = {trace.x + 0.5, trace.yTop + 0.5};
  const std::optional<TriangleSetup> setup = setupOf(trace, visit);
  const std::array<int, 4> box = setup ? boxOf(*setup, trace) : std::array<int, 4>{};
  const bool stageAfterDivide = stage >= ExplorerStage::Setup;
  switch (stage) {
    case ExplorerStage::Vertex:
      o.triangle = triangleOf(trace, visit);
      vertexLines(visit, view.lines);
      break;
    case ExplorerStage::Clip:
      o.triangle = triangleOf(trace, visit);
      if (view.clipPass >= 0) {
        const ClipStep& step = visit.clipSteps[static_cast<std::size_t>(view.clipPass)];
        o.polygonBefore = polygonOf(trace, visit, step.before);
        o.polygon = polygonOf(trace, visit, step.after);
      } else {
        o.polygon = polygonOf(trace, visit);
      }
      clipLines(visit, view.clipPass, view.lines);
      view.clipPlot = clipPlotOf(trace, visit, view.clipPass, choices.clipAxes);
      break;
    case ExplorerStage::Divide:
      o.polygon = polygonOf(trace, visit);
      o.fan = fanOf(o.polygon);
      o.fanTriangle = fanIndexOf(visit);
      divideLines(trace, visit, view.lines);
      break;
    case ExplorerStage::Setup:
      o.fan = fanOf(polygonOf(trace, visit));
      o.fanTriangle = fanIndexOf(visit);
      if (setup) o.boundingBox = box;
      setupLines(visit, setup, box, view.lines);
      break;
    case ExplorerStage::Raster: rasterStage(trace, visit, setup, box, triangleIds, choices, view); break;
    case ExplorerStage::Interpolate:
      if (setup) {
        o.weightCorners = weightCornersOf(trace, visit);
        o.weightMap = weightMapOf(trace, visit, *setup, choices.perspectiveMap);
      }
      interpolateLines(visit, view, view.lines);
      break;
    case ExplorerStage::Shade:
      o.frameArrows = frameArrowsOf(trace, visit);
      shadeLines(visit, view.lines);
      break;
  }
  if (stageAfterDivide && visit.fanTriangle >= 0) o.snapped = snappedOf(trace, visit);
  return view;
}

std::optional<std::array<int, 2>> visitPixelOf(const PixelTrace& trace, const TriangleVisit& visit, int step) {
  const std::optional<TriangleSetup> setup = setupOf(trace, visit);
  if (!setup || step < 0) return std::nullopt;
  for (const auto& run : visitRunsOf(*setup, trace)) {
    if (step < run[1] - run[0]) return std::array<int, 2>{run[0] + step, run[2]};
    step -= run[1] - run[0];
  }
  return std::nullopt;
}

int visitStepOf(const PixelTrace& trace, const TriangleVisit& visit) {
  const std::optional<TriangleSetup> setup = setupOf(trace, visit);
  if (!setup) return -1;
  int before = 0;
  for (const auto& run : visitRunsOf(*setup, trace)) {
    if (run[2] == trace.yTop && trace.x >= run[0] && trace.x < run[1]) return before + trace.x - run[0];
    before += run[1] - run[0];
  }
  return -1;
}

const TriangleVisit* explorerVisitOf(const PixelTrace& trace, int index) {
  if (index >= 0 && index < static_cast<int>(trace.visits.size())) return &trace.visits[static_cast<std::size_t>(index)];
  return stageVisitOf(trace);
}

std::string visitChoiceText(const PixelTrace& trace, int index) {
  const TriangleVisit* visit = explorerVisitOf(trace, index);
  if (!visit) return "no triangle reaches the pixel";
  const std::size_t k = static_cast<std::size_t>(visit - trace.visits.data());
  return "triangle " + std::to_string(k + 1) + " of " + std::to_string(trace.visits.size()) +
         " reaching the pixel (id " + std::to_string(visit->triangleId) + "): " + toString(visit->outcome);
}

int spanStepFrom(const PixelTrace& trace, const TriangleVisit& visit, int step, int direction) {
  const std::optional<TriangleSetup> setup = setupOf(trace, visit);
  if (!setup) return -1;
  std::vector<int> starts;
  int count = 0;
  for (const auto& run : visitRunsOf(*setup, trace)) {
    starts.push_back(count);
    count += run[1] - run[0];
  }
  if (starts.empty()) return -1;
  if (step < 0) return 0;
  // The span holding the step: the last one starting at or before it.
  const auto holding = std::upper_bound(starts.begin(), starts.end(), step) - 1;
  const auto index = std::clamp<std::ptrdiff_t>(holding - starts.begin() + direction, 0,
                                                static_cast<std::ptrdiff_t>(starts.size()) - 1);
  return starts[static_cast<std::size_t>(index)];
}

std::optional<std::array<float, 3>> weightsAt(const ExplorerWeightMap& map, int x, int yTop) {
  if (x < map.x0 || yTop < map.y0 || x >= map.x0 + map.width || yTop >= map.y0 + map.height) return std::nullopt;
  const std::size_t at = static_cast<std::size_t>(yTop - map.y0) * static_cast<std::size_t>(map.width) +
                         static_cast<std::size_t>(x - map.x0);
  if (!map.covered[at]) return std::nullopt;
  return map.weights[at];
}

Image weightMapImage(const ExplorerWeightMap& map) {
  Image image;
  image.width = map.width;
  image.height = map.height;
  image.rgba.assign(map.weights.size() * 4, 0);
  const auto byte = [](float w) { return static_cast<std::uint8_t>(std::lround(std::clamp(w, 0.0f, 1.0f) * 255.0f)); };
  for (std::size_t i = 0; i < map.weights.size(); ++i) {
    if (!map.covered[i]) continue;
    for (std::size_t c = 0; c < 3; ++c) image.rgba[4 * i + c] = byte(map.weights[i][c]);
    image.rgba[4 * i + 3] = 255;
  }
  return image;
}

nlohmann::json explorerViewToJson(const ExplorerView& view) {
  using nlohmann::json;
  const auto points = [](const std::vector<ImagePoint>& list) {
    json a = json::array();
    for (const ImagePoint& p : list) a.push_back({p.x, p.y});
    return a;
  };
  const ExplorerOverlay& o = view.overlay;
  json fan = json::array();
  for (const auto& t : o.fan) fan.push_back(points({t[0], t[1], t[2]}));
  json overlay = {{"triangle", points(o.triangle)},
                  {"polygon", points(o.polygon)},
                  {"polygon_before", points(o.polygonBefore)},
                  {"fan", fan},
                  {"fan_triangle", o.fanTriangle},
                  {"snapped", points(o.snapped)},
                  {"covered", o.covered.size()},
                  {"pixel_centre", {o.pixelCentre.x, o.pixelCentre.y}}};
  if (o.boundingBox) overlay["bounding_box"] = *o.boundingBox;
  int visited = 0;
  for (const auto& run : o.visitedRuns) visited += run[1] - run[0];
  overlay["visited"] = visited;
  if (o.visitPixel) overlay["visit_pixel"] = *o.visitPixel;
  overlay["weight_corners"] = points(o.weightCorners);
  if (!o.weightMap.covered.empty()) {
    const auto& map = o.weightMap;
    json weightMap = {{"box", {map.x0, map.y0, map.width, map.height}},
                      {"covered", std::count(map.covered.begin(), map.covered.end(), std::uint8_t{1})}};
    if (const std::optional<std::array<float, 3>> w = weightsAt(map, static_cast<int>(o.pixelCentre.x),
                                                                   static_cast<int>(o.pixelCentre.y))) {
      weightMap["at_pixel"] = *w;
    }
    overlay["weight_map"] = weightMap;
  }
  if (o.sharedEdge) {
    const ExplorerSharedEdge& e = *o.sharedEdge;
    overlay["shared_edge"] = {{"with", e.with},
                              {"from", {e.from.x, e.from.y}},
                              {"to", {e.to.x, e.to.y}},
                              {"this_owns", e.thisOwns},
                              {"mine", e.mine.size()},
                              {"theirs", e.theirs.size()},
                              {"on_edge", e.onEdge.size()},
                              {"both", e.both}};
  }
  json frame = json::object();
  for (const ExplorerFrameArrow& a : o.frameArrows) {
    frame[std::string(1, a.axis)] = {{a.from.x, a.from.y}, {a.to.x, a.to.y}};
  }
  overlay["frame"] = frame;
  json result = {{"stage", toString(view.stage)},  {"title", view.title},
                 {"clip_pass", view.clipPass},     {"clip_passes", view.clipPasses},
                 {"raster_step", view.rasterStep}, {"raster_steps", view.rasterSteps},
                 {"weights", view.perspectiveMap ? "perspective" : "screen"},
                 {"lines", view.lines},            {"overlay", overlay}};
  if (view.clipPlot) {
    const ClipPlot& plot = *view.clipPlot;
    json planes = json::array();
    for (const ClipPlotLine& line : plot.planes) {
      planes.push_back({{"name", line.name}, {"from", line.from}, {"to", line.to}, {"cutting", line.cutting}});
    }
    result["clip_plot"] = {{"axes", toString(plot.axes)}, {"before", plot.before}, {"after", plot.after},
                           {"cuts", plot.cuts},           {"cut_t", plot.cutTs},   {"planes", planes},
                           {"bounds", plot.bounds},       {"off_plot", plot.offPlot}};
  }
  return result;
}

}  // namespace twr::gui
