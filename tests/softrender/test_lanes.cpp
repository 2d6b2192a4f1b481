// The one shading source (softrender/*-inl.h) compiled here for every Highway target, as
// softrender/fast_kernels.cpp compiles it, and checked lane by lane against its float
// instantiation: the attenuation, the Phong exponent, the fused multiply-add, texture sampling
// and the byte conversion give the float path's bits on every target. A deliberately reordered copy of the
// attenuation (Horner's form, algebraically equal) must NOT give them: it proves that these
// comparisons see a change in the order of operations, so a SIMD path that did not run the
// shared source would fail them.

// clang-format off
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "tests/softrender/test_lanes.cpp"
#include <hwy/foreach_target.h>  // re-includes this file, once per target
#include <hwy/highway.h>
// clang-format on

#include "softrender/shade.h"
#include "softrender/fast_kernels.h"
#include "softrender/texture_sample.h"
#include "softrender/framebuffer.h"

#include <gtest/gtest.h>
#include <hwy/tests/hwy_gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <iterator>
#include <limits>
#include <random>
#include <vector>

#include "softrender/lanes_target_begin.h"
#include "softrender/lanes_hwy-inl.h"
#include "softrender/lane_math-inl.h"
#include "softrender/texel_lanes-inl.h"
#include "softrender/output_merge-inl.h"
#include "softrender/phong_pow-inl.h"
#include "softrender/interpolate-inl.h"

HWY_BEFORE_NAMESPACE();
namespace twr {
namespace HWY_NAMESPACE {
constexpr std::size_t kMaxLanes = HWY_MAX_BYTES / sizeof(float);
// A plain Texture as the vector lanes read it in this test, texel by texel (the level sizes,
// wrap and sRGB are texture_sample.h's own, the indices the fast path's texel_lanes-inl.h).
template <typename L>
HWY_INLINE Vec4L<LaneF> fetchTexelBytes(const Texture& t, int level, LaneI x, LaneI y) {
  HWY_ALIGN std::int32_t xs[kMaxLanes], ys[kMaxLanes];
  HWY_ALIGN float channels[4][kMaxLanes];
  hn::Store(x.v, DI(), xs);
  hn::Store(y.v, DI(), ys);
  for (std::size_t l = 0; l < laneCount(); ++l) {
    const vec4 texel = fetchTexelBytes<float>(t, level, xs[l], ys[l]);
    for (int c = 0; c < 4; ++c) channels[c][l] = texel[c];
  }
  return Vec4L<LaneF>(LaneF(hn::Load(DF(), channels[0])), LaneF(hn::Load(DF(), channels[1])),
                      LaneF(hn::Load(DF(), channels[2])), LaneF(hn::Load(DF(), channels[3])));
}
HWY_INLINE LaneF linearFromSrgbByte(LaneF byte) {
  HWY_ALIGN float values[kMaxLanes];
  hn::Store(byte.v, DF(), values);
  for (std::size_t l = 0; l < laneCount(); ++l) values[l] = ::twr::linearFromSrgbByte(values[l]);
  return {hn::Load(DF(), values)};
}
}  // namespace HWY_NAMESPACE
}  // namespace twr
HWY_AFTER_NAMESPACE();

#include "softrender/texture_sample-inl.h"
#include "softrender/shade-inl.h"

HWY_BEFORE_NAMESPACE();
namespace twr {
namespace HWY_NAMESPACE {

// Runs `lanes(x)` on values[] a vector at a time and `scalar(x)` on each value; counts the
// values whose bits differ.
template <typename LaneFn, typename ScalarFn>
std::size_t countDifferences(const std::vector<float>& values, const LaneFn& lanes, const ScalarFn& scalar) {
  HWY_ALIGN float in[kMaxLanes];
  HWY_ALIGN float out[kMaxLanes];
  std::size_t differences = 0;
  for (std::size_t i = 0; i < values.size(); i += laneCount()) {
    for (std::size_t l = 0; l < laneCount(); ++l) in[l] = i + l < values.size() ? values[i + l] : 1.0f;
    hn::Store(lanes(LaneF(hn::Load(DF(), in))).v, DF(), out);
    for (std::size_t l = 0; l < laneCount() && i + l < values.size(); ++l) {
      if (std::bit_cast<std::uint32_t>(out[l]) != std::bit_cast<std::uint32_t>(scalar(in[l]))) ++differences;
    }
  }
  return differences;
}

std::vector<float> distances() {
  std::mt19937 rng(3);
  std::uniform_real_distribution<float> d(0.0f, 50.0f);
  std::vector<float> values(20000);
  for (float& v : values) v = d(rng);
  return values;
}

void AttenuationIsTheSharedSourceAndSeesAReordering() {
  const vec3 a(1.0f, 0.09f, 0.032f);  // LearnOpenGL's 50-unit light
  const std::vector<float> d = distances();
  const auto shared = [&](LaneF x) HWY_ATTR { return attenuation<LaneF>(a, x); };
  const auto teaching = [&](float x) { return ::twr::lanes::attenuation<float>(a, x); };  // the plain (teaching) instantiation
  EXPECT_EQ(countDifferences(d, shared, teaching), 0u) << "target " << hwy::TargetName(HWY_TARGET);
  // The same formula in Horner's form: equal in exact arithmetic, not in float.
  const auto horner = [&](LaneF x) HWY_ATTR {
    const LaneF denominator = LaneF(a.x) + x * (LaneF(a.y) + LaneF(a.z) * x);
    return LaneF(1.0f) / maxOf(denominator, LaneF(kMinAttenuationDenominator));
  };
  EXPECT_GT(countDifferences(d, horner, teaching), 100u)
      << "a reordered attenuation gave the shared source's bits: the bit-identity tests could not see it";
}

// fusedMulAdd, the uv planes' one rounding: std::fma's bits on every target, those with FMA
// instructions and those that compute it in double (rounded to odd where the plain double sum
// may round twice). The inputs include products landing exactly on a float rounding tie plus a
// tiny c, where rounding the double sum again to float (double rounding) picks the wrong
// neighbour: proven below; and results among the float subnormals. They come in runs of 64:
// ordinary values alone (whole vectors take the plain double sum), ties alone, subnormals
// alone, and ties and ordinary values in alternate lanes.
void FusedMulAddIsStdFmaOnEveryTarget() {
  std::mt19937 rng(11);
  std::uniform_real_distribution<float> any(-1000.0f, 1000.0f);
  std::uniform_real_distribution<float> tiny(-4e-20f, 4e-20f);
  std::uniform_int_distribution<std::uint32_t> bits13(4096, 8191);
  std::vector<float> as, bs, cs;
  const auto ordinary = [&](int i) {
    as.push_back(any(rng));
    bs.push_back(any(rng));
    cs.push_back(i % 4 == 0 ? any(rng) : -as.back() * bs.back());  // also near-total cancellation
  };
  const auto tie = [&](int i) {
    // Two 13-bit integers: a 25- or 26-bit product, often exactly halfway between floats;
    // c a tiny nudge either way decides the rounding.
    as.push_back(static_cast<float>(bits13(rng)));
    bs.push_back(static_cast<float>(bits13(rng)) * 0.5f);
    cs.push_back((i % 4 == 1 ? 1.0f : -1.0f) * 1e-20f);
  };
  std::uniform_int_distribution<std::uint32_t> oddSteps(0, (1u << 20) - 1);
  const auto subnormal = [&](int i) {
    // Results below FLT_MIN (1.2e-38), where float's halfway points are not a normal float's.
    if (i % 2 == 0) {  // random: c is 0 or of the same order as the product
      as.push_back(tiny(rng));
      bs.push_back(tiny(rng));
      cs.push_back(i % 4 == 0 ? 0.0f : std::ldexp(tiny(rng), -100));
      return;
    }
    // A tie in the subnormals: c = k 2^-149 with k odd, a b = 2^-150 (1 - 2^-46), so the exact
    // sum lies just below c's halfway point to the next subnormal and rounds down to c, while
    // the double sum rounds onto the halfway point, and again to float, to the even k + 1.
    const float sign = i % 4 == 1 ? 1.0f : -1.0f;
    as.push_back(sign * std::ldexp(1.0f + 0x1p-23f, -75));
    bs.push_back(std::ldexp(1.0f - 0x1p-23f, -75));
    cs.push_back(sign * std::ldexp(static_cast<float>(2 * oddSteps(rng) + 1), -149));
  };
  for (int i = 0; i < 32000; ++i) {
    switch ((i / 64) % 4) {
      case 0: ordinary(i); break;
      case 1: tie(i); break;
      case 2: subnormal(i); break;
      default: i % 2 == 0 ? ordinary(i) : tie(i); break;
    }
  }
  HWY_ALIGN float a[kMaxLanes], b[kMaxLanes], c[kMaxLanes], out[kMaxLanes];
  std::size_t differences = 0, doubleRoundingMisses = 0;
  for (std::size_t i = 0; i + laneCount() <= as.size(); i += laneCount()) {
    for (std::size_t l = 0; l < laneCount(); ++l) {
      a[l] = as[i + l];
      b[l] = bs[i + l];
      c[l] = cs[i + l];
    }
    const LaneF r = fusedMulAdd(LaneF(hn::Load(DF(), a)), LaneF(hn::Load(DF(), b)), LaneF(hn::Load(DF(), c)));
    hn::Store(r.v, DF(), out);
    for (std::size_t l = 0; l < laneCount(); ++l) {
      const float expected = std::fma(a[l], b[l], c[l]);
      if (std::bit_cast<std::uint32_t>(out[l]) != std::bit_cast<std::uint32_t>(expected)) ++differences;
      const float doubleRounded =
          static_cast<float>(static_cast<double>(a[l]) * static_cast<double>(b[l]) + static_cast<double>(c[l]));
      if (doubleRounded != expected) ++doubleRoundingMisses;
    }
  }
  EXPECT_EQ(differences, 0u) << "target " << hwy::TargetName(HWY_TARGET);
  EXPECT_GT(doubleRoundingMisses, 100u) << "no input where double rounding fails: the test could not see it";
}

// planeAt, two fused multiply-adds: std::fma's bits on every target, for planes that take the
// short way of targets without fused multiply-adds (planeSumsExactInDouble) and planes that do
// not, at pixel indices from 0 to 2^15.
void PlaneAtIsStdFmaOnEveryTarget() {
  std::mt19937 rng(23);
  std::uniform_int_distribution<std::uint32_t> mantissa(1u << 23, (1u << 24) - 1);
  std::uniform_int_distribution<int> exponent(-20, 20), spread(-20, 40), pixel(0, 1 << 15);
  const auto coefficient = [&](int e) {
    const float sign = mantissa(rng) % 2 == 0 ? 1.0f : -1.0f;
    return sign * std::ldexp(static_cast<float>(mantissa(rng)), e - 23);
  };
  HWY_ALIGN float px[kMaxLanes], out[kMaxLanes];
  std::size_t differences = 0, exactPlanes = 0, otherPlanes = 0;
  for (int plane = 0; plane < 4000; ++plane) {
    const int e = exponent(rng);
    const AttributePlaneT<float> t{coefficient(e), coefficient(e - spread(rng)), coefficient(e - spread(rng))};
    AttributePlaneL<LaneF> p{LaneF(t.atOrigin), LaneF(t.dx), LaneF(t.dy)};
#if !HWY_NATIVE_FMA
    p.sumsExactInDouble = planeSumsExactInDouble(t);
#endif
    ++(planeSumsExactInDouble(t) ? exactPlanes : otherPlanes);
    const float py = static_cast<float>(plane % 3 == 0 ? 1 << 15 : pixel(rng));
    for (std::size_t l = 0; l < laneCount(); ++l) px[l] = static_cast<float>(l == 0 ? 0 : pixel(rng));
    hn::Store(planeAt<LaneF>(p, LaneF(hn::Load(DF(), px)), LaneF(py)).v, DF(), out);
    for (std::size_t l = 0; l < laneCount(); ++l) {
      const float expected = std::fma(t.dy, py, std::fma(t.dx, px[l], t.atOrigin));
      if (std::bit_cast<std::uint32_t>(out[l]) != std::bit_cast<std::uint32_t>(expected)) ++differences;
    }
  }
  EXPECT_EQ(differences, 0u) << "target " << hwy::TargetName(HWY_TARGET);
  EXPECT_GT(exactPlanes, 500u);
  EXPECT_GT(otherPlanes, 500u);
}

void PhongPowAndBytesAreTheSharedSource() {
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> x(-0.1f, 1.1f);
  std::vector<float> values(20000);
  for (float& v : values) v = x(rng);
  for (const float s : {0.0f, 1.0f, 7.5f, 32.0f, 200.0f}) {
    const auto lanes = [&](LaneF v) HWY_ATTR { return phongPow<LaneF>(v, s); };
    const auto scalar = [&](float v) { return ::twr::lanes::phongPow<float>(v, s); };
    EXPECT_EQ(countDifferences(values, lanes, scalar), 0u) << "s = " << s;
  }
  const auto lanes = [](LaneF v) HWY_ATTR { return byteValueOf<LaneF>(v); };
  const auto scalar = [](float v) { return static_cast<float>(unitToByte(v)); };
  EXPECT_EQ(countDifferences(values, lanes, scalar), 0u);
}

// One exponent per lane (the deferred pass): each lane gets phongPow's bits for its own s, in
// vectors that mix whole exponents (binary powering) with the rest (the series).
void PerLanePhongPowMixesBothMethods() {
  std::mt19937 rng(6);
  std::uniform_real_distribution<float> x(-0.1f, 1.1f);
  const float exponents[] = {0.0f, 1.0f, 3.0f, 7.5f, 32.0f, 255.0f, 256.0f, 0.5f, 1.0e5f};
  HWY_ALIGN float xs[kMaxLanes], ss[kMaxLanes], out[kMaxLanes];
  std::size_t differences = 0, at = 0;
  for (int round = 0; round < 4000; ++round) {
    for (std::size_t l = 0; l < laneCount(); ++l, ++at) {
      xs[l] = x(rng);
      ss[l] = exponents[(at + static_cast<std::size_t>(round / 100)) % std::size(exponents)];
    }
    if (round % 3 == 0) std::fill(ss, ss + laneCount(), 32.0f);  // every lane whole
    hn::Store(phongPowPerLane<LaneF>(LaneF(hn::Load(DF(), xs)), LaneF(hn::Load(DF(), ss))).v, DF(), out);
    for (std::size_t l = 0; l < laneCount(); ++l) {
      const float expected = ::twr::lanes::phongPow<float>(xs[l], ss[l]);
      if (std::bit_cast<std::uint32_t>(out[l]) != std::bit_cast<std::uint32_t>(expected)) ++differences;
    }
  }
  EXPECT_EQ(differences, 0u) << "target " << hwy::TargetName(HWY_TARGET);
}

// What the float results above cannot show (both methods nearly always round to the same
// float): which lanes take the powering (phongpow::isWholeExponent's, lane by lane, NaN and the
// range's ends included), and that per-lane powering multiplies in powWholeWide's order (the
// double results bit for bit).
void PerLanePoweringIsTheUniformOne() {
  const float exponents[] = {std::nanf(""), -3.0f, 0.0f, 0.999f, 1.0f, 2.0f, 3.0f, 7.5f, 32.0f, 100.0f,
                             254.5f, 255.0f, 256.0f, 1.0e5f, std::numeric_limits<float>::infinity()};
  HWY_ALIGN float ss[kMaxLanes];
  HWY_ALIGN std::int32_t picked[kMaxLanes];
  for (std::size_t first = 0; first < std::size(exponents); ++first) {
    for (std::size_t l = 0; l < laneCount(); ++l) ss[l] = exponents[(first + l) % std::size(exponents)];
    const MaskOf<LaneF> whole = wholeExponentLanes<LaneF>(LaneF(hn::Load(DF(), ss)));
    hn::Store(hn::VecFromMask(DI(), hn::RebindMask(DI(), whole.m)), DI(), picked);
    for (std::size_t l = 0; l < laneCount(); ++l) {
      EXPECT_EQ(picked[l] != 0, phongpow::isWholeExponent(static_cast<double>(ss[l]))) << "s = " << ss[l];
    }
  }
  std::mt19937 rng(8);
  std::uniform_real_distribution<float> x(0.0f, 1.1f);
  std::uniform_int_distribution<int> n(1, static_cast<int>(phongpow::kMaxWholeExponent));
  HWY_ALIGN float xs[kMaxLanes], ns[kMaxLanes];
  HWY_ALIGN double wide[kMaxLanes];
  std::size_t differences = 0;
  for (int round = 0; round < 2000; ++round) {
    for (std::size_t l = 0; l < laneCount(); ++l) xs[l] = x(rng), ns[l] = static_cast<float>(n(rng));
    const LaneW powered = powWholeWidePerLane(toWide(LaneF(hn::Load(DF(), xs))), toWide(LaneF(hn::Load(DF(), ns))));
    hn::Store(powered.lo, DW(), wide);
#if HWY_TARGET != HWY_SCALAR
    hn::Store(powered.hi, DW(), wide + hn::Lanes(DW()));
#endif
    for (std::size_t l = 0; l < laneCount(); ++l) {
      const double expected = ::twr::lanes::powWholeWide<double>(xs[l], static_cast<unsigned>(ns[l]));
      if (std::bit_cast<std::uint64_t>(wide[l]) != std::bit_cast<std::uint64_t>(expected)) ++differences;
    }
  }
  EXPECT_EQ(differences, 0u) << "target " << hwy::TargetName(HWY_TARGET);
}

void SamplingIsTheSharedSource() {
  Texture texture;
  texture.width = 5;  // not a power of two
  texture.height = 3;
  texture.rgba.resize(5 * 3 * 4);
  for (std::size_t i = 0; i < texture.rgba.size(); ++i) texture.rgba[i] = static_cast<std::uint8_t>(i * 37 % 256);
  buildMipChain(texture);
  std::mt19937 rng(9);
  std::uniform_real_distribution<float> uv(-3.0f, 3.0f), lods(-1.5f, 3.5f);
  std::vector<float> us(4000), vs(4000), lodValues(4000);
  for (std::size_t i = 0; i < us.size(); ++i) us[i] = uv(rng), vs[i] = uv(rng), lodValues[i] = lods(rng);
  for (const TextureWrap wrap : {TextureWrap::Repeat, TextureWrap::MirroredRepeat, TextureWrap::ClampToEdge}) {
    for (const bool srgb : {false, true}) {
      texture.options.wrap = wrap;
      texture.options.srgb = srgb;
      for (const TextureFilter filter : kAllTextureFilters) {
        for (int channel = 0; channel < 4; ++channel) {
          std::size_t at = 0;  // us[i] pairs with vs[i] and lodValues[i]: all walk the same indices
          const auto lanes = [&](LaneF u) HWY_ATTR {
            HWY_ALIGN float v[kMaxLanes], lod[kMaxLanes];
            for (std::size_t l = 0; l < laneCount(); ++l) {
              v[l] = at + l < vs.size() ? vs[at + l] : 1.0f;
              lod[l] = at + l < lodValues.size() ? lodValues[at + l] : 0.0f;
            }
            at += laneCount();
            const Vec4L<LaneF> texel = sampleTexture<LaneF>(texture, Vec2L<LaneF>(u, LaneF(hn::Load(DF(), v))),
                                                            filter, LaneF(hn::Load(DF(), lod)));
            return channel == 0 ? texel.x : channel == 1 ? texel.y : channel == 2 ? texel.z : texel.w;
          };
          std::size_t scalarAt = 0;
          const auto scalar = [&](float u) {
            const bool inRange = scalarAt < vs.size();
            const vec4 texel = sampleTexture<float>(texture, vec2(u, inRange ? vs[scalarAt] : 1.0f), filter,
                                                    inRange ? lodValues[scalarAt] : 0.0f);
            ++scalarAt;
            return texel[channel];
          };
          EXPECT_EQ(countDifferences(us, lanes, scalar), 0u)
              << toString(filter) << " " << toString(wrap) << (srgb ? " srgb" : "") << " channel " << channel;
        }
      }
    }
  }
}

}  // namespace HWY_NAMESPACE
}  // namespace twr
HWY_AFTER_NAMESPACE();

#include "softrender/lanes_target_end.h"

#if HWY_ONCE
namespace twr {
namespace {
HWY_BEFORE_TEST(SharedSource);
HWY_EXPORT_AND_TEST_P(SharedSource, AttenuationIsTheSharedSourceAndSeesAReordering);
HWY_EXPORT_AND_TEST_P(SharedSource, PhongPowAndBytesAreTheSharedSource);
HWY_EXPORT_AND_TEST_P(SharedSource, FusedMulAddIsStdFmaOnEveryTarget);
HWY_EXPORT_AND_TEST_P(SharedSource, PlaneAtIsStdFmaOnEveryTarget);
HWY_EXPORT_AND_TEST_P(SharedSource, PerLanePhongPowMixesBothMethods);
HWY_EXPORT_AND_TEST_P(SharedSource, PerLanePoweringIsTheUniformOne);
HWY_EXPORT_AND_TEST_P(SharedSource, SamplingIsTheSharedSource);
}  // namespace
}  // namespace twr
#endif
