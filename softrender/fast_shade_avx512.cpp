// The AVX-512 kernels (fast_shade_avx512.h). Read them beside the scalar stages they repeat:
// every lane does the operations of pixelWeights (interpolate.cpp), interpolateFragment,
// shadeFragment (shade.h), sampleBilinear / sampleNearest (texture_sample.cpp), powPositive
// (phong_pow.cpp) and unitToByte (framebuffer.cpp) in the same order on the same types, so
// each lane rounds as the scalar code does. Lanes the scalar code would not compute (outside
// the triangle, failing the depth test) are computed and discarded by the lane masks.
//
// Everything below is compiled for AVX-512 with floating-point contraction off (a fused
// multiply-add rounds once where the scalar code rounds twice) and sits in an anonymous
// namespace, so the linker can never hand an AVX-512 copy of a function to another caller.
#include "softrender/fast_shade_avx512.h"

#include "softrender/phong_pow.h"
#include "softrender/texture_sample.h"

// GCC 12's AVX-512 headers make "undefined" vectors by initialising them from themselves
// (GCC bug 105593), which -Wuninitialized then reports in every function that inlines them.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wuninitialized"
#if !defined(__clang__)
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#endif
#include <immintrin.h>

#include <algorithm>
#include <cstddef>
#include <array>
#include <bit>
#include <cstdint>
#include <cstring>
#include <limits>
#include <utility>
#include <vector>

namespace twr {

bool cpuHasAvx512() {
  static const bool has = __builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512dq") &&
                          __builtin_cpu_supports("avx512bw") && __builtin_cpu_supports("avx512vl");
  return has;
}

TiledTexture makeTiledTexture(const Texture& texture) {
  TiledTexture out;
  out.width = texture.width;
  out.height = texture.height;
  out.blocksPerRow = (texture.width + kTexelBlockSide - 1) / kTexelBlockSide;
  const int blockRows = (texture.height + kTexelBlockSide - 1) / kTexelBlockSide;
  out.blocks.resize(static_cast<std::size_t>(out.blocksPerRow) * static_cast<std::size_t>(blockRows));
  for (int y = 0; y < texture.height; ++y) {
    for (int x = 0; x < texture.width; ++x) {
      TexelBlock& block = out.blocks[static_cast<std::size_t>(y / kTexelBlockSide) * static_cast<std::size_t>(out.blocksPerRow) +
                                     static_cast<std::size_t>(x / kTexelBlockSide)];
      std::memcpy(&block.texels[static_cast<std::size_t>((y % kTexelBlockSide) * kTexelBlockSide + x % kTexelBlockSide)],
                  texture.texel(x, y), sizeof(std::uint32_t));
    }
  }
  return out;
}

// The kernels' functions are compiled for AVX-512 and without contraction (a * b + c stays
// two roundings, as in the scalar stages). clang (the fuzzing build) spells both differently.
#if defined(__clang__)
#pragma clang attribute push(__attribute__((target("avx512f,avx512dq,avx512bw,avx512vl"))), apply_to = function)
#pragma clang fp contract(off)
#else
#pragma GCC push_options
#pragma GCC target("avx512f,avx512dq,avx512bw,avx512vl")
#pragma GCC optimize("fp-contract=off")
#endif

namespace {

// Block geometry: 16 lanes = 4 x 4 pixels, lane = 4 * row + column.
constexpr int kBlockSide = 4;
constexpr int kLanes = kBlockSide * kBlockSide;
constexpr __mmask16 kRowLanes = 0xF;  // the four lanes of one block row
// _mm512_fpclass_ps_mask categories: quiet NaN | +infinity | -infinity | signalling NaN.
constexpr int kNotFiniteClasses = 0x01 | 0x08 | 0x10 | 0x80;
constexpr float kByteMax = 255.0f;
constexpr float kByteScale = 1.0f / 255.0f;  // texelAt's T(1) / T(kMaxByte)
constexpr float kHalf = 0.5f;                // texel centres; round half away from zero
constexpr std::uint32_t kByteMask = 0xFF;
constexpr std::uint32_t kOpaqueAlpha = 0xFF000000u;
// Coordinates the SIMD texel wrap handles with 32-bit integers (exclusive bound); larger ones
// take the scalar footprint (a repeat count that large is a test case, not a scene).
constexpr float kMaxSimdTexelCoord = 1073741824.0f;  // 2^30

// ---- 16 floats ----
struct Vf {
  __m512 v;
};
inline Vf operator+(Vf a, Vf b) { return {_mm512_add_ps(a.v, b.v)}; }
inline Vf operator-(Vf a, Vf b) { return {_mm512_sub_ps(a.v, b.v)}; }
inline Vf operator*(Vf a, Vf b) { return {_mm512_mul_ps(a.v, b.v)}; }
inline Vf operator/(Vf a, Vf b) { return {_mm512_div_ps(a.v, b.v)}; }
inline Vf splat(float x) { return {_mm512_set1_ps(x)}; }
inline Vf sqrtOf(Vf a) { return {_mm512_sqrt_ps(a.v)}; }
inline Vf floorOf(Vf a) { return {_mm512_roundscale_ps(a.v, _MM_FROUND_TO_NEG_INF | _MM_FROUND_NO_EXC)}; }
inline Vf truncOf(Vf a) { return {_mm512_roundscale_ps(a.v, _MM_FROUND_TO_ZERO | _MM_FROUND_NO_EXC)}; }
// (a > b) ? a : b per lane: std::fmax(a, b) whenever b is not NaN (a NaN a gives b).
inline Vf maxOf(Vf a, Vf b) { return {_mm512_max_ps(a.v, b.v)}; }
// (a < b) ? a : b per lane: std::fmin(a, b) whenever b is not NaN.
inline Vf minOf(Vf a, Vf b) { return {_mm512_min_ps(a.v, b.v)}; }
inline Vf select(__mmask16 m, Vf ifTrue, Vf ifFalse) { return {_mm512_mask_blend_ps(m, ifFalse.v, ifTrue.v)}; }
inline __mmask16 less(Vf a, Vf b) { return _mm512_cmp_ps_mask(a.v, b.v, _CMP_LT_OQ); }
inline __mmask16 greater(Vf a, Vf b) { return _mm512_cmp_ps_mask(a.v, b.v, _CMP_GT_OQ); }
inline __mmask16 greaterEqual(Vf a, Vf b) { return _mm512_cmp_ps_mask(a.v, b.v, _CMP_GE_OQ); }
inline __mmask16 finite(Vf a) { return static_cast<__mmask16>(~_mm512_fpclass_ps_mask(a.v, kNotFiniteClasses)); }

// ---- 16 doubles as two halves (lanes 0..7, 8..15) ----
struct Vd {
  __m512d lo, hi;
};
inline Vd operator+(Vd a, Vd b) { return {_mm512_add_pd(a.lo, b.lo), _mm512_add_pd(a.hi, b.hi)}; }
inline Vd operator*(Vd a, Vd b) { return {_mm512_mul_pd(a.lo, b.lo), _mm512_mul_pd(a.hi, b.hi)}; }
inline Vd operator/(Vd a, Vd b) { return {_mm512_div_pd(a.lo, b.lo), _mm512_div_pd(a.hi, b.hi)}; }
inline Vd splatD(double x) { return {_mm512_set1_pd(x), _mm512_set1_pd(x)}; }
inline Vd toDouble(Vf a) {
  return {_mm512_cvtps_pd(_mm512_castps512_ps256(a.v)), _mm512_cvtps_pd(_mm512_extractf32x8_ps(a.v, 1))};
}
// Rounded to nearest, as static_cast<float>(double).
inline Vf toFloat(Vd a) {
  return {_mm512_insertf32x8(_mm512_castps256_ps512(_mm512_cvtpd_ps(a.lo)), _mm512_cvtpd_ps(a.hi), 1)};
}
inline __mmask16 greaterD(Vd a, Vd b) {
  const __mmask8 lo = _mm512_cmp_pd_mask(a.lo, b.lo, _CMP_GT_OQ);
  const __mmask8 hi = _mm512_cmp_pd_mask(a.hi, b.hi, _CMP_GT_OQ);
  return static_cast<__mmask16>(lo | (hi << 8));
}

// ---- 3-vectors of lanes, with glm's operation order ----
struct V3 {
  Vf x, y, z;
};
inline V3 operator+(const V3& a, const V3& b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
inline V3 operator-(const V3& a, const V3& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
inline V3 operator*(const V3& a, const V3& b) { return {a.x * b.x, a.y * b.y, a.z * b.z}; }
inline V3 operator*(const V3& a, Vf s) { return {a.x * s, a.y * s, a.z * s}; }
inline V3 operator*(Vf s, const V3& a) { return {s * a.x, s * a.y, s * a.z}; }
inline V3 splat3(vec3 v) { return {splat(v.x), splat(v.y), splat(v.z)}; }
inline V3 select3(__mmask16 m, const V3& a, const V3& b) {
  return {select(m, a.x, b.x), select(m, a.y, b.y), select(m, a.z, b.z)};
}
// glm::dot: tmp = a * b; tmp.x + tmp.y + tmp.z.
inline Vf dot3(const V3& a, const V3& b) { return (a.x * b.x + a.y * b.y) + a.z * b.z; }

// safeNormalize (scene/conventions.h): (0, 0, 1) unless kMinLengthSquared < |v|^2 < infinity.
inline V3 safeNormalize3(const V3& v) {
  const Vf lengthSquared = dot3(v, v);
  const Vf infinity = splat(std::numeric_limits<float>::infinity());
  const __mmask16 usable = greater(lengthSquared, splat(kMinLengthSquared)) & less(lengthSquared, infinity);
  const Vf length = sqrtOf(lengthSquared);
  const V3 normalised{v.x / length, v.y / length, v.z / length};
  return select3(usable, normalised, V3{splat(0.0f), splat(0.0f), splat(1.0f)});
}

// interpolateFragment: a0 * p0 + a1 * p1 + a2 * p2, summed from the left.
struct Weights {
  Vf p0, p1, p2;
};
inline Vf interpolate(Vf a0, Vf a1, Vf a2, const Weights& w) { return (a0 * w.p0 + a1 * w.p1) + a2 * w.p2; }

// ---- textures ----
inline __m512i wrapPowerOfTwo(__m512i i, int size) { return _mm512_and_si512(i, _mm512_set1_epi32(size - 1)); }
// floor(i / size) reduced to [0, size) for |i| < 2^30: the quotient in double is within
// 2^-22 of the true one, far from the next integer, so its floor is exact.
inline __m512i wrapAnySize(__m512i i, int size) {
  const __m512d sizeD = _mm512_set1_pd(size);
  const __m512d lo = _mm512_cvtepi32_pd(_mm512_castsi512_si256(i));
  const __m512d hi = _mm512_cvtepi32_pd(_mm512_extracti64x4_epi64(i, 1));
  const __m512d qLo = _mm512_roundscale_pd(_mm512_div_pd(lo, sizeD), _MM_FROUND_TO_NEG_INF | _MM_FROUND_NO_EXC);
  const __m512d qHi = _mm512_roundscale_pd(_mm512_div_pd(hi, sizeD), _MM_FROUND_TO_NEG_INF | _MM_FROUND_NO_EXC);
  const __m512i q = _mm512_inserti64x4(_mm512_castsi256_si512(_mm512_cvtpd_epi32(qLo)), _mm512_cvtpd_epi32(qHi), 1);
  return _mm512_sub_epi32(i, _mm512_mullo_epi32(q, _mm512_set1_epi32(size)));
}
// wrappedFloor for an integer-valued float below 2^30 in magnitude.
inline __m512i wrapFloor(Vf integral, int size) {
  const __m512i i = _mm512_cvttps_epi32(integral.v);
  return (size & (size - 1)) == 0 ? wrapPowerOfTwo(i, size) : wrapAnySize(i, size);
}

// Which texels one sample reads and with what weights (sampleFootprint, per lane), and where
// those texels are in a TiledTexture of that size.
struct Footprint {
  __m512i x0, y0, x1, y1;
  Vf alpha, beta;                  // bilinear only
  __m512i i00, i10, i01, i11;      // tiled indices of (x0, y0), (x1, y0), (x0, y1), (x1, y1)
};

// Tiled index of texel (x, y): ((y / 4) blocksPerRow + x / 4) 16 + (y % 4) 4 + x % 4.
inline __m512i tiledRow(__m512i y, int blocksPerRow) {
  const __m512i blockRow = _mm512_mullo_epi32(_mm512_srli_epi32(y, 2), _mm512_set1_epi32(blocksPerRow * 16));
  return _mm512_add_epi32(blockRow, _mm512_slli_epi32(_mm512_and_si512(y, _mm512_set1_epi32(3)), 2));
}
inline __m512i tiledColumn(__m512i x) {
  return _mm512_add_epi32(_mm512_slli_epi32(_mm512_srli_epi32(x, 2), 4), _mm512_and_si512(x, _mm512_set1_epi32(3)));
}
inline void setTiledIndices(Footprint& f, int width) {
  const int blocksPerRow = (width + kTexelBlockSide - 1) / kTexelBlockSide;
  const __m512i row0 = tiledRow(f.y0, blocksPerRow), row1 = tiledRow(f.y1, blocksPerRow);
  const __m512i column0 = tiledColumn(f.x0), column1 = tiledColumn(f.x1);
  f.i00 = _mm512_add_epi32(row0, column0);
  f.i10 = _mm512_add_epi32(row0, column1);
  f.i01 = _mm512_add_epi32(row1, column0);
  f.i11 = _mm512_add_epi32(row1, column1);
}

inline __m512i nextTexel(__m512i i, int size) {
  const __m512i next = _mm512_add_epi32(i, _mm512_set1_epi32(1));
  const __mmask16 wraps = _mm512_cmpeq_epi32_mask(next, _mm512_set1_epi32(size));
  return _mm512_mask_blend_epi32(wraps, next, _mm512_setzero_si512());
}

// The scalar footprint, lane by lane, for blocks with coordinates too large for the SIMD wrap.
Footprint scalarFootprint(const Texture& texture, Vf u, Vf v, TextureFilter filter, __mmask16 lanes) {
  alignas(64) std::array<float, kLanes> us{}, vs{}, alphas{}, betas{};
  alignas(64) std::array<std::int32_t, kLanes> x0{}, y0{}, x1{}, y1{};
  _mm512_store_ps(us.data(), u.v);
  _mm512_store_ps(vs.data(), v.v);
  for (int l = 0; l < kLanes; ++l) {
    if (((lanes >> l) & 1) == 0) continue;
    const std::size_t k = static_cast<std::size_t>(l);
    const SampleFootprint f = sampleFootprint<float>(texture, vec2(us[k], vs[k]), filter);
    x0[k] = f.x0, y0[k] = f.y0, x1[k] = f.x1, y1[k] = f.y1;
    alphas[k] = f.alpha, betas[k] = f.beta;
  }
  Footprint f;
  f.x0 = _mm512_load_si512(x0.data());
  f.y0 = _mm512_load_si512(y0.data());
  f.x1 = _mm512_load_si512(x1.data());
  f.y1 = _mm512_load_si512(y1.data());
  f.alpha = Vf{_mm512_load_ps(alphas.data())};
  f.beta = Vf{_mm512_load_ps(betas.data())};
  setTiledIndices(f, texture.width);
  return f;
}

Footprint footprint(const Texture& texture, Vf u, Vf v, TextureFilter filter, __mmask16 lanes) {
  const Vf width = splat(static_cast<float>(texture.width));
  const Vf height = splat(static_cast<float>(texture.height));
  Footprint f;
  if (filter == TextureFilter::Nearest) {
    // nearestTexelIndex: floor(coord * size) of the float product, wrapped; 0 if not finite.
    const Vf fu = floorOf(u * width), fv = floorOf(v * height);
    const __mmask16 finiteU = finite(fu), finiteV = finite(fv);
    const Vf limit = splat(kMaxSimdTexelCoord);
    const Vf absU = {_mm512_abs_ps(fu.v)}, absV = {_mm512_abs_ps(fv.v)};
    if ((lanes & ((finiteU & ~less(absU, limit)) | (finiteV & ~less(absV, limit)))) != 0) {
      return scalarFootprint(texture, u, v, filter, lanes);
    }
    f.x0 = _mm512_maskz_mov_epi32(finiteU, wrapFloor(select(finiteU, fu, splat(0.0f)), texture.width));
    f.y0 = _mm512_maskz_mov_epi32(finiteV, wrapFloor(select(finiteV, fv, splat(0.0f)), texture.height));
    f.x1 = f.x0;
    f.y1 = f.y0;
    f.alpha = splat(0.0f);
    f.beta = splat(0.0f);
    setTiledIndices(f, texture.width);
    return f;
  }
  // Bilinear: u' = u w - 0.5, i0 = floor(u'), alpha = u' - i0 (0 and texel 0 if not finite).
  const Vf uTexel = u * width - splat(kHalf), vTexel = v * height - splat(kHalf);
  const __mmask16 finiteU = finite(uTexel), finiteV = finite(vTexel);
  const Vf fu = floorOf(uTexel), fv = floorOf(vTexel);
  const Vf limit = splat(kMaxSimdTexelCoord);
  const Vf absU = {_mm512_abs_ps(fu.v)}, absV = {_mm512_abs_ps(fv.v)};
  if ((lanes & ((finiteU & ~less(absU, limit)) | (finiteV & ~less(absV, limit)))) != 0) {
    return scalarFootprint(texture, u, v, filter, lanes);
  }
  f.alpha = select(finiteU, uTexel - fu, splat(0.0f));
  f.beta = select(finiteV, vTexel - fv, splat(0.0f));
  f.x0 = _mm512_maskz_mov_epi32(finiteU, wrapFloor(select(finiteU, fu, splat(0.0f)), texture.width));
  f.y0 = _mm512_maskz_mov_epi32(finiteV, wrapFloor(select(finiteV, fv, splat(0.0f)), texture.height));
  f.x1 = nextTexel(f.x0, texture.width);
  f.y1 = nextTexel(f.y0, texture.height);
  setTiledIndices(f, texture.width);
  return f;
}

// One texel per lane as RGB in [0, 1] (texelAt: byte * (1 / 255)).
inline V3 texels(const TiledTexture& texture, __m512i index, __mmask16 lanes) {
  const __m512i rgba = _mm512_mask_i32gather_epi32(_mm512_setzero_si512(), lanes, index, texture.blocks.data(), 4);
  const __m512i byteMask = _mm512_set1_epi32(kByteMask);
  const auto channel = [&](int shift) {
    const __m512i bytes = _mm512_and_si512(_mm512_srli_epi32(rgba, static_cast<unsigned>(shift)), byteMask);
    return Vf{_mm512_cvtepi32_ps(bytes)} * splat(kByteScale);
  };
  return {channel(0), channel(8), channel(16)};
}

// sampleTexture's RGB: nearest reads one texel; bilinear
// ((1-a)(1-b) T00 + a(1-b) T10) + (1-a) b T01) + a b T11.
V3 sample(const TiledTexture& texture, const Footprint& f, TextureFilter filter, __mmask16 lanes) {
  if (filter == TextureFilter::Nearest) return texels(texture, f.i00, lanes);
  const Vf one = splat(1.0f);
  const Vf w00 = (one - f.alpha) * (one - f.beta);
  const Vf w10 = f.alpha * (one - f.beta);
  const Vf w01 = (one - f.alpha) * f.beta;
  const Vf w11 = f.alpha * f.beta;
  const V3 t00 = texels(texture, f.i00, lanes), t10 = texels(texture, f.i10, lanes);
  const V3 t01 = texels(texture, f.i01, lanes), t11 = texels(texture, f.i11, lanes);
  return ((w00 * t00 + w10 * t10) + w01 * t01) + w11 * t11;
}

// ---- the Phong exponent (powPositive, phong_pow.cpp), 8 doubles at a time ----
__m512d powPositiveHalf(__m512d x, __m512d s) {
  using namespace phongpow;
  __m512d m = _mm512_getmant_pd(x, _MM_MANT_NORM_1_2, _MM_MANT_SIGN_src);  // frexp's m * 2
  __m512d e = _mm512_getexp_pd(x);                                         // frexp's e - 1
  const __mmask8 halve = _mm512_cmp_pd_mask(m, _mm512_set1_pd(kSqrt2), _CMP_GT_OQ);
  m = _mm512_mask_mul_pd(m, halve, m, _mm512_set1_pd(0.5));
  e = _mm512_mask_add_pd(e, halve, e, _mm512_set1_pd(1.0));
  const __m512d one = _mm512_set1_pd(1.0);
  const __m512d t = _mm512_div_pd(_mm512_sub_pd(m, one), _mm512_add_pd(m, one));
  const __m512d t2 = _mm512_mul_pd(t, t);
  __m512d series = _mm512_set1_pd(kLog2Coefficients[kLog2Terms - 1]);
  for (int k = kLog2Terms - 2; k >= 0; --k) {
    series = _mm512_add_pd(_mm512_mul_pd(series, t2), _mm512_set1_pd(kLog2Coefficients[static_cast<std::size_t>(k)]));
  }
  const __m512d log2x = _mm512_add_pd(e, _mm512_mul_pd(t, series));
  __m512d y = _mm512_mul_pd(s, log2x);
  y = _mm512_mask_mov_pd(y, _mm512_cmp_pd_mask(y, y, _CMP_UNORD_Q), _mm512_setzero_pd());
  y = _mm512_min_pd(_mm512_max_pd(y, _mm512_set1_pd(-kMaxExponent)), _mm512_set1_pd(kMaxExponent));
  const __m512d k = _mm512_roundscale_pd(y, _MM_FROUND_TO_NEAREST_INT | _MM_FROUND_NO_EXC);
  const __m512d f = _mm512_sub_pd(y, k);
  __m512d p = _mm512_set1_pd(kExp2Coefficients[kExp2Terms - 1]);
  for (int n = kExp2Terms - 2; n >= 0; --n) {
    p = _mm512_add_pd(_mm512_mul_pd(p, f), _mm512_set1_pd(kExp2Coefficients[static_cast<std::size_t>(n)]));
  }
  const __m512i biased = _mm512_add_epi64(_mm512_cvtpd_epi64(k), _mm512_set1_epi64(kDoubleExponentBias));
  const __m512d scale = _mm512_castsi512_pd(_mm512_slli_epi64(biased, kDoubleMantissaBits));
  return _mm512_mul_pd(p, scale);
}

// phongPow(x, s) for the lanes in `active`: x > 0 ? powPositive(x, s) : (s > 0 ? 0 : 1).
Vf phongPow16(Vf x, float s, __mmask16 active) {
  const Vf zeroCase = splat(s > 0.0f ? 0.0f : 1.0f);
  const __mmask16 positive = active & greater(x, splat(0.0f));
  if (positive == 0) return zeroCase;
  const Vf infinity = splat(std::numeric_limits<float>::infinity());
  const __mmask16 infinite = positive & ~less(x, infinity);
  // Lanes not computed hold 1, so nothing below sees a zero, a NaN or a negative number.
  const Vd xd = toDouble(select(positive & ~infinite, x, splat(1.0f)));
  const __m512d sd = _mm512_set1_pd(static_cast<double>(s));
  const Vf powered = toFloat(Vd{powPositiveHalf(xd.lo, sd), powPositiveHalf(xd.hi, sd)});
  const Vf infCase = s > 0.0f ? infinity : splat(1.0f);
  return select(infinite, infCase, select(positive, powered, zeroCase));
}

// ---- output merge ----
// unitToByte after glm::clamp(colour, 0, 1): NaN -> 0, else round(clamp(c) * 255), halves up.
inline __m512i toByte(Vf c) {
  const Vf clamped = minOf(maxOf(c, splat(0.0f)), splat(1.0f));
  const Vf scaled = clamped * splat(kByteMax);
  const Vf whole = truncOf(scaled);
  const Vf rounded = whole + select(greaterEqual(scaled - whole, splat(kHalf)), splat(1.0f), splat(0.0f));
  return _mm512_cvttps_epi32(rounded.v);
}


// ---- the visibility pass: 4 x 4 blocks ----
// Row R of a block: its four lanes, to or from `row` (lanes outside `mask` untouched; a row
// with no lane in `mask` is not addressed at all, so rows past the image need no pointer).
template <int R>
inline __mmask8 rowMask(__mmask16 mask) {
  return static_cast<__mmask8>((mask >> (kBlockSide * R)) & kRowLanes);
}
using BlockRows = std::array<float*, kBlockSide>;
using BlockSlotRows = std::array<std::uint32_t*, kBlockSide>;
template <int R>
inline __m512 loadRow(__m512 into, const BlockRows& rows, __mmask16 mask) {
  if (const __mmask8 m = rowMask<R>(mask)) return _mm512_insertf32x4(into, _mm_maskz_loadu_ps(m, rows[R]), R);
  return into;
}
template <int R>
inline void storeRow(const BlockRows& rows, __mmask16 mask, __m512 v) {
  if (const __mmask8 m = rowMask<R>(mask)) _mm_mask_storeu_ps(rows[R], m, _mm512_extractf32x4_ps(v, R));
}
template <int R>
inline void storeRow(const BlockSlotRows& rows, __mmask16 mask, __m512i v) {
  if (const __mmask8 m = rowMask<R>(mask)) _mm_mask_storeu_epi32(rows[R], m, _mm512_extracti32x4_epi32(v, R));
}

// Per-lane column and row inside the block.
inline __m512i laneColumns() { return _mm512_set_epi32(3, 2, 1, 0, 3, 2, 1, 0, 3, 2, 1, 0, 3, 2, 1, 0); }
inline __m512i laneRows() { return _mm512_set_epi32(3, 3, 3, 3, 2, 2, 2, 2, 1, 1, 1, 1, 0, 0, 0, 0); }
inline Vd toDouble(__m512i integers) {
  return {_mm512_cvtepi32_pd(_mm512_castsi512_si256(integers)),
          _mm512_cvtepi32_pd(_mm512_extracti64x4_epi64(integers, 1))};
}

// An edge function at the 16 lanes relative to the block origin: stepX * column + stepY * row,
// in two halves of 8 int64.
struct EdgeLanes {
  __m512i lo, hi;
};
EdgeLanes edgeLaneOffsets(const EdgeFunction& edge) {
  const __m512i columns = laneColumns(), rows = laneRows();
  const auto half = [&](__m256i c, __m256i r) {
    return _mm512_add_epi64(_mm512_mullo_epi64(_mm512_cvtepi32_epi64(c), _mm512_set1_epi64(edge.stepX)),
                            _mm512_mullo_epi64(_mm512_cvtepi32_epi64(r), _mm512_set1_epi64(edge.stepY)));
  };
  return {half(_mm512_castsi512_si256(columns), _mm512_castsi512_si256(rows)),
          half(_mm512_extracti64x4_epi64(columns, 1), _mm512_extracti64x4_epi64(rows, 1))};
}

// pixelWeights' barycentrics lambda_i = atOrigin + dx px + dy py, in double.
inline Vd lambdaAt(double atOrigin, double dx, double dy, const Vd& px, const Vd& py) {
  return (splatD(atOrigin) + splatD(dx) * px) + splatD(dy) * py;
}

}  // namespace

std::uint64_t visibilityAvx512(const TriangleSetup& setup, const std::array<WindowVertex, 3>& window,
                               std::uint32_t slot, int rowBegin, int rowEnd, Framebuffer& fb, std::uint32_t* slots,
                               InterpolationSetup& interpolation, bool& covered) {
  const int yFirst = std::max(setup.y0, rowBegin);
  const int yLast = std::min(setup.y1, rowEnd - 1);
  if (yFirst > yLast || setup.x0 > setup.x1) return 0;

  std::array<EdgeLanes, 3> laneOffsets;
  for (std::size_t e = 0; e < 3; ++e) laneOffsets[e] = edgeLaneOffsets(setup.edges[e]);
  const __m512i columns = laneColumns(), rows = laneRows();
  const Vd columnsD = toDouble(columns), rowsD = toDouble(rows);
  const __m512i slotLanes = _mm512_set1_epi32(static_cast<int>(slot));
  const __m512i zero = _mm512_setzero_si512();
  const std::size_t width = static_cast<std::size_t>(fb.width);
  std::uint64_t passed = 0;

  for (int by = yFirst & ~(kBlockSide - 1); by <= yLast; by += kBlockSide) {
    const __m512i py = _mm512_add_epi32(rows, _mm512_set1_epi32(by));
    const __mmask16 rowLanes =
        _mm512_cmpge_epi32_mask(py, _mm512_set1_epi32(yFirst)) & _mm512_cmple_epi32_mask(py, _mm512_set1_epi32(yLast));
    const Vd pyD = rowsD + splatD(by);
    for (int bx = setup.x0 & ~(kBlockSide - 1); bx <= setup.x1; bx += kBlockSide) {
      // Coverage: every edge function > 0 at the pixel centre, inside the bounding box.
      const __m512i px = _mm512_add_epi32(columns, _mm512_set1_epi32(bx));
      __mmask16 inside = rowLanes & _mm512_cmpge_epi32_mask(px, _mm512_set1_epi32(setup.x0)) &
                         _mm512_cmple_epi32_mask(px, _mm512_set1_epi32(setup.x1));
      for (std::size_t e = 0; e < 3 && inside != 0; ++e) {
        const EdgeFunction& edge = setup.edges[e];
        const __m512i origin = _mm512_set1_epi64(edge.c + edge.stepX * bx + edge.stepY * by);
        const __mmask8 lo = _mm512_cmpgt_epi64_mask(_mm512_add_epi64(origin, laneOffsets[e].lo), zero);
        const __mmask8 hi = _mm512_cmpgt_epi64_mask(_mm512_add_epi64(origin, laneOffsets[e].hi), zero);
        inside &= static_cast<__mmask16>(lo | (hi << 8));
      }
      if (inside == 0) continue;
      if (!covered) {
        interpolation = makeInterpolationSetup<float>(window, setup);
        covered = true;
      }

      // pixelWeights' depth: sum lambda_i z_i in double from 0, to float, clamped to [0, 1].
      const Vd pxD = columnsD + splatD(bx);
      Vd depthD = splatD(0.0);
      for (std::size_t i = 0; i < 3; ++i) {
        const Vd lambda = lambdaAt(interpolation.atOrigin[i], interpolation.dx[i], interpolation.dy[i], pxD, pyD);
        depthD = depthD + lambda * splatD(static_cast<double>(interpolation.zWindow[i]));
      }
      const Vf rounded = toFloat(depthD);
      const Vf depth = select(finite(rounded), minOf(maxOf(rounded, splat(0.0f)), splat(1.0f)), splat(1.0f));

      // GL_LESS against the block's four rows of the depth buffer.
      BlockRows depthRows{};
      BlockSlotRows slotRows{};
      for (int r = 0; r < kBlockSide && by + r <= yLast; ++r) {
        depthRows[static_cast<std::size_t>(r)] = &fb.depth[fb.index(bx, by + r)];
        slotRows[static_cast<std::size_t>(r)] = slots + static_cast<std::size_t>(by + r - rowBegin) * width + bx;
      }
      __m512 stored = _mm512_setzero_ps();
      stored = loadRow<0>(stored, depthRows, inside);
      stored = loadRow<1>(stored, depthRows, inside);
      stored = loadRow<2>(stored, depthRows, inside);
      stored = loadRow<3>(stored, depthRows, inside);
      const __mmask16 pass = inside & less(depth, Vf{stored});
      if (pass == 0) continue;
      storeRow<0>(depthRows, pass, depth.v);
      storeRow<1>(depthRows, pass, depth.v);
      storeRow<2>(depthRows, pass, depth.v);
      storeRow<3>(depthRows, pass, depth.v);
      storeRow<0>(slotRows, pass, slotLanes);
      storeRow<1>(slotRows, pass, slotLanes);
      storeRow<2>(slotRows, pass, slotLanes);
      storeRow<3>(slotRows, pass, slotLanes);
      passed += static_cast<std::uint64_t>(std::popcount(static_cast<unsigned>(pass)));
    }
  }
  return passed;
}

namespace {

// ---- the shading pass: 16 pixels of a row ----
// Where the lanes' triangle data comes from: one triangle for all lanes (broadcast) ...
struct OneTriangle {
  const BinTriangle* t;
  Vd atOrigin(std::size_t i) const { return splatD(t->atOrigin[i]); }
  Vd dx(std::size_t i) const { return splatD(t->dx[i]); }
  Vd dy(std::size_t i) const { return splatD(t->dy[i]); }
  Vd invW(std::size_t i) const { return splatD(static_cast<double>(t->invW[i])); }
  Vf varying(std::size_t vertex, int k) const { return splat(t->varyings[vertex][k]); }
};

// ... or each lane its own (gathers; lanes outside `lanes` read nothing).
struct LaneTriangles {
  const BinTriangle* base;
  __m512i offsetLo, offsetHi;  // byte offsets of each lane's BinTriangle, lanes 0..7 and 8..15
  __mmask8 lanesLo, lanesHi;
  __m512i varyingsLo[3], varyingsHi[3];  // addresses of each lane's vertex varyings

  Vd gatherDouble(std::size_t byteOffset) const {
    const __m512i add = _mm512_set1_epi64(static_cast<long long>(byteOffset));
    return {_mm512_mask_i64gather_pd(_mm512_setzero_pd(), lanesLo, _mm512_add_epi64(offsetLo, add), base, 1),
            _mm512_mask_i64gather_pd(_mm512_setzero_pd(), lanesHi, _mm512_add_epi64(offsetHi, add), base, 1)};
  }
  Vd atOrigin(std::size_t i) const { return gatherDouble(offsetof(BinTriangle, atOrigin) + i * sizeof(double)); }
  Vd dx(std::size_t i) const { return gatherDouble(offsetof(BinTriangle, dx) + i * sizeof(double)); }
  Vd dy(std::size_t i) const { return gatherDouble(offsetof(BinTriangle, dy) + i * sizeof(double)); }
  Vd invW(std::size_t i) const {
    const __m512i add = _mm512_set1_epi64(static_cast<long long>(offsetof(BinTriangle, invW) + i * sizeof(float)));
    const __m256 lo = _mm512_mask_i64gather_ps(_mm256_setzero_ps(), lanesLo, _mm512_add_epi64(offsetLo, add), base, 1);
    const __m256 hi = _mm512_mask_i64gather_ps(_mm256_setzero_ps(), lanesHi, _mm512_add_epi64(offsetHi, add), base, 1);
    return {_mm512_cvtps_pd(lo), _mm512_cvtps_pd(hi)};
  }
  Vf varying(std::size_t vertex, int k) const {
    // Absolute addresses as indices from a null base.
    const __m512i add = _mm512_set1_epi64(static_cast<long long>(k) * static_cast<long long>(sizeof(float)));
    const __m256 lo = _mm512_mask_i64gather_ps(_mm256_setzero_ps(), lanesLo,
                                               _mm512_add_epi64(varyingsLo[vertex], add), nullptr, 1);
    const __m256 hi = _mm512_mask_i64gather_ps(_mm256_setzero_ps(), lanesHi,
                                               _mm512_add_epi64(varyingsHi[vertex], add), nullptr, 1);
    return {_mm512_insertf32x8(_mm512_castps256_ps512(lo), hi, 1)};
  }
};

LaneTriangles laneTriangles(const BinTriangle* base, __m512i slots, __mmask16 lanes) {
  LaneTriangles g;
  g.base = base;
  const __m512i size = _mm512_set1_epi64(static_cast<long long>(sizeof(BinTriangle)));
  g.offsetLo = _mm512_mullo_epi64(_mm512_cvtepu32_epi64(_mm512_castsi512_si256(slots)), size);
  g.offsetHi = _mm512_mullo_epi64(_mm512_cvtepu32_epi64(_mm512_extracti64x4_epi64(slots, 1)), size);
  g.lanesLo = static_cast<__mmask8>(lanes & 0xFF);
  g.lanesHi = static_cast<__mmask8>(lanes >> 8);
  for (std::size_t v = 0; v < 3; ++v) {
    const __m512i add = _mm512_set1_epi64(static_cast<long long>(offsetof(BinTriangle, varyings) + v * sizeof(void*)));
    g.varyingsLo[v] =
        _mm512_mask_i64gather_epi64(_mm512_setzero_si512(), g.lanesLo, _mm512_add_epi64(g.offsetLo, add), base, 1);
    g.varyingsHi[v] =
        _mm512_mask_i64gather_epi64(_mm512_setzero_si512(), g.lanesHi, _mm512_add_epi64(g.offsetHi, add), base, 1);
  }
  return g;
}

// The helpers of shadeLanes and debugLanes are forced inline: called out of line they pass
// their 512-bit vectors through memory (measured: the shaded frame, one thread, lost ~5 %).
// pixelWeights' perspective weights at the lanes (screen weights where the sum is not positive).
template <typename Source>
[[gnu::always_inline]] inline Weights perspectiveWeights(const Source& src, const Vd& px, const Vd& py) {
  std::array<Vd, 3> lambda, perspective;
  Vd perspectiveSum = splatD(0.0);
  for (std::size_t i = 0; i < 3; ++i) {
    lambda[i] = (src.atOrigin(i) + src.dx(i) * px) + src.dy(i) * py;
    perspective[i] = lambda[i] * src.invW(i);
    perspectiveSum = perspectiveSum + perspective[i];
  }
  const __mmask16 sumPositive = greaterD(perspectiveSum, splatD(0.0));
  Weights w;
  w.p0 = select(sumPositive, toFloat(perspective[0] / perspectiveSum), toFloat(lambda[0]));
  w.p1 = select(sumPositive, toFloat(perspective[1] / perspectiveSum), toFloat(lambda[1]));
  w.p2 = select(sumPositive, toFloat(perspective[2] / perspectiveSum), toFloat(lambda[2]));
  return w;
}

// interpolateFragment's varyings at the lanes: float k of the layout, or floats k .. k + 2.
template <typename Source>
struct LaneVaryings {
  const Source& src;
  Weights w;
  [[gnu::always_inline]] Vf at(int k) const { return interpolate(src.varying(0, k), src.varying(1, k), src.varying(2, k), w); }
  [[gnu::always_inline]] V3 at3(int k) const { return V3{at(k), at(k + 1), at(k + 2)}; }
};

// The texture samples of one fragment: footprints computed once per texture size (maps of one
// material usually match).
struct LaneSampler {
  const ShadeUniforms& u;
  Vf uvX, uvY;
  __mmask16 lanes;
  const Texture* footprintOf = nullptr;
  Footprint shared{};
  [[gnu::always_inline]] V3 operator()(const Texture& texture, const TiledTexture& tiled) {
    if (!footprintOf || footprintOf->width != texture.width || footprintOf->height != texture.height) {
      shared = footprint(texture, uvX, uvY, u.filter, lanes);
      footprintOf = &texture;
    }
    return sample(tiled, shared, u.filter, lanes);
  }
};

// shadeFragment's mappedTangent: safeNormalize(2 texel - 1) of the normal map, else (0, 0, 1).
template <bool kNormal>
[[gnu::always_inline]] inline V3 mappedTangentAt(const ShadeUniforms& u, const ItemMaps& maps, LaneSampler& sampleMap) {
  if constexpr (kNormal) {
    const V3 texel = sampleMap(*u.normalMap, *maps.normal);
    const Vf two = splat(2.0f), one = splat(1.0f);
    return safeNormalize3(V3{two * texel.x - one, two * texel.y - one, two * texel.z - one});
  } else {
    return V3{splat(0.0f), splat(0.0f), splat(1.0f)};
  }
}

// shadeFragment's nl in world lighting space: the mapped normal through the normalised
// interpolated frame, or the normalised interpolated normal without a normal map.
template <bool kNormal, typename Source>
[[gnu::always_inline]] inline V3 worldNormalAt(const LaneVaryings<Source>& varyings, const V3& mappedTangent) {
  const V3 n = safeNormalize3(varyings.at3(kVaryingNormal));
  if constexpr (kNormal) {
    const V3 t = safeNormalize3(varyings.at3(kVaryingTangent));
    const V3 b = safeNormalize3(varyings.at3(kVaryingBitangent));
    return safeNormalize3((t * mappedTangent.x + b * mappedTangent.y) + n * mappedTangent.z);
  } else {
    return n;
  }
}

// shadeFragment for View::Shaded at the lanes in `lanes`: pixelWeights' perspective weights,
// interpolateFragment, then the lighting; returns the colour before clamping.
template <bool kDiffuse, bool kNormal, bool kSpecular, bool kTangent, typename Source>
V3 shadeLanes(const Source& src, const ShadeUniforms& u, const ItemMaps& maps, const Vd& px, const Vd& py,
              __mmask16 lanes) {
  const LaneVaryings<Source> varyings{src, perspectiveWeights(src, px, py)};
  const V3 posWorld = varyings.at3(kVaryingPosWorld);
  constexpr bool kAnyMap = kDiffuse || kNormal || kSpecular;
  LaneSampler sampleMap{u, splat(0.0f), splat(0.0f), lanes};
  if constexpr (kAnyMap) {
    sampleMap.uvX = varyings.at(kVaryingUv);
    sampleMap.uvY = varyings.at(kVaryingUv + 1);
  }

  const V3 ones{splat(1.0f), splat(1.0f), splat(1.0f)};
  V3 albedo = ones;
  if constexpr (kDiffuse) albedo = sampleMap(*u.diffuseMap, *maps.diffuse);
  V3 specScale = ones;
  if constexpr (kSpecular) specScale = sampleMap(*u.specularMap, *maps.specular);
  const V3 mappedTangent = mappedTangentAt<kNormal>(u, maps, sampleMap);
  V3 nl = mappedTangent;  // tangent lighting space
  if constexpr (!kTangent) nl = worldNormalAt<kNormal>(varyings, mappedTangent);

  const V3 vVec = kTangent ? varyings.at3(kVaryingEyeDirTangent) : splat3(u.eyePosWorld) - posWorld;
  const V3 v = safeNormalize3(vVec);
  const V3 kdAlbedo = splat3(u.kd) * albedo;  // u.kd * albedo, the first product of diffuse
  const V3 ksSpec = splat3(u.ks) * specScale;
  const Vf zero = splat(0.0f);
  V3 sum{zero, zero, zero};
  for (int i = 0; i < u.lightCount; ++i) {
    const LightUniform& light = u.lights[static_cast<std::size_t>(i)];
    const V3 toLight = splat3(light.posWorld) - posWorld;
    const V3 lVec = kTangent ? varyings.at3(kVaryingLightDirTangent + 3 * i) : toLight;
    const Vf d = sqrtOf(dot3(toLight, toLight));
    const V3 l = safeNormalize3(lVec);
    const Vf nDotL = dot3(nl, l);
    const V3 r = (splat(2.0f) * nDotL) * nl - l;
    const Vf rDotV = maxOf(dot3(r, v), zero);
    const Vf denominator = (splat(light.attenuation.x) + splat(light.attenuation.y) * d) +
                           (splat(light.attenuation.z) * d) * d;
    const Vf attenuation = splat(1.0f) / maxOf(denominator, splat(kMinAttenuationDenominator));
    const Vf lambert = maxOf(nDotL, zero);
    const V3 diffuse = {(kdAlbedo.x * lambert) * splat(light.diffuse.x),
                        (kdAlbedo.y * lambert) * splat(light.diffuse.y),
                        (kdAlbedo.z * lambert) * splat(light.diffuse.z)};
    const __mmask16 lit = lanes & greater(nDotL, zero);
    V3 specular{zero, zero, zero};
    if (lit != 0) {
      const Vf powered = phongPow16(rDotV, u.shininess, lit);
      specular = {select(lit, (ksSpec.x * powered) * splat(light.specular.x), zero),
                  select(lit, (ksSpec.y * powered) * splat(light.specular.y), zero),
                  select(lit, (ksSpec.z * powered) * splat(light.specular.z), zero)};
    }
    sum = sum + (diffuse + specular) * attenuation;
  }
  const V3 ambient = (splat3(u.ka) * albedo) * splat3(u.ambient);
  return ambient + sum;
}

// vectorAsColour: (v + 1) * 0.5 per component.
inline V3 vectorAsColour3(const V3& v) {
  const Vf one = splat(1.0f), half = splat(0.5f);
  return {(v.x + one) * half, (v.y + one) * half, (v.z + one) * half};
}

// shadeFragment for a debug view that reads varyings (every one but Depth, and Albedo without
// a diffuse map, which shadeSegment handles without them), before clamping.
template <View kView, bool kDiffuse, bool kNormal, bool kTangent, typename Source>
V3 debugLanes(const Source& src, const ShadeUniforms& u, const ItemMaps& maps, const Vd& px, const Vd& py,
              __mmask16 lanes) {
  const LaneVaryings<Source> varyings{src, perspectiveWeights(src, px, py)};
  const Vf zero = splat(0.0f);
  if constexpr (kView == View::Albedo) {
    LaneSampler sampleMap{u, varyings.at(kVaryingUv), varyings.at(kVaryingUv + 1), lanes};
    return sampleMap(*u.diffuseMap, *maps.diffuse) * splat3(u.kd);
  } else if constexpr (kView == View::Normal) {
    return vectorAsColour3(safeNormalize3(varyings.at3(kVaryingNormal)));
  } else if constexpr (kView == View::Tangent) {
    return vectorAsColour3(safeNormalize3(varyings.at3(kVaryingTangent)));
  } else if constexpr (kView == View::Bitangent) {
    return vectorAsColour3(safeNormalize3(varyings.at3(kVaryingBitangent)));
  } else if constexpr (kView == View::MappedNormal) {
    LaneSampler sampleMap{u, zero, zero, lanes};
    if constexpr (kNormal) {
      sampleMap.uvX = varyings.at(kVaryingUv);
      sampleMap.uvY = varyings.at(kVaryingUv + 1);
    }
    const V3 mappedTangent = mappedTangentAt<kNormal>(u, maps, sampleMap);
    if constexpr (kTangent) return vectorAsColour3(mappedTangent);
    else return vectorAsColour3(worldNormalAt<kNormal>(varyings, mappedTangent));
  } else if constexpr (kView == View::Uv) {
    const Vf uvX = varyings.at(kVaryingUv), uvY = varyings.at(kVaryingUv + 1);
    return {uvX - floorOf(uvX), uvY - floorOf(uvY), zero};
  } else {
    static_assert(kView == View::LightTangent || kView == View::EyeTangent);
    constexpr bool kLight = kView == View::LightTangent;
    V3 dirTangent{zero, zero, zero};  // no light: (0, 0, 0), shown as grey 0.5
    if (!kLight || u.lightCount > 0) {
      if constexpr (kTangent) {
        dirTangent = safeNormalize3(varyings.at3(kLight ? kVaryingLightDirTangent : kVaryingEyeDirTangent));
      } else {
        const V3 n = safeNormalize3(varyings.at3(kVaryingNormal));
        const V3 t = safeNormalize3(varyings.at3(kVaryingTangent));
        const V3 b = safeNormalize3(varyings.at3(kVaryingBitangent));
        const V3 w = splat3(kLight ? u.lights[0].posWorld : u.eyePosWorld) - varyings.at3(kVaryingPosWorld);
        dirTangent = safeNormalize3(V3{dot3(t, w), dot3(b, w), dot3(n, w)});
      }
    }
    return vectorAsColour3(dirTangent);
  }
}

// One draw item's lanes of a 16-pixel row segment starting at (x, py): shade and write
// colour and triangle id.
struct Segment {
  const std::vector<BinTriangle>* triangles;
  __m512i slots;   // per lane
  __m512i ids;     // per lane triangle id
  __mmask16 lanes;  // this item's lanes
  int x, py;
};
using SegmentKernel = void (*)(const Segment& segment, const ShadeUniforms& u, const ItemMaps& maps, Framebuffer& fb);

template <View kView, bool kDiffuse, bool kNormal, bool kSpecular, bool kTangent>
void shadeSegment(const Segment& s, const ShadeUniforms& u, const ItemMaps& maps, Framebuffer& fb) {
  const std::size_t origin = fb.index(s.x, s.py);
  V3 colour;
  if constexpr (kView == View::Depth) {
    // The depth buffer holds the visible triangle's pixelWeights depth once visibility is done.
    const Vf depth{_mm512_maskz_loadu_ps(s.lanes, &fb.depth[origin])};
    colour = {depth, depth, depth};
  } else if constexpr (kView == View::Albedo && !kDiffuse) {
    colour = splat3(vec3(1.0f)) * splat3(u.kd);  // albedo 1 times kd
  } else {
    const Vd px = toDouble(_mm512_add_epi32(_mm512_set_epi32(15, 14, 13, 12, 11, 10, 9, 8, 7, 6, 5, 4, 3, 2, 1, 0),
                                            _mm512_set1_epi32(s.x)));
    const Vd py = splatD(s.py);
    const auto shade = [&](const auto& src) {
      if constexpr (kView == View::Shaded) {
        return shadeLanes<kDiffuse, kNormal, kSpecular, kTangent>(src, u, maps, px, py, s.lanes);
      } else {
        return debugLanes<kView, kDiffuse, kNormal, kTangent>(src, u, maps, px, py, s.lanes);
      }
    };
    // All lanes on one triangle (the common case inside large triangles): broadcast its data.
    const std::uint32_t firstSlot = static_cast<std::uint32_t>(
        _mm_cvtsi128_si32(_mm512_castsi512_si128(_mm512_maskz_compress_epi32(s.lanes, s.slots))));
    const bool oneTriangle =
        _mm512_mask_cmpneq_epi32_mask(s.lanes, s.slots, _mm512_set1_epi32(static_cast<int>(firstSlot))) == 0;
    colour = oneTriangle ? shade(OneTriangle{&(*s.triangles)[firstSlot]})
                         : shade(laneTriangles(s.triangles->data(), s.slots, s.lanes));
  }
  const __m512i rgba = _mm512_or_si512(
      _mm512_or_si512(toByte(colour.x), _mm512_slli_epi32(toByte(colour.y), 8)),
      _mm512_or_si512(_mm512_slli_epi32(toByte(colour.z), 16), _mm512_set1_epi32(static_cast<int>(kOpaqueAlpha))));
  _mm512_mask_storeu_epi32(&fb.rgba[4 * origin], s.lanes, rgba);
  _mm512_mask_storeu_epi32(&fb.triangleId[origin], s.lanes, s.ids);
}

// Shaded kernels indexed by diffuse + 2 normal + 4 specular + 8 tangent.
template <int kIndex>
constexpr SegmentKernel shadedKernelAt() {
  return &shadeSegment<View::Shaded, (kIndex & 1) != 0, (kIndex & 2) != 0, (kIndex & 4) != 0, (kIndex & 8) != 0>;
}
template <int... kIndices>
constexpr std::array<SegmentKernel, sizeof...(kIndices)> shadedKernelTable(std::integer_sequence<int, kIndices...>) {
  return {shadedKernelAt<kIndices>()...};
}
constexpr int kShadedKernelCount = 16;
constexpr std::array<SegmentKernel, kShadedKernelCount> kShadedKernels =
    shadedKernelTable(std::make_integer_sequence<int, kShadedKernelCount>());

// A debug view's kernel, instantiated only for the features that view reads (diffuse for
// Albedo; normal map and lighting space for MappedNormal; lighting space for the two
// tangent-space directions), so 15 kernels cover the nine views.
template <View kView>
SegmentKernel debugKernel(bool diffuse, bool normal, bool tangent) {
  if constexpr (kView == View::Albedo) {
    return diffuse ? &shadeSegment<kView, true, false, false, false> : &shadeSegment<kView, false, false, false, false>;
  } else if constexpr (kView == View::MappedNormal) {
    if (normal) return tangent ? &shadeSegment<kView, false, true, false, true> : &shadeSegment<kView, false, true, false, false>;
    return tangent ? &shadeSegment<kView, false, false, false, true> : &shadeSegment<kView, false, false, false, false>;
  } else if constexpr (kView == View::LightTangent || kView == View::EyeTangent) {
    return tangent ? &shadeSegment<kView, false, false, false, true> : &shadeSegment<kView, false, false, false, false>;
  } else {
    return &shadeSegment<kView, false, false, false, false>;
  }
}

SegmentKernel kernelFor(const ShaderKey& key) {
  const bool tangent = key.space == LightingSpace::Tangent;
  const bool d = key.diffuseMap, n = key.normalMap;
  switch (key.view) {
    case View::Shaded: break;
    case View::Albedo: return debugKernel<View::Albedo>(d, n, tangent);
    case View::Normal: return debugKernel<View::Normal>(d, n, tangent);
    case View::Tangent: return debugKernel<View::Tangent>(d, n, tangent);
    case View::Bitangent: return debugKernel<View::Bitangent>(d, n, tangent);
    case View::MappedNormal: return debugKernel<View::MappedNormal>(d, n, tangent);
    case View::Uv: return debugKernel<View::Uv>(d, n, tangent);
    case View::Depth: return debugKernel<View::Depth>(d, n, tangent);
    case View::LightTangent: return debugKernel<View::LightTangent>(d, n, tangent);
    case View::EyeTangent: return debugKernel<View::EyeTangent>(d, n, tangent);
  }
  const int index = (d ? 1 : 0) + (n ? 2 : 0) + (key.specularMap ? 4 : 0) + (tangent ? 8 : 0);
  return kShadedKernels[static_cast<std::size_t>(index)];
}

// A 32-bit field of each lane's BinTriangle (lanes outside `lanes` give 0).
__m512i gatherField(const std::vector<BinTriangle>& triangles, __m512i slots, __mmask16 lanes, std::size_t offset) {
  const __m512i size = _mm512_set1_epi64(static_cast<long long>(sizeof(BinTriangle)));
  const __m512i add = _mm512_set1_epi64(static_cast<long long>(offset));
  const __m512i lo = _mm512_add_epi64(_mm512_mullo_epi64(_mm512_cvtepu32_epi64(_mm512_castsi512_si256(slots)), size), add);
  const __m512i hi =
      _mm512_add_epi64(_mm512_mullo_epi64(_mm512_cvtepu32_epi64(_mm512_extracti64x4_epi64(slots, 1)), size), add);
  const __m256i fieldLo = _mm512_mask_i64gather_epi32(_mm256_setzero_si256(), static_cast<__mmask8>(lanes & 0xFF), lo,
                                                      triangles.data(), 1);
  const __m256i fieldHi = _mm512_mask_i64gather_epi32(_mm256_setzero_si256(), static_cast<__mmask8>(lanes >> 8), hi,
                                                      triangles.data(), 1);
  return _mm512_inserti64x4(_mm512_castsi256_si512(fieldLo), fieldHi, 1);
}

}  // namespace

void shadeBinAvx512(const std::vector<BinTriangle>& triangles, const std::vector<ItemState>& items,
                    const std::vector<ItemMaps>& maps, const std::uint32_t* slots, int rowBegin, int rowEnd,
                    std::uint32_t background, Framebuffer& fb) {
  const std::size_t width = static_cast<std::size_t>(fb.width);
  const __m512i noSlot = _mm512_set1_epi32(static_cast<int>(kNoSlot));
  const __m512i backgroundLanes = _mm512_set1_epi32(static_cast<int>(background));
  const __m512i noTriangle = _mm512_set1_epi32(static_cast<int>(kNoTriangle));
  for (int py = rowBegin; py < rowEnd; ++py) {
    const std::uint32_t* row = slots + static_cast<std::size_t>(py - rowBegin) * width;
    for (int x = 0; x < fb.width; x += kLanes) {
      const int inRow = std::min(kLanes, fb.width - x);
      const __mmask16 inImage = static_cast<__mmask16>((1u << inRow) - 1u);
      const __m512i slotLanes = _mm512_maskz_loadu_epi32(inImage, row + x);
      __mmask16 remaining = _mm512_mask_cmpneq_epi32_mask(inImage, slotLanes, noSlot);
      const __mmask16 empty = static_cast<__mmask16>(inImage & ~remaining);
      const std::size_t origin = fb.index(x, py);
      _mm512_mask_storeu_epi32(&fb.rgba[4 * origin], empty, backgroundLanes);
      _mm512_mask_storeu_epi32(&fb.triangleId[origin], empty, noTriangle);
      if (remaining == 0) continue;
      const __m512i itemLanes = gatherField(triangles, slotLanes, remaining, offsetof(BinTriangle, item));
      const __m512i idLanes = gatherField(triangles, slotLanes, remaining, offsetof(BinTriangle, triangleId));
      // One pass per draw item present in the segment (usually one).
      while (remaining != 0) {
        const std::uint32_t item = static_cast<std::uint32_t>(
            _mm_cvtsi128_si32(_mm512_castsi512_si128(_mm512_maskz_compress_epi32(remaining, itemLanes))));
        const __mmask16 lanes =
            _mm512_mask_cmpeq_epi32_mask(remaining, itemLanes, _mm512_set1_epi32(static_cast<int>(item)));
        remaining = static_cast<__mmask16>(remaining & ~lanes);
        const ItemState& s = items[item];
        kernelFor(s.shaderKey)(Segment{&triangles, slotLanes, idLanes, lanes, x, py}, s.shade, maps[item], fb);
      }
    }
  }
}

void powPositiveAvx512(const float* x, float s, float* out, std::size_t count) {
  for (std::size_t i = 0; i < count; i += kLanes) {
    const std::size_t n = std::min<std::size_t>(kLanes, count - i);
    const __mmask16 lanes = static_cast<__mmask16>((1u << n) - 1u);
    const Vf values{_mm512_maskz_loadu_ps(lanes, x + i)};
    _mm512_mask_storeu_ps(out + i, lanes, phongPow16(values, s, lanes).v);
  }
}

#if defined(__clang__)
#pragma clang attribute pop
#else
#pragma GCC pop_options
#endif

}  // namespace twr

#pragma GCC diagnostic pop
