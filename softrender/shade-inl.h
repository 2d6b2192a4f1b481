// Stage 7, shade, over any lane type: the one C++ source of shaders/phong.frag (shade.h has
// the model and docs/shading.md the derivation). Instantiated for float (the teaching path),
// double (the reference) and Highway vectors (the fast path); the same operations in the
// same order in every instantiation, so each lane of a vector gets the float path's bits.
// Shared source, included plainly and per Highway target (softrender/lanes.h).

#if defined(TWR_LANES_HIGHWAY)
#if defined(TWR_SHADE_INL_TARGET) == defined(HWY_TARGET_TOGGLE)
#ifdef TWR_SHADE_INL_TARGET
#undef TWR_SHADE_INL_TARGET
#else
#define TWR_SHADE_INL_TARGET
#endif
#define TWR_SHADE_INL_EMIT
#endif
#elif !defined(TWR_SHADE_INL_PLAIN)
#define TWR_SHADE_INL_PLAIN
#define TWR_SHADE_INL_EMIT
#endif

#ifdef TWR_SHADE_INL_EMIT
#undef TWR_SHADE_INL_EMIT

#include "softrender/environment-inl.h"
#include "softrender/environment_view-inl.h"
#include "softrender/interpolate-inl.h"
#include "softrender/lane_math-inl.h"
#include "softrender/lanes.h"
#include "softrender/phong_pow-inl.h"
#include "softrender/shadow-inl.h"
#include "softrender/surface_detail-inl.h"
#include "softrender/texture_sample-inl.h"

#include <cstddef>
#include <type_traits>

TWR_LANES_BEGIN


// If = 1 / max(A_C + A_L d + A_Q d^2, kMinAttenuationDenominator), evaluated as
// (A_C + A_L d) + (A_Q d) d: the order phong.frag writes it (tests/softrender/test_lanes.cpp
// shows that an equivalent form, Horner's, rounds differently).
template <typename L>
TWR_LANE_INLINE L attenuation(const Vec3T<ScalarOf<L>>& a, L d) {
  using S = ScalarOf<L>;
  const L denominator = (L(a.x) + L(a.y) * d) + (L(a.z) * d) * d;
  return L(S(1)) / maxOf(denominator, L(static_cast<S>(kMinAttenuationDenominator)));
}

// A spot light's cone at a point (lighting.glsl's spotFactor): smoothstep(cos outer, cos inner,
// cos angle) written out, the angle between the cone's axis and the way from the light to the
// point; toLight is the vector from the point to the light.
template <typename L>
TWR_LANE_INLINE L spotFactor(const LightUniformT<ScalarOf<L>>& light, const Vec3L<L>& toLight) {
  using S = ScalarOf<L>;
  const L zero(S(0)), one(S(1));
  const L cosAngle = zero - dot3<L>(Vec3L<L>(light.spotAxis), safeNormalize<L>(toLight));
  const L x = minOf(maxOf((cosAngle - L(light.spotCosOuter)) / L(light.spotCosRange), zero), one);
  return (x * x) * (L(S(3)) - L(S(2)) * x);
}

// The vector from p to a light: xyz - w p, with the light as lightVectorWorld gives it (w 1 for
// a point light, 0 for a directional one). phong.frag's toLightWorld.
template <typename L>
TWR_LANE_INLINE Vec3L<L> toLightWorld(const LightUniformT<ScalarOf<L>>& light, const Vec3L<L>& p) {
  const L w(light.vectorWorld.w);
  return Vec3L<L>(Vec3T<ScalarOf<L>>(light.vectorWorld)) - w * p;
}

// Which map a uv transform belongs to (ShadeUniformsT::uvTransform).
inline constexpr std::size_t kDiffuseSlot = 0, kNormalSlot = 1, kSpecularSlot = 2;

// One material map at `uv` (the fragment's, or where a parallax method moved it): the map's
// own uv transform first (phong.frag's <MAP>_UV_TRANSFORM, uv * scale + offset), then the LOD
// of the fragment's quad when the filter uses mipmaps (the differences scale with the
// transform), or with anisotropy the elliptical filter over the quad's differences. The
// differences are always the fragment's own (a shifted uv is read with textureGrad in GLSL).
template <typename L, typename View>
TWR_LANE_INLINE Vec4L<L> sampleMap(const View& map, const ShadeUniformsT<ScalarOf<L>>& u, std::size_t slot,
                                   const FragmentL<L>& f, const Vec2L<L>& uvIn, bool shifted) {
  using S = ScalarOf<L>;
  Vec2L<L> uv = uvIn, dx = shifted ? f.uvDxFine : f.uvDx, dy = shifted ? f.uvDyFine : f.uvDy;
  if (u.uvTransform[slot]) {
    const Vec2L<L> scale(L(u.uvScale[slot].x), L(u.uvScale[slot].y));
    const Vec2L<L> offset(L(u.uvOffset[slot].x), L(u.uvOffset[slot].y));
    uv = uv * scale + offset;
    dx = dx * scale;
    dy = dy * scale;
  }
  if (u.anisotropic) return sampleTextureAnisotropic<L>(map, uv, u.filter, dx, dy);
  const L lod = usesMipmaps(u.filter) ? quadLod<L>(dx, dy, texLevelWidth(map, 0), texLevelHeight(map, 0)) : L(S(0));
  return sampleTexture<L>(map, uv, u.filter, lod);
}

// Self-shadowing of one light by the height field (1 = lit) at the surface detail's uv; lT is
// the light in tangent space, normalised. Called only when a height map is bound.
template <typename L, typename Maps>
TWR_LANE_INLINE L selfShadow(const Maps& maps, const ShadeUniformsT<ScalarOf<L>>& u, const FragmentL<L>& f,
                             const SurfaceDetailL<L>& detail, const Vec3L<L>& lT) {
  using S = ScalarOf<L>;
  if (u.selfShadow == SelfShadow::HeightMarch) {
    return heightMarchShadow<L>(*maps.height, u, f, detail.uv, detail.height, lT);
  }
  if (u.selfShadow == SelfShadow::HorizonMap) return horizonShadow<L>(maps, u, f, detail.uv, lT);
  return L(S(1));
}

// What lighting reads of a surface at one fragment: the fragment's normalised frame, the
// surface detail (the parallax methods move the uv every map is read at; bump_blinn makes the
// normal; the rest read the height), the normal map's texel and the normal lighting uses (nl,
// in the lighting space). The shading and the environment's quad partners
// (setEnvironmentDifferences) both take it from here. wantHeight: the height at the
// shifted uv too (parallax).
template <typename L>
struct SurfaceFrameL {
  Vec3L<L> n, t, b;
  SurfaceDetailL<L> detail;
  Vec4L<L> normalTexel;
  Vec3L<L> mappedTangent;
  Vec3L<L> nl;
};
template <typename Features, typename L, typename Maps>
TWR_LANE_INLINE SurfaceFrameL<L> surfaceFrame(const FragmentL<L>& f, const ShadeUniformsT<ScalarOf<L>>& u,
                                              const Maps& maps, bool wantHeight) {
  using S = ScalarOf<L>;
  constexpr bool kTangentSpace = Features::kSpace == LightingSpace::Tangent;
  const L zero(S(0)), one(S(1)), two(S(2));
  SurfaceFrameL<L> s;
  s.n = safeNormalize<L>(f.nWorld);
  s.t = safeNormalize<L>(f.tWorld);
  s.b = safeNormalize<L>(f.bWorld);
  const Vec3L<L>& n = s.n;
  const Vec3L<L>& t = s.t;
  const Vec3L<L>& b = s.b;

  s.detail = SurfaceDetailL<L>{f.uv, one, zero, Vec3L<L>(zero, zero, one)};
  if constexpr (Features::kHasHeightMap) {
    if (shiftsUv(u.surfaceDetail)) {
      const Vec3L<L> eyeVec = kTangentSpace ? f.eyeDirTangent : Vec3L<L>(u.eyePosWorld) - f.posWorld;
      const Vec3L<L> vT = tangentFromLighting<L>(eyeVec, t, b, n, kTangentSpace);
      s.detail = parallax<L>(*maps.height, u, f, vT, wantHeight);
    } else {
      if (u.surfaceDetail == SurfaceDetail::BumpBlinn) s.detail.bumpTangent = bumpBlinn<L>(*maps.height, u, f);
      s.detail.height = heightAt<L>(*maps.height, u, f.uv, f);
    }
  }
  const bool uvShifted = Features::kHasHeightMap && shiftsUv(u.surfaceDetail);
  const bool bumpNormal = Features::kHasHeightMap && u.surfaceDetail == SurfaceDetail::BumpBlinn;

  s.mappedTangent = Vec3L<L>(zero, zero, one);
  s.normalTexel = Vec4L<L>(zero);
  if constexpr (Features::kHasNormalMap) {
    s.normalTexel = sampleMap<L>(*maps.normal, u, kNormalSlot, f, s.detail.uv, uvShifted);
    Vec3L<L> encoded(s.normalTexel.x, s.normalTexel.y, s.normalTexel.z);
    if (u.normalGreenDown) encoded.y = one - encoded.y;
    Vec3L<L> tangentNormal = two * encoded - one;
    if (u.normalXy) {
      tangentNormal.z = sqrtOf(maxOf(one - (tangentNormal.x * tangentNormal.x + tangentNormal.y * tangentNormal.y), zero));
    }
    if (u.normalStrengthOn) {
      const L strength(u.normalStrength);
      tangentNormal.x = tangentNormal.x * strength;
      tangentNormal.y = tangentNormal.y * strength;
    }
    s.mappedTangent = safeNormalize<L>(tangentNormal);
  }
  if (bumpNormal) s.mappedTangent = s.detail.bumpTangent;

  s.nl = n;
  if constexpr (kTangentSpace) {
    s.nl = s.mappedTangent;
  } else if (Features::kHasNormalMap || bumpNormal) {
    s.nl = safeNormalize<L>(t * s.mappedTangent.x + b * s.mappedTangent.y + n * s.mappedTangent.z);
  }
  return s;
}

// The environment's direction differences at pixel (px, py) of the quad whose first column
// and row are (qx, qy): GLSL's fine dFdx / dFdy of the reflected and refracted directions,
// which texture(samplerCube, ...) takes its LOD from (for a sphere or paraboloid map, the
// quad differences of the map's coordinate instead, layer_sample-inl.h). A GPU shades the quad's four pixels
// together (helper pixels included) and differences the values; here the pixel's row partner
// and column partner are interpolated from the triangle's planes and their directions found
// as the shading finds them (surfaceFrame, environmentDirections). The pixel itself
// is one end of both differences: three evaluations of the surface per pixel, paid only by a
// material that reads the environment.
template <typename Features, typename L, typename Maps>
TWR_LANE_OUTLINE void setEnvironmentDifferences(const VaryingPlanesL<L>& planes, const L& px, const L& py,
                                                const L& qx, const L& qy, const ShadeUniformsT<ScalarOf<L>>& u,
                                                const Maps& maps, FragmentL<L>& f) {
  using S = ScalarOf<L>;
  constexpr bool kTangentSpace = Features::kSpace == LightingSpace::Tangent;
  // The diffuse light and a prefiltered reflection are read at an explicit LOD.
  if (!u.environment.readsDifferences()) return;
  const UvPlanesL<L> uvPlanes{planes.overW[kVaryingUv], planes.overW[kVaryingUv + 1], planes.oneOverW};
  const auto directionsAt = [&](const L& x, const L& y) {
    FragmentL<L> g = interpolateFragment<L>(planes, x, y, f.depth);
    g.uvDx = f.uvDx;  // the same quad
    g.uvDy = f.uvDy;
    if (Features::kHasHeightMap) setFineUvDifferences<L>(uvPlanes, qx, qy, x, y, g);
    const SurfaceFrameL<L> frame = (surfaceFrame<Features, L>)(g, u, maps, false);
    const Vec3L<L> eyeVec = kTangentSpace ? g.eyeDirTangent : Vec3L<L>(u.eyePosWorld) - g.posWorld;
    return (environmentDirections<L>)(u.environment, frame.nl, eyeVec, frame.t, frame.b, frame.n, kTangentSpace);
  };
  const L one(S(1));
  if (u.environment.layers) {
    // A sphere or paraboloid map is a 2D texture: one LOD per quad, from the coordinate at
    // the quad's first pixel, the one to its right and the one above.
    const EnvironmentParameterization kind = u.environment.layers->kind;
    const EnvironmentDirectionsL<L> first = directionsAt(qx, qy);
    const EnvironmentDirectionsL<L> right = directionsAt(qx + one, qy);
    const EnvironmentDirectionsL<L> above = directionsAt(qx, qy + one);
    (mapDifferences<L>)(kind, first.reflectWorld, right.reflectWorld, above.reflectWorld, f.reflectDx, f.reflectDy);
    (mapDifferences<L>)(kind, first.refractWorld, right.refractWorld, above.refractWorld, f.refractDx, f.refractDy);
    return;
  }
  // The partners: the other column of the pixel's row, the other row of its column.
  const auto firstColumn = px == qx, firstRow = py == qy;
  const EnvironmentDirectionsL<L> own = directionsAt(px, py);
  const EnvironmentDirectionsL<L> rowPartner = directionsAt(select(firstColumn, qx + one, qx), py);
  const EnvironmentDirectionsL<L> columnPartner = directionsAt(px, select(firstRow, qy + one, qy));
  // right - left along the row, upper - lower along the column.
  const auto difference = [&](const auto& mask, const Vec3L<L>& pixel, const Vec3L<L>& partner) {
    return select3<L>(mask, partner - pixel, pixel - partner);
  };
  f.reflectDx = difference(firstColumn, own.reflectWorld, rowPartner.reflectWorld);
  f.reflectDy = difference(firstRow, own.reflectWorld, columnPartner.reflectWorld);
  f.refractDx = difference(firstColumn, own.refractWorld, rowPartner.refractWorld);
  f.refractDy = difference(firstRow, own.refractWorld, columnPartner.refractWorld);
}

// The material's own texels at the surface detail's uv: the diffuse map's albedo and the
// specular map's scale (1 without the map, or where the view reads no such map). phong.frag's
// albedo and specScale, whose #ifdefs are a uniform branch here: one kernel for a material
// with and without the maps.
template <typename L>
struct MaterialTexelsL {
  Vec3L<L> albedo, specScale;
};
template <typename Features, typename L, typename Maps>
TWR_LANE_INLINE MaterialTexelsL<L> materialTexels(const FragmentL<L>& f, const ShadeUniformsT<ScalarOf<L>>& u,
                                                  const Maps& maps, const SurfaceDetailL<L>& detail) {
  using S = ScalarOf<L>;
  const L one(S(1));
  // A shifted uv is read with GLSL's dFdx / dFdy (textureGrad), the fine differences.
  const bool uvShifted = Features::kHasHeightMap && shiftsUv(u.surfaceDetail);
  MaterialTexelsL<L> m{Vec3L<L>(one), Vec3L<L>(one)};
  if (maps.diffuse != nullptr && viewReadsDiffuseMap(u.view)) {
    const Vec4L<L> texel = sampleMap<L>(*maps.diffuse, u, kDiffuseSlot, f, detail.uv, uvShifted);
    m.albedo = Vec3L<L>(texel.x, texel.y, texel.z);
  }
  if (maps.specular != nullptr && viewReadsSpecularMap(u.view)) {
    const Vec4L<L> texel = sampleMap<L>(*maps.specular, u, kSpecularSlot, f, detail.uv, uvShifted);
    m.specScale = Vec3L<L>(texel.x, texel.y, texel.z);
  }
  return m;
}

// x^s for the specular term, s one uniform (forward shading) or one per lane (the deferred
// lighting pass reads it from the G-buffer): the same bits for the same s.
template <typename L, typename Shininess>
TWR_LANE_INLINE L specularPow(L x, const Shininess& s) {
  if constexpr (std::is_same_v<Shininess, ScalarOf<L>>) {
    return phongPow<L>(x, s);
  } else {
    return phongPowPerLane<L>(x, s);
  }
}

// Whether x^s is 0 at x = 0 for every lane: a uniform exponent above 0 (a per-lane one is not
// looked into). Lets lightSum skip pow where no lit lane faces the reflection.
template <typename S>
TWR_LANE_INLINE bool exponentAboveZero(const S& s) {
  if constexpr (std::is_arithmetic_v<S>) {
    return s > S(0);
  } else {
    return false;
  }
}

// The frame's lights at one surface point: shaders/lighting.glsl's lightSum, the loop the
// forward shading and the deferred lighting pass share. `frame` gives n (the interpolated
// normal: the shadow maps' slope), nl (the normal lighting uses, in the lighting space) and,
// for a height-mapped material, t, b and the surface detail; kdAlbedo and ksSpec are the
// diffuse and specular terms' first products. `f` is the fragment a forward shading reads the
// tangent-space light vectors and the height field's uv from; the deferred pass lights in
// world space without a height map and passes null.
template <typename L>
struct LightSumL {
  Vec3L<L> sum;                    // sum_i (diffuse + specular) If shadow
  ShadowTestL<L> firstShadowTest;  // the first shadowed light's test, for the shadow views
  L firstShadowCosine;
  bool haveShadowTest;
  // The Phong-term views' sums (isPhongTermView), each term as `sum` weighs it: kept only
  // in those views, a uniform branch per light.
  Vec3L<L> diffuseSum, specularSum;
};
// One light's shadow map (shadow-inl.h): tested only where it can matter (`wanted`: a lane the
// light lights, the shadow views, the trace), its visibility multiplied into `shadow`, the
// first light's test kept for the shadow views. Its angle is the geometric normal's, in world
// space. Returns whether it tested. GLSL: lighting.glsl's shadowMapStep.
template <typename L>
TWR_LANE_INLINE bool shadowMapStep(const LightUniformT<ScalarOf<L>>& light, const Vec3L<L>& posWorld,
                                   const Vec3L<L>& n, const Vec3L<L>& toLight, bool wanted, LightSumL<L>& out,
                                   L& shadow, ShadowTestL<L>& mapTest) {
  if (light.shadow.depth == nullptr || !wanted) return false;  // no map, or no lane it can matter to
  mapTest = (shadowTest<L>)(light.shadow, posWorld, n, safeNormalize<L>(toLight));
  shadow = shadow * mapTest.visibility;
  if (!out.haveShadowTest) {
    out.firstShadowTest = mapTest;
    out.firstShadowCosine = dot3<L>(n, safeNormalize<L>(toLight));
    out.haveShadowTest = true;
  }
  return true;
}

// One light's intermediate values, as the pixel trace shows them (scalar lanes only).
template <typename L>
struct LightStepL {
  Vec3L<L> lVec, vVec;
  L d;
  Vec3L<L> l, v, r;
  L nDotL, rDotV, attenuation, selfShadow;
  bool mapOn;
  ShadowTestL<L> mapTest;
  Vec3L<L> diffuse, specular;
};
template <typename L, typename LightTerms>
TWR_LANE_INLINE void traceLightStep(LightTerms& lt, const LightStepL<L>& s) {
  lt.lVec = s.lVec;
  lt.vVec = s.vVec;
  lt.distance = s.d;
  lt.l = s.l;
  lt.v = s.v;
  lt.r = s.r;
  lt.nDotL = s.nDotL;
  lt.rDotV = s.rDotV;
  lt.attenuation = s.attenuation;
  lt.selfShadow = s.selfShadow;
  lt.shadowOn = s.mapOn;
  lt.shadowVisibility = s.mapTest.visibility;
  lt.shadowDepth = s.mapTest.depth;
  lt.shadowBias = s.mapTest.bias;
  lt.shadowStored = s.mapTest.stored;
  lt.shadowReference = s.mapTest.reference;
  lt.shadowInside = s.mapTest.inside > L(ScalarOf<L>(0));
  lt.shadowTexel = decltype(lt.shadowTexel)(s.mapTest.texelX, s.mapTest.texelY, s.mapTest.layer);
  lt.diffuse = s.diffuse;
  lt.specular = s.specular;
}

template <typename Features, typename L, typename Maps, typename Shininess, typename Terms>
TWR_LANE_INLINE LightSumL<L> lightSum(const FragmentL<L>* f, const ShadeUniformsT<ScalarOf<L>>& u, const Maps& maps,
                                      const Vec3L<L>& posWorld, const SurfaceFrameL<L>& frame,
                                      const Vec3L<L>& kdAlbedo, const Vec3L<L>& ksSpec, const Shininess& shininess,
                                      Terms* terms) {
  using S = ScalarOf<L>;
  constexpr bool kTrace = !std::is_same_v<Terms, std::nullptr_t>;
  constexpr bool kTangentSpace = Features::kSpace == LightingSpace::Tangent;
  const L zero(S(0)), one(S(1)), two(S(2));
  const Vec3L<L>& n = frame.n;
  const Vec3L<L>& nl = frame.nl;
  const bool emboss = Features::kHasHeightMap && u.surfaceDetail == SurfaceDetail::BumpEmboss;
  const bool selfShadowOn = Features::kHasHeightMap && u.selfShadow != SelfShadow::None;
  const bool termSums = isPhongTermView(u.view);
  LightSumL<L> out{Vec3L<L>(zero), ShadowTestL<L>{one, zero, zero, one, zero, zero, zero, zero, zero, zero}, zero, false,
                   Vec3L<L>(zero), Vec3L<L>(zero)};
  if (u.lightCount == 0) return out;
  // The way to the eye, for every light. Tangent space: the vertex stage's (f is not null).
  const Vec3L<L> vVec = kTangentSpace ? f->eyeDirTangent : Vec3L<L>(u.eyePosWorld) - posWorld;
  const Vec3L<L> v = safeNormalize<L>(vVec);
  for (int i = 0; i < u.lightCount; ++i) {
    const LightUniformT<S>& light = u.lights[static_cast<std::size_t>(i)];
    const Vec3L<L> toLight = toLightWorld<L>(light, posWorld);
    const Vec3L<L> lVec = kTangentSpace ? f->lightDirTangent[static_cast<std::size_t>(i)] : toLight;
    const L d = length3<L>(toLight);
    const Vec3L<L> l = safeNormalize<L>(lVec);
    const L nDotL = dot3<L>(nl, l);
    const Vec3L<L> r = (two * nDotL) * nl - l;
    const L rDotV = maxOf(dot3<L>(r, v), zero);
    L falloff = attenuation<L>(light.attenuation, d);
    if (light.spot) falloff = falloff * spotFactor<L>(light, toLight);
    L diffuseFactor = maxOf(nDotL, zero);
    L selfShadowValue = one;
    if constexpr (Features::kHasHeightMap) {
      Vec3L<L> lT(zero, zero, one);  // the light in tangent space (emboss and self-shadowing)
      if (emboss || selfShadowOn) lT = tangentFromLighting<L>(lVec, frame.t, frame.b, n, kTangentSpace);
      if (emboss) {
        // Emboss: N'.L ~ N.L + s (h(uv) - h(uv + lT.xy d)) / d, d = one texel: Blinn's first
        // order term along the light, from two height samples; diffuse only.
        const L texel(u.heightTexel.x);
        const L hShifted =
            heightAt<L>(*maps.height, u, Vec2L<L>(f->uv.x + lT.x * texel, f->uv.y + lT.y * texel), *f);
        diffuseFactor = maxOf(nDotL + L(u.heightScale) * (frame.detail.height - hShifted) / texel, zero);
      }
      if (selfShadowOn) selfShadowValue = selfShadow<L>(maps, u, *f, frame.detail, lT);
    }
    const Vec3L<L> diffuse = (kdAlbedo * diffuseFactor) * Vec3L<L>(light.diffuse);
    // The specular term only where N.L > 0, and pow only when some lane needs it: a lit lane
    // that faces the reflection (R.V > 0), or any lit lane when the exponent may be 0 (0^0 = 1).
    const auto lit = nDotL > zero;
    const auto litFacing = lit & (rDotV > zero);  // named: masks combine with &, never &&
    Vec3L<L> specular(zero);
    if (!emboss && anyOf(lit) && (!exponentAboveZero(shininess) || anyOf(litFacing))) {
      specular = select3<L>(lit, (ksSpec * specularPow<L>(rDotV, shininess)) * Vec3L<L>(light.specular), specular);
    }
    L shadow = selfShadowValue;
    ShadowTestL<L> mapTest{one, zero, zero, one, zero, zero, zero, zero, zero, zero};
    // A runtime branch per light, never taken by a light without a map (nor its lanes' mask read).
    const bool mapOn = light.shadow.depth != nullptr &&
                       (shadowMapStep<L>)(light, posWorld, n, toLight,
                                          kTrace || isShadowView(u.view) || anyOf((diffuseFactor > zero) | lit), out,
                                          shadow, mapTest);
    if (selfShadowOn || mapOn) {
      out.sum += ((diffuse + specular) * falloff) * shadow;
    } else {
      out.sum += (diffuse + specular) * falloff;
    }
    if (termSums) {
      out.diffuseSum += (diffuse * falloff) * shadow;
      out.specularSum += (specular * falloff) * shadow;
    }
    if constexpr (kTrace) {
      if (terms) {
        traceLightStep<L>(terms->lights[static_cast<std::size_t>(i)],
                          {lVec, vVec, d, l, v, r, nDotL, rDotV, falloff, selfShadowValue, mapOn, mapTest, diffuse, specular});
      }
    }
  }
  return out;
}

// What no light scales, summed first: the ambient term, then the environment's diffuse light
// added as the lights' diffuse terms are (kd albedo times it). The forward shading adds the
// lights to it; the deferred pipeline's G-buffer pass stores it (gbufferFragment).
template <typename L>
struct UnlitTermsL {
  Vec3L<L> ambient, environmentDiffuse, unlit;
};
template <typename Features, typename L>
TWR_LANE_INLINE UnlitTermsL<L> unlitTerms(const ShadeUniformsT<ScalarOf<L>>& u, const SurfaceFrameL<L>& frame,
                                          const Vec3L<L>& albedo, const Vec3L<L>& kdAlbedo) {
  using S = ScalarOf<L>;
  constexpr bool kTangentSpace = Features::kSpace == LightingSpace::Tangent;
  UnlitTermsL<L> out;
  out.ambient = (Vec3L<L>(u.ka) * albedo) * Vec3L<L>(u.ambient);
  out.environmentDiffuse = Vec3L<L>(L(S(0)));
  out.unlit = out.ambient;
  if (u.environment.cube && u.environment.diffuse != EnvironmentDiffuse::None) {
    out.environmentDiffuse = (environmentDiffuse<L>)(u.environment, frame.nl, frame.t, frame.b, frame.n, kTangentSpace);
    out.unlit = out.unlit + kdAlbedo * out.environmentDiffuse;
  }
  return out;
}

// A Phong-term view's colour (isPhongTermView): the ambient term, or the lights' diffuse or
// specular terms summed, alpha 1. GLSL: phong.frag's phongTermColour.
template <typename L>
TWR_LANE_INLINE Vec4L<L> phongTermColour(View view, const Vec3L<L>& ambientTerm, const LightSumL<L>& lit) {
  const L one(ScalarOf<L>(1));
  if (view == View::Ambient) return Vec4L<L>(ambientTerm, one);
  if (view == View::Diffuse) return Vec4L<L>(lit.diffuseSum, one);
  return Vec4L<L>(lit.specularSum, one);
}

// The pixel trace's surface terms (scalar lanes only): the frame and the material's texels.
template <typename L, typename Terms>
TWR_LANE_INLINE void traceSurfaceTerms(Terms* terms, const SurfaceFrameL<L>& frame, const MaterialTexelsL<L>& texels) {
  if constexpr (!std::is_same_v<Terms, std::nullptr_t>) {
    if (!terms) return;
    terms->n = frame.n;
    terms->t = frame.t;
    terms->b = frame.b;
    terms->albedo = texels.albedo;
    terms->specScale = texels.specScale;
    terms->normalTexel = frame.normalTexel;
    terms->mappedTangent = frame.mappedTangent;
    terms->nl = frame.nl;
    terms->uvShifted = frame.detail.uv;
    terms->height = frame.detail.height;
    terms->parallaxSteps = frame.detail.steps;
  }
}

// The environment mixed into the Phong colour, or one of its views; an environment view on a
// surface that reads no reflection is dimmed to grey. GLSL: phong.frag's environmentStep.
template <typename Features, typename L, typename Terms>
TWR_LANE_INLINE Vec4L<L> environmentStep(const FragmentL<L>& f, const ShadeUniformsT<ScalarOf<L>>& u,
                                         const SurfaceFrameL<L>& frame, Vec4L<L> colour, Terms* terms) {
  using S = ScalarOf<L>;
  constexpr bool kTangentSpace = Features::kSpace == LightingSpace::Tangent;
  if (!(u.environment.cube && u.environment.readsDirections())) {
    return isEnvironmentView(u.view) ? (dimmedColour<L>)(colour) : colour;
  }
  const Vec3L<L> eyeVec = kTangentSpace ? f.eyeDirTangent : Vec3L<L>(u.eyePosWorld) - f.posWorld;
  const Vec3L<L> phong(colour.x, colour.y, colour.z);
  const EnvironmentDirectionsL<L> directions =
      (environmentDirections<L>)(u.environment, frame.nl, eyeVec, frame.t, frame.b, frame.n, kTangentSpace);
  const EnvironmentTermsL<L> env = (environmentMix<L>)(u.environment, directions, f, phong);
  colour = Vec4L<L>(env.colour, L(S(1)));
  if (isEnvironmentView(u.view)) {
    const EnvironmentParameterization kind =
        u.environment.layers ? u.environment.layers->kind : EnvironmentParameterization::Cube;
    const int levels = u.environment.prefiltered
                           ? u.environment.specularCube->levelCount()
                           : (u.environment.layers ? u.environment.layers->levelCount() : u.environment.cube->levelCount());
    colour = (environmentViewColour<L>)(u.view, kind, env.reflectWorld, (clampedLod<L>)(env.reflectLod, levels));
  }
  if constexpr (!std::is_same_v<Terms, std::nullptr_t>) {
    if (terms) {
      terms->environmentOn = true;
      terms->reflectWorld = env.reflectWorld;
      terms->refractWorld = env.refractWorld;
      terms->environmentReflected = env.reflected;
      terms->environmentTransmitted = env.transmitted;
      terms->environmentShare = env.share;
      terms->environmentReflectLod = env.reflectLod;
      terms->environmentPrefiltered = u.environment.prefiltered;
      terms->totalInternalReflection = env.totalInternal;
      terms->phongColour = phong;
    }
  }
  return colour;
}

// The shadow views (shadow-inl.h): the first shadowed light's test, or dimmed without one.
// GLSL: phong.frag's shadowViewStep.
template <typename L>
TWR_LANE_INLINE Vec4L<L> shadowViewStep(View view, const LightSumL<L>& lit, const Vec4L<L>& colour) {
  if (!isShadowView(view)) return colour;
  if (!lit.haveShadowTest) return (dimmedColour<L>)(colour);
  if (view == View::Shadow) return (shadowViewColour<L>)(lit.firstShadowTest, lit.firstShadowCosine);
  return (lightDepthColour<L>)(lit.firstShadowTest);
}

// The shaded view: the unlit terms, the lights, the environment, then the shadow or Phong-term
// view in place of the colour. GLSL: phong.frag's shadedColour.
template <typename Features, typename L, typename Maps, typename Terms>
TWR_LANE_INLINE Vec4L<L> shadedColour(const FragmentL<L>& f, const ShadeUniformsT<ScalarOf<L>>& u, const Maps& maps,
                                      const SurfaceFrameL<L>& frame, const MaterialTexelsL<L>& texels,
                                      Terms* terms) {
  using S = ScalarOf<L>;
  const Vec3L<L> kdAlbedo = Vec3L<L>(u.kd) * texels.albedo;     // u.kd * albedo, diffuse's first product
  const Vec3L<L> ksSpec = Vec3L<L>(u.ks) * texels.specScale;    // u.ks * specScale, specular's first
  const UnlitTermsL<L> unlit = (unlitTerms<Features, L>)(u, frame, texels.albedo, kdAlbedo);
  const LightSumL<L> lit = (lightSum<Features, L>)(&f, u, maps, f.posWorld, frame, kdAlbedo, ksSpec, u.shininess, terms);
  Vec4L<L> colour(unlit.unlit + lit.sum, L(S(1)));
  if constexpr (!std::is_same_v<Terms, std::nullptr_t>) {
    if (terms) {
      if (u.environment.cube) {
        terms->environmentDiffuseOn = u.environment.diffuse != EnvironmentDiffuse::None;
        terms->environmentDiffuse = unlit.environmentDiffuse;
      }
      terms->ambient = unlit.ambient;
      terms->diffuseSum = lit.diffuseSum;
      terms->specularSum = lit.specularSum;
      terms->lightCount = u.lightCount;
    }
  }
  colour = (environmentStep<Features, L>)(f, u, frame, colour, terms);
  colour = (shadowViewStep<L>)(u.view, lit, colour);
  if (isPhongTermView(u.view)) colour = (phongTermColour<L>)(u.view, unlit.ambient, lit);
  return colour;
}

// A tangent-space direction view: the first light's or the eye's direction in the fragment's
// tangent frame; no light gives (0, 0, 0), shown as grey 0.5. GLSL: phong.frag's
// tangentDirectionColour.
template <typename Features, typename L>
TWR_LANE_INLINE Vec4L<L> tangentDirectionColour(const FragmentL<L>& f, const ShadeUniformsT<ScalarOf<L>>& u,
                                                const SurfaceFrameL<L>& s, bool toLight) {
  using S = ScalarOf<L>;
  Vec3L<L> dirTangent(L(S(0)));
  if (!toLight || u.lightCount > 0) {
    if constexpr (Features::kSpace == LightingSpace::Tangent) {
      dirTangent = safeNormalize<L>(toLight ? f.lightDirTangent[0] : f.eyeDirTangent);
    } else {
      const Vec3L<L> w = toLight ? toLightWorld<L>(u.lights[0], f.posWorld) : Vec3L<L>(u.eyePosWorld) - f.posWorld;
      dirTangent = safeNormalize<L>(Vec3L<L>(dot3<L>(s.t, w), dot3<L>(s.b, w), dot3<L>(s.n, w)));
    }
  }
  return vectorAsColour<L>(dirTangent);
}

// The first light's self-shadowing factor as grey (1 without self-shadowing or lights).
// GLSL: phong.frag's selfShadowColour.
template <typename Features, typename L, typename Maps>
TWR_LANE_INLINE Vec4L<L> selfShadowColour(const FragmentL<L>& f, const ShadeUniformsT<ScalarOf<L>>& u,
                                          const Maps& maps, const SurfaceFrameL<L>& s) {
  using S = ScalarOf<L>;
  constexpr bool kTangentSpace = Features::kSpace == LightingSpace::Tangent;
  L shadow(S(1));
  if (Features::kHasHeightMap && u.selfShadow != SelfShadow::None && u.lightCount > 0) {
    const Vec3L<L> lVec0 = kTangentSpace ? f.lightDirTangent[0] : toLightWorld<L>(u.lights[0], f.posWorld);
    shadow = selfShadow<L>(maps, u, f, s.detail, tangentFromLighting<L>(lVec0, s.t, s.b, s.n, kTangentSpace));
  }
  return Vec4L<L>(shadow, shadow, shadow, L(S(1)));
}

// The debug views, one value of the surface as a colour (docs/shading.md); a branch on
// the view, the same for every lane. GLSL: phong.frag's debugViewColour, in the same order.
template <typename Features, typename L, typename Maps>
TWR_LANE_INLINE Vec4L<L> debugViewColour(const FragmentL<L>& f, const ShadeUniformsT<ScalarOf<L>>& u,
                                         const Maps& maps, const SurfaceFrameL<L>& s,
                                         const MaterialTexelsL<L>& m) {
  using S = ScalarOf<L>;
  const L zero(S(0)), one(S(1)), half(S(0.5));
  switch (u.view) {
    case View::Albedo: return Vec4L<L>(m.albedo * Vec3L<L>(u.kd), one);
    case View::Normal: return vectorAsColour<L>(s.n);
    case View::Tangent: return vectorAsColour<L>(s.t);
    case View::Bitangent: return vectorAsColour<L>(s.b);
    case View::MappedNormal: return vectorAsColour<L>(s.nl);
    case View::Uv: return Vec4L<L>(f.uv.x - floorOf(f.uv.x), f.uv.y - floorOf(f.uv.y), zero, one);
    case View::Depth: return Vec4L<L>(f.depth, f.depth, f.depth, one);
    case View::LightTangent: return (tangentDirectionColour<Features, L>)(f, u, s, true);
    case View::EyeTangent: return (tangentDirectionColour<Features, L>)(f, u, s, false);
    case View::Height: return Vec4L<L>(s.detail.height, s.detail.height, s.detail.height, one);
    case View::ParallaxOffset: {
      const L gain(static_cast<S>(kParallaxOffsetViewGain));
      return Vec4L<L>(half + (s.detail.uv.x - f.uv.x) * gain, half + (s.detail.uv.y - f.uv.y) * gain, half, one);
    }
    case View::ParallaxSteps: return heatColour<L>(s.detail.steps / L(static_cast<S>(u.layerCap + u.refinementSteps)));
    case View::SelfShadow: return (selfShadowColour<Features, L>)(f, u, maps, s);
    default: return Vec4L<L>(zero, zero, zero, one);  // fragmentViewOf leaves no other view here
  }
}

// Shades one fragment per lane with the permutation `Features` (shade.h's ShaderFeatures) in
// the view u.view. `maps` holds the material's textures as the lane type reads them (members
// diffuse, normal, specular: pointers to views, see texture_sample-inl.h); `terms`, when not
// null, receives every intermediate value (the pixel trace; scalar lanes only, nullptr_t
// otherwise). GLSL: phong.frag's main.
template <typename Features, typename L, typename Maps, typename Terms>
TWR_LANE_INLINE Vec4L<L> shadeFragment(const FragmentL<L>& f, const ShadeUniformsT<ScalarOf<L>>& u, const Maps& maps,
                                       Terms* terms) {
  constexpr bool kTrace = !std::is_same_v<Terms, std::nullptr_t>;
  const bool wantHeight = kTrace || u.view == View::Height || u.selfShadow == SelfShadow::HeightMarch;
  const SurfaceFrameL<L> frame = (surfaceFrame<Features, L>)(f, u, maps, wantHeight);
  const MaterialTexelsL<L> texels = (materialTexels<Features, L>)(f, u, maps, frame.detail);
  traceSurfaceTerms<L>(terms, frame, texels);
  Vec4L<L> colour = isShadedView(u.view) ? (shadedColour<Features, L>)(f, u, maps, frame, texels, terms)
                                         : (debugViewColour<Features, L>)(f, u, maps, frame, texels);
  colour = clampUnit4<L>(colour);
  if constexpr (kTrace) {
    if (terms) terms->colour = colour;
  }
  return colour;
}

TWR_LANES_END

#endif  // TWR_SHADE_INL_EMIT
