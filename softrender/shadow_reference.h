// Shadow maps against the truth (docs/shadows.md, "Against a ray tracer"): for every pixel of a
// frame that shows a surface turned towards a light, the light's visibility from that surface
// point traced against the scene's own triangles in double (scene/triangle_bvh.h), beside the
// visibility the light's shadow map gives the same point (shadow-inl.h in double). Only the
// map's shortcut is measured: the point, its normal and the map are the same on both sides.
#pragma once

#include "scene/renderer.h"
#include "scene/triangle_bvh.h"

#include <cstdint>
#include <vector>

namespace twr {

struct ShadowVisibility {
  int width = 0, height = 0;
  // Per pixel, top row first: the traced visibility (0 or 1) and the map's ([0, 1]); NaN where
  // the pixel shows no surface or one turned away from the light (neither side lights it).
  std::vector<double> traced, map;
  std::uint64_t measured = 0;        // pixels with both values
  std::uint64_t tracedShadowed = 0;  // of those, in the traced shadow
  std::uint64_t wrong = 0;           // |map - traced| > 0.5: the map's answer is the other one
  std::uint64_t partial = 0;         // 0 < map < 1 (a PCF edge)
  double meanAbsError = 0.0;         // mean |map - traced| over the measured pixels
  double wrongPercent() const { return measured ? 100.0 * static_cast<double>(wrong) / static_cast<double>(measured) : 0.0; }
};

// `frame` is a render of `scene` (its triangle ids and shadow maps are read); `light` indexes
// scene.lights and must have a map in frame.shadowMaps. The surface point of a pixel is where
// the ray through its centre meets the plane of the triangle the frame shows there, in double.
// Throws InputError when the light has no map in the frame.
ShadowVisibility measureShadowVisibility(const Scene& scene, std::size_t light, const RenderOutput& frame,
                                         const TriangleBvh& bvh);

}  // namespace twr
