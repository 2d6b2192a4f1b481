// The fast path's AVX-512 kernels, run per bin of rows as a visibility buffer:
//   1. visibility, per triangle in submission order, 4 x 4 pixel blocks: coverage by the
//      edge-function test E > 0 (what the span rasterizer is equivalent to), the window depth
//      from the double barycentrics (pixelWeights), GL_LESS against the depth buffer; a
//      passing pixel takes the triangle's depth and its slot in the bin's slot buffer;
//   2. shading, once per pixel that ended with a slot, 16 pixels of a row at a time, grouped
//      by draw item: perspective weights, interpolation and shadeFragment for the frame's view
//      (the lit image or a debug colour view; Depth reads the depth buffer the visibility pass
//      left, a flat Albedo needs no varyings), reading the slot's vertices by broadcast when
//      all lanes share a triangle and by gathers otherwise; colour and triangle id are written.
// The last triangle to pass the depth test at a pixel is the one whose shading the teaching
// path leaves there, and shading depends only on the triangle and the pixel, so the image is
// the same; every lane performs the scalar stages' IEEE operations in the same order. The
// kernels are compiled for AVX-512 (F, DQ, BW, VL) with contraction off and picked at run
// time (cpuHasAvx512).
#pragma once

#include "scene/conventions.h"
#include "scene/texture.h"
#include "softrender/draw_list.h"
#include "softrender/framebuffer.h"
#include "softrender/interpolate.h"
#include "softrender/setup.h"

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace twr {

// A vertex's varyings as the fast path stores them: floats in this order (offsets in floats).
inline constexpr int kVaryingPosWorld = 0;
inline constexpr int kVaryingNormal = 3;
inline constexpr int kVaryingTangent = 6;
inline constexpr int kVaryingBitangent = 9;
inline constexpr int kVaryingUv = 12;
inline constexpr int kVaryingEyeDirTangent = 14;    // tangent lighting space only
inline constexpr int kVaryingLightDirTangent = 17;  // light i at 17 + 3 i, tangent lighting only
inline constexpr int kMaxVaryings = kVaryingLightDirTangent + 3 * kMaxLights;  // 41
// Floats per vertex: 14 in world lighting space, 17 + 3 lightCount in tangent space.
inline int varyingCount(bool tangentLighting, int lightCount) {
  return tangentLighting ? kVaryingLightDirTangent + 3 * lightCount : kVaryingEyeDirTangent;
}

// No triangle in a bin's slot buffer.
inline constexpr std::uint32_t kNoSlot = 0xFFFFFFFFu;

// One triangle of a bin as the shading pass reads it.
struct BinTriangle {
  std::array<double, 3> atOrigin{}, dx{}, dy{};  // InterpolationSetup's barycentric planes
  std::array<float, 3> invW{};
  std::uint32_t triangleId = 0;
  std::uint32_t item = 0;                     // index into the frame's ItemState list
  std::array<const float*, 3> varyings{};     // each vertex's varyings, submission order
};

// A texture as the kernels read it: the RGBA8 texels of each 4 x 4 block of texels stored
// together in one 64-byte block (one cache line), blocks in rows, sides padded up to multiples
// of 4. A bilinear footprint then touches one to four cache lines near each other instead of
// two texture rows far apart.
inline constexpr int kTexelBlockSide = 4;
struct alignas(64) TexelBlock {
  std::array<std::uint32_t, kTexelBlockSide * kTexelBlockSide> texels{};
};
struct TiledTexture {
  int width = 0, height = 0;  // texels, as the source texture
  int blocksPerRow = 0;
  std::vector<TexelBlock> blocks;
};
TiledTexture makeTiledTexture(const Texture& texture);

// The tiled maps of one draw item (null where the shading uniforms have no such map).
struct ItemMaps {
  const TiledTexture* diffuse = nullptr;
  const TiledTexture* normal = nullptr;
  const TiledTexture* specular = nullptr;
};

// True when this CPU runs the AVX-512 kernels.
bool cpuHasAvx512();

// Visibility pass for one triangle over rows [rowBegin, rowEnd) (exclusive end). slots holds
// the bin's rows: pixel (px, py) at (py - rowBegin) * fb.width + px. On the first covered
// pixel it computes `interpolation` = makeInterpolationSetup(window, setup) and sets
// `covered`; returns how many pixels passed the depth test.
std::uint64_t visibilityAvx512(const TriangleSetup& setup, const std::array<WindowVertex, 3>& window,
                               std::uint32_t slot, int rowBegin, int rowEnd, Framebuffer& fb, std::uint32_t* slots,
                               InterpolationSetup& interpolation, bool& covered);

// Shading pass over rows [rowBegin, rowEnd), writing colour and triangle id of every pixel:
// for a pixel with a slot from triangles[slot], items[triangles[slot].item] (any view) and that
// item's maps (maps[item], the tiled copies of its uniforms' maps); for one without, the
// background word (backgroundWord) and kNoTriangle. Runs after the bin's visibility passes
// (the Depth view reads the depth buffer).
void shadeBinAvx512(const std::vector<BinTriangle>& triangles, const std::vector<ItemState>& items,
                    const std::vector<ItemMaps>& maps, const std::uint32_t* slots, int rowBegin, int rowEnd,
                    std::uint32_t background, Framebuffer& fb);

// powPositive (phong_pow.h) of x[0, count) with the kernels' SIMD code, into out; exposed so
// the tests can compare it bit for bit with the scalar function. Requires cpuHasAvx512().
void powPositiveAvx512(const float* x, float s, float* out, std::size_t count);

}  // namespace twr
