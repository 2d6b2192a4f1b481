// The deferred pipeline's per-pixel work over any lane type (deferred.h describes the
// pipeline): the G-buffer pass's surface (shaders/phong.frag with GBUFFER_PASS) and the
// lighting pass (shaders/deferred_lighting.frag), in the same order of operations as GLSL.
// Both reuse the forward shading's own pieces (shade-inl.h): the surface frame, the material's
// texels, the unlit terms, the light loop. Shared source, included plainly and per Highway
// target (softrender/lanes.h).

#if defined(TWR_LANES_HIGHWAY)
#if defined(TWR_DEFERRED_INL_TARGET) == defined(HWY_TARGET_TOGGLE)
#ifdef TWR_DEFERRED_INL_TARGET
#undef TWR_DEFERRED_INL_TARGET
#else
#define TWR_DEFERRED_INL_TARGET
#endif
#define TWR_DEFERRED_INL_EMIT
#endif
#elif !defined(TWR_DEFERRED_INL_PLAIN)
#define TWR_DEFERRED_INL_PLAIN
#define TWR_DEFERRED_INL_EMIT
#endif

#ifdef TWR_DEFERRED_INL_EMIT
#undef TWR_DEFERRED_INL_EMIT

#include "softrender/lane_math-inl.h"
#include "softrender/lanes.h"
#include "softrender/shade-inl.h"

#include <cstddef>

TWR_LANES_BEGIN

// One pixel of the G-buffer as the passes compute it (deferred.h's GBuffer, target by target).
template <typename L>
struct GBufferTexelL {
  Vec3L<L> nl;         // normal.xyz: the lighting normal, world space
  L shininess;         // normal.w
  Vec3L<L> n;          // geometric.xyz
  Vec3L<L> kdAlbedo;   // albedo.xyz
  Vec3L<L> ksSpec;     // specular.xyz
  Vec3L<L> emission;   // emission.xyz
  Vec3L<L> posWorld;   // position.xyz (when the G-buffer stores it)
  L ssrReflect;        // specular.w: the material's share of the screen-space reflection
};

// The G-buffer pass's shading of one fragment (phong.frag's main with GBUFFER_PASS): the forward
// shading's surface half. The lighting normal goes to world space (a tangent-space material's
// mapped normal through its TBN, as world lighting forms it). The environment's mix,
// colour = phong + (C - phong) w, is linear in the lights' terms, so it is folded in here:
// albedo and specular scaled by (1 - w), the emission (1 - w) unlit + w C; with refraction the
// colour does not read phong at all (w = 1, C the mix). A material litInGBufferPass is shaded
// forward into the emission.
template <typename Features, typename L, typename Maps>
TWR_LANE_INLINE GBufferTexelL<L> gbufferFragment(const FragmentL<L>& f, const ShadeUniformsT<ScalarOf<L>>& u,
                                                 const Maps& maps) {
  using S = ScalarOf<L>;
  constexpr bool kTangentSpace = Features::kSpace == LightingSpace::Tangent;
  const L zero(S(0)), one(S(1));
  const SurfaceFrameL<L> frame = (surfaceFrame<Features, L>)(f, u, maps, false);
  Vec3L<L> nlWorld = frame.nl;
  if constexpr (kTangentSpace) {
    const bool mapped = Features::kHasNormalMap || (Features::kHasHeightMap && u.surfaceDetail == SurfaceDetail::BumpBlinn);
    const Vec3L<L>& m = frame.mappedTangent;
    nlWorld = mapped ? safeNormalize<L>(frame.t * m.x + frame.b * m.y + frame.n * m.z) : frame.n;
  }
  GBufferTexelL<L> g{nlWorld,         L(u.shininess), frame.n,    Vec3L<L>(zero),
                     Vec3L<L>(zero),  Vec3L<L>(zero), f.posWorld, L(u.ssrReflect)};
  if constexpr (Features::kHasHeightMap) {
    if (litInGBufferPass(u)) {
      const Vec4L<L> colour = (shadeFragment<Features, L>)(f, u, maps, static_cast<std::nullptr_t*>(nullptr));
      g.emission = Vec3L<L>(colour.x, colour.y, colour.z);
      return g;
    }
  }
  const MaterialTexelsL<L> texels = (materialTexels<Features, L>)(f, u, maps, frame.detail);
  const Vec3L<L> kdAlbedo = Vec3L<L>(u.kd) * texels.albedo;
  const Vec3L<L> ksSpec = Vec3L<L>(u.ks) * texels.specScale;
  const UnlitTermsL<L> unlit = (unlitTerms<Features, L>)(u, frame, texels.albedo, kdAlbedo);
  if (!(u.environment.cube && u.environment.readsDirections())) {
    g.kdAlbedo = kdAlbedo;
    g.ksSpec = ksSpec;
    g.emission = unlit.unlit;
    return g;
  }
  const Vec3L<L> eyeVec = kTangentSpace ? f.eyeDirTangent : Vec3L<L>(u.eyePosWorld) - f.posWorld;
  const EnvironmentDirectionsL<L> directions =
      (environmentDirections<L>)(u.environment, frame.nl, eyeVec, frame.t, frame.b, frame.n, kTangentSpace);
  const EnvironmentTermsL<L> env = (environmentMix<L>)(u.environment, directions, f, Vec3L<L>(zero));
  const L w = u.environment.refraction ? one : env.share;
  const Vec3L<L> c = u.environment.refraction ? env.colour : env.reflected;
  const L keep = one - w;
  g.kdAlbedo = kdAlbedo * keep;
  g.ksSpec = ksSpec * keep;
  g.emission = unlit.unlit * keep + c * w;
  return g;
}

// A pixel's world position from its window depth (deferred_lighting.frag's worldFromWindow):
// the pixel centre and depth to NDC, through worldFromClip (columns summed from the left), then
// divided by w.
template <typename L>
TWR_LANE_INLINE Vec3L<L> worldFromWindow(const Mat4T<ScalarOf<L>>& m, const Vec2T<ScalarOf<L>>& viewportSize,
                                         const L& px, const L& py, const L& depth) {
  using S = ScalarOf<L>;
  const L one(S(1)), two(S(2)), half(S(0.5));
  const L x = (two * (px + half)) / L(viewportSize.x) - one;
  const L y = (two * (py + half)) / L(viewportSize.y) - one;
  const L z = two * depth - one;
  const L wx = ((L(m[0][0]) * x + L(m[1][0]) * y) + L(m[2][0]) * z) + L(m[3][0]);
  const L wy = ((L(m[0][1]) * x + L(m[1][1]) * y) + L(m[2][1]) * z) + L(m[3][1]);
  const L wz = ((L(m[0][2]) * x + L(m[1][2]) * y) + L(m[2][2]) * z) + L(m[3][2]);
  const L w = ((L(m[0][3]) * x + L(m[1][3]) * y) + L(m[2][3]) * z) + L(m[3][3]);
  return Vec3L<L>(wx / w, wy / w, wz / w);
}

// The lighting pass at one pixel (deferred_lighting.frag's main): the G-buffer's surface at
// g.posWorld (its stored position, or worldFromWindow's) lit by the frame's lights with the forward shading's own loop (world space, no
// height field), added to the emission and clamped as the forward colour is.
struct NoMaps {};
using DeferredLightingFeatures = ShaderFeatures<false, LightingSpace::World, false>;
template <typename L>
TWR_LANE_INLINE Vec4L<L> deferredLighting(const GBufferTexelL<L>& g, const ShadeUniformsT<ScalarOf<L>>& u) {
  using S = ScalarOf<L>;
  const L zero(S(0)), one(S(1));
  SurfaceFrameL<L> frame;
  frame.n = g.n;
  frame.t = Vec3L<L>(zero);  // read only for a height field
  frame.b = Vec3L<L>(zero);
  frame.detail = SurfaceDetailL<L>{Vec2L<L>(zero, zero), one, zero, Vec3L<L>(zero, zero, one)};
  frame.normalTexel = Vec4L<L>(zero);
  frame.mappedTangent = Vec3L<L>(zero, zero, one);
  frame.nl = g.nl;
  const LightSumL<L> lit = (lightSum<DeferredLightingFeatures, L>)(
      static_cast<const FragmentL<L>*>(nullptr), u, NoMaps{}, g.posWorld, frame, g.kdAlbedo, g.ksSpec, g.shininess,
      static_cast<std::nullptr_t*>(nullptr));
  return clampUnit4<L>(Vec4L<L>(g.emission + lit.sum, one));
}

TWR_LANES_END

#endif  // TWR_DEFERRED_INL_EMIT
