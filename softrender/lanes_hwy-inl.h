// The fast path's lane type: LaneF, one Highway vector of floats (one pixel per lane), with
// the operations softrender/lanes.h lists, so the shared shading source compiles for it
// exactly as for float. Included once per Highway target by fast_kernels-inl.h, inside
// twr::HWY_NAMESPACE; nothing here is ever compiled for the static target alone.
//
// Lane counts: AVX-512 16, AVX2 8, SSE4, NEON and EMU128 4, SCALAR 1. WideOf<LaneF> is LaneW,
// the same lanes as doubles: two double vectors (the lower and upper halves), or one on the
// one-lane SCALAR target.
//
// Every operation maps to one IEEE operation per lane (Highway's Add, Mul, Div, Sqrt, Floor,
// Round, ConvertTo, PromoteTo, DemoteTo are exact or correctly rounded on every target); Max
// and Min are deliberately not used, because targets differ in what they return for NaN.

#if defined(TWR_LANES_HWY_INL_TARGET) == defined(HWY_TARGET_TOGGLE)
#ifdef TWR_LANES_HWY_INL_TARGET
#undef TWR_LANES_HWY_INL_TARGET
#else
#define TWR_LANES_HWY_INL_TARGET
#endif

#include <hwy/highway.h>

#include <cstdint>

#include "softrender/lanes.h"

HWY_BEFORE_NAMESPACE();
namespace twr {
namespace HWY_NAMESPACE {

namespace hn = hwy::HWY_NAMESPACE;

using DF = hn::ScalableTag<float>;       // the lanes of one LaneF
using DI = hn::RebindToSigned<DF>;       // the same lanes as int32
using DU = hn::RebindToUnsigned<DF>;     // ... and uint32
#if HWY_TARGET == HWY_SCALAR
inline constexpr bool kWideHalves = false;
using DW = hn::Rebind<double, DF>;       // one double
#else
inline constexpr bool kWideHalves = true;
using DH = hn::Half<DF>;                 // half the float lanes
using DW = hn::Rebind<double, DH>;       // those lanes as doubles: one full double vector
#endif
using DW64 = hn::RebindToUnsigned<DW>;   // the doubles' bits

// Lanes per LaneF on this target.
inline size_t laneCount() { return hn::Lanes(DF()); }

struct LaneMask {
  hn::Mask<DF> m;
};
HWY_INLINE LaneMask operator&(LaneMask a, LaneMask b) { return {hn::And(a.m, b.m)}; }
HWY_INLINE LaneMask operator|(LaneMask a, LaneMask b) { return {hn::Or(a.m, b.m)}; }
HWY_INLINE LaneMask operator!(LaneMask a) { return {hn::Not(a.m)}; }
HWY_INLINE bool anyOf(LaneMask a) { return !hn::AllFalse(DF(), a.m); }
HWY_INLINE bool allOf(LaneMask a) { return hn::AllTrue(DF(), a.m); }

struct LaneF {
  hn::Vec<DF> v;
  LaneF() = default;
  HWY_INLINE LaneF(hn::Vec<DF> raw) : v(raw) {}
  HWY_INLINE LaneF(float x) : v(hn::Set(DF(), x)) {}  // broadcast, as float(x) for float lanes
};
HWY_INLINE LaneF operator+(LaneF a, LaneF b) { return {hn::Add(a.v, b.v)}; }
HWY_INLINE LaneF operator-(LaneF a, LaneF b) { return {hn::Sub(a.v, b.v)}; }
HWY_INLINE LaneF operator*(LaneF a, LaneF b) { return {hn::Mul(a.v, b.v)}; }
HWY_INLINE LaneF operator/(LaneF a, LaneF b) { return {hn::Div(a.v, b.v)}; }
HWY_INLINE LaneF& operator+=(LaneF& a, LaneF b) { return a = a + b; }
HWY_INLINE LaneMask operator>(LaneF a, LaneF b) { return {hn::Gt(a.v, b.v)}; }
HWY_INLINE LaneMask operator<(LaneF a, LaneF b) { return {hn::Lt(a.v, b.v)}; }
HWY_INLINE LaneMask operator>=(LaneF a, LaneF b) { return {hn::Ge(a.v, b.v)}; }
HWY_INLINE LaneF select(LaneMask m, LaneF a, LaneF b) { return {hn::IfThenElse(m.m, a.v, b.v)}; }
HWY_INLINE LaneF maxOf(LaneF a, LaneF b) { return select(a > b, a, b); }
HWY_INLINE LaneF minOf(LaneF a, LaneF b) { return select(a < b, a, b); }
HWY_INLINE LaneF sqrtOf(LaneF a) { return {hn::Sqrt(a.v)}; }
HWY_INLINE LaneF floorOf(LaneF a) { return {hn::Floor(a.v)}; }
HWY_INLINE LaneF truncOf(LaneF a) { return {hn::Trunc(a.v)}; }
HWY_INLINE LaneMask isFinite(LaneF a) { return {hn::IsFinite(a.v)}; }
HWY_INLINE LaneMask isNaN(LaneF a) { return {hn::IsNaN(a.v)}; }
HWY_INLINE LaneMask operator==(LaneF a, LaneF b) { return {hn::Eq(a.v, b.v)}; }
HWY_INLINE LaneMask operator<=(LaneF a, LaneF b) { return {hn::Le(a.v, b.v)}; }
// Round to nearest, halves to even (Highway's Round is round-half-even, as rintf).
HWY_INLINE LaneF roundEvenOf(LaneF a) { return {hn::Round(a.v)}; }
HWY_INLINE LaneF absOf(LaneF a) { return {hn::Abs(a.v)}; }
// table[index] per lane, for integer-valued indices within the table.
HWY_INLINE LaneF lookupLanes(const float* table, LaneF index) {
  return {hn::GatherIndex(DF(), table, hn::ConvertTo(DI(), index.v))};
}
// The smallest and largest lane (for integer-valued lanes such as a mip level).
HWY_INLINE float lowestLane(LaneF a) { return hn::GetLane(hn::MinOfLanes(DF(), a.v)); }
HWY_INLINE float highestLane(LaneF a) { return hn::GetLane(hn::MaxOfLanes(DF(), a.v)); }
// Float bits: for x = m 2^e (normal), m in [1, 2) and e, both as floats (exact).
HWY_INLINE LaneF floatMantissaOf(LaneF x) {
  const DU du;
  const auto bits = hn::BitCast(du, x.v);
  return {hn::BitCast(DF(), hn::Or(hn::And(bits, hn::Set(du, 0x007FFFFFu)), hn::Set(du, 0x3F800000u)))};
}
HWY_INLINE LaneF floatExponentOf(LaneF x) {
  const DU du;
  const auto biased = hn::And(hn::ShiftRight<23>(hn::BitCast(du, x.v)), hn::Set(du, 0xFFu));
  return {hn::Sub(hn::ConvertTo(DF(), hn::BitCast(DI(), biased)), hn::Set(DF(), 127.0f))};
}

struct LaneI {
  hn::Vec<DI> v;
  LaneI() = default;
  HWY_INLINE LaneI(hn::Vec<DI> raw) : v(raw) {}
  HWY_INLINE LaneI(std::int32_t x) : v(hn::Set(DI(), x)) {}
};
HWY_INLINE LaneI select(LaneMask m, LaneI a, LaneI b) {
  return {hn::IfThenElse(hn::RebindMask(DI(), m.m), a.v, b.v)};
}

// Double lanes: the lanes of one LaneF, lower half in lo, upper half in hi.
struct LaneWMask {
  hn::Mask<DW> lo;
#if HWY_TARGET != HWY_SCALAR
  hn::Mask<DW> hi;
#endif
};
struct LaneW {
  hn::Vec<DW> lo;
#if HWY_TARGET != HWY_SCALAR
  hn::Vec<DW> hi;
#endif
  LaneW() = default;
#if HWY_TARGET == HWY_SCALAR
  HWY_INLINE LaneW(hn::Vec<DW> l) : lo(l) {}
  HWY_INLINE LaneW(double x) : lo(hn::Set(DW(), x)) {}
#else
  HWY_INLINE LaneW(hn::Vec<DW> l, hn::Vec<DW> h) : lo(l), hi(h) {}
  HWY_INLINE LaneW(double x) : lo(hn::Set(DW(), x)), hi(hn::Set(DW(), x)) {}
#endif
};
#if HWY_TARGET == HWY_SCALAR
#define TWR_WIDE_OP(name, expr) \
  HWY_INLINE LaneW name(LaneW a, LaneW b) { return {expr(a.lo, b.lo)}; }
#define TWR_WIDE_CMP(name, expr) \
  HWY_INLINE LaneWMask name(LaneW a, LaneW b) { return {expr(a.lo, b.lo)}; }
#else
#define TWR_WIDE_OP(name, expr) \
  HWY_INLINE LaneW name(LaneW a, LaneW b) { return {expr(a.lo, b.lo), expr(a.hi, b.hi)}; }
#define TWR_WIDE_CMP(name, expr) \
  HWY_INLINE LaneWMask name(LaneW a, LaneW b) { return {expr(a.lo, b.lo), expr(a.hi, b.hi)}; }
#endif
TWR_WIDE_OP(operator+, hn::Add)
TWR_WIDE_OP(operator-, hn::Sub)
TWR_WIDE_OP(operator*, hn::Mul)
TWR_WIDE_OP(operator/, hn::Div)
TWR_WIDE_CMP(operator>, hn::Gt)
TWR_WIDE_CMP(operator<, hn::Lt)
#undef TWR_WIDE_OP
#undef TWR_WIDE_CMP
HWY_INLINE LaneW& operator+=(LaneW& a, LaneW b) { return a = a + b; }

HWY_INLINE LaneW select(LaneWMask m, LaneW a, LaneW b) {
#if HWY_TARGET == HWY_SCALAR
  return {hn::IfThenElse(m.lo, a.lo, b.lo)};
#else
  return {hn::IfThenElse(m.lo, a.lo, b.lo), hn::IfThenElse(m.hi, a.hi, b.hi)};
#endif
}
HWY_INLINE LaneW maxOf(LaneW a, LaneW b) { return select(a > b, a, b); }
HWY_INLINE LaneW minOf(LaneW a, LaneW b) { return select(a < b, a, b); }
HWY_INLINE LaneWMask isNaN(LaneW a) {
#if HWY_TARGET == HWY_SCALAR
  return {hn::IsNaN(a.lo)};
#else
  return {hn::IsNaN(a.lo), hn::IsNaN(a.hi)};
#endif
}
HWY_INLINE LaneW floorOf(LaneW a) {
#if HWY_TARGET == HWY_SCALAR
  return {hn::Floor(a.lo)};
#else
  return {hn::Floor(a.lo), hn::Floor(a.hi)};
#endif
}
HWY_INLINE LaneW roundEvenOf(LaneW a) {
#if HWY_TARGET == HWY_SCALAR
  return {hn::Round(a.lo)};
#else
  return {hn::Round(a.lo), hn::Round(a.hi)};
#endif
}

// Float lanes to double lanes (exact) and back (rounded to nearest).
HWY_INLINE LaneW toWide(LaneF a) {
#if HWY_TARGET == HWY_SCALAR
  return {hn::PromoteTo(DW(), a.v)};
#else
  return {hn::PromoteTo(DW(), hn::LowerHalf(DH(), a.v)), hn::PromoteTo(DW(), hn::UpperHalf(DH(), a.v))};
#endif
}
HWY_INLINE LaneF toNarrowLanes(LaneW a) {
#if HWY_TARGET == HWY_SCALAR || HWY_TARGET == HWY_EMU128
  // The emulated targets' DemoteTo saturates at the largest float; IEEE rounds past it to
  // infinity (as x86 and NEON do), so the lanes are converted one by one.
  HWY_ALIGN double wide[HWY_MAX_BYTES / sizeof(float)];
  HWY_ALIGN float narrow[HWY_MAX_BYTES / sizeof(float)];
  hn::Store(a.lo, DW(), wide);
#if HWY_TARGET != HWY_SCALAR
  hn::Store(a.hi, DW(), wide + hn::Lanes(DW()));
#endif
  for (size_t l = 0; l < hn::Lanes(DF()); ++l) narrow[l] = static_cast<float>(wide[l]);
  return {hn::Load(DF(), narrow)};
#else
  return {hn::Combine(DF(), hn::DemoteTo(DH(), a.hi), hn::DemoteTo(DH(), a.lo))};
#endif
}

// a b + c rounded once, as std::fma. Targets with FMA instructions (AVX2, AVX-512, NEON on
// AArch64) fuse; the others (SSE4, SSSE3, EMU128, SCALAR) compute it exactly in double: the
// product of two floats is exact there, the sum is rounded to odd (Boldo and Melquiond: a
// result with at least two more bits than float, rounded to odd, then rounded to float, is
// the correctly rounded float), so every target gives std::fma's bits.
#if !HWY_NATIVE_FMA
HWY_INLINE hn::Vec<DW> sumRoundedToOddHalf(hn::Vec<DW> p, hn::Vec<DW> c) {
  const DW dw;
  const DW64 du;
  const auto sum = hn::Add(p, c);
  // Knuth's two-sum: sum + error == p + c exactly.
  const auto cPart = hn::Sub(sum, p);
  const auto pPart = hn::Sub(sum, cPart);
  const auto error = hn::Add(hn::Sub(p, pPart), hn::Sub(c, cPart));
  // Inexact and even: step one ULP towards the exact value (magnitude up when the error has
  // the sum's sign, down otherwise), which makes the last bit 1.
  const auto bits = hn::BitCast(du, sum);
  const auto even = hn::Eq(hn::And(bits, hn::Set(du, 1u)), hn::Zero(du));
  const auto inexact = hn::And(hn::Ne(error, hn::Zero(dw)), hn::IsFinite(sum));
  const auto sameSign = hn::Eq(hn::ShiftRight<63>(hn::Xor(bits, hn::BitCast(du, error))), hn::Zero(du));
  const auto stepped = hn::IfThenElse(sameSign, hn::Add(bits, hn::Set(du, 1u)), hn::Sub(bits, hn::Set(du, 1u)));
  const auto adjust = hn::And(hn::RebindMask(du, inexact), even);
  return hn::BitCast(dw, hn::IfThenElse(adjust, stepped, bits));
}
// Lanes where rounding the double sum s (the exact a b + c rounded to double) to float may
// differ from rounding the exact value: s exactly halfway between two normal floats (bit 28 of
// the 52-bit fraction set, the 28 below it clear), or s in the float subnormals' range, whose
// halfway points lie elsewhere. Anywhere else the exact value and s are on the same side of
// every halfway point, so one more rounding gives the correctly rounded float.
HWY_INLINE hn::Mask<DW> mayRoundTwiceHalf(hn::Vec<DW> s) {
  const DW dw;
  const DW64 du;
  constexpr std::uint64_t kDroppedBits = (std::uint64_t{1} << 29) - 1;  // double fraction bits float drops
  constexpr std::uint64_t kHalfway = std::uint64_t{1} << 28;
  constexpr double kSmallestNormalFloat = 1.17549435082228750797e-38;  // FLT_MIN
  const auto halfway = hn::Eq(hn::And(hn::BitCast(du, s), hn::Set(du, kDroppedBits)), hn::Set(du, kHalfway));
  const auto magnitude = hn::Abs(s);
  const auto subnormal = hn::And(hn::Lt(magnitude, hn::Set(dw, kSmallestNormalFloat)), hn::Gt(magnitude, hn::Zero(dw)));
  return hn::Or(hn::RebindMask(dw, halfway), subnormal);
}
#endif
HWY_INLINE LaneF fusedMulAdd(LaneF a, LaneF b, LaneF c) {
#if HWY_NATIVE_FMA
  return {hn::MulAdd(a.v, b.v, c.v)};
#else
  const LaneW p = toWide(a) * toWide(b);
  const LaneW cw = toWide(c);
  // Usually the plain double sum rounds to the right float; rounding to odd only where it may not.
#if HWY_TARGET == HWY_SCALAR
  const LaneW sum(hn::Add(p.lo, cw.lo));
  if (hn::AllFalse(DW(), mayRoundTwiceHalf(sum.lo))) return toNarrowLanes(sum);
  return toNarrowLanes(LaneW(sumRoundedToOddHalf(p.lo, cw.lo)));
#else
  const LaneW sum(hn::Add(p.lo, cw.lo), hn::Add(p.hi, cw.hi));
  if (hn::AllFalse(DW(), hn::Or(mayRoundTwiceHalf(sum.lo), mayRoundTwiceHalf(sum.hi)))) return toNarrowLanes(sum);
  return toNarrowLanes(LaneW(sumRoundedToOddHalf(p.lo, cw.lo), sumRoundedToOddHalf(p.hi, cw.hi)));
#endif
#endif
}

#if !HWY_NATIVE_FMA
// fusedMulAdd(a1, b1, fusedMulAdd(a2, b2, c)) for an attribute plane whose two sums are exact
// in double (planeSumsExactInDouble, interpolate.h), b1 and b2 pixel indices (integers in
// [0, 2^15]): each product is exact in double (24 + 16 bits), each sum exact by that check, so
// the one rounding of each sum to float is std::fma's, with no double-rounding check.
HWY_INLINE LaneF fusedMulAddsOfExactSums(LaneF a1, LaneF b1, LaneF a2, LaneF b2, LaneF c) {
  const LaneF inner = toNarrowLanes(toWide(a2) * toWide(b2) + toWide(c));
  return toNarrowLanes(toWide(a1) * toWide(b1) + toWide(inner));
}
#endif

// Bit-level helpers of lanes.h's mantissaOf / exponentOf / exp2Integer, lane by lane (each
// exact, so the same bits as the scalar versions).
HWY_INLINE hn::Vec<DW> mantissaOfHalf(hn::Vec<DW> x) {
  using namespace doublebits;
  const DW64 du;
  const auto bits = hn::BitCast(du, x);
  return hn::BitCast(DW(), hn::Or(hn::And(bits, hn::Set(du, kMantissaMask)), hn::Set(du, kOneBits)));
}
HWY_INLINE hn::Vec<DW> exponentOfHalf(hn::Vec<DW> x) {
  using namespace doublebits;
  const DW64 du;
  // The biased exponent (an integer below 2^11) in the low bits of 2^52's mantissa, then
  // 2^52 subtracted: the integer as a double, exactly.
  const auto biased = hn::And(hn::ShiftRight<kMantissaBits>(hn::BitCast(du, x)), hn::Set(du, kExponentMask));
  const auto asDouble = hn::BitCast(DW(), hn::Or(biased, hn::BitCast(du, hn::Set(DW(), kTwoTo52))));
  return hn::Sub(hn::Sub(asDouble, hn::Set(DW(), kTwoTo52)), hn::Set(DW(), static_cast<double>(kExponentBias)));
}
HWY_INLINE hn::Vec<DW> exp2IntegerHalf(hn::Vec<DW> k) {
  using namespace doublebits;
  const DW64 du;
  // k + bias (an integer in [1, 2046]) in the low mantissa bits of 2^52 + k + bias, shifted
  // into the exponent field; the bits above it shift out.
  const auto biased = hn::Add(hn::Add(k, hn::Set(DW(), static_cast<double>(kExponentBias))), hn::Set(DW(), kTwoTo52));
  return hn::BitCast(DW(), hn::ShiftLeft<kMantissaBits>(hn::BitCast(du, biased)));
}
#if HWY_TARGET == HWY_SCALAR
HWY_INLINE LaneW mantissaOf(LaneW x) { return {mantissaOfHalf(x.lo)}; }
HWY_INLINE LaneW exponentOf(LaneW x) { return {exponentOfHalf(x.lo)}; }
HWY_INLINE LaneW exp2Integer(LaneW k) { return {exp2IntegerHalf(k.lo)}; }
#else
HWY_INLINE LaneW mantissaOf(LaneW x) { return {mantissaOfHalf(x.lo), mantissaOfHalf(x.hi)}; }
HWY_INLINE LaneW exponentOf(LaneW x) { return {exponentOfHalf(x.lo), exponentOfHalf(x.hi)}; }
HWY_INLINE LaneW exp2Integer(LaneW k) { return {exp2IntegerHalf(k.lo), exp2IntegerHalf(k.hi)}; }
#endif

// Small vectors of lanes, with GLM's componentwise operators (same order, same roundings).
template <typename L>
struct Vec2L {
  L x, y;
  Vec2L() = default;
  HWY_INLINE explicit Vec2L(L s) : x(s), y(s) {}
  HWY_INLINE Vec2L(L x_, L y_) : x(x_), y(y_) {}
};
template <typename L>
struct Vec3L {
  L x, y, z;
  Vec3L() = default;
  HWY_INLINE explicit Vec3L(L s) : x(s), y(s), z(s) {}
  HWY_INLINE Vec3L(L x_, L y_, L z_) : x(x_), y(y_), z(z_) {}
  // A uniform broadcast to every lane.
  HWY_INLINE explicit Vec3L(const glm::vec3& v) : x(v.x), y(v.y), z(v.z) {}
};
template <typename L>
struct Vec4L {
  L x, y, z, w;
  Vec4L() = default;
  HWY_INLINE explicit Vec4L(L s) : x(s), y(s), z(s), w(s) {}
  HWY_INLINE Vec4L(L x_, L y_, L z_, L w_) : x(x_), y(y_), z(z_), w(w_) {}
  HWY_INLINE Vec4L(const Vec3L<L>& v, L w_) : x(v.x), y(v.y), z(v.z), w(w_) {}
};
template <typename L>
HWY_INLINE Vec2L<L> operator+(const Vec2L<L>& a, const Vec2L<L>& b) { return {a.x + b.x, a.y + b.y}; }
template <typename L>
HWY_INLINE Vec2L<L> operator-(const Vec2L<L>& a, const Vec2L<L>& b) { return {a.x - b.x, a.y - b.y}; }
template <typename L>
HWY_INLINE Vec2L<L> operator*(const Vec2L<L>& a, const Vec2L<L>& b) { return {a.x * b.x, a.y * b.y}; }
template <typename L>
HWY_INLINE Vec2L<L> operator*(const Vec2L<L>& a, L s) { return {a.x * s, a.y * s}; }
template <typename L>
HWY_INLINE Vec3L<L> operator+(const Vec3L<L>& a, const Vec3L<L>& b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
template <typename L>
HWY_INLINE Vec3L<L> operator-(const Vec3L<L>& a, const Vec3L<L>& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
template <typename L>
HWY_INLINE Vec3L<L> operator*(const Vec3L<L>& a, const Vec3L<L>& b) { return {a.x * b.x, a.y * b.y, a.z * b.z}; }
template <typename L>
HWY_INLINE Vec3L<L> operator*(const Vec3L<L>& a, L s) { return {a.x * s, a.y * s, a.z * s}; }
template <typename L>
HWY_INLINE Vec3L<L> operator*(L s, const Vec3L<L>& a) { return {s * a.x, s * a.y, s * a.z}; }
template <typename L>
HWY_INLINE Vec3L<L> operator+(const Vec3L<L>& a, L s) { return {a.x + s, a.y + s, a.z + s}; }
template <typename L>
HWY_INLINE Vec3L<L> operator-(const Vec3L<L>& a, L s) { return {a.x - s, a.y - s, a.z - s}; }
template <typename L>
HWY_INLINE Vec3L<L>& operator+=(Vec3L<L>& a, const Vec3L<L>& b) { return a = a + b; }
template <typename L>
HWY_INLINE Vec4L<L> operator+(const Vec4L<L>& a, const Vec4L<L>& b) {
  return {a.x + b.x, a.y + b.y, a.z + b.z, a.w + b.w};
}
template <typename L>
HWY_INLINE Vec4L<L> operator-(const Vec4L<L>& a, const Vec4L<L>& b) {
  return {a.x - b.x, a.y - b.y, a.z - b.z, a.w - b.w};
}
template <typename L>
HWY_INLINE Vec4L<L> operator*(const Vec4L<L>& a, L s) { return {a.x * s, a.y * s, a.z * s, a.w * s}; }
template <typename L>
HWY_INLINE Vec4L<L> operator*(L s, const Vec4L<L>& a) { return {s * a.x, s * a.y, s * a.z, s * a.w}; }

}  // namespace HWY_NAMESPACE

// The fast path's lane traits (specialising twr::LaneTraits of lanes.h).
template <>
struct LaneTraits<HWY_NAMESPACE::LaneF> {
  using Scalar = float;
  using Wide = HWY_NAMESPACE::LaneW;
  using Mask = HWY_NAMESPACE::LaneMask;
  using Int = HWY_NAMESPACE::LaneI;
};

namespace HWY_NAMESPACE {
template <typename L>
HWY_INLINE L toNarrow(LaneW a);
template <>
HWY_INLINE LaneF toNarrow<LaneF>(LaneW a) {
  return toNarrowLanes(a);
}
template <typename L>
HWY_INLINE L splat(float a) {
  return L(a);
}
template <typename L>
HWY_INLINE LaneW wideSplat(double a) {
  return LaneW(a);
}
}  // namespace HWY_NAMESPACE

}  // namespace twr
HWY_AFTER_NAMESPACE();

#endif  // TWR_LANES_HWY_INL_TARGET toggle
