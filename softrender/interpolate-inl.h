// Stage 5, interpolation, over any lane type (interpolate.h has the formulas): the window
// depth and every varying from float planes as llvmpipe evaluates them; barycentrics and
// perspective weights in double for the pixel trace. Shared source, included plainly and per
// Highway target (softrender/lanes.h).

#if defined(TWR_LANES_HIGHWAY)
#if defined(TWR_INTERPOLATE_INL_TARGET) == defined(HWY_TARGET_TOGGLE)
#ifdef TWR_INTERPOLATE_INL_TARGET
#undef TWR_INTERPOLATE_INL_TARGET
#else
#define TWR_INTERPOLATE_INL_TARGET
#endif
#define TWR_INTERPOLATE_INL_EMIT
#endif
#elif !defined(TWR_INTERPOLATE_INL_PLAIN)
#define TWR_INTERPOLATE_INL_PLAIN
#define TWR_INTERPOLATE_INL_EMIT
#endif

#ifdef TWR_INTERPOLATE_INL_EMIT
#undef TWR_INTERPOLATE_INL_EMIT

#include "softrender/framebuffer.h"
#include "softrender/lanes.h"

#include <array>

TWR_LANES_BEGIN

#if defined(TWR_LANES_HIGHWAY)
// The texture coordinate's planes as lanes (interpolate.h).
template <typename L>
struct AttributePlaneL {
  L atOrigin, dx, dy;
#if !HWY_NATIVE_FMA
  bool sumsExactInDouble = false;  // in every lane (planeSumsExactInDouble): planeAt's short way
#endif
};
template <typename L>
struct UvPlanesL {
  AttributePlaneL<L> uOverW, vOverW, oneOverW;
};
// The fast path's lanes of one triangle's interpolation setup (each lane may belong to
// another triangle), of its vertices' varyings, of the weights and of the fragment.
template <typename L>
struct InterpolationL {
  std::array<WideOf<L>, 3> atOrigin, dx, dy;  // lambda_i = atOrigin + dx px + dy py
  std::array<L, 3> zWindow, invW;
  UvPlanesL<L> uv;
  AttributePlaneL<L> depth;
};
template <typename L>
struct VaryingPlanesL {
  AttributePlaneL<L> oneOverW;
  std::array<AttributePlaneL<L>, kMaxVaryings> overW;  // the first `count` set
  int count;
};
template <typename L>
struct PixelWeightsL {
  std::array<L, 3> screen, perspective;
  L depth;
  Vec2L<L> uv;
};
template <typename L>
struct FragmentL {
  Vec3L<L> posWorld, nWorld, tWorld, bWorld;
  Vec2L<L> uv;
  Vec2L<L> uvDx, uvDy;
  Vec2L<L> uvDxFine, uvDyFine;
  Vec3L<L> reflectDx, reflectDy, refractDx, refractDy;  // interpolate.h's FragmentT says
  std::array<Vec3L<L>, kMaxLights> lightDirTangent;
  Vec3L<L> eyeDirTangent;
  L depth;
};
#else
// Plainly the teaching path's own types (interpolate.h).
template <typename L>
using AttributePlaneL = AttributePlaneT<L>;
template <typename L>
using UvPlanesL = UvPlanesT<L>;
template <typename L>
using InterpolationL = InterpolationSetupT<L>;
template <typename L>
using VaryingPlanesL = VaryingPlanesT<L>;
template <typename L>
using PixelWeightsL = PixelWeightsT<L>;
template <typename L>
using FragmentL = FragmentT<L>;
#endif

// An attribute plane at pixel (px, py): two fused multiply-adds, as llvmpipe evaluates it.
template <typename L>
TWR_LANE_INLINE L planeAt(const AttributePlaneL<L>& p, const L& px, const L& py) {
#if defined(TWR_LANES_HIGHWAY) && !HWY_NATIVE_FMA
  // Without fused multiply-add instructions, a plane shown exact in double skips the emulation's check.
  if (p.sumsExactInDouble) return fusedMulAddsOfExactSums(p.dy, py, p.dx, px, p.atOrigin);
#endif
  return fusedMulAdd(p.dy, py, fusedMulAdd(p.dx, px, p.atOrigin));
}

// The uv at pixel (px, py), covered or not (a helper pixel of a quad): (u/w, v/w) times the
// reciprocal of 1/w.
// A non-finite result (a plane overflowing float on extreme inputs, or 1/w rounding to 0 at a
// helper pixel) becomes 0, which is how llvmpipe's sampler reads such a coordinate anyway.
template <typename L>
TWR_LANE_INLINE Vec2L<L> uvAtPixel(const UvPlanesL<L>& s, const L& px, const L& py) {
  using S = ScalarOf<L>;
  const L zero(S(0));
  const L w = L(S(1)) / planeAt<L>(s.oneOverW, px, py);
  const L u = planeAt<L>(s.uOverW, px, py) * w, v = planeAt<L>(s.vOverW, px, py) * w;
  return Vec2L<L>(select(isFinite(u), u, zero), select(isFinite(v), v, zero));
}

// Largest value of the 24-bit depth buffer llvmpipe renders into (GL_DEPTH_COMPONENT24).
inline constexpr float kDepthUnormMax = 16777215.0f;  // 2^24 - 1

// The depth llvmpipe's depth test compares and stores for an interpolated window z: clamped to
// [0, 1], scaled to 24-bit unorm and rounded to the nearest integer, ties to even (one float
// multiply, then cvtps2dq), returned as that integer / (2^24 - 1), so comparing two results is
// comparing the integers. Two fragments whose z round to the same integer tie (GL_LESS keeps the
// first) as on llvmpipe. A NaN z (a triangle whose float area is 0: its plane divides by it)
// fails GL_LESS there against any stored depth (probe: a sliver with a snapped area but collinear
// float corners draws with GL_ALWAYS and not with GL_LESS), so it becomes 1 here, which never
// passes either; -inf clamps to 0 and +inf to 1, as llvmpipe clamps them.
template <typename L>
TWR_LANE_INLINE L storedDepth(const L& z) {
  using S = ScalarOf<L>;
  const L zero(S(0)), one(S(1)), unormMax(static_cast<S>(kDepthUnormMax));
  const L clamped = minOf(maxOf(z, zero), one);
  // The reference (double) is the ground truth, not llvmpipe: its depth keeps every bit.
  if constexpr (std::is_same_v<S, double>) return select(isNaN(z), one, clamped);
  return select(isNaN(z), one, roundEvenOf(clamped * unormMax) / unormMax);
}

// The depth a GL_DEPTH_COMPONENT32F attachment (a shadow map) compares and stores: the window z
// clamped to [0, 1] with every float bit kept. NaN becomes 1, which never passes GL_LESS (as
// NaN fails it on llvmpipe).
template <typename L>
TWR_LANE_INLINE L storedFloatDepth(const L& z) {
  using S = ScalarOf<L>;
  const L zero(S(0)), one(S(1));
  return select(isNaN(z), one, minOf(maxOf(z, zero), one));
}

// The depth a target of `format` stores (framebuffer.h's DepthFormat): storedDepth or
// storedFloatDepth.
template <typename L>
TWR_LANE_INLINE L depthAsStored(const L& z, DepthFormat format) {
  return format == DepthFormat::Float32 ? storedFloatDepth<L>(z) : storedDepth<L>(z);
}

// Window depth at pixel (px, py): the depth plane with two fused multiply-adds, as stored
// (storedDepth). All the visibility pass needs.
template <typename L>
TWR_LANE_INLINE L windowDepth(const InterpolationL<L>& s, const WideOf<L>& px, const WideOf<L>& py) {
  return storedDepth<L>(planeAt<L>(s.depth, toNarrow<L>(px), toNarrow<L>(py)));
}

// lambda_i at pixel (px, py), depth as windowDepth, p_i = (lambda_i / w_i) /
// sum_k (lambda_k / w_k) (the screen weight where the sum is not positive: a centre a hair
// outside the float triangle), and the uv from its planes.
template <typename L>
TWR_LANE_INLINE PixelWeightsL<L> pixelWeights(const InterpolationL<L>& s, const WideOf<L>& px, const WideOf<L>& py) {
  using W = WideOf<L>;
  PixelWeightsL<L> w;
  std::array<W, 3> lambda, perspective;
  W perspectiveSum(0.0);
  for (std::size_t i = 0; i < 3; ++i) {
    lambda[i] = (W(s.atOrigin[i]) + W(s.dx[i]) * px) + W(s.dy[i]) * py;
    w.screen[i] = toNarrow<L>(lambda[i]);
    perspective[i] = lambda[i] * toWide(s.invW[i]);
    perspectiveSum += perspective[i];
  }
  const auto positive = perspectiveSum > W(0.0);
  for (std::size_t i = 0; i < 3; ++i) {
    w.perspective[i] = toNarrow<L>(select(positive, perspective[i] / perspectiveSum, lambda[i]));
  }
  w.depth = windowDepth<L>(s, px, py);
  w.uv = uvAtPixel<L>(s.uv, toNarrow<L>(px), toNarrow<L>(py));
  return w;
}

// Varying k at a pixel: its a/w plane times the reciprocal of the pixel's 1/w.
template <typename L>
TWR_LANE_INLINE L varyingAt(const VaryingPlanesL<L>& p, int k, const L& px, const L& py, const L& w) {
  return planeAt<L>(p.overW[static_cast<std::size_t>(k)], px, py) * w;
}
template <typename L>
TWR_LANE_INLINE Vec3L<L> varying3At(const VaryingPlanesL<L>& p, int k, const L& px, const L& py, const L& w) {
  return Vec3L<L>(varyingAt<L>(p, k, px, py, w), varyingAt<L>(p, k + 1, px, py, w),
                  varyingAt<L>(p, k + 2, px, py, w));
}

// Every varying at pixel (px, py) from its plane, as llvmpipe's fragment shader reads it; the
// uv as uvAtPixel (a non-finite coordinate read as 0). Tangent-space light and eye
// directions where the planes hold them (tangent lighting space); otherwise the eye's is zero
// and the lights' are left as they were (zero in the teaching path's FragmentT).
template <typename L>
TWR_LANE_INLINE FragmentL<L> interpolateFragment(const VaryingPlanesL<L>& p, const L& px, const L& py,
                                                 const L& depth) {
  using S = ScalarOf<L>;
  const L zero(S(0));
  // A non-finite w (1/w rounding to 0 at a pixel a hair inside an edge of a triangle with
  // extreme depths) would make every varying NaN; it reads as 0, as the uv does.
  const L reciprocal = L(S(1)) / planeAt<L>(p.oneOverW, px, py);
  const L w = select(isFinite(reciprocal), reciprocal, zero);
  FragmentL<L> f;
  f.posWorld = varying3At<L>(p, kVaryingPosWorld, px, py, w);
  f.nWorld = varying3At<L>(p, kVaryingNormal, px, py, w);
  f.tWorld = varying3At<L>(p, kVaryingTangent, px, py, w);
  f.bWorld = varying3At<L>(p, kVaryingBitangent, px, py, w);
  const L u = varyingAt<L>(p, kVaryingUv, px, py, w), v = varyingAt<L>(p, kVaryingUv + 1, px, py, w);
  f.uv = Vec2L<L>(select(isFinite(u), u, zero), select(isFinite(v), v, zero));
  const Vec3L<L> zero3(zero);
  const bool tangentLighting = p.count > kVaryingEyeDirTangent;
  f.eyeDirTangent = tangentLighting ? varying3At<L>(p, kVaryingEyeDirTangent, px, py, w) : zero3;
  // Only the lights the planes hold, the only ones lighting reads (in world space, none): zero
  // vectors for the other kMaxLights were 24 stores a segment on AVX-512, 3 % of its samples.
  for (int k = 0; kVaryingLightDirTangent + 3 * k < p.count; ++k) {
    f.lightDirTangent[static_cast<std::size_t>(k)] = varying3At<L>(p, kVaryingLightDirTangent + 3 * k, px, py, w);
  }
  f.depth = depth;
  f.uvDx = Vec2L<L>(zero);
  f.uvDy = Vec2L<L>(zero);
  f.uvDxFine = Vec2L<L>(zero);
  f.uvDyFine = Vec2L<L>(zero);
  f.reflectDx = f.reflectDy = f.refractDx = f.refractDy = zero3;
  return f;
}

// The quad differences of uv for pixel (px, py): its 2x2 quad starts at the even column and
// the even row (GL window rows, from the bottom); du/dx = uv(x0 + 1, y0) - uv(x0, y0),
// du/dy = uv(x0, y0 + 1) - uv(x0, y0), the same for all four pixels (llvmpipe's per-quad LOD).
// qx, qy: the quad's first column and row.
template <typename L>
TWR_LANE_INLINE void setQuadUvDifferences(const UvPlanesL<L>& s, const L& qx, const L& qy, FragmentL<L>& f) {
  using S = ScalarOf<L>;
  const Vec2L<L> topLeft = uvAtPixel<L>(s, qx, qy);
  const Vec2L<L> right = uvAtPixel<L>(s, qx + L(S(1)), qy);
  const Vec2L<L> above = uvAtPixel<L>(s, qx, qy + L(S(1)));
  f.uvDx = right - topLeft;
  f.uvDy = above - topLeft;
}

// GLSL's dFdx(uv) and dFdy(uv) on llvmpipe, which are "fine": the difference along the
// pixel's own row of its quad (right - left) and along its own column (upper - lower). The
// height-field methods read with them (textureGrad), so they differ from the per-quad ones
// above in the quad's second row and column. qx, qy: the quad's first column and row.
template <typename L>
TWR_LANE_INLINE void setFineUvDifferences(const UvPlanesL<L>& s, const L& qx, const L& qy, const L& px,
                                          const L& py, FragmentL<L>& f) {
  using S = ScalarOf<L>;
  const Vec2L<L> left = uvAtPixel<L>(s, qx, py);
  const Vec2L<L> right = uvAtPixel<L>(s, qx + L(S(1)), py);
  const Vec2L<L> lower = uvAtPixel<L>(s, px, qy);
  const Vec2L<L> upper = uvAtPixel<L>(s, px, qy + L(S(1)));
  f.uvDxFine = right - left;
  f.uvDyFine = upper - lower;
}

TWR_LANES_END

#endif  // TWR_INTERPOLATE_INL_EMIT
