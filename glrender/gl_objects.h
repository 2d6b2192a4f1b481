// Owning handles for GL objects: deleted when they go out of scope, movable, not copyable.
// The context that created them must be current when they die.
#pragma once

#include <glad/gl.h>

#include <utility>

namespace twr {

template <void (*Delete)(GLuint)>
class GlHandle {
 public:
  GlHandle() = default;
  explicit GlHandle(GLuint id) : id_(id) {}
  ~GlHandle() { reset(); }
  GlHandle(GlHandle&& other) noexcept : id_(std::exchange(other.id_, 0)) {}
  GlHandle& operator=(GlHandle&& other) noexcept {
    if (this != &other) {
      reset();
      id_ = std::exchange(other.id_, 0);
    }
    return *this;
  }
  GlHandle(const GlHandle&) = delete;
  GlHandle& operator=(const GlHandle&) = delete;

  GLuint id() const { return id_; }
  void reset() {
    if (id_ != 0) Delete(id_);
    id_ = 0;
  }

 private:
  GLuint id_ = 0;
};

namespace gldelete {
inline void buffer(GLuint id) { glDeleteBuffers(1, &id); }
inline void vertexArray(GLuint id) { glDeleteVertexArrays(1, &id); }
inline void texture(GLuint id) { glDeleteTextures(1, &id); }
inline void renderbuffer(GLuint id) { glDeleteRenderbuffers(1, &id); }
inline void framebuffer(GLuint id) { glDeleteFramebuffers(1, &id); }
inline void query(GLuint id) { glDeleteQueries(1, &id); }
inline void program(GLuint id) { glDeleteProgram(id); }
inline void shader(GLuint id) { glDeleteShader(id); }
}  // namespace gldelete

using GlBuffer = GlHandle<gldelete::buffer>;
using GlVertexArray = GlHandle<gldelete::vertexArray>;
using GlTexture = GlHandle<gldelete::texture>;
using GlRenderbuffer = GlHandle<gldelete::renderbuffer>;
using GlFramebuffer = GlHandle<gldelete::framebuffer>;
using GlQuery = GlHandle<gldelete::query>;
using GlProgram = GlHandle<gldelete::program>;
using GlShader = GlHandle<gldelete::shader>;

inline GlBuffer makeGlBuffer() {
  GLuint id = 0;
  glGenBuffers(1, &id);
  return GlBuffer(id);
}
inline GlVertexArray makeGlVertexArray() {
  GLuint id = 0;
  glGenVertexArrays(1, &id);
  return GlVertexArray(id);
}
inline GlTexture makeGlTexture() {
  GLuint id = 0;
  glGenTextures(1, &id);
  return GlTexture(id);
}
inline GlRenderbuffer makeGlRenderbuffer() {
  GLuint id = 0;
  glGenRenderbuffers(1, &id);
  return GlRenderbuffer(id);
}
inline GlFramebuffer makeGlFramebuffer() {
  GLuint id = 0;
  glGenFramebuffers(1, &id);
  return GlFramebuffer(id);
}
inline GlQuery makeGlQuery() {
  GLuint id = 0;
  glGenQueries(1, &id);
  return GlQuery(id);
}

}  // namespace twr
