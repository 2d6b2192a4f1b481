// Texel indices for the fast path's lanes: wrapTexelIndex and nextTexelIndex as
// texture_sample-inl.h needs them for LaneF / LaneI (the scalar versions are in
// texture_sample.h). Per Highway target only; include after softrender/texture_sample.h and
// softrender/lanes_hwy-inl.h, before texture_sample-inl.h.

#if defined(TWR_TEXEL_LANES_INL_TARGET) == defined(HWY_TARGET_TOGGLE)
#ifdef TWR_TEXEL_LANES_INL_TARGET
#undef TWR_TEXEL_LANES_INL_TARGET
#else
#define TWR_TEXEL_LANES_INL_TARGET
#endif

HWY_BEFORE_NAMESPACE();
namespace twr {
namespace HWY_NAMESPACE {

// wrappedFloorIndex lane by lane, for coordinates too large for 32-bit lanes (a repeat count
// that large is a test case, not a scene). Out of line, as the rare path; `inline` because
// every kernel object (fast_kernels_<group>.cpp) includes this file for every target.
inline HWY_NOINLINE LaneI wrapTexelIndexEachLane(int size, LaneF integral) {
  HWY_ALIGN float values[HWY_MAX_BYTES / sizeof(float)];
  HWY_ALIGN std::int32_t indices[HWY_MAX_BYTES / sizeof(float)];
  hn::Store(integral.v, DF(), values);
  for (std::size_t l = 0; l < laneCount(); ++l) indices[l] = wrappedFloorIndex(static_cast<double>(values[l]), size);
  return {hn::Load(DI(), indices)};
}

// floor value mod size, exact: the same integers as wrappedFloorIndex.
HWY_INLINE LaneI wrapTexelIndex(int size, LaneF integral) {
  constexpr float kMaxLaneCoord = 1073741824.0f;  // 2^30: below it, int32 lanes hold i and i + size
  if (!hn::AllTrue(DF(), hn::Lt(hn::Abs(integral.v), hn::Set(DF(), kMaxLaneCoord)))) {
    return wrapTexelIndexEachLane(size, integral);
  }
  if ((size & (size - 1)) == 0) {  // a power of two: two's complement AND is floor mod
    return {hn::And(hn::ConvertTo(DI(), integral.v), hn::Set(DI(), size - 1))};
  }
  // i - floor(i / size) size in double: the quotient is within 2^-22 of the true one, and a
  // non-integer true quotient is at least 1 / size > 2^-22 from the next integer, so the floor
  // is exact, and so is everything after it.
  const LaneW i = toWide(integral);
  const LaneW sizeW(static_cast<double>(size));
  const LaneW remainder = i - floorOf(i / sizeW) * sizeW;
  return {hn::ConvertTo(DI(), toNarrowLanes(remainder).v)};
}

// i + 1, wrapped to 0 at size.
HWY_INLINE LaneI nextTexelIndex(LaneI i, int size) {
  const auto next = hn::Add(i.v, hn::Set(DI(), 1));
  return {hn::IfThenZeroElse(hn::Eq(next, hn::Set(DI(), size)), next)};
}

}  // namespace HWY_NAMESPACE
}  // namespace twr
HWY_AFTER_NAMESPACE();

#endif  // TWR_TEXEL_LANES_INL_TARGET toggle
