#include "softrender/phong_pow.h"

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>

namespace twr {

float powPositive(float x, float s) {
  using namespace phongpow;
  if (!(x < std::numeric_limits<float>::infinity())) return s > 0.0f ? x : 1.0f;  // +inf^s
  // frexp gives m in [1/2, 1); doubling is exact and puts it in [1, 2), as AVX-512's getmant.
  int e = 0;
  double m = std::frexp(static_cast<double>(x), &e);
  m = m * 2.0;
  e = e - 1;
  if (m > kSqrt2) {
    m = m * 0.5;
    e = e + 1;
  }
  const double t = (m - 1.0) / (m + 1.0);
  const double t2 = t * t;
  double series = kLog2Coefficients[kLog2Terms - 1];
  for (int k = kLog2Terms - 2; k >= 0; --k) series = series * t2 + kLog2Coefficients[static_cast<std::size_t>(k)];
  const double log2x = static_cast<double>(e) + t * series;

  double y = static_cast<double>(s) * log2x;
  if (y != y) y = 0.0;  // infinity * 0
  y = std::fmin(std::fmax(y, -kMaxExponent), kMaxExponent);
  const double k = std::nearbyint(y);  // round half to even, as AVX-512's roundscale
  const double f = y - k;              // exact: |f| <= 1/2
  double p = kExp2Coefficients[kExp2Terms - 1];
  for (int n = kExp2Terms - 2; n >= 0; --n) p = p * f + kExp2Coefficients[static_cast<std::size_t>(n)];
  const std::uint64_t scaleBits = static_cast<std::uint64_t>(static_cast<std::int64_t>(k) + kDoubleExponentBias)
                                  << kDoubleMantissaBits;
  return static_cast<float>(p * std::bit_cast<double>(scaleBits));
}

}  // namespace twr
