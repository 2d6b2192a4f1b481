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
//   fetchTexelRedByte<L>(view, level, IntOf<L> x, IntOf<L> y) its red byte alone
//   fetchRedFootprintBytes<L>(view, level, x0, x1, y0, y1) the red bytes of the bilinear
//       footprint (x0, y0), (x1, y0), (x0, y1), (x1, y1) as Vec4L<L>, where x1 is x0 or the
//       texel after it (wrapped to 0 at the edge), and y1 likewise
//   linearFromSrgbByte(L byte)                        the sRGB decode of one byte value
// plainly a Texture (texture_sample.h), in the fast path a tiled copy (fast_kernels-inl.h).

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

#include <type_traits>

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
TWR_LANE_INLINE IntOf<L> nearestTexel(const L& c, int size, TextureWrap wrap) {
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
TWR_LANE_INLINE AxisFootprintL<L> linearAxis(const L& c, int size, TextureWrap wrap) {
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

// What a caller knows of a texture's sampler state at compile time. A march reads its height
// map dozens of times per pixel; for the usual map (GL_REPEAT, linear texels, bytes not sRGB)
// the reads are compiled without the branches of every other case, which otherwise keep the
// compiler from holding the march's values in registers. The arithmetic is the same either way.
enum class SamplerCase { kAny, kRepeatLinearUnorm };

// What a sample returns: every channel (Vec4L<L>), or the red one alone (L) for a height map,
// which GLSL reads as texture(...).r. Each channel is fetched, decoded and filtered alone, so
// the red one has the same bits either way; reading one channel saves three quarters of the
// decoding and blending, and a march reads the height map dozens of times per pixel.
template <typename L, SamplerCase kCase = SamplerCase::kAny, typename View>
TWR_LANE_INLINE L redValue(const View& texture, const L& byte) {
  using S = ScalarOf<L>;
  if (kCase == SamplerCase::kRepeatLinearUnorm || !texSrgb(texture)) return byte * L(S(1) / S(255));
  return L(linearFromSrgbByte(byte));
}
template <typename L, typename Texel, typename View>
TWR_LANE_INLINE Texel texel(const View& texture, int level, const IntOf<L>& x, const IntOf<L>& y) {
  if constexpr (std::is_same_v<Texel, L>) {
    return (redValue<L>)(texture, fetchTexelRedByte<L>(texture, level, x, y));
  } else {
    return texelValue<L>(texture, fetchTexelBytes<L>(texture, level, x, y));
  }
}

// One level, the same for every lane: RGBA (or red) in [0, 1]. Bilinear is a lerp along u on
// both rows, then along v: a + w (b - a) (llvmpipe fuses each into one FMA; the CPU rounds
// twice, about one float ULP apart).
template <typename L, typename View, typename Texel = Vec4L<L>, SamplerCase kCase = SamplerCase::kAny>
TWR_LANE_INLINE Texel sampleLevelInline(const View& texture, int level, const Vec2L<L>& uv, bool linear) {
  constexpr bool kFixed = kCase == SamplerCase::kRepeatLinearUnorm;
  const int width = texLevelWidth(texture, level), height = texLevelHeight(texture, level);
  const TextureWrap wrap = kFixed ? TextureWrap::Repeat : texWrap(texture);
  if (!kFixed && !linear) {
    return (texel<L, Texel>)(texture, level, (nearestTexel<L>)(uv.x, width, wrap),
                             (nearestTexel<L>)(uv.y, height, wrap));
  }
  const AxisFootprintL<L> ax = (linearAxis<L>)(uv.x, width, wrap);
  const AxisFootprintL<L> ay = (linearAxis<L>)(uv.y, height, wrap);
  Texel t00, t10, t01, t11;
  if constexpr (std::is_same_v<Texel, L>) {
    // The red channel alone: the view hands the four bytes over together (the fast path reads
    // them with one gather from a height map's footprint words).
    const Vec4L<L> bytes = fetchRedFootprintBytes<L>(texture, level, ax.i0, ax.i1, ay.i0, ay.i1);
    t00 = (redValue<L, kCase>)(texture, bytes.x);
    t10 = (redValue<L, kCase>)(texture, bytes.y);
    t01 = (redValue<L, kCase>)(texture, bytes.z);
    t11 = (redValue<L, kCase>)(texture, bytes.w);
  } else {
    t00 = (texel<L, Texel>)(texture, level, ax.i0, ay.i0);
    t10 = (texel<L, Texel>)(texture, level, ax.i1, ay.i0);
    t01 = (texel<L, Texel>)(texture, level, ax.i0, ay.i1);
    t11 = (texel<L, Texel>)(texture, level, ax.i1, ay.i1);
  }
  const Texel bottomRow = t00 + (t10 - t00) * ax.weight;
  const Texel topRow = t01 + (t11 - t01) * ax.weight;
  return bottomRow + (topRow - bottomRow) * ay.weight;
}
// The same, one out-of-line copy (a colour read, inlined in every kernel, would multiply their
// compile time).
template <typename L, typename View, typename Texel = Vec4L<L>>
TWR_LANE_OUTLINE Texel sampleLevel(const View& texture, int level, const Vec2L<L>& uv, bool linear) {
  return (sampleLevelInline<L, View, Texel>)(texture, level, uv, linear);
}
// A height read (red alone) is inlined into sampleMipLevelsInline: a march makes dozens
// per pixel, and the levels of a trilinear read then overlap. A colour read is, where
// TWR_LANES_INLINE_COLOUR_READS says (softrender/lanes_target_begin.h).
template <typename L, typename View, typename Texel, SamplerCase kCase>
TWR_LANE_INLINE Texel sampleLevelFor(const View& texture, int level, const Vec2L<L>& uv, bool linear) {
  if constexpr (std::is_same_v<Texel, L> || TWR_LANES_INLINE_COLOUR_READS) {
    return (sampleLevelInline<L, View, Texel, kCase>)(texture, level, uv, linear);
  } else {
    return (sampleLevel<L, View, Texel>)(texture, level, uv, linear);
  }
}

// The mip levels a sample reads, from its LOD and the filter: each lane's first and second
// level (integer values, level1 >= level0; equal for *_mipmap_nearest, 0 for filters without
// mipmaps), the weight of the second, and the lowest and highest level any lane reads. Reads
// that share a LOD share these: a march over a height map finds them once per fragment.
// *_mipmap_nearest: level rint(lod); *_mipmap_linear: levels floor(lod) and the next, blended
// by frac(lod). Levels clamp to the chain the texture has. A lane whose weight is 0
// (magnified, lod < 0, at the last level, or lod a whole number) takes its first level as its
// second too: a + 0 (b - a) is a, whatever b is, so where no lane blends, the second level is
// never read (the same bits).
template <typename L>
struct MipLevelsL {
  L level0, level1, fraction;
  int lowest = 0, highest = 0;
};
template <typename L, typename View>
TWR_LANE_INLINE MipLevelsL<L> mipLevels(const View& texture, TextureFilter filter, const L& lod) {
  using S = ScalarOf<L>;
  const int last = texLevelCount(texture) - 1;
  const L zero(S(0));
  MipLevelsL<L> m{zero, zero, zero, 0, 0};
  if (!usesMipmaps(filter) || last == 0) return m;
  const L lastL(static_cast<S>(last));
  const L clamped = minOf(lod, lastL);
  if (!levelsLinear(filter)) {
    m.level0 = minOf(maxOf(roundEvenOf(clamped), zero), lastL);
    m.level1 = m.level0;
  } else {
    const L floorLod = floorOf(clamped);
    const auto below = floorLod < zero;
    const auto atLast = floorLod >= lastL;
    m.level0 = select(below, zero, select(atLast, lastL, floorLod));
    m.fraction = select(below | atLast, zero, clamped - floorLod);
    m.level1 = select(m.fraction == zero, m.level0, minOf(m.level0 + L(S(1)), lastL));
  }
  m.lowest = static_cast<int>(lowestLane(m.level0));
  m.highest = static_cast<int>(highestLane(m.level1));
  return m;
}

// Lanes may read different levels: each distinct level is sampled once, for every lane that
// takes it as its first or its second level (a vector straddling a level boundary reads 3
// levels for trilinear, not 4).
template <typename L>
TWR_LANE_INLINE Vec4L<L> selectTexel(const MaskOf<L>& mask, const Vec4L<L>& a, const Vec4L<L>& b) {
  return Vec4L<L>(select(mask, a.x, b.x), select(mask, a.y, b.y), select(mask, a.z, b.z), select(mask, a.w, b.w));
}
template <typename L>
TWR_LANE_INLINE L selectTexel(const MaskOf<L>& mask, const L& a, const L& b) {
  return select(mask, a, b);
}
template <typename L, typename View, typename Texel, SamplerCase kCase>
TWR_LANE_INLINE void sampleLevelPair(const View& texture, const MipLevelsL<L>& mips, const Vec2L<L>& uv,
                                     bool linear, Texel& s0, Texel& s1) {
  using S = ScalarOf<L>;
  s0 = (sampleLevelFor<L, View, Texel, kCase>)(texture, mips.lowest, uv, linear);
  s1 = s0;
  for (int l = mips.lowest + 1; l <= mips.highest; ++l) {
    const L here(static_cast<S>(l));
    const auto first = mips.level0 == here, second = mips.level1 == here;
    if (!anyOf(first | second)) continue;
    const Texel r = (sampleLevelFor<L, View, Texel, kCase>)(texture, l, uv, linear);
    s0 = (selectTexel<L>)(first, r, s0);
    s1 = (selectTexel<L>)(second, r, s1);
  }
}

// The LOD of a quad from its uv differences (top-left pixel to its right and upper
// neighbours), as llvmpipe computes it: rho^2 = max((du/dx W)^2 + (dv/dx H)^2,
// (du/dy W)^2 + (dv/dy H)^2) with W x H the base level, lod = fastLog2(rho^2) / 2 where
// fastLog2(m 2^e) = e + (m - 1) (exact at powers of two, up to 0.086 below log2 between).
template <typename L>
TWR_LANE_INLINE L quadLod(const Vec2L<L>& dUvDx, const Vec2L<L>& dUvDy, int width, int height) {
  using S = ScalarOf<L>;
  const L w(static_cast<S>(width)), h(static_cast<S>(height));
  const L a = dUvDx.x * w, b = dUvDy.x * w, c = dUvDx.y * h, d = dUvDy.y * h;
  const L rx = a * a + c * c, ry = b * b + d * d;
  const L rho2 = maxOf(rx, ry);
  return (floatExponentOf(rho2) + (floatMantissaOf(rho2) - L(S(1)))) * L(S(0.5));
}

// The filtered RGBA (or red) in [0, 1] at uv, reading the levels `mips` chose. Texels within
// a level are picked or blended as texelsLinear(filter) says (GL's minification and
// magnification filters agree for every filter here, so magnification, lod <= 0, is level 0
// with the same texel filter); *_mipmap_linear blends its two levels as a + f (b - a).
template <typename L, typename View, typename Texel = Vec4L<L>, SamplerCase kCase = SamplerCase::kAny>
TWR_LANE_INLINE Texel sampleMipLevelsInline(const View& texture, const Vec2L<L>& uvIn, TextureFilter filter,
                                            const MipLevelsL<L>& mips) {
  const Vec2L<L> uv((sanitizedCoord<L>)(uvIn.x), (sanitizedCoord<L>)(uvIn.y));
  Texel s0, s1;
  (sampleLevelPair<L, View, Texel, kCase>)(texture, mips, uv, texelsLinear(filter), s0, s1);
  if (!usesMipmaps(filter) || texLevelCount(texture) == 1 || !levelsLinear(filter)) return s0;
  return s0 + (s1 - s0) * mips.fraction;
}
template <typename L, typename View, typename Texel = Vec4L<L>>
TWR_LANE_OUTLINE Texel sampleMipLevels(const View& texture, const Vec2L<L>& uvIn, TextureFilter filter,
                                       const MipLevelsL<L>& mips) {
  return (sampleMipLevelsInline<L, View, Texel>)(texture, uvIn, filter, mips);
}

// The filtered RGBA (or red) in [0, 1]. `lod` is the quad's (quadLod); filters without
// mipmaps ignore it.
template <typename L, typename View, typename Texel = Vec4L<L>>
TWR_LANE_INLINE Texel sampleTexture(const View& texture, const Vec2L<L>& uv, TextureFilter filter, const L& lod) {
  if constexpr (TWR_LANES_INLINE_COLOUR_READS) {
    return (sampleMipLevelsInline<L, View, Texel>)(texture, uv, filter, (mipLevels<L>)(texture, filter, lod));
  } else {
    return (sampleMipLevels<L, View, Texel>)(texture, uv, filter, (mipLevels<L>)(texture, filter, lod));
  }
}

// ---- Anisotropic filtering (GL_TEXTURE_MAX_ANISOTROPY > 1), as llvmpipe does it ----
// llvmpipe (lp_bld_sample_soa.c) filters with Heckbert's elliptical weighted average: the
// pixel's footprint in the texture is the ellipse the quad's uv differences span, every texel
// of its bounding box is read with GL_NEAREST, weighted by a Gaussian of its distance inside
// the ellipse (weights 1 .. e^-2 from a 1024-entry table, 0 outside), and the sum divided by
// the total weight. One level, picked from the *shorter* axis: lod = fastLog2(min(rx, ry)) / 2
// with rx, ry as quadLod, level = clamp(trunc(lod), 0, last) for a mipmapped filter
// (level 0 otherwise); the texel filter and the mip filter are otherwise ignored. llvmpipe's
// clamp of the short axis to long / max_anisotropy compares the short axis with itself and
// never fires (Mesa 22.3), so every anisotropy above 1 draws the same picture: 2x and 16x are
// identical on llvmpipe, measured, and on the CPU by construction.

// Half the bounding box the CPU reads at most, texels of the level (a deviation: llvmpipe has
// no bound, and past it a pixel reads millions of texels).
inline constexpr float kMaxEwaHalfExtent = 1024.0f;

// The ellipse of one level's footprint (Heckbert's EWA as llvmpipe computes it): the form
// A u^2 + B u v + C v^2 = F scaled so that F is the weight table's last entry, the sample point
// in texels of the level (centres at integers) and the box of texels [u0, u1] x [v0, v1] it
// reads; a lane not in `lanes`, or whose box is not finite, gets an empty box (last < first).
template <typename L>
struct EwaEllipseL {
  L aScaled, bScaled, cScaled, ddq, texU, texV, u0, v0, u1, v1;
};
template <typename L>
TWR_LANE_INLINE EwaEllipseL<L> ewaEllipse(const Vec2L<L>& uv, const Vec2L<L>& dUvDx, const Vec2L<L>& dUvDy,
                                          L width0, L height0, ScalarOf<L> scaling, const MaskOf<L>& lanes) {
  using S = ScalarOf<L>;
  const L one(S(1)), zero(S(0));
  // The differences in this level's texels: (ux, vx) along a pixel step in x, (uy, vy) in y.
  const L ux = dUvDx.x * width0 * L(scaling), uy = dUvDy.x * width0 * L(scaling);
  const L vx = dUvDx.y * height0 * L(scaling), vy = dUvDy.y * height0 * L(scaling);
  // The ellipse A u^2 + B u v + C v^2 = F (the +1 keeps it at least a texel wide).
  const L a = (vx * vx + vy * vy) + one;
  const L b = (ux * vx + uy * vy) * L(S(-2));
  const L c = (ux * ux + uy * uy) + one;
  const L f = a * c - b * b / L(S(4));
  const L d = (zero - b * b) + a * c * L(S(4));
  // Half the bounding box, then the form scaled so that F is the table's last entry.
  L boxU = L(S(2)) / d * sqrtOf(d * c * f);
  L boxV = L(S(2)) / d * sqrtOf(a * d * f);
  const L formScale = L(static_cast<S>(kEwaWeightCount - 1)) / f;
  EwaEllipseL<L> e;
  e.aScaled = a * formScale;
  e.bScaled = b * formScale;
  e.cScaled = c * formScale;
  e.ddq = e.aScaled * L(S(2));
  // The sample point in texels of this level, texel centres at integers.
  e.texU = uv.x * (width0 * L(scaling)) + L(S(-0.5));
  e.texV = uv.y * (height0 * L(scaling)) + L(S(-0.5));
  // Texel indices stay exact in float (and the loops finite) below 2^22 texels; a lane beyond
  // that, or with a non-finite box, reads nothing and falls back to bilinear.
  const L limit(static_cast<S>(kMaxEwaHalfExtent)), farthest(S(4194304));
  const auto finiteU = isFinite(boxU), finiteV = isFinite(boxV);  // named: masks combine with &, never &&
  const auto nearU = absOf(e.texU) < farthest, nearV = absOf(e.texV) < farthest;
  const auto usable = lanes & finiteU & finiteV & nearU & nearV;
  boxU = select(usable, minOf(boxU, limit), zero);
  boxV = select(usable, minOf(boxV, limit), zero);
  // An unused lane's box is empty: last < first.
  e.u0 = select(usable, floorOf(e.texU - boxU), zero);
  e.v0 = select(usable, floorOf(e.texV - boxV), zero);
  e.u1 = select(usable, zero - floorOf(zero - (e.texU + boxU)), zero - one);  // ceil
  e.v1 = select(usable, zero - floorOf(zero - (e.texV + boxV)), zero - one);
  return e;
}

// The ellipse filter on one level for the lanes in `lanes` (the others compute nothing:
// their box is empty). width0, height0: level 0's size.
template <typename L, typename View>
TWR_LANE_OUTLINE Vec4L<L> sampleEwaLevel(const View& texture, int level, const Vec2L<L>& uv,
                                         const Vec2L<L>& dUvDx, const Vec2L<L>& dUvDy, const MaskOf<L>& lanes) {
  using S = ScalarOf<L>;
  const TextureWrap wrap = texWrap(texture);
  const int width = texLevelWidth(texture, level), height = texLevelHeight(texture, level);
  const S scaling = S(1) / static_cast<S>(1 << level);  // level 0 texels to this level's
  const L width0(static_cast<S>(texLevelWidth(texture, 0))), height0(static_cast<S>(texLevelHeight(texture, 0)));
  const L one(S(1)), zero(S(0));
  const EwaEllipseL<L> e = (ewaEllipse<L>)(uv, dUvDx, dUvDy, width0, height0, scaling, lanes);
  const L &aScaled = e.aScaled, &bScaled = e.bScaled, &cScaled = e.cScaled, &ddq = e.ddq;
  const L &texU = e.texU, &texV = e.texV, &u0 = e.u0, &v0 = e.v0, &u1 = e.u1, &v1 = e.v1;
  // q = A U^2 + B U V + C V^2 at each texel, stepped along u with dq and ddq.
  const L uStart = u0 - texU;
  const L dqBase = (uStart * L(S(2)) + one) * aScaled;
  const L qBase = uStart * uStart * aScaled;
  const float* weights = ewaWeightTable().data();
  const L lastWeight(static_cast<S>(kEwaWeightCount));
  const L intLow(S(-2147483648.0)), intHigh(S(2147483648.0));
  Vec4L<L> sum(zero);
  L total = zero;
  for (L v = v0; anyOf(v <= v1); v = v + one) {
    const auto inV = v <= v1;
    const L rowV = v - texV;
    L dq = rowV * bScaled + dqBase;
    L q = (cScaled * rowV + bScaled * uStart) * rowV + qBase;
    for (L u = u0; anyOf(inV & (u <= u1)); u = u + one) {
      // llvmpipe truncates q to an int32 (x86: out of range or NaN gives INT_MIN, which reads
      // entry 0); from 1024 on the texel is outside the ellipse.
      const auto converts = (q >= intLow) & (q < intHigh);
      const auto outside = converts & (q >= lastWeight);
      const L index = select(converts & !outside, maxOf(truncOf(q), zero), zero);
      const L weight = select(inV & (u <= u1) & !outside, (lookupLanes)(weights, index), zero);
      // Most of a thin ellipse's box is outside it: no lane weighs this texel, so skip the read
      // (as llvmpipe does; adding zeros would not change the sums).
      if (!anyOf(weight > zero)) {
        q = q + dq;
        dq = dq + ddq;
        continue;
      }
      const Vec4L<L> texel = texelValue<L>(
          texture, fetchTexelBytes<L>(texture, level, (nearestTexel<L>)(u / L(static_cast<S>(width)), width, wrap),
                                      (nearestTexel<L>)(v / L(static_cast<S>(height)), height, wrap)));
      sum = sum + texel * weight;
      total = total + weight;
      q = q + dq;
      dq = dq + ddq;
    }
  }
  const Vec4L<L> filtered(sum.x / total, sum.y / total, sum.z / total, sum.w / total);
  const auto empty = total == zero;
  if (!anyOf(empty)) return filtered;
  // No weight at all: llvmpipe falls back to bilinear on the level.
  return (selectTexel<L>)(empty, (sampleLevel<L>)(texture, level, uv, true), filtered);
}

// The anisotropic sample: each lane's level (see above), each distinct level filtered once.
template <typename L, typename View>
TWR_LANE_OUTLINE Vec4L<L> sampleTextureAnisotropic(const View& texture, const Vec2L<L>& uvIn, TextureFilter filter,
                                                   const Vec2L<L>& dUvDx, const Vec2L<L>& dUvDy) {
  using S = ScalarOf<L>;
  const Vec2L<L> uv((sanitizedCoord<L>)(uvIn.x), (sanitizedCoord<L>)(uvIn.y));
  const int last = texLevelCount(texture) - 1;
  const L zero(S(0));
  L level = zero;
  if (usesMipmaps(filter) && last > 0) {
    const L w(static_cast<S>(texLevelWidth(texture, 0))), h(static_cast<S>(texLevelHeight(texture, 0)));
    const L a = dUvDx.x * w, b = dUvDy.x * w, c = dUvDx.y * h, d = dUvDy.y * h;
    const L rx = a * a + c * c, ry = b * b + d * d;
    const L shorter = minOf(rx, ry);
    const L lod = (floatExponentOf(shorter) + (floatMantissaOf(shorter) - L(S(1)))) * L(S(0.5));
    level = minOf(maxOf(truncOf(lod), zero), L(static_cast<S>(last)));
  }
  const int lowest = static_cast<int>(lowestLane(level)), highest = static_cast<int>(highestLane(level));
  Vec4L<L> result = (sampleEwaLevel<L>)(texture, lowest, uv, dUvDx, dUvDy, level == L(static_cast<S>(lowest)));
  for (int l = lowest + 1; l <= highest; ++l) {
    const auto here = level == L(static_cast<S>(l));
    if (!anyOf(here)) continue;
    result = (selectTexel<L>)(here, (sampleEwaLevel<L>)(texture, l, uv, dUvDx, dUvDy, here), result);
  }
  return result;
}

// The level-0 footprint of a sample (the pixel trace's picture of one texture read).
template <typename L, typename View>
TWR_LANE_INLINE FootprintL<L> sampleFootprint(const View& texture, const Vec2L<L>& uvIn, TextureFilter filter) {
  using S = ScalarOf<L>;
  const Vec2L<L> uv((sanitizedCoord<L>)(uvIn.x), (sanitizedCoord<L>)(uvIn.y));
  const int width = texLevelWidth(texture, 0), height = texLevelHeight(texture, 0);
  const TextureWrap wrap = texWrap(texture);
  FootprintL<L> f;
  if (!texelsLinear(filter)) {
    f.x0 = f.x1 = (nearestTexel<L>)(uv.x, width, wrap);
    f.y0 = f.y1 = (nearestTexel<L>)(uv.y, height, wrap);
    f.alpha = f.beta = L(S(0));
    return f;
  }
  const AxisFootprintL<L> ax = (linearAxis<L>)(uv.x, width, wrap);
  const AxisFootprintL<L> ay = (linearAxis<L>)(uv.y, height, wrap);
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
