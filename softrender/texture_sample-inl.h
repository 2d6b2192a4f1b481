// Texture sampling over any lane type, exactly as GL 3.3 defines it for GL_REPEAT without
// mipmaps (texture_sample.h has the formulas). Shared source, included plainly and per
// Highway target (softrender/lanes.h). A texture is reached through a view type that provides
//   texWidth(view), texHeight(view)               texels
//   wrapTexelIndex(view size, integral L) -> IntOf<L>   floor value reduced mod size, exactly
//   nextTexelIndex(IntOf<L> i, size)              i + 1, wrapped
//   fetchTexel<L>(view, IntOf<L> x, IntOf<L> y)   texel RGBA as L in [0, 1] (byte / 255)
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
#include "softrender/lanes.h"

TWR_LANES_BEGIN

// Which texels one sample reads and with what weights.
template <typename L>
struct FootprintL {
  IntOf<L> x0, y0, x1, y1;  // texel indices (x1, y1 equal x0, y0 for nearest)
  L alpha, beta;            // bilinear weights towards x1 and y1 (0 for nearest)
};

// nearest: i = floor(u * w), j = floor(v * h), the float products floored and wrapped; a
// non-finite coordinate reads texel 0.
// bilinear: u' = u * w - 0.5, i0 = floor(u'), alpha = u' - i0, i1 = i0 + 1 (same for v),
// wrapped; a non-finite u' gives i0 = 0 and alpha = 0.
template <typename L, typename View>
TWR_LANE_INLINE FootprintL<L> sampleFootprintLanes(const View& texture, const Vec2L<L>& uv, TextureFilter filter) {
  using S = ScalarOf<L>;
  const int width = texWidth(texture), height = texHeight(texture);
  const L zero(S(0));
  FootprintL<L> f;
  if (filter == TextureFilter::Nearest) {
    const L fu = floorOf(uv.x * L(static_cast<S>(width)));
    const L fv = floorOf(uv.y * L(static_cast<S>(height)));
    f.x0 = wrapTexelIndex(width, select(isFinite(fu), fu, zero));
    f.y0 = wrapTexelIndex(height, select(isFinite(fv), fv, zero));
    f.x1 = f.x0;
    f.y1 = f.y0;
    f.alpha = zero;
    f.beta = zero;
    return f;
  }
  constexpr S kTexelCentre = S(0.5);  // texel centres at +0.5
  const L u = uv.x * L(static_cast<S>(width)) - L(kTexelCentre);
  const L v = uv.y * L(static_cast<S>(height)) - L(kTexelCentre);
  const auto finiteU = isFinite(u);
  const auto finiteV = isFinite(v);
  const L fu = floorOf(u), fv = floorOf(v);
  f.alpha = select(finiteU, u - fu, zero);
  f.beta = select(finiteV, v - fv, zero);
  f.x0 = wrapTexelIndex(width, select(finiteU, fu, zero));
  f.y0 = wrapTexelIndex(height, select(finiteV, fv, zero));
  f.x1 = nextTexelIndex(f.x0, width);
  f.y1 = nextTexelIndex(f.y0, height);
  return f;
}

// The filtered RGBA: nearest reads T(x0, y0); bilinear
//   (1-a)(1-b) T(x0,y0) + a(1-b) T(x1,y0) + (1-a) b T(x0,y1) + a b T(x1,y1), summed from the left.
template <typename L, typename View>
TWR_LANE_INLINE Vec4L<L> sampleTextureLanes(const View& texture, const Vec2L<L>& uv, TextureFilter filter) {
  using S = ScalarOf<L>;
  const FootprintL<L> f = sampleFootprintLanes<L>(texture, uv, filter);
  if (filter == TextureFilter::Nearest) return fetchTexel<L>(texture, f.x0, f.y0);
  const L a = f.alpha, b = f.beta, one(S(1));
  return (one - a) * (one - b) * fetchTexel<L>(texture, f.x0, f.y0) + a * (one - b) * fetchTexel<L>(texture, f.x1, f.y0) +
         (one - a) * b * fetchTexel<L>(texture, f.x0, f.y1) + a * b * fetchTexel<L>(texture, f.x1, f.y1);
}

TWR_LANES_END

#endif  // TWR_TEXTURE_SAMPLE_INL_EMIT
