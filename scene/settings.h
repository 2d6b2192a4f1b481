// Render settings: plain structs the scene file fills, the UI edits, both renderers read.
#pragma once

#include "scene/conventions.h"

#include <string>
#include <string_view>
#include <vector>

namespace twr {

enum class CullMode { None, Back, Front };
enum class FrontFace { Ccw, Cw };
// MipLevel: which mip level the sampler reads, as colours (scene/mip_level_view.h); both
// renderers draw it as the albedo of a stand-in texture, so no shader has a case for it.
// Height, ParallaxOffset, ParallaxSteps, SelfShadow: the height-field views (docs/parallax.md).
// Ambient, Diffuse, Specular: Phong's terms one at a time (isPhongTermView).
enum class View {
  Shaded, Albedo, Normal, Tangent, Bitangent, MappedNormal, Uv, Depth, LightTangent, EyeTangent, MipLevel,
  Height, ParallaxOffset, ParallaxSteps, SelfShadow, ReflectDir, EnvFace, EnvLod, Shadow, LightDepth,
  SsrHit, SsrSteps, SsrUv, HizLevel, Ambient, Diffuse, Specular
};
// Whether the view shows a height-field quantity (drawn only where a material has a height map).
constexpr bool isHeightView(View v) {
  return v == View::Height || v == View::ParallaxOffset || v == View::ParallaxSteps || v == View::SelfShadow;
}

// Whether the view shows what the environment is read with (docs/environment.md, "Debug
// views"): the reflected direction, the cube face (or hemisphere) it lands on, the LOD it is
// read at. Drawn by the shaded permutation with the environment's value in place of the
// colour, on the surfaces that read a reflection or refraction and on the sky box; other
// surfaces are shown dimmed to grey.
constexpr bool isEnvironmentView(View v) { return v == View::ReflectDir || v == View::EnvFace || v == View::EnvLod; }
// Whether the view shows the first shadowed light's shadow-map test (docs/shadows.md): shadow
// (lit, in shadow, acne, turned away) and light_depth (the map's depth where the fragment
// falls). Drawn by the shaded permutation like the environment views; without a shadowed
// light every surface is shown dimmed to grey.
constexpr bool isShadowView(View v) { return v == View::Shadow || v == View::LightDepth; }
// Whether the view shows each pixel's screen-space reflection march (docs/ssr.md, "Debug
// views"): ssr_hit (how it ended), ssr_steps (its steps), ssr_uv (where it hit), hiz_level (the
// highest Hi-Z level it used). The frame draws deferred and shaded, then the reflection pass
// marches every drawn pixel's mirror ray (whatever ssr.enabled and ssr_reflect say) and writes
// the march's value in place of the colour. Not a per-fragment view: not in kAllViews.
constexpr bool isSsrView(View v) {
  return v == View::SsrHit || v == View::SsrSteps || v == View::SsrUv || v == View::HizLevel;
}
// Whether the view shows one of Phong's terms alone (docs/shading.md): ambient (ka albedo Ia),
// diffuse or specular, each summed over the lights with their attenuation and shadows, in place
// of the colour; no environment and no sky. Drawn by the shaded permutation like the shadow views.
constexpr bool isPhongTermView(View v) { return v == View::Ambient || v == View::Diffuse || v == View::Specular; }
// Whether the view is drawn by the shaded permutation (the lights, the environment, the sky).
constexpr bool isShadedView(View v) {
  return v == View::Shaded || isEnvironmentView(v) || isShadowView(v) || isPhongTermView(v);
}
// Whether the view draws the sky box behind the surfaces (the shaded and environment views).
constexpr bool viewDrawsSky(View v) { return isShadedView(v) && !isShadowView(v) && !isPhongTermView(v); }

// How a material's surface detail is drawn (docs/parallax.md). NormalMap: the normal map alone
// (today's behaviour). The others read the height map: two bump methods that change the lighting
// only, and five parallax methods that shift the uv every map is read at.
enum class SurfaceDetail { NormalMap, BumpBlinn, BumpEmboss, Parallax, ParallaxOffsetLimited, SteepParallax, Relief, ParallaxOcclusion };
inline constexpr SurfaceDetail kAllSurfaceDetails[] = {
    SurfaceDetail::NormalMap, SurfaceDetail::BumpBlinn, SurfaceDetail::BumpEmboss, SurfaceDetail::Parallax,
    SurfaceDetail::ParallaxOffsetLimited, SurfaceDetail::SteepParallax, SurfaceDetail::Relief, SurfaceDetail::ParallaxOcclusion};
// Whether the method shifts uv (the parallax family), and whether it marches layers.
constexpr bool shiftsUv(SurfaceDetail d) {
  return d == SurfaceDetail::Parallax || d == SurfaceDetail::ParallaxOffsetLimited || d == SurfaceDetail::SteepParallax ||
         d == SurfaceDetail::Relief || d == SurfaceDetail::ParallaxOcclusion;
}
constexpr bool marchesLayers(SurfaceDetail d) {
  return d == SurfaceDetail::SteepParallax || d == SurfaceDetail::Relief || d == SurfaceDetail::ParallaxOcclusion;
}
// Self-shadowing of the height field: none, a march towards the light through the height field,
// or a precomputed horizon map (scene/horizon_map.h).
enum class SelfShadow { None, HeightMarch, HorizonMap };
// How a material mixes in the environment (docs/environment.md). Fresnel: the reflected share
// is the material's reflectivity (none) or Schlick's approximation (schlick). Specular: no
// reflection of the environment, the mirror direction read exactly (mirror), or a prefiltered
// glossy map (prefiltered). Diffuse: environment light on the diffuse term, from an irradiance
// map or nine spherical-harmonic coefficients.
enum class Fresnel { None, Schlick };
enum class EnvironmentSpecular { None, Mirror, Prefiltered };
enum class EnvironmentDiffuse { None, IrradianceMap, Sh9 };
enum class LightingSpace { World, Tangent };
// How the rasterizer spreads each varying over a triangle (docs/pipeline.md, "Interpolation"):
// perspective (GLSL's default, smooth): a / w and 1 / w are linear on the screen and divided
// per pixel, so a texture stays put on a receding floor; affine (GLSL's noperspective): the
// varying itself is linear on the screen, as early consoles drew it, and textures swim. Depth
// is z / w, linear on the screen either way.
enum class Interpolation { Perspective, Affine };
// How a shaded frame is lit (docs/deferred.md): forward (every fragment lit as it is drawn) or
// deferred (a G-buffer pass writes each pixel's surface, then one lighting pass per pixel).
enum class Pipeline { Forward, Deferred };
// Where the deferred lighting pass finds a pixel's world position: `stored`, a G-buffer target
// holding the position the forward shading interpolates (so deferred lights the very point
// forward lights); `depth`, rebuilt from the window depth through the inverse camera matrix
// (no extra target, but the depth's quantisation moves the point along its ray).
enum class GBufferPosition { Stored, Depth };
enum class TangentTransform { Model, InverseTranspose };
// GL's minification filters (docs/textures.md): nearest = GL_NEAREST, bilinear = GL_LINEAR
// (level 0 only), trilinear = GL_LINEAR_MIPMAP_LINEAR, and the other three mipmapped ones by
// their GL names. Magnification uses GL_NEAREST for the *nearest* ones' texel filter
// (nearest, nearest_mipmap_*), GL_LINEAR for the others.
enum class TextureFilter { Nearest, Bilinear, Trilinear, NearestMipmapNearest, LinearMipmapNearest, NearestMipmapLinear };
inline constexpr TextureFilter kAllTextureFilters[] = {
    TextureFilter::Nearest, TextureFilter::Bilinear, TextureFilter::Trilinear, TextureFilter::NearestMipmapNearest,
    TextureFilter::LinearMipmapNearest, TextureFilter::NearestMipmapLinear};
// Whether the filter reads mip levels (else level 0 only).
constexpr bool usesMipmaps(TextureFilter f) { return f != TextureFilter::Nearest && f != TextureFilter::Bilinear; }
// Whether texels within a level are blended bilinearly (GL_LINEAR*) or picked (GL_NEAREST*).
constexpr bool texelsLinear(TextureFilter f) {
  return f == TextureFilter::Bilinear || f == TextureFilter::Trilinear || f == TextureFilter::LinearMipmapNearest;
}
// Whether two levels are blended (GL_*_MIPMAP_LINEAR).
constexpr bool levelsLinear(TextureFilter f) { return f == TextureFilter::Trilinear || f == TextureFilter::NearestMipmapLinear; }

// Most anisotropy (GL_TEXTURE_MAX_ANISOTROPY): 1 = isotropic, up to 16 as GL drivers offer.
inline constexpr float kMaxTextureAnisotropy = 16.0f;
enum class LineMode { Core, Immediate };

// Each frustum plane of the homogeneous clipper, on (true) or off.
struct ClipSwitches {
  bool left = true, right = true, bottom = true, top = true, near = true, far = true;
};

struct TbnLines {
  bool enabled = false;
  float length = 0.1f;             // world units
  LineMode mode = LineMode::Core;  // immediate needs a compatibility context (GL only)
};

// Screen-space reflections (docs/ssr.md): after the deferred lighting pass, each pixel whose
// material has ssr_reflect > 0 marches its mirror ray through the depth buffer and adds
// reflect_strength * ssr_reflect times the lit colour where the ray hits.
//   linear_world    the GAMES202 write-up's march: fixed world-space steps of `step`; a hit
//                   when the ray passes behind the depth buffer's surface by less than
//                   `thickness` (both sides of the crossing), placed between the two steps;
//   adaptive_world  its adaptive step: `step` first, halved at every overshoot until it is
//                   step / 16, then the same test;
//   dda_screen      the ray as a line on the screen, one pixel per step (perspective-correct:
//                   1 / eye distance is linear on the screen); a hit where the ray between two
//                   samples meets the pixel's surface within `thickness`; `step` is not used;
//   hiz             dda_screen's samples and answer in fewer steps: cells of a min-distance
//                   mip chain the ray passes wholly in front of are skipped at once.
enum class SsrMarch { LinearWorld, AdaptiveWorld, DdaScreen, Hiz };
enum class SampleDistribution { Uniform, Cosine };
inline constexpr int kMaxSsrSteps = 1024;
inline constexpr int kMaxSsrIndirectSamples = 64;
// The largest reflect_strength (unitless): a reflection may be brighter than the lit colour.
inline constexpr float kMaxSsrReflectStrength = 4.0f;
// adaptive_world stops halving at step * this (unitless: four halvings).
inline constexpr float kSsrAdaptiveMinStepRatio = 1.0f / 16.0f;
// The largest frame the march addresses (pixels): its element indices are exact in a float lane.
inline constexpr long long kMaxSsrFramePixels = 1LL << 24;
// Why a frame of this size cannot be marched; empty when it can. Both renderers refuse alike.
std::string ssrSizeProblem(int width, int height);
// The most levels above the frame the hiz march's chain holds (a 65536-pixel side halves 16 times).
inline constexpr int kMaxHizLevels = 16;
// How many levels above a width x height frame its Hi-Z chain holds: while both sides are at
// least 1 (floor(log2(min(width, height))), at most kMaxHizLevels). Both renderers build these.
int hizLevelsOf(int width, int height);
// Why these reflection settings cannot be drawn (a march or indirect light not built yet, a
// value out of its range); empty when they can. Both renderers refuse alike, whoever filled
// the settings in (the scene loader refuses the same by key).
struct SsrSettings;
std::string ssrSettingsProblem(const SsrSettings& ssr);
struct SsrSettings {
  bool enabled = false;
  SsrMarch march = SsrMarch::LinearWorld;
  int maxSteps = 64;        // [1, kMaxSsrSteps]
  float step = 0.05f;       // world units, > 0: linear's every step, adaptive's first (screen marches: unused)
  float thickness = 0.1f;   // world units, > 0: how far behind a surface a ray still hits it
  int indirectSamples = 0;  // [0, kMaxSsrIndirectSamples]: indirect diffuse rays per pixel, 0 none
  SampleDistribution sampleDistribution = SampleDistribution::Uniform;
  float reflectStrength = 1.0f;  // [0, kMaxSsrReflectStrength]
};

struct RenderSettings {
  CullMode cull = CullMode::Back;
  FrontFace frontFace = FrontFace::Ccw;
  ClipSwitches clip;
  std::vector<vec4> userClipPlanes;  // world space, keeps a*x + b*y + c*z + d >= 0
  View view = View::Shaded;
  LightingSpace lightingSpace = LightingSpace::World;
  Pipeline pipeline = Pipeline::Forward;
  GBufferPosition gbufferPosition = GBufferPosition::Stored;  // read by a deferred frame only
  TangentTransform tangentTransform = TangentTransform::Model;
  Interpolation interpolation = Interpolation::Perspective;
  TextureFilter textureFilter = TextureFilter::Bilinear;
  float anisotropy = 1.0f;  // GL_TEXTURE_MAX_ANISOTROPY, in [1, kMaxTextureAnisotropy]
  TbnLines tbnLines;
  SsrSettings ssr;
};

// Whether a frame with these settings marches screen-space reflections (docs/ssr.md): they are
// on and the view is the shaded one.
inline bool drawsSsr(const RenderSettings& settings) {
  return (settings.ssr.enabled && settings.view == View::Shaded) || isSsrView(settings.view);
}
// Whether a frame with these settings draws deferred (docs/deferred.md): the pipeline asks for
// it, or the reflections need its G-buffer, and the view is the shaded one (every debug view
// shows one surface quantity, drawn forward).
inline bool drawsDeferred(const RenderSettings& settings) {
  return ((settings.pipeline == Pipeline::Deferred || settings.ssr.enabled) && settings.view == View::Shaded) ||
         isSsrView(settings.view);
}
// Whether a deferred frame's G-buffer holds the position (its sixth target).
inline bool storesGBufferPosition(const RenderSettings& settings) {
  return drawsDeferred(settings) && settings.gbufferPosition == GBufferPosition::Stored;
}

// Names as written in scene files and on the command line.
std::string_view toString(CullMode v);
std::string_view toString(FrontFace v);
std::string_view toString(View v);
std::string_view toString(LightingSpace v);
std::string_view toString(Interpolation v);
std::string_view toString(Pipeline v);
std::string_view toString(GBufferPosition v);
std::string_view toString(SsrMarch v);
std::string_view toString(SampleDistribution v);
std::string_view toString(TangentTransform v);
std::string_view toString(TextureFilter v);
std::string_view toString(LineMode v);
std::string_view toString(SurfaceDetail v);
std::string_view toString(SelfShadow v);
std::string_view toString(Fresnel v);
std::string_view toString(EnvironmentSpecular v);
std::string_view toString(EnvironmentDiffuse v);

// Parsers return false for an unknown name.
bool parse(std::string_view s, CullMode& out);
bool parse(std::string_view s, FrontFace& out);
bool parse(std::string_view s, View& out);
bool parse(std::string_view s, LightingSpace& out);
bool parse(std::string_view s, Interpolation& out);
bool parse(std::string_view s, Pipeline& out);
bool parse(std::string_view s, GBufferPosition& out);
bool parse(std::string_view s, SsrMarch& out);
bool parse(std::string_view s, SampleDistribution& out);
bool parse(std::string_view s, TangentTransform& out);
bool parse(std::string_view s, TextureFilter& out);
bool parse(std::string_view s, LineMode& out);
bool parse(std::string_view s, SurfaceDetail& out);
bool parse(std::string_view s, SelfShadow& out);
bool parse(std::string_view s, Fresnel& out);
bool parse(std::string_view s, EnvironmentSpecular& out);
bool parse(std::string_view s, EnvironmentDiffuse& out);

// GL has kMaxUserClipPlanes clip distances. Near or far switched on alone needs one of them
// (depth clamp turns both off, the one still on comes back as a clip distance,
// glrender/gl_clip_state.h), so then at most kMaxUserClipPlanes - 1 user planes fit. Empty
// when the settings fit, else why not: both renderers refuse such settings rather than draw
// two different scenes.
std::string clipSlotProblem(const RenderSettings& settings);

// "shaded|albedo|..." for help texts and error messages.
std::string allViewNames();
inline constexpr View kAllViews[] = {View::Shaded, View::Albedo, View::Normal, View::Tangent, View::Bitangent,
                                     View::MappedNormal, View::Uv, View::Depth, View::LightTangent,
                                     View::EyeTangent, View::MipLevel, View::Height, View::ParallaxOffset,
                                     View::ParallaxSteps, View::SelfShadow, View::ReflectDir, View::EnvFace,
                                     View::EnvLod, View::Shadow, View::LightDepth, View::Ambient, View::Diffuse,
                                     View::Specular};
// The reflection pass's views (isSsrView), drawn over the whole frame, never one fragment alone.
inline constexpr View kSsrViews[] = {View::SsrHit, View::SsrSteps, View::SsrUv, View::HizLevel};


}  // namespace twr
