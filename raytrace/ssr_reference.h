// Screen-space reflections against the truth (docs/ssr.md, "Against a ray tracer"). From every
// pixel that reflects, the mirror ray and the indirect rays SSR would march (the same origin,
// normal and random pairs) are traced against the scene's own triangles (raytrace/ray_scene.h)
// instead, and the light they bring is added to the same lit frame with the same weights. So
// a perfect march would draw this frame: what remains between an SSR frame and it is what the
// march's shortcuts cost, and what no screen-space method can see.
//
// What a traced ray met (SsrTruth), the error classes of the report:
//   sky        nothing: SSR should add nothing, so any light it adds is a false hit (a
//              thickness leak, a step through a gap)
//   visible    a surface the frame shows at the hit's pixel: the lit frame holds its colour,
//              which is what the reference adds; SSR could have found it, its error here is
//              the march's own
//   off_screen a surface outside the frame (beside it, behind the eye, beyond near or far):
//              SSR cannot see it
//   occluded   a surface inside the frame hidden behind a nearer one (or a face the frame
//              culls): SSR cannot see it either
// Surfaces the frame does not show are lit here with the frame's own forward shading
// (shadeFragmentDynamic: the same materials, lights and shadow maps), at texture level 0, seen
// from the camera as the lit frame sees every surface; a ray that meets nothing brings no
// light, as in the SSR pass.
#pragma once

#include "raytrace/ray_scene.h"
#include "scene/renderer.h"
#include "scene/settings.h"

#include <array>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace twr {

enum class SsrTruth : std::uint8_t { None = 0, Sky, Visible, OffScreen, Occluded };
inline constexpr std::size_t kSsrTruthCount = 5;
const char* toString(SsrTruth truth);  // "none", "sky", "visible", "off_screen", "occluded"

// A pixel is "visible" at a hit when the frame shows the hit's triangle there, or a surface
// whose eye distance is within this share of the hit's (a neighbouring triangle of the same
// surface: the hit's pixel centre lies on the next triangle). Unitless.
inline constexpr double kSsrVisibleDistanceShare = 0.02;
// A traced ray starts this share of the scene's extent along its direction, past the surface
// it leaves (the G-buffer's position rounds to either side of it). Unitless.
inline constexpr double kSsrRayStartShare = 1e-4;
// The most indirect rays per pixel the reference traces.
inline constexpr int kMaxSsrReferenceSamples = 1024;

struct SsrReferenceOptions {
  // Indirect rays per pixel: -1 the frame's settings.ssr.indirect_samples (the very rays SSR
  // marches, so only the march differs); more traces those and further ones from the same
  // sequence (ssrRandomPairOf), a converged truth to measure SSR's noise against.
  int indirectSamples = -1;
  int threads = 0;  // 0: one per hardware thread
};

struct SsrReference {
  // The lit frame with the traced light added (its depth, ids and G-buffer are the base's).
  RenderOutput frame;
  std::vector<SsrTruth> mirror;  // per pixel, top row first: what its mirror ray met (None: no mirror ray)
  std::vector<std::uint8_t> indirectOnly;  // per pixel: 1 where indirect rays were traced but no mirror ray
  std::array<std::uint64_t, kSsrTruthCount> mirrorRays{}, indirectRays{};  // by SsrTruth
  int indirectSamples = 0;  // indirect rays traced per pixel
  double milliseconds = 0.0;
};

// The frame's own forward shading of a traced hit: the hit triangle's three vertices through the
// vertex stage, their varyings weighted by the hit's barycentrics (what perspective-correct
// interpolation gives a raster fragment there), shaded with the same materials, lights and
// shadow maps at texture level 0, seen from the camera. What the reference adds for a surface
// the frame does not show.
class HitShader {
 public:
  // `settings`' shading (drawn forward, shaded view); `shadows`: the frame's maps (they must
  // outlive the shader); width and height: the frame's (the camera's aspect).
  HitShader(const Scene& scene, const RenderSettings& settings, const ShadowMaps& shadows, int width, int height);
  ~HitShader();
  HitShader(const HitShader&) = delete;
  HitShader& operator=(const HitShader&) = delete;
  // Linear colour in [0, 1]. `hit` must be a hit of a RayScene of the same scene.
  glm::dvec3 litAt(const RayHit& hit) const;

 private:
  struct Items;
  std::unique_ptr<Items> items_;
};

// The settings of the frame the reference adds light to: `settings` drawn deferred and shaded
// with reflections off (render `base` with them on the CPU renderer).
RenderSettings ssrBaseSettings(const RenderSettings& settings);

// `settings`: the reflections to trace (settings.ssr, on and shaded); `base`: the CPU renderer's
// frame of ssrBaseSettings(settings), at the size the reference is wanted (its G-buffer, lit
// colour, depth, triangle ids and shadow maps are read). Throws InputError for settings with
// reflections off or in a debug view, a base frame without a G-buffer, or options out of range.
SsrReference traceSsrReference(const Scene& scene, const RenderSettings& settings, const RenderOutput& base,
                               const RayScene& rays, const SsrReferenceOptions& options = {});

// An SSR frame's error against the reference, over the pixels that reflect, by class: the
// pixel's mirror ray's SsrTruth, or indirect_only where only indirect rays were traced.
enum class SsrErrorClass : std::uint8_t { Sky, Visible, OffScreen, Occluded, IndirectOnly };
inline constexpr std::size_t kSsrErrorClassCount = 5;
const char* toString(SsrErrorClass c);  // "sky", "visible", "off_screen", "occluded", "indirect_only"

struct SsrErrorRow {
  std::uint64_t pixels = 0;
  double meanAbs = 0.0;        // mean over the pixels of the largest channel difference, levels
  int maxAbs = 0;              // levels 0-255
  std::uint64_t over3 = 0;     // pixels with a channel more than 3 levels off
  double sumAbs = 0.0;         // the mean's sum: the share of the whole error a class carries
};
struct SsrReferenceError {
  std::array<SsrErrorRow, kSsrErrorClassCount> byClass{};
  SsrErrorRow all;
  // Pixel i's largest channel difference (0 where nothing reflects), top row first.
  std::vector<std::uint8_t> pixelError;
};
// `frame`: an SSR frame of the reference's scene and settings at its size (either renderer's).
// Throws InputError when the sizes differ.
SsrReferenceError measureSsrError(const SsrReference& reference, const RenderOutput& frame);

// Which class each reflecting pixel is in, as an RGBA image (top row first): sky grey, visible
// green, off_screen yellow, occluded red, indirect_only blue; black where nothing reflects.
std::vector<std::uint8_t> ssrTruthImage(const SsrReference& reference);
std::array<std::uint8_t, 3> ssrErrorClassColour(SsrErrorClass c);

}  // namespace twr
