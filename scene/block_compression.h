// Block-compressed texels (S3TC / RGTC, D3D's BC1-BC5): 4x4 texel blocks of 8 or 16 bytes.
// The CPU renderer decodes them texel for texel as llvmpipe (Mesa 22.3) does, measured bit
// for bit against its sampler on random blocks of every format (docs/textures.md), so a
// nearest-filtered render matches llvmpipe sampling the same blocks uploaded compressed.
// The interpolations are llvmpipe's 8-bit lerps, lerp8(w, a, b) = a + ((w (b - a)) >> 8)
// (floor shift), not the textbook (2 c0 + c1) / 3, which is 1 off on 4-12 % of texels.
//
//   BC1 (DXT1)  8 bytes: two RGB565 endpoints c0, c1, 2-bit indices. c0 > c1: 4 colours
//               c0, c1, lerp8(85, c0, c1), lerp8(170, c0, c1); else 3 colours c0, c1,
//               (c0 + c1 + 1) >> 1 and index 3 = transparent black. Endpoints widen 5/6 -> 8
//               bits by bit replication.
//   BC2 (DXT3) 16 bytes: 4-bit explicit alpha (a * 17), then a BC1 colour block that always
//               uses the 4-colour rule.
//   BC3 (DXT5) 16 bytes: a BC4-style alpha block, then a 4-colour BC1 colour block.
//   BC4 (RGTC1) 8 bytes: two 8-bit endpoints a0, a1, 3-bit indices. a0 > a1: values
//               lerp8(255 (k - 1) / 7, a0, a1) for k = 2..7; else lerp8(255 (k - 1) / 5, a0, a1)
//               for k = 2..5, k = 6 -> 0, k = 7 -> 255. Sampled as (r, 0, 0, 1).
//   BC5 (RGTC2) 16 bytes: two BC4 blocks, red then green. Sampled as (r, g, 0, 1).
// Texel (i, j) of a block is column i, row j; row 0 comes first in the file (the top row of
// an image file; texture.h turns rows around).
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string_view>
#include <vector>

namespace twr {

enum class BlockFormat { Bc1, Bc2, Bc3, Bc4, Bc5 };

inline constexpr int kBlockSide = 4;  // texels per block side

// Bytes per 4x4 block: 8 for BC1 and BC4, 16 for BC2, BC3 and BC5.
int blockBytes(BlockFormat format);
// "BC1 (DXT1)", ... for messages and `info`.
std::string_view toString(BlockFormat format);
// Blocks along a side of `texels` texels (at least 1).
inline int blocksAlong(int texels) { return texels <= 0 ? 1 : (texels + kBlockSide - 1) / kBlockSide; }
// Bytes of a width x height level (every side rounded up to whole blocks).
std::size_t blockLevelBytes(BlockFormat format, int width, int height);

// The 16 texels of one block as RGBA8, row by row (texel (i, j) at [4 j + i]).
using BlockTexels = std::array<std::array<std::uint8_t, 4>, 16>;
BlockTexels decodeBlock(BlockFormat format, const std::uint8_t* block);

// A whole level: `blocks` holds blocksAlong(width) * blocksAlong(height) blocks, block rows in
// file order; returns width * height RGBA8 texels in the same row order (texels past the
// level's edge in the last block row or column are dropped).
std::vector<std::uint8_t> decodeBlockLevel(BlockFormat format, int width, int height, const std::uint8_t* blocks);

// The same level with its texel rows in the opposite order, still compressed: block rows
// reversed and the rows inside each block reversed. Possible only when the rows map onto
// whole blocks: height <= 4 (one block row; rows past the edge stay where they are) or a
// multiple of 4. Otherwise nullopt (the caller decodes instead).
std::optional<std::vector<std::uint8_t>> flipBlockLevelRows(BlockFormat format, int width, int height,
                                                            const std::uint8_t* blocks);

}  // namespace twr
