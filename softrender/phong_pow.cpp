#include "softrender/phong_pow.h"

#include "softrender/phong_pow-inl.h"

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>

namespace twr {

float powPositive(float x, float s) { return lanes::phongPow<float>(x, s); }

}  // namespace twr
