// The stage explorer: one traced triangle stepped through the CPU pipeline's stages, vertex to
// shade, as the inspector shows it and draws it over both images. Everything it shows is the
// pixel trace's own (softrender/pixel_trace.h): its numbers as the trace holds them, its
// positions through the pipeline's own functions (windowFromClip, setupSnappedTriangle),
// never a formula of the UI's. No drawing here: the app draws the overlay, tests read it.
#pragma once

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
// The stage after and before, the ends held.
ExplorerStage nextStage(ExplorerStage stage);
ExplorerStage previousStage(ExplorerStage stage);

// A place on the image in pixels from the left and from the top (the PNGs' convention; a pixel
// centre at +0.5), so the app scales it onto each image however large it shows it.
struct ImagePoint {
  double x = 0.0, y = 0.0;
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
  ImagePoint pixelCentre;  // the traced pixel's centre
};

struct ExplorerView {
  ExplorerStage stage = ExplorerStage::Vertex;
  int clipPass = -1;    // the clipper's pass shown at the Clip stage, -1: all of them
  int clipPasses = 0;   // how many passes the clipper made
  std::string title;
  std::vector<std::string> lines;  // the stage's numbers, as the trace holds them
  ExplorerOverlay overlay;
};

// The stage's lines and overlay for `visit`, one of `trace`'s visits. `triangleIds`: the
// frame's ids (RenderOutput::triangleId, top row first, trace.width x trace.height), or null.
// `clipPass`: at the Clip stage, the clipper's pass k (visit.clipSteps[k]) to draw before and
// after, its lines marked; -1 (or a pass the triangle does not have): the final polygon.
ExplorerView explorerViewOf(const PixelTrace& trace, const TriangleVisit& visit, ExplorerStage stage,
                            const std::vector<std::uint32_t>* triangleIds, int clipPass = -1);

// The view as the scripted tests read it from the app's test state: {"stage", "title",
// "clip_pass", "clip_passes", "lines", "overlay": {"triangle": [[x, y], ...], "polygon",
// "polygon_before", "fan", "fan_triangle", "snapped",
// "bounding_box": [x0, y0, x1, y1], "covered" (a count), "pixel_centre"}}.
nlohmann::json explorerViewToJson(const ExplorerView& view);

}  // namespace twr::gui
