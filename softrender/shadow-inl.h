// The shadow-map test over any lane type (scene/shadow_map.h states it): the C++ twin of
// shaders/shadow.glsl, function by function in the same order of operations. Shared source,
// included plainly and per Highway target (softrender/lanes.h).

#if defined(TWR_LANES_HIGHWAY)
#if defined(TWR_SHADOW_INL_TARGET) == defined(HWY_TARGET_TOGGLE)
#ifdef TWR_SHADOW_INL_TARGET
#undef TWR_SHADOW_INL_TARGET
#else
#define TWR_SHADOW_INL_TARGET
#endif
#define TWR_SHADOW_INL_EMIT
#endif
#elif !defined(TWR_SHADOW_INL_PLAIN)
#define TWR_SHADOW_INL_PLAIN
#define TWR_SHADOW_INL_EMIT
#endif

#ifdef TWR_SHADOW_INL_EMIT
#undef TWR_SHADOW_INL_EMIT

#include "scene/shadow_map.h"
#include "softrender/cube_sample-inl.h"
#include "softrender/lane_math-inl.h"
#include "softrender/lanes.h"
#include "softrender/shadow_uniforms.h"

TWR_LANES_BEGIN

// One fragment's test against one light's map: what the shading multiplies the light by and
// what the shadow and light_depth views show.
template <typename L>
struct ShadowTestL {
  L visibility;  // [0, 1]: the share of the pcf x pcf texels that see the fragment (1 outside the map)
  L depth;       // the fragment's own depth from the light (window depth of the map's camera)
  L bias;        // depth units
  L stored;      // the map's depth at the fragment's own texel (1 outside the map)
  L inside;      // 1 where the fragment lies inside the map, else 0
  L acneWindow;  // depth units: kShadowAcneTexels of the surface's own rise (at least a texel's)
  L reference;   // what each tap compares with the map: depth - bias
  L texelX, texelY;  // the fragment's own texel (the kernel's centre), 0 outside the map
  L layer;           // its layer (a cube's face), 0 outside the map
};

// The test at posWorld; n is the surface's unit normal and l the unit vector to the light, both
// in world space (the slope term's angle).
// Where a point lies in a shadow map: (s, t) in [0, 1), its depth z, the layer; one texel's
// width in world units and the map's depth units per world unit there; whether it lies in
// front of a spot light (a spot map's points behind the light are outside it).
template <typename L>
struct ShadowMapPointL {
  L s, t, z, layer, texelWorld, depthPerWorld;
  MaskOf<L> inFront;
};
template <typename L>
TWR_LANE_INLINE ShadowMapPointL<L> shadowMapPoint(const ShadowUniformT<ScalarOf<L>>& u, const Vec3L<L>& posWorld) {
  using S = ScalarOf<L>;
  const L zero(S(0)), one(S(1)), half(S(0.5));
  ShadowMapPointL<L> p{zero, zero, zero, zero, zero, zero, one > zero};  // inFront: all true
  if (u.kind == ShadowKind::Orthographic || u.kind == ShadowKind::Perspective) {
    const Mat4T<S>& m = u.clipFromWorld;  // columns summed from the left (orthographic: w = 1, vertex.h's transformPoint)
    const L x = ((L(m[0][0]) * posWorld.x + L(m[1][0]) * posWorld.y) + L(m[2][0]) * posWorld.z) + L(m[3][0]);
    const L y = ((L(m[0][1]) * posWorld.x + L(m[1][1]) * posWorld.y) + L(m[2][1]) * posWorld.z) + L(m[3][1]);
    if (u.kind == ShadowKind::Orthographic) {
      const L zc = ((L(m[0][2]) * posWorld.x + L(m[1][2]) * posWorld.y) + L(m[2][2]) * posWorld.z) + L(m[3][2]);
      p.s = x * half + half;
      p.t = y * half + half;
      p.z = zc * half + half;
      p.texelWorld = L(u.texelWorld);
      p.depthPerWorld = L(u.depthPerWorld);
    } else {
      // Spot: w is the distance along the cone's axis, m; the depth as a cube face's at m.
      const L w = ((L(m[0][3]) * posWorld.x + L(m[1][3]) * posWorld.y) + L(m[2][3]) * posWorld.z) + L(m[3][3]);
      p.inFront = w > zero;
      const L safeW = select(p.inFront, w, one);
      p.s = (x / safeW) * half + half;
      p.t = (y / safeW) * half + half;
      p.z = half * ((L(u.depthB) - L(u.depthA) * safeW) / safeW) + half;
      p.texelWorld = L(u.texelWorld) * safeW;
      p.depthPerWorld = L(u.depthPerWorld) / (safeW * safeW);
    }
    return p;
  }
  const Vec3L<L> d = posWorld - Vec3L<L>(u.lightPosWorld);
  const CubeCoordL<L> c = (cubeCoord<L>)(d);
  const L ma = maxOf(absOf(d.z), maxOf(absOf(d.x), absOf(d.y)));
  p.s = c.s;
  p.t = c.t;
  p.z = half * ((L(u.depthB) - L(u.depthA) * ma) / ma) + half;
  p.layer = c.face;
  p.texelWorld = L(u.texelWorld) * ma;
  p.depthPerWorld = L(u.depthPerWorld) / (ma * ma);
  return p;
}

template <typename L>
TWR_LANE_INLINE ShadowTestL<L> shadowTest(const ShadowUniformT<ScalarOf<L>>& u, const Vec3L<L>& posWorld,
                                          const Vec3L<L>& n, const Vec3L<L>& l) {
  using S = ScalarOf<L>;
  const L zero(S(0)), one(S(1));
  const L cosTheta = maxOf(dot3<L>(n, l), L(static_cast<S>(kMinShadowCosine)));
  const L sinTheta = sqrtOf(maxOf(one - cosTheta * cosTheta, zero));
  const L tanTheta = minOf(sinTheta / cosTheta, L(static_cast<S>(kMaxShadowSlopeTangent)));

  const ShadowMapPointL<L> p = (shadowMapPoint<L>)(u, posWorld);
  const L &s = p.s, &t = p.t, &z = p.z, &layer = p.layer, &texelWorld = p.texelWorld, &depthPerWorld = p.depthPerWorld;
  // bias = (constant + slope tan(theta) texel (1 + pcf / 2)) depth units per world unit
  const L reach(static_cast<S>(1 + u.pcf / 2));
  const L rise = tanTheta * texelWorld;  // the surface's rise across one texel, world units
  const L bias = (L(u.biasConstant) + (L(u.biasSlope) * rise) * reach) * depthPerWorld;
  const auto inside = p.inFront & (s >= zero) & (s < one) & (t >= zero) & (t < one) & (z <= one) & isFinite(z);
  const L size = L(u.size), last = size - one;
  // Out-of-map lanes read texel 0 (and count as lit below).
  const L x0 = select(inside, floorOf(s * size), zero);
  const L y0 = select(inside, floorOf(t * size), zero);
  const L base = select(inside, layer, zero) * size;
  const L reference = z - bias;
  const int radius = u.pcf / 2;
  L lit = zero, stored = one;
  for (int dy = -radius; dy <= radius; ++dy) {
    const L ty = minOf(maxOf(y0 + L(static_cast<S>(dy)), zero), last);
    for (int dx = -radius; dx <= radius; ++dx) {
      const L tx = minOf(maxOf(x0 + L(static_cast<S>(dx)), zero), last);
      const L texel = lookupLanes(u.depth, (base + ty) * size + tx);
      lit += select(reference <= texel, one, zero);
      if (dx == 0 && dy == 0) stored = texel;
    }
  }
  const L taps(static_cast<S>(u.pcf * u.pcf));
  ShadowTestL<L> r;
  r.visibility = select(inside, lit / taps, one);
  r.depth = z;
  r.bias = bias;
  r.stored = select(inside, stored, one);
  r.inside = select(inside, one, zero);
  r.acneWindow = (L(static_cast<S>(kShadowAcneTexels)) * maxOf(rise, texelWorld)) * depthPerWorld;
  r.reference = reference;
  r.texelX = x0;
  r.texelY = y0;
  r.layer = select(inside, layer, zero);
  return r;
}

// The `shadow` view's colour of one test; nDotL is the geometric normal's cosine to the light.
template <typename L>
TWR_LANE_INLINE Vec4L<L> shadowViewColour(const ShadowTestL<L>& test, const L& nDotL) {
  using S = ScalarOf<L>;
  const L zero(S(0)), one(S(1));
  const auto colour = [](const float (&c)[3]) { return Vec3L<L>(L(S(c[0])), L(S(c[1])), L(S(c[2]))); };
  const Vec3L<L> lit = colour(kShadowViewLit), shadowed = colour(kShadowViewShadowed);
  Vec3L<L> c = shadowed + (lit - shadowed) * test.visibility;
  const L reference = test.depth - test.bias;
  const auto acne = (test.inside > zero) & (test.stored < reference) &
                    (reference - test.stored < test.acneWindow);
  c = select3<L>(acne, colour(kShadowViewAcne), c);
  c = select3<L>(nDotL > zero, c, colour(kShadowViewAway));
  return Vec4L<L>(c, one);
}

// The light_depth view: the map's depth at the fragment's texel as grey (what the light sees
// there), dark red outside the map.
template <typename L>
TWR_LANE_INLINE Vec4L<L> lightDepthColour(const ShadowTestL<L>& test) {
  using S = ScalarOf<L>;
  const Vec3L<L> outside{L(S(kLightDepthOutside[0])), L(S(kLightDepthOutside[1])), L(S(kLightDepthOutside[2]))};
  return Vec4L<L>(select3<L>(test.inside > L(S(0)), Vec3L<L>(test.stored), outside), L(S(1)));
}

TWR_LANES_END

#endif  // TWR_SHADOW_INL_EMIT
