// Draws the flattened scene with the phong program permutations: meshes and textures come
// from the context's upload cache (uploaded once, kept while the scene uses them), the fixed
// pipeline state from the settings, and one glDrawElements per draw item.
#pragma once

#include "glrender/gl_clip_state.h"
#include "glrender/gl_program.h"
#include "glrender/gl_shadow_pass.h"
#include "glrender/gl_renderer.h"
#include "glrender/gl_upload_cache.h"
#include "scene/renderer.h"

#include <cstdint>
#include <functional>
#include <vector>

namespace twr {

struct SceneDrawStats {
  std::uint64_t trianglesIn = 0;   // triangles submitted
  std::uint64_t samplesPassed = 0;  // fragments that passed the depth test (GL_SAMPLES_PASSED)
};

// The permutation defines of the phong program for one material (exposed for tests).
// `environment`: the scene's environment when the material mixes it in (shaders/environment.glsl),
// else null.
// settings.frontFace and settings.cull as GL state (the frame's draws and the shadow pass).
void applyFaceCulling(const RenderSettings& settings);

// The defines that choose how the environment is read (shaders/environment_map.glsl):
// ENVIRONMENT_SPHERE or ENVIRONMENT_DUAL_PARABOLOID for a built map, none for the cube.
std::vector<std::string> environmentMapDefines(const Environment& environment);
std::vector<std::string> phongDefines(const Material& material, const RenderSettings& settings,
                                      const Environment* environment = nullptr);

// Draws `items` into the bound framebuffer's current draw buffers, within the scissor the
// caller set (GlRenderer: none for a frame, one pixel for renderGlPixel). Throws InputError for
// textures it cannot upload. Calls uploads.beginFrame() and, when it returns, endFrame().
// GlFrame::Full wraps the draws in a GL_SAMPLES_PASSED query and waits for its result
// (samplesPassed), and the programs write the triangle id (location 1). GlFrame::Lean draws
// as a user does: no query (samplesPassed 0), programs compiled with NO_TRIANGLE_ID.
// `shadows`: the maps the shadow pass drew this frame (null or none drawn: a scene without
// shadows), read by programs compiled with HAS_SHADOWS. `gbufferLighting` (the deferred
// pipeline, gl_gbuffer.h): the items are drawn with GBUFFER_PASS into the bound G-buffer, then
// it is called (the lighting pass) before the sky.
SceneDrawStats drawScene(ProgramCache& programs, GlUploadCache& uploads, const Scene& scene,
                         const RenderSettings& settings, const GlClipState& clipState,
                         const std::vector<DrawItem>& items, const mat4& clipFromWorld, int width, int height,
                         GlFrame frame = GlFrame::Full, const GlShadowMaps* shadows = nullptr,
                         const std::function<void()>& gbufferLighting = {});

// The frame's lights and eye (shaders/lighting.glsl's uniforms, and phong.vert's
// lightVectorWorld[]) on `program`, which is in use.
void setLightUniforms(GLuint program, const Scene& scene);

}  // namespace twr
