// How the clip settings map onto GL. GL clips x/y always, and near/far together or (with
// GL_DEPTH_CLAMP) not at all. The CPU switches each plane alone, so when exactly one of
// near/far is off, depth clamp turns both off and the one still on comes back as a
// clip-space clip distance in slot 0 (w + z >= 0 for near, w - z >= 0 for far), applied
// after the x/y planes and before the user planes, as the CPU's clipper orders them.
// The user planes then take slots 1..count; with all kMaxUserClipPlanes (8) slots in use
// there is no room: such settings are refused before drawing (clipSlotProblem, scene/settings.h).
#pragma once

// No GL header here: tbn_lines_immediate.cpp includes this beside the compatibility loader.
#include "scene/camera.h"
#include "scene/settings.h"

#include <vector>

namespace twr {

struct GlClipState {
  bool depthClamp = false;
  bool frustumPlaneInSlot0 = false;  // clip distance 0 is frustumPlaneClip
  vec4 frustumPlaneClip{0.0f};       // in clip space: keeps dot(plane, gl_Position) >= 0
  vec4 frustumPlaneView{0.0f};       // the same plane in view space (fixed-function lines)
  int firstUserSlot = 0;             // user plane j is clip distance firstUserSlot + j
  int userPlaneCount = 0;
};

GlClipState makeGlClipState(const RenderSettings& settings, const Camera& camera);

// Switches GL_DEPTH_CLAMP and GL_CLIP_DISTANCE0.. for `state`.
void applyGlClipState(const GlClipState& state);
// Clip uniforms of phong.vert and tbn_lines.vert.
void setGlClipUniforms(unsigned int program, const GlClipState& state, const std::vector<vec4>& userClipPlanes);
// Turns depth clamp and every clip distance off again.
void resetGlClipState();

}  // namespace twr
