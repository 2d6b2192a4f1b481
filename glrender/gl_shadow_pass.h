// The GL shadow pass (docs/shadows.md): each shadowed light's map drawn into a depth-only
// framebuffer, one layer of a GL_TEXTURE_2D_ARRAY (GL_DEPTH_COMPONENT32F, the floats the CPU's
// depth buffer holds) per orthographic map or cube face, with the scene's own vertex transform
// and the frame's culling; then bound on texture units 12 to 15 for phong.frag's shadow.glsl,
// read with texelFetch. The CPU twin is softrender/shadow_pass.cpp.
#pragma once

#include "glrender/gl_objects.h"
#include "glrender/gl_program.h"
#include "glrender/gl_upload_cache.h"
#include "scene/scene.h"
#include "scene/shadow_map.h"

#include <array>
#include <optional>
#include <vector>

namespace twr {

// The first texture unit of the shadow maps (slot s on unit kFirstShadowUnit + s).
inline constexpr int kFirstShadowUnit = 12;

class GlShadowMaps {
 public:
  // Draws every shadowed light's map (at most kMaxShadowedLights; InputError beyond) and, with
  // readBack, copies each into the returned ShadowMaps (per light index); without it the maps
  // hold their projection and no depth. Leaves the draw framebuffer unbound (0).
  ShadowMaps draw(ProgramCache& programs, GlUploadCache& uploads, const Scene& scene, const RenderSettings& settings,
                  const std::vector<DrawItem>& items, bool readBack);
  // Binds the maps of the last draw() to their units and sets phong.frag's shadow uniforms
  // (shadowSlotOfLight[], shadows[], shadowMap0..3) on `program`, and the probe's.
  void bind(GLuint program) const;

  // The pixel inspector's probe (shadow.glsl's SHADOW_PROBE): while set, the frame's programs
  // are compiled with SHADOW_PROBE and write field `field` of light `light`'s test as the colour.
  struct Probe {
    int light = 0;
    int field = 0;
  };
  void setProbe(const std::optional<Probe>& probe) { probe_ = probe; }
  bool probing() const { return probe_.has_value(); }

 private:
  std::optional<Probe> probe_;
  struct Slot {
    GlTexture texture;
    GlFramebuffer framebuffer;
    int size = 0, layers = 0;  // the texture's shape
    ShadowProjection projection;
  };
  std::array<Slot, kMaxShadowedLights> slots_;
  std::array<int, kMaxLights> slotOfLight_{};  // -1: no map
  int slotCount_ = 0;
};

}  // namespace twr
