// Images and image files: PNG, JPEG, BMP and TGA through stb_image (libstb-dev), DDS through
// scene/dds.h, Radiance HDR (float) through stb_image; PNG writing through stb_image_write.
// Image pixels are stored top row first, as image files are.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace twr {

// Largest image or texture side we accept, in pixels (inclusive). Bounds memory:
// 16384^2 * 4 bytes = 1 GiB.
inline constexpr int kMaxImageSide = 16384;
// Most pixels a rendered image may have (inclusive): 8192 x 8192, or 16384 x 4096. `compare`
// holds about 65 bytes per pixel (two renders with depth and triangle ids, llvmpipe's own
// buffers, the per-pixel comparison, the heat, class and side-by-side images): 4.4 GB peak
// measured here (docs/compare.md, "Memory"). A side-by-side image of more would also pass the
// 2 GiB that stb_image_write's int sizes hold.
inline constexpr long long kMaxRenderPixels = 8192LL * 8192LL;

// Empty when a rendered image of this size is allowed: each side in [1, kMaxImageSide] and at
// most kMaxRenderPixels in all; else why not.
std::string renderSizeProblem(int width, int height);

struct Image {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> rgba;  // width * height * 4, top row first

  std::uint8_t* pixel(int x, int y) { return &rgba[(static_cast<std::size_t>(y) * width + x) * 4]; }
  const std::uint8_t* pixel(int x, int y) const {
    return &rgba[(static_cast<std::size_t>(y) * width + x) * 4];
  }
};

Image makeImage(int width, int height, std::uint32_t fillRgba = 0);

// Largest image file read (inclusive, bytes).
inline constexpr std::uintmax_t kMaxImageFileBytes = 256ull * 1024 * 1024;

// Linear floating-point RGBA (Radiance HDR), top row first; alpha 1.
struct ImageF {
  int width = 0;
  int height = 0;
  std::vector<float> rgba;  // width * height * 4
};

// Which format the first bytes announce. TGA has no signature: a file that none of the others
// claims (and that is not GIF, PSD, PIC or PNM, which are refused) is taken for a TGA.
enum class ImageFileFormat { Png, Jpeg, Bmp, Tga, Hdr, Dds, Unknown };
ImageFileFormat imageFileFormat(const std::uint8_t* bytes, std::size_t size);
std::string_view toString(ImageFileFormat format);

// Loads an 8-bit image converted to RGBA8: PNG (grey, grey + alpha, palette, RGB, RGBA; 8 or
// 16 bits, interlaced or not), JPEG (baseline and progressive), BMP (1 to 32 bits, no RLE),
// TGA (true colour, grey, colour-mapped, RLE or not) through stb_image, DDS (level 0,
// decoded; scene/dds.h). Radiance HDR is refused here (loadHdrImage reads it), so are the
// other formats stb knows and a side outside [1, kMaxImageSide], checked in the header before
// anything is decoded. Throws InputError naming the file and the reason.
Image loadPng(const std::string& path);
inline Image loadImage(const std::string& path) { return loadPng(path); }
// The same from bytes in memory; `nameForMessages` starts every error message.
Image decodeImage(const std::uint8_t* bytes, std::size_t size, const std::string& nameForMessages);
// Width and height from an image header, without decoding; false when there is none.
bool readImageHeader(const std::uint8_t* bytes, std::size_t size, int& width, int& height);
// Radiance HDR (RLE or flat RGBE) as linear floats; throws InputError naming the file.
ImageF decodeHdrImage(const std::uint8_t* bytes, std::size_t size, const std::string& nameForMessages);
ImageF loadHdrImage(const std::string& path);
// Throws InputError when the file cannot be written.
void savePng(const std::string& path, const Image& image);

// `size` bytes as a zlib stream (RFC 1950: what a browser's DecompressionStream("deflate")
// reads), with stb_image_write's compressor, the one its PNGs use. Throws std::length_error
// over 2 GiB (stb's sizes are int).
std::vector<std::uint8_t> zlibCompress(const std::uint8_t* data, std::size_t size);

}  // namespace twr
