// TBN lines in immediate mode, exactly as the normal-mapping tutorial debugs its tangent
// space: fixed-function matrices (glMatrixMode/glLoadMatrixf), glUseProgram(0) and
// glBegin(GL_LINES). Needs a compatibility-profile context. A debugging tool only: one
// driver call per vertex, deprecated state, absent from core profiles (docs/gl-path.md).
//
// This header includes no GL header: the .cpp is the only file that includes glad's
// compatibility loader (glad_compat/gl.h, a GladGLContext instead of global pointers).
#pragma once

#include "glrender/gl_clip_state.h"
#include "glrender/gl_context.h"
#include "glrender/tbn_lines.h"

#include <memory>

namespace twr {

class ImmediateTbnLines {
 public:
  // Loads the compatibility entry points of the current context; throws InputError when
  // the context is a core profile.
  explicit ImmediateTbnLines(const GlProcFunction& procAddress);
  ~ImmediateTbnLines();
  ImmediateTbnLines(const ImmediateTbnLines&) = delete;
  ImmediateTbnLines& operator=(const ImmediateTbnLines&) = delete;

  // Draws `lines` (world space) into the current draw buffers, clipped as `clipState`
  // says (applied by the caller) through glClipPlane. Leaves the fixed-function matrices
  // loaded.
  void draw(const std::vector<TbnLineVertex>& lines, const mat4& clipFromView, const mat4& viewFromWorld,
            const GlClipState& clipState, const std::vector<vec4>& userClipPlanes) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace twr
