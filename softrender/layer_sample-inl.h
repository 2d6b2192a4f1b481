// Sphere and dual-paraboloid maps over any lane type (scene/environment.h has the formulas,
// docs/environment.md the pictures): where a direction is read, and texture() on the 2D array
// the map is uploaded as, as llvmpipe samples an RGB32F array with GL_LINEAR_MIPMAP_LINEAR and
// GL_CLAMP_TO_EDGE. The C++ twin of shaders/environment_map.glsl, the same operations in the
// same order. Shared source, included plainly and per Highway target (softrender/lanes.h).
//
// Unlike a cube (cube_sample-inl.h, fine differences per pixel), a 2D texture takes its LOD
// once per 2x2 quad from the coordinate's differences at the quad's first pixel, to its right
// and above (texture_sample-inl.h's quadLod; docs/textures.md): the coordinate here is
// computed from the direction, so the caller evaluates it at those three pixels.

#if defined(TWR_LANES_HIGHWAY)
#if defined(TWR_LAYER_SAMPLE_INL_TARGET) == defined(HWY_TARGET_TOGGLE)
#ifdef TWR_LAYER_SAMPLE_INL_TARGET
#undef TWR_LAYER_SAMPLE_INL_TARGET
#else
#define TWR_LAYER_SAMPLE_INL_TARGET
#endif
#define TWR_LAYER_SAMPLE_INL_EMIT
#endif
#elif !defined(TWR_LAYER_SAMPLE_INL_PLAIN)
#define TWR_LAYER_SAMPLE_INL_PLAIN
#define TWR_LAYER_SAMPLE_INL_EMIT
#endif

#ifdef TWR_LAYER_SAMPLE_INL_EMIT
#undef TWR_LAYER_SAMPLE_INL_EMIT

#include "scene/environment.h"
#include "softrender/cube_sample-inl.h"
#include "softrender/lane_math-inl.h"
#include "softrender/lanes.h"
#include "softrender/texture_sample-inl.h"

TWR_LANES_BEGIN

// Where a map is read: the layer (0 or 1, as a lane value) and (u, v).
template <typename L>
struct MapCoordL {
  L layer, u, v;
};

// The formulas of scene/environment.h for a direction r of any length (normalised first, as
// the sky's direction is not). GLSL: environmentCoord.
template <typename L>
TWR_LANE_INLINE MapCoordL<L> environmentCoord(EnvironmentParameterization kind, const Vec3L<L>& rIn) {
  using S = ScalarOf<L>;
  const L zero(S(0)), one(S(1)), two(S(2)), half(S(0.5));
  const Vec3L<L> r = safeNormalize<L>(rIn);
  if (kind == EnvironmentParameterization::Sphere) {
    const L z1 = r.z + one;
    const L m = two * sqrtOf((r.x * r.x + r.y * r.y) + z1 * z1);
    return MapCoordL<L>{zero, r.x / m + half, r.y / m + half};
  }
  const L d = one + absOf(r.z);
  return MapCoordL<L>{select(r.z < zero, one, zero), (r.x / d) * half + half, (r.y / d) * half + half};
}

// Bilinear on one level, clamped to the edge: llvmpipe's u * size - 1/2, its floor and
// fraction, the footprint's indices clamped to the layer, lerps fused (as the cube's).
template <typename L>
TWR_LANE_INLINE Vec3L<L> sampleMapLevel(const ParameterizedMap& map, int level, const MapCoordL<L>& c) {
  using S = ScalarOf<L>;
  const CubeMapLevel& lv = map.levels[static_cast<std::size_t>(level)];
  const L zero(S(0)), one(S(1)), sizeL(static_cast<S>(lv.size)), last(static_cast<S>(lv.size - 1));
  const L u = c.u * sizeL - L(S(0.5)), v = c.v * sizeL - L(S(0.5));
  const L x0 = floorOf(u), y0 = floorOf(v);
  const L alpha = u - x0, beta = v - y0;
  const L xa = minOf(maxOf(x0, zero), last), xb = minOf(maxOf(x0 + one, zero), last);
  const L ya = minOf(maxOf(y0, zero), last), yb = minOf(maxOf(y0 + one, zero), last);
  const L layerBase = c.layer * sizeL;
  const auto texel = [&](const L& x, const L& y) {
    const L index = (layerBase + y) * sizeL + x;
    return Vec3L<L>((lookupLanes)(lv.r.data(), index), (lookupLanes)(lv.g.data(), index),
                    (lookupLanes)(lv.b.data(), index));
  };
  return (lerpFused3<L>)((lerpFused3<L>)(texel(xa, ya), texel(xb, ya), alpha),
                         (lerpFused3<L>)(texel(xa, yb), texel(xb, yb), alpha), beta);
}

// The map at an explicit LOD (textureLod with GL_LINEAR_MIPMAP_LINEAR): the cube's level
// choice and blend (cube_sample-inl.h, blendLevels).
template <typename L>
TWR_LANE_OUTLINE Vec3L<L> sampleMapLod(const ParameterizedMap& map, const MapCoordL<L>& cIn, const L& lod) {
  const MapCoordL<L> c{cIn.layer, (sanitizedCoord<L>)(cIn.u), (sanitizedCoord<L>)(cIn.v)};
  return (blendLevels<L>)(map.levelCount(), lod,
                          [&](int level) { return (sampleMapLevel<L>)(map, level, c); });
}

// texture(sampler2DArray, vec3(uv, layer)) with the coordinate's quad differences (du/dx,
// dv/dx) and (du/dy, dv/dy): the 2D LOD rule over the base level's side.
template <typename L>
TWR_LANE_INLINE L mapLod(const Vec2L<L>& dx, const Vec2L<L>& dy, int size) {
  using S = ScalarOf<L>;
  const L lod = (quadLod<L>)(dx, dy, size, size);
  return select(isFinite(lod), lod, L(S(0)));
}

// The differences texture() takes for a direction read at the quad's first pixel (`first`),
// the one to its right and the one above: a cube's fine differences are the caller's; a map's
// are its coordinate's, (du, dv, 0) in x and y.
template <typename L>
TWR_LANE_INLINE void mapDifferences(EnvironmentParameterization kind, const Vec3L<L>& first,
                                    const Vec3L<L>& right, const Vec3L<L>& above, Vec3L<L>& dx, Vec3L<L>& dy) {
  using S = ScalarOf<L>;
  const MapCoordL<L> c0 = (environmentCoord<L>)(kind, first), cx = (environmentCoord<L>)(kind, right),
                     cy = (environmentCoord<L>)(kind, above);
  dx = Vec3L<L>(cx.u - c0.u, cx.v - c0.v, L(S(0)));
  dy = Vec3L<L>(cy.u - c0.u, cy.v - c0.v, L(S(0)));
}

// What the environment holds in direction r, read with texture(): the cube with r's fine
// differences, or the sphere or paraboloid map (when `layers` is not null) with its
// coordinate's quad differences (mapDifferences), both in dx and dy. First the LOD
// texture() takes from them:
template <typename L>
TWR_LANE_INLINE L environmentReadLod(const CubeMap& cube, const ParameterizedMap* layers, const Vec3L<L>& r,
                                     const Vec3L<L>& dx, const Vec3L<L>& dy) {
  if (!layers) return (cubeLod<L>)(r, dx, dy, cube.size());
  return (mapLod<L>)(Vec2L<L>(dx.x, dx.y), Vec2L<L>(dy.x, dy.y), layers->size());
}
// The same read at a LOD already found (environmentReadLod, or textureLod's explicit one).
template <typename L>
TWR_LANE_INLINE Vec3L<L> sampleEnvironmentAtLod(const CubeMap& cube, const ParameterizedMap* layers,
                                                const Vec3L<L>& r, const L& lod) {
  if (!layers) return (sampleCubeLod<L>)(cube, r, lod);
  return (sampleMapLod<L>)(*layers, (environmentCoord<L>)(layers->kind, r), lod);
}
template <typename L>
TWR_LANE_INLINE Vec3L<L> sampleEnvironment(const CubeMap& cube, const ParameterizedMap* layers, const Vec3L<L>& r,
                                           const Vec3L<L>& dx, const Vec3L<L>& dy) {
  return (sampleEnvironmentAtLod<L>)(cube, layers, r, (environmentReadLod<L>)(cube, layers, r, dx, dy));
}

TWR_LANES_END

#endif  // TWR_LAYER_SAMPLE_INL_EMIT
