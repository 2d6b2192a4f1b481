#include "glrender/gl_gbuffer.h"

#include "glrender/gl_scene_draw.h"
#include "scene/camera.h"
#include "scene/renderer.h"
#include "scene/settings.h"

#include <algorithm>
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

// A full-screen pass's state: no depth test or writes, no culling, the scissor as given; the
// scene's own is restored after, for the sky and the lines that draw on.
class ScreenPassState {
 public:
  explicit ScreenPassState(bool keepScissor) {
    glGetBooleanv(GL_DEPTH_WRITEMASK, &depthMask_);
    depthTest_ = glIsEnabled(GL_DEPTH_TEST);
    cull_ = glIsEnabled(GL_CULL_FACE);
    scissor_ = glIsEnabled(GL_SCISSOR_TEST);
    glDisable(GL_DEPTH_TEST);
    glDepthMask(GL_FALSE);
    glDisable(GL_CULL_FACE);
    if (!keepScissor) glDisable(GL_SCISSOR_TEST);
  }
  ~ScreenPassState() {
    if (depthTest_) glEnable(GL_DEPTH_TEST);
    glDepthMask(depthMask_);
    if (cull_) glEnable(GL_CULL_FACE);
    if (scissor_) glEnable(GL_SCISSOR_TEST);
  }
  ScreenPassState(const ScreenPassState&) = delete;
  ScreenPassState& operator=(const ScreenPassState&) = delete;

 private:
  GLboolean depthMask_ = GL_TRUE, depthTest_ = GL_FALSE, cull_ = GL_FALSE, scissor_ = GL_FALSE;
};

// One full-screen triangle (sky.vert's) with the bound program.
void drawScreenTriangle() {
  GlVertexArray empty = makeGlVertexArray();  // core profile: a draw needs a vertex array
  glBindVertexArray(empty.id());
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glBindVertexArray(0);
}

// The surface distances' uniforms (ssr_distance.glsl), as makeSsrUniforms makes them: the
// distance terms in double, rounded once.
void setDistanceUniforms(GLuint program, const Scene& scene, const mat4& clipFromWorld) {
  const double n = scene.camera.near, f = scene.camera.far;
  glUniformMatrix4fv(uniformLocation(program, "clipFromWorld"), 1, GL_FALSE, &clipFromWorld[0][0]);
  glUniform1f(uniformLocation(program, "distanceNumerator"), static_cast<float>(2.0 * n * f));
  glUniform1f(uniformLocation(program, "distanceSum"), static_cast<float>(f + n));
  glUniform1f(uniformLocation(program, "distanceDifference"), static_cast<float>(f - n));
}

// Binds `textures` to units 0, 1, ... and names each unit in the program's sampler; unbind()
// clears them after the draw.
template <std::size_t N>
void bindTextures(GLuint program, const std::array<std::pair<const char*, GLuint>, N>& textures) {
  for (std::size_t unit = 0; unit < N; ++unit) {
    glUniform1i(uniformLocation(program, textures[unit].first), static_cast<GLint>(unit));
    glActiveTexture(static_cast<GLenum>(GL_TEXTURE0 + unit));
    glBindTexture(GL_TEXTURE_2D, textures[unit].second);
  }
}
void unbindTextures(std::size_t count) {
  for (std::size_t unit = 0; unit < count; ++unit) {
    glActiveTexture(static_cast<GLenum>(GL_TEXTURE0 + unit));
    glBindTexture(GL_TEXTURE_2D, 0);
  }
  glActiveTexture(GL_TEXTURE0);
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

  const ScreenPassState state(true);

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
  drawScreenTriangle();
  unbindTextures(kPositionUnit + 1);
  restoreSurfaceDrawBuffers();
}

void GlGBuffer::restoreSurfaceDrawBuffers() const {
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

  const SsrSettings& ssr = settings.ssr;
  const int hizLevels = ssr.march == SsrMarch::Hiz ? hizLevelsOf(width_, height_) : 0;
  if (ssr.march == SsrMarch::Hiz) buildHiz(programs, scene, clipFromWorld, hizLevels);

  glBindFramebuffer(GL_FRAMEBUFFER, targets.framebufferId());
  glViewport(0, 0, width_, height_);
  const std::array<GLenum, 2> colourOnly = {GL_COLOR_ATTACHMENT0, GL_NONE};
  glDrawBuffers(set_ == GlFrame::Full ? 2 : 1, colourOnly.data());
  const ScreenPassState state(true);

  const GLuint program = useSsrProgram(programs, scene, settings, clipFromWorld, hizLevels, false);
  const std::array<std::pair<const char*, GLuint>, 7> textures = ssrTextures();
  bindTextures(program, textures);
  drawScreenTriangle();
  unbindTextures(textures.size());
  restoreSurfaceDrawBuffers();
}

GLuint GlGBuffer::useSsrProgram(ProgramCache& programs, const Scene& scene, const RenderSettings& settings,
                                const mat4& clipFromWorld, int hizLevels, bool probe) const {
  std::vector<std::string> defines;
  if (storesPosition_) defines.push_back("GBUFFER_POSITION");
  if (probe) defines.push_back("SSR_PROBE");
  const GLuint program = programs.get(
      ProgramDesc{probe ? "ssr_probe" : "ssr", {"common.glsl", "sky.vert"}, {"common.glsl", "ssr_distance.glsl", "ssr.frag"}, defines});
  const SsrSettings& ssr = settings.ssr;
  glUseProgram(program);
  const auto setFloat = [&](const char* name, float value) { glUniform1f(uniformLocation(program, name), value); };
  setDistanceUniforms(program, scene, clipFromWorld);
  if (!storesPosition_) {
    const mat4 worldFromClip = worldFromClipOf(clipFromWorld);
    glUniformMatrix4fv(uniformLocation(program, "worldFromClip"), 1, GL_FALSE, &worldFromClip[0][0]);
  }
  const vec2 viewportSize(static_cast<float>(width_), static_cast<float>(height_));
  glUniform2fv(uniformLocation(program, "viewportSize"), 1, &viewportSize.x);
  glUniform3fv(uniformLocation(program, "eyePosWorld"), 1, &scene.camera.position.x);
  const int marchKind = ssr.march == SsrMarch::LinearWorld ? 0 : ssr.march == SsrMarch::AdaptiveWorld ? 1 : 2;
  glUniform1i(uniformLocation(program, "marchKind"), marchKind);
  glUniform1i(uniformLocation(program, "maxSteps"), ssr.maxSteps);
  setFloat("marchStep", ssr.step);
  setFloat("minStep", ssr.step * kSsrAdaptiveMinStepRatio);
  setFloat("thickness", ssr.thickness);
  setFloat("reflectStrength", ssr.reflectStrength);
  // As makeSsrUniforms: the camera's near and far, rounded once.
  setFloat("nearDistance", static_cast<float>(scene.camera.near));
  setFloat("farDistance", static_cast<float>(scene.camera.far));
  glUniform1i(uniformLocation(program, "hizLevels"), hizLevels);
  const int debugView = settings.view == View::SsrHit     ? 1
                        : settings.view == View::SsrSteps ? 2
                        : settings.view == View::SsrUv    ? 3
                        : settings.view == View::HizLevel ? 4
                                                          : 0;
  glUniform1i(uniformLocation(program, "debugView"), debugView);
  glUniform1i(uniformLocation(program, "indirectSamples"), debugView != 0 ? 0 : ssr.indirectSamples);
  glUniform1i(uniformLocation(program, "cosineSamples"), ssr.sampleDistribution == SampleDistribution::Cosine ? 1 : 0);
  // As makeSsrUniforms: 1 / samples rounded once here, so neither renderer divides its own way.
  setFloat("indirectScale", ssr.indirectSamples > 0 ? 1.0f / static_cast<float>(ssr.indirectSamples) : 1.0f);
  return program;
}

std::array<std::pair<const char*, GLuint>, 7> GlGBuffer::ssrTextures() const {
  return {{{"gbufferDepth", depth_.id()},
           {"gbufferNormal", targets_[0].id()},
           {"gbufferSpecular", targets_[3].id()},
           {"gbufferPosition", position_.id()},
           {"litColour", litCopy_.id()},
           {"hizDistance", hiz_.id()},
           {"gbufferAlbedo", targets_[2].id()}}};
}

void GlGBuffer::probeReflection(ProgramCache& programs, const Scene& scene, const RenderSettings& settings,
                                const mat4& clipFromWorld, int x, int yGl, int ray, SsrMarchTrace& trace) {
  const SsrSettings& ssr = settings.ssr;
  const int hizLevels = ssr.march == SsrMarch::Hiz ? hizLevelsOf(width_, height_) : 0;
  if (ssr.march == SsrMarch::Hiz) buildHiz(programs, scene, clipFromWorld, hizLevels);
  // A strip of max_steps (at least 2, for the ray's row) x 3 texels: fragment (k, 0) step k's
  // sample, (k, 1) its decision; (0, 2) the ray's direction and weight, (1, 2) its origin.
  const int steps = ssr.maxSteps;
  const int columns = std::max(steps, 2);
  constexpr int kRows = 3;
  GlTexture strip = makeTarget(GL_RGBA32F, GL_RGBA, GL_FLOAT, columns, kRows);
  GlFramebuffer framebuffer = makeGlFramebuffer();
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer.id());
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, strip.id(), 0);
  const GLenum first = GL_COLOR_ATTACHMENT0;
  glDrawBuffers(1, &first);
  GLint viewport[4] = {0, 0, 0, 0};
  glGetIntegerv(GL_VIEWPORT, viewport);
  GLint previous = 0;  // the frame's framebuffer, bound again after
  glGetIntegerv(GL_FRAMEBUFFER_BINDING, &previous);
  glViewport(0, 0, columns, kRows);
  std::vector<float> texels(static_cast<std::size_t>(columns) * kRows * 4, 0.0f);
  {
    const ScreenPassState state(false);
    const GLuint program = useSsrProgram(programs, scene, settings, clipFromWorld, hizLevels, true);
    glUniform2i(uniformLocation(program, "probePixel"), x, yGl);
    glUniform1i(uniformLocation(program, "probeRay"), ray);
    const std::array<std::pair<const char*, GLuint>, 7> textures = ssrTextures();
    bindTextures(program, textures);
    drawScreenTriangle();
    unbindTextures(textures.size());
    glReadBuffer(GL_COLOR_ATTACHMENT0);
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    glReadPixels(0, 0, columns, kRows, GL_RGBA, GL_FLOAT, texels.data());
  }
  glViewport(viewport[0], viewport[1], viewport[2], viewport[3]);
  glBindFramebuffer(GL_FRAMEBUFFER, static_cast<GLuint>(previous));
  const float* rayRow = &texels[static_cast<std::size_t>(columns) * 2 * 4];
  trace.direction = vec3(rayRow[0], rayRow[1], rayRow[2]);
  trace.weight = rayRow[3];
  trace.origin = vec3(rayRow[4], rayRow[5], rayRow[6]);
  trace.steps.clear();
  for (int k = 0; k < steps; ++k) {
    const float* sample = &texels[static_cast<std::size_t>(k) * 4];
    const float* decision = &texels[(static_cast<std::size_t>(columns) + static_cast<std::size_t>(k)) * 4];
    if (decision[3] != 1.0f) break;  // the march ended before step k
    SsrMarchStep step;
    step.pixel = vec2(sample[0], sample[1]);
    step.rayDistance = sample[2];
    step.surfaceDistance = sample[3];
    step.level = static_cast<int>(decision[0]);
    step.kind = static_cast<SsrStepKind>(static_cast<int>(decision[1]));
    step.along = decision[2];
    trace.steps.push_back(step);
  }
}

void GlGBuffer::buildHiz(ProgramCache& programs, const Scene& scene, const mat4& clipFromWorld, int levels) {
  if (hiz_.id() == 0 || hizWidth_ != width_ || hizHeight_ != height_ || hizLevels_ != levels) {
    hiz_ = makeGlTexture();
    glBindTexture(GL_TEXTURE_2D, hiz_.id());
    for (int k = 0; k <= levels; ++k) {
      glTexImage2D(GL_TEXTURE_2D, k, GL_R32F, std::max(1, width_ >> k), std::max(1, height_ >> k), 0, GL_RED, GL_FLOAT,
                   nullptr);
    }
    // Read with texelFetch at a level; levels 0 to `levels` defined and no more, so the
    // texture is mipmap complete (a level above the base is only drawn into then).
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, levels);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST_MIPMAP_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glBindTexture(GL_TEXTURE_2D, 0);
    hizFramebuffer_ = makeGlFramebuffer();
    hizWidth_ = width_;
    hizHeight_ = height_;
    hizLevels_ = levels;
  }
  const ScreenPassState state(false);  // every texel of every level, whatever the frame's scissor
  glBindFramebuffer(GL_FRAMEBUFFER, hizFramebuffer_.id());
  const GLenum target = GL_COLOR_ATTACHMENT0;
  glDrawBuffers(1, &target);
  std::vector<std::string> defines = {"HIZ_FROM_GBUFFER"};
  if (storesPosition_) defines.push_back("GBUFFER_POSITION");
  const GLuint fromGBuffer = programs.get(
      ProgramDesc{"hiz_from_gbuffer", {"common.glsl", "sky.vert"}, {"common.glsl", "ssr_distance.glsl", "hiz.frag"}, defines});
  const GLuint fromBelow =
      programs.get(ProgramDesc{"hiz", {"common.glsl", "sky.vert"}, {"common.glsl", "hiz.frag"}, {}});
  for (int k = 0; k <= levels; ++k) {
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, hiz_.id(), k);
    const GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
    if (status != GL_FRAMEBUFFER_COMPLETE) {
      throw std::logic_error("GL: Hi-Z level " + std::to_string(k) + " framebuffer incomplete (status " +
                             std::to_string(status) + ")");
    }
    glViewport(0, 0, std::max(1, width_ >> k), std::max(1, height_ >> k));
    if (k == 0) {
      glUseProgram(fromGBuffer);
      setDistanceUniforms(fromGBuffer, scene, clipFromWorld);
      const std::array<std::pair<const char*, GLuint>, 2> textures = {
          {{"gbufferDepth", depth_.id()}, {"gbufferPosition", position_.id()}}};
      bindTextures(fromGBuffer, textures);
      drawScreenTriangle();
      unbindTextures(textures.size());
      continue;
    }
    // The level below alone is read while this one is drawn: the base level, with a filter
    // that reads the base alone (no feedback loop).
    glBindTexture(GL_TEXTURE_2D, hiz_.id());
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_BASE_LEVEL, k - 1);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glBindTexture(GL_TEXTURE_2D, 0);
    glUseProgram(fromBelow);
    const std::array<std::pair<const char*, GLuint>, 1> textures = {{{"levelBelow", hiz_.id()}}};
    bindTextures(fromBelow, textures);
    drawScreenTriangle();
    unbindTextures(textures.size());
  }
  glBindTexture(GL_TEXTURE_2D, hiz_.id());
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_BASE_LEVEL, 0);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST_MIPMAP_NEAREST);
  glBindTexture(GL_TEXTURE_2D, 0);
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
