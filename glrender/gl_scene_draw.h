// Draws the flattened scene with the phong program permutations: uploads meshes to
// indexed VBOs and textures, sets the fixed pipeline state from the settings, issues one
// glDrawElements per draw item. Everything uploaded here is freed when the call returns.
#pragma once

#include "glrender/gl_clip_state.h"
#include "glrender/gl_program.h"
#include "scene/renderer.h"

#include <cstdint>
#include <vector>

namespace twr {

struct SceneDrawStats {
  std::uint64_t trianglesIn = 0;   // triangles submitted
  std::uint64_t samplesPassed = 0;  // fragments that passed the depth test (GL_SAMPLES_PASSED)
};

// The permutation defines of the phong program for one material (exposed for tests).
std::vector<std::string> phongDefines(const Material& material, const RenderSettings& settings);

// Draws `items` into the bound framebuffer's current draw buffers. Throws InputError for
// textures it cannot upload.
SceneDrawStats drawScene(ProgramCache& programs, const Scene& scene, const RenderSettings& settings,
                         const GlClipState& clipState, const std::vector<DrawItem>& items, const mat4& clipFromWorld);

}  // namespace twr
