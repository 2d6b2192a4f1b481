// The stage explorer: one traced triangle stepped through the CPU pipeline's stages, vertex to
// shade, as the inspector shows it and draws it over both images. Everything it shows is the
// pixel trace's own (softrender/pixel_trace.h): its numbers as the trace holds them, its
// positions through the pipeline's own functions (windowFromClip, setupSnappedTriangle),
// never a formula of the UI's. No drawing here: the app draws the overlay, tests read it.
#pragma once

#include "scene/image.h"
#include "softrender/pixel_trace.h"

#include <nlohmann/json_fwd.hpp>

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace twr::gui {

enum class ExplorerStage { Vertex, Clip, Divide, Setup, Raster, Interpolate, Shade };
inline constexpr ExplorerStage kExplorerStages[] = {ExplorerStage::Vertex,      ExplorerStage::Clip,
                                                    ExplorerStage::Divide,      ExplorerStage::Setup,
                                                    ExplorerStage::Raster,      ExplorerStage::Interpolate,
                                                    ExplorerStage::Shade};
const char* toString(ExplorerStage stage);  // "vertex", "clip", ... (the probe's and the tests' names)
const char* titleOf(ExplorerStage stage);   // "Vertex", "Clip", "Divide and viewport", ...
// What the stage does and what its drawing's colours mean, for the student reading its numbers.
const char* stageHintOf(ExplorerStage stage);
// The stage after and before, the ends held.
ExplorerStage nextStage(ExplorerStage stage);
ExplorerStage previousStage(ExplorerStage stage);

// A place on the image in pixels from the left and from the top (the PNGs' convention; a pixel
// centre at +0.5), so the app scales it onto each image however large it shows it.
struct ImagePoint {
  double x = 0.0, y = 0.0;
};

// Interpolate's map: one fan triangle's weights at every pixel it covers.
struct ExplorerWeightMap {
  int x0 = 0, y0 = 0, width = 0, height = 0;  // setup's box, top-left pixels; row y0 first
  std::vector<std::array<float, 3>> weights;  // width x height; the weights where covered
  std::vector<std::uint8_t> covered;          // 1 where the fan triangle covers the pixel
};
// The weights at pixel (x, yTop) of the image; none where the triangle does not cover it.
std::optional<std::array<float, 3>> weightsAt(const ExplorerWeightMap& map, int x, int yTop);
// The map as a picture of its box: weight i in channel i (corner 0 red, 1 green, 2 blue),
// transparent where the triangle does not cover the pixel.
Image weightMapImage(const ExplorerWeightMap& map);

// The fill rule at an edge the covering fan triangle shares with a neighbour: the next fan
// triangle of its clipped polygon, or (unclipped) the mesh's triangle across that edge, the
// one nearest the pixel. Both are set up by the pipeline; the pixels near the edge each covers.
struct ExplorerSharedEdge {
  std::string with;             // "fan triangle 2 of the same polygon", "triangle 1506 of the mesh"
  ImagePoint from, to;          // the edge on the image (snapped corners)
  bool thisOwns = false;        // the traced triangle takes the pixel centres exactly on it
  std::vector<std::array<int, 2>> mine, theirs;  // pixels within reach of the edge each covers (top-left)
  std::vector<std::array<int, 2>> onEdge;        // pixel centres exactly on the edge
  int both = 0;                                  // pixels both cover (the rule leaves none)
};

struct ExplorerFrameArrow {
  char axis = 'N';  // 'T', 'B', 'N' or 'L' (the normal the lighting used)
  ImagePoint from, to;
};

// The Clip stage's plot of a pass: one clip coordinate against w, where a side plane is a line
// through the origin (x = w, x = -w) and the clipper's cut is where an edge crosses it; or
// x/w against y/w (NDC), where the frustum is the square [-1, 1]^2 (vertices in front of the
// eye only).
enum class ClipPlotAxes { XW, YW, ZW, Ndc };
inline constexpr ClipPlotAxes kClipPlotAxes[] = {ClipPlotAxes::XW, ClipPlotAxes::YW, ClipPlotAxes::ZW, ClipPlotAxes::Ndc};
const char* toString(ClipPlotAxes axes);  // "x-w", "y-w", "z-w", "ndc"

using PlotPoint = std::array<double, 2>;  // horizontal, vertical (up)
struct ClipPlotLine {
  std::string name;  // the plane, "right: x = w"
  PlotPoint from, to;
  bool cutting = false;  // the plane of the pass shown
};
struct ClipPlot {
  ClipPlotAxes axes = ClipPlotAxes::XW;
  std::string horizontal, vertical;       // the axes' names: "x" and "w", or "x/w" and "y/w"
  std::vector<PlotPoint> before, after;   // the polygon the pass cut and what it left (all passes:
                                          // the triangle and the final polygon)
  std::vector<PlotPoint> cuts;            // the vertices the pass made
  std::vector<float> cutTs;               // ... and each one's t along its edge
  std::vector<ClipPlotLine> planes;       // the frustum planes that are lines in this plot
  std::array<double, 4> bounds{};         // what to show: min h, min v, max h, max v
  int offPlot = 0;                        // NDC: the vertices of `before` left out (w <= 0)
};

// What the stage draws over the images; empty parts are not drawn.
struct ExplorerOverlay {
  // The input triangle's corners through the divide and viewport, where w > 0 (a corner
  // behind the eye has no place on the image); all three: its outline is drawn.
  std::vector<ImagePoint> triangle;
  std::vector<ImagePoint> polygon;                // the clipped polygon (Clip and after)
  // At the Clip stage with one pass chosen: the polygon that plane cut, `polygon` being what it
  // left (vertices with w <= 0 have no place on the image and are left out of both).
  std::vector<ImagePoint> polygonBefore;
  std::vector<std::array<ImagePoint, 3>> fan;     // its fan (0, i, i + 1) (Divide and after)
  int fanTriangle = -1;  // fan[fanTriangle] covers the pixel (the trace's fan triangle i is fan[i - 1])
  std::vector<ImagePoint> snapped;                // its corners as setup snapped them (Setup and after)
  // Setup's bounding box, inclusive pixels from the top-left: x0, y0, x1, y1 (Setup, Raster).
  std::optional<std::array<int, 4>> boundingBox;
  // The pixels the triangle won in the frame (its id in the frame's triangle ids), top-left
  // coordinates, inside the bounding box (Raster).
  std::vector<std::array<int, 2>> covered;
  std::optional<ExplorerSharedEdge> sharedEdge;  // Raster: the fill rule where it shares an edge
  // Raster with a step of the visit order chosen: the pixels the rasterizer had visited by then,
  // in its order, as runs along a row {x begin, x end (exclusive), y from the top}, and the
  // pixel of that step (the last run's last pixel).
  std::vector<std::array<int, 3>> visitedRuns;
  std::optional<std::array<int, 2>> visitPixel;
  // Interpolate: the covering fan triangle's corners in the order its weights are listed
  // (corner i is weight i: red, green, blue), and the map of those weights over its pixels.
  std::vector<ImagePoint> weightCorners;
  ExplorerWeightMap weightMap;
  // Shade: the surface frame at the fragment, T, B, N and the normal lighting used (its
  // direction in world space), each an arrow from the fragment's position on the image.
  std::vector<ExplorerFrameArrow> frameArrows;
  ImagePoint pixelCentre;  // the traced pixel's centre
};

// What the reader chose beside the stage.
struct ExplorerChoices {
  int clipPass = -1;    // the clipper's pass the Clip stage draws, -1: the final polygon
  int rasterStep = -1;  // the Raster stage's step of the visit order (0: the first pixel), -1: none
  bool perspectiveMap = false;  // Interpolate maps the perspective weights, else the screen barycentrics
  ClipPlotAxes clipAxes = ClipPlotAxes::XW;  // the Clip stage's plot
};

struct ExplorerView {
  ExplorerStage stage = ExplorerStage::Vertex;
  int clipPass = -1;    // the clipper's pass shown at the Clip stage, -1: all of them
  int clipPasses = 0;   // how many passes the clipper made
  int rasterStep = -1;  // the visit order's step shown at the Raster stage, -1: none
  std::optional<ClipPlot> clipPlot;  // the Clip stage's plot of the pass shown
  int rasterSteps = 0;  // how many pixels the rasterizer visits (covers) for the fan triangle
  bool perspectiveMap = false;
  std::string title;
  std::vector<std::string> lines;  // the stage's numbers, as the trace holds them
  ExplorerOverlay overlay;
};

// The visit the explorer follows: the trace's visit `index` (its triangles in draw order) where
// there is one, else the pictures' (stageVisitOf: the one that wrote the pixel); null when no
// triangle reaches the pixel.
const TriangleVisit* explorerVisitOf(const PixelTrace& trace, int index);
// "triangle 2 of 3 reaching the pixel: failed the depth test" for the visit `explorerVisitOf` gives.
std::string visitChoiceText(const PixelTrace& trace, int index);

// The stage's lines and overlay for `visit`, one of `trace`'s visits. `triangleIds`: the
// frame's ids (RenderOutput::triangleId, top row first, trace.width x trace.height), or null.
// `clipPass`: at the Clip stage, the clipper's pass k (visit.clipSteps[k]) to draw before and
// after, its lines marked; -1 (or a pass the triangle does not have): the final polygon.
ExplorerView explorerViewOf(const PixelTrace& trace, const TriangleVisit& visit, ExplorerStage stage,
                            const std::vector<std::uint32_t>* triangleIds, int clipPass = -1);
// The same with every choice: `choices.rasterStep` past the last pixel shows the last one.
ExplorerView explorerViewOf(const PixelTrace& trace, const TriangleVisit& visit, ExplorerStage stage,
                            const std::vector<std::uint32_t>* triangleIds, const ExplorerChoices& choices);

// The pixel the rasterizer visits at `step` of the fan triangle that covers the traced pixel
// (rows from the bottom in GL's order, each row's span left to right), top-left coordinates;
// none past the end. The step of the traced pixel itself is visitStepOf.
std::optional<std::array<int, 2>> visitPixelOf(const PixelTrace& trace, const TriangleVisit& visit, int step);
int visitStepOf(const PixelTrace& trace, const TriangleVisit& visit);  // -1: not covered
// Stepping the visit order a span at a time: the first pixel of the span after (direction +1)
// or before (-1) the one holding `step`, the ends held; from no step (-1), the first span.
int spanStepFrom(const PixelTrace& trace, const TriangleVisit& visit, int step, int direction);

// The view as the scripted tests read it from the app's test state: {"stage", "title",
// "clip_pass", "clip_passes", "lines", "overlay": {"triangle": [[x, y], ...], "polygon",
// "polygon_before", "fan", "fan_triangle", "snapped",
// "bounding_box": [x0, y0, x1, y1], "covered" (a count), "pixel_centre", "visited" (a count),
// "visit_pixel": [x, y], "weight_corners", "weight_map": {"box": [x0, y0, width, height],
// "covered" (a count), "at_pixel": [w0, w1, w2]}, "frame": {"T": [[x, y], [x, y]], ...}},
// "shared_edge": {"with", "from", "to", "this_owns", "mine", "theirs", "on_edge", "both"} (counts),
// "raster_step", "raster_steps", "weights": "screen" or "perspective", "clip_plot" (the Clip
// stage): {"axes", "before", "after", "cuts", "cut_t", "planes": [{"name", "from", "to",
// "cutting"}], "bounds", "off_plot"}}.
nlohmann::json explorerViewToJson(const ExplorerView& view);

}  // namespace twr::gui
