// The Phong exponent x^s of the float pipeline over any lane type: phong_pow.h describes the
// method (2^(s log2 x) in double, every operation written out). Shared source, included
// plainly and per Highway target (softrender/lanes.h).

#if defined(TWR_LANES_HIGHWAY)
#if defined(TWR_PHONG_POW_INL_TARGET) == defined(HWY_TARGET_TOGGLE)
#ifdef TWR_PHONG_POW_INL_TARGET
#undef TWR_PHONG_POW_INL_TARGET
#else
#define TWR_PHONG_POW_INL_TARGET
#endif
#define TWR_PHONG_POW_INL_EMIT
#endif
#elif !defined(TWR_PHONG_POW_INL_PLAIN)
#define TWR_PHONG_POW_INL_PLAIN
#define TWR_PHONG_POW_INL_EMIT
#endif

#ifdef TWR_PHONG_POW_INL_EMIT
#undef TWR_PHONG_POW_INL_EMIT

#include "softrender/lanes.h"
#include "softrender/phong_pow.h"

#include <cmath>
#include <limits>
#include <type_traits>

TWR_LANES_BEGIN

// x^s in double lanes, for x a positive normal double and s >= 0 (phong_pow.h).
template <typename W>
TWR_LANE_INLINE W powPositiveWide(W x, W s) {
  using namespace phongpow;
  W m = mantissaOf(x);  // x = m 2^e, m in [1, 2)
  W e = exponentOf(x);
  const auto halve = m > W(kSqrt2);  // m in [sqrt(1/2), sqrt(2)) keeps |t| small
  m = select(halve, m * W(0.5), m);
  e = select(halve, e + W(1.0), e);
  const W t = (m - W(1.0)) / (m + W(1.0));
  const W t2 = t * t;
  W series(kLog2Coefficients[kLog2Terms - 1]);
  for (int k = kLog2Terms - 2; k >= 0; --k) series = series * t2 + W(kLog2Coefficients[static_cast<std::size_t>(k)]);
  const W log2x = e + t * series;

  W y = s * log2x;
  y = select(isNaN(y), W(0.0), y);  // infinity * 0
  y = minOf(maxOf(y, W(-kMaxExponent)), W(kMaxExponent));
  const W k = roundEvenOf(y);
  const W f = y - k;  // exact: |f| <= 1/2
  W p(kExp2Coefficients[kExp2Terms - 1]);
  for (int n = kExp2Terms - 2; n >= 0; --n) p = p * f + W(kExp2Coefficients[static_cast<std::size_t>(n)]);
  return p * exp2Integer(k);
}

// x^n for a whole n in [1, kMaxWholeExponent] (phong_pow.h): binary powering in double, the
// power squared for each bit of n and multiplied in where the bit is set, lowest bit first.
template <typename W>
TWR_LANE_INLINE W powWholeWide(W x, unsigned n) {
  W result(1.0), power = x;
  for (;;) {
    if ((n & 1u) != 0) result = result * power;
    n >>= 1;
    if (n == 0) return result;
    power = power * power;
  }
}
// The same with one n per lane (whole, in [1, kMaxWholeExponent]): every lane gets
// powWholeWide's products in its order (its squarings past its last bit are never used).
template <typename W>
TWR_LANE_INLINE W powWholeWidePerLane(W x, W n) {
  W result(1.0), power = x;
  for (int bit = 0; bit < phongpow::kWholeExponentBits; ++bit) {
    const W half = floorOf(n * W(0.5));
    const auto set = n - half * W(2.0) > W(0.5);  // the lowest bit of n, exactly
    result = select(set, result * power, result);
    n = half;
    power = power * power;
  }
  return result;
}

// pow(x, s) for the Phong term: 0^s = 0 for s > 0 and 0^0 = 1 (both renderers agree on it),
// +inf^s = +inf for s > 0. Float lanes: powPositiveWide, rounded once to float. The reference
// (double) uses libm's pow: it is the ground truth, not a twin of the float bits.
template <typename L>
TWR_LANE_INLINE L phongPow(L x, ScalarOf<L> s) {
  using S = ScalarOf<L>;
  if constexpr (std::is_same_v<L, double>) {
    if (!(x > 0.0)) return s > 0.0 ? 0.0 : 1.0;
    return std::pow(x, s);
  } else {
    const S infinity = std::numeric_limits<S>::infinity();
    const auto positive = x > L(S(0));
    const auto infinite = positive & !(x < L(infinity));
    // Lanes not computed hold 1, so nothing below sees a zero, a NaN or an infinity.
    const L finiteX = select(positive & !infinite, x, L(S(1)));
    const L powered = phongpow::isWholeExponent(static_cast<double>(s))
                          ? toNarrow<L>(powWholeWide(toWide(finiteX), static_cast<unsigned>(s)))
                          : toNarrow<L>(powPositiveWide(toWide(finiteX), wideSplat<L>(static_cast<double>(s))));
    const L zeroCase(s > S(0) ? S(0) : S(1));
    const L infCase(s > S(0) ? infinity : S(1));
    return select(infinite, infCase, select(positive, powered, zeroCase));
  }
}

// The lanes whose exponent phongPow raises by powering: phongpow::isWholeExponent lane by lane.
template <typename L>
TWR_LANE_INLINE MaskOf<L> wholeExponentLanes(const L& s) {
  using S = ScalarOf<L>;
  const L whole = floorOf(s);
  const auto inRange = (s >= L(S(1))) & (s <= L(static_cast<S>(phongpow::kMaxWholeExponent)));  // NaN: not
  return inRange & !(s < whole) & !(s > whole);
}

// phongPow with one exponent per lane (the deferred lighting pass reads the shininess from the
// G-buffer): the same operations, so a lane gets phongPow's bits for its own s. Float lanes only.
template <typename L>
TWR_LANE_INLINE L phongPowPerLane(L x, L s) {
  using S = ScalarOf<L>;
  const S infinity = std::numeric_limits<S>::infinity();
  const L zero(S(0)), one(S(1));
  const auto positive = x > zero;
  const auto infinite = positive & !(x < L(infinity));
  const L finiteX = select(positive & !infinite, x, one);
  // Each lane by phongPow's method for its own s: whole exponents by powering, the rest by the
  // series, each computed only where some lane needs it.
  const auto byPowering = wholeExponentLanes<L>(s);
  const L poweredWhole =
      anyOf(byPowering) ? toNarrow<L>(powWholeWidePerLane(toWide(finiteX), toWide(select(byPowering, s, one)))) : one;
  const L powered = allOf(byPowering)
                        ? poweredWhole
                        : select(byPowering, poweredWhole, toNarrow<L>(powPositiveWide(toWide(finiteX), toWide(s))));
  const auto sPositive = s > zero;
  const L zeroCase = select(sPositive, zero, one);
  const L infCase = select(sPositive, L(infinity), one);
  return select(infinite, infCase, select(positive, powered, zeroCase));
}

TWR_LANES_END

#endif  // TWR_PHONG_POW_INL_EMIT
