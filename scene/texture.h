// A texture as both renderers see it: RGBA8 texels, rows stored bottom row first (row 0 is
// v = 0), exactly the bytes glTexImage2D receives, level 0 and its mip chain. Sampling rules
// live in softrender/texture_sample.* (docs/textures.md has the whole story).
#pragma once

#include "scene/block_compression.h"
#include "scene/conventions.h"
#include "scene/image.h"

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace twr {

// GL_REPEAT, GL_MIRRORED_REPEAT, GL_CLAMP_TO_EDGE, in s and t alike.
enum class TextureWrap { Repeat, MirroredRepeat, ClampToEdge };
// Which way a normal map's green channel points in tangent space: up (+v, OpenGL and
// Blender's convention, the default) or down (Direct3D-style tools, some LearnOpenGL assets).
enum class GreenAxis { Up, Down };
// What a texel's channels hold as GL samples the texture: RGBA, or a one- / two-channel
// format (BC4, BC5) that GL returns as (r, 0, 0, 1) / (r, g, 0, 1).
enum class TextureChannels { Rgba, Red, RedGreen };

std::string_view toString(TextureWrap v);
std::string_view toString(GreenAxis v);
bool parse(std::string_view s, TextureWrap& out);
bool parse(std::string_view s, GreenAxis& out);

// How one use of an image file is read (the scene file's texture object). The defaults keep
// the pixels of every scene written before the options existed.
struct TextureOptions {
  bool flipV = false;  // false: the file's top row is v = 1 (as GL tutorials load images); true: v = 0
  TextureWrap wrap = TextureWrap::Repeat;
  bool srgb = false;   // colour textures: decode sRGB to linear before filtering, as GL_SRGB8_ALPHA8
  GreenAxis green = GreenAxis::Up;  // normal maps only (the shader flips the sampled green)
  // The map's own uv transform (an MTL's -s and -o): sampled at uv * uvScale + uvOffset.
  vec2 uvScale{1.0f};
  vec2 uvOffset{0.0f};
  bool operator==(const TextureOptions&) const = default;
};

struct TextureLevel {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> rgba;  // width * height * 4, bottom row first
};

// Where the levels after the first come from.
enum class MipSource { None, File, Built };

struct Texture {
  std::string path;  // where it came from, for messages and the UI
  int width = 0;     // level 0
  int height = 0;
  std::vector<std::uint8_t> rgba;  // level 0: width * height * 4, bottom row first
  // Levels 1, 2, ...: each side floor(previous / 2), at least 1. Empty for a texture built in
  // code; then every filter reads level 0 alone (GL_TEXTURE_MAX_LEVEL 0).
  std::vector<TextureLevel> mips;
  MipSource mipSource = MipSource::None;
  // Set when GL uploads the file's compressed blocks (one entry per level, rows bottom first,
  // each decoding to exactly the level's rgba); unset when GL receives the RGBA8 texels.
  std::optional<BlockFormat> blockFormat;
  std::vector<std::vector<std::uint8_t>> blockLevels;
  TextureChannels channels = TextureChannels::Rgba;
  TextureOptions options;
  std::string formatName;             // "PNG", "DDS BC2 (DXT3)": for the UI and `info`
  std::vector<std::string> warnings;  // read and ignored, one line each, naming the file

  const std::uint8_t* texel(int x, int y) const {
    return &rgba[(static_cast<std::size_t>(y) * width + x) * 4];
  }
  int levelCount() const { return 1 + static_cast<int>(mips.size()); }
  int levelWidth(int level) const { return level == 0 ? width : mips[static_cast<std::size_t>(level - 1)].width; }
  int levelHeight(int level) const { return level == 0 ? height : mips[static_cast<std::size_t>(level - 1)].height; }
  const std::vector<std::uint8_t>& levelTexels(int level) const {
    return level == 0 ? rgba : mips[static_cast<std::size_t>(level - 1)].rgba;
  }
};

// Flips an image file's top-first rows into texture order.
Texture textureFromImage(const Image& image, const std::string& path);
// Most texel memory one scene may load (inclusive, bytes of RGBA8 over every level, each
// file and option set counted once): twelve 4096^2 textures with their chains; the largest
// single one about 14000^2 (a 16384^2 image is 1 GiB before its chain).
inline constexpr std::uintmax_t kMaxSceneTextureBytes = 1024ull * 1024 * 1024;

// The mip chain GL's glGenerateMipmap would need, built the same way for both renderers
// (GL then receives every level, so no driver filter is involved): each texel of level i + 1
// is the area-weighted mean of the level-i texels its footprint covers (a 2x2 box when both
// sides are even; an odd side n -> floor(n / 2) spreads each texel over its share of
// n / floor(n / 2) texels), computed in double and rounded to nearest. With srgb the colour
// channels are averaged as linear light (decoded, averaged, encoded); alpha always linearly.
void buildMipChain(Texture& texture);

// Loads PNG, JPEG, BMP, TGA or DDS; throws InputError naming the file. DDS keeps its own mip
// chain (and its blocks for GL when the rows can be turned around block-wise); other files
// get buildMipChain. The size in the header is checked against `budgetBytes` before
// decoding; on success `budgetBytes` shrinks by the texels of every level.
Texture loadTexture(const std::string& path, const TextureOptions& options, std::uintmax_t& budgetBytes);
Texture loadTexture(const std::string& path, std::uintmax_t& budgetBytes);
Texture loadTexture(const std::string& path);

// Bytes of RGBA8 over every level.
std::uintmax_t textureTexelBytes(const Texture& texture);

// sRGB <-> linear as GL defines them (EXT_texture_sRGB): c <= 0.04045 ? c / 12.92
// : ((c + 0.055) / 1.055)^2.4, and the inverse; in double.
double linearFromSrgb(double c);
double srgbFromLinear(double linear);

}  // namespace twr
