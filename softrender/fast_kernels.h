// The fast path's kernels, run per bin of rows as a visibility buffer, compiled by Highway for
// every SIMD target (AVX-512, AVX2, SSE4, NEON, scalar) and picked at run time:
//   1. visibility, per triangle in submission order: each row's covered span (the teaching
//      rasterizer's coveredSpan), its pixels a vector of lanes at a time: the window depth
//      from llvmpipe's depth plane (windowDepth), GL_LESS against the depth buffer; a
//      passing pixel takes the triangle's depth and its slot in the bin's slot buffer;
//   2. shading, once per pixel that ended with a slot, a vector of pixels of a row at a time,
//      grouped by draw item: the shared sources interpolate-inl.h, shade-inl.h (with
//      texture_sample-inl.h and phong_pow-inl.h) and output_merge-inl.h instantiated for
//      the target's float vector, reading the slot's triangle by broadcast when all lanes
//      share one and lane by lane otherwise; colour and triangle id are written.
// The last triangle to pass the depth test at a pixel is the one whose shading the teaching
// path leaves there, and shading depends only on the triangle and the pixel, so the image is
// the same bit for bit (tests/softrender/test_fast_path.cpp, on every target).
#pragma once

#include "scene/conventions.h"
#include "scene/texture.h"
#include "softrender/cpu_renderer.h"
#include "softrender/deferred.h"
#include "softrender/ssr.h"
#include "softrender/draw_list.h"
#include "softrender/framebuffer.h"
#include "softrender/interpolate.h"
#include "softrender/setup.h"
#include "softrender/clip.h"
#include "softrender/vertex.h"

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace twr {

// A vertex's varyings are stored as floats in interpolate.h's layout (kVaryingPosWorld ...).

// No triangle in a bin's slot buffer.
inline constexpr std::uint32_t kNoSlot = 0xFFFFFFFFu;

// One triangle of a bin as the shading pass reads it: its planes, as llvmpipe interpolates.
// (Its depth the shading reads from the depth buffer: at a pixel the triangle holds, the
// visibility pass stored the depth of this triangle's plane there.)
struct BinTriangle {
  VaryingPlanesT<float> varyings;  // every varying's a/w plane and the 1/w plane
  std::uint32_t triangleId = 0;
  std::uint32_t item = 0;  // index into the frame's ItemState list
};
// For targets without fused multiply-adds (FastKernels::fusesMultiplyAdds false), the planes of
// a binned triangle that planeSumsExactInDouble holds for: bit 0 1/w, bit 1 + k varying k. Kept
// beside the triangles, not in them, so the other targets' bins stay as they were.
inline constexpr int kExactSumOneOverWBit = 0;
inline constexpr int kExactSumFirstVaryingBit = 1;
static_assert(kExactSumFirstVaryingBit + kMaxVaryings <= 64);
// Those bits of a triangle's planes.
std::uint64_t exactSumPlaneBits(const BinTriangle& t);

// A texture as the kernels read it: the RGBA8 texels of each 4 x 4 block of texels stored
// together in one 64-byte block (one cache line), blocks in rows, sides padded up to multiples
// of 4. A bilinear footprint then touches one to four cache lines near each other instead of
// two texture rows far apart.
inline constexpr int kTexelBlockSide = 4;
struct alignas(64) TexelBlock {
  std::array<std::uint32_t, kTexelBlockSide * kTexelBlockSide> texels{};
};
struct TiledLevel {
  int width = 0, height = 0;  // texels, as the source level
  int blocksPerRow = 0;
  std::vector<TexelBlock> blocks;
};
// A height map's red channel as a march reads it, dozens of times per pixel: one 32-bit word
// per texel holding the red bytes of the bilinear footprint that starts there, (x, y),
// (x + 1, y), (x, y + 1), (x + 1, y + 1) in bytes 0 to 3, the neighbours wrapped as repeat
// wraps them. One gather then fetches what took four. A read that clamps or mirrors at an edge
// takes (x, y) twice instead, which the word also holds. The words are tiled as TiledLevel's
// texels are (a 4 x 4 block per cache line): a vector of neighbouring pixels marching side by
// side then gathers from a few lines instead of one per texel row.
struct RedFootprintLevel {
  int width = 0, height = 0;  // texels, as the source level
  int blocksPerRow = 0;
  std::vector<TexelBlock> blocks;  // words, laid out as TiledLevel::blocks
};
struct TiledTexture {
  std::vector<TiledLevel> levels;  // every level of the source texture, level 0 first
  std::vector<RedFootprintLevel> redFootprints;  // every level, or empty: only height maps have them
  TextureWrap wrap = TextureWrap::Repeat;
  bool srgb = false;
};
TiledTexture makeTiledTexture(const Texture& texture);
std::vector<RedFootprintLevel> makeRedFootprints(const Texture& texture);

// The tiled maps of one draw item (null where the shading uniforms have no such map).
struct ItemMaps {
  const TiledTexture* diffuse = nullptr;
  const TiledTexture* normal = nullptr;
  const TiledTexture* specular = nullptr;
  const TiledTexture* height = nullptr;
  std::array<const TiledTexture*, kMaxHorizonDirections / 4> horizon{};
};

// What the back end's setup and interpolation read of a vertex.
struct FastVertex {
  WindowVertex window;                  // windowFromClip (fused multiply-add for stage outputs)
  std::int32_t xFixed = 0, yFixed = 0;  // snapToSubpixel of window x and y (1/256 px)
};

// What the front end reads of a vertex (12 bytes, in an array of its own: a million-triangle
// frame's front end streams it once per corner): the snapped position again, and the outcode.
struct SnappedCorner {
  std::int32_t xFixed = 0, yFixed = 0;  // as FastVertex's
  std::uint32_t outcode = 0;            // planes it is outside of, or kClipNonFiniteBit
};

// One target's kernels.
struct FastKernels {
  CpuIsa isa = CpuIsa::Scalar;  // the target they were compiled for
  int lanes = 1;                // floats per vector on it
  bool fusesMultiplyAdds = true;  // false: fusedMulAdd is emulated, exactSumPlaneBits helps

  // Visibility pass for one triangle over rows [rowBegin, rowEnd) (exclusive end). `slots`
  // holds the bin's rows: pixel (px, py) at (py - rowBegin) * fb.width + px. Sets `covered`
  // if the triangle covers a pixel of these rows (its depth plane, makeDepthPlane(window,
  // setup), is made there); returns how many pixels passed the depth test.
  std::uint64_t (*visibility)(const TriangleSetup& setup, const std::array<WindowVertex, 3>& window,
                              std::uint32_t slot, int rowBegin, int rowEnd, Framebuffer& fb, std::uint32_t* slots,
                              bool& covered) = nullptr;

  // Shading pass over rows [rowBegin, rowEnd), writing colour and triangle id of every pixel:
  // for a pixel with a slot, triangles[slot] shaded with items[triangles[slot].item] and that
  // item's tiled maps; for one without, the background word and kNoTriangle.
  // exactSumPlanes: exactSumPlaneBits of each triangle where the target does not fuse
  // multiply-adds, else null.
  void (*shadeBin)(const std::vector<BinTriangle>& triangles, const std::uint64_t* exactSumPlanes,
                   const std::vector<ItemState>& items,
                   const std::vector<ItemMaps>& maps, const std::uint32_t* slots, int rowBegin, int rowEnd,
                   std::uint32_t background, Framebuffer& fb) = nullptr;

  // The deferred pipeline's G-buffer pass over rows [rowBegin, rowEnd), as shadeBin but with
  // the shaded permutation's surface (gbufferFragment, deferred-inl.h) written into
  // `surfaces` instead of the colour: every pixel of the rows gets its texel (0 where nothing
  // was drawn) and the background word in colour.
  void (*surfaceBin)(const std::vector<BinTriangle>& triangles, const std::uint64_t* exactSumPlanes,
                     const std::vector<ItemState>& items,
                     const std::vector<ItemMaps>& maps, const std::uint32_t* slots, int rowBegin, int rowEnd,
                     std::uint32_t background, Framebuffer& fb, GBuffer& surfaces) = nullptr;

  // The deferred lighting pass over rows [rowBegin, rowEnd): every pixel whose depth is below
  // the clear depth gets deferredLighting's colour (alpha 255); the others keep theirs.
  void (*lightRows)(const GBuffer& surfaces, const DeferredUniforms& u, int rowBegin, int rowEnd, Framebuffer& fb) = nullptr;

  // Screen-space reflections over rows [rowBegin, rowEnd) (ssr-inl.h): each pixel with a
  // surface and ssr_reflect > 0 (surfaces.specular.w) marches its mirror ray from its position
  // (the G-buffer's, else rebuilt from depth through worldFromClip); a hit pixel gets
  // ssrPixel's colour (alpha 255), the others keep theirs. u's buffers must be set.
  void (*reflectRows)(const GBuffer& surfaces, const SsrUniforms& u, const Mat4T<float>& worldFromClip,
                      bool positionStored, int rowBegin, int rowEnd, Framebuffer& fb) = nullptr;

  // The vertex stage (vertex_stage-inl.h) of vertices[0, count), a vector of vertices at a
  // time: each one's window position (windowFromClip, fused multiply-adds) and snapped
  // corner into out[i] and corners[i] (its outcode under `clip`, or kClipNonFiniteBit for a
  // clip position that is not finite), its varyings (storeVaryings, stride floats) from
  // varyings + i * stride. The same bits as those functions one vertex at a time.
  void (*vertexRange)(const Vertex* vertices, std::size_t count, const VertexUniforms& u, const Viewport& viewport,
                      const ClipConfig& clip, FastVertex* out, SnappedCorner* corners, float* varyings,
                      std::size_t stride) = nullptr;

  // phongPow of x[0, count) with this target's vectors, into out (for the tests: the same
  // bits as powPositive).
  void (*phongPow)(const float* x, float s, float* out, std::size_t count) = nullptr;
};

// The kernels of `isa` (Auto: Highway's dynamic dispatch picks the best target this CPU
// runs). Throws InputError for a target this binary or CPU cannot run (cpuIsaSupported).
FastKernels fastKernelsFor(CpuIsa isa);

}  // namespace twr
