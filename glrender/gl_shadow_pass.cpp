#include "glrender/gl_shadow_pass.h"

#include "glrender/gl_clip_state.h"
#include "glrender/gl_scene_draw.h"
#include "scene/errors.h"

#include <chrono>
#include <string>

namespace twr {

ShadowMaps GlShadowMaps::draw(ProgramCache& programs, GlUploadCache& uploads, const Scene& scene,
                              const RenderSettings& settings, const std::vector<DrawItem>& items, bool readBack) {
  slotOfLight_.fill(-1);
  slotCount_ = 0;
  if (!sceneHasShadows(scene)) return {};
  const WorldBounds bounds = worldBoundsOf(scene);
  ShadowMaps maps(scene.lights.size());
  const GLuint program = programs.get(ProgramDesc{"shadow_depth", {"shadow_depth.vert"}, {"shadow_depth.frag"}, {}});
  glUseProgram(program);
  // The frame's culling and winding, every frustum plane, no user planes (shadow_pass.h).
  resetGlClipState();
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glDepthMask(GL_TRUE);
  glDisable(GL_SCISSOR_TEST);
  applyFaceCulling(settings);
  for (std::size_t i = 0; i < scene.lights.size() && i < static_cast<std::size_t>(kMaxLights); ++i) {
    const Light& light = scene.lights[i];
    if (!light.shadow) continue;
    if (slotCount_ == kMaxShadowedLights) {
      throw InputError("GL: more than " + std::to_string(kMaxShadowedLights) + " lights cast shadows");
    }
    const auto start = std::chrono::steady_clock::now();
    Slot& slot = slots_[static_cast<std::size_t>(slotCount_)];
    slotOfLight_[i] = slotCount_++;
    slot.projection = shadowProjectionFor(light, bounds);
    const int size = slot.projection.size, layers = slot.projection.layers;
    if (slot.size != size || slot.layers != layers || slot.texture.id() == 0) {
      slot.texture = makeGlTexture();
      glBindTexture(GL_TEXTURE_2D_ARRAY, slot.texture.id());
      glTexImage3D(GL_TEXTURE_2D_ARRAY, 0, GL_DEPTH_COMPONENT32F, size, size, layers, 0, GL_DEPTH_COMPONENT, GL_FLOAT,
                   nullptr);
      // texelFetch reads level 0; nearest makes that level complete on its own.
      glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
      glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
      glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MAX_LEVEL, 0);
      glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_COMPARE_MODE, GL_NONE);
      glBindTexture(GL_TEXTURE_2D_ARRAY, 0);
      slot.framebuffer = makeGlFramebuffer();
      slot.size = size;
      slot.layers = layers;
    }
    glBindFramebuffer(GL_FRAMEBUFFER, slot.framebuffer.id());
    glDrawBuffer(GL_NONE);
    glReadBuffer(GL_NONE);
    glViewport(0, 0, size, size);
    for (int layer = 0; layer < layers; ++layer) {
      glFramebufferTextureLayer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, slot.texture.id(), 0, layer);
      if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
        throw InputError("GL: the shadow map's framebuffer (" + std::to_string(size) + "^2 depth) is incomplete");
      }
      glClearDepth(1.0);
      glClear(GL_DEPTH_BUFFER_BIT);
      const mat4& clipFromWorld = slot.projection.clipFromWorld[static_cast<std::size_t>(layer)];
      glUniformMatrix4fv(uniformLocation(program, "clipFromWorld"), 1, GL_FALSE, &clipFromWorld[0][0]);
      for (const DrawItem& item : items) {
        if (item.mesh->indices.empty()) continue;
        glUniformMatrix4fv(uniformLocation(program, "worldFromModel"), 1, GL_FALSE, &item.worldFromModel[0][0]);
        const GlMesh& mesh = uploads.mesh(*item.mesh);
        glBindVertexArray(mesh.vertexArray.id());
        glDrawElements(GL_TRIANGLES, mesh.indexCount, GL_UNSIGNED_INT, nullptr);
      }
    }
    glBindVertexArray(0);
    auto map = std::make_shared<ShadowMap>();
    map->projection = slot.projection;
    if (readBack) {
      map->depth.resize(static_cast<std::size_t>(size) * static_cast<std::size_t>(size) *
                        static_cast<std::size_t>(layers));
      glBindTexture(GL_TEXTURE_2D_ARRAY, slot.texture.id());
      glPixelStorei(GL_PACK_ALIGNMENT, 4);
      glGetTexImage(GL_TEXTURE_2D_ARRAY, 0, GL_DEPTH_COMPONENT, GL_FLOAT, map->depth.data());
      glBindTexture(GL_TEXTURE_2D_ARRAY, 0);
    } else {
      glFinish();  // the time is the drawing's, as the read-back's glGetTexImage waits for it
    }
    map->milliseconds = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    maps[i] = std::move(map);
  }
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  return maps;
}

void GlShadowMaps::bind(GLuint program) const {
  if (probe_) {
    glUniform1i(uniformLocation(program, "shadowProbeLight"), probe_->light);
    glUniform1i(uniformLocation(program, "shadowProbeField"), probe_->field);
  }
  if (slotCount_ == 0) return;
  std::array<GLint, kMaxLights> slotOfLight{};
  for (std::size_t i = 0; i < slotOfLight.size(); ++i) slotOfLight[i] = slotOfLight_[i];
  glUniform1iv(uniformLocation(program, "shadowSlotOfLight"), kMaxLights, slotOfLight.data());
  for (int s = 0; s < kMaxShadowedLights; ++s) {
    glUniform1i(uniformLocation(program, ("shadowMap" + std::to_string(s)).c_str()), kFirstShadowUnit + s);
  }
  for (int s = 0; s < slotCount_; ++s) {
    const Slot& slot = slots_[static_cast<std::size_t>(s)];
    const ShadowProjection& p = slot.projection;
    const std::string prefix = "shadows[" + std::to_string(s) + "].";
    const auto name = [&](const char* member) { return prefix + member; };
    glUniform1i(uniformLocation(program, name("kind").c_str()), static_cast<GLint>(p.kind));
    glUniformMatrix4fv(uniformLocation(program, name("clipFromWorld").c_str()), 1, GL_FALSE, &p.clipFromWorld[0][0][0]);
    glUniform3fv(uniformLocation(program, name("lightPosWorld").c_str()), 1, &p.lightPosWorld.x);
    glUniform1f(uniformLocation(program, name("depthA").c_str()), p.depthA);
    glUniform1f(uniformLocation(program, name("depthB").c_str()), p.depthB);
    glUniform1f(uniformLocation(program, name("size").c_str()), static_cast<float>(p.size));
    glUniform1f(uniformLocation(program, name("biasConstant").c_str()), p.bias.x);
    glUniform1f(uniformLocation(program, name("biasSlope").c_str()), p.bias.y);
    glUniform1f(uniformLocation(program, name("texelWorld").c_str()), p.texelWorld);
    glUniform1f(uniformLocation(program, name("depthPerWorld").c_str()), p.depthPerWorld);
    glUniform1i(uniformLocation(program, name("pcf").c_str()), p.pcf);
    glActiveTexture(static_cast<GLenum>(GL_TEXTURE0 + kFirstShadowUnit + s));
    glBindTexture(GL_TEXTURE_2D_ARRAY, slot.texture.id());
  }
}

}  // namespace twr
