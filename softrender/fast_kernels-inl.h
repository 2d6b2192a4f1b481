// The fast path's kernel bodies, once per Highway target (fast_kernels.h says what they do;
// fast_kernels.cpp re-includes this file through hwy/foreach_target.h and holds the dispatch).
// The shading itself is not here: the shared sources (softrender/*-inl.h) are included below
// into each target's namespace and instantiated with that target's LaneF. What is here is the
// fast path's own design: the visibility pass, the slot buffer, gathering a vector's
// triangles, tiled textures, and each kernel's loop over a bin.
//
// Highway's per-target include guard: the toggle flips on every pass, so each target's pass
// compiles the bodies once.
#if defined(TWR_FAST_KERNELS_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef TWR_FAST_KERNELS_INL_H_
#undef TWR_FAST_KERNELS_INL_H_
#else
#define TWR_FAST_KERNELS_INL_H_
#endif

#include <hwy/highway.h>

#include "scene/errors.h"
#include "softrender/cpu_isa_targets.h"
#include "softrender/deferred.h"
#include "softrender/fast_kernels.h"
#include "softrender/raster.h"
#include "softrender/shade.h"
#include "softrender/ssr.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <limits>
#include <type_traits>
#include <utility>

// The shared sources for this target: in twr::HWY_NAMESPACE, with its attributes.
#include "softrender/lanes_target_begin.h"

#include "softrender/lanes_hwy-inl.h"
#include "softrender/lane_math-inl.h"
#include "softrender/texel_lanes-inl.h"

HWY_BEFORE_NAMESPACE();
namespace twr {
namespace HWY_NAMESPACE {

// Most lanes a vector has on any target (AVX-512: 16 floats), for stack buffers.
// (Unused in the objects that leave this target's kernels to another: clang says so.)
[[maybe_unused]] constexpr std::size_t kMaxLanes = HWY_MAX_BYTES / sizeof(float);

// ---- a TiledTexture as texture_sample-inl.h reads it ----
HWY_INLINE int texLevelCount(const TiledTexture& t) { return static_cast<int>(t.levels.size()); }
HWY_INLINE int texLevelWidth(const TiledTexture& t, int level) { return t.levels[static_cast<std::size_t>(level)].width; }
HWY_INLINE int texLevelHeight(const TiledTexture& t, int level) { return t.levels[static_cast<std::size_t>(level)].height; }
HWY_INLINE TextureWrap texWrap(const TiledTexture& t) { return t.wrap; }
HWY_INLINE bool texSrgb(const TiledTexture& t) { return t.srgb; }

// The texel words of each lane from the tiled index
// ((y / 4) blocksPerRow + x / 4) 16 + (y % 4) 4 + x % 4.
HWY_INLINE auto tiledWords(const std::vector<TexelBlock>& blocks, int blocksPerRow, LaneI x, LaneI y) {
  const DI di;
  const auto three = hn::Set(di, kTexelBlockSide - 1);
  const auto row = hn::Add(hn::Mul(hn::ShiftRight<2>(y.v), hn::Set(di, blocksPerRow * kTexelBlockSide * kTexelBlockSide)),
                           hn::ShiftLeft<2>(hn::And(y.v, three)));
  const auto column = hn::Add(hn::ShiftLeft<4>(hn::ShiftRight<2>(x.v)), hn::And(x.v, three));
  return hn::BitCast(DU(), hn::GatherIndex(di, reinterpret_cast<const std::int32_t*>(blocks.data()), hn::Add(row, column)));
}
HWY_INLINE auto tiledTexelWords(const TiledTexture& t, int levelIndex, LaneI x, LaneI y) {
  const TiledLevel& level = t.levels[static_cast<std::size_t>(levelIndex)];
  return tiledWords(level.blocks, level.blocksPerRow, x, y);
}
// Byte `Shift / 8` of each word, as float lanes. On the vector targets a byte shuffle moves it
// to the word's low byte and zeroes the rest: one shuffle instead of a shift and a mask, which
// x86 runs on the port the float arithmetic needs (a 512-bit shift on port 0 alone).
template <int Shift, typename Words>
HWY_INLINE LaneF wordByte(Words words) {
#if HWY_TARGET == HWY_SCALAR
  const auto bytes = hn::And(hn::ShiftRight<Shift>(words), hn::Set(DU(), 0xFFu));
#else
  static_assert(Shift % 8 == 0 && Shift < 32);
  constexpr std::uint8_t b = Shift / 8, z = 0x80;  // z: a zero byte
  // The word of lane i is bytes 4 (i % 4) to 4 (i % 4) + 3 of its 16-byte block.
  alignas(16) static constexpr std::uint8_t kIndices[16] = {b,     z, z, z, b + 4,  z, z, z,
                                                            b + 8, z, z, z, b + 12, z, z, z};
  const hn::Repartition<std::uint8_t, DU> d8;
  const auto bytes =
      hn::BitCast(DU(), hn::TableLookupBytesOr0(hn::BitCast(d8, words), hn::LoadDup128(d8, kIndices)));
#endif
  return LaneF(hn::ConvertTo(DF(), hn::BitCast(DI(), bytes)));
}
template <typename L>
HWY_INLINE Vec4L<LaneF> fetchTexelBytes(const TiledTexture& t, int levelIndex, LaneI x, LaneI y) {
  static_assert(std::is_same_v<L, LaneF>);
  const auto words = tiledTexelWords(t, levelIndex, x, y);
  return Vec4L<LaneF>(wordByte<0>(words), wordByte<8>(words), wordByte<16>(words), wordByte<24>(words));
}
template <typename L>
HWY_INLINE LaneF fetchTexelRedByte(const TiledTexture& t, int levelIndex, LaneI x, LaneI y) {
  static_assert(std::is_same_v<L, LaneF>);
  return wordByte<0>(tiledTexelWords(t, levelIndex, x, y));
}

// The four red bytes of a bilinear footprint: one gather from the footprint words where the
// texture has them (a height map), four from the tiled texels otherwise. x1 is x0 or the next
// texel (wrapped), y1 likewise (texture_sample-inl.h's linearAxis).
template <typename L>
HWY_INLINE Vec4L<LaneF> fetchRedFootprintBytes(const TiledTexture& t, int levelIndex, LaneI x0, LaneI x1, LaneI y0,
                                               LaneI y1) {
  static_assert(std::is_same_v<L, LaneF>);
  if (t.redFootprints.empty()) {
    return Vec4L<LaneF>(fetchTexelRedByte<L>(t, levelIndex, x0, y0), fetchTexelRedByte<L>(t, levelIndex, x1, y0),
                        fetchTexelRedByte<L>(t, levelIndex, x0, y1), fetchTexelRedByte<L>(t, levelIndex, x1, y1));
  }
  const RedFootprintLevel& level = t.redFootprints[static_cast<std::size_t>(levelIndex)];
  const auto words = tiledWords(level.blocks, level.blocksPerRow, x0, y0);
  const LaneF b00 = wordByte<0>(words), b10 = wordByte<8>(words), b01 = wordByte<16>(words), b11 = wordByte<24>(words);
  // Repeat reads exactly the word's footprint (on a side of one texel, x1 = x0 = 0, and so is
  // the word's neighbour).
  if (t.wrap == TextureWrap::Repeat) return Vec4L<LaneF>(b00, b10, b01, b11);
  // Where a clamped or mirrored read stays on its texel (x1 == x0), it takes the word's own
  // column again; likewise for rows.
  const auto sameX = hn::RebindMask(DF(), hn::Eq(x1.v, x0.v));
  const auto sameY = hn::RebindMask(DF(), hn::Eq(y1.v, y0.v));
  const LaneF t10(hn::IfThenElse(sameX, b00.v, b10.v));
  const LaneF t01(hn::IfThenElse(sameY, b00.v, b01.v));
  const LaneF t11(hn::IfThenElse(sameX, t01.v, hn::IfThenElse(sameY, t10.v, b11.v)));
  return Vec4L<LaneF>(b00, t10, t01, t11);
}

// The sRGB decode of byte values, from texture_sample.h's table (doubles rounded to float).
HWY_INLINE LaneF linearFromSrgbByte(LaneF byte) {
  static const std::array<float, 256> table = [] {
    std::array<float, 256> t{};
    for (std::size_t c = 0; c < t.size(); ++c) t[c] = static_cast<float>(srgbDecodeTable()[c]);
    return t;
  }();
  return {hn::GatherIndex(DF(), table.data(), hn::ConvertTo(DI(), byte.v))};
}

}  // namespace HWY_NAMESPACE
}  // namespace twr
HWY_AFTER_NAMESPACE();

#include "softrender/output_merge-inl.h"
#include "softrender/shade-inl.h"
#include "softrender/deferred-inl.h"
#include "softrender/ssr-inl.h"
#include "softrender/vertex_stage-inl.h"

#if defined(TWR_FAST_KERNEL_TARGETS) && (HWY_TARGET & (TWR_FAST_KERNEL_TARGETS)) && (HWY_TARGET & (TWR_KERNEL_TARGETS))
HWY_BEFORE_NAMESPACE();
namespace twr {
namespace HWY_NAMESPACE {
namespace {

// Lanes [0, count) on, the rest off.
HWY_INLINE LaneMask firstLanes(std::size_t count) { return {hn::FirstN(DF(), count)}; }
// The lanes whose bit is set in `bits` (bit l = lane l: a little-endian word's bytes are
// Highway's mask bytes in order).
static_assert(std::endian::native == std::endian::little);
HWY_INLINE LaneMask lanesOf(std::uint64_t bits) {
  std::uint8_t bytes[sizeof bits];
  std::memcpy(bytes, &bits, sizeof bits);
  return {hn::LoadMaskBits(DF(), bytes)};
}
// The bits of a mask's lanes (bit l = lane l), lanesOf's inverse.
HWY_INLINE std::uint64_t bitsOf(hn::Mask<DU> mask) {
  std::uint8_t bytes[sizeof(std::uint64_t)] = {};
  hn::StoreMaskBits(DU(), mask, bytes);
  std::uint64_t bits = 0;
  std::memcpy(&bits, bytes, sizeof bits);
  return bits;
}
// The lanes of `lanes` (bits) whose word in `words` (one per lane) equals `value`.
HWY_INLINE std::uint64_t lanesHolding(const std::uint32_t* words, std::uint32_t value, std::uint64_t lanes) {
  return lanes & bitsOf(hn::Eq(hn::LoadU(DU(), words), hn::Set(DU(), value)));
}
// 0, 1, 2, ... per lane, loaded from a constant (Highway's Iota stores the lanes one by one and
// loads them back as a vector, a load the store buffer cannot forward; 3.5 % of the AVX2
// kernel's samples sat on it when the pixel columns were made with it).
HWY_INLINE hn::Vec<DI> laneIndices() {
  HWY_ALIGN static constexpr std::array<std::int32_t, kMaxLanes> kIndices = [] {
    std::array<std::int32_t, kMaxLanes> indices{};
    for (std::size_t l = 0; l < kMaxLanes; ++l) indices[l] = static_cast<std::int32_t>(l);
    return indices;
  }();
  return hn::Load(DI(), kIndices.data());
}
// x, x + 1, ... as float lanes (pixel indices are exact in float).
HWY_INLINE LaneF pixelColumnsF(int x) {
  return LaneF(hn::Add(hn::Set(DF(), static_cast<float>(x)), hn::ConvertTo(DF(), laneIndices())));
}

HWY_INLINE AttributePlaneL<LaneF> broadcastPlane(const AttributePlaneT<float>& p) {
  return {LaneF(p.atOrigin), LaneF(p.dx), LaneF(p.dy)};
}

// ---- pass 1: visibility ----
std::uint64_t Visibility(const TriangleSetup& setup, const std::array<WindowVertex, 3>& window, std::uint32_t slot,
                         int rowBegin, int rowEnd, Framebuffer& fb, std::uint32_t* slots, bool& covered) {
  const int yFirst = std::max(setup.y0, rowBegin);
  const int yLast = std::min(setup.y1, rowEnd - 1);
  if (yFirst > yLast || setup.x0 > setup.x1) return 0;
  const DF df;
  const DU du;
  const std::size_t lanes = laneCount();
  const std::size_t width = static_cast<std::size_t>(fb.width);
  AttributePlaneL<LaneF> plane{};  // set on the first covered row (zeroed: GCC 12 for aarch64 cannot see that)
  const auto slotLanes = hn::Set(du, slot);
  std::uint64_t passed = 0;
  for (int py = yFirst; py <= yLast; ++py) {
    const Span span = coveredSpan(setup, py);
    if (span.xBegin >= span.xEnd) continue;
    if (!covered) {
      covered = true;
      plane = broadcastPlane(makeDepthPlane<float>(window, setup));
    }
    const LaneF pyF(static_cast<float>(py));
    float* depthRow = &fb.depth[fb.index(0, py)];
    std::uint32_t* slotRow = slots + static_cast<std::size_t>(py - rowBegin) * width;
    for (int x = span.xBegin; x < span.xEnd; x += static_cast<int>(lanes)) {
      const std::size_t count = std::min(lanes, static_cast<std::size_t>(span.xEnd - x));
      const LaneF depth = (depthAsStored<LaneF>)(planeAt<LaneF>(plane, pixelColumnsF(x), pyF), fb.depthFormat);
      // GL_LESS against the stored depth; a vector past the row's end goes through a buffer.
      HWY_ALIGN float depthBuffer[kMaxLanes];
      HWY_ALIGN std::uint32_t slotBuffer[kMaxLanes];
      const bool whole = count == lanes;
      float* depthAt = whole ? depthRow + x : depthBuffer;
      std::uint32_t* slotAt = whole ? slotRow + x : slotBuffer;
      if (!whole) {
        std::memcpy(depthBuffer, depthRow + x, count * sizeof(float));
        std::memcpy(slotBuffer, slotRow + x, count * sizeof(std::uint32_t));
      }
      const LaneMask pass = firstLanes(count) & (depth < LaneF(hn::LoadU(df, depthAt)));
      if (!anyOf(pass)) continue;
      hn::BlendedStore(depth.v, pass.m, df, depthAt);
      hn::BlendedStore(slotLanes, hn::RebindMask(du, pass.m), du, slotAt);
      if (!whole) {
        std::memcpy(depthRow + x, depthBuffer, count * sizeof(float));
        std::memcpy(slotRow + x, slotBuffer, count * sizeof(std::uint32_t));
      }
      passed += hn::CountTrue(df, pass.m);
    }
  }
  return passed;
}

// ---- pass 2: shading ----
// One draw item's lanes of a row segment starting at pixel (x, py).
struct Segment {
  const std::vector<BinTriangle>* triangles;
  const std::uint64_t* exactSumPlanes;  // per triangle, or null (fast_kernels.h)
  const std::uint32_t* slots;  // per lane (kNoSlot for lanes of no triangle)
  // Per lane, the depth buffer's value: where a triangle holds the pixel, the visibility pass
  // stored its depth plane there (storedDepth), so the fragment's depth is read, not evaluated.
  const float* depths;
  std::uint64_t bits;          // this item's lanes
  int x, py;
};

// Every lane on one triangle: its planes broadcast, written in place (the planes are 4 KB, and
// only `count` of them are in use).
HWY_INLINE void broadcastVaryingPlanes(const VaryingPlanesT<float>& t, VaryingPlanesL<LaneF>& p) {
  p.count = t.count;
  p.oneOverW = broadcastPlane(t.oneOverW);
  for (int k = 0; k < t.count; ++k) p.overW[static_cast<std::size_t>(k)] = broadcastPlane(t.overW[static_cast<std::size_t>(k)]);
}

// The triangles a segment's lanes lie on, when there are few: each one's slot and lanes (the
// first is the first lane's); `few` false when there are more than kMaxBlendedTriangles.
// A few are blended into vectors plane by plane, more are transposed through memory, a scalar
// store per plane coefficient and lane. Up to 8 (AVX2's lanes: it never transposes) blending
// is the cheaper: on AVX-512, the default frame on two threads took 7.27 ms with 4, 7.21 with 8
// (bench_frame, five alternated rounds), and no less with 16.
inline constexpr int kMaxBlendedTriangles = 8;
struct SegmentTriangles {
  std::uint32_t slots[kMaxBlendedTriangles];
  std::uint64_t bits[kMaxBlendedTriangles];
  int count = 0;
  bool few = true;
};
HWY_INLINE SegmentTriangles segmentTriangles(const Segment& s) {
  SegmentTriangles d;
  for (std::uint64_t remaining = s.bits; remaining != 0;) {
    if (d.count == kMaxBlendedTriangles) {
      d.few = false;
      return d;
    }
    const std::uint32_t slot = s.slots[__builtin_ctzll(remaining)];
    d.slots[d.count] = slot;
    d.bits[d.count] = lanesHolding(s.slots, slot, remaining);
    remaining &= ~d.bits[d.count];
    ++d.count;
  }
  return d;
}
HWY_INLINE void blendPlane(const LaneMask& mask, const AttributePlaneT<float>& t, AttributePlaneL<LaneF>& p) {
  p.atOrigin = select(mask, LaneF(t.atOrigin), p.atOrigin);
  p.dx = select(mask, LaneF(t.dx), p.dx);
  p.dy = select(mask, LaneF(t.dy), p.dy);
}

// The planes of a segment's lanes on a few triangles: the first triangle's in every lane (it
// stands in for lanes of other items, so every lane computes with sane numbers; the mask
// discards their results), each other triangle's blended into its lanes.
HWY_INLINE void blendedPlanes(const std::vector<BinTriangle>& triangles, [[maybe_unused]] const std::uint64_t* exactSumPlanes,
                              const SegmentTriangles& distinct, VaryingPlanesL<LaneF>& planes) {
  const BinTriangle& first = triangles[distinct.slots[0]];
  broadcastVaryingPlanes(first.varyings, planes);
  for (int j = 1; j < distinct.count; ++j) {
    const BinTriangle& t = triangles[distinct.slots[j]];
    const LaneMask mask = lanesOf(distinct.bits[j]);
    blendPlane(mask, t.varyings.oneOverW, planes.oneOverW);
    for (int k = 0; k < planes.count; ++k) {
      blendPlane(mask, t.varyings.overW[static_cast<std::size_t>(k)], planes.overW[static_cast<std::size_t>(k)]);
    }
  }
#if !HWY_NATIVE_FMA
  std::uint64_t exactSums = 0;
  if (exactSumPlanes) {
    exactSums = ~std::uint64_t{0};
    for (int j = 0; j < distinct.count; ++j) exactSums &= exactSumPlanes[distinct.slots[j]];
  }
  // A plane takes planeAt's short way where it does on every triangle of the segment.
  const auto exact = [&](int bit) { return ((exactSums >> bit) & 1u) != 0; };
  planes.oneOverW.sumsExactInDouble = exact(kExactSumOneOverWBit);
  for (int k = 0; k < planes.count; ++k) {
    planes.overW[static_cast<std::size_t>(k)].sumsExactInDouble = exact(kExactSumFirstVaryingBit + k);
  }
#endif
}

// The same for lanes on many triangles: each plane transposed into columns through memory,
// [plane][atOrigin, dx, dy][lane]; plane 0 is 1/w, 1 + k varying k.
HWY_INLINE void transposedPlanes(const Segment& s, int count, VaryingPlanesL<LaneF>& planes) {
  const DF df;
  const std::vector<BinTriangle>& triangles = *s.triangles;
  const std::uint32_t firstSlot = s.slots[__builtin_ctzll(s.bits)];
  constexpr int kOneOverWColumn = 0, kFirstVaryingColumn = 1;
  HWY_ALIGN float columns[kFirstVaryingColumn + kMaxVaryings][3][kMaxLanes];
  for (std::size_t l = 0; l < laneCount(); ++l) {
    const BinTriangle& t = triangles[((s.bits >> l) & 1u) != 0 ? s.slots[l] : firstSlot];
    const auto put = [&](int column, const AttributePlaneT<float>& p) {
      columns[column][0][l] = p.atOrigin;
      columns[column][1][l] = p.dx;
      columns[column][2][l] = p.dy;
    };
    put(kOneOverWColumn, t.varyings.oneOverW);
    for (int k = 0; k < count; ++k) put(kFirstVaryingColumn + k, t.varyings.overW[static_cast<std::size_t>(k)]);
  }
  const auto planeOfColumn = [&](int column) HWY_ATTR {
    return AttributePlaneL<LaneF>{LaneF(hn::Load(df, columns[column][0])), LaneF(hn::Load(df, columns[column][1])),
                                  LaneF(hn::Load(df, columns[column][2]))};
  };
  planes.oneOverW = planeOfColumn(kOneOverWColumn);
  planes.count = count;
  for (int k = 0; k < count; ++k) planes.overW[static_cast<std::size_t>(k)] = planeOfColumn(kFirstVaryingColumn + k);
}

#if HWY_TARGET != HWY_SCALAR
// The quad and fine uv differences (interpolate-inl.h) of a segment whose lanes all lie on one
// triangle: its lanes are side by side from an even column, so a quad's left and right pixels
// are neighbouring lanes. The segment's row and the quad's other row are evaluated once each
// (two divisions instead of seven); the rest is lanes duplicated from them, the same bits as
// evaluating each neighbour on that triangle's planes.
HWY_INLINE void setUvDifferencesOfOneTriangle(const UvPlanesL<LaneF>& uv, LaneF px, int py, bool fine,
                                              FragmentL<LaneF>& f) {
  const bool evenRow = (py & 1) == 0;
  const Vec2L<LaneF> own = uvAtPixel<LaneF>(uv, px, LaneF(static_cast<float>(py)));
  const Vec2L<LaneF> other = uvAtPixel<LaneF>(uv, px, LaneF(static_cast<float>(evenRow ? py + 1 : py - 1)));
  const Vec2L<LaneF>& lower = evenRow ? own : other;  // the quad's rows (GL rows: the even one is lower)
  const Vec2L<LaneF>& upper = evenRow ? other : own;
  const auto even = [](const Vec2L<LaneF>& v) HWY_ATTR {
    return Vec2L<LaneF>(LaneF(hn::DupEven(v.x.v)), LaneF(hn::DupEven(v.y.v)));
  };
  const auto odd = [](const Vec2L<LaneF>& v) HWY_ATTR {
    return Vec2L<LaneF>(LaneF(hn::DupOdd(v.x.v)), LaneF(hn::DupOdd(v.y.v)));
  };
  const Vec2L<LaneF> topLeft = even(lower);
  f.uvDx = odd(lower) - topLeft;
  f.uvDy = even(upper) - topLeft;
  if (fine) {
    f.uvDxFine = odd(own) - even(own);
    f.uvDyFine = upper - lower;
  }
}
#endif

// The fragments of a segment's lanes: their triangles' planes (broadcast when all lanes share
// one, gathered lane by lane otherwise) evaluated at the lanes' pixels, with the quad
// differences the permutation reads.
// The fragments of a segment's lanes: their triangles' planes (broadcast when all lanes share
// one, gathered lane by lane otherwise) evaluated at the lanes' pixels, with the quad
// differences the permutation reads.
template <typename Features>
HWY_INLINE FragmentL<LaneF> SegmentFragment(const Segment& s, const ItemState& item, const ItemMaps& maps) {
  const bool tangent = Features::kSpace == LightingSpace::Tangent;
  const int lightCount = item.shade.lightCount;
  const std::vector<BinTriangle>& triangles = *s.triangles;

  const SegmentTriangles distinct = segmentTriangles(s);
  [[maybe_unused]] const bool oneTriangle = distinct.few && distinct.count == 1;  // (the scalar target has one lane)
  VaryingPlanesL<LaneF> planes;
  if (distinct.few) {
    blendedPlanes(triangles, s.exactSumPlanes, distinct, planes);
  } else {
    transposedPlanes(s, varyingCount(tangent, lightCount), planes);
  }

  const LaneF px = pixelColumnsF(s.x), py(static_cast<float>(s.py));
  const LaneF depth(hn::Load(DF(), s.depths));
  FragmentL<LaneF> fragment = interpolateFragment<LaneF>(planes, px, py, depth);
  if (item.shade.needsQuadDifferences()) {
    // Each lane's 2x2 quad: the even column and row at or below it (exact in float).
    const UvPlanesL<LaneF> uv{planes.overW[kVaryingUv], planes.overW[kVaryingUv + 1], planes.oneOverW};
#if HWY_TARGET != HWY_SCALAR
    if (oneTriangle) {
      setUvDifferencesOfOneTriangle(uv, px, s.py, item.shade.heightMap != nullptr, fragment);
    } else
#endif
    {
      const LaneF quadColumns = floorOf(px * LaneF(0.5f)) * LaneF(2.0f);
      const LaneF quadRow(static_cast<float>(s.py - (s.py & 1)));
      setQuadUvDifferences<LaneF>(uv, quadColumns, quadRow, fragment);
      if (item.shade.heightMap) setFineUvDifferences<LaneF>(uv, quadColumns, quadRow, px, py, fragment);
    }
  }
  // A material that reads the environment, in a view that shows it: its directions' quad
  // differences (shade-inl.h).
  if (isShadedView(item.shade.view) && item.shade.environment.cube) {
    const LaneF quadColumns = floorOf(px * LaneF(0.5f)) * LaneF(2.0f);
    const LaneF quadRow(static_cast<float>(s.py - (s.py & 1)));
    setEnvironmentDifferences<Features, LaneF>(planes, px, py, quadColumns, quadRow, item.shade, maps, fragment);
  }
  return fragment;
}

// Output merge: each lane's colour as its RGBA8 word, alpha 255 (geometry drawn).
HWY_INLINE auto rgbaWordsOf(const Vec4L<LaneF>& colour) {
  const DI di;
  const DU du;
  const auto byteOf = [&](LaneF c) HWY_ATTR { return hn::BitCast(du, hn::ConvertTo(di, byteValueOf<LaneF>(c).v)); };
  return hn::Or(hn::Or(byteOf(colour.x), hn::ShiftLeft<8>(byteOf(colour.y))),
                hn::Or(hn::ShiftLeft<16>(byteOf(colour.z)), hn::Set(du, 0xFF000000u)));
}

template <typename Features>
void ShadeSegment(const Segment& s, const ItemState& item, const ItemMaps& maps, std::uint32_t* rgbaOut) {
  const FragmentL<LaneF> fragment = SegmentFragment<Features>(s, item, maps);
  const Vec4L<LaneF> colour =
      shadeFragment<Features, LaneF>(fragment, item.shade, maps, static_cast<std::nullptr_t*>(nullptr));

  hn::BlendedStore(rgbaWordsOf(colour), hn::RebindMask(DU(), lanesOf(s.bits).m), DU(), rgbaOut);
}

// The deferred pipeline's G-buffer pass for a segment: the surface (gbufferFragment) of
// this item's lanes into `channels` (deferred.h's targets in order, four floats of normal then
// three each of geometric, albedo, specular, emission and position, then the specular's w),
// the other lanes left as they were.
inline constexpr int kSurfaceChannels = 20;
inline constexpr int kPositionChannel = 16;  // the first of the position's three
inline constexpr int kSsrReflectChannel = 19;
template <typename Features>
void SurfaceSegment(const Segment& s, const ItemState& item, const ItemMaps& maps, float (*channels)[kMaxLanes]) {
  const DF df;
  const FragmentL<LaneF> fragment = SegmentFragment<Features>(s, item, maps);
  const GBufferTexelL<LaneF> g = gbufferFragment<Features, LaneF>(fragment, item.shade, maps);
  const LaneF values[kSurfaceChannels] = {g.nl.x,       g.nl.y,       g.nl.z,       g.shininess,
                                          g.n.x,        g.n.y,        g.n.z,        g.kdAlbedo.x,
                                          g.kdAlbedo.y, g.kdAlbedo.z, g.ksSpec.x,   g.ksSpec.y,
                                          g.ksSpec.z,   g.emission.x, g.emission.y, g.emission.z,
                                          g.posWorld.x, g.posWorld.y, g.posWorld.z, g.ssrReflect};
  const auto mask = lanesOf(s.bits).m;
  for (int c = 0; c < kSurfaceChannels; ++c) hn::BlendedStore(values[c].v, mask, df, channels[c]);
}

using SegmentKernel = void (*)(const Segment&, const ItemState&, const ItemMaps&, std::uint32_t*);

// The kernel of a shader permutation (withShaderFeatures, shade.h): one per combination of
// maps and lighting space, the view a branch inside it, as on the teaching path.
SegmentKernel kernelFor(const ShaderKey& key) {
  SegmentKernel kernel = nullptr;
  withShaderFeatures(key, [&]<typename Features>() { kernel = &ShadeSegment<Features>; });
  return kernel;
}
using SurfaceKernel = void (*)(const Segment&, const ItemState&, const ItemMaps&, float (*)[kMaxLanes]);
SurfaceKernel surfaceKernelFor(const ShaderKey& key) {
  SurfaceKernel kernel = nullptr;
  withShaderFeatures(key, [&]<typename Features>() { kernel = &SurfaceSegment<Features>; });
  return kernel;
}

// The first `count` lanes of an aligned buffer to `to`: a whole vector as one store (a
// variable-length memcpy compiles to `rep movs`, whose start-up costs more than the copy).
HWY_INLINE void copyLanes(const std::uint32_t* from, std::uint32_t* to, std::size_t count) {
  if (count == laneCount()) {
    hn::StoreU(hn::Load(DU(), from), DU(), to);
  } else {
    std::memcpy(to, from, count * sizeof(std::uint32_t));
  }
}

// `count` depths from `from` into an aligned buffer of a vector's lanes (those past `count`:
// the clear depth, a finite value no lane of the segment uses).
HWY_INLINE void loadDepthLanes(const float* from, float* to, std::size_t count) {
  if (count == laneCount()) {
    hn::Store(hn::LoadU(DF(), from), DF(), to);
  } else {
    std::fill(to, to + laneCount(), kClearDepth);
    std::memcpy(to, from, count * sizeof(float));
  }
}

// A row segment's lanes: each one's slot (kNoSlot past the row's end), and for the lanes a
// triangle holds, its draw item and triangle id (kNoTriangle elsewhere). Returns the bits of
// the lanes a triangle holds. The words are gathered from the bin's triangles by slot.
HWY_INLINE std::uint64_t segmentLanes(const std::vector<BinTriangle>& triangles, const std::uint32_t* rowSlots,
                                      std::size_t inRow, std::uint32_t* slotLanes, std::uint32_t* itemLanes,
                                      std::uint32_t* idLanes) {
  const DU du;
  const DI di;
  if (inRow == laneCount()) {
    hn::Store(hn::LoadU(du, rowSlots), du, slotLanes);
  } else {
    std::fill(slotLanes, slotLanes + laneCount(), kNoSlot);
    std::memcpy(slotLanes, rowSlots, inRow * sizeof(std::uint32_t));
  }
  const auto slots = hn::Load(du, slotLanes);
  const auto drawn = hn::Ne(slots, hn::Set(du, kNoSlot));
  const std::uint64_t bits = bitsOf(drawn);
  hn::Store(hn::Set(du, kNoTriangle), du, idLanes);
  if (bits == 0) return 0;
  // Every drawn lane on one triangle (the usual case): its words read once, not gathered.
  const std::uint32_t firstSlot = slotLanes[__builtin_ctzll(bits)];
  if (lanesHolding(slotLanes, firstSlot, bits) == bits) {
    const BinTriangle& t = triangles[firstSlot];
    hn::Store(hn::Set(du, t.item), du, itemLanes);
    hn::Store(hn::IfThenElse(drawn, hn::Set(du, t.triangleId), hn::Set(du, kNoTriangle)), du, idLanes);
    return bits;
  }
  static_assert(std::is_standard_layout_v<BinTriangle> && sizeof(BinTriangle) % sizeof(std::uint32_t) == 0);
  constexpr std::size_t kWords = sizeof(BinTriangle) / sizeof(std::uint32_t);
  if (triangles.size() > static_cast<std::size_t>(std::numeric_limits<std::int32_t>::max()) / kWords) {
    for (std::size_t l = 0; l < laneCount(); ++l) {  // word indices past int32: lane by lane
      if (((bits >> l) & 1u) == 0) continue;
      itemLanes[l] = triangles[slotLanes[l]].item;
      idLanes[l] = triangles[slotLanes[l]].triangleId;
    }
    return bits;
  }
  // Lanes of no triangle read slot 0's words (the bin has triangles) and keep kNoTriangle.
  const auto index = hn::BitCast(di, hn::Mul(hn::IfThenElseZero(drawn, slots), hn::Set(du, static_cast<std::uint32_t>(kWords))));
  const auto* base = reinterpret_cast<const std::int32_t*>(triangles.data());
  constexpr std::size_t kItemWord = offsetof(BinTriangle, item) / sizeof(std::uint32_t);
  constexpr std::size_t kIdWord = offsetof(BinTriangle, triangleId) / sizeof(std::uint32_t);
  hn::Store(hn::BitCast(du, hn::GatherIndex(di, base + kItemWord, index)), du, itemLanes);
  hn::Store(hn::IfThenElse(drawn, hn::BitCast(du, hn::GatherIndex(di, base + kIdWord, index)), hn::Set(du, kNoTriangle)),
            du, idLanes);
  return bits;
}

// Both shading passes of a bin: every pixel of rows [rowBegin, rowEnd) gets its triangle id
// and, without `surfaces`, its colour (the background word where nothing was drawn); with
// `surfaces`, the background word and its G-buffer texel (0 where nothing was drawn).
void ShadeRows(const std::vector<BinTriangle>& triangles, const std::uint64_t* exactSumPlanes,
               const std::vector<ItemState>& items,
               const std::vector<ItemMaps>& maps, const std::uint32_t* slots, int rowBegin, int rowEnd,
               std::uint32_t background, Framebuffer& fb, GBuffer* surfaces) {
  const std::size_t lanes = laneCount();
  const std::size_t width = static_cast<std::size_t>(fb.width);
  std::vector<SegmentKernel> kernels(items.size());
  std::vector<SurfaceKernel> surfaceKernels(items.size());
  for (std::size_t k = 0; k < items.size(); ++k) {
    if (surfaces) {
      surfaceKernels[k] = surfaceKernelFor(items[k].shaderKey);
    } else {
      kernels[k] = kernelFor(items[k].shaderKey);
    }
  }
  HWY_ALIGN std::uint32_t slotLanes[kMaxLanes];
  HWY_ALIGN std::uint32_t itemLanes[kMaxLanes];
  HWY_ALIGN std::uint32_t rgbaLanes[kMaxLanes];
  HWY_ALIGN std::uint32_t idLanes[kMaxLanes];
  HWY_ALIGN float depthLanes[kMaxLanes];
  HWY_ALIGN float channels[kSurfaceChannels][kMaxLanes];
  for (int py = rowBegin; py < rowEnd; ++py) {
    const std::uint32_t* row = slots + static_cast<std::size_t>(py - rowBegin) * width;
    for (std::size_t x = 0; x < width; x += lanes) {
      const std::size_t inRow = std::min(lanes, width - x);
      std::uint64_t remaining = segmentLanes(triangles, row + x, inRow, slotLanes, itemLanes, idLanes);
      const std::size_t origin = fb.index(static_cast<int>(x), py);
      if (remaining != 0) loadDepthLanes(&fb.depth[origin], depthLanes, inRow);
      hn::Store(hn::Set(DU(), background), DU(), rgbaLanes);
      if (surfaces) {
        for (auto& channel : channels) std::fill(channel, channel + lanes, 0.0f);
      }
      // One pass per draw item present in the segment (usually one).
      while (remaining != 0) {
        const std::uint32_t item = itemLanes[__builtin_ctzll(remaining)];
        const std::uint64_t bits = lanesHolding(itemLanes, item, remaining);
        remaining &= ~bits;
        const Segment segment{&triangles, exactSumPlanes, slotLanes, depthLanes, bits, static_cast<int>(x), py};
        if (surfaces) {
          surfaceKernels[item](segment, items[item], maps[item], channels);
        } else {
          kernels[item](segment, items[item], maps[item], rgbaLanes);
        }
      }
      copyLanes(rgbaLanes, reinterpret_cast<std::uint32_t*>(&fb.rgba[4 * origin]), inRow);
      copyLanes(idLanes, &fb.triangleId[origin], inRow);
      if (surfaces) {
        for (std::size_t l = 0; l < inRow; ++l) {
          const float w = slotLanes[l] == kNoSlot ? 0.0f : 1.0f;  // nothing drawn: every target 0
          const auto at = [&](int c) { return channels[c][l]; };
          surfaces->normal[origin + l] = vec4(at(0), at(1), at(2), at(3));
          surfaces->geometric[origin + l] = vec4(at(4), at(5), at(6), w);
          surfaces->albedo[origin + l] = vec4(at(7), at(8), at(9), w);
          surfaces->specular[origin + l] = vec4(at(10), at(11), at(12), at(kSsrReflectChannel));
          surfaces->emission[origin + l] = vec4(at(13), at(14), at(15), w);
          if (!surfaces->position.empty()) surfaces->position[origin + l] = vec4(at(16), at(17), at(18), w);
        }
      }
    }
  }
}

void ShadeBin(const std::vector<BinTriangle>& triangles, const std::uint64_t* exactSumPlanes,
              const std::vector<ItemState>& items,
              const std::vector<ItemMaps>& maps, const std::uint32_t* slots, int rowBegin, int rowEnd,
              std::uint32_t background, Framebuffer& fb) {
  ShadeRows(triangles, exactSumPlanes, items, maps, slots, rowBegin, rowEnd, background, fb, nullptr);
}

void SurfaceBin(const std::vector<BinTriangle>& triangles, const std::uint64_t* exactSumPlanes,
                const std::vector<ItemState>& items,
                const std::vector<ItemMaps>& maps, const std::uint32_t* slots, int rowBegin, int rowEnd,
                std::uint32_t background, Framebuffer& fb, GBuffer& surfaces) {
  ShadeRows(triangles, exactSumPlanes, items, maps, slots, rowBegin, rowEnd, background, fb, &surfaces);
}

// The lighting pass over rows [rowBegin, rowEnd): a vector of pixels of a row at a time, the
// G-buffer's texels gathered into lanes, deferredLighting where the depth is below the
// clear depth; the other pixels keep their colour.
void LightRows(const GBuffer& g, const DeferredUniforms& u, int rowBegin, int rowEnd, Framebuffer& fb) {
  const DF df;
  const DU du;
  const std::size_t lanes = laneCount();
  const std::size_t width = static_cast<std::size_t>(fb.width);
  HWY_ALIGN float channels[kSurfaceChannels + 1][kMaxLanes];  // the surface, then the depth
  const vec4 noPosition(0.0f);
  for (int py = rowBegin; py < rowEnd; ++py) {
    for (std::size_t x = 0; x < width; x += lanes) {
      const std::size_t inRow = std::min(lanes, width - x);
      const std::size_t origin = fb.index(static_cast<int>(x), py);
      std::uint64_t bits = 0;
      for (std::size_t l = 0; l < lanes; ++l) {
        const bool drawn = l < inRow && fb.depth[origin + l] < kClearDepth;
        if (drawn) bits |= std::uint64_t{1} << l;
        const std::size_t i = drawn ? origin + l : origin;  // a sane texel for lanes not written
        const vec4 &n = g.normal[i], &m = g.geometric[i], &a = g.albedo[i], &sp = g.specular[i], &e = g.emission[i];
        const vec4& p = u.positionStored ? g.position[i] : noPosition;
        const float values[kSurfaceChannels + 1] = {n.x, n.y, n.z, n.w, m.x, m.y, m.z, a.x,  a.y,  a.z,        sp.x,
                                                    sp.y, sp.z, e.x, e.y, e.z, p.x, p.y, p.z, sp.w, fb.depth[i]};
        for (int c = 0; c <= kSurfaceChannels; ++c) channels[c][l] = values[c];
      }
      if (bits == 0) continue;
      const auto lane = [&](int c) HWY_ATTR { return LaneF(hn::Load(df, channels[c])); };
      const LaneF px = pixelColumnsF(static_cast<int>(x)), pyLanes(static_cast<float>(py));
      const Vec3L<LaneF> posWorld =
          u.positionStored
              ? Vec3L<LaneF>(lane(kPositionChannel), lane(kPositionChannel + 1), lane(kPositionChannel + 2))
              : worldFromWindow<LaneF>(u.worldFromClip, u.viewportSize, px, pyLanes, lane(kSurfaceChannels));
      const GBufferTexelL<LaneF> surface{Vec3L<LaneF>(lane(0), lane(1), lane(2)),    lane(3),
                                         Vec3L<LaneF>(lane(4), lane(5), lane(6)),    Vec3L<LaneF>(lane(7), lane(8), lane(9)),
                                         Vec3L<LaneF>(lane(10), lane(11), lane(12)), Vec3L<LaneF>(lane(13), lane(14), lane(15)),
                                         posWorld,                                   lane(kSsrReflectChannel)};
      const Vec4L<LaneF> colour = deferredLighting<LaneF>(surface, u.lighting);
      HWY_ALIGN std::uint32_t words[kMaxLanes];
      hn::Store(rgbaWordsOf(colour), du, words);
      for (std::size_t l = 0; l < inRow; ++l) {
        if (((bits >> l) & 1u) != 0) std::memcpy(&fb.rgba[4 * (origin + l)], &words[l], sizeof(std::uint32_t));
      }
    }
  }
}

// Screen-space reflections over rows [rowBegin, rowEnd): a vector of pixels of a row at a time,
// gathered from the G-buffer, with each pixel's indirect random pairs, through ssrPixel
// where a surface reflects or indirect light is on; the pixels it changed get their new colour,
// the others keep theirs.
void ReflectRows(const GBuffer& g, const SsrUniforms& u, const Mat4T<float>& worldFromClip, bool positionStored,
                 int rowBegin, int rowEnd, Framebuffer& fb) {
  const DF df;
  const DU du;
  const std::size_t lanes = laneCount();
  const std::size_t width = static_cast<std::size_t>(fb.width);
  // normal xyz, position xyz, ssr_reflect, depth, own colour rgb, albedo rgb
  constexpr int kChannels = 14;
  constexpr int kReflect = 6, kDepth = 7, kColour = 8, kAlbedo = 11;
  HWY_ALIGN float channels[kChannels][kMaxLanes];
  HWY_ALIGN float random[2 * kMaxSsrIndirectSamples][kMaxLanes];  // per sample: xi.x, xi.y
  Vec2L<LaneF> samples[kMaxSsrIndirectSamples];
  const vec4 noPosition(0.0f);
  const bool everyPixel = u.indirectSamples > 0 || isSsrView(u.view);  // not only the reflecting ones
  for (int py = rowBegin; py < rowEnd; ++py) {
    for (std::size_t x = 0; x < width; x += lanes) {
      const std::size_t inRow = std::min(lanes, width - x);
      const std::size_t origin = fb.index(static_cast<int>(x), py);
      std::uint64_t bits = 0;
      for (std::size_t l = 0; l < lanes; ++l) {
        const bool drawn = l < inRow && fb.depth[origin + l] < kClearDepth;
        const bool marched = drawn && (g.specular[origin + l].w > 0.0f || everyPixel);
        if (marched) bits |= std::uint64_t{1} << l;
        const std::size_t i = marched ? origin + l : origin;  // a sane texel for lanes not marched
        const vec4& n = g.normal[i];
        const vec4& p = positionStored ? g.position[i] : noPosition;
        const vec4& a = g.albedo[i];
        const float values[kChannels] = {n.x, n.y, n.z, p.x, p.y, p.z, g.specular[i].w, fb.depth[i],
                                         u.colour[0][i], u.colour[1][i], u.colour[2][i], a.x, a.y, a.z};
        for (int c = 0; c < kChannels; ++c) channels[c][l] = values[c];
        if (!marched) channels[kReflect][l] = 0.0f;  // ssr_reflect 0: no mirror ray
        if (!marched) channels[kDepth][l] = kClearDepth;  // nothing drawn: no indirect rays
        for (int k = 0; k < u.indirectSamples; ++k) {
          const vec2 xi = ssrRandomPairOf(static_cast<std::uint32_t>(x + l), static_cast<std::uint32_t>(py),
                                          static_cast<std::uint32_t>(k));
          random[2 * k][l] = xi.x;
          random[2 * k + 1][l] = xi.y;
        }
      }
      if (bits == 0) continue;
      const auto lane = [&](int c) HWY_ATTR { return LaneF(hn::Load(df, channels[c])); };
      for (int k = 0; k < u.indirectSamples; ++k) {
        samples[k] = Vec2L<LaneF>(LaneF(hn::Load(df, random[2 * k])), LaneF(hn::Load(df, random[2 * k + 1])));
      }
      const LaneF px = pixelColumnsF(static_cast<int>(x)), pyLanes(static_cast<float>(py));
      const Vec3L<LaneF> posWorld =
          positionStored ? Vec3L<LaneF>(lane(3), lane(4), lane(5))
                         : worldFromWindow<LaneF>(worldFromClip, u.viewportSize, px, pyLanes, lane(kDepth));
      Vec3L<LaneF> colour(lane(kColour), lane(kColour + 1), lane(kColour + 2));
      const SsrPixelL<LaneF> p = (ssrPixel<LaneF>)(
          u, Vec3L<LaneF>(lane(0), lane(1), lane(2)), posWorld, lane(kReflect),
          Vec3L<LaneF>(lane(kAlbedo), lane(kAlbedo + 1), lane(kAlbedo + 2)), samples, lane(kDepth) < LaneF(kClearDepth),
          colour);
      if (!anyOf(p.changed)) continue;
      HWY_ALIGN float changed[kMaxLanes];
      hn::Store(select(p.changed, LaneF(1.0f), LaneF(0.0f)).v, df, changed);
      HWY_ALIGN std::uint32_t words[kMaxLanes];
      hn::Store(rgbaWordsOf(Vec4L<LaneF>(colour, LaneF(1.0f))), du, words);
      for (std::size_t l = 0; l < inRow; ++l) {
        if (((bits >> l) & 1u) != 0 && changed[l] != 0.0f) {
          std::memcpy(&fb.rgba[4 * (origin + l)], &words[l], sizeof(std::uint32_t));
        }
      }
    }
  }
}

void PhongPow(const float* x, float s, float* out, std::size_t count) {
  const std::size_t lanes = laneCount();
  HWY_ALIGN float in[kMaxLanes];
  HWY_ALIGN float result[kMaxLanes];
  for (std::size_t i = 0; i < count; i += lanes) {
    const std::size_t n = std::min(lanes, count - i);
    for (std::size_t l = 0; l < lanes; ++l) in[l] = l < n ? x[i + l] : 1.0f;
    hn::Store(phongPow<LaneF>(LaneF(hn::Load(DF(), in)), s).v, DF(), result);
    std::memcpy(out + i, result, n * sizeof(float));
  }
}

// ---- the vertex stage, a vector of vertices at a time ----
static_assert(std::is_standard_layout_v<Vertex> && sizeof(Vertex) == 12 * sizeof(float));
inline constexpr int kVertexFloats = 12;  // posModel, nModel, tangentModel, uv (scene/mesh.h)

// setup.cpp's clampedTo per lane: fmin(fmax(v, -bound), bound), NaN to -bound.
HWY_INLINE LaneF clampedTo(LaneF v, float bound) {
  return select(v >= LaneF(-bound), select(v > LaneF(bound), LaneF(bound), v), LaneF(-bound));
}

// setup.cpp's windowFromClip for a vertex from the vertex stage (fused multiply-adds).
HWY_INLINE Vec4L<LaneF> windowFromClipLanes(const Vec4L<LaneF>& posClip, const Viewport& viewport) {
  const LaneF halfWidth(0.5f * static_cast<float>(viewport.width)), halfHeight(0.5f * static_cast<float>(viewport.height));
  const LaneF halfDepthRange(0.5f);  // glDepthRange(0, 1): scale and offset 0.5
  const LaneF invW = select(posClip.w >= LaneF(std::numeric_limits<float>::min()), LaneF(1.0f) / posClip.w,
                            LaneF(1.0f) / LaneF(kMinClipW));
  const LaneF xNdc = posClip.x * invW, yNdc = posClip.y * invW;
  const LaneF zNdc = clampedTo(posClip.z * invW, kMaxNdcDepth);
  return Vec4L<LaneF>(fusedMulAdd(xNdc, halfWidth, halfWidth), fusedMulAdd(yNdc, halfHeight, halfHeight),
                      fusedMulAdd(zNdc, halfDepthRange, halfDepthRange), invW);
}

// setup.cpp's snapToSubpixel per lane (NearestInt rounds halves to even, as lrint).
HWY_INLINE hn::Vec<DI> snapToSubpixelLanes(LaneF windowCoord) {
  const LaneF bounded = clampedTo(windowCoord, kMaxWindowCoord);
  return hn::NearestInt(
      ((bounded - LaneF(static_cast<float>(kPixelCentreOffset))) * LaneF(static_cast<float>(kSubpixelScale))).v);
}

// clip.cpp's outcode per lane: kClipNonFiniteBit where a clip coordinate or user distance is
// beyond kMaxClipCoordinate (or not finite), else a bit for each active plane the vertex is
// outside of, each distance as clipDistanceTo writes it.
HWY_INLINE hn::Vec<DU> outcodeLanes(const VertexOutL<LaneF>& v, const ClipConfig& config) {
  const DU du;
  const Vec4L<LaneF>& p = v.posClip;
  const LaneF range(kMaxClipCoordinate);
  LaneMask usable = (absOf(p.x) <= range) & (absOf(p.y) <= range) & (absOf(p.z) <= range) & (absOf(p.w) <= range);
  for (int j = 0; j < config.userPlaneCount; ++j) usable = usable & (absOf(v.clipDistance[static_cast<std::size_t>(j)]) <= range);
  auto code = hn::Zero(du);
  const auto outside = [&](int plane, LaneF distance) HWY_ATTR {
    code = hn::Or(code, hn::IfThenElseZero(hn::RebindMask(du, (distance < LaneF(0.0f)).m), hn::Set(du, 1u << plane)));
  };
  const LaneF gx = LaneF(config.guardBandX) * p.w, gy = LaneF(config.guardBandY) * p.w;
  outside(kClipPlaneRight, (config.frustum.right ? p.w : gx) - p.x);
  outside(kClipPlaneLeft, (config.frustum.left ? p.w : gx) + p.x);
  outside(kClipPlaneTop, (config.frustum.top ? p.w : gy) - p.y);
  outside(kClipPlaneBottom, (config.frustum.bottom ? p.w : gy) + p.y);
  if (config.frustum.near) outside(kClipPlaneNear, p.w + p.z);
  if (config.frustum.far) outside(kClipPlaneFar, p.w - p.z);
  for (int j = 0; j < config.userPlaneCount; ++j) outside(kClipPlaneUser0 + j, v.clipDistance[static_cast<std::size_t>(j)]);
  if (!config.frustum.near) outside(kClipPlaneMinW, p.w - LaneF(kMinClipW));
  return hn::IfThenElse(hn::RebindMask(du, usable.m), code, hn::Set(du, kClipNonFiniteBit));
}

// The vertices' fields per lane, gathered from the array (a vector past `count` repeats the
// last vertex).
HWY_INLINE VertexInL<LaneF> vertexLanes(const Vertex* vertices, std::size_t count) {
  const DI di;
  const auto index =
      hn::Mul(hn::Min(laneIndices(), hn::Set(di, static_cast<std::int32_t>(count - 1))), hn::Set(di, kVertexFloats));
  const float* base = reinterpret_cast<const float*>(vertices);
  const auto field = [&](int k) HWY_ATTR { return LaneF(hn::GatherIndex(DF(), base + k, index)); };
  return VertexInL<LaneF>{Vec3L<LaneF>(field(0), field(1), field(2)), Vec3L<LaneF>(field(3), field(4), field(5)),
                          Vec4L<LaneF>(field(6), field(7), field(8), field(9)), Vec2L<LaneF>(field(10), field(11))};
}

void VertexRange(const Vertex* vertices, std::size_t count, const VertexUniforms& u, const Viewport& viewport,
                 const ClipConfig& clip, FastVertex* out, SnappedCorner* corners, float* varyings, std::size_t stride) {
  const DF df;
  const DI di;
  const DU du;
  const std::size_t lanes = laneCount();
  // Lanes stored per column, then written vertex by vertex: storeVaryings' layout first.
  constexpr int kWindow = kMaxVaryings, kFixedX = kWindow + 4, kFixedY = kFixedX + 1, kOutcode = kFixedY + 1;
  HWY_ALIGN float columns[kOutcode + 1][kMaxLanes];
  const auto put = [&](int column, LaneF value) HWY_ATTR { hn::Store(value.v, df, columns[column]); };
  const auto put3 = [&](int column, const Vec3L<LaneF>& value) HWY_ATTR {
    put(column, value.x);
    put(column + 1, value.y);
    put(column + 2, value.z);
  };
  for (std::size_t first = 0; first < count; first += lanes) {
    const std::size_t n = std::min(lanes, count - first);
    const VertexOutL<LaneF> v = vertexStage<LaneF>(vertexLanes(vertices + first, n), u);
    const Vec4L<LaneF> window = windowFromClipLanes(v.posClip, viewport);
    put3(kVaryingPosWorld, v.posWorld);
    put3(kVaryingNormal, v.nWorld);
    put3(kVaryingTangent, v.tWorld);
    put3(kVaryingBitangent, v.bWorld);
    put(kVaryingUv, v.uv.x);
    put(kVaryingUv + 1, v.uv.y);
    if (u.tangentLighting) {
      put3(kVaryingEyeDirTangent, v.eyeDirTangent);
      for (int i = 0; i < u.lightCount; ++i) put3(kVaryingLightDirTangent + 3 * i, v.lightDirTangent[static_cast<std::size_t>(i)]);
    }
    put(kWindow, window.x);
    put(kWindow + 1, window.y);
    put(kWindow + 2, window.z);
    put(kWindow + 3, window.w);
    hn::Store(snapToSubpixelLanes(window.x), di, reinterpret_cast<std::int32_t*>(columns[kFixedX]));
    hn::Store(snapToSubpixelLanes(window.y), di, reinterpret_cast<std::int32_t*>(columns[kFixedY]));
    hn::Store(outcodeLanes(v, clip), du, reinterpret_cast<std::uint32_t*>(columns[kOutcode]));
    const auto word = [&](int column, std::size_t l) {
      std::uint32_t bits;
      std::memcpy(&bits, &columns[column][l], sizeof bits);
      return bits;
    };
    for (std::size_t l = 0; l < n; ++l) {
      FastVertex& f = out[first + l];
      f.window = WindowVertex{columns[kWindow][l], columns[kWindow + 1][l], columns[kWindow + 2][l], columns[kWindow + 3][l]};
      f.xFixed = static_cast<std::int32_t>(word(kFixedX, l));
      f.yFixed = static_cast<std::int32_t>(word(kFixedY, l));
      corners[first + l] = SnappedCorner{f.xFixed, f.yFixed, word(kOutcode, l)};
      float* to = varyings + (first + l) * stride;
      for (std::size_t c = 0; c < stride; ++c) to[c] = columns[c][l];
    }
  }
}

CpuIsa isaOfThisTarget() {
#if HWY_TARGET == HWY_AVX3
  return CpuIsa::Avx512;
#elif HWY_TARGET == HWY_AVX2
  return CpuIsa::Avx2;
#elif HWY_TARGET == HWY_SSE4
  return CpuIsa::Sse4;
#elif HWY_TARGET == HWY_NEON
  return CpuIsa::Neon;
#else
  return CpuIsa::Scalar;
#endif
}

}  // namespace

FastKernels GetKernels() {
  FastKernels k;
  k.isa = isaOfThisTarget();
  k.lanes = static_cast<int>(laneCount());
#if HWY_NATIVE_FMA
  k.fusesMultiplyAdds = true;
#else
  k.fusesMultiplyAdds = false;
#endif
  k.visibility = &Visibility;
  k.shadeBin = &ShadeBin;
  k.surfaceBin = &SurfaceBin;
  k.lightRows = &LightRows;
  k.reflectRows = &ReflectRows;
  k.phongPow = &PhongPow;
  k.vertexRange = &VertexRange;
  return k;
}

}  // namespace HWY_NAMESPACE
}  // namespace twr
HWY_AFTER_NAMESPACE();
#else
// This target's kernels are in another object (its fast_kernels_<group>.cpp).
HWY_BEFORE_NAMESPACE();
namespace twr {
namespace HWY_NAMESPACE {
FastKernels GetKernels();
}  // namespace HWY_NAMESPACE
}  // namespace twr
HWY_AFTER_NAMESPACE();
#endif

#include "softrender/lanes_target_end.h"

#endif  // the per-target include guard
