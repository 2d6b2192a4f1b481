// The environment's debug views over any lane type (docs/environment.md, "Debug views"): the
// C++ twin of environmentViewColour and dimmedColour in shaders/environment_map.glsl, the same
// operations in the same order.
//   reflect_dir  the reflected direction (world space, normalised) as (r + 1) / 2
//   env_face     the cube face it lands on (GL's face choice, cube_sample-inl.h), or for a
//                sphere or paraboloid map the hemisphere (+Z or -Z) that holds it
//   env_lod      the LOD it is read at, clamped to the chain read (what the sampler uses), as
//                the heat ramp over [0, kEnvironmentLodViewMax]
// Surfaces that read no reflection or refraction show their shaded colour dimmed to grey, so
// the ones that do stand out. The sky box shows the same values for its view direction.
// Shared source, included plainly and per Highway target (softrender/lanes.h).

#if defined(TWR_LANES_HIGHWAY)
#if defined(TWR_ENVIRONMENT_VIEW_INL_TARGET) == defined(HWY_TARGET_TOGGLE)
#ifdef TWR_ENVIRONMENT_VIEW_INL_TARGET
#undef TWR_ENVIRONMENT_VIEW_INL_TARGET
#else
#define TWR_ENVIRONMENT_VIEW_INL_TARGET
#endif
#define TWR_ENVIRONMENT_VIEW_INL_EMIT
#endif
#elif !defined(TWR_ENVIRONMENT_VIEW_INL_PLAIN)
#define TWR_ENVIRONMENT_VIEW_INL_PLAIN
#define TWR_ENVIRONMENT_VIEW_INL_EMIT
#endif

#ifdef TWR_ENVIRONMENT_VIEW_INL_EMIT
#undef TWR_ENVIRONMENT_VIEW_INL_EMIT

#include "scene/environment.h"
#include "scene/settings.h"
#include "softrender/cube_sample-inl.h"
#include "softrender/lane_math-inl.h"
#include "softrender/lanes.h"

TWR_LANES_BEGIN

// The colour of face f (0..5, GL order), kCubeFaceViewColours: the positive face bright, the
// negative dark, red for x, green for y, blue for z.
template <typename L>
TWR_LANE_INLINE Vec3L<L> faceColour(const L& face) {
  using S = ScalarOf<L>;
  const auto colourOf = [](int f) {
    const float* c = kCubeFaceViewColours[f];
    return Vec3L<L>(L(static_cast<S>(c[0])), L(static_cast<S>(c[1])), L(static_cast<S>(c[2])));
  };
  Vec3L<L> c = colourOf(0);
  for (int f = 1; f < kCubeFaces; ++f) c = select3<L>(face == L(static_cast<S>(f)), colourOf(f), c);
  return c;
}

// The LOD a read at `lod` uses on a chain of `levelCount` levels: clamped to it, 0 when not
// finite (blendLevels' rule), so the value is the one the sampler blends at.
template <typename L>
TWR_LANE_INLINE L clampedLod(const L& lod, int levelCount) {
  using S = ScalarOf<L>;
  const L zero(S(0));
  return minOf(maxOf(select(isFinite(lod), lod, zero), zero), L(static_cast<S>(levelCount - 1)));
}

// The environment view's colour for direction r read at `lod` (clamped); `kind` is how the map is read
// (the cube, or a sphere or paraboloid map: the hemisphere then, +Z as face 4, -Z as face 5).
template <typename L>
TWR_LANE_INLINE Vec4L<L> environmentViewColour(View view, EnvironmentParameterization kind, const Vec3L<L>& r,
                                               const L& lod) {
  using S = ScalarOf<L>;
  const L one(S(1));
  if (view == View::ReflectDir) return (vectorAsColour<L>)(safeNormalize<L>(r));
  if (view == View::EnvLod) return (heatColour<L>)(lod * L(static_cast<S>(1.0 / kEnvironmentLodViewMax)));
  const L face = kind == EnvironmentParameterization::Cube ? (cubeCoord<L>)(r).face
                                                            : select(r.z < L(S(0)), L(S(5)), L(S(4)));
  return Vec4L<L>((faceColour<L>)(face), one);
}

// A surface that reads no reflection in an environment view: its colour clamped, then a
// quarter of its luminance (Rec. 709 weights) as grey.
template <typename L>
TWR_LANE_INLINE Vec4L<L> dimmedColour(const Vec4L<L>& colour) {
  using S = ScalarOf<L>;
  const Vec4L<L> c = (clampUnit4<L>)(colour);
  const L grey = L(S(0.25)) * ((L(S(0.2126)) * c.x + L(S(0.7152)) * c.y) + L(S(0.0722)) * c.z);
  return Vec4L<L>(grey, grey, grey, L(S(1)));
}

TWR_LANES_END

#endif  // TWR_ENVIRONMENT_VIEW_INL_EMIT
