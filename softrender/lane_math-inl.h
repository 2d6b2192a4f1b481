// Vector helpers over any lane type (softrender/lanes.h), in GLM's order of operations:
// dot3 = (x x' + y y') + z z', safeNormalize, componentwise select and clamp. Shared source:
// included plainly (float, double) and per Highway target (see lanes.h).

// Include guard: once plainly, and once per Highway target (toggled like Highway's own).
#if defined(TWR_LANES_HIGHWAY)
#if defined(TWR_LANE_MATH_INL_TARGET) == defined(HWY_TARGET_TOGGLE)
#ifdef TWR_LANE_MATH_INL_TARGET
#undef TWR_LANE_MATH_INL_TARGET
#else
#define TWR_LANE_MATH_INL_TARGET
#endif
#define TWR_LANE_MATH_INL_EMIT
#endif
#elif !defined(TWR_LANE_MATH_INL_PLAIN)
#define TWR_LANE_MATH_INL_PLAIN
#define TWR_LANE_MATH_INL_EMIT
#endif

#ifdef TWR_LANE_MATH_INL_EMIT
#undef TWR_LANE_MATH_INL_EMIT

#include "softrender/lanes.h"

TWR_LANES_BEGIN

// glm::dot: tmp = a * b; (tmp.x + tmp.y) + tmp.z.
template <typename L>
TWR_LANE_INLINE L dot3(const Vec3L<L>& a, const Vec3L<L>& b) {
  return (a.x * b.x + a.y * b.y) + a.z * b.z;
}

// glm::length: sqrt(dot(v, v)).
template <typename L>
TWR_LANE_INLINE L length3(const Vec3L<L>& v) {
  return sqrtOf(dot3(v, v));
}

template <typename L>
TWR_LANE_INLINE Vec3L<L> select3(const MaskOf<L>& m, const Vec3L<L>& a, const Vec3L<L>& b) {
  return Vec3L<L>(select(m, a.x, b.x), select(m, a.y, b.y), select(m, a.z, b.z));
}
template <typename L>
TWR_LANE_INLINE Vec4L<L> select4(const MaskOf<L>& m, const Vec4L<L>& a, const Vec4L<L>& b) {
  return Vec4L<L>(select(m, a.x, b.x), select(m, a.y, b.y), select(m, a.z, b.z), select(m, a.w, b.w));
}

// safeNormalize (scene/conventions.h) per lane: v / |v| when kMinLengthSquared < |v|^2 <
// infinity, else (0, 0, 1).
template <typename L>
TWR_LANE_INLINE Vec3L<L> safeNormalize(const Vec3L<L>& v) {
  using S = ScalarOf<L>;
  const L lengthSquared = dot3(v, v);
  const MaskOf<L> usable = (lengthSquared > L(static_cast<S>(kMinLengthSquared))) & isFinite(lengthSquared);
  const L length = sqrtOf(lengthSquared);
  const Vec3L<L> normalised(v.x / length, v.y / length, v.z / length);
  return select3<L>(usable, normalised, Vec3L<L>(L(S(0)), L(S(0)), L(S(1))));
}

// glm::clamp(c, 0, 1) per component, with maxOf first (a NaN component becomes 0).
template <typename L>
TWR_LANE_INLINE Vec4L<L> clampUnit4(const Vec4L<L>& c) {
  using S = ScalarOf<L>;
  const L zero(S(0)), one(S(1));
  return Vec4L<L>(minOf(maxOf(c.x, zero), one), minOf(maxOf(c.y, zero), one), minOf(maxOf(c.z, zero), one),
                  minOf(maxOf(c.w, zero), one));
}

// (v + 1) / 2 with alpha 1: how the debug views show a vector.
template <typename L>
TWR_LANE_INLINE Vec4L<L> vectorAsColour(const Vec3L<L>& v) {
  using S = ScalarOf<L>;
  const L one(S(1)), half(S(0.5));
  return Vec4L<L>((v.x + one) * half, (v.y + one) * half, (v.z + one) * half, one);
}

// The heat views' colour (parallax_steps, env_lod): a blue-cyan-green-yellow-red ramp over t in [0, 1].
// Each channel is a tent clamp(1.5 - |4 t - centre|, 0, 1): red centred at 3, green at 2,
// blue at 1.
template <typename L>
TWR_LANE_INLINE L heatChannel(const L& t, ScalarOf<L> centre) {
  using S = ScalarOf<L>;
  return minOf(maxOf(L(S(1.5)) - absOf(L(S(4)) * t - L(centre)), L(S(0))), L(S(1)));
}
template <typename L>
TWR_LANE_INLINE Vec4L<L> heatColour(const L& tIn) {
  using S = ScalarOf<L>;
  const L t = minOf(maxOf(tIn, L(S(0))), L(S(1)));
  return Vec4L<L>(heatChannel<L>(t, S(3)), heatChannel<L>(t, S(2)), heatChannel<L>(t, S(1)), L(S(1)));
}

TWR_LANES_END

#endif  // TWR_LANE_MATH_INL_EMIT
