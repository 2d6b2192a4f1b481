// Stage 8's colour conversion over any lane type: round(clamp(c, 0, 1) * 255), halves up,
// NaN to 0 (the same bytes as unitToByte's lround). Shared source, included plainly and per
// Highway target (softrender/lanes.h).

#if defined(TWR_LANES_HIGHWAY)
#if defined(TWR_OUTPUT_MERGE_INL_TARGET) == defined(HWY_TARGET_TOGGLE)
#ifdef TWR_OUTPUT_MERGE_INL_TARGET
#undef TWR_OUTPUT_MERGE_INL_TARGET
#else
#define TWR_OUTPUT_MERGE_INL_TARGET
#endif
#define TWR_OUTPUT_MERGE_INL_EMIT
#endif
#elif !defined(TWR_OUTPUT_MERGE_INL_PLAIN)
#define TWR_OUTPUT_MERGE_INL_PLAIN
#define TWR_OUTPUT_MERGE_INL_EMIT
#endif

#ifdef TWR_OUTPUT_MERGE_INL_EMIT
#undef TWR_OUTPUT_MERGE_INL_EMIT

#include "softrender/lanes.h"

TWR_LANES_BEGIN

// The byte value 0..255 of a colour channel, as an integer-valued lane.
template <typename L>
TWR_LANE_INLINE L byteValueOf(L c) {
  using S = ScalarOf<L>;
  constexpr S kByteMax = S(255);
  const L zero(S(0)), one(S(1));
  const L scaled = minOf(maxOf(c, zero), one) * L(kByteMax);  // maxOf first: NaN -> 0
  const L whole = truncOf(scaled);
  return whole + select(scaled - whole >= L(S(0.5)), one, zero);
}

TWR_LANES_END

#endif  // TWR_OUTPUT_MERGE_INL_EMIT
