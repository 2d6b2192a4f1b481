#include "glrender/gl_clip_state.h"

#include "glrender/gl_program.h"

namespace twr {

GlClipState makeGlClipState(const RenderSettings& settings, const Camera& camera) {
  GlClipState state;
  state.userPlaneCount = static_cast<int>(settings.userClipPlanes.size());
  state.depthClamp = !settings.clip.near || !settings.clip.far;
  const bool exactlyOneOff = settings.clip.near != settings.clip.far;
  if (exactlyOneOff && state.userPlaneCount < kMaxUserClipPlanes) {
    state.frustumPlaneInSlot0 = true;
    state.firstUserSlot = 1;
    if (settings.clip.near) {
      state.frustumPlaneClip = vec4(0.0f, 0.0f, 1.0f, 1.0f);           // w + z >= 0
      state.frustumPlaneView = vec4(0.0f, 0.0f, -1.0f, -camera.near);  // -z_view >= near
    } else {
      state.frustumPlaneClip = vec4(0.0f, 0.0f, -1.0f, 1.0f);         // w - z >= 0
      state.frustumPlaneView = vec4(0.0f, 0.0f, 1.0f, camera.far);     // -z_view <= far
    }
  }
  return state;
}

void applyGlClipState(const GlClipState& state) {
  if (state.depthClamp) {
    glEnable(GL_DEPTH_CLAMP);
  } else {
    glDisable(GL_DEPTH_CLAMP);
  }
  const int usedSlots = state.firstUserSlot + state.userPlaneCount;
  for (int slot = 0; slot < kMaxUserClipPlanes; ++slot) {
    if (slot < usedSlots) {
      glEnable(static_cast<GLenum>(GL_CLIP_DISTANCE0 + slot));
    } else {
      glDisable(static_cast<GLenum>(GL_CLIP_DISTANCE0 + slot));
    }
  }
}

void setGlClipUniforms(unsigned int program, const GlClipState& state, const std::vector<vec4>& userClipPlanes) {
  glUniform4fv(uniformLocation(program, "frustumClipPlane"), 1, &state.frustumPlaneClip.x);
  glUniform1i(uniformLocation(program, "firstUserClipSlot"), state.firstUserSlot);
  const GLsizei planeCount = static_cast<GLsizei>(userClipPlanes.size());
  glUniform1i(uniformLocation(program, "userClipPlaneCount"), planeCount);
  if (planeCount > 0) glUniform4fv(uniformLocation(program, "userClipPlanes"), planeCount, &userClipPlanes[0].x);
}

void resetGlClipState() {
  glDisable(GL_DEPTH_CLAMP);
  for (int slot = 0; slot < kMaxUserClipPlanes; ++slot) glDisable(static_cast<GLenum>(GL_CLIP_DISTANCE0 + slot));
}

}  // namespace twr
