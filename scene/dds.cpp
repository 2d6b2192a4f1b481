#include "scene/dds.h"

#include "scene/errors.h"
#include "scene/image.h"
#include "scene/read_file.h"

#include <bit>
#include <cstdio>
#include <cstring>

namespace twr {
namespace {

// Layout (Microsoft's DDS_HEADER, DDS_PIXELFORMAT, DDS_HEADER_DXT10), byte offsets from the
// start of the file: a 4-byte magic, a 124-byte header, an optional 20-byte DX10 header.
constexpr std::size_t kMagicBytes = 4;
constexpr std::uint32_t kHeaderBytes = 124;
constexpr std::uint32_t kPixelFormatBytes = 32;
constexpr std::size_t kDx10HeaderBytes = 20;
constexpr std::size_t kOffsetHeaderSize = 4, kOffsetFlags = 8, kOffsetHeight = 12, kOffsetWidth = 16,
                      kOffsetDepth = 24, kOffsetMipCount = 28, kOffsetPfSize = 76, kOffsetPfFlags = 80,
                      kOffsetFourCc = 84, kOffsetBitCount = 88, kOffsetRMask = 92, kOffsetGMask = 96,
                      kOffsetBMask = 100, kOffsetAMask = 104, kOffsetCaps = 108, kOffsetCaps2 = 112;
constexpr std::size_t kDataStart = kMagicBytes + kHeaderBytes;

// Header flags (dwFlags, ddspf.dwFlags, dwCaps, dwCaps2).
constexpr std::uint32_t kFlagMipCount = 0x20000, kFlagDepth = 0x800000;
constexpr std::uint32_t kPfAlphaPixels = 0x1, kPfAlpha = 0x2, kPfFourCc = 0x4, kPfPalette8 = 0x20, kPfRgb = 0x40,
                        kPfYuv = 0x200, kPfLuminance = 0x20000, kPfBumpDuDv = 0x80000;
constexpr std::uint32_t kCapsMipmap = 0x400000;
constexpr std::uint32_t kCaps2Cubemap = 0x200, kCaps2Volume = 0x200000;
// DX10 header fields.
constexpr std::uint32_t kDimensionTexture2d = 3;
constexpr std::uint32_t kMiscTextureCube = 0x4;

// DXGI_FORMAT values this reader knows.
enum Dxgi : std::uint32_t {
  kR8G8B8A8Unorm = 28, kR8G8B8A8UnormSrgb = 29,
  kBc1Typeless = 70, kBc1Unorm = 71, kBc1UnormSrgb = 72,
  kBc2Typeless = 73, kBc2Unorm = 74, kBc2UnormSrgb = 75,
  kBc3Typeless = 76, kBc3Unorm = 77, kBc3UnormSrgb = 78,
  kBc4Typeless = 79, kBc4Unorm = 80, kBc4Snorm = 81,
  kBc5Typeless = 82, kBc5Unorm = 83, kBc5Snorm = 84,
  kB8G8R8A8Unorm = 87, kB8G8R8X8Unorm = 88, kB8G8R8A8UnormSrgb = 91, kB8G8R8X8UnormSrgb = 93,
  kBc6hTypeless = 94, kBc6hSf16 = 96, kBc7Typeless = 97, kBc7UnormSrgb = 99,
};

std::uint32_t read32(const std::uint8_t* bytes, std::size_t at) {
  return static_cast<std::uint32_t>(bytes[at]) | (static_cast<std::uint32_t>(bytes[at + 1]) << 8) |
         (static_cast<std::uint32_t>(bytes[at + 2]) << 16) | (static_cast<std::uint32_t>(bytes[at + 3]) << 24);
}

constexpr std::uint32_t fourCc(const char (&s)[5]) {
  return static_cast<std::uint32_t>(static_cast<unsigned char>(s[0])) |
         (static_cast<std::uint32_t>(static_cast<unsigned char>(s[1])) << 8) |
         (static_cast<std::uint32_t>(static_cast<unsigned char>(s[2])) << 16) |
         (static_cast<std::uint32_t>(static_cast<unsigned char>(s[3])) << 24);
}

std::string hexOf(std::uint32_t value) {
  char hex[11];
  std::snprintf(hex, sizeof hex, "0x%08X", value);
  return hex;
}

std::string fourCcText(std::uint32_t code) {
  std::string text;
  for (int i = 0; i < 4; ++i) {
    const char c = static_cast<char>((code >> (8 * i)) & 0xFF);
    text += (c >= 0x20 && c < 0x7F) ? c : '?';
  }
  return "'" + text + "' (" + hexOf(code) + ")";
}

// One channel given by a bit mask: where it starts, how many bits, widened to 8 bits as
// round(v * 255 / (2^bits - 1)).
struct MaskChannel {
  std::uint32_t mask = 0;
  int shift = 0;
  int bits = 0;
  std::uint8_t fallback = 0;  // when the mask is 0

  std::uint8_t of(std::uint32_t texel) const {
    if (bits == 0) return fallback;
    const std::uint32_t v = (texel & mask) >> shift;
    if (bits == 8) return static_cast<std::uint8_t>(v);
    const std::uint64_t max = (std::uint64_t{1} << bits) - 1;
    return static_cast<std::uint8_t>((v * 255ull + max / 2) / max);
  }
};

struct Reader {
  const std::uint8_t* bytes;
  std::size_t size;
  const std::string& name;

  [[noreturn]] void fail(const std::string& what) const { throw InputError(name + ": DDS: " + what); }

  MaskChannel channel(std::uint32_t mask, std::uint8_t fallback, const char* which) const {
    MaskChannel c;
    c.fallback = fallback;
    if (mask == 0) return c;
    c.mask = mask;
    c.shift = std::countr_zero(mask);
    c.bits = std::popcount(mask);
    // A full 32-bit mask is one run too; 1 << 32 would be undefined (found by review).
    if (c.bits != 32 && (mask >> c.shift) != (std::uint32_t{1} << c.bits) - 1) {
      fail(std::string("the ") + which + " mask " + hexOf(mask) + " is not one run of bits");
    }
    if (c.bits > 16) fail(std::string("the ") + which + " channel has " + std::to_string(c.bits) + " bits (at most 16 read)");
    return c;
  }
};

}  // namespace

bool isDds(const std::uint8_t* bytes, std::size_t size) {
  return size >= kMagicBytes && std::memcmp(bytes, "DDS ", kMagicBytes) == 0;
}

bool readDdsHeader(const std::uint8_t* bytes, std::size_t size, int& width, int& height) {
  if (!isDds(bytes, size) || size < kDataStart) return false;
  const std::uint32_t w = read32(bytes, kOffsetWidth), h = read32(bytes, kOffsetHeight);
  if (w == 0 || h == 0 || w > static_cast<std::uint32_t>(kMaxImageSide) || h > static_cast<std::uint32_t>(kMaxImageSide)) {
    return false;
  }
  width = static_cast<int>(w);
  height = static_cast<int>(h);
  return true;
}

DdsFile parseDds(const std::uint8_t* bytes, std::size_t size, const std::string& nameForMessages) {
  const Reader in{bytes, size, nameForMessages};
  if (!isDds(bytes, size)) in.fail("the file does not start with 'DDS '");
  if (size < kDataStart) in.fail("the file ends inside its header (" + std::to_string(size) + " bytes, expected at least 128)");
  if (read32(bytes, kOffsetHeaderSize) != kHeaderBytes) {
    in.fail("header size " + std::to_string(read32(bytes, kOffsetHeaderSize)) + ", expected 124");
  }
  if (read32(bytes, kOffsetPfSize) != kPixelFormatBytes) {
    in.fail("pixel-format size " + std::to_string(read32(bytes, kOffsetPfSize)) + ", expected 32");
  }
  const std::uint32_t width = read32(bytes, kOffsetWidth), height = read32(bytes, kOffsetHeight);
  if (width == 0 || height == 0 || width > static_cast<std::uint32_t>(kMaxImageSide) ||
      height > static_cast<std::uint32_t>(kMaxImageSide)) {
    in.fail("image is " + std::to_string(width) + "x" + std::to_string(height) + ", expected each side in [1, " +
            std::to_string(kMaxImageSide) + "]");
  }
  const std::uint32_t flags = read32(bytes, kOffsetFlags), caps = read32(bytes, kOffsetCaps),
                      caps2 = read32(bytes, kOffsetCaps2), pfFlags = read32(bytes, kOffsetPfFlags);
  if (caps2 & kCaps2Cubemap) in.fail("a cube map (six faces); a material map takes a 2D texture");
  if ((caps2 & kCaps2Volume) || ((flags & kFlagDepth) && read32(bytes, kOffsetDepth) > 1)) {
    in.fail("a volume texture; a material map takes a 2D texture");
  }

  DdsFile file;
  std::size_t dataStart = kDataStart;
  std::optional<MaskChannel> r, g, b, a;  // uncompressed layouts
  int bytesPerTexel = 0;
  const std::uint32_t code = read32(bytes, kOffsetFourCc);
  if (pfFlags & kPfFourCc) {
    if (code == fourCc("DX10")) {
      if (size < kDataStart + kDx10HeaderBytes) in.fail("the file ends inside its DX10 header");
      dataStart += kDx10HeaderBytes;
      const std::uint32_t format = read32(bytes, kDataStart), dimension = read32(bytes, kDataStart + 4),
                          misc = read32(bytes, kDataStart + 8), arraySize = read32(bytes, kDataStart + 12);
      if (dimension != kDimensionTexture2d) {
        in.fail("DX10 resource dimension " + std::to_string(dimension) + ", expected 3 (a 2D texture)");
      }
      if (misc & kMiscTextureCube) in.fail("a cube map (six faces); a material map takes a 2D texture");
      if (arraySize > 1) in.fail("a texture array of " + std::to_string(arraySize) + " layers; a material map takes one");
      switch (format) {
        case kBc1Typeless: case kBc1Unorm: case kBc1UnormSrgb: file.blockFormat = BlockFormat::Bc1; break;
        case kBc2Typeless: case kBc2Unorm: case kBc2UnormSrgb: file.blockFormat = BlockFormat::Bc2; break;
        case kBc3Typeless: case kBc3Unorm: case kBc3UnormSrgb: file.blockFormat = BlockFormat::Bc3; break;
        case kBc4Typeless: case kBc4Unorm: file.blockFormat = BlockFormat::Bc4; break;
        case kBc5Typeless: case kBc5Unorm: file.blockFormat = BlockFormat::Bc5; break;
        case kR8G8B8A8Unorm: case kR8G8B8A8UnormSrgb:
          r = in.channel(0xFF, 0, "red"); g = in.channel(0xFF00, 0, "green");
          b = in.channel(0xFF0000, 0, "blue"); a = in.channel(0xFF000000u, 255, "alpha");
          bytesPerTexel = 4;
          file.formatName = "R8G8B8A8";
          break;
        case kB8G8R8A8Unorm: case kB8G8R8A8UnormSrgb: case kB8G8R8X8Unorm: case kB8G8R8X8UnormSrgb: {
          const bool hasAlpha = format == kB8G8R8A8Unorm || format == kB8G8R8A8UnormSrgb;
          r = in.channel(0xFF0000, 0, "red"); g = in.channel(0xFF00, 0, "green");
          b = in.channel(0xFF, 0, "blue"); a = in.channel(hasAlpha ? 0xFF000000u : 0, 255, "alpha");
          bytesPerTexel = 4;
          file.formatName = hasAlpha ? "B8G8R8A8" : "B8G8R8X8";
          break;
        }
        case kBc4Snorm: case kBc5Snorm: in.fail("signed BC4/BC5 (SNORM) is not read; save it as UNORM");
        default:
          if (format >= kBc6hTypeless && format <= kBc6hSf16) in.fail("BC6H (float HDR blocks) is not read");
          if (format >= kBc7Typeless && format <= kBc7UnormSrgb) in.fail("BC7 is not read; save it as BC1, BC3 or BC5");
          in.fail("DXGI format " + std::to_string(format) + " is not read (BC1-BC5 and 8-bit RGBA/BGRA are)");
      }
      file.srgbInFile = format == kBc1UnormSrgb || format == kBc2UnormSrgb || format == kBc3UnormSrgb ||
                        format == kR8G8B8A8UnormSrgb || format == kB8G8R8A8UnormSrgb || format == kB8G8R8X8UnormSrgb;
    } else if (code == fourCc("DXT1")) {
      file.blockFormat = BlockFormat::Bc1;
    } else if (code == fourCc("DXT2") || code == fourCc("DXT3")) {
      file.blockFormat = BlockFormat::Bc2;
      if (code == fourCc("DXT2")) file.warnings.push_back("DXT2 holds premultiplied alpha; read as DXT3 (straight alpha)");
    } else if (code == fourCc("DXT4") || code == fourCc("DXT5")) {
      file.blockFormat = BlockFormat::Bc3;
      if (code == fourCc("DXT4")) file.warnings.push_back("DXT4 holds premultiplied alpha; read as DXT5 (straight alpha)");
    } else if (code == fourCc("ATI1") || code == fourCc("BC4U")) {
      file.blockFormat = BlockFormat::Bc4;
    } else if (code == fourCc("ATI2") || code == fourCc("BC5U")) {
      file.blockFormat = BlockFormat::Bc5;
    } else if (code == fourCc("BC4S") || code == fourCc("BC5S")) {
      in.fail("signed BC4/BC5 is not read; save it as unsigned (ATI1/ATI2)");
    } else {
      in.fail("FourCC " + fourCcText(code) + " is not read (DXT1-DXT5, ATI1/BC4U, ATI2/BC5U and DX10 are)");
    }
  } else if (pfFlags & (kPfRgb | kPfLuminance | kPfAlpha)) {
    if (pfFlags & (kPfPalette8 | kPfYuv | kPfBumpDuDv)) in.fail("palette, YUV and bump (du/dv) layouts are not read");
    const std::uint32_t bitCount = read32(bytes, kOffsetBitCount);
    if (bitCount != 8 && bitCount != 16 && bitCount != 24 && bitCount != 32) {
      in.fail(std::to_string(bitCount) + " bits per texel, expected 8, 16, 24 or 32");
    }
    bytesPerTexel = static_cast<int>(bitCount / 8);
    const std::uint32_t alphaMask = (pfFlags & (kPfAlphaPixels | kPfAlpha)) ? read32(bytes, kOffsetAMask) : 0;
    a = in.channel(alphaMask, 255, "alpha");
    if (pfFlags & kPfRgb) {
      r = in.channel(read32(bytes, kOffsetRMask), 0, "red");
      g = in.channel(read32(bytes, kOffsetGMask), 0, "green");
      b = in.channel(read32(bytes, kOffsetBMask), 0, "blue");
      file.formatName = std::to_string(bitCount) + "-bit RGB" + (alphaMask ? "A" : "") + " (bit masks)";
    } else if (pfFlags & kPfLuminance) {
      r = g = b = in.channel(read32(bytes, kOffsetRMask), 0, "luminance");
      file.formatName = std::to_string(bitCount) + "-bit luminance" + (alphaMask ? " + alpha" : "");
    } else {
      r = g = b = MaskChannel{};  // alpha only: GL's ALPHA reads black
      file.formatName = std::to_string(bitCount) + "-bit alpha";
    }
  } else {
    in.fail("the pixel format has none of the FourCC, RGB, luminance or alpha flags");
  }
  if (file.blockFormat) file.formatName = std::string(toString(*file.blockFormat));

  // Levels: the header's count when the flags say it holds one (some writers set only one
  // of the two flags), at most a full chain.
  std::uint32_t levelCount = 1;
  const std::uint32_t declared = read32(bytes, kOffsetMipCount);
  if (((flags & kFlagMipCount) || (caps & kCapsMipmap)) && declared > 1) levelCount = declared;
  std::uint32_t fullChain = 1;
  for (std::uint32_t side = std::max(width, height); side > 1; side /= 2) ++fullChain;
  if (levelCount > fullChain) {
    file.warnings.push_back("the header declares " + std::to_string(levelCount) + " mip levels; a " +
                            std::to_string(width) + "x" + std::to_string(height) + " texture has at most " +
                            std::to_string(fullChain) + ", the rest are ignored");
    levelCount = fullChain;
  }

  std::size_t at = dataStart;
  int w = static_cast<int>(width), h = static_cast<int>(height);
  for (std::uint32_t level = 0; level < levelCount; ++level) {
    const std::size_t levelBytes = file.blockFormat
                                       ? blockLevelBytes(*file.blockFormat, w, h)
                                       : static_cast<std::size_t>(w) * static_cast<std::size_t>(h) * bytesPerTexel;
    if (size - at < levelBytes) {
      in.fail("the file ends inside mip level " + std::to_string(level) + " (" + std::to_string(w) + "x" +
              std::to_string(h) + ", " + describeBytes(levelBytes) + " from byte " + std::to_string(at) + ", " +
              std::to_string(size - at) + " bytes left)");
    }
    DdsLevel out;
    out.width = w;
    out.height = h;
    if (file.blockFormat) {
      out.data.assign(bytes + at, bytes + at + levelBytes);
    } else {
      out.data.resize(static_cast<std::size_t>(w) * static_cast<std::size_t>(h) * 4);
      for (std::size_t t = 0; t < static_cast<std::size_t>(w) * static_cast<std::size_t>(h); ++t) {
        std::uint32_t texel = 0;
        for (int i = 0; i < bytesPerTexel; ++i) texel |= static_cast<std::uint32_t>(bytes[at + t * bytesPerTexel + i]) << (8 * i);
        out.data[4 * t + 0] = r->of(texel);
        out.data[4 * t + 1] = g->of(texel);
        out.data[4 * t + 2] = b->of(texel);
        out.data[4 * t + 3] = a->of(texel);
      }
    }
    file.levels.push_back(std::move(out));
    at += levelBytes;
    w = std::max(1, w / 2);
    h = std::max(1, h / 2);
  }
  if (at < size) {
    file.warnings.push_back(std::to_string(size - at) + " bytes after the last mip level are ignored");
  }
  return file;
}

}  // namespace twr
