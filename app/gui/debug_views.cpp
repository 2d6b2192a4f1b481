#include "app/gui/debug_views.h"

#include "scene/mip_level_view.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

namespace twr::gui {

const char* viewLegend(View view) {
  switch (view) {
    case View::Shaded:
      return "The lit colour: ambient + diffuse + specular of every light (docs/shading.md).";
    case View::Albedo:
      return "kd times the diffuse map: the surface colour before lighting.";
    case View::Normal:
      return "Interpolated normal N in world space as (N + 1) / 2: red = x, green = y, blue = z. "
             "(128, 255, 128) faces up (+y), (128, 128, 255) faces +z, (255, 128, 128) faces +x.";
    case View::Tangent:
      return "Tangent T in world space as (T + 1) / 2: red = x, green = y, blue = z. It follows the "
             "direction u grows on the surface.";
    case View::Bitangent:
      return "Bitangent B = sign * cross(N, T) in world space as (B + 1) / 2: red = x, green = y, blue = z. It "
             "follows the direction v grows.";
    case View::MappedNormal:
      return "The normal used for lighting (from the normal map when there is one) as (N + 1) / 2: red = x, "
             "green = y, blue = z, in the lighting space chosen above.";
    case View::Uv:
      return "Texture coordinates, fractional part: red = u, green = v (0 black, 1 full). Each repeat of the "
             "texture is one black-to-red-green ramp.";
    case View::Depth:
      return "Window depth d as grey: black 0 at the near plane, white 1 at the far plane. d is 1 / z-like, so "
             "nearly everything beyond a few near distances is almost white; 'linearised' shows the eye "
             "distance instead, from the nearest drawn pixel (black) to the farthest (white).";
    case View::LightTangent:
      return "Direction to light 0 in tangent space as (L + 1) / 2: red = along T, green = along B, blue = along "
             "N. Blue-ish: the light is above the surface. Grey (128, 128, 128): no light.";
    case View::EyeTangent:
      return "Direction to the eye in tangent space as (V + 1) / 2: red = along T, green = along B, blue = "
             "along N. Blue-ish: the surface faces the camera.";
    case View::MipLevel:
      return "The mip level each pixel's texture reads, as the sampler chose it: level 0 blue, 1 cyan, 2 green, 3 "
             "yellow, 4 red, 5 magenta, 6 white, 7 light grey, 8 grey, 9 black, 10 navy, 11 purple, 12 maroon; "
             "trilinear blends neighbours (cyan-green = level 1.5). Nearest and bilinear read level 0 only; "
             "brown surfaces have no map.";
    case View::Height:
      return "The height field's height where the maps are read (after a parallax shift), as grey: black 0 = "
             "the bottom of the relief, white 1 = the top, where the polygon lies. White everywhere: no height "
             "map (docs/parallax.md).";
    case View::ParallaxOffset:
      return "How far a parallax method moved uv: red = 0.5 + 10 du, green = 0.5 + 10 dv (grey: no shift; a "
             "shift of 0.05 uv reaches black or full). Plain parallax's shift grows as 1 / V.z towards grazing "
             "views; offset limiting caps it at the depth.";
    case View::ParallaxSteps:
      return "Layers marched per pixel (steep, relief, occlusion), plus relief's refinement steps, as a heat map: "
             "blue 0, cyan 1/4, green 1/2, yellow 3/4, red = the most (parallax_layers' max + refinement "
             "steps). Grazing views march more.";
    case View::SelfShadow:
      return "How much light 0 reaches the point through the height field: white lit, black in its shadow "
             "(height march or horizon map). White everywhere: self_shadow is none or there is no light.";
  }
  return "";
}

vec3 parallaxStepsColour(float tIn) {
  const float t = std::isnan(tIn) ? 0.0f : std::clamp(tIn, 0.0f, 1.0f);
  const auto channel = [t](float centre) { return std::clamp(1.5f - std::abs(4.0f * t - centre), 0.0f, 1.0f); };
  return {channel(3.0f), channel(2.0f), channel(1.0f)};
}

int parallaxStepsMost(const Material& material) {
  return material.parallaxLayers.y +
         (material.surfaceDetail == SurfaceDetail::Relief ? material.reliefRefinementSteps : 0);
}

bool isVectorView(View view) {
  return view == View::Normal || view == View::Tangent || view == View::Bitangent || view == View::MappedNormal ||
         view == View::LightTangent || view == View::EyeTangent;
}

PixelSample sampleAt(const RenderOutput& output, PixelPos pixel) {
  PixelSample sample;
  const std::size_t i = static_cast<std::size_t>(pixel.yTop) * static_cast<std::size_t>(output.width) +
                        static_cast<std::size_t>(pixel.x);
  for (std::size_t c = 0; c < 4; ++c) sample.rgba[c] = output.rgba[i * 4 + c];
  sample.depth = output.depth[i];
  sample.drawn = drawnAt(output, i);
  return sample;
}

std::string describeViewSample(View view, const PixelSample& sample) {
  if (!sample.drawn) return "empty (nothing drawn: background colour)";
  const auto unit = [&sample](int c) { return static_cast<double>(sample.rgba[static_cast<std::size_t>(c)]) / 255.0; };
  char text[96];
  if (isVectorView(view)) {
    std::snprintf(text, sizeof text, "vector %.2f %.2f %.2f", unit(0) * 2.0 - 1.0, unit(1) * 2.0 - 1.0,
                  unit(2) * 2.0 - 1.0);
  } else if (view == View::MipLevel) {
    const std::optional<float> level = mipLevelFromColour({sample.rgba[0], sample.rgba[1], sample.rgba[2]});
    if (level) {
      std::snprintf(text, sizeof text, "mip level %.2f", static_cast<double>(*level));
    } else {
      std::snprintf(text, sizeof text, "no level colour (no map)");
    }
  } else if (view == View::Uv) {
    std::snprintf(text, sizeof text, "uv %.3f %.3f (fractional part)", unit(0), unit(1));
  } else if (view == View::Depth) {
    std::snprintf(text, sizeof text, "depth %.7f", static_cast<double>(sample.depth));
  } else {
    std::snprintf(text, sizeof text, "rgb %.3f %.3f %.3f", unit(0), unit(1), unit(2));
  }
  return text;
}

float linearDepth(float windowDepth, float near, float far) {
  if (!std::isfinite(windowDepth)) return 1.0f;
  const float d = std::clamp(windowDepth, 0.0f, 1.0f);
  if (!(near > 0.0f) || !(far > near) || !std::isfinite(far)) return d;
  const double n = near, f = far;
  const double zNdc = 2.0 * static_cast<double>(d) - 1.0;
  const double denominator = (f + n) - zNdc * (f - n);  // >= 2 n > 0 for z_ndc in [-1, 1]
  const double zEye = 2.0 * n * f / denominator;
  return static_cast<float>(std::clamp((zEye - n) / (f - n), 0.0, 1.0));
}

float eyeDistance(float windowDepth, float near, float far) {
  if (!(near > 0.0f) || !(far > near) || !std::isfinite(far)) return near;
  return near + linearDepth(windowDepth, near, far) * (far - near);
}

EyeRange drawnEyeRange(std::initializer_list<const RenderOutput*> outputs, float near, float far) {
  EyeRange range{std::numeric_limits<float>::max(), 0.0f};
  bool any = false;
  for (const RenderOutput* output : outputs) {
    if (!output) continue;
    for (std::size_t i = 0; i < output->depth.size() && i * 4 + 3 < output->rgba.size(); ++i) {
      if (!drawnAt(*output, i)) continue;
      const float distance = eyeDistance(output->depth[i], near, far);
      range.nearest = std::min(range.nearest, distance);
      range.farthest = std::max(range.farthest, distance);
      any = true;
    }
  }
  return any ? range : EyeRange{};
}

RenderOutput withLinearDepth(const RenderOutput& output, float near, float far, EyeRange range) {
  RenderOutput out = output;
  const float span = range.farthest - range.nearest;
  const std::size_t count = out.depth.size();
  for (std::size_t i = 0; i < count && i * 4 + 3 < out.rgba.size(); ++i) {
    if (!drawnAt(out, i)) continue;
    const float distance = eyeDistance(out.depth[i], near, far);
    const float shade = span > 0.0f ? std::clamp((distance - range.nearest) / span, 0.0f, 1.0f) : 0.0f;
    const auto grey = static_cast<std::uint8_t>(std::lround(shade * 255.0f));
    out.rgba[i * 4 + 0] = out.rgba[i * 4 + 1] = out.rgba[i * 4 + 2] = grey;
  }
  return out;
}

}  // namespace twr::gui
