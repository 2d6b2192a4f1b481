// Lanes: the number type the one shading source is written over (docs/pipeline.md, "One
// shading source"). A lane type L is one of
//   float    the teaching path: one pixel at a time, easy to step through;
//   double   the reference renderer: the same operations in double precision;
//   LaneF    the fast path: a Highway vector of floats, one pixel (or vertex) per lane, compiled once
//            per SIMD target (softrender/lanes_hwy-inl.h).
// The shared sources (vertex_stage-inl.h, phong_pow-inl.h, texture_sample-inl.h, interpolate-inl.h,
// output_merge-inl.h, shade-inl.h) use only what every lane type provides:
//   + - * / on L, comparisons giving MaskOf<L>, & | ! on masks, select(mask, a, b),
//   maxOf / minOf (written as selects, so every target treats NaN alike), sqrtOf, floorOf,
//   truncOf, isFinite, anyOf, fusedMulAdd (a b + c rounded once), WideOf<L> (double lanes for the parts computed in double) with
//   toWide / toNarrow, IntOf<L> for texel indices, and Vec2L / Vec3L / Vec4L of lanes.
// Every operation is IEEE single or double with round-to-nearest, contraction off (set in
// CMakeLists.txt), no approximate reciprocal or square root: each lane of a vector computes
// exactly what the float instantiation computes for that pixel, on every target.
//
// This header holds the scalar lane types. Each shared "-inl.h" source is included twice
// over: once plainly into namespace twr (float and double), and once per Highway target into
// twr::HWY_NAMESPACE by softrender/fast_kernels-inl.h (which defines TWR_LANES_HIGHWAY around
// those includes), so that the vector instantiations are compiled with that target's
// instructions (Highway's foreach_target mechanism; see hwy/foreach_target.h).
#pragma once

#include "scene/conventions.h"
#include "softrender/precision.h"

#include <bit>
#include <cmath>
#include <cstdint>
#include <type_traits>

namespace twr {

// The scalar lane types and their companions.
template <typename L>
struct LaneTraits;
template <>
struct LaneTraits<float> {
  using Scalar = float;         // the type of one lane
  using Wide = double;          // what the float pipeline computes in double
  using Mask = bool;
  using Int = std::int32_t;     // texel indices
};
template <>
struct LaneTraits<double> {
  using Scalar = double;
  using Wide = double;
  using Mask = bool;
  using Int = std::int32_t;
};
template <typename L>
using ScalarOf = typename LaneTraits<L>::Scalar;
template <typename L>
using WideOf = typename LaneTraits<L>::Wide;
template <typename L>
using MaskOf = typename LaneTraits<L>::Mask;
template <typename L>
using IntOf = typename LaneTraits<L>::Int;

// Vectors of lanes: GLM's for scalar lanes (componentwise operators in the order the shared
// source writes them).
template <typename L>
using Vec2L = glm::vec<2, L>;
template <typename L>
using Vec3L = glm::vec<3, L>;
template <typename L>
using Vec4L = glm::vec<4, L>;

template <typename S>
concept ScalarLane = std::is_floating_point_v<S>;

template <ScalarLane S>
inline S select(bool mask, S ifTrue, S ifFalse) {
  return mask ? ifTrue : ifFalse;
}
inline std::int32_t select(bool mask, std::int32_t ifTrue, std::int32_t ifFalse) { return mask ? ifTrue : ifFalse; }
// a > b ? a : b, and a < b ? a : b: a NaN in a gives b, on every lane type.
template <ScalarLane S>
inline S maxOf(S a, S b) {
  return a > b ? a : b;
}
template <ScalarLane S>
inline S minOf(S a, S b) {
  return a < b ? a : b;
}
template <ScalarLane S>
inline S sqrtOf(S a) {
  return std::sqrt(a);
}
template <ScalarLane S>
inline S floorOf(S a) {
  return std::floor(a);
}
template <ScalarLane S>
inline S truncOf(S a) {
  return std::trunc(a);
}
// a b + c with one rounding (IEEE fusedMultiplyAdd): llvmpipe evaluates its attribute planes
// this way on CPUs with FMA.
template <ScalarLane S>
inline S fusedMulAdd(S a, S b, S c) {
  return std::fma(a, b, c);
}
// table[index] for an integer-valued index in [0, table size) (a gather on vector lanes).
template <ScalarLane S>
inline S lookupLanes(const float* table, S index) {
  return static_cast<S>(table[static_cast<std::size_t>(index)]);
}
// Round to the nearest integer, halves to even (the default rounding mode).
template <ScalarLane S>
inline S roundEvenOf(S a) {
  return std::nearbyint(a);
}
template <ScalarLane S>
inline bool isFinite(S a) {
  return std::isfinite(a);
}
template <ScalarLane S>
inline bool isNaN(S a) {
  return a != a;
}
inline bool anyOf(bool mask) { return mask; }
inline bool allOf(bool mask) { return mask; }
template <ScalarLane S>
inline S absOf(S a) {
  return std::fabs(a);
}
// The smallest and largest lane: the value itself for one lane.
template <ScalarLane S>
inline S lowestLane(S a) {
  return a;
}
template <ScalarLane S>
inline S highestLane(S a) {
  return a;
}
// IEEE single fields of a float value x = m 2^e (normal): m in [1, 2) and e, exact. For a
// double lane the value is taken as the float it holds (the reference computes LODs as GL).
template <ScalarLane S>
inline S floatMantissaOf(S x) {
  const std::uint32_t bits = std::bit_cast<std::uint32_t>(static_cast<float>(x));
  return static_cast<S>(std::bit_cast<float>((bits & 0x007FFFFFu) | 0x3F800000u));
}
template <ScalarLane S>
inline S floatExponentOf(S x) {
  const std::uint32_t bits = std::bit_cast<std::uint32_t>(static_cast<float>(x));
  return static_cast<S>(static_cast<int>((bits >> 23) & 0xFFu) - 127);
}

template <ScalarLane S>
inline double toWide(S a) {
  return static_cast<double>(a);
}
// A double rounded to the lane type L (to nearest; no-op for double).
template <typename L>
inline L toNarrow(double a) {
  return static_cast<L>(a);
}
// A double broadcast to Wide lanes, for code written over L.
template <typename L>
inline WideOf<L> wideSplat(double a) {
  return a;
}
template <typename L>
inline L splat(ScalarOf<L> a) {
  return a;
}

// IEEE double fields, for the Phong exponent's log2 and exp2 (phong_pow-inl.h).
namespace doublebits {
inline constexpr int kMantissaBits = 52;
inline constexpr int kExponentBias = 1023;
inline constexpr std::uint64_t kMantissaMask = (std::uint64_t{1} << kMantissaBits) - 1;
inline constexpr std::uint64_t kExponentMask = 0x7FF;
inline constexpr std::uint64_t kOneBits = std::uint64_t{kExponentBias} << kMantissaBits;  // bits of 1.0
// 2^52 as a double: adding it to an integer 0 <= k < 2^52 leaves k in the low mantissa bits.
inline constexpr double kTwoTo52 = 4503599627370496.0;
}  // namespace doublebits

// For a positive normal double x = m 2^e with m in [1, 2): m (exact).
inline double mantissaOf(double x) {
  using namespace doublebits;
  return std::bit_cast<double>((std::bit_cast<std::uint64_t>(x) & kMantissaMask) | kOneBits);
}
// ... and e, as a double (exact).
inline double exponentOf(double x) {
  using namespace doublebits;
  const std::uint64_t biased = (std::bit_cast<std::uint64_t>(x) >> kMantissaBits) & kExponentMask;
  return static_cast<double>(biased) - kExponentBias;
}
// 2^k for an integer-valued k in [-1022, 1023] (exact).
inline double exp2Integer(double k) {
  using namespace doublebits;
  const std::uint64_t biased = static_cast<std::uint64_t>(k + kExponentBias);
  return std::bit_cast<double>(biased << kMantissaBits);
}

}  // namespace twr

// Opening and closing the namespace of a shared "-inl.h" source: plainly `twr` here;
// fast_kernels-inl.h redefines both to twr::HWY_NAMESPACE with the target's attributes.
#define TWR_LANES_BEGIN \
  namespace twr {        \
  namespace lanes {
#define TWR_LANES_END \
  }                   \
  }
// How the shared sources' functions are declared: plainly `inline` (the teaching path stays
// easy to step through); per target forced inline, because a vector struct passed to a call
// goes through memory (lanes_target_begin.h).
#define TWR_LANE_INLINE inline
// ... and a large one many kernels call (softrender/lanes_target_begin.h).
#define TWR_LANE_OUTLINE inline
// Whether a colour read (one mip level of a map) is inlined into its caller
// (softrender/lanes_target_begin.h): not plainly.
#define TWR_LANES_INLINE_COLOUR_READS 0
