// The Phong exponent x^s of the float pipeline, computed in double with every operation written
// out (no libm call): a whole s up to kMaxWholeExponent by binary powering (below), any other
// as 2^(s log2 x), written once over the lane type in phong_pow-inl.h
// so the SIMD fast path repeats the same operations lane by lane and gets the same bits. The result is the
// exactly rounded float of a value accurate to about 1e-15 relative, so it equals libm's
// powf except where powf itself is off by an ulp; GLSL leaves pow's precision to the driver.
//
//   x = m 2^e, m in [sqrt(1/2), sqrt(2))         (frexp, then one halving when m > sqrt(2))
//   log2 m = 2 / ln 2 * atanh(t) = sum_k c_k t^(2k+1),  t = (m - 1) / (m + 1), |t| <= 0.1716
//   y = s (e + log2 m), clamped to [-kMaxExponent, kMaxExponent]
//   2^y = 2^k 2^f,  k = nearest integer to y, f = y - k in [-1/2, 1/2]
//   2^f = sum_n (f ln 2)^n / n!
#pragma once

#include <array>

namespace twr {

namespace phongpow {

inline constexpr double kLn2 = 0.693147180559945309417232121458;
inline constexpr double kSqrt2 = 1.41421356237309504880168872421;

// Terms t^1 .. t^15 of the log series: the first term left out, t^17 2 / (17 ln 2), is below
// 2e-14 for |t| <= 0.1716, so y = s log2 x is off by at most s 2e-14 and x^s by a relative
// 1.4e-14 s: for any exponent a scene uses, far below half an ulp of float (6e-8).
inline constexpr int kLog2Terms = 8;
// Terms up to (f ln 2)^10 / 10!: the first left out is below 3e-13 (relative) for |f| <= 1/2.
inline constexpr int kExp2Terms = 11;
// Whole exponents from 1 to this are computed by binary powering (x^n by squarings and
// products in double): up to 2 kWholeExponentBits roundings of relative 2^-53, each at most
// doubled by the squarings after it, so x^n is within 2n 2^-53 <= 2^-44 (relative) of the
// true value, far below half an ulp of float (2^-24) as the series is; eight squarings and
// products instead of the series' 20 terms and a division. A Phong exponent is usually whole.
inline constexpr int kWholeExponentBits = 8;
inline constexpr double kMaxWholeExponent = 255.0;
static_assert(kMaxWholeExponent == (1 << kWholeExponentBits) - 1, "every whole exponent fits the bits powered");
constexpr bool isWholeExponent(double s) {
  return s >= 1.0 && s <= kMaxWholeExponent && s == static_cast<double>(static_cast<int>(s));
}
// |y| above this gives 0 or infinity in float anyway (2^-150 rounds to 0, 2^128 overflows);
// clamping keeps 2^k a normal double.
inline constexpr double kMaxExponent = 160.0;
// Exponent bias and mantissa bits of an IEEE double, to build 2^k from its bits.
inline constexpr int kDoubleExponentBias = 1023;
inline constexpr int kDoubleMantissaBits = 52;

// c_k = 2 / ((2k + 1) ln 2), evaluated by the compiler in double.
constexpr std::array<double, kLog2Terms> log2Coefficients() {
  std::array<double, kLog2Terms> c{};
  for (int k = 0; k < kLog2Terms; ++k) c[static_cast<std::size_t>(k)] = 2.0 / ((2 * k + 1) * kLn2);
  return c;
}
// e_n = (ln 2)^n / n!.
constexpr std::array<double, kExp2Terms> exp2Coefficients() {
  std::array<double, kExp2Terms> e{};
  double term = 1.0;
  for (int n = 0; n < kExp2Terms; ++n) {
    e[static_cast<std::size_t>(n)] = term;
    term = term * kLn2 / (n + 1);
  }
  return e;
}
inline constexpr std::array<double, kLog2Terms> kLog2Coefficients = log2Coefficients();
inline constexpr std::array<double, kExp2Terms> kExp2Coefficients = exp2Coefficients();

}  // namespace phongpow

// x^s for x > 0 (finite or +infinity) and s >= 0, as described above. A NaN product
// s log2 x (s infinite and x = 1) counts as 0, so 1^s = 1.
float powPositive(float x, float s);

}  // namespace twr
