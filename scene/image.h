// RGBA8 images and PNG I/O (stb_image / stb_image_write from libstb-dev).
// Image pixels are stored top row first, as image files are.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace twr {

// Largest image or texture side we accept, in pixels (inclusive). Bounds memory:
// 16384^2 * 4 bytes = 1 GiB.
inline constexpr int kMaxImageSide = 16384;

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

// Loads a PNG (grey, grey + alpha, palette, RGB, RGBA; 8 or 16 bits, interlaced or not) or a
// JPEG through stb_image, converted to RGBA8; other formats stb knows are refused, as is a
// side outside [1, kMaxImageSide], checked in the header before anything is decoded.
// Throws InputError naming the file and the reason.
Image loadPng(const std::string& path);
// The same from bytes in memory; `nameForMessages` starts every error message.
Image decodeImage(const std::uint8_t* bytes, std::size_t size, const std::string& nameForMessages);
// Width and height from a PNG or JPEG header, without decoding; false when there is none.
bool readImageHeader(const std::uint8_t* bytes, std::size_t size, int& width, int& height);
// Throws InputError when the file cannot be written.
void savePng(const std::string& path, const Image& image);

}  // namespace twr
