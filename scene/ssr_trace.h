// One pixel's march, step by step (docs/ssr.md, "One pixel's march"): its mirror ray or one of
// its indirect light's rays, what each renderer's march did at every step, recorded by the
// march itself (softrender/ssr-inl.h on the CPU, shaders/ssr.frag's SSR_PROBE on GL), so the
// pixel inspector and `trace` can show both side by side and point at the first step where
// they part.
#pragma once

#include "scene/conventions.h"

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace twr {

// What a step of the march did (the same numbers in ssr.frag's record calls).
enum class SsrStepKind : int {
  InFront = 0,      // the sample lies in front of its pixel's surface (or over nothing): go on
  Hit = 1,          // the ray met the surface within the thickness: the march ends here
  Behind = 2,       // it passed behind the surface by more than the thickness: ends, nothing found
  OffScreen = 3,    // the sample left the screen (or went behind the eye): ends
  Ended = 4,        // screen marches: the ray's last sample was reached: ends, nothing found
  Refine = 5,       // adaptive_world: the sample crossed the surface, the step halves
  CellSkipped = 6,  // hiz: every sample in the cell lies in front of its nearest surface: jumped past
  CellDescend = 7,  // hiz: the cell could not be skipped: try a level lower
};
const char* toString(SsrStepKind kind);  // "in_front", "hit", ...
bool endsMarch(SsrStepKind kind);        // Hit, Behind, OffScreen, Ended

struct SsrMarchStep {
  vec2 pixel{0.0f};             // the sample's pixel, window column and row from the bottom (0 off the screen)
  float rayDistance = 0.0f;     // the ray's eye distance there (a cell: the farthest of its samples in the cell)
  float surfaceDistance = 0.0f; // what it was compared with: the pixel's surface distance, or the cell's least (world units)
  int level = 0;                // 0: one pixel; k: a hiz cell of 2^k x 2^k pixels
  // How far along: the world marches' distance along the ray (world units), the screen marches'
  // sample index (after a skip, the sample jumped to).
  float along = 0.0f;
  SsrStepKind kind = SsrStepKind::InFront;
};

// Which of a pixel's rays a trace follows: the mirror ray, or indirect light's sample k >= 0.
constexpr int kSsrMirrorRay = -1;

struct SsrMarchTrace {
  bool marched = false;   // the pixel shows a surface (its ray was marched)
  int ray = kSsrMirrorRay;  // the mirror ray, or indirect sample k
  vec3 origin{0.0f};      // the G-buffer's position (or the one rebuilt from depth), world (each renderer's own)
  vec3 direction{0.0f};   // the ray's direction, world, unit (each renderer's own)
  float weight = 1.0f;    // an indirect sample's weight (its pdf's: uniform 2 cos, cosine 1); 1 for the mirror ray
  std::vector<SsrMarchStep> steps;  // in order; the last one ends the march unless max_steps ran out
};

// Throws InputError unless `ray` is the mirror ray or one of `settings`' indirect samples
// (0 .. indirect_samples - 1).
struct RenderSettings;
void checkSsrRay(const RenderSettings& settings, int ray);

// The ray's name as trace and the pixel inspector print it: "mirror ray" or "indirect sample k".
std::string ssrRayName(int ray);

// The first step where two traces differ: another kind, level or pixel, or a distance more than
// `relativeTolerance` of itself apart; also where one has a step the other has not. None: the same.
std::optional<std::size_t> firstDifferingStep(const SsrMarchTrace& a, const SsrMarchTrace& b,
                                              float relativeTolerance = 1e-5f);

}  // namespace twr
