// Stage pictures: one traced triangle drawn at each stage of the CPU pipeline, from the pixel
// trace's own numbers (softrender/pixel_trace.h), never recomputed: the clipped polygon and
// its fan in normalised device coordinates, the snapped corners over the pixel grid with the
// pixels the triangle won, the pixel's screen and perspective barycentrics, and the Phong
// terms that sum to its colour. `twinraster trace SCENE X Y --stages DIR` writes them, one SVG
// per stage and an index.html, for docs and for students without a display.
#pragma once

#include "scene/renderer.h"
#include "softrender/pixel_trace.h"

#include <cstdint>
#include <string>
#include <vector>

namespace twr {

// The clip planes in `planesCut` by name, "left, near"; "" for none, and what a non-finite
// position did (the trace's mask, clip.h).
std::string clipPlaneNames(std::uint32_t planesCut);

// The visit the pictures follow: the shaded visit that wrote the pixel, else the last shaded
// one, else the first that reached it (culled, clipped away, behind); null when none did.
const TriangleVisit* stageVisitOf(const PixelTrace& trace);

// Clip and divide: the triangle's vertices and its clipped polygon at x/w, y/w, the [-1, 1]
// square, the fan from the polygon's first vertex with the fan triangle that covers the pixel
// filled, and the pixel's centre.
std::string clipStageSvg(const PixelTrace& trace, const TriangleVisit& visit);

// Vertex: each corner's model and clip positions, the frustum planes it lies outside of, and
// the corners in front of the eye (w > 0) at x/w, y/w against the [-1, 1] square.
std::string vertexStageSvg(const PixelTrace& trace, const TriangleVisit& visit);

// Divide and viewport: the clipped polygon in window pixels (GL's, y up) over the image's
// rectangle, its fan with the covering triangle filled, and the pixel's centre.
std::string divideStageSvg(const PixelTrace& trace, const TriangleVisit& visit);

// Setup: the fan triangle's snapped corners over the pixel grid, setup's bounding box, and
// each edge function's edge named with whether it owns the pixel centres on it.
std::string setupStageSvg(const PixelTrace& trace, const TriangleVisit& visit);

// Setup and raster: the fan triangle's snapped corners (1/256 pixel, as setup holds them)
// over the pixel grid around it, the pixels whose id in `triangleIds` (the frame's, top row
// first) is the triangle's, and the traced pixel outlined. At most kStageGridPixels across.
inline constexpr int kStageGridPixels = 40;
std::string rasterStageSvg(const PixelTrace& trace, const TriangleVisit& visit,
                           const std::vector<std::uint32_t>& triangleIds);

// Interpolate: each corner's screen barycentric lambda_i beside its perspective weight p_i.
std::string interpolateStageSvg(const TriangleVisit& visit);

// Shade: per colour channel, the ambient term and each light's diffuse and specular stacked,
// beside the colour written.
std::string shadeStageSvg(const TriangleVisit& visit);

struct StagePicture {
  std::string file;     // "1_clip.svg", relative to the folder
  std::string title;    // "Clip and divide"
  std::string caption;  // what it shows, with the trace's numbers
};

// Writes one picture per stage (0_vertex, 1_clip, 1_divide, 2_setup, 2_raster, 3_interpolate,
// 4_shade .svg) and DIR/index.html listing them in the pipeline's order (DIR created). Throws InputError when the folder
// cannot be written or no triangle reaches the pixel.
std::vector<StagePicture> writeStagePictures(const std::string& dir, const PixelTrace& trace,
                                             const RenderOutput& frame);

}  // namespace twr
