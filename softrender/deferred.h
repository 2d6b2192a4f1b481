// The deferred pipeline on the CPU (docs/deferred.md): a G-buffer pass, the frame's existing
// stages with the shading's surface half writing every pixel's surface instead of its colour,
// then a lighting pass over the pixels reading it. The G-buffer is this renderer's own
// texture type; shaders/phong.frag's GBUFFER_PASS outputs and shaders/deferred_lighting.frag
// are the GL twins, deferred-inl.h the one C++ source of both passes' per-pixel work.
#pragma once

#include "scene/conventions.h"
#include "scene/renderer.h"
#include "softrender/precision.h"
#include "softrender/shade.h"

#include <array>
#include <vector>

namespace twr {

// The G-buffer is scene/renderer.h's GBuffer: the CPU writes it in place, rows as the
// framebuffer stores them (Framebuffer::index), and hands it to the frame's output.
// Sized for the frame; `clear`: every target 0 (no surface), else whatever was there (a pass
// that writes every pixel). `position`: with the position target (else it is emptied).
void resizeGBuffer(GBuffer& g, int width, int height, bool clear, bool position);

// What the lighting pass reads besides the G-buffer: the frame's lights and eye (a shading
// uniform block with no material), and how a pixel's window depth becomes a world position.
template <typename S>
struct DeferredUniformsT {
  ShadeUniformsT<S> lighting;  // lights, lightCount, eyePosWorld (shadow maps set), view Shaded
  Mat4T<S> worldFromClip{S(1)};  // the inverse of the camera's clipFromWorld (computed in double)
  Vec2T<S> viewportSize{S(1)};   // pixels
  bool positionStored = false;   // read the G-buffer's position target, else rebuild it from depth
};
using DeferredUniforms = DeferredUniformsT<float>;
DeferredUniforms makeDeferredUniforms(const Scene& scene, const RenderSettings& settings, int width, int height,
                                      const ShadowMaps& shadows);

// A material the G-buffer cannot hold: its light terms read the height field per light (emboss,
// self-shadowing). The G-buffer pass lights it there, forward, into the emission target, with
// zero albedo and specular so the lighting pass adds nothing (docs/deferred.md).
template <typename S>
bool litInGBufferPass(const ShadeUniformsT<S>& u) {
  return u.heightMap != nullptr && (u.surfaceDetail == SurfaceDetail::BumpEmboss || u.selfShadow != SelfShadow::None);
}

// The lighting pass on the teaching path, scalar float, over `threads` bands of rows: every
// pixel whose depth is below the clear depth gets deferredLighting's colour in fb.rgba.
struct Framebuffer;
void lightGBufferTeaching(const GBuffer& g, const DeferredUniforms& u, int threads, Framebuffer& fb);

}  // namespace twr

#include "softrender/deferred-inl.h"

namespace twr {

// The G-buffer pass's surface of one fragment on the teaching path (gbufferFragment).
template <typename Features, typename T>
lanes::GBufferTexelL<T> gbufferFragment(const FragmentT<T>& f, const ShadeUniformsT<T>& u) {
  return lanes::gbufferFragment<Features, T>(f, u, TextureMaps{u.diffuseMap, u.normalMap, u.specularMap, u.heightMap, u.horizonMaps});
}

}  // namespace twr
