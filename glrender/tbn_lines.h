// The TBN debug lines as plain data, shared by both GL drawing paths (immediate mode and
// VBO), so the two modes draw the very same segments.
#pragma once

#include "scene/scene.h"
#include "scene/settings.h"

#include <vector>

namespace twr {

struct TbnLineVertex {
  vec3 posWorld{0.0f};
  vec3 colour{0.0f};  // linear RGB
};

inline constexpr vec3 kTangentLineColour{1.0f, 0.0f, 0.0f};    // T red
inline constexpr vec3 kBitangentLineColour{0.0f, 1.0f, 0.0f};  // B green
inline constexpr vec3 kNormalLineColour{0.0f, 0.0f, 1.0f};     // N blue

// Two vertices per segment. For every mesh vertex, in draw-list and vertex order: N, T, B
// (the CPU's order, so overlapping pixels end up alike),
// each from posWorld to posWorld + lengthWorld * safeNormalize(direction in world space),
// with the directions the vertex stage computes (so tangent_transform applies). Offsetting
// in world space keeps the length in world units under any scale.
std::vector<TbnLineVertex> buildTbnLines(const std::vector<DrawItem>& items, const RenderSettings& settings);

}  // namespace twr
