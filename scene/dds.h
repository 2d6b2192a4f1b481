// DirectDraw Surface files (.dds): the 2D texture formats real assets ship in. Read:
//   - block-compressed BC1..BC5 by FourCC (DXT1, DXT2/DXT3, DXT4/DXT5, ATI1/BC4U, ATI2/BC5U)
//     or by a DX10 header's DXGI format (BC1..BC5 UNORM, BC1..BC3 UNORM_SRGB, typeless);
//   - uncompressed texels given by bit masks (RGB, RGBA, luminance, luminance + alpha, alpha;
//     8, 16, 24 or 32 bits per texel), as ImageMagick and older tools write them;
//   - the file's own mip chain (all of it, or the first N levels it holds).
// Refused with a message naming the file and what it holds: cube maps, volume textures,
// arrays, signed or float formats, BC6H/BC7, palettes, and any size or length that does not
// add up. The file's first row is the image's top row, as in every image file.
#pragma once

#include "scene/block_compression.h"

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace twr {

struct DdsLevel {
  int width = 0;
  int height = 0;
  // Compressed: the level's blocks as stored. Uncompressed: RGBA8 texels. Top row first.
  std::vector<std::uint8_t> data;
};

struct DdsFile {
  std::optional<BlockFormat> blockFormat;  // nullopt: uncompressed, decoded to RGBA8
  bool srgbInFile = false;                 // a DX10 *_UNORM_SRGB format
  std::string formatName;                  // "BC2 (DXT3)", "B8G8R8A8 (32-bit masks)": for messages
  std::vector<DdsLevel> levels;            // level 0 first, each side halved (at least 1)
  std::vector<std::string> warnings;       // what was read and ignored (one line each)
};

// "DDS " at the start.
bool isDds(const std::uint8_t* bytes, std::size_t size);
// Width and height from the header, without reading texels; false when there is none.
bool readDdsHeader(const std::uint8_t* bytes, std::size_t size, int& width, int& height);
// Throws InputError starting with nameForMessages.
DdsFile parseDds(const std::uint8_t* bytes, std::size_t size, const std::string& nameForMessages);

}  // namespace twr
