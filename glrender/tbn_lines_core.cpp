#include "glrender/tbn_lines_core.h"

#include <cstddef>

namespace twr {
namespace {

constexpr GLuint kPositionLocation = 0;  // layout(location) in shaders/tbn_lines.vert
constexpr GLuint kColourLocation = 1;

}  // namespace

CoreTbnLines::CoreTbnLines(const std::vector<TbnLineVertex>& lines)
    : vertexArray_(makeGlVertexArray()), vertices_(makeGlBuffer()), vertexCount_(static_cast<GLsizei>(lines.size())) {
  glBindVertexArray(vertexArray_.id());
  glBindBuffer(GL_ARRAY_BUFFER, vertices_.id());
  glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(lines.size() * sizeof(TbnLineVertex)), lines.data(),
               GL_STATIC_DRAW);
  constexpr GLsizei kStride = sizeof(TbnLineVertex);
  glEnableVertexAttribArray(kPositionLocation);
  glVertexAttribPointer(kPositionLocation, 3, GL_FLOAT, GL_FALSE, kStride,
                        reinterpret_cast<const void*>(offsetof(TbnLineVertex, posWorld)));
  glEnableVertexAttribArray(kColourLocation);
  glVertexAttribPointer(kColourLocation, 3, GL_FLOAT, GL_FALSE, kStride,
                        reinterpret_cast<const void*>(offsetof(TbnLineVertex, colour)));
  glBindVertexArray(0);
}

void CoreTbnLines::draw(ProgramCache& programs, const mat4& clipFromWorld, const GlClipState& clipState,
                        const std::vector<vec4>& userClipPlanes) const {
  const ProgramDesc desc{"tbn_lines", {"tbn_lines.vert"}, {"tbn_lines.frag"}, {}};
  const GLuint program = programs.get(desc);
  glUseProgram(program);
  glUniformMatrix4fv(uniformLocation(program, "clipFromWorld"), 1, GL_FALSE, &clipFromWorld[0][0]);
  setGlClipUniforms(program, clipState, userClipPlanes);
  glBindVertexArray(vertexArray_.id());
  glDrawArrays(GL_LINES, 0, vertexCount_);
  glBindVertexArray(0);
}

}  // namespace twr
