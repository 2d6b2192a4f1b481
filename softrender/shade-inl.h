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
TWR_LANE_INLINE L attenuationLanes(const Vec3T<ScalarOf<L>>& a, L d) {
  using S = ScalarOf<L>;
  const L denominator = (L(a.x) + L(a.y) * d) + (L(a.z) * d) * d;
  return L(S(1)) / maxOf(denominator, L(static_cast<S>(kMinAttenuationDenominator)));
}

// A spot light's cone at a point (lighting.glsl's spotFactor): smoothstep(cos outer, cos inner,
// cos angle) written out, the angle between the cone's axis and the way from the light to the
// point; toLight is the vector from the point to the light.
template <typename L>
TWR_LANE_INLINE L spotFactorLanes(const LightUniformT<ScalarOf<L>>& light, const Vec3L<L>& toLight) {
  using S = ScalarOf<L>;
  const L zero(S(0)), one(S(1));
  const L cosAngle = zero - dot3<L>(Vec3L<L>(light.spotAxis), safeNormalize3<L>(toLight));
  const L x = minOf(maxOf((cosAngle - L(light.spotCosOuter)) / L(light.spotCosRange), zero), one);
  return (x * x) * (L(S(3)) - L(S(2)) * x);
}

// The vector from p to a light: xyz - w p, with the light as lightVectorWorld gives it (w 1 for
// a point light, 0 for a directional one). phong.frag's toLightWorld.
template <typename L>
TWR_LANE_INLINE Vec3L<L> toLightLanes(const LightUniformT<ScalarOf<L>>& light, const Vec3L<L>& p) {
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
TWR_LANE_INLINE Vec4L<L> sampleMapLanes(const View& map, const ShadeUniformsT<ScalarOf<L>>& u, std::size_t slot,
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
  if (u.anisotropic) return sampleTextureAnisotropicLanes<L>(map, uv, u.filter, dx, dy);
  const L lod = usesMipmaps(u.filter) ? quadLodLanes<L>(dx, dy, texLevelWidth(map, 0), texLevelHeight(map, 0)) : L(S(0));
  return sampleTextureLanes<L>(map, uv, u.filter, lod);
}

// Self-shadowing of one light by the height field (1 = lit) at the surface detail's uv; lT is
// the light in tangent space, normalised. Called only when a height map is bound.
template <typename L, typename Maps>
TWR_LANE_INLINE L selfShadowLanes(const Maps& maps, const ShadeUniformsT<ScalarOf<L>>& u, const FragmentL<L>& f,
                                  const SurfaceDetailL<L>& detail, const Vec3L<L>& lT) {
  using S = ScalarOf<L>;
  if (u.selfShadow == SelfShadow::HeightMarch) {
    return heightMarchShadowLanes<L>(*maps.height, u, f, detail.uv, detail.height, lT);
  }
  if (u.selfShadow == SelfShadow::HorizonMap) return horizonShadowLanes<L>(maps, u, f, detail.uv, lT);
  return L(S(1));
}

// What lighting reads of a surface at one fragment: the fragment's normalised frame, the
// surface detail (the parallax methods move the uv every map is read at; bump_blinn makes the
// normal; the rest read the height), the normal map's texel and the normal lighting uses (nl,
// in the lighting space). The shading and the environment's quad partners
// (setEnvironmentDifferencesLanes) both take it from here. wantHeight: the height at the
// shifted uv too (parallaxLanes).
template <typename L>
struct SurfaceFrameL {
  Vec3L<L> n, t, b;
  SurfaceDetailL<L> detail;
  Vec4L<L> normalTexel;
  Vec3L<L> mappedTangent;
  Vec3L<L> nl;
};
template <typename Features, typename L, typename Maps>
TWR_LANE_INLINE SurfaceFrameL<L> surfaceFrameLanes(const FragmentL<L>& f, const ShadeUniformsT<ScalarOf<L>>& u,
                                                   const Maps& maps, bool wantHeight) {
  using S = ScalarOf<L>;
  constexpr bool kTangentSpace = Features::kSpace == LightingSpace::Tangent;
  const L zero(S(0)), one(S(1)), two(S(2));
  SurfaceFrameL<L> s;
  s.n = safeNormalize3<L>(f.nWorld);
  s.t = safeNormalize3<L>(f.tWorld);
  s.b = safeNormalize3<L>(f.bWorld);
  const Vec3L<L>& n = s.n;
  const Vec3L<L>& t = s.t;
  const Vec3L<L>& b = s.b;

  s.detail = SurfaceDetailL<L>{f.uv, one, zero, Vec3L<L>(zero, zero, one)};
  if constexpr (Features::kHasHeightMap) {
    if (shiftsUv(u.surfaceDetail)) {
      const Vec3L<L> eyeVec = kTangentSpace ? f.eyeDirTangent : Vec3L<L>(u.eyePosWorld) - f.posWorld;
      const Vec3L<L> vT = tangentFromLightingLanes<L>(eyeVec, t, b, n, kTangentSpace);
      s.detail = parallaxLanes<L>(*maps.height, u, f, vT, wantHeight);
    } else {
      if (u.surfaceDetail == SurfaceDetail::BumpBlinn) s.detail.bumpTangent = bumpBlinnLanes<L>(*maps.height, u, f);
      s.detail.height = heightAtLanes<L>(*maps.height, u, f.uv, f);
    }
  }
  const bool uvShifted = Features::kHasHeightMap && shiftsUv(u.surfaceDetail);
  const bool bumpNormal = Features::kHasHeightMap && u.surfaceDetail == SurfaceDetail::BumpBlinn;

  s.mappedTangent = Vec3L<L>(zero, zero, one);
  s.normalTexel = Vec4L<L>(zero);
  if constexpr (Features::kHasNormalMap) {
    s.normalTexel = sampleMapLanes<L>(*maps.normal, u, kNormalSlot, f, s.detail.uv, uvShifted);
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
    s.mappedTangent = safeNormalize3<L>(tangentNormal);
  }
  if (bumpNormal) s.mappedTangent = s.detail.bumpTangent;

  s.nl = n;
  if constexpr (kTangentSpace) {
    s.nl = s.mappedTangent;
  } else if (Features::kHasNormalMap || bumpNormal) {
    s.nl = safeNormalize3<L>(t * s.mappedTangent.x + b * s.mappedTangent.y + n * s.mappedTangent.z);
  }
  return s;
}

// The environment's direction differences at pixel (px, py) of the quad whose first column
// and row are (qx, qy): GLSL's fine dFdx / dFdy of the reflected and refracted directions,
// which texture(samplerCube, ...) takes its LOD from (for a sphere or paraboloid map, the
// quad differences of the map's coordinate instead, layer_sample-inl.h). A GPU shades the quad's four pixels
// together (helper pixels included) and differences the values; here the pixel's row partner
// and column partner are interpolated from the triangle's planes and their directions found
// as the shading finds them (surfaceFrameLanes, environmentDirectionsLanes). The pixel itself
// is one end of both differences: three evaluations of the surface per pixel, paid only by a
// material that reads the environment.
template <typename Features, typename L, typename Maps>
TWR_LANE_OUTLINE void setEnvironmentDifferencesLanes(const VaryingPlanesL<L>& planes, const L& px, const L& py,
                                                     const L& qx, const L& qy, const ShadeUniformsT<ScalarOf<L>>& u,
                                                     const Maps& maps, FragmentL<L>& f) {
  using S = ScalarOf<L>;
  constexpr bool kTangentSpace = Features::kSpace == LightingSpace::Tangent;
  // The diffuse light and a prefiltered reflection are read at an explicit LOD.
  if (!u.environment.readsDifferences()) return;
  const UvPlanesL<L> uvPlanes{planes.overW[kVaryingUv], planes.overW[kVaryingUv + 1], planes.oneOverW};
  const auto directionsAt = [&](const L& x, const L& y) {
    FragmentL<L> g = interpolateFragmentLanes<L>(planes, x, y, f.depth);
    g.uvDx = f.uvDx;  // the same quad
    g.uvDy = f.uvDy;
    if (Features::kHasHeightMap) setFineUvDifferencesLanes<L>(uvPlanes, qx, qy, x, y, g);
    const SurfaceFrameL<L> frame = (surfaceFrameLanes<Features, L>)(g, u, maps, false);
    const Vec3L<L> eyeVec = kTangentSpace ? g.eyeDirTangent : Vec3L<L>(u.eyePosWorld) - g.posWorld;
    return (environmentDirectionsLanes<L>)(u.environment, frame.nl, eyeVec, frame.t, frame.b, frame.n, kTangentSpace);
  };
  const L one(S(1));
  if (u.environment.layers) {
    // A sphere or paraboloid map is a 2D texture: one LOD per quad, from the coordinate at
    // the quad's first pixel, the one to its right and the one above.
    const EnvironmentParameterization kind = u.environment.layers->kind;
    const EnvironmentDirectionsL<L> first = directionsAt(qx, qy);
    const EnvironmentDirectionsL<L> right = directionsAt(qx + one, qy);
    const EnvironmentDirectionsL<L> above = directionsAt(qx, qy + one);
    (mapDifferencesLanes<L>)(kind, first.reflectWorld, right.reflectWorld, above.reflectWorld, f.reflectDx, f.reflectDy);
    (mapDifferencesLanes<L>)(kind, first.refractWorld, right.refractWorld, above.refractWorld, f.refractDx, f.refractDy);
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
// specular map's scale (1 without the map). phong.frag's albedo and specScale.
template <typename L>
struct MaterialTexelsL {
  Vec3L<L> albedo, specScale;
};
template <typename Features, typename L, typename Maps>
TWR_LANE_INLINE MaterialTexelsL<L> materialTexelsLanes(const FragmentL<L>& f, const ShadeUniformsT<ScalarOf<L>>& u,
                                                       const Maps& maps, const SurfaceDetailL<L>& detail) {
  using S = ScalarOf<L>;
  const L one(S(1));
  // A shifted uv is read with GLSL's dFdx / dFdy (textureGrad), the fine differences.
  const bool uvShifted = Features::kHasHeightMap && shiftsUv(u.surfaceDetail);
  MaterialTexelsL<L> m{Vec3L<L>(one), Vec3L<L>(one)};
  if constexpr (Features::kHasDiffuseMap) {
    const Vec4L<L> texel = sampleMapLanes<L>(*maps.diffuse, u, kDiffuseSlot, f, detail.uv, uvShifted);
    m.albedo = Vec3L<L>(texel.x, texel.y, texel.z);
  }
  if constexpr (Features::kHasSpecularMap) {
    const Vec4L<L> texel = sampleMapLanes<L>(*maps.specular, u, kSpecularSlot, f, detail.uv, uvShifted);
    m.specScale = Vec3L<L>(texel.x, texel.y, texel.z);
  }
  return m;
}

// x^s for the specular term, s one uniform (forward shading) or one per lane (the deferred
// lighting pass reads it from the G-buffer): the same bits for the same s.
template <typename L, typename Shininess>
TWR_LANE_INLINE L specularPowLanes(L x, const Shininess& s) {
  if constexpr (std::is_same_v<Shininess, ScalarOf<L>>) {
    return phongPow<L>(x, s);
  } else {
    return phongPowPerLane<L>(x, s);
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
template <typename Features, typename L, typename Maps, typename Shininess, typename Terms>
TWR_LANE_INLINE LightSumL<L> lightSumLanes(const FragmentL<L>* f, const ShadeUniformsT<ScalarOf<L>>& u, const Maps& maps,
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
  const bool termSums = isPhongTermView(u.shadedView);
  LightSumL<L> out{Vec3L<L>(zero), ShadowTestL<L>{one, zero, zero, one, zero, zero, zero, zero, zero, zero}, zero, false,
                   Vec3L<L>(zero), Vec3L<L>(zero)};
  for (int i = 0; i < u.lightCount; ++i) {
    const LightUniformT<S>& light = u.lights[static_cast<std::size_t>(i)];
    const Vec3L<L> toLight = toLightLanes<L>(light, posWorld);
    Vec3L<L> lVec, vVec;
    if constexpr (kTangentSpace) {
      lVec = f->lightDirTangent[static_cast<std::size_t>(i)];
      vVec = f->eyeDirTangent;
    } else {
      lVec = toLight;
      vVec = Vec3L<L>(u.eyePosWorld) - posWorld;
    }
    const L d = lengthOf<L>(toLight);
    const Vec3L<L> l = safeNormalize3<L>(lVec);
    const Vec3L<L> v = safeNormalize3<L>(vVec);
    const L nDotL = dot3<L>(nl, l);
    const Vec3L<L> r = (two * nDotL) * nl - l;
    const L rDotV = maxOf(dot3<L>(r, v), zero);
    L attenuation = attenuationLanes<L>(light.attenuation, d);
    if (light.spot) attenuation = attenuation * spotFactorLanes<L>(light, toLight);
    L diffuseFactor = maxOf(nDotL, zero);
    L selfShadowValue = one;
    if constexpr (Features::kHasHeightMap) {
      Vec3L<L> lT(zero, zero, one);  // the light in tangent space (emboss and self-shadowing)
      if (emboss || selfShadowOn) lT = tangentFromLightingLanes<L>(lVec, frame.t, frame.b, n, kTangentSpace);
      if (emboss) {
        // Emboss: N'.L ~ N.L + s (h(uv) - h(uv + lT.xy d)) / d, d = one texel: Blinn's first
        // order term along the light, from two height samples; diffuse only.
        const L texel(u.heightTexel.x);
        const L hShifted =
            heightAtLanes<L>(*maps.height, u, Vec2L<L>(f->uv.x + lT.x * texel, f->uv.y + lT.y * texel), *f);
        diffuseFactor = maxOf(nDotL + L(u.heightScale) * (frame.detail.height - hShifted) / texel, zero);
      }
      if (selfShadowOn) selfShadowValue = selfShadowLanes<L>(maps, u, *f, frame.detail, lT);
    }
    const Vec3L<L> diffuse = (kdAlbedo * diffuseFactor) * Vec3L<L>(light.diffuse);
    // The specular term only where N.L > 0 (and pow only when some lane needs it).
    const auto lit = nDotL > zero;
    Vec3L<L> specular(zero);
    if (!emboss && anyOf(lit)) {
      specular = select3<L>(lit, (ksSpec * specularPowLanes<L>(rDotV, shininess)) * Vec3L<L>(light.specular), specular);
    }
    L shadow = selfShadowValue;
    // The light's shadow map (shadow-inl.h): a runtime branch per light, never taken by a
    // light without one. Its angle is the geometric normal's, in world space.
    ShadowTestL<L> mapTest{one, zero, zero, one, zero, zero, zero, zero, zero, zero};
    // Tested only where it can matter: a lane the light lights (diffuse or specular), the
    // shadow views and the trace; elsewhere both terms are 0 and so is their product with it.
    const bool mapOn = light.shadow.depth != nullptr &&
                       (kTrace || isShadowView(u.shadedView) || anyOf((diffuseFactor > zero) | lit));
    if (mapOn) {
      mapTest = (shadowTestLanes<L>)(light.shadow, posWorld, n, safeNormalize3<L>(toLight));
      shadow = shadow * mapTest.visibility;
      if (!out.haveShadowTest) {
        out.firstShadowTest = mapTest;
        out.firstShadowCosine = dot3<L>(n, safeNormalize3<L>(toLight));
        out.haveShadowTest = true;
      }
    }
    if (selfShadowOn || mapOn) {
      out.sum += ((diffuse + specular) * attenuation) * shadow;
    } else {
      out.sum += (diffuse + specular) * attenuation;
    }
    if (termSums) {
      out.diffuseSum += (diffuse * attenuation) * shadow;
      out.specularSum += (specular * attenuation) * shadow;
    }
    if constexpr (kTrace) {
      if (terms) {
        auto& lt = terms->lights[static_cast<std::size_t>(i)];
        lt.lVec = lVec;
        lt.vVec = vVec;
        lt.distance = d;
        lt.l = l;
        lt.v = v;
        lt.r = r;
        lt.nDotL = nDotL;
        lt.rDotV = rDotV;
        lt.attenuation = attenuation;
        lt.selfShadow = selfShadowValue;
        lt.shadowOn = mapOn;
        lt.shadowVisibility = mapTest.visibility;
        lt.shadowDepth = mapTest.depth;
        lt.shadowBias = mapTest.bias;
        lt.shadowStored = mapTest.stored;
        lt.shadowReference = mapTest.reference;
        lt.shadowInside = mapTest.inside > zero;
        lt.shadowTexel = decltype(lt.shadowTexel)(mapTest.texelX, mapTest.texelY, mapTest.layer);
        lt.diffuse = diffuse;
        lt.specular = specular;
      }
    }
  }
  return out;
}

// What no light scales, summed first: the ambient term, then the environment's diffuse light
// added as the lights' diffuse terms are (kd albedo times it). The forward shading adds the
// lights to it; the deferred pipeline's G-buffer pass stores it (gbufferFragmentLanes).
template <typename L>
struct UnlitTermsL {
  Vec3L<L> ambient, environmentDiffuse, unlit;
};
template <typename Features, typename L>
TWR_LANE_INLINE UnlitTermsL<L> unlitTermsLanes(const ShadeUniformsT<ScalarOf<L>>& u, const SurfaceFrameL<L>& frame,
                                               const Vec3L<L>& albedo, const Vec3L<L>& kdAlbedo) {
  using S = ScalarOf<L>;
  constexpr bool kTangentSpace = Features::kSpace == LightingSpace::Tangent;
  UnlitTermsL<L> out;
  out.ambient = (Vec3L<L>(u.ka) * albedo) * Vec3L<L>(u.ambient);
  out.environmentDiffuse = Vec3L<L>(L(S(0)));
  out.unlit = out.ambient;
  if (u.environment.cube && u.environment.diffuse != EnvironmentDiffuse::None) {
    out.environmentDiffuse = (environmentDiffuseLanes<L>)(u.environment, frame.nl, frame.t, frame.b, frame.n, kTangentSpace);
    out.unlit = out.unlit + kdAlbedo * out.environmentDiffuse;
  }
  return out;
}

// A Phong-term view's colour (isPhongTermView): the ambient term, or the lights' diffuse or
// specular terms summed, alpha 1. GLSL: phong.frag's phongTermColour.
template <typename L>
TWR_LANE_INLINE Vec4L<L> phongTermColourLanes(View view, const Vec3L<L>& ambientTerm, const LightSumL<L>& lit) {
  const L one(ScalarOf<L>(1));
  if (view == View::Ambient) return Vec4L<L>(ambientTerm, one);
  if (view == View::Diffuse) return Vec4L<L>(lit.diffuseSum, one);
  return Vec4L<L>(lit.specularSum, one);
}

// Shades one fragment per lane with the permutation `Features` (shade.h's ShaderFeatures).
// `maps` holds the material's textures as the lane type reads them (members diffuse, normal,
// specular: pointers to views, see texture_sample-inl.h); `terms`, when not null, receives
// every intermediate value (the pixel trace; scalar lanes only, nullptr_t otherwise).
template <typename Features, typename L, typename Maps, typename Terms>
TWR_LANE_INLINE Vec4L<L> shadeFragmentLanes(const FragmentL<L>& f, const ShadeUniformsT<ScalarOf<L>>& u, const Maps& maps,
                                   Terms* terms) {
  using S = ScalarOf<L>;
  constexpr bool kTrace = !std::is_same_v<Terms, std::nullptr_t>;
  constexpr bool kTangentSpace = Features::kSpace == LightingSpace::Tangent;
  const L zero(S(0)), one(S(1));
  const bool wantHeight = kTrace || Features::kView == View::Height || u.selfShadow == SelfShadow::HeightMarch;
  const SurfaceFrameL<L> frame = (surfaceFrameLanes<Features, L>)(f, u, maps, wantHeight);
  const Vec3L<L>& n = frame.n;
  const Vec3L<L>& t = frame.t;
  const Vec3L<L>& b = frame.b;
  const SurfaceDetailL<L>& detail = frame.detail;
  const Vec3L<L>& nl = frame.nl;
  const Vec3L<L>& mappedTangent = frame.mappedTangent;
  const Vec4L<L>& normalTexel = frame.normalTexel;
  const bool selfShadowOn = Features::kHasHeightMap && u.selfShadow != SelfShadow::None;

  const MaterialTexelsL<L> texels = (materialTexelsLanes<Features, L>)(f, u, maps, detail);
  const Vec3L<L>& albedo = texels.albedo;
  const Vec3L<L>& specScale = texels.specScale;

  if constexpr (kTrace) {
    if (terms) {
      terms->n = n;
      terms->t = t;
      terms->b = b;
      terms->albedo = albedo;
      terms->specScale = specScale;
      terms->normalTexel = normalTexel;
      terms->mappedTangent = mappedTangent;
      terms->nl = nl;
      terms->uvShifted = detail.uv;
      terms->height = detail.height;
      terms->parallaxSteps = detail.steps;
    }
  }

  Vec4L<L> colour(zero);
  if constexpr (Features::kView == View::Shaded) {
    const Vec3L<L> kdAlbedo = Vec3L<L>(u.kd) * albedo;   // u.kd * albedo, diffuse's first product
    const Vec3L<L> ksSpec = Vec3L<L>(u.ks) * specScale;  // u.ks * specScale, specular's first
    const UnlitTermsL<L> unlitTerms = (unlitTermsLanes<Features, L>)(u, frame, albedo, kdAlbedo);
    const Vec3L<L>& ambient = unlitTerms.ambient;
    const Vec3L<L>& unlit = unlitTerms.unlit;
    if constexpr (kTrace) {
      if (terms && u.environment.cube) {
        terms->environmentDiffuseOn = u.environment.diffuse != EnvironmentDiffuse::None;
        terms->environmentDiffuse = unlitTerms.environmentDiffuse;
      }
    }
    const LightSumL<L> lit = (lightSumLanes<Features, L>)(&f, u, maps, f.posWorld, frame, kdAlbedo, ksSpec, u.shininess, terms);
    colour = Vec4L<L>(unlit + lit.sum, one);
    if constexpr (kTrace) {
      if (terms) {
        terms->ambient = ambient;
        terms->diffuseSum = lit.diffuseSum;
        terms->specularSum = lit.specularSum;
        terms->lightCount = u.lightCount;
      }
    }
    if (u.environment.cube && u.environment.readsDirections()) {
      const Vec3L<L> eyeVec = kTangentSpace ? f.eyeDirTangent : Vec3L<L>(u.eyePosWorld) - f.posWorld;
      const Vec3L<L> phong(colour.x, colour.y, colour.z);
      const EnvironmentDirectionsL<L> directions =
          (environmentDirectionsLanes<L>)(u.environment, nl, eyeVec, t, b, n, kTangentSpace);
      const EnvironmentTermsL<L> env = (environmentLanes<L>)(u.environment, directions, f, phong);
      colour = Vec4L<L>(env.colour, one);
      if (isEnvironmentView(u.shadedView)) {
        const EnvironmentParameterization kind =
            u.environment.layers ? u.environment.layers->kind : EnvironmentParameterization::Cube;
        const int levels = u.environment.prefiltered
                               ? u.environment.specularCube->levelCount()
                               : (u.environment.layers ? u.environment.layers->levelCount() : u.environment.cube->levelCount());
        colour = (environmentViewColourLanes<L>)(u.shadedView, kind, env.reflectWorld,
                                                 (clampedLodLanes<L>)(env.reflectLod, levels));
      }
      if constexpr (kTrace) {
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
    }
    if (isPhongTermView(u.shadedView)) {
      colour = (phongTermColourLanes<L>)(u.shadedView, ambient, lit);
    } else if (isShadowView(u.shadedView)) {
      // The shadow views (shadow-inl.h): the first shadowed light's test, or dimmed without one.
      if (!lit.haveShadowTest) {
        colour = (dimmedColourLanes<L>)(colour);
      } else if (u.shadedView == View::Shadow) {
        colour = (shadowViewColourLanes<L>)(lit.firstShadowTest, lit.firstShadowCosine);
      } else {
        colour = (lightDepthColourLanes<L>)(lit.firstShadowTest);
      }
    } else if (u.shadedView != View::Shaded && !(u.environment.cube && u.environment.readsDirections())) {
      colour = (dimmedColourLanes<L>)(colour);
    }
  } else if constexpr (Features::kView == View::Albedo) {
    colour = Vec4L<L>(albedo * Vec3L<L>(u.kd), one);
  } else if constexpr (Features::kView == View::Normal) {
    colour = vectorAsColourLanes<L>(n);
  } else if constexpr (Features::kView == View::Tangent) {
    colour = vectorAsColourLanes<L>(t);
  } else if constexpr (Features::kView == View::Bitangent) {
    colour = vectorAsColourLanes<L>(b);
  } else if constexpr (Features::kView == View::MappedNormal) {
    colour = vectorAsColourLanes<L>(nl);
  } else if constexpr (Features::kView == View::Uv) {
    colour = Vec4L<L>(f.uv.x - floorOf(f.uv.x), f.uv.y - floorOf(f.uv.y), zero, one);
  } else if constexpr (Features::kView == View::Depth) {
    colour = Vec4L<L>(f.depth, f.depth, f.depth, one);
  } else if constexpr (Features::kView == View::LightTangent || Features::kView == View::EyeTangent) {
    constexpr bool kLight = Features::kView == View::LightTangent;
    Vec3L<L> dirTangent(zero);  // no light: (0, 0, 0), shown as grey 0.5
    if (!kLight || u.lightCount > 0) {
      if constexpr (kTangentSpace) {
        dirTangent = safeNormalize3<L>(kLight ? f.lightDirTangent[0] : f.eyeDirTangent);
      } else {
        const Vec3L<L> w = kLight ? toLightLanes<L>(u.lights[0], f.posWorld) : Vec3L<L>(u.eyePosWorld) - f.posWorld;
        dirTangent = safeNormalize3<L>(Vec3L<L>(dot3<L>(t, w), dot3<L>(b, w), dot3<L>(n, w)));
      }
    }
    colour = vectorAsColourLanes<L>(dirTangent);
  } else if constexpr (Features::kView == View::Height) {
    colour = Vec4L<L>(detail.height, detail.height, detail.height, one);
  } else if constexpr (Features::kView == View::ParallaxOffset) {
    const L gain(static_cast<S>(kParallaxOffsetViewGain)), half(S(0.5));
    colour = Vec4L<L>(half + (detail.uv.x - f.uv.x) * gain, half + (detail.uv.y - f.uv.y) * gain, half, one);
  } else if constexpr (Features::kView == View::ParallaxSteps) {
    const L most(static_cast<S>(u.layerCap + u.refinementSteps));
    colour = heatColourLanes<L>(detail.steps / most);
  } else if constexpr (Features::kView == View::SelfShadow) {
    L shadow = one;
    if (selfShadowOn && u.lightCount > 0) {
      const Vec3L<L> lVec = kTangentSpace ? f.lightDirTangent[0] : toLightLanes<L>(u.lights[0], f.posWorld);
      shadow = selfShadowLanes<L>(maps, u, f, detail, tangentFromLightingLanes<L>(lVec, t, b, n, kTangentSpace));
    }
    colour = Vec4L<L>(shadow, shadow, shadow, one);
  }
  colour = clampUnit4<L>(colour);
  if constexpr (kTrace) {
    if (terms) terms->colour = colour;
  }
  return colour;
}

TWR_LANES_END

#endif  // TWR_SHADE_INL_EMIT
