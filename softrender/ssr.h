// Screen-space reflections on the CPU (docs/ssr.md): after the deferred lighting pass, every
// pixel whose material has ssr_reflect > 0 marches its mirror ray through the frame's depth
// buffer (settings.ssr.march: linear_world and adaptive_world step in world units, dda_screen
// one pixel at a time, hiz the same pixels skipping what a min-distance chain clears) and, where it hits, adds
// reflect_strength * ssr_reflect times the lit colour at the hit. It reads the G-buffer (the
// lighting normal, the position, ssr_reflect in specular.w), the depth and a copy of the lit
// colour; shaders/ssr.frag is the GL twin, ssr-inl.h the one C++ source of the per-pixel work.
#pragma once

#include "scene/conventions.h"
#include "scene/renderer.h"
#include "scene/settings.h"
#include "scene/ssr_trace.h"
#include "softrender/precision.h"

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace twr {

struct Scene;
struct Framebuffer;

// What a march ended in (the lane value of SsrMarchL::result).
enum class SsrResult : int {
  NotMarched = 0,  // nothing drawn, or ssr_reflect 0
  Hit = 1,         // the ray met a surface within the thickness
  Miss = 2,        // max_steps taken, nothing met (screen marches: or the ray's end reached)
  OffScreen = 3,   // the ray left the screen (or went behind the eye)
  Behind = 4,      // the ray passed behind a surface by more than the thickness
};

// What the march reads besides the G-buffer.
template <typename S>
struct SsrUniformsT {
  Mat4T<S> clipFromWorld{S(1)};
  Vec2T<S> viewportSize{S(1)};  // pixels
  // A window depth d's eye distance, 2 n f / ((f + n) - (2 d - 1) (f - n)): the three terms
  // from the camera's near and far in double, rounded once.
  S distanceNumerator = S(1), distanceSum = S(2), distanceDifference = S(0);
  // The camera's near and far distances: the screen marches' ray ends where its eye distance
  // reaches one of them (world units).
  S nearDistance = S(1), farDistance = S(100);
  // The distance the surface-distance plane gives where nothing was drawn (the clear depth's):
  // the screen marches pass over such pixels, there is nothing there to hit.
  S skyDistance = S(100);
  Vec3T<S> eyePosWorld{S(0)};
  SsrMarch march = SsrMarch::LinearWorld;
  int maxSteps = 64;
  S step = S(0.05), minStep = S(0.05), thickness = S(0.1), reflectStrength = S(1);  // world units; unitless
  // Per element, top row first: the eye distance of the surface there (ssrSurfaceDistances),
  // and the lit frame's r, g, b in [0, 1].
  const float* surfaceDistance = nullptr;
  std::array<const float*, 3> colour{};
  // hiz: the chain's levels above the frame (0 for every other march; a screen march with 0
  // levels is dda_screen). Level k >= 1 is floor(width / 2^k) x floor(height / 2^k) cells,
  // bottom row first, from hizCells + hizOffset[k]; a cell holds the least surface distance of
  // the 2x2 cells below it (3 wide or high at an odd level's last column or row).
  int hizLevels = 0;
  const float* hizCells = nullptr;
  std::array<float, kMaxHizLevels + 1> hizOffset{};  // elements, exact in a float
  // Indirect diffuse light: rays per pixel (0: none) over the hemisphere of the lighting
  // normal, uniform or cosine-weighted (indirect).
  int indirectSamples = 0;
  SampleDistribution distribution = SampleDistribution::Uniform;
  S indirectScale = S(1);  // 1 / indirectSamples, rounded once (GL gets the same float)
  // A reflection view (isSsrView): every drawn pixel's mirror ray, its march shown in place of
  // the colour. Shaded: the pass adds light.
  View view = View::Shaded;
};
using SsrUniforms = SsrUniformsT<float>;

// Indirect light's random numbers: sample k of the pixel at window column x, row y (from the
// bottom) as two numbers in [0, 1) with 24 random bits each, the top bits of PCG hashes of the
// three integers (Jarzynski and Olano, "Hash Functions for GPU Rendering", 2020). The same
// integer arithmetic as ssr.frag's randomPair, so both renderers send the same rays.
std::uint32_t pcgHash(std::uint32_t v);
vec2 ssrRandomPairOf(std::uint32_t x, std::uint32_t y, std::uint32_t k);

// The frame's uniforms (the buffers are set by the pass).
SsrUniforms makeSsrUniforms(const Scene& scene, const RenderSettings& settings, int width, int height);

// What the march reads of the lit frame: its colour as three float planes (byte / 255), and
// each element's surface distance. With the G-buffer's position, the distance is the
// position's own (distanceOfPoint): the same floats on every renderer, so a ray meets
// a surface at the same step everywhere. Without, the depth's (distanceOfDepth), which
// rounds as each renderer converts its depth. The clear depth gives the far plane.
// With the hiz march, the min-distance chain over the surface distances too (hizChainOf).
struct SsrPlanes {
  std::array<std::vector<float>, 3> rgb;
  std::vector<float> surfaceDistance;
  std::vector<float> hizCells;  // levels 1 and up, as SsrUniforms::hizCells
  int hizLevels = 0;
  std::array<float, kMaxHizLevels + 1> hizOffset{};
};
void ssrPlanesOf(const Framebuffer& fb, const GBuffer& g, bool positionStored, const SsrUniforms& u,
                 SsrPlanes& planes);
// The surface distances and (hiz) the chain alone, from a frame's window depth (top row
// first, as the framebuffer and RenderOutput store it) and its G-buffer: ssrPlanesOf's half
// the march reads.
void ssrDistancesOf(const std::vector<float>& depth, int width, int height, const GBuffer& g, bool positionStored,
                    const SsrUniforms& u, SsrPlanes& planes);

// Pixel (x, yTop)'s march on the CPU, step by step (scene/ssr_trace.h; the pixel inspector and
// `trace`): of its mirror ray, or with `ray` k >= 0 of its indirect light's sample k (the
// direction and weight the pass gives it). `frame` is this renderer's frame of `settings` (its
// G-buffer and depth are read), the march the teaching path's, recording as it goes. Throws
// InputError when the frame has no G-buffer (settings draw no reflections), the pixel is
// outside it or the settings have no sample k.
SsrMarchTrace traceSsrMarch(const Scene& scene, const RenderSettings& settings, const RenderOutput& frame, int x,
                            int yTop, int ray = kSsrMirrorRay);

// Points u's buffers at the planes' (the colour, the distances, the chain).
void useSsrPlanes(const SsrPlanes& planes, SsrUniforms& u);

// The min-distance chain over a top-row-first plane of surface distances (SsrUniforms's
// hizCells): each cell the least of the cells below it, the level above's odd last column or
// row folded into the last cell. GL builds the same levels with shaders/hiz.frag.
void hizChainOf(const std::vector<float>& surfaceDistance, int width, int height, SsrPlanes& planes);

// The pass on the teaching path, scalar float, over `threads` bands of rows: each drawn pixel
// of fb with ssr_reflect > 0 is marched and, on a hit, gets ssrPixel's colour.
// `positionStored`: the ray starts at the G-buffer's position, else at the one rebuilt from depth
// with worldFromClip.
void reflectTeaching(const GBuffer& g, SsrUniforms u, const Mat4T<float>& worldFromClip, bool positionStored,
                     int threads, Framebuffer& fb);

}  // namespace twr

#include "softrender/ssr-inl.h"
