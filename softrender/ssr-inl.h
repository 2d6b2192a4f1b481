// Screen-space reflections over any lane type (ssr.h describes the pass): a pixel's mirror ray
// marched through the depth buffer, and the colour it adds. The GL twin is shaders/ssr.frag,
// function by function in the same order of operations. Shared source, included plainly and
// per Highway target (softrender/lanes.h).

#if defined(TWR_LANES_HIGHWAY)
#if defined(TWR_SSR_INL_TARGET) == defined(HWY_TARGET_TOGGLE)
#ifdef TWR_SSR_INL_TARGET
#undef TWR_SSR_INL_TARGET
#else
#define TWR_SSR_INL_TARGET
#endif
#define TWR_SSR_INL_EMIT
#endif
#elif !defined(TWR_SSR_INL_PLAIN)
#define TWR_SSR_INL_PLAIN
#define TWR_SSR_INL_EMIT
#endif

#ifdef TWR_SSR_INL_EMIT
#undef TWR_SSR_INL_EMIT

#include "softrender/lane_math-inl.h"
#include "softrender/lanes.h"

TWR_LANES_BEGIN

// A world point's eye distance: the clip w of the camera's projection, the row the screen
// mapping divides by (ssr.frag's distanceOfPoint).
template <typename L>
TWR_LANE_INLINE L ssrDistanceOfPointLanes(const SsrUniformsT<ScalarOf<L>>& u, const Vec3L<L>& p) {
  const auto& m = u.clipFromWorld;
  return ((L(m[0][3]) * p.x + L(m[1][3]) * p.y) + L(m[2][3]) * p.z) + L(m[3][3]);
}

// Where a world point lands on the screen (ssr.frag's screenOf): its clip w (the eye distance
// along the view axis), its window position in pixels, whether that is on the screen (w > 0,
// inside [0, size)), and its pixel's element in the frame's top-row-first buffers (0 off it).
template <typename L>
struct SsrScreenL {
  L w;
  L windowX, windowY;
  MaskOf<L> onScreen;
  L index;
};
template <typename L>
TWR_LANE_INLINE SsrScreenL<L> ssrScreenOfLanes(const SsrUniformsT<ScalarOf<L>>& u, const Vec3L<L>& p) {
  using S = ScalarOf<L>;
  const L zero(S(0)), one(S(1)), half(S(0.5));
  const Mat4T<S>& m = u.clipFromWorld;  // columns summed from the left
  const L x = ((L(m[0][0]) * p.x + L(m[1][0]) * p.y) + L(m[2][0]) * p.z) + L(m[3][0]);
  const L y = ((L(m[0][1]) * p.x + L(m[1][1]) * p.y) + L(m[2][1]) * p.z) + L(m[3][1]);
  const L w = (ssrDistanceOfPointLanes<L>)(u, p);
  const L width(u.viewportSize.x), height(u.viewportSize.y);
  const MaskOf<L> front = w > zero;
  const L safeW = select(front, w, one);
  SsrScreenL<L> s;
  s.w = w;
  s.windowX = ((x / safeW) * half + half) * width;
  s.windowY = ((y / safeW) * half + half) * height;
  s.onScreen = front & (s.windowX >= zero) & (s.windowX < width) & (s.windowY >= zero) & (s.windowY < height);
  const L px = floorOf(select(s.onScreen, s.windowX, zero));
  const L py = floorOf(select(s.onScreen, s.windowY, zero));
  s.index = ((height - one) - py) * width + px;  // exact: frames hold at most 2^24 pixels
  return s;
}

// A window depth's eye distance, 2 n f / ((f + n) - (2 d - 1) (f - n)), f at the clear depth
// (ssr.frag's distanceOfDepth): what a frame without stored positions compares against.
template <typename L>
TWR_LANE_INLINE L ssrDistanceOfDepthLanes(const SsrUniformsT<ScalarOf<L>>& u, const L& d) {
  using S = ScalarOf<L>;
  const L zNdc = L(S(2)) * d - L(S(1));
  return L(u.distanceNumerator) / (L(u.distanceSum) - zNdc * L(u.distanceDifference));
}

// The eye distance of the surface the frame holds at an element (ssr.frag's bufferDistance),
// from the pass's plane of them (ssrSurfaceDistances).
template <typename L>
TWR_LANE_INLINE L ssrBufferDistanceLanes(const SsrUniformsT<ScalarOf<L>>& u, const L& index) {
  return lookupLanes(u.surfaceDistance, index);
}

// An SsrResult as a lane value.
template <typename L>
TWR_LANE_INLINE L ssrResultLane(SsrResult r) {
  return L(static_cast<ScalarOf<L>>(static_cast<int>(r)));
}

// One march's outcome per lane.
template <typename L>
struct SsrMarchL {
  L result;    // an SsrResult, as a lane value
  L steps;     // the steps taken
  L hitIndex;  // the hit pixel's element (valid where result is Hit)
};

// The mirror ray from `origin` along the unit `dir`, for the lanes in `active` (ssr.frag's
// march). Each step puts `next` one step on from `cur`; a `next` the depth buffer's surface
// is still behind moves `cur` there. At the first `next` behind the surface: linear_world
// decides, adaptive_world halves its step and tries again from `cur` until the step is the
// smallest. Deciding: s1 = how far `cur` lies in front of its pixel's surface, s2 = how far
// `next` lies behind its; both under the thickness is a hit, placed s1 / (s1 + s2) of the way
// from `cur` to `next`; otherwise the ray passed behind the surface (behind).
template <typename L>
TWR_LANE_INLINE SsrMarchL<L> ssrMarchLanes(const SsrUniformsT<ScalarOf<L>>& u, const Vec3L<L>& origin,
                                           const Vec3L<L>& dir, const MaskOf<L>& active) {
  using S = ScalarOf<L>;
  const L zero(S(0)), one(S(1)), half(S(0.5));
  const L thickness(u.thickness), minStep(u.minStep);
  const bool adaptive = u.march == SsrMarch::AdaptiveWorld;
  SsrMarchL<L> m{select(active, (ssrResultLane<L>)(SsrResult::Miss), (ssrResultLane<L>)(SsrResult::NotMarched)), zero, zero};
  MaskOf<L> live = active;
  // Distances along the ray, summed in plain adds: every renderer rounds them alike (a
  // multiply-add a GPU compiler may fuse would let positions stepped one from the next drift
  // apart by an ulp a step); each point is origin + dir t from them.
  L tCur = zero;
  L stepLength(u.step);
  for (int i = 0; i < u.maxSteps && anyOf(live); ++i) {
    const L tNext = tCur + stepLength;
    const SsrScreenL<L> sn = (ssrScreenOfLanes<L>)(u, origin + dir * tNext);
    m.steps = select(live, m.steps + one, m.steps);
    m.result = select(live & !sn.onScreen, (ssrResultLane<L>)(SsrResult::OffScreen), m.result);
    live = live & sn.onScreen;
    const L surfaceNext = (ssrBufferDistanceLanes<L>)(u, sn.index);
    const MaskOf<L> inFront = live & (sn.w < surfaceNext);
    const MaskOf<L> crossed = live & !(sn.w < surfaceNext);
    const MaskOf<L> decide = adaptive ? crossed & !(stepLength > minStep) : crossed;
    if (anyOf(decide)) {
      const SsrScreenL<L> sc = (ssrScreenOfLanes<L>)(u, origin + dir * tCur);
      const L s1 = (ssrBufferDistanceLanes<L>)(u, sc.index) - sc.w;
      const L s2 = sn.w - surfaceNext;
      const L sum = s1 + s2;
      const L t = select(sum > zero, s1 / select(sum > zero, sum, one), zero);
      const SsrScreenL<L> sh = (ssrScreenOfLanes<L>)(u, origin + dir * (tCur + stepLength * t));
      const MaskOf<L> hit = decide & (s1 < thickness) & (s2 < thickness) & sh.onScreen;
      m.hitIndex = select(hit, sh.index, m.hitIndex);
      m.result = select(hit, (ssrResultLane<L>)(SsrResult::Hit), select(decide, (ssrResultLane<L>)(SsrResult::Behind), m.result));
      live = live & !decide;
    }
    tCur = select(inFront, tNext, tCur);
    if (adaptive) stepLength = select(crossed & live, stepLength * half, stepLength);
  }
  return m;
}

// One pixel's reflection (ssr.frag's main): the G-buffer's lighting normal, position and
// ssr_reflect, the pixel's own lit colour. The mirror direction of the eye's, marched; on a
// hit, the lit colour there times reflect_strength ssr_reflect is added and clamped. Returns
// the march and, in `colour`, the pixel's new colour (its own where nothing was hit).
template <typename L>
TWR_LANE_INLINE SsrMarchL<L> ssrPixelLanes(const SsrUniformsT<ScalarOf<L>>& u, const Vec3L<L>& nl,
                                           const Vec3L<L>& posWorld, const L& ssrReflect, const MaskOf<L>& drawn,
                                           Vec3L<L>& colour) {
  using S = ScalarOf<L>;
  const L zero(S(0)), two(S(2));
  const Vec3L<L> wo = safeNormalize3<L>(Vec3L<L>(u.eyePosWorld) - posWorld);
  const Vec3L<L> r = safeNormalize3<L>((two * dot3<L>(nl, wo)) * nl - wo);
  const MaskOf<L> active = drawn & (ssrReflect > zero);
  const SsrMarchL<L> m = (ssrMarchLanes<L>)(u, posWorld, r, active);
  const MaskOf<L> hit = m.result == (ssrResultLane<L>)(SsrResult::Hit);
  if (anyOf(hit)) {
    const L index = select(hit, m.hitIndex, zero);
    const Vec3L<L> reflected(lookupLanes(u.colour[0], index), lookupLanes(u.colour[1], index),
                             lookupLanes(u.colour[2], index));
    const L k = L(u.reflectStrength) * ssrReflect;
    const Vec4L<L> lit = clampUnit4<L>(Vec4L<L>(colour + reflected * k, L(S(1))));
    colour = select3<L>(hit, Vec3L<L>(lit.x, lit.y, lit.z), colour);
  }
  return m;
}

TWR_LANES_END

#endif  // TWR_SSR_INL_EMIT
