// Cube-map sampling over any lane type, as llvmpipe (Mesa 22.3) samples a samplerCube with
// GL_TEXTURE_CUBE_MAP_SEAMLESS on, measured against it on RGBA32F cubes texel for texel
// (docs/environment.md, "How llvmpipe reads a cube"):
//   face      z when |z| >= max(|x|, |y|), else x when |x| > |y|, else y (ties go to z, then
//             y); the sign bit of that component picks + or - (a zero vector reads +Z)
//   s, t      GL's table (scene/environment.h): k = 0.5 / |ma| (0 when ma = 0), s = sc k + 0.5
//   bilinear  u = max(s, 0) size - 0.5, x0 = floor(u), alpha = u - x0, likewise in t; a texel one
//             step past an edge is read from the face across that edge (cubeEdgeTable), and
//             each lerp is one fused multiply-add, a + w (b - a) rounded once, as llvmpipe's
//   corners   where three faces meet the fourth texel does not exist: its bilinear weight is
//             split in thirds over the other three, and the sum ((w00 t00 + w10 t10) + w01 t01)
//             + w11 t11 is taken instead of the lerps
//   levels    level floor(lod) and the next, blended as fma(f, c1 - c0, c0), the LOD explicit
//             (textureLod) or from the direction's quad differences (texture(), cubeLod);
//             the wrap mode plays no part (llvmpipe ignores it for cubes).
// One known difference: llvmpipe takes the weighted sum for all 8 pixels of a SIMD vector (4x2
// pixels) when one of them needs it, which can move the others by one float ULP.
// A cube map is planar floats (scene/environment.h's CubeMapLevel), gathered with
// lookupLanes: one index per texel, exact in float.
// Shared source, included plainly and per Highway target (softrender/lanes.h).

#if defined(TWR_LANES_HIGHWAY)
#if defined(TWR_CUBE_SAMPLE_INL_TARGET) == defined(HWY_TARGET_TOGGLE)
#ifdef TWR_CUBE_SAMPLE_INL_TARGET
#undef TWR_CUBE_SAMPLE_INL_TARGET
#else
#define TWR_CUBE_SAMPLE_INL_TARGET
#endif
#define TWR_CUBE_SAMPLE_INL_EMIT
#endif
#elif !defined(TWR_CUBE_SAMPLE_INL_PLAIN)
#define TWR_CUBE_SAMPLE_INL_PLAIN
#define TWR_CUBE_SAMPLE_INL_EMIT
#endif

#ifdef TWR_CUBE_SAMPLE_INL_EMIT
#undef TWR_CUBE_SAMPLE_INL_EMIT

#include "scene/environment.h"
#include "softrender/lane_math-inl.h"
#include "softrender/lanes.h"
#include "softrender/texture_sample-inl.h"

TWR_LANES_BEGIN

// Which face a direction looks at, and where on it: the face index (0..5, GL order) and
// s, t in [0, 1], both as lanes.
template <typename L>
struct CubeCoordL {
  L face, s, t;
};

// GL's table (scene/environment.h) per lane, with llvmpipe's tie rule and order of operations.
template <typename L>
TWR_LANE_INLINE CubeCoordL<L> cubeCoord(const Vec3L<L>& r) {
  using S = ScalarOf<L>;
  const L zero(S(0)), one(S(1)), half(S(0.5));
  const L ax = absOf(r.x), ay = absOf(r.y), az = absOf(r.z);
  const auto onZ = az >= maxOf(ax, ay);
  const auto onX = (!onZ) & (ax > ay);
  const auto onY = !(onZ | onX);
  // Only z can be a signed zero as the major axis (all three are zero then): its sign bit
  // decides, 1 / -0 = -inf.
  const auto xNegative = r.x < zero, yNegative = r.y < zero;
  const auto zNegative = (r.z < zero) | ((r.z == zero) & (one / r.z < zero));
  const L negZ = zero - r.z, negY = zero - r.y, negX = zero - r.x;
  CubeCoordL<L> c;
  c.face = select(onZ, select(zNegative, L(S(5)), L(S(4))),
                  select(onX, select(xNegative, L(S(1)), L(S(0))), select(yNegative, L(S(3)), L(S(2)))));
  const L sc = select(onZ, select(zNegative, negX, r.x), select(onX, select(xNegative, r.z, negZ), r.x));
  const L tc = select(onY, select(yNegative, negZ, r.z), negY);
  const L ma = select(onZ, az, select(onX, ax, ay));
  const auto usable = ma > zero;
  const L k = select(usable, half / select(usable, ma, one), zero);
  c.s = sc * k + half;
  c.t = tc * k + half;
  return c;
}

// One texel of level `level`, at (face, x, y) where x, y may be one step past an edge
// (-1 or size) but not both: such a texel is read from the neighbouring face. RGB.
template <typename L>
TWR_LANE_INLINE Vec3L<L> cubeTexel(const CubeMap& cube, int level, const L& face, const L& x, const L& y) {
  using S = ScalarOf<L>;
  const CubeMapLevel& lv = cube.levels[static_cast<std::size_t>(level)];
  const CubeEdgeTable& edges = cubeEdgeTable();
  const L zero(S(0)), one(S(1)), last(static_cast<S>(lv.size - 1)), sizeL(static_cast<S>(lv.size));
  const auto left = x < zero, right = x > last, below = y < zero, above = y > last;
  const auto acrossX = left | right, acrossY = below | above;
  const auto across = acrossX | acrossY;
  L tx = x, ty = y, tf = face;
  if (anyOf(across)) {
    // Edge 0: x = -1, 1: x = size, 2: y = -1, 3: y = size; the coordinate along it stays.
    const L edge = select(left, zero, select(right, one, select(below, L(S(2)), L(S(3)))));
    const L entry = select(across, face * L(S(4)) + edge, zero);
    const L along = select(acrossX, y, x);
    const L nx = (lookupLanes)(edges.xAtLast.data(), entry) * last + (lookupLanes)(edges.xPerAlong.data(), entry) * along;
    const L ny = (lookupLanes)(edges.yAtLast.data(), entry) * last + (lookupLanes)(edges.yPerAlong.data(), entry) * along;
    tf = select(across, (lookupLanes)(edges.face.data(), entry), face);
    tx = select(across, nx, x);
    ty = select(across, ny, y);
  }
  const L index = (tf * sizeL + ty) * sizeL + tx;
  return Vec3L<L>((lookupLanes)(lv.r.data(), index), (lookupLanes)(lv.g.data(), index), (lookupLanes)(lv.b.data(), index));
}

// a + w (b - a), rounded once (llvmpipe's lerp).
template <typename L>
TWR_LANE_INLINE Vec3L<L> lerpFused3(const Vec3L<L>& a, const Vec3L<L>& b, const L& w) {
  return Vec3L<L>(fusedMulAdd(w, b.x - a.x, a.x), fusedMulAdd(w, b.y - a.y, a.y), fusedMulAdd(w, b.z - a.z, a.z));
}

// Seamless bilinear on one level at (face, s, t): RGB.
template <typename L>
TWR_LANE_INLINE Vec3L<L> sampleCubeLevel(const CubeMap& cube, int level, const CubeCoordL<L>& c) {
  using S = ScalarOf<L>;
  const int size = cube.levels[static_cast<std::size_t>(level)].size;
  const L zero(S(0)), one(S(1)), sizeL(static_cast<S>(size)), last(static_cast<S>(size - 1));
  const L u = maxOf(c.s, zero) * sizeL - L(S(0.5)), v = maxOf(c.t, zero) * sizeL - L(S(0.5));
  const L x0 = floorOf(u), y0 = floorOf(v);
  const L alpha = u - x0, beta = v - y0;
  const L x1 = x0 + one, y1 = y0 + one;
  // Past both edges (a corner) the texel does not exist; it is read clamped in y (any texel
  // will do: its weight is 0 below).
  const L y0Read = maxOf(y0, zero), y1Read = minOf(y1, last);
  const auto x0Out = x0 < zero, x1Out = x1 > last, y0Out = y0 < zero, y1Out = y1 > last;
  const Vec3L<L> t00 = (cubeTexel<L>)(cube, level, c.face, x0, select(x0Out, y0Read, y0));
  const Vec3L<L> t10 = (cubeTexel<L>)(cube, level, c.face, x1, select(x1Out, y0Read, y0));
  const Vec3L<L> t01 = (cubeTexel<L>)(cube, level, c.face, x0, select(x0Out, y1Read, y1));
  const Vec3L<L> t11 = (cubeTexel<L>)(cube, level, c.face, x1, select(x1Out, y1Read, y1));
  const Vec3L<L> lerped = (lerpFused3<L>)((lerpFused3<L>)(t00, t10, alpha), (lerpFused3<L>)(t01, t11, alpha), beta);
  const auto corner00 = x0Out & y0Out, corner10 = x1Out & y0Out, corner01 = x0Out & y1Out, corner11 = x1Out & y1Out;
  const auto corner = corner00 | corner10 | corner01 | corner11;
  if (!anyOf(corner)) return lerped;
  // A corner: the missing texel's weight goes in thirds to the other three.
  const L ax0 = one - alpha, ay0 = one - beta;
  L w00 = ax0 * ay0, w10 = alpha * ay0, w01 = ax0 * beta, w11 = alpha * beta;
  const L third(static_cast<S>(1.0f / 3.0f));  // llvmpipe's float 1/3, in the reference too
  const L share = select(corner00, w00, select(corner10, w10, select(corner01, w01, w11))) * third;
  w00 = select(corner00, zero, select(corner, w00 + share, w00));
  w10 = select(corner10, zero, select(corner, w10 + share, w10));
  w01 = select(corner01, zero, select(corner, w01 + share, w01));
  w11 = select(corner11, zero, select(corner, w11 + share, w11));
  const Vec3L<L> summed = ((t00 * w00 + t10 * w10) + t01 * w01) + t11 * w11;
  return select3<L>(corner, summed, lerped);
}

// textureLod's level choice with GL_LINEAR_MIPMAP_LINEAR over any chain of `levelCount`
// levels: the LOD clamped to the chain (0 when not finite), its floor and the next level (the
// same one past the last or when the fraction is 0), each distinct level read once for the
// lanes that need it (readLevel(l) reads level l in every lane), blended fused. Cubes and the
// sphere and paraboloid maps (layer_sample-inl.h) share it.
template <typename L, typename ReadLevel>
TWR_LANE_INLINE Vec3L<L> blendLevels(int levelCount, const L& lod, const ReadLevel& readLevel) {
  using S = ScalarOf<L>;
  const int lastLevel = levelCount - 1;
  const L zero(S(0)), lastL(static_cast<S>(lastLevel));
  const L clamped = minOf(maxOf(select(isFinite(lod), lod, zero), zero), lastL);
  const L level0 = floorOf(clamped);
  const L fraction = clamped - level0;
  const L level1 = select(fraction == zero, level0, minOf(level0 + L(S(1)), lastL));
  const int lowest = static_cast<int>(lowestLane(level0)), highest = static_cast<int>(highestLane(level1));
  Vec3L<L> s0 = readLevel(lowest), s1 = s0;
  for (int l = lowest + 1; l <= highest; ++l) {
    const L here(static_cast<S>(l));
    const auto first = level0 == here, second = level1 == here;
    if (!anyOf(first | second)) continue;
    const Vec3L<L> read = readLevel(l);
    s0 = select3<L>(first, read, s0);
    s1 = select3<L>(second, read, s1);
  }
  return (lerpFused3<L>)(s0, s1, fraction);
}

// The environment in direction r at an explicit LOD (textureLod with GL_LINEAR_MIPMAP_LINEAR).
template <typename L>
TWR_LANE_OUTLINE Vec3L<L> sampleCubeLod(const CubeMap& cube, const Vec3L<L>& r, const L& lod) {
  const CubeCoordL<L> c = (cubeCoord<L>)(Vec3L<L>((sanitizedCoord<L>)(r.x), (sanitizedCoord<L>)(r.y),
                                                  (sanitizedCoord<L>)(r.z)));
  return (blendLevels<L>)(cube.levelCount(), lod,
                          [&](int level) { return (sampleCubeLevel<L>)(cube, level, c); });
}

// The LOD of texture(samplerCube, r) from r's differences across the quad (GLSL's fine dFdx and
// dFdy of r, environment-inl.h), per pixel on its own face, as llvmpipe takes it: the
// differences are mirrored as r's components are (dsc, dtc along the face, dma along its axis),
// projected by the quotient rule with ima = 1 / ma (ma signed) and h = 0.5 ima,
//   q = dma ima,  ds = (dsc - q sc) h,  dt = (dtc - q tc) h            (each step rounded)
// then, with W the base level's side, rho^2 = max((W dsx)^2 + (W dtx)^2, (W dsy)^2 + (W dty)^2)
// (0 when not finite) and lod = fastLog2(rho^2) / 2, quadLod' logarithm.
template <typename L>
TWR_LANE_INLINE L cubeLod(const Vec3L<L>& r, const Vec3L<L>& dx, const Vec3L<L>& dy, int size) {
  using S = ScalarOf<L>;
  const L zero(S(0)), one(S(1)), half(S(0.5));
  const L ax = absOf(r.x), ay = absOf(r.y), az = absOf(r.z);
  const auto onZ = az >= maxOf(ax, ay);
  const auto onX = (!onZ) & (ax > ay);
  const auto xNegative = r.x < zero, yNegative = r.y < zero;
  const auto zNegative = (r.z < zero) | ((r.z == zero) & (one / r.z < zero));
  // (minor s, minor t, major) of a vector as the pixel's face reads it.
  const auto onFace = [&](const Vec3L<L>& v) {
    const L sc = select(onZ, select(zNegative, zero - v.x, v.x), select(onX, select(xNegative, v.z, zero - v.z), v.x));
    const L tc = select(onZ | onX, zero - v.y, select(yNegative, zero - v.z, v.z));
    const L ma = select(onZ, v.z, select(onX, v.x, v.y));
    return Vec3L<L>(sc, tc, ma);
  };
  const Vec3L<L> c = onFace(r), ddx = onFace(dx), ddy = onFace(dy);
  const L ima = one / c.z, h = half * ima;
  const L qx = ddx.z * ima, qy = ddy.z * ima;
  const L dsx = (ddx.x - qx * c.x) * h, dtx = (ddx.y - qx * c.y) * h;
  const L dsy = (ddy.x - qy * c.x) * h, dty = (ddy.y - qy * c.y) * h;
  const L w(static_cast<S>(size));
  const L a = w * dsx, b = w * dtx, cc = w * dsy, e = w * dty;
  const L rho2Raw = maxOf(a * a + b * b, cc * cc + e * e);
  const L rho2 = select(isFinite(rho2Raw), rho2Raw, zero);
  return (floatExponentOf(rho2) + (floatMantissaOf(rho2) - one)) * half;
}

// texture(samplerCube, r) with r's quad differences: the LOD above, then sampleCubeLod.
template <typename L>
TWR_LANE_INLINE Vec3L<L> sampleCubeGrad(const CubeMap& cube, const Vec3L<L>& r, const Vec3L<L>& dx,
                                        const Vec3L<L>& dy) {
  return (sampleCubeLod<L>)(cube, r, (cubeLod<L>)(r, dx, dy, cube.size()));
}

TWR_LANES_END

#endif  // TWR_CUBE_SAMPLE_INL_EMIT
