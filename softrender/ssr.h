// Screen-space reflections on the CPU (docs/ssr.md): after the deferred lighting pass, every
// pixel whose material has ssr_reflect > 0 marches its mirror ray through the frame's depth
// buffer (linear_world or adaptive_world, settings.ssr) and, where it hits, adds
// reflect_strength * ssr_reflect times the lit colour at the hit. It reads the G-buffer (the
// lighting normal, the position, ssr_reflect in specular.w), the depth and a copy of the lit
// colour; shaders/ssr.frag is the GL twin, ssr-inl.h the one C++ source of the per-pixel work.
#pragma once

#include "scene/conventions.h"
#include "scene/renderer.h"
#include "scene/settings.h"
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
  Miss = 2,        // max_steps taken, nothing met
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
  Vec3T<S> eyePosWorld{S(0)};
  SsrMarch march = SsrMarch::LinearWorld;
  int maxSteps = 64;
  S step = S(0.05), minStep = S(0.05), thickness = S(0.1), reflectStrength = S(1);  // world units; unitless
  // Per element, top row first: the eye distance of the surface there (ssrSurfaceDistances),
  // and the lit frame's r, g, b in [0, 1].
  const float* surfaceDistance = nullptr;
  std::array<const float*, 3> colour{};
};
using SsrUniforms = SsrUniformsT<float>;

// The frame's uniforms (the buffers are set by the pass).
SsrUniforms makeSsrUniforms(const Scene& scene, const RenderSettings& settings, int width, int height);

// What the march reads of the lit frame: its colour as three float planes (byte / 255), and
// each element's surface distance. With the G-buffer's position, the distance is the
// position's own (ssrDistanceOfPointLanes): the same floats on every renderer, so a ray meets
// a surface at the same step everywhere. Without, the depth's (ssrDistanceOfDepthLanes), which
// rounds as each renderer converts its depth. The clear depth gives the far plane.
struct SsrPlanes {
  std::array<std::vector<float>, 3> rgb;
  std::vector<float> surfaceDistance;
};
void ssrPlanesOf(const Framebuffer& fb, const GBuffer& g, bool positionStored, const SsrUniforms& u,
                 SsrPlanes& planes);

// The pass on the teaching path, scalar float, over `threads` bands of rows: each drawn pixel
// of fb with ssr_reflect > 0 is marched and, on a hit, gets ssrPixelLanes's colour.
// `positionStored`: the ray starts at the G-buffer's position, else at the one rebuilt from depth
// with worldFromClip.
void reflectTeaching(const GBuffer& g, SsrUniforms u, const Mat4T<float>& worldFromClip, bool positionStored,
                     int threads, Framebuffer& fb);

}  // namespace twr

#include "softrender/ssr-inl.h"
