// Height fields over any lane type: Blinn's bump mapping, emboss bump mapping, the parallax
// family (plain, offset limited, steep, relief, parallax occlusion) and self-shadowing by a
// march towards the light or a horizon map. The C++ twin of the functions of the same names
// in shaders/surface_detail.glsl, in the same order of operations; docs/parallax.md derives
// each one. Shared source, included plainly and per Highway target (softrender/lanes.h).
//
// The marching functions are TWR_LANE_OUTLINE: one out-of-line copy per target rather than one
// inside every kernel (a march inlined into each permutation multiplied fast_kernels-inl.h's
// compile time; the loops, not the call, dominate their cost).
//
// Conventions (docs/parallax.md): a height h in [0, 1] is the map's red channel, 1 = top. The
// polygon lies at the top of the relief; a point of height h lies (1 - h) heightScale below it,
// in texture-space units (1 = one uv unit along the surface), so depth = 1 - h in [0, 1] is
// measured in units of heightScale. Every height is read with the fragment's own uv
// differences (textureGrad in GLSL with dFdx and dFdy: the fine ones, FragmentL::uvDxFine), so
// the mip level does not jump where a march moves uv.

#if defined(TWR_LANES_HIGHWAY)
#if defined(TWR_SURFACE_DETAIL_INL_TARGET) == defined(HWY_TARGET_TOGGLE)
#ifdef TWR_SURFACE_DETAIL_INL_TARGET
#undef TWR_SURFACE_DETAIL_INL_TARGET
#else
#define TWR_SURFACE_DETAIL_INL_TARGET
#endif
#define TWR_SURFACE_DETAIL_INL_EMIT
#endif
#elif !defined(TWR_SURFACE_DETAIL_INL_PLAIN)
#define TWR_SURFACE_DETAIL_INL_PLAIN
#define TWR_SURFACE_DETAIL_INL_EMIT
#endif

#ifdef TWR_SURFACE_DETAIL_INL_EMIT
#undef TWR_SURFACE_DETAIL_INL_EMIT

#include "softrender/interpolate-inl.h"
#include "softrender/lane_math-inl.h"
#include "softrender/lanes.h"
#include "softrender/texture_sample-inl.h"

#include <cstddef>
#include <type_traits>

TWR_LANES_BEGIN

// A map read at `uv` with explicit uv differences (GLSL's textureGrad): the LOD of the
// differences when the filter uses mipmaps, or the elliptical filter with anisotropy.
template <typename L, typename View, typename Texel = Vec4L<L>>
TWR_LANE_INLINE Texel sampleGrad(const View& map, const ShadeUniformsT<ScalarOf<L>>& u, const Vec2L<L>& uv,
                                 const Vec2L<L>& dx, const Vec2L<L>& dy) {
  using S = ScalarOf<L>;
  if (u.anisotropic) {
    const Vec4L<L> filtered = sampleTextureAnisotropic<L>(map, uv, u.filter, dx, dy);
    if constexpr (std::is_same_v<Texel, L>) {
      return filtered.x;
    } else {
      return filtered;
    }
  }
  const L lod = usesMipmaps(u.filter) ? quadLod<L>(dx, dy, texLevelWidth(map, 0), texLevelHeight(map, 0)) : L(S(0));
  return sampleTexture<L, View, Texel>(map, uv, u.filter, lod);
}

// Every height read of one fragment uses the fragment's uv differences, so all share one LOD
// and one choice of mip levels: found once per fragment (a march reads dozens of heights), the
// same levels textureGrad finds at each read in GLSL. Anisotropic reads keep the differences.
template <typename L>
struct HeightReadsL {
  MipLevelsL<L> mips;
};
template <typename L, typename View>
TWR_LANE_INLINE HeightReadsL<L> heightReads(const View& heightMap, const ShadeUniformsT<ScalarOf<L>>& u,
                                            const FragmentL<L>& f) {
  using S = ScalarOf<L>;
  const bool mipmapped = usesMipmaps(u.filter) && !u.anisotropic;
  const L lod = mipmapped ? quadLod<L>(f.uvDxFine, f.uvDyFine, texLevelWidth(heightMap, 0),
                                       texLevelHeight(heightMap, 0))
                          : L(S(0));
  return HeightReadsL<L>{(mipLevels<L>)(heightMap, u.filter, lod)};
}

// heightAt: the height in [0, 1] at uv (the red channel alone), with the fragment's uv
// differences. kCase: what the caller knows of the map's sampler state (texture_sample-inl.h).
// The general case calls the one out-of-line copy of the read (heightAt is also called from
// every shading kernel); the compiled case, which only the parallax march takes, is inlined.
template <typename L, typename View, SamplerCase kCase = SamplerCase::kAny>
TWR_LANE_INLINE L heightAt(const View& heightMap, const ShadeUniformsT<ScalarOf<L>>& u,
                           const HeightReadsL<L>& reads, const Vec2L<L>& uv, const FragmentL<L>& f) {
  if constexpr (kCase == SamplerCase::kAny) {
    if (u.anisotropic) return sampleGrad<L, View, L>(heightMap, u, uv, f.uvDxFine, f.uvDyFine);
    return (sampleMipLevels<L, View, L>)(heightMap, uv, u.filter, reads.mips);
  } else {
    return (sampleMipLevelsInline<L, View, L, kCase>)(heightMap, uv, u.filter, reads.mips);
  }
}
// The case a march can compile its reads for (SamplerCase::kRepeatLinearUnorm), or kAny.
template <typename View, typename Uniforms>
TWR_LANE_INLINE bool readsAsRepeatLinearUnorm(const View& heightMap, const Uniforms& u) {
  return texWrap(heightMap) == TextureWrap::Repeat && !texSrgb(heightMap) && texelsLinear(u.filter) && !u.anisotropic;
}
// One read alone.
template <typename L, typename View>
TWR_LANE_INLINE L heightAt(const View& heightMap, const ShadeUniformsT<ScalarOf<L>>& u, const Vec2L<L>& uv,
                           const FragmentL<L>& f) {
  return heightAt<L>(heightMap, u, heightReads<L>(heightMap, u, f), uv, f);
}

// A lighting-space direction in the fragment's tangent frame, normalised: tangent space hands
// the interpolated vector over as it is; world space projects w onto (t, b, n).
template <typename L>
TWR_LANE_INLINE Vec3L<L> tangentFromLighting(const Vec3L<L>& w, const Vec3L<L>& t, const Vec3L<L>& b,
                                             const Vec3L<L>& n, bool tangentSpace) {
  if (tangentSpace) return safeNormalize<L>(w);
  return safeNormalize<L>(Vec3L<L>(dot3<L>(t, w), dot3<L>(b, w), dot3<L>(n, w)));
}

// Layers for a march along `dir` (tangent space, normalised): parallaxLayers' min looking
// straight down, its max at grazing angles, linear in 1 - |dir.z| (not rounded).
template <typename L>
TWR_LANE_INLINE L layerCount(const ShadeUniformsT<ScalarOf<L>>& u, const Vec3L<L>& dir) {
  using S = ScalarOf<L>;
  return L(u.layersMin) + L(u.layersMax - u.layersMin) * (L(S(1)) - absOf(dir.z));
}

// What the surface-detail stage hands to the rest of the shading.
template <typename L>
struct SurfaceDetailL {
  Vec2L<L> uv;            // where every map is read (uv shifted by the parallax methods)
  L height;               // the height at that uv
  L steps;                // layers marched, plus refinement steps (parallax_steps view)
  Vec3L<L> bumpTangent;   // bump_blinn's tangent-space normal, (0, 0, 1) otherwise
};

// Blinn (1978): the height field displaces the surface along N by heightScale h(u, v); to
// first order its tangent-space normal is (-s dh/du, -s dh/dv, 1), normalised. The partial
// derivatives are central differences one level-0 texel (u.heightTexel) either side.
template <typename L, typename View>
TWR_LANE_OUTLINE Vec3L<L> bumpBlinn(const View& heightMap, const ShadeUniformsT<ScalarOf<L>>& u, const FragmentL<L>& f) {
  using S = ScalarOf<L>;
  const L du(u.heightTexel.x), dv(u.heightTexel.y), zero(S(0)), one(S(1)), two(S(2));
  const HeightReadsL<L> reads = heightReads<L>(heightMap, u, f);
  const L hL = heightAt<L>(heightMap, u, reads, Vec2L<L>(f.uv.x - du, f.uv.y), f);
  const L hR = heightAt<L>(heightMap, u, reads, Vec2L<L>(f.uv.x + du, f.uv.y), f);
  const L hD = heightAt<L>(heightMap, u, reads, Vec2L<L>(f.uv.x, f.uv.y - dv), f);
  const L hU = heightAt<L>(heightMap, u, reads, Vec2L<L>(f.uv.x, f.uv.y + dv), f);
  const L dhDu = (hR - hL) / (two * du);
  const L dhDv = (hU - hD) / (two * dv);
  const L s(u.heightScale);
  return safeNormalize<L>(Vec3L<L>(zero - s * dhDu, zero - s * dhDv, one));
}

// The steep methods' march: from the fragment's uv, one layer of depth a step along deltaUv
// until the ray is below the height field (or u.layerCap steps). Ends with the ray's uv and
// depth, the field's depth there, the layer before (the last uv where the ray was still above)
// and the steps each lane took; h0 is the height at the fragment's uv.
template <typename L>
struct LayerMarchL {
  Vec2L<L> uvC, prevUv;
  L depthC, surfaceDepth, prevSurfaceDepth, steps;
};
template <typename L, typename View, SamplerCase kCase>
TWR_LANE_INLINE LayerMarchL<L> layerMarch(const View& heightMap, const ShadeUniformsT<ScalarOf<L>>& u,
                                          const HeightReadsL<L>& reads, const FragmentL<L>& f, L h0,
                                          const Vec2L<L>& deltaUv, L layerDepth) {
  using S = ScalarOf<L>;
  const L zero(S(0)), one(S(1));
  Vec2L<L> uvC = f.uv;
  L depthC = zero;             // the ray's depth, in units of heightScale
  L surfaceDepth = one - h0;   // the height field's depth at uvC
  L steps = zero;
  Vec2L<L> prevUv = uvC;
  L prevSurfaceDepth = surfaceDepth;
  // The next layer is read where the ray would be had every lane kept marching: in a lane
  // still marching that is uvC - deltaUv (the same subtractions, the same bits); a lane that
  // stopped ignores it. So a read never waits for the one before: the CPU overlaps the reads
  // of consecutive layers, and only the loop's exit depends on what they return.
  Vec2L<L> uvNext = uvC;
  L depthNext = depthC;
  for (int i = 0; i < u.layerCap; ++i) {
    const auto above = depthC < surfaceDepth;
    if (!anyOf(above)) break;
    uvNext = Vec2L<L>(uvNext.x - deltaUv.x, uvNext.y - deltaUv.y);
    depthNext = depthNext + layerDepth;
    const L surfaceNext = one - heightAt<L, View, kCase>(heightMap, u, reads, uvNext, f);
    prevUv = Vec2L<L>(select(above, uvC.x, prevUv.x), select(above, uvC.y, prevUv.y));
    prevSurfaceDepth = select(above, surfaceDepth, prevSurfaceDepth);
    uvC = Vec2L<L>(select(above, uvNext.x, uvC.x), select(above, uvNext.y, uvC.y));
    depthC = select(above, depthNext, depthC);
    surfaceDepth = select(above, surfaceNext, surfaceDepth);
    steps = select(above, steps + one, steps);
  }
  return {uvC, prevUv, depthC, surfaceDepth, prevSurfaceDepth, steps};
}

// The parallax family: where the view ray through the fragment meets the height field, as uv.
// vT: the eye direction in tangent space, normalised. wantHeight: read the height at the
// shifted uv for the marching methods (a height march, the height view, the pixel trace); left
// at 1 otherwise, a read GLSL's compiler drops where nothing uses it.
template <typename L, typename View, SamplerCase kCase>
TWR_LANE_INLINE SurfaceDetailL<L> parallaxCase(const View& heightMap, const ShadeUniformsT<ScalarOf<L>>& u,
                                                   const FragmentL<L>& f, const Vec3L<L>& vT, bool wantHeight) {
  using S = ScalarOf<L>;
  const L zero(S(0)), one(S(1)), half(S(0.5));
  const L scale(u.heightScale);
  SurfaceDetailL<L> r{f.uv, one, zero, Vec3L<L>(zero, zero, one)};
  // A view at or below the tangent plane (interpolated normals at silhouettes) would divide by
  // zero: vz is kept at kMinParallaxViewZ or above, so the shift stays finite there.
  const L vz = maxOf(vT.z, L(static_cast<S>(kMinParallaxViewZ)));
  const HeightReadsL<L> reads = heightReads<L>(heightMap, u, f);
  const L h0 = heightAt<L, View, kCase>(heightMap, u, reads, f.uv, f);
  if (u.surfaceDetail == SurfaceDetail::Parallax) {
    // Kaneko et al.: the height at uv, taken as constant along the ray; 1 / vz grows without
    // bound at grazing angles (docs/parallax.md shows it).
    const L depth = (one - h0) * scale;
    r.uv = Vec2L<L>(f.uv.x - vT.x / vz * depth, f.uv.y - vT.y / vz * depth);
  } else if (u.surfaceDetail == SurfaceDetail::ParallaxOffsetLimited) {
    // Welsh: without the division, the shift never exceeds the depth.
    const L depth = (one - h0) * scale;
    r.uv = Vec2L<L>(f.uv.x - vT.x * depth, f.uv.y - vT.y * depth);
  } else {
    // Steep parallax: step down layer by layer until the ray is below the height field.
    const L layers = layerCount<L>(u, vT);
    const L layerDepth = one / layers;
    const L shiftPerLayer = scale / layers;
    const Vec2L<L> deltaUv(vT.x / vz * shiftPerLayer, vT.y / vz * shiftPerLayer);
    LayerMarchL<L> m = (layerMarch<L, View, kCase>)(heightMap, u, reads, f, h0, deltaUv, layerDepth);
    Vec2L<L>& uvC = m.uvC;
    L& depthC = m.depthC;
    L& surfaceDepth = m.surfaceDepth;
    L& steps = m.steps;
    if (u.surfaceDetail == SurfaceDetail::Relief) {
      // Policarpo et al.: binary search in the last layer, starting half a layer back.
      Vec2L<L> du = deltaUv;
      L dd = layerDepth;
      for (int k = 0; k < u.refinementSteps; ++k) {
        du = Vec2L<L>(du.x * half, du.y * half);
        dd = dd * half;
        const auto below = depthC >= surfaceDepth;
        uvC = Vec2L<L>(select(below, uvC.x + du.x, uvC.x - du.x), select(below, uvC.y + du.y, uvC.y - du.y));
        depthC = select(below, depthC - dd, depthC + dd);
        surfaceDepth = one - heightAt<L, View, kCase>(heightMap, u, reads, uvC, f);
      }
      steps = steps + L(static_cast<S>(u.refinementSteps));
    } else if (u.surfaceDetail == SurfaceDetail::ParallaxOcclusion) {
      // Tatarchuk: intersect the ray with the straight line between the heights of the last
      // two layers. after <= 0 <= before; a zero denominator keeps the last layer. The layer
      // before is the one the march read (no second read; with no step taken, after = 0 and
      // the weight is 0).
      const L after = surfaceDepth - depthC;
      const L before = m.prevSurfaceDepth - depthC + layerDepth;
      const L denominator = after - before;
      const L weight = select(absOf(denominator) > zero, after / denominator, zero);
      uvC = Vec2L<L>(m.prevUv.x * weight + uvC.x * (one - weight), m.prevUv.y * weight + uvC.y * (one - weight));
    }
    r.uv = uvC;
    r.steps = steps;
  }
  if (u.surfaceDetail == SurfaceDetail::Parallax || u.surfaceDetail == SurfaceDetail::ParallaxOffsetLimited) {
    r.height = h0;
  } else if (wantHeight) {
    r.height = heightAt<L, View, kCase>(heightMap, u, reads, r.uv, f);
  }
  return r;
}

// The same, its reads compiled for the height map's sampler state where it is the usual one.
template <typename L, typename View>
TWR_LANE_OUTLINE SurfaceDetailL<L> parallax(const View& heightMap, const ShadeUniformsT<ScalarOf<L>>& u,
                                                const FragmentL<L>& f, const Vec3L<L>& vT, bool wantHeight) {
  if ((readsAsRepeatLinearUnorm)(heightMap, u)) {
    return parallaxCase<L, View, SamplerCase::kRepeatLinearUnorm>(heightMap, u, f, vT, wantHeight);
  }
  return parallaxCase<L, View, SamplerCase::kAny>(heightMap, u, f, vT, wantHeight);
}

// Self-shadowing by a march from the shaded point (uvP, depth 1 - hP) up towards the light
// (lT: tangent space, normalised): 1 = lit. Each sample whose height field lies above the ray
// occludes by how far it lies above, weighted down with the distance along the march; the
// strongest occluder times kSelfShadowSharpness is the shadow (a soft edge, docs/parallax.md).
template <typename L, typename View>
TWR_LANE_OUTLINE L heightMarchShadow(const View& heightMap, const ShadeUniformsT<ScalarOf<L>>& u,
                                         const FragmentL<L>& f, const Vec2L<L>& uvP, const L& hP, const Vec3L<L>& lT) {
  using S = ScalarOf<L>;
  const L zero(S(0)), one(S(1));
  const L lz = maxOf(lT.z, L(static_cast<S>(kMinParallaxViewZ)));
  const L layers = layerCount<L>(u, lT);
  const L startDepth = one - hP;
  const L layerDepth = startDepth / layers;
  const L shiftPerLayer = L(u.heightScale) * startDepth / layers;
  const Vec2L<L> deltaUv(lT.x / lz * shiftPerLayer, lT.y / lz * shiftPerLayer);
  const HeightReadsL<L> reads = heightReads<L>(heightMap, u, f);
  L occlusion = zero;
  Vec2L<L> uvC = uvP;
  L depthC = startDepth;
  for (int i = 1; i <= u.layerCap; ++i) {
    const L index(static_cast<S>(i));
    const auto belowLast = index < layers;
    const auto underTop = depthC > zero;
    const auto marching = belowLast & underTop;
    if (!anyOf(marching)) break;
    uvC = Vec2L<L>(uvC.x + deltaUv.x, uvC.y + deltaUv.y);
    depthC = depthC - layerDepth;
    const L surfaceDepth = one - heightAt<L>(heightMap, u, reads, uvC, f);
    const L above = (depthC - surfaceDepth) * (one - index / layers);
    occlusion = select(marching, maxOf(occlusion, above), occlusion);
  }
  const L lit = one - minOf(occlusion * L(static_cast<S>(kSelfShadowSharpness)), one);
  return select(lT.z > zero, lit, zero);
}

// Horizon mapping (Max 1988; Sloan and Cohen 2000): the map stores, per texel and azimuth,
// the sine of the horizon's elevation (scene/horizon_map.h). The light's azimuth is a
// "diamond angle" in [0, 4) (monotonic in the true angle, no atan), so the two stored
// azimuths around it and the weight between them are found without trigonometry; the light
// is lit by how far its elevation sine lT.z clears the interpolated horizon.
template <typename L, typename Maps>
TWR_LANE_OUTLINE L horizonShadow(const Maps& maps, const ShadeUniformsT<ScalarOf<L>>& u, const FragmentL<L>& f,
                                     const Vec2L<L>& uvP, const Vec3L<L>& lT) {
  using S = ScalarOf<L>;
  const L zero(S(0)), one(S(1)), two(S(2)), four(S(4)), half(S(0.5));
  // Every azimuth's sine (4 per texel of each horizon texture).
  L horizon[kMaxHorizonDirections] = {};
  const int textures = u.horizonDirections / 4;
  for (int k = 0; k < textures; ++k) {
    const Vec4L<L> texel = sampleGrad<L>(*maps.horizon[static_cast<std::size_t>(k)], u, uvP, f.uvDxFine, f.uvDyFine);
    horizon[4 * k + 0] = texel.x;
    horizon[4 * k + 1] = texel.y;
    horizon[4 * k + 2] = texel.z;
    horizon[4 * k + 3] = texel.w;
  }
  // Diamond angle of (x, y): 0 along +x, 1 along +y, 2 along -x, 3 along -y.
  const L ax = absOf(lT.x), ay = absOf(lT.y);
  const L sum = maxOf(ax + ay, L(static_cast<S>(kMinLengthSquared)));
  const L q = ay / sum;  // in [0, 1] within the quadrant
  L diamond = select(lT.x >= zero, select(lT.y >= zero, q, four - q), select(lT.y >= zero, two - q, two + q));
  diamond = select(diamond >= four, diamond - four, diamond);
  const L position = diamond * L(static_cast<S>(u.horizonDirections)) / four;  // in [0, directions)
  const L k0f = minOf(floorOf(position), L(static_cast<S>(u.horizonDirections - 1)));
  const L weight = position - k0f;
  // Pick horizon[k0] and horizon[k0 + 1] lane by lane (k0 differs between lanes).
  L h0 = horizon[0], h1 = horizon[1];
  for (int k = 0; k < u.horizonDirections; ++k) {
    const auto here = k0f == L(static_cast<S>(k));
    h0 = select(here, horizon[k], h0);
    h1 = select(here, horizon[(k + 1) % u.horizonDirections], h1);
  }
  const L horizonSine = h0 + (h1 - h0) * weight;
  const L lit = minOf(maxOf(half + (lT.z - horizonSine) * L(static_cast<S>(kHorizonSharpness)), zero), one);
  return select(lT.z > zero, lit, zero);
}

TWR_LANES_END

#endif  // TWR_SURFACE_DETAIL_INL_EMIT
