#include "gui/debug_views.h"

#include "scene/environment.h"
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
    case View::ReflectDir:
      return "The reflected direction the environment is read in, world space, as (R + 1) / 2: red = x, green = "
             "y, blue = z; on the sky box, the view direction. Surfaces that read no reflection are dimmed to grey "
             "(docs/environment.md).";
    case View::EnvFace:
      return "Which cube face the reflection reads: +X red, -X dark red, +Y green, -Y dark green, +Z blue, -Z dark "
             "blue (the face is the direction's largest component, GL's table); under a sphere or dual-paraboloid "
             "map, the hemisphere instead (+Z blue, -Z dark blue). The sky box shows its own faces.";
    case View::EnvLod:
      return "The LOD the reflection is read at, as a heat map from 0 (dark blue) to 10 (dark red): a mirror's "
             "from its direction's differences across the 2x2 quad (curved or bumpy surfaces read blurrier "
             "levels), a prefiltered reflection's from the shininess.";
    case View::Shadow:
      return "The first shadowed light's shadow-map test: warm white lit, blue in its shadow (PCF blends the two), "
             "magenta acne (the surface shadows itself: raise the bias), grey turned away from the light. Dimmed "
             "to grey when no light has a shadow map (docs/shadows.md).";
    case View::LightDepth:
      return "The first shadowed light's map depth where each pixel falls, as grey (0 black, 1 white): what the "
             "light sees there. Dark red outside the map; dimmed when no light has a shadow map.";
    case View::SsrHit:
      return "How each pixel's mirror ray ended with the chosen march (docs/ssr.md): green hit, blue miss (out of "
             "steps or at the ray's end), yellow off screen, red behind a surface by more than the thickness. "
             "Every drawn pixel is marched, whatever its ssr reflect.";
    case View::SsrSteps:
      return "The steps each pixel's mirror ray took, as a heat map from 0 (dark blue) to max steps (dark red).";
    case View::SsrUv:
      return "Where each pixel's mirror ray hit, as screen coordinates: red = x, green = y (0 at the left and "
             "bottom, 1 at the right and top); black where it did not hit.";
    case View::HizLevel:
      return "The highest Hi-Z level each pixel's mirror ray skipped a cell at, as a heat map from 0 (dark blue: "
             "pixel by pixel) to the chain's top (dark red). Black under the other marches.";
    case View::Ambient:
      return "The ambient term alone, ka times albedo times the scene's ambient Ia (docs/shading.md): what a "
             "surface shows with every light off. No environment and no sky.";
    case View::Diffuse:
      return "The diffuse term alone, kd albedo max(N.L, 0) Id summed over the lights, each with its "
             "attenuation and shadow: Lambert's light, the same from every viewpoint. No environment and no sky.";
    case View::Specular:
      return "The specular term alone, ks specScale pow(R.V, shininess) Is summed over the lights, each with its "
             "attenuation and shadow: the highlights, which move with the eye. No environment and no sky.";
  }
  return "";
}

vec3 parallaxStepsColour(float tIn) {
  const float t = std::isnan(tIn) ? 0.0f : std::clamp(tIn, 0.0f, 1.0f);
  const auto channel = [t](float centre) { return std::clamp(1.5f - std::abs(4.0f * t - centre), 0.0f, 1.0f); };
  return {channel(3.0f), channel(2.0f), channel(1.0f)};
}

std::optional<float> heatRampFromColour(const std::array<std::uint8_t, 3>& rgb) {
  // The ramp is continuous and one-to-one: the nearest of 1001 samples, if it is near at all.
  float best = 0.0f, bestDistance = std::numeric_limits<float>::max();
  for (int i = 0; i <= 1000; ++i) {
    const float t = static_cast<float>(i) / 1000.0f;
    const vec3 c = parallaxStepsColour(t) * 255.0f;
    const float d = std::abs(c.r - rgb[0]) + std::abs(c.g - rgb[1]) + std::abs(c.b - rgb[2]);
    if (d < bestDistance) {
      bestDistance = d;
      best = t;
    }
  }
  constexpr float kMaxLevelsOff = 6.0f;  // the sum of three channels' rounding and a level of disagreement
  if (bestDistance > kMaxLevelsOff) return std::nullopt;
  return best;
}

const char* environmentFaceFromColour(const std::array<std::uint8_t, 3>& rgb) {
  int best = 0;
  float bestDistance = std::numeric_limits<float>::max();
  for (int f = 0; f < kCubeFaces; ++f) {
    float d = 0.0f;
    for (int c = 0; c < 3; ++c) d += std::abs(kCubeFaceViewColours[f][c] * 255.0f - static_cast<float>(rgb[static_cast<std::size_t>(c)]));
    if (d < bestDistance) {
      bestDistance = d;
      best = f;
    }
  }
  constexpr float kMaxLevelsOff = 6.0f;
  return bestDistance <= kMaxLevelsOff ? kCubeFaceNames[best] : "none (dimmed: no reflection read)";
}

int parallaxStepsMost(const Material& material) {
  return material.parallaxLayers.y +
         (material.surfaceDetail == SurfaceDetail::Relief ? material.reliefRefinementSteps : 0);
}

bool isVectorView(View view) {
  return view == View::Normal || view == View::Tangent || view == View::Bitangent || view == View::MappedNormal ||
         view == View::LightTangent || view == View::EyeTangent || view == View::ReflectDir;
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
  } else if (view == View::EnvFace) {
    std::snprintf(text, sizeof text, "face %s", environmentFaceFromColour({sample.rgba[0], sample.rgba[1], sample.rgba[2]}));
  } else if (view == View::EnvLod) {
    const std::optional<float> t = heatRampFromColour({sample.rgba[0], sample.rgba[1], sample.rgba[2]});
    if (t) {
      std::snprintf(text, sizeof text, "LOD %.2f", static_cast<double>(*t * kEnvironmentLodViewMax));
    } else {
      std::snprintf(text, sizeof text, "no LOD colour (dimmed: no reflection read)");
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
