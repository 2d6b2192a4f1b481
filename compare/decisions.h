// Decisions: where two renderers part because a binary choice went the other way (a shadow
// tap, an SSR march's hit or miss, a parallax march's layer count, the mip level a texel came
// from), not because a colour rounded differently. Each such choice has a debug view that
// shows it per pixel; a differing pixel of the same surface whose decision views differ too is
// class "decision" (PixelClass::Decision, metrics.json's class_decision) instead of "shading".
// The views are drawn only for what the scene turns on, and only when a frame has differing
// pixels of the same surface: a frame that agrees pays nothing.
#pragma once

#include "compare/metrics.h"
#include "scene/renderer.h"
#include "scene/scene.h"

#include <cstdint>
#include <vector>

namespace twr {

// A decision view's pixel differs when a channel differs by more than this (levels,
// exclusive): a decision moves a view's colour by a kernel tap's share or more, a rounding by 1.
inline constexpr int kDecisionViewLevels = 1;

// The views that show the decisions `settings` takes on `scene`, in this order: shadow (the
// first shadowed light's PCF taps and acne), ssr_hit (each pixel's mirror ray), parallax_steps
// (a marching height method's layers), mip_level (a mipmapped filter's level). Empty for a
// debug view's frame, which shows one of these itself.
std::vector<View> decisionViewsFor(const Scene& scene, const RenderSettings& settings);

// One renderer's decision views of a frame: each view's RGBA8 (top row first) and coverage.
struct DecisionViews {
  int width = 0, height = 0;
  std::vector<View> views;
  std::vector<RenderOutput> outputs;  // parallel to views
};

// `renderer` draws `scene` with `settings` in each of `views` (TBN lines off).
DecisionViews renderDecisionViews(Renderer& renderer, const Scene& scene, const RenderSettings& settings,
                                  const std::vector<View>& views, int width, int height);

// Whether some decision view differs at pixel i (top row first): one side covers it and the
// other not, or a colour channel differs by more than kDecisionViewLevels. Throws InputError
// when the two were drawn at other sizes or in other views, an image is missing or of another
// size, or i lies outside them.
bool decisionDiffersAt(const DecisionViews& cpu, const DecisionViews& gl, std::size_t i);

// Moves every Shading pixel of `result` whose decision views differ to Decision, and its count
// from classShading to classDecision. Returns how many moved. Throws InputError as
// decisionDiffersAt does, or when the views are not of the frame's size.
std::uint64_t classifyDecisions(CompareResult& result, const DecisionViews& cpu, const DecisionViews& gl);

}  // namespace twr
