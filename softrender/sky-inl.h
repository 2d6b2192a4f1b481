// The sky's direction and colour over any lane type (sky.h has the formulas; the C++ twin
// of shaders/sky.frag). Shared source, included plainly and per Highway target.

#if defined(TWR_LANES_HIGHWAY)
#if defined(TWR_SKY_INL_TARGET) == defined(HWY_TARGET_TOGGLE)
#ifdef TWR_SKY_INL_TARGET
#undef TWR_SKY_INL_TARGET
#else
#define TWR_SKY_INL_TARGET
#endif
#define TWR_SKY_INL_EMIT
#endif
#elif !defined(TWR_SKY_INL_PLAIN)
#define TWR_SKY_INL_PLAIN
#define TWR_SKY_INL_EMIT
#endif

#ifdef TWR_SKY_INL_EMIT
#undef TWR_SKY_INL_EMIT

#include "softrender/environment_view-inl.h"
#include "softrender/layer_sample-inl.h"
#include "softrender/lane_math-inl.h"
#include "softrender/lanes.h"
#include "softrender/sky.h"

TWR_LANES_BEGIN

// The view direction through pixel centre (px + 0.5, py + 0.5), world space, unnormalised.
template <typename L>
TWR_LANE_INLINE Vec3L<L> skyDirection(const SkyUniformsT<ScalarOf<L>>& sky, const L& px, const L& py) {
  using S = ScalarOf<L>;
  const L half(S(0.5)), one(S(1));
  const L ndcX = (px + half) * L(sky.ndcPerPixel.x) - one;
  const L ndcY = (py + half) * L(sky.ndcPerPixel.y) - one;
  return (Vec3L<L>(sky.forward) + Vec3L<L>(sky.right) * ndcX) + Vec3L<L>(sky.up) * ndcY;
}

// What the sky reads at pixel (px, py): the direction and its fine differences across the
// pixel's 2x2 quad (GLSL's dFdx / dFdy, which texture() takes its LOD from). The quad's other
// pixels are evaluated where they would be, as a GPU's helper pixels are, past the frame's
// edge included.
template <typename L>
struct SkyReadL {
  Vec3L<L> dir, dx, dy;
};
template <typename L>
TWR_LANE_INLINE SkyReadL<L> skyRead(const SkyUniformsT<ScalarOf<L>>& sky, const L& px, const L& py) {
  using S = ScalarOf<L>;
  const L one(S(1)), two(S(2)), half(S(0.5));
  const L qx = floorOf(px * half) * two, qy = floorOf(py * half) * two;
  SkyReadL<L> read;
  read.dir = (skyDirection<L>)(sky, px, py);
  if (sky.layers) {
    // A 2D map: its coordinate's differences at the quad's first pixel (layer_sample-inl.h).
    (mapDifferences<L>)(sky.layers->kind, (skyDirection<L>)(sky, qx, qy),
                        (skyDirection<L>)(sky, qx + one, qy), (skyDirection<L>)(sky, qx, qy + one),
                        read.dx, read.dy);
    return read;
  }
  read.dx = (skyDirection<L>)(sky, qx + one, py) - (skyDirection<L>)(sky, qx, py);
  read.dy = (skyDirection<L>)(sky, px, qy + one) - (skyDirection<L>)(sky, px, qy);
  return read;
}

// The sky's colour there: the environment read with texture() (the LOD from the direction's
// differences, cubeLod) times the intensity, clamped to [0, 1]; in an environment view,
// the view's colour for the direction and that LOD.
template <typename L>
TWR_LANE_INLINE Vec3L<L> skyColour(const SkyUniformsT<ScalarOf<L>>& sky, const L& px, const L& py) {
  using S = ScalarOf<L>;
  const L zero(S(0)), one(S(1));
  const SkyReadL<L> read = (skyRead<L>)(sky, px, py);
  const L lod = (environmentReadLod<L>)(*sky.cube, sky.layers, read.dir, read.dx, read.dy);
  if (sky.view != View::Shaded) {
    const EnvironmentParameterization kind = sky.layers ? sky.layers->kind : EnvironmentParameterization::Cube;
    const int levels = sky.layers ? sky.layers->levelCount() : sky.cube->levelCount();
    const Vec4L<L> v = (environmentViewColour<L>)(sky.view, kind, read.dir, (clampedLod<L>)(lod, levels));
    return Vec3L<L>(v.x, v.y, v.z);
  }
  const Vec3L<L> c = (sampleEnvironmentAtLod<L>)(*sky.cube, sky.layers, read.dir, lod) * L(sky.intensity);
  return Vec3L<L>(minOf(maxOf(c.x, zero), one), minOf(maxOf(c.y, zero), one), minOf(maxOf(c.z, zero), one));
}

TWR_LANES_END

#endif  // TWR_SKY_INL_EMIT
