// The environment on a surface over any lane type: the C++ twin of shaders/environment.glsl,
// function by function, the same operations in the same order (docs/environment.md):
//   v = normalize(eye direction), n the normal lighting uses (both in the lighting space)
//   R = 2 (n.v) n - v                       reflect(-v, n)
//   k = 1 - eta^2 (1 - (n.v)^2)             refract(-v, n, eta); k < 0: total internal reflection
//   T = -eta v - (sqrt(k) - eta (n.v)) n    (GLSL's refract, written out)
//   F = F0 + (1 - F0) (1 - max(n.v, 0))^5   Schlick, F0 = reflectivity, or ((1 - eta) / (1 + eta))^2
//                                           when the material refracts
//   colour = mix(transmitted, reflected, F or reflectivity)
// where reflected is the environment in direction R, or with environment_specular prefiltered
// the glossy cube at the LOD of the material's shininess (scene/environment_specular.h), and transmitted is the Phong colour, or the refracted environment when the material
// refracts (the reflected one under total internal reflection), and a direction found in
// tangent space is brought to world space by the fragment's frame before the cube is read.
// Each direction is read with texture(): a cube's LOD from its differences across the pixel's
// 2x2 quad, as GLSL's fine dFdx / dFdy take them (cube_sample-inl.h, cubeLod); a sphere
// or paraboloid map's from its coordinate's quad differences (layer_sample-inl.h).
// Shared source, included plainly and per Highway target (softrender/lanes.h).

#if defined(TWR_LANES_HIGHWAY)
#if defined(TWR_ENVIRONMENT_INL_TARGET) == defined(HWY_TARGET_TOGGLE)
#ifdef TWR_ENVIRONMENT_INL_TARGET
#undef TWR_ENVIRONMENT_INL_TARGET
#else
#define TWR_ENVIRONMENT_INL_TARGET
#endif
#define TWR_ENVIRONMENT_INL_EMIT
#endif
#elif !defined(TWR_ENVIRONMENT_INL_PLAIN)
#define TWR_ENVIRONMENT_INL_PLAIN
#define TWR_ENVIRONMENT_INL_EMIT
#endif

#ifdef TWR_ENVIRONMENT_INL_EMIT
#undef TWR_ENVIRONMENT_INL_EMIT

#include "scene/environment.h"
#include "softrender/environment_uniforms.h"
#include "softrender/cube_sample-inl.h"
#include "softrender/layer_sample-inl.h"
#include "softrender/interpolate-inl.h"
#include "softrender/lane_math-inl.h"
#include "softrender/lanes.h"

TWR_LANES_BEGIN

// What the environment gave one fragment (the pixel trace shows it).
template <typename L>
struct EnvironmentTermsL {
  Vec3L<L> reflectWorld, refractWorld;  // the directions read (world space)
  Vec3L<L> reflected, transmitted;      // what was read, times the intensity
  L reflectLod;                         // the LOD the reflection was read at (before clamping to the chain)
  L share;                              // the reflected share: Schlick's F or the reflectivity
  MaskOf<L> totalInternal;              // refraction found no transmitted ray
  Vec3L<L> colour;                      // the mix
};

// A lighting-space direction in world space: the fragment's frame (t, b, n) in tangent
// space, itself in world space.
template <typename L>
TWR_LANE_INLINE Vec3L<L> worldFromLighting(const Vec3L<L>& d, const Vec3L<L>& t, const Vec3L<L>& b,
                                           const Vec3L<L>& n, bool tangentSpace) {
  if (!tangentSpace) return d;
  return (t * d.x + b * d.y) + n * d.z;
}

// Schlick: F0 + (1 - F0) m^5 with m = 1 - max(cos, 0), m^5 as (m^2)^2 m.
template <typename L>
TWR_LANE_INLINE L schlick(const L& f0, const L& cosTheta) {
  using S = ScalarOf<L>;
  const L one(S(1));
  const L m = one - maxOf(cosTheta, L(S(0)));
  const L m2 = m * m;
  return f0 + (one - f0) * ((m2 * m2) * m);
}

// The directions the environment is read in, from nl (the lighting normal) and vVec (the
// unnormalised eye direction), both in the lighting space; t, b, n the fragment's frame. The
// refracted direction is computed whatever k (GLSL's texture() differentiates the argument it
// is given, used or not); k < 0 says total internal reflection.
template <typename L>
struct EnvironmentDirectionsL {
  L nDotV, k;
  Vec3L<L> reflectWorld, refractWorld;
};
template <typename L>
TWR_LANE_INLINE EnvironmentDirectionsL<L> environmentDirections(const EnvironmentUniformsT<ScalarOf<L>>& e,
                                                                const Vec3L<L>& nl, const Vec3L<L>& vVec,
                                                                const Vec3L<L>& t, const Vec3L<L>& b,
                                                                const Vec3L<L>& n, bool tangentSpace) {
  using S = ScalarOf<L>;
  const L zero(S(0)), one(S(1)), two(S(2));
  EnvironmentDirectionsL<L> d;
  const Vec3L<L> v = safeNormalize<L>(vVec);
  d.nDotV = dot3<L>(nl, v);
  const Vec3L<L> r = (two * d.nDotV) * nl - v;  // reflect(-v, nl)
  d.reflectWorld = (worldFromLighting<L>)(r, t, b, n, tangentSpace);
  d.k = one;
  d.refractWorld = Vec3L<L>(zero);
  if (e.refraction) {
    // refract(-v, nl, eta), written out.
    const L eta(e.eta);
    d.k = one - (eta * eta) * (one - d.nDotV * d.nDotV);
    const L root = sqrtOf(maxOf(d.k, zero));
    const Vec3L<L> refracted = (zero - eta) * v - (root - eta * d.nDotV) * nl;
    d.refractWorld = (worldFromLighting<L>)(refracted, t, b, n, tangentSpace);
  }
  return d;
}

// The environment mixed into `base` (the Phong colour), each direction read with texture():
// its LOD from the direction's quad differences (FragmentL::reflectDx ...); a prefiltered
// reflection with textureLod at the shininess's LOD instead.
template <typename L>
TWR_LANE_INLINE EnvironmentTermsL<L> environmentMix(const EnvironmentUniformsT<ScalarOf<L>>& e,
                                                    const EnvironmentDirectionsL<L>& d, const FragmentL<L>& f,
                                                    const Vec3L<L>& base) {
  using S = ScalarOf<L>;
  const L zero(S(0)), one(S(1)), intensity(e.intensity);
  // Built from values, never default-constructed: a Highway mask has no default constructor
  // the per-target code may call (GCC refuses it on NEON).
  // The reflection: the environment with texture() (its LOD from the direction's quad
  // differences), or the prefiltered glossy map with textureLod at the shininess's LOD.
  const L reflectLod = e.prefiltered ? L(e.specularLod)
                                     : (environmentReadLod<L>)(*e.cube, e.layers, d.reflectWorld, f.reflectDx, f.reflectDy);
  const Vec3L<L> reflected =
      (e.prefiltered ? (sampleEnvironmentAtLod<L>)(*e.specularCube, e.specularLayers, d.reflectWorld, reflectLod)
                     : (sampleEnvironmentAtLod<L>)(*e.cube, e.layers, d.reflectWorld, reflectLod)) *
      intensity;
  Vec3L<L> transmitted = base;
  const auto totalInternal = e.refraction ? d.k < zero : zero > one;  // zero > one: no lane
  L f0(e.reflectivity);
  if (e.refraction) {
    const L eta(e.eta);
    const Vec3L<L> through = (sampleEnvironment<L>)(*e.cube, e.layers, d.refractWorld, f.refractDx, f.refractDy) * intensity;
    transmitted = select3<L>(totalInternal, reflected, through);
    const L ratio = (one - eta) / (one + eta);
    f0 = ratio * ratio;
  }
  L share = zero;
  if (e.reflects) share = e.schlick ? (schlick<L>)(f0, d.nDotV) : L(e.reflectivity);
  const Vec3L<L> colour = transmitted + (reflected - transmitted) * share;
  return EnvironmentTermsL<L>{d.reflectWorld, d.refractWorld, reflected, transmitted, reflectLod, share, totalInternal, colour};
}

// The diffuse light at the lighting normal nl (environment_diffuse, scene/environment_light.h):
// nl brought to world space and normalised, then the irradiance cube (or its sphere or
// paraboloid map) read there at level 0 (textureLod), or the nine SH coefficients evaluated
//   D = c0 + c1 y + c2 z + c3 x + c4 (x y) + c5 (y z) + c6 (3 z^2 - 1) + c7 (x z) + c8 (x^2 - y^2)
// left to right and clamped at 0; times the intensity. GLSL: environmentDiffuse.
template <typename L>
TWR_LANE_INLINE Vec3L<L> environmentDiffuse(const EnvironmentUniformsT<ScalarOf<L>>& e, const Vec3L<L>& nl,
                                            const Vec3L<L>& t, const Vec3L<L>& b, const Vec3L<L>& n,
                                            bool tangentSpace) {
  using S = ScalarOf<L>;
  const L zero(S(0)), intensity(e.intensity);
  const Vec3L<L> w = safeNormalize<L>((worldFromLighting<L>)(nl, t, b, n, tangentSpace));
  if (e.diffuse == EnvironmentDiffuse::IrradianceMap) {
    const Vec3L<L> read = e.irradianceLayers
                              ? (sampleMapLod<L>)(*e.irradianceLayers, (environmentCoord<L>)(e.irradianceLayers->kind, w), zero)
                              : (sampleCubeLod<L>)(*e.irradiance, w, zero);
    return read * intensity;
  }
  const auto& c = e.sh9;
  const L three(S(3)), one(S(1));
  Vec3L<L> d = Vec3L<L>(c[0]) + Vec3L<L>(c[1]) * w.y;
  d = d + Vec3L<L>(c[2]) * w.z;
  d = d + Vec3L<L>(c[3]) * w.x;
  d = d + Vec3L<L>(c[4]) * (w.x * w.y);
  d = d + Vec3L<L>(c[5]) * (w.y * w.z);
  d = d + Vec3L<L>(c[6]) * ((three * (w.z * w.z)) - one);
  d = d + Vec3L<L>(c[7]) * (w.x * w.z);
  d = d + Vec3L<L>(c[8]) * ((w.x * w.x) - (w.y * w.y));
  return Vec3L<L>(maxOf(d.x, zero), maxOf(d.y, zero), maxOf(d.z, zero)) * intensity;
}

TWR_LANES_END

#endif  // TWR_ENVIRONMENT_INL_EMIT
