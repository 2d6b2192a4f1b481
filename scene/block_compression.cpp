#include "scene/block_compression.h"

#include <cstring>

namespace twr {
namespace {

constexpr int kTexelsPerBlock = kBlockSide * kBlockSide;
constexpr int kHalfBlockBytes = 8;  // a BC1 colour block, a BC4 block, a BC2 alpha block

std::uint16_t read16(const std::uint8_t* p) { return static_cast<std::uint16_t>(p[0] | (p[1] << 8)); }

// llvmpipe's 8-bit lerp: a + ((w (b - a)) >> 8) with an arithmetic (floor) shift, kept to 8 bits;
// w in [0, 255] is the weight of b in 256ths.
int lerp8(int weight, int a, int b) { return (a + ((weight * (b - a)) >> 8)) & 0xFF; }
// Weights of the interpolated BC1 colours (1/3, 2/3) and of BC4 values k = 2..7 or 2..5:
// 255 (k - 1) / 7 and 255 (k - 1) / 5, truncated.
constexpr int kThirdWeight = 85, kTwoThirdsWeight = 170;

// RGB565 widened to 8 bits per channel by bit replication (Mesa's EXP5TO8R etc.).
std::array<int, 3> rgbOf565(std::uint16_t c) {
  const int r5 = (c >> 11) & 0x1F, g6 = (c >> 5) & 0x3F, b5 = c & 0x1F;
  return {(r5 << 3) | (r5 >> 2), (g6 << 2) | (g6 >> 4), (b5 << 3) | (b5 >> 2)};
}

// A BC1 colour block into `out`. fourColours: BC2 and BC3 always use the 4-colour rule;
// BC1 only when c0 > c1 (as 16-bit numbers).
void decodeColourBlock(const std::uint8_t* block, bool alwaysFourColours, BlockTexels& out) {
  const std::uint16_t c0 = read16(block), c1 = read16(block + 2);
  const std::array<int, 3> e0 = rgbOf565(c0), e1 = rgbOf565(c1);
  const bool fourColours = alwaysFourColours || c0 > c1;
  std::array<std::array<std::uint8_t, 4>, 4> palette{};
  for (int c = 0; c < 3; ++c) {
    palette[0][c] = static_cast<std::uint8_t>(e0[c]);
    palette[1][c] = static_cast<std::uint8_t>(e1[c]);
    palette[2][c] = static_cast<std::uint8_t>(fourColours ? lerp8(kThirdWeight, e0[c], e1[c]) : (e0[c] + e1[c] + 1) >> 1);
    palette[3][c] = static_cast<std::uint8_t>(fourColours ? lerp8(kTwoThirdsWeight, e0[c], e1[c]) : 0);
  }
  for (int k = 0; k < 4; ++k) palette[k][3] = 255;
  if (!fourColours) palette[3][3] = 0;  // transparent black (BC1 only)
  const std::uint32_t indices = static_cast<std::uint32_t>(block[4]) | (static_cast<std::uint32_t>(block[5]) << 8) |
                                (static_cast<std::uint32_t>(block[6]) << 16) | (static_cast<std::uint32_t>(block[7]) << 24);
  for (int t = 0; t < kTexelsPerBlock; ++t) out[t] = palette[(indices >> (2 * t)) & 3];
}

// A BC4 block (or BC3's alpha half): the 16 values, row by row.
std::array<std::uint8_t, 16> decodeValueBlock(const std::uint8_t* block) {
  const int a0 = block[0], a1 = block[1];
  std::uint64_t indices = 0;  // 16 x 3 bits, little-endian from byte 2
  for (int i = 0; i < 6; ++i) indices |= static_cast<std::uint64_t>(block[2 + i]) << (8 * i);
  std::array<std::uint8_t, 16> values{};
  for (int t = 0; t < kTexelsPerBlock; ++t) {
    const int k = static_cast<int>((indices >> (3 * t)) & 7);
    int v;
    if (k == 0) {
      v = a0;
    } else if (k == 1) {
      v = a1;
    } else if (a0 > a1) {
      v = lerp8(255 * (k - 1) / 7, a0, a1);
    } else if (k < 6) {
      v = lerp8(255 * (k - 1) / 5, a0, a1);
    } else {
      v = k == 6 ? 0 : 255;
    }
    values[t] = static_cast<std::uint8_t>(v);
  }
  return values;
}

// Rows r0 .. rows-1 of one half block (8 bytes) reversed in place; `kind` says how rows are
// laid out: BC1 colour (a byte of indices per row after 4 bytes of endpoints), BC2 alpha (two
// bytes per row), BC4 values (12 bits per row after 2 bytes of endpoints).
enum class HalfKind { Colour, ExplicitAlpha, Values };

void flipHalfBlockRows(HalfKind kind, int rows, std::uint8_t* half) {
  switch (kind) {
    case HalfKind::Colour:
      for (int a = 0, b = rows - 1; a < b; ++a, --b) std::swap(half[4 + a], half[4 + b]);
      break;
    case HalfKind::ExplicitAlpha:
      for (int a = 0, b = rows - 1; a < b; ++a, --b) {
        std::swap(half[2 * a], half[2 * b]);
        std::swap(half[2 * a + 1], half[2 * b + 1]);
      }
      break;
    case HalfKind::Values: {
      std::uint64_t bits = 0;
      for (int i = 0; i < 6; ++i) bits |= static_cast<std::uint64_t>(half[2 + i]) << (8 * i);
      constexpr std::uint64_t kRowMask = 0xFFF;  // 4 texels x 3 bits
      std::uint64_t flipped = bits;
      for (int r = 0; r < rows; ++r) {
        const std::uint64_t row = (bits >> (12 * r)) & kRowMask;
        const int to = rows - 1 - r;
        flipped = (flipped & ~(kRowMask << (12 * to))) | (row << (12 * to));
      }
      for (int i = 0; i < 6; ++i) half[2 + i] = static_cast<std::uint8_t>(flipped >> (8 * i));
      break;
    }
  }
}

void flipBlockRows(BlockFormat format, int rows, std::uint8_t* block) {
  switch (format) {
    case BlockFormat::Bc1: flipHalfBlockRows(HalfKind::Colour, rows, block); break;
    case BlockFormat::Bc2:
      flipHalfBlockRows(HalfKind::ExplicitAlpha, rows, block);
      flipHalfBlockRows(HalfKind::Colour, rows, block + kHalfBlockBytes);
      break;
    case BlockFormat::Bc3:
      flipHalfBlockRows(HalfKind::Values, rows, block);
      flipHalfBlockRows(HalfKind::Colour, rows, block + kHalfBlockBytes);
      break;
    case BlockFormat::Bc4: flipHalfBlockRows(HalfKind::Values, rows, block); break;
    case BlockFormat::Bc5:
      flipHalfBlockRows(HalfKind::Values, rows, block);
      flipHalfBlockRows(HalfKind::Values, rows, block + kHalfBlockBytes);
      break;
  }
}

}  // namespace

int blockBytes(BlockFormat format) {
  return format == BlockFormat::Bc1 || format == BlockFormat::Bc4 ? 8 : 16;
}

std::string_view toString(BlockFormat format) {
  switch (format) {
    case BlockFormat::Bc1: return "BC1 (DXT1)";
    case BlockFormat::Bc2: return "BC2 (DXT3)";
    case BlockFormat::Bc3: return "BC3 (DXT5)";
    case BlockFormat::Bc4: return "BC4 (RGTC1, ATI1)";
    case BlockFormat::Bc5: return "BC5 (RGTC2, ATI2)";
  }
  return "?";
}

std::size_t blockLevelBytes(BlockFormat format, int width, int height) {
  return static_cast<std::size_t>(blocksAlong(width)) * static_cast<std::size_t>(blocksAlong(height)) *
         static_cast<std::size_t>(blockBytes(format));
}

BlockTexels decodeBlock(BlockFormat format, const std::uint8_t* block) {
  BlockTexels out{};
  switch (format) {
    case BlockFormat::Bc1: decodeColourBlock(block, false, out); break;
    case BlockFormat::Bc2:
      decodeColourBlock(block + kHalfBlockBytes, true, out);
      for (int t = 0; t < kTexelsPerBlock; ++t) {
        const int nibble = (block[t / 2] >> (4 * (t & 1))) & 0xF;
        out[t][3] = static_cast<std::uint8_t>(nibble * 17);  // 4 -> 8 bits: (a << 4) | a
      }
      break;
    case BlockFormat::Bc3: {
      decodeColourBlock(block + kHalfBlockBytes, true, out);
      const std::array<std::uint8_t, 16> alpha = decodeValueBlock(block);
      for (int t = 0; t < kTexelsPerBlock; ++t) out[t][3] = alpha[t];
      break;
    }
    case BlockFormat::Bc4: {
      const std::array<std::uint8_t, 16> red = decodeValueBlock(block);
      for (int t = 0; t < kTexelsPerBlock; ++t) out[t] = {red[t], 0, 0, 255};
      break;
    }
    case BlockFormat::Bc5: {
      const std::array<std::uint8_t, 16> red = decodeValueBlock(block);
      const std::array<std::uint8_t, 16> green = decodeValueBlock(block + kHalfBlockBytes);
      for (int t = 0; t < kTexelsPerBlock; ++t) out[t] = {red[t], green[t], 0, 255};
      break;
    }
  }
  return out;
}

std::vector<std::uint8_t> decodeBlockLevel(BlockFormat format, int width, int height, const std::uint8_t* blocks) {
  std::vector<std::uint8_t> rgba(static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 4);
  const int across = blocksAlong(width), down = blocksAlong(height), bytes = blockBytes(format);
  for (int by = 0; by < down; ++by) {
    for (int bx = 0; bx < across; ++bx) {
      const BlockTexels texels = decodeBlock(format, blocks + (static_cast<std::size_t>(by) * across + bx) * bytes);
      for (int j = 0; j < kBlockSide && by * kBlockSide + j < height; ++j) {
        for (int i = 0; i < kBlockSide && bx * kBlockSide + i < width; ++i) {
          const std::size_t at = (static_cast<std::size_t>(by * kBlockSide + j) * width + bx * kBlockSide + i) * 4;
          std::memcpy(&rgba[at], texels[j * kBlockSide + i].data(), 4);
        }
      }
    }
  }
  return rgba;
}

std::optional<std::vector<std::uint8_t>> flipBlockLevelRows(BlockFormat format, int width, int height,
                                                            const std::uint8_t* blocks) {
  if (height > kBlockSide && height % kBlockSide != 0) return std::nullopt;
  const int across = blocksAlong(width), down = blocksAlong(height), bytes = blockBytes(format);
  const std::size_t rowBytes = static_cast<std::size_t>(across) * bytes;
  std::vector<std::uint8_t> out(rowBytes * down);
  const int rowsInBlock = height < kBlockSide ? height : kBlockSide;
  for (int by = 0; by < down; ++by) {
    std::uint8_t* row = &out[static_cast<std::size_t>(down - 1 - by) * rowBytes];
    std::memcpy(row, blocks + static_cast<std::size_t>(by) * rowBytes, rowBytes);
    for (int bx = 0; bx < across; ++bx) flipBlockRows(format, rowsInBlock, row + static_cast<std::size_t>(bx) * bytes);
  }
  return out;
}

}  // namespace twr
