// What a student needs to read the debug views: a legend per view (which colour is which
// axis, how depth maps), a pinned pixel's value decoded only where something was drawn
// (an empty pixel holds the background colour, not a vector), and depth linearised to the
// eye distance, since window depth crowds everything beyond a few near distances into the
// last few levels below white.
#pragma once

#include "gui/pixel_probe.h"
#include "scene/renderer.h"
#include "scene/scene.h"
#include "scene/settings.h"

#include <array>
#include <cstdint>
#include <initializer_list>
#include <optional>
#include <string>

namespace twr::gui {

// One or two sentences: what the colours of `view` mean.
const char* viewLegend(View view);

// The parallax_steps view's colour for t = steps / parallaxStepsMost in [0, 1] (clamped), as
// both renderers draw it (heatColour in shaders/surface_detail.glsl): per channel
// clamp(1.5 - |4 t - c|, 0, 1) with c = 3 (red), 2 (green), 1 (blue), so dark blue at 0, cyan
// at 1/4, green at 1/2, yellow at 3/4, dark red at 1. Linear RGB in [0, 1].
vec3 parallaxStepsColour(float t);
// The step count the parallax_steps view draws red for `material`: parallax_layers' max, plus
// relief_refinement_steps when the method is relief (the shaders' layerCap + refinementSteps).
int parallaxStepsMost(const Material& material);

// The heat ramp's t in [0, 1] a colour shows (parallaxStepsColour inverted), or none when the
// colour is not on the ramp (the env_lod view's dimmed surfaces).
std::optional<float> heatRampFromColour(const std::array<std::uint8_t, 3>& rgb);
// The cube face (kCubeFaceNames) the env_face view's colour stands for, or a note when it is
// none of them.
const char* environmentFaceFromColour(const std::array<std::uint8_t, 3>& rgb);

// True for the views that show a unit vector as (v + 1) / 2.
bool isVectorView(View view);

// Pixel (x, yTop) of `output` (inside it): colour, depth and whether anything was drawn.
PixelSample sampleAt(const RenderOutput& output, PixelPos pixel);

// A pixel read back from `view`: "empty (nothing drawn: background colour)" where nothing was
// drawn, else the value the colour encodes ("vector x y z", "uv u v", "depth d", "rgb r g b").
std::string describeViewSample(View view, const PixelSample& sample);

// Window depth d in [0, 1] back to the eye distance, mapped to [0, 1] between near (0) and
// far (1): z_ndc = 2 d - 1, z_eye = 2 n f / ((f + n) - z_ndc (f - n)). Out-of-range or
// non-finite inputs clamp to [0, 1]; near >= far gives d unchanged.
float linearDepth(float windowDepth, float near, float far);

// Window depth d back to the eye distance along -z, world units: 2 n f / ((f + n) - z_ndc (f - n)).
// Clamped to [near, far]; near >= far gives near.
float eyeDistance(float windowDepth, float near, float far);

// The nearest and farthest eye distance of the drawn pixels (drawnAt), world units.
struct EyeRange {
  float nearest = 0.0f;
  float farthest = 0.0f;
  bool empty() const { return !(farthest > 0.0f) || farthest < nearest; }
};
// Over every output given (both backends, so both images share one mapping); empty when none
// has a drawn pixel.
EyeRange drawnEyeRange(std::initializer_list<const RenderOutput*> outputs, float near, float far);

// The output with its colour replaced by the eye distance as grey, from range.nearest (black)
// to range.farthest (white); pixels where nothing was drawn keep their colour and alpha.
// For the Depth view only: most of a scene sits in a thin slice of window depth, but spreads
// over the whole grey ramp here.
RenderOutput withLinearDepth(const RenderOutput& output, float near, float far, EyeRange range);

}  // namespace twr::gui
