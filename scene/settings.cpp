#include "scene/settings.h"

#include <array>
#include <cmath>
#include <utility>

namespace twr {

namespace {

template <typename E, std::size_t N>
using NameTable = std::array<std::pair<E, std::string_view>, N>;

constexpr NameTable<CullMode, 3> kCull{{{CullMode::None, "none"}, {CullMode::Back, "back"}, {CullMode::Front, "front"}}};
constexpr NameTable<FrontFace, 2> kFront{{{FrontFace::Ccw, "ccw"}, {FrontFace::Cw, "cw"}}};
constexpr NameTable<View, 27> kView{{{View::Shaded, "shaded"},
                                     {View::Albedo, "albedo"},
                                     {View::Normal, "normal"},
                                     {View::Tangent, "tangent"},
                                     {View::Bitangent, "bitangent"},
                                     {View::MappedNormal, "mapped_normal"},
                                     {View::Uv, "uv"},
                                     {View::Depth, "depth"},
                                     {View::LightTangent, "light_tangent"},
                                     {View::EyeTangent, "eye_tangent"},
                                     {View::MipLevel, "mip_level"},
                                     {View::Height, "height"},
                                     {View::ParallaxOffset, "parallax_offset"},
                                     {View::ParallaxSteps, "parallax_steps"},
                                     {View::SelfShadow, "self_shadow"},
                                     {View::ReflectDir, "reflect_dir"},
                                     {View::EnvFace, "env_face"},
                                     {View::EnvLod, "env_lod"},
                                     {View::Shadow, "shadow"},
                                     {View::LightDepth, "light_depth"},
                                     {View::SsrHit, "ssr_hit"},
                                     {View::SsrSteps, "ssr_steps"},
                                     {View::SsrUv, "ssr_uv"},
                                     {View::HizLevel, "hiz_level"},
                                     {View::Ambient, "ambient"},
                                     {View::Diffuse, "diffuse"},
                                     {View::Specular, "specular"}}};
constexpr NameTable<LightingSpace, 2> kSpace{{{LightingSpace::World, "world"}, {LightingSpace::Tangent, "tangent"}}};
constexpr NameTable<Pipeline, 2> kPipeline{{{Pipeline::Forward, "forward"}, {Pipeline::Deferred, "deferred"}}};
constexpr NameTable<GBufferPosition, 2> kGBufferPosition{
    {{GBufferPosition::Stored, "stored"}, {GBufferPosition::Depth, "depth"}}};
constexpr NameTable<SsrMarch, 4> kSsrMarch{{{SsrMarch::LinearWorld, "linear_world"},
                                            {SsrMarch::AdaptiveWorld, "adaptive_world"},
                                            {SsrMarch::DdaScreen, "dda_screen"},
                                            {SsrMarch::Hiz, "hiz"}}};
constexpr NameTable<SampleDistribution, 2> kSampleDistribution{
    {{SampleDistribution::Uniform, "uniform"}, {SampleDistribution::Cosine, "cosine"}}};
constexpr NameTable<TangentTransform, 2> kTangent{
    {{TangentTransform::Model, "model"}, {TangentTransform::InverseTranspose, "inverse_transpose"}}};
constexpr NameTable<TextureFilter, 6> kFilter{{{TextureFilter::Nearest, "nearest"},
                                              {TextureFilter::Bilinear, "bilinear"},
                                              {TextureFilter::Trilinear, "trilinear"},
                                              {TextureFilter::NearestMipmapNearest, "nearest_mipmap_nearest"},
                                              {TextureFilter::LinearMipmapNearest, "linear_mipmap_nearest"},
                                              {TextureFilter::NearestMipmapLinear, "nearest_mipmap_linear"}}};
// GL's own names for two of them, accepted as well.
constexpr NameTable<TextureFilter, 3> kFilterAliases{{{TextureFilter::Nearest, "nearest"},
                                                     {TextureFilter::Bilinear, "linear"},
                                                     {TextureFilter::Trilinear, "linear_mipmap_linear"}}};
constexpr NameTable<LineMode, 2> kLine{{{LineMode::Core, "core"}, {LineMode::Immediate, "immediate"}}};
constexpr NameTable<SurfaceDetail, 8> kSurfaceDetail{{{SurfaceDetail::NormalMap, "normal_map"},
                                                     {SurfaceDetail::BumpBlinn, "bump_blinn"},
                                                     {SurfaceDetail::BumpEmboss, "bump_emboss"},
                                                     {SurfaceDetail::Parallax, "parallax"},
                                                     {SurfaceDetail::ParallaxOffsetLimited, "parallax_offset_limited"},
                                                     {SurfaceDetail::SteepParallax, "steep_parallax"},
                                                     {SurfaceDetail::Relief, "relief"},
                                                     {SurfaceDetail::ParallaxOcclusion, "parallax_occlusion"}}};
constexpr NameTable<SelfShadow, 3> kSelfShadow{
    {{SelfShadow::None, "none"}, {SelfShadow::HeightMarch, "height_march"}, {SelfShadow::HorizonMap, "horizon_map"}}};
constexpr NameTable<Interpolation, 2> kInterpolation{
    {{Interpolation::Perspective, "perspective"}, {Interpolation::Affine, "affine"}}};
constexpr NameTable<Fresnel, 2> kFresnel{{{Fresnel::None, "none"}, {Fresnel::Schlick, "schlick"}}};
constexpr NameTable<EnvironmentSpecular, 3> kEnvironmentSpecular{{{EnvironmentSpecular::None, "none"},
                                                                  {EnvironmentSpecular::Mirror, "mirror"},
                                                                  {EnvironmentSpecular::Prefiltered, "prefiltered"}}};
constexpr NameTable<EnvironmentDiffuse, 3> kEnvironmentDiffuse{{{EnvironmentDiffuse::None, "none"},
                                                                {EnvironmentDiffuse::IrradianceMap, "irradiance_map"},
                                                                {EnvironmentDiffuse::Sh9, "sh9"}}};

template <typename E, std::size_t N>
std::string_view nameOf(const NameTable<E, N>& table, E value) {
  for (const auto& [v, name] : table)
    if (v == value) return name;
  return "?";
}

template <typename E, std::size_t N>
bool valueOf(const NameTable<E, N>& table, std::string_view s, E& out) {
  for (const auto& [v, name] : table) {
    if (name == s) {
      out = v;
      return true;
    }
  }
  return false;
}

}  // namespace

std::string ssrSizeProblem(int width, int height) {
  const long long pixels = static_cast<long long>(width) * static_cast<long long>(height);
  if (pixels <= kMaxSsrFramePixels) return "";
  return "settings.ssr: a frame of " + std::to_string(width) + "x" + std::to_string(height) + " (" +
         std::to_string(pixels) + " pixels) is not marched: at most " + std::to_string(kMaxSsrFramePixels) +
         " pixels (4096x4096), whose element indices are exact in a float lane";
}

int hizLevelsOf(int width, int height) {
  int levels = 0;
  while (levels < kMaxHizLevels && (width >> (levels + 1)) >= 1 && (height >> (levels + 1)) >= 1) ++levels;
  return levels;
}

std::string ssrSettingsProblem(const SsrSettings& ssr) {
  if (!(ssr.indirectSamples >= 0 && ssr.indirectSamples <= kMaxSsrIndirectSamples)) {
    return "settings.ssr.indirect_samples: out of [0, 64]";
  }
  if (!(ssr.maxSteps >= 1 && ssr.maxSteps <= kMaxSsrSteps)) return "settings.ssr.max_steps: out of [1, 1024]";
  if (!(ssr.step > 0.0f) || !std::isfinite(ssr.step)) return "settings.ssr.step: expected a finite number > 0";
  if (!(ssr.thickness > 0.0f) || !std::isfinite(ssr.thickness)) {
    return "settings.ssr.thickness: expected a finite number > 0";
  }
  if (!(ssr.reflectStrength >= 0.0f && ssr.reflectStrength <= kMaxSsrReflectStrength)) {
    return "settings.ssr.reflect_strength: out of [0, 4]";
  }
  return "";
}

std::string_view toString(CullMode v) { return nameOf(kCull, v); }
std::string_view toString(FrontFace v) { return nameOf(kFront, v); }
std::string_view toString(View v) { return nameOf(kView, v); }
std::string_view toString(LightingSpace v) { return nameOf(kSpace, v); }
std::string_view toString(Pipeline v) { return nameOf(kPipeline, v); }
std::string_view toString(Interpolation v) { return nameOf(kInterpolation, v); }
std::string_view toString(GBufferPosition v) { return nameOf(kGBufferPosition, v); }
std::string_view toString(SsrMarch v) { return nameOf(kSsrMarch, v); }
std::string_view toString(SampleDistribution v) { return nameOf(kSampleDistribution, v); }
std::string_view toString(TangentTransform v) { return nameOf(kTangent, v); }
std::string_view toString(TextureFilter v) { return nameOf(kFilter, v); }
std::string_view toString(LineMode v) { return nameOf(kLine, v); }
std::string_view toString(SurfaceDetail v) { return nameOf(kSurfaceDetail, v); }
std::string_view toString(SelfShadow v) { return nameOf(kSelfShadow, v); }
std::string_view toString(Fresnel v) { return nameOf(kFresnel, v); }
std::string_view toString(EnvironmentSpecular v) { return nameOf(kEnvironmentSpecular, v); }
std::string_view toString(EnvironmentDiffuse v) { return nameOf(kEnvironmentDiffuse, v); }

bool parse(std::string_view s, CullMode& out) { return valueOf(kCull, s, out); }
bool parse(std::string_view s, FrontFace& out) { return valueOf(kFront, s, out); }
bool parse(std::string_view s, View& out) { return valueOf(kView, s, out); }
bool parse(std::string_view s, LightingSpace& out) { return valueOf(kSpace, s, out); }
bool parse(std::string_view s, Pipeline& out) { return valueOf(kPipeline, s, out); }
bool parse(std::string_view s, Interpolation& out) { return valueOf(kInterpolation, s, out); }
bool parse(std::string_view s, GBufferPosition& out) { return valueOf(kGBufferPosition, s, out); }
bool parse(std::string_view s, SsrMarch& out) { return valueOf(kSsrMarch, s, out); }
bool parse(std::string_view s, SampleDistribution& out) { return valueOf(kSampleDistribution, s, out); }
bool parse(std::string_view s, TangentTransform& out) { return valueOf(kTangent, s, out); }
bool parse(std::string_view s, TextureFilter& out) { return valueOf(kFilter, s, out) || valueOf(kFilterAliases, s, out); }
bool parse(std::string_view s, LineMode& out) { return valueOf(kLine, s, out); }
bool parse(std::string_view s, SurfaceDetail& out) { return valueOf(kSurfaceDetail, s, out); }
bool parse(std::string_view s, SelfShadow& out) { return valueOf(kSelfShadow, s, out); }
bool parse(std::string_view s, Fresnel& out) { return valueOf(kFresnel, s, out); }
bool parse(std::string_view s, EnvironmentSpecular& out) { return valueOf(kEnvironmentSpecular, s, out); }
bool parse(std::string_view s, EnvironmentDiffuse& out) { return valueOf(kEnvironmentDiffuse, s, out); }

std::string clipSlotProblem(const RenderSettings& settings) {
  const bool oneDepthPlane = settings.clip.near != settings.clip.far;
  const std::size_t slots = static_cast<std::size_t>(kMaxUserClipPlanes) - (oneDepthPlane ? 1u : 0u);
  if (settings.userClipPlanes.size() <= slots) return {};
  return std::to_string(settings.userClipPlanes.size()) + " user clip planes with only the " +
         (settings.clip.near ? "near" : "far") + " plane on: GL has " + std::to_string(kMaxUserClipPlanes) +
         " clip distances and that plane takes one, so at most " + std::to_string(slots) +
         " user planes fit (switch near and far both on or both off, or drop a plane)";
}

std::string allViewNames() {
  std::string names;
  for (const auto& [v, name] : kView) {
    if (!names.empty()) names += '|';
    names += name;
  }
  return names;
}

}  // namespace twr
