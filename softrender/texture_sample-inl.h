// Texture sampling over any lane type, as llvmpipe (Mesa 22.3) samples in the precise mode
// twinraster runs it in (GALLIVM_PERF=no_aos_sampling,no_quad_lod, docs/compare.md): texel
// selection per wrap mode, float bilinear weights, the LOD of a 2x2 quad and the blend of two
// mip levels (texture_sample.h has the formulas; docs/textures.md how each was measured).
// Shared source, included plainly and per Highway target (softrender/lanes.h). A texture is
// reached through a view type that provides
//   texLevelCount(view), texLevelWidth(view, level), texLevelHeight(view, level)   texels
//   texWrap(view) -> TextureWrap, texSrgb(view) -> bool
//   wrapTexelIndex(size, integral L) -> IntOf<L>     floor value reduced mod size, exactly
//   nextTexelIndex(IntOf<L> i, size)                 i + 1, wrapped
//   fetchTexelBytes<L>(view, level, IntOf<L> x, IntOf<L> y)   texel RGBA as bytes 0..255 in L
//   linearFromSrgbByte(L byte)                        the sRGB decode of one byte value
// plainly a Texture (texture_sample.h), in the fast path a tiled copy (fast_kernels.cpp).

#if defined(TWR_LANES_HIGHWAY)
#if defined(TWR_TEXTURE_SAMPLE_INL_TARGET) == defined(HWY_TARGET_TOGGLE)
#ifdef TWR_TEXTURE_SAMPLE_INL_TARGET
#undef TWR_TEXTURE_SAMPLE_INL_TARGET
#else
#define TWR_TEXTURE_SAMPLE_INL_TARGET
#endif
#define TWR_TEXTURE_SAMPLE_INL_EMIT
#endif
#elif !defined(TWR_TEXTURE_SAMPLE_INL_PLAIN)
#define TWR_TEXTURE_SAMPLE_INL_PLAIN
#define TWR_TEXTURE_SAMPLE_INL_EMIT
#endif

#ifdef TWR_TEXTURE_SAMPLE_INL_EMIT
#undef TWR_TEXTURE_SAMPLE_INL_EMIT

#include "scene/settings.h"
#include "scene/texture.h"
#include "softrender/lanes.h"

TWR_LANES_BEGIN

// Texel selection along one axis: the indices of the one or two texels read, and the weight
// of the second, in [0, 1).
template <typename L>
struct AxisFootprintL {
  IntOf<L> i0, i1;
  L weight;
};

// Which texels one sample reads and with what weights (for the pixel trace).
template <typename L>
struct FootprintL {
  IntOf<L> x0, y0, x1, y1;  // texel indices (x1, y1 equal x0, y0 for nearest)
  L alpha, beta;            // weights towards x1 and y1 in [0, 1) (0 for nearest)
};

// A coordinate as llvmpipe's sampler takes it: non-finite reads as 0 (GL leaves it undefined),
// denormals flush to 0 (llvmpipe's code runs with FTZ/DAZ).
template <typename L>
TWR_LANE_INLINE L sanitizedCoord(const L& c) {
  using S = ScalarOf<L>;
  constexpr S kSmallestNormal = S(1.17549435e-38f);  // FLT_MIN
  const L zero(S(0));
  const L finite = select(isFinite(c), c, zero);
  return select(absOf(finite) < L(kSmallestNormal), zero, finite);
}

// GL_NEAREST along an axis of `size` texels:
//   repeat  f = min(c - floor(c), 1 - 2^-24); i = trunc(f size)      (equals floor(c size) mod
//           size for a power of two, and is what llvmpipe computes for any size)
//   clamp   i = clamp(trunc(c size), 0, size - 1)
//   mirror  h = c / 2; i = min(trunc(|2 (h - rint(h))| size), size - 1)
template <typename L>
TWR_LANE_INLINE IntOf<L> nearestTexelLanes(const L& c, int size, TextureWrap wrap) {
  using S = ScalarOf<L>;
  constexpr S kBelowOne = S(0.99999994f);  // the largest float below 1
  const L zero(S(0)), sizeL(static_cast<S>(size)), last(static_cast<S>(size - 1));
  L i = zero;
  switch (wrap) {
    case TextureWrap::Repeat: i = truncOf(minOf(c - floorOf(c), L(kBelowOne)) * sizeL); break;
    case TextureWrap::ClampToEdge: i = minOf(maxOf(truncOf(c * sizeL), zero), last); break;
    case TextureWrap::MirroredRepeat: {
      const L h = c * L(S(0.5));
      const L d = h - roundEvenOf(h);
      i = minOf(truncOf(absOf(d + d) * sizeL), last);
      break;
    }
  }
  return wrapTexelIndex(size, i);
}

// GL_LINEAR along an axis, as llvmpipe's float (SoA) sampler does: c' = c size - 0.5, i0 =
// floor(c'), weight = c' - i0, i1 = i0 + 1, each index wrapped; repeat on a size that is not
// a power of two takes the fraction first (f = min(c - floor(c), 1 - 2^-24), c' = f size - 0.5,
// i0 = -1 -> size - 1); mirrored_repeat folds c to |2 (c/2 - rint(c/2))| first.
template <typename L>
TWR_LANE_INLINE AxisFootprintL<L> linearAxisLanes(const L& c, int size, TextureWrap wrap) {
  using S = ScalarOf<L>;
  constexpr S kBelowOne = S(0.99999994f);  // the largest float below 1
  const L zero(S(0)), one(S(1)), last(static_cast<S>(size - 1)), sizeL(static_cast<S>(size));
  const bool powerOfTwo = (size & (size - 1)) == 0;
  L folded = c;
  if (wrap == TextureWrap::MirroredRepeat) {
    const L h = c * L(S(0.5));
    folded = absOf(L(S(2)) * (h - roundEvenOf(h)));
  } else if (wrap == TextureWrap::Repeat && !powerOfTwo) {
    folded = minOf(c - floorOf(c), L(kBelowOne));
  }
  // A product past the float range (|c| near 3e38) reads texel 0 with weight 0, never NaN.
  const L product = folded * sizeL - L(S(0.5));
  const L scaled = select(isFinite(product), product, zero);
  const L i = floorOf(scaled);
  AxisFootprintL<L> a;
  a.weight = scaled - i;
  if (wrap == TextureWrap::Repeat) {
    a.i0 = wrapTexelIndex(size, i);
    a.i1 = nextTexelIndex(a.i0, size);
  } else {  // clamp_to_edge, and mirrored_repeat (already folded into [0, 1])
    a.i0 = wrapTexelIndex(size, minOf(maxOf(i, zero), last));
    a.i1 = wrapTexelIndex(size, minOf(maxOf(i + one, zero), last));
  }
  return a;
}

// Calls between these functions are written (f<L>)(...): the parentheses turn off
// argument-dependent lookup, which would otherwise also find the plain copies in namespace twr
// (through TextureWrap or the view) and make each call ambiguous in the per-target copies.

// A texel as the sampler reads it: sRGB decoded (colour channels; alpha stays linear), else
// byte / 255 (as c * (1 / 255)).
template <typename L, typename View>
TWR_LANE_INLINE Vec4L<L> texelValue(const View& texture, const Vec4L<L>& bytes) {
  using S = ScalarOf<L>;
  if (!texSrgb(texture)) return bytes * L(S(1) / S(255));
  return Vec4L<L>(linearFromSrgbByte(bytes.x), linearFromSrgbByte(bytes.y), linearFromSrgbByte(bytes.z),
                  bytes.w * L(S(1) / S(255)));
}

// One level, the same for every lane: RGBA in [0, 1]. Bilinear is a lerp along u on both rows,
// then along v: a + w (b - a) (llvmpipe fuses each into one FMA; the CPU rounds twice, about
// one float ULP apart).
template <typename L, typename View>
TWR_LANE_OUTLINE Vec4L<L> sampleLevelLanes(const View& texture, int level, const Vec2L<L>& uv, bool linear) {
  const int width = texLevelWidth(texture, level), height = texLevelHeight(texture, level);
  const TextureWrap wrap = texWrap(texture);
  if (!linear) {
    return texelValue<L>(texture, fetchTexelBytes<L>(texture, level, (nearestTexelLanes<L>)(uv.x, width, wrap),
                                                     (nearestTexelLanes<L>)(uv.y, height, wrap)));
  }
  const AxisFootprintL<L> ax = (linearAxisLanes<L>)(uv.x, width, wrap);
  const AxisFootprintL<L> ay = (linearAxisLanes<L>)(uv.y, height, wrap);
  const Vec4L<L> t00 = texelValue<L>(texture, fetchTexelBytes<L>(texture, level, ax.i0, ay.i0));
  const Vec4L<L> t10 = texelValue<L>(texture, fetchTexelBytes<L>(texture, level, ax.i1, ay.i0));
  const Vec4L<L> t01 = texelValue<L>(texture, fetchTexelBytes<L>(texture, level, ax.i0, ay.i1));
  const Vec4L<L> t11 = texelValue<L>(texture, fetchTexelBytes<L>(texture, level, ax.i1, ay.i1));
  const Vec4L<L> bottomRow = t00 + (t10 - t00) * ax.weight;
  const Vec4L<L> topRow = t01 + (t11 - t01) * ax.weight;
  return bottomRow + (topRow - bottomRow) * ay.weight;
}

// Lanes may read different levels. For a first and a second level per lane (integer values,
// level1 >= level0), each distinct level is sampled once, for every lane that takes it as its
// first or its second level: a vector straddling a level boundary reads 3 levels for trilinear,
// not 4. One level per lane is the pair (level, level).
template <typename L>
TWR_LANE_INLINE Vec4L<L> selectVec4(const MaskOf<L>& mask, const Vec4L<L>& a, const Vec4L<L>& b) {
  return Vec4L<L>(select(mask, a.x, b.x), select(mask, a.y, b.y), select(mask, a.z, b.z), select(mask, a.w, b.w));
}
template <typename L, typename View>
TWR_LANE_INLINE void sampleLevelPairLanes(const View& texture, const L& level0, const L& level1, const Vec2L<L>& uv,
                                          bool linear, Vec4L<L>& s0, Vec4L<L>& s1) {
  using S = ScalarOf<L>;
  const int lowest = static_cast<int>(lowestLane(level0));
  const int highest = static_cast<int>(highestLane(level1));
  s0 = (sampleLevelLanes<L>)(texture, lowest, uv, linear);
  s1 = s0;
  for (int l = lowest + 1; l <= highest; ++l) {
    const L here(static_cast<S>(l));
    const auto first = level0 == here, second = level1 == here;
    if (!anyOf(first | second)) continue;
    const Vec4L<L> r = (sampleLevelLanes<L>)(texture, l, uv, linear);
    s0 = (selectVec4<L>)(first, r, s0);
    s1 = (selectVec4<L>)(second, r, s1);
  }
}

// The LOD of a quad from its uv differences (top-left pixel to its right and upper
// neighbours), as llvmpipe computes it: rho^2 = max((du/dx W)^2 + (dv/dx H)^2,
// (du/dy W)^2 + (dv/dy H)^2) with W x H the base level, lod = fastLog2(rho^2) / 2 where
// fastLog2(m 2^e) = e + (m - 1) (exact at powers of two, up to 0.086 below log2 between).
template <typename L>
TWR_LANE_INLINE L quadLodLanes(const Vec2L<L>& dUvDx, const Vec2L<L>& dUvDy, int width, int height) {
  using S = ScalarOf<L>;
  const L w(static_cast<S>(width)), h(static_cast<S>(height));
  const L a = dUvDx.x * w, b = dUvDy.x * w, c = dUvDx.y * h, d = dUvDy.y * h;
  const L rx = a * a + c * c, ry = b * b + d * d;
  const L rho2 = maxOf(rx, ry);
  return (floatExponentOf(rho2) + (floatMantissaOf(rho2) - L(S(1)))) * L(S(0.5));
}

// The filtered RGBA in [0, 1]. `lod` is the quad's (quadLodLanes); filters without mipmaps
// ignore it. Texels within a level are picked or blended as texelsLinear(filter) says (GL's
// minification and magnification filters agree for every filter here, so magnification,
// lod <= 0, is level 0 with the same texel filter). *_mipmap_nearest: level rint(lod);
// *_mipmap_linear: levels floor(lod) and the next, blended by frac(lod) (a + f (b - a)).
// Levels clamp to the chain the texture has.
template <typename L, typename View>
TWR_LANE_OUTLINE Vec4L<L> sampleTextureLanes(const View& texture, const Vec2L<L>& uvIn, TextureFilter filter,
                                            const L& lod) {
  using S = ScalarOf<L>;
  const Vec2L<L> uv((sanitizedCoord<L>)(uvIn.x), (sanitizedCoord<L>)(uvIn.y));
  const bool linear = texelsLinear(filter);
  const int last = texLevelCount(texture) - 1;
  Vec4L<L> result;
  if (!usesMipmaps(filter) || last == 0) {
    result = (sampleLevelLanes<L>)(texture, 0, uv, linear);
  } else {
    const L zero(S(0)), lastL(static_cast<S>(last));
    const L clamped = minOf(lod, lastL);
    Vec4L<L> s0, s1;
    if (!levelsLinear(filter)) {
      const L level = minOf(maxOf(roundEvenOf(clamped), zero), lastL);
      (sampleLevelPairLanes<L>)(texture, level, level, uv, linear, s0, s1);
      result = s0;
    } else {
      const L floorLod = floorOf(clamped);
      const auto below = floorLod < zero;
      const auto atLast = floorLod >= lastL;
      const L level0 = select(below, zero, select(atLast, lastL, floorLod));
      const L fraction = select(below | atLast, zero, clamped - floorLod);
      const L level1 = minOf(level0 + L(S(1)), lastL);
      (sampleLevelPairLanes<L>)(texture, level0, level1, uv, linear, s0, s1);
      result = s0 + (s1 - s0) * fraction;
    }
  }
  return result;
}

// The level-0 footprint of a sample (the pixel trace's picture of one texture read).
template <typename L, typename View>
TWR_LANE_INLINE FootprintL<L> sampleFootprintLanes(const View& texture, const Vec2L<L>& uvIn, TextureFilter filter) {
  using S = ScalarOf<L>;
  const Vec2L<L> uv((sanitizedCoord<L>)(uvIn.x), (sanitizedCoord<L>)(uvIn.y));
  const int width = texLevelWidth(texture, 0), height = texLevelHeight(texture, 0);
  const TextureWrap wrap = texWrap(texture);
  FootprintL<L> f;
  if (!texelsLinear(filter)) {
    f.x0 = f.x1 = (nearestTexelLanes<L>)(uv.x, width, wrap);
    f.y0 = f.y1 = (nearestTexelLanes<L>)(uv.y, height, wrap);
    f.alpha = f.beta = L(S(0));
    return f;
  }
  const AxisFootprintL<L> ax = (linearAxisLanes<L>)(uv.x, width, wrap);
  const AxisFootprintL<L> ay = (linearAxisLanes<L>)(uv.y, height, wrap);
  f.x0 = ax.i0;
  f.x1 = ax.i1;
  f.y0 = ay.i0;
  f.y1 = ay.i1;
  f.alpha = ax.weight;
  f.beta = ay.weight;
  return f;
}

TWR_LANES_END

#endif  // TWR_TEXTURE_SAMPLE_INL_EMIT
