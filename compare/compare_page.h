// One comparison as a page (`compare --html`): DIR/index.html beside the images compare writes,
// with both frames under a split slider, flicker, the heat and class maps, zoom with sharp
// pixels, and a readout of both renderers' RGBA, depth, triangle id and class under the
// pointer; the metrics with their targets and verdicts; a row per compared buffer that opens
// its images. Self-contained (inline style and script, no network) and working from file://.
//
// A page opened from file:// may not read the pixels of its own images (the canvas is
// tainted), so the per-pixel values travel in DIR/pixels.js: the planes zlib-packed and base64
// encoded, unpacked in the browser with DecompressionStream.
#pragma once

#include "compare/metrics.h"

#include <nlohmann/json_fwd.hpp>  // declarations only: json.hpp costs 4 s per source that includes it

#include <cstdint>
#include <string>
#include <vector>

namespace twr {

struct ComparePagePaths {
  std::string page;     // index.html
  std::string pixels;   // pixels.js: window.twrPixels
  std::string heat;     // page_heat.png: the heat map without its legend, exactly the frame's size
  std::string classes;  // page_classes.png: the class map, the same
};

// One plane of pixels.js: its name, element type ("u8", "u32", "f32") and byte range in the
// unpacked data.
struct PixelPlane {
  std::string name;
  std::string type;
  std::size_t offset = 0, bytes = 0;
};

// The unpacked bytes of pixels.js and their planes, in this order: cpu_rgba, gl_rgba (u8, 4 per
// pixel), cpu_depth, gl_depth (f32: 1 where a renderer has no depth buffer), cpu_triangle,
// gl_triangle (u32: kNoTriangle where none), class (u8: PixelClass), diff (u8: levels). Every
// plane is top row first; the four-byte planes come first so each starts 4-byte aligned.
// Multi-byte values are little-endian whatever the host.
struct PixelPlanes {
  std::vector<PixelPlane> planes;
  std::vector<std::uint8_t> bytes;
};
PixelPlanes pixelPlanesOf(const RenderOutput& cpu, const RenderOutput& gl, const PixelAnalysis& pixels);

// The text of pixels.js for those planes.
std::string pixelScript(const PixelPlanes& planes, int width, int height);

// The text of index.html for a comparison whose metrics.json is `metrics` (compare's keys).
std::string comparePageHtml(const nlohmann::json& metrics);

// Writes index.html, pixels.js, page_heat.png and page_classes.png into `dir` (which exists).
// Throws InputError naming a file that cannot be written.
ComparePagePaths writeComparePage(const std::string& dir, const RenderOutput& cpu, const RenderOutput& gl,
                                  const CompareResult& result, const nlohmann::json& metrics);

// The base64 encoding (RFC 4648, with padding) of `bytes`.
std::string base64Of(const std::vector<std::uint8_t>& bytes);

}  // namespace twr
