#include "glrender/gl_targets.h"

#include "scene/errors.h"

#include <array>
#include <cstring>
#include <stdexcept>
#include <string>

namespace twr {
namespace {

constexpr GLenum kColourAttachment = GL_COLOR_ATTACHMENT0;
constexpr GLenum kTriangleIdAttachment = GL_COLOR_ATTACHMENT1;
constexpr GLenum kLineMaskAttachment = GL_COLOR_ATTACHMENT2;

GlRenderbuffer makeStorage(GLenum internalFormat, int width, int height) {
  GlRenderbuffer buffer = makeGlRenderbuffer();
  glBindRenderbuffer(GL_RENDERBUFFER, buffer.id());
  glRenderbufferStorage(GL_RENDERBUFFER, internalFormat, width, height);
  return buffer;
}

// GL rows are bottom first, RenderOutput's top first: swaps rows in place (rowBytes each).
void flipRowsInPlace(std::uint8_t* rows, std::size_t rowBytes, int height, std::vector<std::uint8_t>& scratch) {
  scratch.resize(rowBytes);
  for (int top = 0, bottom = height - 1; top < bottom; ++top, --bottom) {
    std::uint8_t* a = rows + static_cast<std::size_t>(top) * rowBytes;
    std::uint8_t* b = rows + static_cast<std::size_t>(bottom) * rowBytes;
    std::memcpy(scratch.data(), a, rowBytes);
    std::memcpy(a, b, rowBytes);
    std::memcpy(b, scratch.data(), rowBytes);
  }
}

void checkComplete(const char* what) {
  const GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
  if (status != GL_FRAMEBUFFER_COMPLETE) {
    throw std::logic_error(std::string("GL: ") + what + " incomplete (status " + std::to_string(status) + ")");
  }
}

// Reads an attachment straight into `out` (no staging copy: a frame's read-back is mostly
// memory traffic) and flips its rows there. `scratch` holds one row.
template <typename T>
void readAttachment(GLenum attachment, GLenum format, GLenum type, int width, int height, std::size_t channels,
                    std::vector<T>& out, std::vector<std::uint8_t>& scratch) {
  const std::size_t rowBytes = static_cast<std::size_t>(width) * channels * sizeof(T);
  out.resize(static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * channels);
  if (attachment != GL_NONE) glReadBuffer(attachment);
  glReadPixels(0, 0, width, height, format, type, out.data());
  flipRowsInPlace(reinterpret_cast<std::uint8_t*>(out.data()), rowBytes, height, scratch);
}

}  // namespace

void RenderTargets::prepare(int width, int height) {
  if (framebuffer_.id() != 0 && width == width_ && height == height_) return;
  GLint maxRenderbuffer = 0;
  glGetIntegerv(GL_MAX_RENDERBUFFER_SIZE, &maxRenderbuffer);
  std::array<GLint, 2> maxViewport{};
  glGetIntegerv(GL_MAX_VIEWPORT_DIMS, maxViewport.data());
  if (width > maxRenderbuffer || height > maxRenderbuffer || width > maxViewport[0] || height > maxViewport[1]) {
    throw InputError("GL: " + std::to_string(width) + " x " + std::to_string(height) +
                     " exceeds this context's largest framebuffer (" + std::to_string(maxRenderbuffer) + " px, " +
                     "viewport " + std::to_string(maxViewport[0]) + " x " + std::to_string(maxViewport[1]) + ")");
  }
  width_ = width;
  height_ = height;
  colour_ = makeStorage(GL_RGBA8, width, height);
  depth_ = makeStorage(GL_DEPTH_COMPONENT24, width, height);
  framebuffer_ = makeGlFramebuffer();
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_.id());
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, kColourAttachment, GL_RENDERBUFFER, colour_.id());
  if (set_ == GlFrame::Lean) {
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth_.id());
    checkComplete("lean offscreen framebuffer");
    return;
  }
  triangleId_ = makeStorage(GL_R32UI, width, height);
  lineMask_ = makeStorage(GL_RGBA8, width, height);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, kTriangleIdAttachment, GL_RENDERBUFFER, triangleId_.id());
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, kLineMaskAttachment, GL_RENDERBUFFER, lineMask_.id());
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth_.id());
  checkComplete("offscreen framebuffer");

  lineFramebuffer_ = makeGlFramebuffer();
  glBindFramebuffer(GL_FRAMEBUFFER, lineFramebuffer_.id());
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, colour_.id());
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT1, GL_RENDERBUFFER, lineMask_.id());
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth_.id());
  checkComplete("line framebuffer");
}

void RenderTargets::bind() const {
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_.id());
  glViewport(0, 0, width_, height_);
}

void RenderTargets::clear(const vec4& background) const {
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  glDepthMask(GL_TRUE);
  const std::array<GLfloat, 4> colour = {background.r, background.g, background.b, background.a};
  const GLfloat farDepth = 1.0f;
  if (set_ == GlFrame::Lean) {
    const GLenum colourOnly = kColourAttachment;
    glDrawBuffers(1, &colourOnly);
    glClearBufferfv(GL_COLOR, 0, colour.data());
    glClearBufferfv(GL_DEPTH, 0, &farDepth);
    return;
  }
  // glClearBuffer addresses draw buffers, so all three attachments are selected first.
  const std::array<GLenum, 3> all = {kColourAttachment, kTriangleIdAttachment, kLineMaskAttachment};
  glDrawBuffers(static_cast<GLsizei>(all.size()), all.data());
  glClearBufferfv(GL_COLOR, 0, colour.data());
  const std::array<GLuint, 4> noTriangle = {kNoTriangle, 0, 0, 0};
  glClearBufferuiv(GL_COLOR, 1, noTriangle.data());
  const std::array<GLfloat, 4> noLine = {0.0f, 0.0f, 0.0f, 0.0f};
  glClearBufferfv(GL_COLOR, 2, noLine.data());
  glClearBufferfv(GL_DEPTH, 0, &farDepth);
}

void RenderTargets::drawSurfaces() const {
  if (set_ == GlFrame::Lean) {
    const GLenum colourOnly = kColourAttachment;
    glDrawBuffers(1, &colourOnly);
    return;
  }
  const std::array<GLenum, 2> buffers = {kColourAttachment, kTriangleIdAttachment};
  glDrawBuffers(static_cast<GLsizei>(buffers.size()), buffers.data());
}

void RenderTargets::bindForLines() const {
  if (set_ == GlFrame::Lean) {
    // No integer attachment here, so immediate mode may draw into this framebuffer.
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_.id());
    const GLenum colourOnly = kColourAttachment;
    glDrawBuffers(1, &colourOnly);
    return;
  }
  glBindFramebuffer(GL_FRAMEBUFFER, lineFramebuffer_.id());
  const std::array<GLenum, 2> buffers = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1};
  glDrawBuffers(static_cast<GLsizei>(buffers.size()), buffers.data());
}

void RenderTargets::readBack(RenderOutput& out) const {
  out.width = width_;
  out.height = height_;
  glBindFramebuffer(GL_READ_FRAMEBUFFER, framebuffer_.id());
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  readAttachment(kColourAttachment, GL_RGBA, GL_UNSIGNED_BYTE, width_, height_, 4, out.rgba, rowScratch_);
  if (set_ == GlFrame::Lean) {
    out.depth.clear();
    out.triangleId.clear();
    out.lineMask.clear();
    return;
  }
  readAttachment(kTriangleIdAttachment, GL_RED_INTEGER, GL_UNSIGNED_INT, width_, height_, 1, out.triangleId,
                 rowScratch_);
  // The mask is the line attachment's alpha (GL_ALPHA is no read format in a core context).
  readAttachment(kLineMaskAttachment, GL_RGBA, GL_UNSIGNED_BYTE, width_, height_, 4, lineRgba_, rowScratch_);
  out.lineMask.resize(lineRgba_.size() / 4);
  for (std::size_t i = 0; i < out.lineMask.size(); ++i) out.lineMask[i] = lineRgba_[i * 4 + 3] != 0 ? 1 : 0;
  readAttachment(GL_NONE, GL_DEPTH_COMPONENT, GL_FLOAT, width_, height_, 1, out.depth, rowScratch_);
}

void RenderTargets::readPixel(int x, int yGl, RenderOutput& out) const {
  out.width = 1;
  out.height = 1;
  glBindFramebuffer(GL_READ_FRAMEBUFFER, framebuffer_.id());
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  out.rgba.resize(4);
  glReadBuffer(kColourAttachment);
  glReadPixels(x, yGl, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, out.rgba.data());
  out.triangleId.resize(1);
  glReadBuffer(kTriangleIdAttachment);
  glReadPixels(x, yGl, 1, 1, GL_RED_INTEGER, GL_UNSIGNED_INT, out.triangleId.data());
  std::array<std::uint8_t, 4> line{};
  glReadBuffer(kLineMaskAttachment);
  glReadPixels(x, yGl, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, line.data());
  out.lineMask.assign(1, line[3] != 0 ? 1 : 0);
  out.depth.resize(1);
  glReadPixels(x, yGl, 1, 1, GL_DEPTH_COMPONENT, GL_FLOAT, out.depth.data());
}

}  // namespace twr
