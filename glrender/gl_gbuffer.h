// The deferred pipeline on GL (docs/deferred.md): the G-buffer pass draws the scene with
// phong.frag's GBUFFER_PASS into five RGBA32F textures (scene/renderer.h's GBuffer, target by
// target), a sixth for the position when the frame stores it, a DEPTH_COMPONENT24 texture and, in a full frame, the frame's own triangle-id
// storage; the lighting pass (deferred_lighting.frag) then draws one full-screen triangle into
// the frame's colour, reading them with texelFetch. The CPU twin is softrender/deferred.h.
#pragma once

#include "glrender/gl_objects.h"
#include "glrender/gl_program.h"
#include "glrender/gl_renderer.h"
#include "glrender/gl_shadow_pass.h"
#include "glrender/gl_targets.h"
#include "scene/renderer.h"
#include "scene/ssr_trace.h"

#include <array>
#include <memory>
#include <utility>
#include <vector>

namespace twr {

inline constexpr int kGBufferTargets = 5;  // normal, geometric, albedo, specular, emission

class GlGBuffer {
 public:
  // (Re)creates the textures at `targets`' size and binds the G-buffer framebuffer with every
  // target cleared: colours to 0, depth to 1, ids to kNoTriangle (full set). Fragment outputs:
  // locations 0-4 the targets, 5 the position (`position`: settings.gbuffer_position stored),
  // 6 the triangle id.
  void bindForSurfaces(const RenderTargets& targets, GlFrame set, bool position);

  // After the surfaces: copies the depth into `targets` (the frame's depth, for the sky and
  // the lines), binds it and draws the lighting pass into its colour alone, with the frame's
  // lights, eye and shadow maps. The caller's scissor applies.
  void light(ProgramCache& programs, const Scene& scene, const GlShadowMaps* shadows, const mat4& clipFromWorld,
             const RenderTargets& targets) const;

  // Screen-space reflections (docs/ssr.md), after light(): copies the frame's lit colour into
  // a texture and draws ssr.frag over the frame's colour alone, which changes the pixels whose
  // mirror ray hits. The caller's scissor applies (not to the hiz march's chain, built whole).
  void reflect(ProgramCache& programs, const Scene& scene, const RenderSettings& settings, const mat4& clipFromWorld,
               const RenderTargets& targets);

  // The pixel inspector's probe (scene/ssr_trace.h), after reflect(): window pixel (x, yGl)'s
  // march of `ray` (its mirror ray or indirect sample k) step by step, as ssr.frag's SSR_PROBE
  // records it, one step per fragment of a strip read back; fills trace's steps, origin,
  // direction and weight. The frame's targets and bindings are left as they were.
  void probeReflection(ProgramCache& programs, const Scene& scene, const RenderSettings& settings,
                       const mat4& clipFromWorld, int x, int yGl, int ray, SsrMarchTrace& trace);

  // The hiz march's chain (shaders/hiz.frag): level 0 the surface distances, `levels` above.
  void buildHiz(ProgramCache& programs, const Scene& scene, const mat4& clipFromWorld, int levels);

  // The targets (five, or six with the position), top row first (a full frame's compare rows).
  std::shared_ptr<GBuffer> readBack() const;

 private:
  void restoreSurfaceDrawBuffers() const;
  // ssr.frag bound with every uniform the settings give (SSR_PROBE: the probe's variant).
  GLuint useSsrProgram(ProgramCache& programs, const Scene& scene, const RenderSettings& settings,
                       const mat4& clipFromWorld, int hizLevels, bool probe) const;
  std::array<std::pair<const char*, GLuint>, 7> ssrTextures() const;

  int width_ = 0, height_ = 0;
  GlFrame set_ = GlFrame::Full;
  bool storesPosition_ = false;
  GLuint triangleIdStorage_ = 0;  // the one attached, to notice a new frame's storage
  GlFramebuffer framebuffer_;
  std::array<GlTexture, kGBufferTargets> targets_;
  GlTexture position_;  // 0 when the position is rebuilt from depth
  GlTexture depth_;
  GlTexture litCopy_;  // reflect()'s copy of the lit colour (RGBA8), made at the frame's size
  int litCopyWidth_ = 0, litCopyHeight_ = 0;
  GlTexture hiz_;  // the hiz march's min-distance chain (R32F, one level per halving)
  GlFramebuffer hizFramebuffer_;
  int hizWidth_ = 0, hizHeight_ = 0, hizLevels_ = -1;
};

}  // namespace twr
