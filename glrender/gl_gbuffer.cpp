#include "glrender/gl_gbuffer.h"

#include "glrender/gl_scene_draw.h"
#include "scene/camera.h"
#include "scene/renderer.h"

#include <cstring>
#include <stdexcept>
#include <string>
#include <vector>

namespace twr {
namespace {

constexpr GLenum kFirstTarget = GL_COLOR_ATTACHMENT0;                           // five: 0 to 4
constexpr GLenum kPositionTarget = GL_COLOR_ATTACHMENT0 + kGBufferTargets;        // 5
constexpr GLenum kTriangleIdTarget = GL_COLOR_ATTACHMENT0 + kGBufferTargets + 1;  // 6
constexpr int kDrawBuffers = kGBufferTargets + 2;
// The lighting pass's texture units: the depth, the five targets, the position.
constexpr GLint kDepthUnit = 0;
constexpr GLint kFirstTargetUnit = 1;
constexpr GLint kPositionUnit = kFirstTargetUnit + kGBufferTargets;
constexpr std::array<const char*, kGBufferTargets> kTargetSamplers = {"gbufferNormal", "gbufferGeometric",
                                                                      "gbufferAlbedo", "gbufferSpecular",
                                                                      "gbufferEmission"};

GlTexture makeTarget(GLenum internalFormat, GLenum format, GLenum type, int width, int height) {
  GlTexture texture = makeGlTexture();
  glBindTexture(GL_TEXTURE_2D, texture.id());
  glTexImage2D(GL_TEXTURE_2D, 0, static_cast<GLint>(internalFormat), width, height, 0, format, type, nullptr);
  // Read with texelFetch only; one level, so the texture is complete.
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, 0);
  glBindTexture(GL_TEXTURE_2D, 0);
  return texture;
}

}  // namespace

void GlGBuffer::bindForSurfaces(const RenderTargets& targets, GlFrame set, bool position) {
  const int width = targets.width(), height = targets.height();
  if (framebuffer_.id() == 0 || width != width_ || height != height_ || set != set_ || position != storesPosition_ ||
      targets.triangleIdStorage() != triangleIdStorage_) {
    width_ = width;
    height_ = height;
    set_ = set;
    storesPosition_ = position;
    triangleIdStorage_ = targets.triangleIdStorage();
    framebuffer_ = makeGlFramebuffer();
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_.id());
    for (int k = 0; k < kGBufferTargets; ++k) {
      targets_[static_cast<std::size_t>(k)] = makeTarget(GL_RGBA32F, GL_RGBA, GL_FLOAT, width, height);
      glFramebufferTexture2D(GL_FRAMEBUFFER, static_cast<GLenum>(kFirstTarget + k), GL_TEXTURE_2D,
                             targets_[static_cast<std::size_t>(k)].id(), 0);
    }
    position_ = position ? makeTarget(GL_RGBA32F, GL_RGBA, GL_FLOAT, width, height) : GlTexture{};
    if (position) glFramebufferTexture2D(GL_FRAMEBUFFER, kPositionTarget, GL_TEXTURE_2D, position_.id(), 0);
    depth_ = makeTarget(GL_DEPTH_COMPONENT24, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, width, height);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, depth_.id(), 0);
    if (set == GlFrame::Full) {
      glFramebufferRenderbuffer(GL_FRAMEBUFFER, kTriangleIdTarget, GL_RENDERBUFFER, triangleIdStorage_);
    }
    const GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
    if (status != GL_FRAMEBUFFER_COMPLETE) {
      throw std::logic_error("GL: G-buffer framebuffer incomplete (status " + std::to_string(status) + ")");
    }
  }
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_.id());
  glViewport(0, 0, width_, height_);
  std::array<GLenum, kDrawBuffers> buffers{};
  for (int k = 0; k < kGBufferTargets; ++k) buffers[static_cast<std::size_t>(k)] = static_cast<GLenum>(kFirstTarget + k);
  buffers[kGBufferTargets] = storesPosition_ ? kPositionTarget : GL_NONE;
  buffers[kGBufferTargets + 1] = set_ == GlFrame::Full ? kTriangleIdTarget : GL_NONE;
  glDrawBuffers(static_cast<GLsizei>(buffers.size()), buffers.data());
  const std::array<GLfloat, 4> zero = {0.0f, 0.0f, 0.0f, 0.0f};
  for (int k = 0; k < kGBufferTargets + (storesPosition_ ? 1 : 0); ++k) glClearBufferfv(GL_COLOR, k, zero.data());
  if (set_ == GlFrame::Full) {
    const std::array<GLuint, 4> noTriangle = {kNoTriangle, 0, 0, 0};
    glClearBufferuiv(GL_COLOR, kGBufferTargets + 1, noTriangle.data());
  }
  const GLfloat farDepth = 1.0f;
  glClearBufferfv(GL_DEPTH, 0, &farDepth);
}

void GlGBuffer::light(ProgramCache& programs, const Scene& scene, const GlShadowMaps* shadows,
                      const mat4& clipFromWorld, const RenderTargets& targets) const {
  // The frame's depth is the G-buffer's (the sky and the lines test against it).
  glBindFramebuffer(GL_READ_FRAMEBUFFER, framebuffer_.id());
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, targets.framebufferId());
  glBlitFramebuffer(0, 0, width_, height_, 0, 0, width_, height_, GL_DEPTH_BUFFER_BIT, GL_NEAREST);
  glBindFramebuffer(GL_FRAMEBUFFER, targets.framebufferId());
  const std::array<GLenum, 2> colourOnly = {GL_COLOR_ATTACHMENT0, GL_NONE};
  glDrawBuffers(set_ == GlFrame::Full ? 2 : 1, colourOnly.data());

  // Saved and restored: the scene's state, for the sky and the lines after.
  GLboolean depthMask = GL_TRUE;
  glGetBooleanv(GL_DEPTH_WRITEMASK, &depthMask);
  const GLboolean depthTest = glIsEnabled(GL_DEPTH_TEST);
  const GLboolean cull = glIsEnabled(GL_CULL_FACE);
  glDisable(GL_DEPTH_TEST);
  glDepthMask(GL_FALSE);
  glDisable(GL_CULL_FACE);

  std::vector<std::string> defines;
  if (sceneHasShadows(scene)) defines.push_back("HAS_SHADOWS");
  if (storesPosition_) defines.push_back("GBUFFER_POSITION");
  const GLuint program = programs.get(ProgramDesc{"deferred_lighting",
                                                 {"common.glsl", "sky.vert"},
                                                 {"common.glsl", "shadow.glsl", "lighting.glsl", "deferred_lighting.frag"},
                                                 defines});
  glUseProgram(program);
  setLightUniforms(program, scene);
  if (shadows) shadows->bind(program);
  const mat4 worldFromClip = worldFromClipOf(clipFromWorld);
  glUniformMatrix4fv(uniformLocation(program, "worldFromClip"), 1, GL_FALSE, &worldFromClip[0][0]);
  const vec2 viewportSize(static_cast<float>(width_), static_cast<float>(height_));
  glUniform2fv(uniformLocation(program, "viewportSize"), 1, &viewportSize.x);
  glUniform1i(uniformLocation(program, "gbufferDepth"), kDepthUnit);
  glActiveTexture(static_cast<GLenum>(GL_TEXTURE0 + kDepthUnit));
  glBindTexture(GL_TEXTURE_2D, depth_.id());
  for (int k = 0; k < kGBufferTargets; ++k) {
    glUniform1i(uniformLocation(program, kTargetSamplers[static_cast<std::size_t>(k)]), kFirstTargetUnit + k);
    glActiveTexture(static_cast<GLenum>(GL_TEXTURE0 + kFirstTargetUnit + k));
    glBindTexture(GL_TEXTURE_2D, targets_[static_cast<std::size_t>(k)].id());
  }
  if (storesPosition_) {
    glUniform1i(uniformLocation(program, "gbufferPosition"), kPositionUnit);
    glActiveTexture(static_cast<GLenum>(GL_TEXTURE0 + kPositionUnit));
    glBindTexture(GL_TEXTURE_2D, position_.id());
  }
  GlVertexArray empty = makeGlVertexArray();  // core profile: a draw needs a vertex array
  glBindVertexArray(empty.id());
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glBindVertexArray(0);
  for (int k = 0; k <= kPositionUnit; ++k) {
    glActiveTexture(static_cast<GLenum>(GL_TEXTURE0 + k));
    glBindTexture(GL_TEXTURE_2D, 0);
  }
  glActiveTexture(GL_TEXTURE0);

  if (depthTest) glEnable(GL_DEPTH_TEST);
  glDepthMask(depthMask);
  if (cull) glEnable(GL_CULL_FACE);
  // The surfaces' draw buffers again (colour, triangle id), as the frame's draws left them.
  const std::array<GLenum, 2> surfaces = {GL_COLOR_ATTACHMENT0,
                                          set_ == GlFrame::Full ? GLenum{GL_COLOR_ATTACHMENT1} : GLenum{GL_NONE}};
  glDrawBuffers(2, surfaces.data());
}

void GlGBuffer::reflect(ProgramCache& programs, const Scene& scene, const RenderSettings& settings,
                        const mat4& clipFromWorld, const RenderTargets& targets) {
  // The lit colour, copied: the pass reads it at other pixels while it writes the frame.
  if (litCopy_.id() == 0 || litCopyWidth_ != width_ || litCopyHeight_ != height_) {
    litCopy_ = makeTarget(GL_RGBA8, GL_RGBA, GL_UNSIGNED_BYTE, width_, height_);
    litCopyWidth_ = width_;
    litCopyHeight_ = height_;
  }
  glBindFramebuffer(GL_READ_FRAMEBUFFER, targets.framebufferId());
  glReadBuffer(GL_COLOR_ATTACHMENT0);
  glBindTexture(GL_TEXTURE_2D, litCopy_.id());
  glCopyTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 0, 0, width_, height_);  // the scissor does not limit a copy
  glBindTexture(GL_TEXTURE_2D, 0);

  glBindFramebuffer(GL_FRAMEBUFFER, targets.framebufferId());
  const std::array<GLenum, 2> colourOnly = {GL_COLOR_ATTACHMENT0, GL_NONE};
  glDrawBuffers(set_ == GlFrame::Full ? 2 : 1, colourOnly.data());
  GLboolean depthMask = GL_TRUE;
  glGetBooleanv(GL_DEPTH_WRITEMASK, &depthMask);
  const GLboolean depthTest = glIsEnabled(GL_DEPTH_TEST);
  const GLboolean cull = glIsEnabled(GL_CULL_FACE);
  glDisable(GL_DEPTH_TEST);
  glDepthMask(GL_FALSE);
  glDisable(GL_CULL_FACE);

  std::vector<std::string> defines;
  if (storesPosition_) defines.push_back("GBUFFER_POSITION");
  const GLuint program =
      programs.get(ProgramDesc{"ssr", {"common.glsl", "sky.vert"}, {"common.glsl", "ssr.frag"}, defines});
  glUseProgram(program);
  const SsrSettings& ssr = settings.ssr;
  const double n = scene.camera.near, f = scene.camera.far;
  const auto setFloat = [&](const char* name, float value) { glUniform1f(uniformLocation(program, name), value); };
  glUniformMatrix4fv(uniformLocation(program, "clipFromWorld"), 1, GL_FALSE, &clipFromWorld[0][0]);
  if (!storesPosition_) {
    const mat4 worldFromClip = worldFromClipOf(clipFromWorld);
    glUniformMatrix4fv(uniformLocation(program, "worldFromClip"), 1, GL_FALSE, &worldFromClip[0][0]);
  }
  const vec2 viewportSize(static_cast<float>(width_), static_cast<float>(height_));
  glUniform2fv(uniformLocation(program, "viewportSize"), 1, &viewportSize.x);
  // The distance terms as makeSsrUniforms makes them: double, rounded once.
  setFloat("distanceNumerator", static_cast<float>(2.0 * n * f));
  setFloat("distanceSum", static_cast<float>(f + n));
  setFloat("distanceDifference", static_cast<float>(f - n));
  glUniform3fv(uniformLocation(program, "eyePosWorld"), 1, &scene.camera.position.x);
  glUniform1i(uniformLocation(program, "adaptiveMarch"), ssr.march == SsrMarch::AdaptiveWorld ? 1 : 0);
  glUniform1i(uniformLocation(program, "maxSteps"), ssr.maxSteps);
  setFloat("marchStep", ssr.step);
  setFloat("minStep", ssr.step * kSsrAdaptiveMinStepRatio);
  setFloat("thickness", ssr.thickness);
  setFloat("reflectStrength", ssr.reflectStrength);
  // Texture units: depth, normal, specular, position, the lit colour.
  const std::array<std::pair<const char*, GLuint>, 5> textures = {{{"gbufferDepth", depth_.id()},
                                                                   {"gbufferNormal", targets_[0].id()},
                                                                   {"gbufferSpecular", targets_[3].id()},
                                                                   {"gbufferPosition", position_.id()},
                                                                   {"litColour", litCopy_.id()}}};
  for (std::size_t unit = 0; unit < textures.size(); ++unit) {
    glUniform1i(uniformLocation(program, textures[unit].first), static_cast<GLint>(unit));
    glActiveTexture(static_cast<GLenum>(GL_TEXTURE0 + unit));
    glBindTexture(GL_TEXTURE_2D, textures[unit].second);
  }
  GlVertexArray empty = makeGlVertexArray();  // core profile: a draw needs a vertex array
  glBindVertexArray(empty.id());
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glBindVertexArray(0);
  for (std::size_t unit = 0; unit < textures.size(); ++unit) {
    glActiveTexture(static_cast<GLenum>(GL_TEXTURE0 + unit));
    glBindTexture(GL_TEXTURE_2D, 0);
  }
  glActiveTexture(GL_TEXTURE0);

  if (depthTest) glEnable(GL_DEPTH_TEST);
  glDepthMask(depthMask);
  if (cull) glEnable(GL_CULL_FACE);
  const std::array<GLenum, 2> surfaces = {GL_COLOR_ATTACHMENT0,
                                          set_ == GlFrame::Full ? GLenum{GL_COLOR_ATTACHMENT1} : GLenum{GL_NONE}};
  glDrawBuffers(2, surfaces.data());
}

std::shared_ptr<GBuffer> GlGBuffer::readBack() const {
  auto g = std::make_shared<GBuffer>();
  g->width = width_;
  g->height = height_;
  glBindFramebuffer(GL_READ_FRAMEBUFFER, framebuffer_.id());
  std::vector<vec4>* outputs[kGBufferTargets + 1] = {&g->normal,   &g->geometric, &g->albedo,
                                                     &g->specular, &g->emission,  &g->position};
  const std::size_t rowTexels = static_cast<std::size_t>(width_);
  std::vector<vec4> row(rowTexels);
  for (int k = 0; k < kGBufferTargets + (storesPosition_ ? 1 : 0); ++k) {  // the position is attachment 5
    std::vector<vec4>& out = *outputs[k];
    out.resize(rowTexels * static_cast<std::size_t>(height_));
    glReadBuffer(static_cast<GLenum>(kFirstTarget + k));
    glReadPixels(0, 0, width_, height_, GL_RGBA, GL_FLOAT, out.data());
    for (int top = 0, bottom = height_ - 1; top < bottom; ++top, --bottom) {  // GL rows bottom first
      vec4* a = out.data() + static_cast<std::size_t>(top) * rowTexels;
      vec4* b = out.data() + static_cast<std::size_t>(bottom) * rowTexels;
      std::memcpy(row.data(), a, rowTexels * sizeof(vec4));
      std::memcpy(a, b, rowTexels * sizeof(vec4));
      std::memcpy(b, row.data(), rowTexels * sizeof(vec4));
    }
  }
  glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
  return g;
}

}  // namespace twr
