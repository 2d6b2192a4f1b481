// TBN lines from a VBO with a tiny shader (shaders/tbn_lines.*): the core-profile way.
#pragma once

#include "glrender/gl_clip_state.h"
#include "glrender/gl_program.h"
#include "glrender/tbn_lines.h"

#include <vector>

namespace twr {

class CoreTbnLines {
 public:
  // Uploads `lines` (world space) once; draw() may then run several passes.
  explicit CoreTbnLines(const std::vector<TbnLineVertex>& lines);

  // Draws into the current draw buffers, clipped as `clipState` says (applied by the caller).
  void draw(ProgramCache& programs, const mat4& clipFromWorld, const GlClipState& clipState,
            const std::vector<vec4>& userClipPlanes) const;

 private:
  GlVertexArray vertexArray_;
  GlBuffer vertices_;
  GLsizei vertexCount_ = 0;
};

}  // namespace twr
