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

#include "scene/ssr_trace.h"
#include "softrender/lane_math-inl.h"
#include "softrender/lanes.h"

#include <type_traits>
#include <vector>

TWR_LANES_BEGIN

// A world point's eye distance: the clip w of the camera's projection, the row the screen
// mapping divides by (ssr.frag's distanceOfPoint).
template <typename L>
TWR_LANE_INLINE L distanceOfPoint(const SsrUniformsT<ScalarOf<L>>& u, const Vec3L<L>& p) {
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
TWR_LANE_INLINE SsrScreenL<L> screenOf(const SsrUniformsT<ScalarOf<L>>& u, const Vec3L<L>& p) {
  using S = ScalarOf<L>;
  const L zero(S(0)), one(S(1)), half(S(0.5));
  const Mat4T<S>& m = u.clipFromWorld;  // columns summed from the left
  const L x = ((L(m[0][0]) * p.x + L(m[1][0]) * p.y) + L(m[2][0]) * p.z) + L(m[3][0]);
  const L y = ((L(m[0][1]) * p.x + L(m[1][1]) * p.y) + L(m[2][1]) * p.z) + L(m[3][1]);
  const L w = (distanceOfPoint<L>)(u, p);
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
TWR_LANE_INLINE L distanceOfDepth(const SsrUniformsT<ScalarOf<L>>& u, const L& d) {
  using S = ScalarOf<L>;
  const L zNdc = L(S(2)) * d - L(S(1));
  return L(u.distanceNumerator) / (L(u.distanceSum) - zNdc * L(u.distanceDifference));
}

// The eye distance of the surface the frame holds at an element (ssr.frag's bufferDistance),
// from the pass's plane of them (ssrSurfaceDistances).
template <typename L>
TWR_LANE_INLINE L bufferDistance(const SsrUniformsT<ScalarOf<L>>& u, const L& index) {
  return lookupLanes(u.surfaceDistance, index);
}

// An SsrResult as a lane value.
template <typename L>
TWR_LANE_INLINE L ssrResultLane(SsrResult r) {
  return L(static_cast<ScalarOf<L>>(static_cast<int>(r)));
}

// The pixel inspector's record of one step (scene/ssr_trace.h), on the scalar lanes only (the
// teaching path's float, the reference's double; a vector of pixels records nothing): the
// march passes `log` only to trace one pixel (traceSsrMarch), else null. ssr.frag's record()
// stores the same numbers at the same points.
template <typename S>
inline void ssrRecordStep(std::vector<SsrMarchStep>* log, SsrStepKind kind, S pixelX, S pixelY, S rayDistance,
                          S surfaceDistance, S level, S along) {
  if (!log) return;
  SsrMarchStep step;
  step.pixel = vec2(static_cast<float>(pixelX), static_cast<float>(pixelY));
  step.rayDistance = static_cast<float>(rayDistance);
  step.surfaceDistance = static_cast<float>(surfaceDistance);
  step.level = static_cast<int>(level);
  step.along = static_cast<float>(along);
  step.kind = kind;
  log->push_back(step);
}
// The same where `where` holds, for any lane type: a vector of pixels records nothing.
template <typename L, typename Mask>
TWR_LANE_INLINE void ssrRecordWhere(std::vector<SsrMarchStep>* log, const Mask& where, SsrStepKind kind, L pixelX,
                                    L pixelY, L rayDistance, L surfaceDistance, L level, L along) {
  if constexpr (std::is_floating_point_v<L>) {
    if (where) ssrRecordStep<L>(log, kind, pixelX, pixelY, rayDistance, surfaceDistance, level, along);
  }
}

// One march's outcome per lane.
template <typename L>
struct SsrMarchL {
  L result;        // an SsrResult, as a lane value
  L steps;         // the steps taken
  L hitIndex;      // the hit pixel's element (valid where result is Hit)
  L hitX, hitY;    // the hit pixel's column and row from the bottom (valid where result is Hit)
  L level;         // hiz: the highest level a cell was skipped at (0: none, and for the other marches)
};

// The mirror ray from `origin` along the unit `dir`, for the lanes in `active` (ssr.frag's
// march). Each step puts `next` one step on from `cur`; a `next` the depth buffer's surface
// is still behind moves `cur` there. At the first `next` behind the surface: linear_world
// decides, adaptive_world halves its step and tries again from `cur` until the step is the
// smallest. Deciding: s1 = how far `cur` lies in front of its pixel's surface, s2 = how far
// `next` lies behind its; both under the thickness is a hit, placed s1 / (s1 + s2) of the way
// from `cur` to `next`; otherwise the ray passed behind the surface (behind).
template <typename L>
TWR_LANE_INLINE SsrMarchL<L> march(const SsrUniformsT<ScalarOf<L>>& u, const Vec3L<L>& origin,
                                   const Vec3L<L>& dir, const MaskOf<L>& active,
                                   std::vector<SsrMarchStep>* log = nullptr) {
  using S = ScalarOf<L>;
  const L zero(S(0)), one(S(1)), half(S(0.5));
  const L thickness(u.thickness), minStep(u.minStep);
  const bool adaptive = u.march == SsrMarch::AdaptiveWorld;
  SsrMarchL<L> m{select(active, (ssrResultLane<L>)(SsrResult::Miss), (ssrResultLane<L>)(SsrResult::NotMarched)),
                 zero, zero, zero, zero, zero};
  MaskOf<L> live = active;
  // Distances along the ray, summed in plain adds: every renderer rounds them alike (a
  // multiply-add a GPU compiler may fuse would let positions stepped one from the next drift
  // apart by an ulp a step); each point is origin + dir t from them.
  L tCur = zero;
  L stepLength(u.step);
  for (int i = 0; i < u.maxSteps && anyOf(live); ++i) {
    const L tNext = tCur + stepLength;
    const SsrScreenL<L> sn = (screenOf<L>)(u, origin + dir * tNext);
    m.steps = select(live, m.steps + one, m.steps);
    m.result = select(live & !sn.onScreen, (ssrResultLane<L>)(SsrResult::OffScreen), m.result);
    live = live & sn.onScreen;
    const L surfaceNext = (bufferDistance<L>)(u, sn.index);
    const MaskOf<L> inFront = live & (sn.w < surfaceNext);
    const MaskOf<L> crossed = live & !(sn.w < surfaceNext);
    const MaskOf<L> decide = adaptive ? crossed & !(stepLength > minStep) : crossed;
    if (anyOf(decide)) {
      const SsrScreenL<L> sc = (screenOf<L>)(u, origin + dir * tCur);
      const L s1 = (bufferDistance<L>)(u, sc.index) - sc.w;
      const L s2 = sn.w - surfaceNext;
      const L sum = s1 + s2;
      const L t = select(sum > zero, s1 / select(sum > zero, sum, one), zero);
      const SsrScreenL<L> sh = (screenOf<L>)(u, origin + dir * (tCur + stepLength * t));
      const MaskOf<L> hit = decide & (s1 < thickness) & (s2 < thickness) & sh.onScreen;
      m.hitIndex = select(hit, sh.index, m.hitIndex);
      m.hitX = select(hit, floorOf(select(sh.onScreen, sh.windowX, zero)), m.hitX);
      m.hitY = select(hit, floorOf(select(sh.onScreen, sh.windowY, zero)), m.hitY);
      m.result = select(hit, (ssrResultLane<L>)(SsrResult::Hit), select(decide, (ssrResultLane<L>)(SsrResult::Behind), m.result));
      live = live & !decide;
    }
    if constexpr (std::is_floating_point_v<L>) {
      const SsrStepKind kind = !sn.onScreen ? SsrStepKind::OffScreen
                               : decide     ? (m.result == (ssrResultLane<L>)(SsrResult::Hit) ? SsrStepKind::Hit : SsrStepKind::Behind)
                               : inFront    ? SsrStepKind::InFront
                                            : SsrStepKind::Refine;
      const L px = sn.onScreen ? std::floor(sn.windowX) : zero, py = sn.onScreen ? std::floor(sn.windowY) : zero;
      ssrRecordStep<L>(log, kind, px, py, sn.w, sn.onScreen ? surfaceNext : zero, zero, tNext);
    }
    tCur = select(inFront, tNext, tCur);
    if (adaptive) stepLength = select(crossed & live, stepLength * half, stepLength);
  }
  return m;
}

// The screen marches' ray (ssr.frag's screenRay): the mirror ray from `origin` along the unit
// `dir` as a line on the screen, from the origin's window position to where the ray's eye
// distance reaches the far distance (moving away from the eye) or the near one (toward it), at
// most farDistance world units along it. Sample j lies j steps from the origin, a step one
// pixel along the line's major axis; 1 / (eye distance) is linear on the screen, so the ray's
// eye distance at sample j is 1 / (k0 + stepK j) (McGuire and Mara 2014: perspective-correct).
template <typename L>
struct SsrScreenRayL {
  L x0, y0;        // the origin's window position (pixels)
  L stepX, stepY;  // window pixels per sample: 1 along the major axis
  L k0, stepK;     // 1 / eye distance at the origin, and its change per sample (1 / world units)
  L lastSample;    // the samples run 1 .. lastSample (0: the line is under a pixel long)
};
template <typename L>
TWR_LANE_INLINE SsrScreenRayL<L> screenRay(const SsrUniformsT<ScalarOf<L>>& u, const Vec3L<L>& origin,
                                           const Vec3L<L>& dir) {
  using S = ScalarOf<L>;
  const L zero(S(0)), one(S(1));
  const auto& m = u.clipFromWorld;
  const SsrScreenL<L> s0 = (screenOf<L>)(u, origin);
  // The eye distance's change per world unit along the ray (the clip w row, without its offset).
  const L wPerT = (L(m[0][3]) * dir.x + L(m[1][3]) * dir.y) + L(m[2][3]) * dir.z;
  const L nearW(u.nearDistance), farW(u.farDistance);
  const MaskOf<L> away = wPerT > zero, toward = wPerT < zero;
  const L tAway = (farW - s0.w) / select(away, wPerT, one);
  const L tToward = (nearW - s0.w) / select(toward, wPerT, L(S(-1)));
  const L tEnd = minOf(maxOf(select(away, tAway, select(toward, tToward, farW)), zero), farW);
  const SsrScreenL<L> s1 = (screenOf<L>)(u, origin + dir * tEnd);
  const L dx = s1.windowX - s0.windowX, dy = s1.windowY - s0.windowY;
  const L length = maxOf(absOf(dx), absOf(dy));  // pixels along the major axis
  const MaskOf<L> long1 = length >= one;
  const L safeLength = select(long1, length, one);
  const L safeW0 = select(s0.w > zero, s0.w, one), safeW1 = select(s1.w > zero, s1.w, one);
  SsrScreenRayL<L> r;
  r.x0 = s0.windowX;
  r.y0 = s0.windowY;
  r.stepX = dx / safeLength;
  r.stepY = dy / safeLength;
  r.k0 = one / safeW0;
  r.stepK = (one / safeW1 - r.k0) / safeLength;
  r.lastSample = select(long1 & (s0.w > zero), floorOf(length), zero);
  return r;
}

// Sample j of a screen ray (ssr.frag's sampleAt): the ray's eye distance there, its pixel and
// whether that is on the screen, the pixel's element (0 off the screen).
template <typename L>
struct SsrSampleL {
  L w;
  L pixelX, pixelY;  // 0 off the screen
  MaskOf<L> onScreen;
  L index;
};
template <typename L>
TWR_LANE_INLINE SsrSampleL<L> sampleAt(const SsrUniformsT<ScalarOf<L>>& u, const SsrScreenRayL<L>& r,
                                       const L& j) {
  using S = ScalarOf<L>;
  const L zero(S(0)), one(S(1));
  const L x = r.x0 + r.stepX * j;
  const L y = r.y0 + r.stepY * j;
  const L width(u.viewportSize.x), height(u.viewportSize.y);
  SsrSampleL<L> s;
  s.w = one / (r.k0 + r.stepK * j);
  s.onScreen = (x >= zero) & (x < width) & (y >= zero) & (y < height);
  s.pixelX = floorOf(select(s.onScreen, x, zero));
  s.pixelY = floorOf(select(s.onScreen, y, zero));
  s.index = ((height - one) - s.pixelY) * width + s.pixelX;
  return s;
}

// The cell of side cellSize holding pixel (px, py), its pixel bounds [left, right) x [bottom,
// top) (a level's last column or row also holds the odd one the halving dropped), and the last
// sample of the ray inside it, axis by axis: x0 + stepX j < right moving right, >= left moving
// left. GLSL: ssr.frag's cellOf (levelWidth kept for the cell's index).
template <typename L>
struct SsrCellL {
  L x, y, left, bottom, right, top, last, levelWidth;
};
template <typename L>
TWR_LANE_INLINE SsrCellL<L> cellOf(const SsrUniformsT<ScalarOf<L>>& u, const SsrScreenRayL<L>& ray, L px, L py,
                                   L cellSize) {
  using S = ScalarOf<L>;
  const L zero(S(0)), one(S(1));
  const L width(u.viewportSize.x), height(u.viewportSize.y);
  SsrCellL<L> c;
  c.levelWidth = floorOf(width / cellSize);
  const L levelHeight = floorOf(height / cellSize);
  c.x = minOf(floorOf(px / cellSize), c.levelWidth - one);
  c.y = minOf(floorOf(py / cellSize), levelHeight - one);
  c.left = c.x * cellSize;
  c.bottom = c.y * cellSize;
  c.right = select(c.x == c.levelWidth - one, width, c.left + cellSize);
  c.top = select(c.y == levelHeight - one, height, c.bottom + cellSize);
  const MaskOf<L> rightward = ray.stepX > zero, leftward = ray.stepX < zero;
  const MaskOf<L> upward = ray.stepY > zero, downward = ray.stepY < zero;
  const L safeStepX = select(rightward | leftward, ray.stepX, one);
  const L safeStepY = select(upward | downward, ray.stepY, one);
  const L lastX = select(rightward, (zero - floorOf((ray.x0 - c.right) / safeStepX)) - one,
                         select(leftward, floorOf((c.left - ray.x0) / safeStepX), ray.lastSample));
  const L lastY = select(upward, (zero - floorOf((ray.y0 - c.top) / safeStepY)) - one,
                         select(downward, floorOf((c.bottom - ray.y0) / safeStepY), ray.lastSample));
  c.last = minOf(minOf(lastX, lastY), ray.lastSample);
  return c;
}

// The screen marches (ssr.frag's screenMarch): dda_screen with u.hizLevels 0, hiz above.
// dda_screen takes the ray's samples one pixel at a time: a sample in front of its pixel's
// surface (or over a pixel where nothing was drawn) moves on; at the first one that is not, the ray between the sample before and this
// one met the surface if its nearer end lies less than the thickness behind it: a hit at this
// pixel; otherwise the ray passed behind (linear_world's two-sided test would compare the
// sample before with its own pixel's surface, which a step across a pixel leaves far behind).
// hiz reaches the same samples and the same answer in fewer steps. After a sample in front, the
// next is tried a level up: the cell of that level holding it, its least surface distance
// from the chain, and the ray's samples while they stay in the cell. If the farthest of them
// (the ray's eye distance only grows or only shrinks along it) is nearer than the cell's
// nearest surface, every one is in front of its pixel's surface: the march jumps past them and
// climbs a level; otherwise it descends one and tries again, down to single pixels (and a
// level-1 cell that could not be skipped is not tried again while the march is inside it).
template <typename L>
TWR_LANE_INLINE SsrMarchL<L> screenMarch(const SsrUniformsT<ScalarOf<L>>& u, const Vec3L<L>& origin,
                                         const Vec3L<L>& dir, const MaskOf<L>& active,
                                         std::vector<SsrMarchStep>* log = nullptr) {
  using S = ScalarOf<L>;
  const L zero(S(0)), one(S(1)), two(S(2)), half(S(0.5));
  const L thickness(u.thickness), topLevel(static_cast<S>(u.hizLevels));
  const SsrScreenRayL<L> ray = (screenRay<L>)(u, origin, dir);
  SsrMarchL<L> m{select(active, (ssrResultLane<L>)(SsrResult::Miss), (ssrResultLane<L>)(SsrResult::NotMarched)),
                 zero, zero, zero, zero, zero};
  MaskOf<L> live = active;
  L j = zero;         // the last sample marched: it and every one before lie in front
  L level = zero;     // the level the next sample is tried at (0: its pixel alone)
  L cellSize = one;   // that level's cells' side, pixels (2^level, exact)
  // The last sample of the last level-1 cell that could not be skipped: until the march is
  // past it, it stays with single pixels instead of testing that cell again at every step.
  L blockedUntil = zero;
  for (int i = 0; i < u.maxSteps && anyOf(live); ++i) {
    const L n = j + one;
    m.steps = select(live, m.steps + one, m.steps);
    const MaskOf<L> ended = live & (n > ray.lastSample);
    m.result = select(ended, (ssrResultLane<L>)(SsrResult::Miss), m.result);
    live = live & !ended;
    (ssrRecordWhere<L>)(log, ended, SsrStepKind::Ended, zero, zero, zero, zero, zero, n);
    const SsrSampleL<L> sn = (sampleAt<L>)(u, ray, n);
    (ssrRecordWhere<L>)(log, live & !sn.onScreen, SsrStepKind::OffScreen, zero, zero, sn.w, zero, zero, n);
    m.result = select(live & !sn.onScreen, (ssrResultLane<L>)(SsrResult::OffScreen), m.result);
    live = live & sn.onScreen;
    const MaskOf<L> atPixel = live & (level == zero);
    const MaskOf<L> atCell = live & (level > zero);
    if (anyOf(atPixel)) {
      const L surfaceN = (bufferDistance<L>)(u, sn.index);
      const MaskOf<L> passes = (sn.w < surfaceN) | !(surfaceN < L(u.skyDistance));  // in front, or nothing there
      const MaskOf<L> inFront = atPixel & passes;
      const MaskOf<L> crossed = atPixel & !passes;
      if (anyOf(crossed)) {
        // The ray's nearest point between the last sample and this one, against this pixel's
        // surface: within the thickness behind it, the ray met the surface.
        const L behindBy = minOf((sampleAt<L>)(u, ray, j).w, sn.w) - surfaceN;
        const MaskOf<L> hit = crossed & (behindBy < thickness);
        m.hitIndex = select(hit, sn.index, m.hitIndex);
        m.hitX = select(hit, sn.pixelX, m.hitX);
        m.hitY = select(hit, sn.pixelY, m.hitY);
        m.result = select(hit, (ssrResultLane<L>)(SsrResult::Hit), select(crossed, (ssrResultLane<L>)(SsrResult::Behind), m.result));
        live = live & !crossed;
        (ssrRecordWhere<L>)(log, hit, SsrStepKind::Hit, sn.pixelX, sn.pixelY, sn.w, surfaceN, zero, n);
        (ssrRecordWhere<L>)(log, crossed & !hit, SsrStepKind::Behind, sn.pixelX, sn.pixelY, sn.w, surfaceN, zero, n);
      }
      (ssrRecordWhere<L>)(log, inFront, SsrStepKind::InFront, sn.pixelX, sn.pixelY, sn.w, surfaceN, zero, n);
      j = select(inFront, n, j);
      const MaskOf<L> up = inFront & (topLevel > zero) & !(n < blockedUntil);
      level = select(up, one, level);
      cellSize = select(up, two, cellSize);
    }
    if (anyOf(atCell)) {
      // The cell holding sample n, its pixel bounds and the ray's last sample inside it.
      const SsrCellL<L> c = (cellOf<L>)(u, ray, sn.pixelX, sn.pixelY, cellSize);
      const L& last = c.last;
      // Rounding may put the computed last sample a pixel out: then the cell is not used.
      const SsrSampleL<L> sl = (sampleAt<L>)(u, ray, last);
      const MaskOf<L> fits = atCell & (last >= n) & sl.onScreen & (sl.pixelX >= c.left) & (sl.pixelX < c.right) &
                             (sl.pixelY >= c.bottom) & (sl.pixelY < c.top);
      const L cellIndex = lookupLanes(u.hizOffset.data(), select(atCell, level, zero)) + c.y * c.levelWidth + c.x;
      const L cellLeast = lookupLanes(u.hizCells, select(fits, cellIndex, zero));
      const MaskOf<L> skip = fits & (maxOf(sn.w, sl.w) < cellLeast);
      const MaskOf<L> down = atCell & !skip;
      const MaskOf<L> climb = skip & (level < topLevel);
      const L cellRecorded = select(fits, cellLeast, zero);
      (ssrRecordWhere<L>)(log, skip, SsrStepKind::CellSkipped, sn.pixelX, sn.pixelY, maxOf(sn.w, sl.w), cellRecorded, level, last);
      (ssrRecordWhere<L>)(log, down, SsrStepKind::CellDescend, sn.pixelX, sn.pixelY, maxOf(sn.w, sl.w), cellRecorded, level, n);
      j = select(skip, last, j);
      m.level = select(skip, maxOf(m.level, level), m.level);
      blockedUntil = select(fits & !skip & (level == one), last, blockedUntil);
      level = select(climb, level + one, select(down, level - one, level));
      cellSize = select(climb, cellSize * two, select(down, cellSize * half, cellSize));
    }
  }
  return m;
}

// The cosine and sine of a turn in [0, 1) (ssr.frag's circle): written out, not the library's
// or GLSL's own, which round differently, so both renderers turn a ray alike. The quadrant
// (exact: 4 turn and its fraction are exact in a float), then Taylor series of the angle in
// [0, pi/2) to the 11th and 12th powers, in Horner form (error below 1e-7).
template <typename L>
TWR_LANE_INLINE Vec2L<L> circle(const L& turn) {
  using S = ScalarOf<L>;
  const L zero(S(0)), one(S(1));
  const L q4 = turn * L(S(4));
  const L quadrant = floorOf(q4);
  const L a = (q4 - quadrant) * L(S(1.57079637f));  // radians
  const L a2 = a * a;
  const L sinA =
      a * (one + a2 * (L(S(-0.166666672f)) +
                       a2 * (L(S(0.00833333377f)) +
                             a2 * (L(S(-0.000198412701f)) + a2 * (L(S(2.75573188e-06f)) + a2 * L(S(-2.50521079e-08f)))))));
  const L cosA =
      one + a2 * (L(S(-0.5f)) +
                  a2 * (L(S(0.0416666679f)) +
                        a2 * (L(S(-0.00138888892f)) +
                              a2 * (L(S(2.48015876e-05f)) + a2 * (L(S(-2.755732e-07f)) + a2 * L(S(2.08767559e-09f)))))));
  const MaskOf<L> q0 = quadrant == zero, q1 = quadrant == one, q2 = quadrant == L(S(2));
  const L c = select(q0, cosA, select(q1, zero - sinA, select(q2, zero - cosA, sinA)));
  const L s = select(q0, sinA, select(q1, cosA, select(q2, zero - sinA, zero - cosA)));
  return Vec2L<L>(c, s);
}

// A direction over the hemisphere of the unit normal n (ssr.frag's hemisphere): xi.x picks the
// height z (uniform: z = xi.x; cosine-weighted: z = sqrt(1 - xi.x)), xi.y the turn about n; the
// local direction is set in Duff et al.'s basis of n ("Building an Orthonormal Basis,
// Revisited", JCGT 2017: s = sign of n.z, a = -1 / (s + n.z), b = n.x n.y a,
// b1 = (1 + s n.x^2 a, s b, -s n.x), b2 = (b, s + n.y^2 a, -n.y); s + n.z never cancels).
// `weight` is the sample's share of the diffuse light, f cos / pdf with f = albedo / pi taken
// out as the albedo: uniform (pdf 1 / 2pi) 2 z, cosine (pdf z / pi) 1.
template <typename L>
TWR_LANE_INLINE Vec3L<L> hemisphere(const SsrUniformsT<ScalarOf<L>>& u, const Vec3L<L>& n,
                                    const Vec2L<L>& xi, L& weight) {
  using S = ScalarOf<L>;
  const L zero(S(0)), one(S(1)), two(S(2));
  const L sign = select(n.z >= zero, one, L(S(-1)));
  const L a = L(S(-1)) / (sign + n.z);
  const L b = n.x * n.y * a;
  const Vec3L<L> b1(one + sign * n.x * n.x * a, sign * b, zero - sign * n.x);
  const Vec3L<L> b2(b, sign + n.y * n.y * a, zero - n.y);
  const Vec2L<L> turn = (circle<L>)(xi.y);
  L z, r;
  if (u.distribution == SampleDistribution::Cosine) {
    r = sqrtOf(xi.x);
    z = sqrtOf(maxOf(zero, one - xi.x));
    weight = one;
  } else {
    z = xi.x;
    r = sqrtOf(maxOf(zero, one - z * z));
    weight = two * z;
  }
  return safeNormalize<L>(b1 * (r * turn.x) + b2 * (r * turn.y) + n * z);
}

// The lit frame's colour at an element.
template <typename L>
TWR_LANE_INLINE Vec3L<L> ssrLitAt(const SsrUniformsT<ScalarOf<L>>& u, const L& index) {
  return Vec3L<L>(lookupLanes(u.colour[0], index), lookupLanes(u.colour[1], index), lookupLanes(u.colour[2], index));
}

// The march the settings name.
template <typename L>
TWR_LANE_INLINE SsrMarchL<L> marchOf(const SsrUniformsT<ScalarOf<L>>& u, const Vec3L<L>& origin,
                                     const Vec3L<L>& dir, const MaskOf<L>& active,
                                     std::vector<SsrMarchStep>* log = nullptr) {
  const bool screen = u.march == SsrMarch::DdaScreen || u.march == SsrMarch::Hiz;
  return screen ? (screenMarch<L>)(u, origin, dir, active, log)
                : (march<L>)(u, origin, dir, active, log);
}

// Indirect diffuse light (ssr.frag's indirect; the write-up's EvalIndirectionLight): for each
// of the pixel's samples a hemisphere direction, marched; where it hits, the lit colour there is
// light the surface receives, weighted as its sample's pdf asks. Returns (1 / N) sum weight
// lit(hit), the light still to be multiplied by the albedo, and the samples that hit.
template <typename L>
struct SsrIndirectL {
  Vec3L<L> light;
  L hits;
};
template <typename L>
TWR_LANE_INLINE SsrIndirectL<L> indirect(const SsrUniformsT<ScalarOf<L>>& u, const Vec3L<L>& nl,
                                         const Vec3L<L>& posWorld, const Vec2L<L>* samples,
                                         const MaskOf<L>& active) {
  using S = ScalarOf<L>;
  const L zero(S(0)), one(S(1));
  Vec3L<L> sum(zero);
  L hits = zero;
  for (int k = 0; k < u.indirectSamples; ++k) {
    L weight = zero;
    const Vec3L<L> dir = (hemisphere<L>)(u, nl, samples[k], weight);
    const SsrMarchL<L> m = (marchOf<L>)(u, posWorld, dir, active);
    const MaskOf<L> hit = m.result == (ssrResultLane<L>)(SsrResult::Hit);
    if (!anyOf(hit)) continue;
    const Vec3L<L> lit = (ssrLitAt<L>)(u, select(hit, m.hitIndex, zero));
    sum = select3<L>(hit, sum + lit * weight, sum);
    hits = select(hit, hits + one, hits);
  }
  return SsrIndirectL<L>{sum * L(u.indirectScale), hits};
}

// A debug view's colour for a march (ssr.frag's viewColour; isSsrView says what each shows).
template <typename L>
TWR_LANE_INLINE Vec3L<L> viewColour(const SsrUniformsT<ScalarOf<L>>& u, const SsrMarchL<L>& m) {
  using S = ScalarOf<L>;
  const L zero(S(0)), half(S(0.5));
  const MaskOf<L> hit = m.result == (ssrResultLane<L>)(SsrResult::Hit);
  switch (u.view) {
    case View::SsrHit: {
      // hit green, miss blue, off screen yellow, behind red, not marched black
      const MaskOf<L> miss = m.result == (ssrResultLane<L>)(SsrResult::Miss);
      const MaskOf<L> off = m.result == (ssrResultLane<L>)(SsrResult::OffScreen);
      const MaskOf<L> behind = m.result == (ssrResultLane<L>)(SsrResult::Behind);
      const Vec3L<L> black(zero);
      return select3<L>(hit, Vec3L<L>(L(S(0.2f)), L(S(0.85f)), L(S(0.2f))),
                        select3<L>(miss, Vec3L<L>(L(S(0.15f)), L(S(0.3f)), L(S(0.9f))),
                                   select3<L>(off, Vec3L<L>(L(S(0.95f)), L(S(0.85f)), L(S(0.1f))),
                                              select3<L>(behind, Vec3L<L>(L(S(0.9f)), L(S(0.15f)), L(S(0.15f))), black))));
    }
    case View::SsrSteps: {
      const Vec4L<L> heat = (heatColour<L>)(m.steps / L(static_cast<S>(u.maxSteps)));
      return Vec3L<L>(heat.x, heat.y, heat.z);
    }
    case View::SsrUv: {
      const L x = (m.hitX + half) / L(u.viewportSize.x), y = (m.hitY + half) / L(u.viewportSize.y);
      return select3<L>(hit, Vec3L<L>(x, y, zero), Vec3L<L>(zero));
    }
    default: {  // hiz_level
      if (u.hizLevels == 0) return Vec3L<L>(zero);
      const Vec4L<L> heat = (heatColour<L>)(m.level / L(static_cast<S>(u.hizLevels)));
      return Vec3L<L>(heat.x, heat.y, heat.z);
    }
  }
}

// One pixel's pass (ssr.frag's main): the G-buffer's lighting normal, position, ssr_reflect
// and albedo, the pixel's own lit colour, its indirect samples' random pairs
// (ssrRandomPairOf). The mirror direction of the eye's, marched where ssr_reflect > 0; on a
// hit, the lit colour there times reflect_strength ssr_reflect is added. With indirect
// samples, albedo times the indirect light is added too. The sum is clamped. Returns the
// mirror march, whether the colour changed (a mirror hit or an indirect sample's) and, in
// `colour`, the pixel's new colour (its own where nothing changed).
template <typename L>
struct SsrPixelL {
  SsrMarchL<L> mirror;
  L indirectHits;
  MaskOf<L> changed;
};
template <typename L>
TWR_LANE_INLINE SsrPixelL<L> ssrPixel(const SsrUniformsT<ScalarOf<L>>& u, const Vec3L<L>& nl,
                                      const Vec3L<L>& posWorld, const L& ssrReflect, const Vec3L<L>& albedo,
                                      const Vec2L<L>* samples, const MaskOf<L>& drawn, Vec3L<L>& colour) {
  using S = ScalarOf<L>;
  const L zero(S(0)), two(S(2));
  const Vec3L<L> wo = safeNormalize<L>(Vec3L<L>(u.eyePosWorld) - posWorld);
  const Vec3L<L> r = safeNormalize<L>((two * dot3<L>(nl, wo)) * nl - wo);
  const MaskOf<L> reflects = drawn & (ssrReflect > zero);
  const MaskOf<L> none = zero > zero;
  SsrPixelL<L> p{{(ssrResultLane<L>)(SsrResult::NotMarched), zero, zero, zero, zero, zero}, zero, none};
  if (isSsrView(u.view)) {
    // A debug view: every drawn pixel's mirror ray, its march's value in place of the colour.
    p.mirror = (marchOf<L>)(u, posWorld, r, drawn);
    p.changed = drawn;
    colour = select3<L>(drawn, (viewColour<L>)(u, p.mirror), colour);
    return p;
  }
  Vec3L<L> total = colour;
  if (anyOf(reflects)) {
    p.mirror = (marchOf<L>)(u, posWorld, r, reflects);
    const MaskOf<L> hit = p.mirror.result == (ssrResultLane<L>)(SsrResult::Hit);
    if (anyOf(hit)) {
      const Vec3L<L> reflected = (ssrLitAt<L>)(u, select(hit, p.mirror.hitIndex, zero));
      const L k = L(u.reflectStrength) * ssrReflect;
      total = select3<L>(hit, total + reflected * k, total);
      p.changed = hit;
    }
  }
  if (u.indirectSamples > 0 && anyOf(drawn)) {
    const SsrIndirectL<L> indirectLight = (indirect<L>)(u, nl, posWorld, samples, drawn);
    total = total + albedo * indirectLight.light;
    p.indirectHits = indirectLight.hits;
    p.changed = p.changed | (indirectLight.hits > zero);
  }
  if (anyOf(p.changed)) {
    const Vec4L<L> lit = clampUnit4<L>(Vec4L<L>(total, L(S(1))));
    colour = select3<L>(p.changed, Vec3L<L>(lit.x, lit.y, lit.z), colour);
  }
  return p;
}

TWR_LANES_END

#endif  // TWR_SSR_INL_EMIT
