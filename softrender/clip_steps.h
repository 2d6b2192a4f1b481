// The clipper's work on one triangle plane by plane, for the pixel trace and the stage
// pictures: the same Sutherland-Hodgman passes clipTriangle makes (clip.cpp runs both through
// one loop), with the polygon left after each plane and, for each vertex a plane made, the
// edge it cut and its intersection parameter t. Apart from clip.h so the kernels, which only
// clip, do not depend on it.
#pragma once

#include "softrender/clip.h"

#include <cstdint>
#include <vector>

namespace twr {

// A vertex a plane made: on the edge from `nearer` to `farther` (indices into the polygon
// before this plane), at nearer + t (farther - nearer) with t = d_nearer / (d_nearer - d_farther).
struct ClipCut {
  int nearer = 0, farther = 0;
  float t = 0.0f;
  int index = 0;  // its place in the polygon after the plane
  // Where along the edge its varyings were taken: t, or with affine varyings its place on the
  // screen (clip.h, screenLinearT).
  float tVaryings = 0.0f;
};

struct ClipStep {
  int plane = 0;                  // clip.h's plane index (clipPlaneName names it)
  std::vector<vec4> before;       // the polygon this plane cut (clip positions)
  std::vector<vec4> after;        // what it left (empty: nothing)
  std::vector<ClipCut> cuts;      // the vertices it made, in the order they appear in `after`
  std::vector<float> distances;   // each vertex of `before`'s distance to the plane (inside >= 0)
};

// The steps clipTriangle(a, b, c, config, ...) takes, one per plane that cut the triangle, in
// the clipper's order; empty when the triangle is entirely inside, trivially outside or has an
// unusable vertex. The last step's `after` is clipTriangle's polygon.
std::vector<ClipStep> clipTriangleSteps(const ClipVertex& a, const ClipVertex& b, const ClipVertex& c,
                                        const ClipConfig& config);

}  // namespace twr
