#include "gui/stage_explorer.h"

#include "softrender/clip.h"
#include "softrender/setup.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdio>
#include <iterator>

namespace twr::gui {

namespace {

constexpr double kFixedOne = 256.0;  // setup's sub-pixel steps per pixel (8 bits)

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

// Setup run again on the trace's snapped corners: its box and edge functions.
std::optional<TriangleSetup> setupOf(const PixelTrace& trace, const TriangleVisit& visit) {
  if (visit.fanTriangle < 0) return std::nullopt;
  TriangleSetup setup;
  if (setupSnappedTriangle(visit.xFixed, visit.yFixed, CullMode::None, FrontFace::Ccw,
                           Viewport{trace.width, trace.height}, setup) != SetupResult::Ready) {
    return std::nullopt;
  }
  return setup;
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

void rasterLines(const TriangleVisit& visit, const ExplorerOverlay& overlay, std::vector<std::string>& lines) {
  const bool inside = visit.edgeValue[0] > 0 && visit.edgeValue[1] > 0 && visit.edgeValue[2] > 0;
  lines.push_back("the pixel is inside when E > 0 on all three edges (a pixel exactly on an edge goes to its owner): " +
                  std::string(inside ? "inside" : "outside"));
  if (overlay.boundingBox) {
    const auto& b = *overlay.boundingBox;
    const long long boxPixels = static_cast<long long>(b[2] - b[0] + 1) * static_cast<long long>(b[3] - b[1] + 1);
    lines.push_back("won " + std::to_string(overlay.covered.size()) + " of the " + std::to_string(boxPixels) +
                    " pixels of its box in the frame (its triangle id)");
  }
}

void interpolateLines(const TriangleVisit& visit, std::vector<std::string>& lines) {
  const PixelWeights& w = visit.weights;
  lines.push_back("screen barycentrics " + vec(w.screen, 3));
  lines.push_back("perspective weights " + vec(w.perspective, 3));
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
  lines.push_back("N " + vec(s.n, 3) + ", Nl " + vec(s.nl, 3));
  lines.push_back("albedo " + vec(s.albedo, 3) + ", ambient " + vec(s.ambient, 3));
  for (int l = 0; l < s.lightCount; ++l) {
    const LightTerms& t = s.lights[static_cast<std::size_t>(l)];
    lines.push_back("light " + std::to_string(l) + ": N.L " + num(t.nDotL) + ", R.V " + num(t.rDotV) + ", If " +
                    num(t.attenuation) + ", diffuse " + vec(t.diffuse, 3) + ", specular " + vec(t.specular, 3));
  }
  lines.push_back("colour " + vec(s.colour, 4));
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
  ExplorerView view;
  view.stage = stage;
  view.clipPasses = static_cast<int>(visit.clipSteps.size());
  view.clipPass = clipPass >= 0 && clipPass < view.clipPasses ? clipPass : -1;
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
      break;
    case ExplorerStage::Divide:
      o.polygon = polygonOf(trace, visit);
      o.fan = fanOf(o.polygon);
      o.fanTriangle = fanIndexOf(visit);
      divideLines(trace, visit, view.lines);
      break;
    case ExplorerStage::Setup:
    case ExplorerStage::Raster:
      o.fan = fanOf(polygonOf(trace, visit));
      o.fanTriangle = fanIndexOf(visit);
      if (setup) o.boundingBox = box;
      if (stage == ExplorerStage::Raster && setup && triangleIds) o.covered = coveredOf(box, visit, trace, *triangleIds);
      if (stage == ExplorerStage::Setup) setupLines(visit, setup, box, view.lines);
      else rasterLines(visit, o, view.lines);
      break;
    case ExplorerStage::Interpolate: interpolateLines(visit, view.lines); break;
    case ExplorerStage::Shade: shadeLines(visit, view.lines); break;
  }
  if (stageAfterDivide && visit.fanTriangle >= 0) o.snapped = snappedOf(trace, visit);
  return view;
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
  return {{"stage", toString(view.stage)}, {"title", view.title},   {"clip_pass", view.clipPass},
          {"clip_passes", view.clipPasses},  {"lines", view.lines}, {"overlay", overlay}};
}

}  // namespace twr::gui
