// RGBA8 images and PNG I/O (stb_image / stb_image_write from libstb-dev).
// Image pixels are stored top row first, as image files are.
#pragma once

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

// Loads any PNG stb understands (grey, palette, 16-bit are converted to RGBA8).
// Throws InputError naming the file and the reason.
Image loadPng(const std::string& path);
// Throws InputError when the file cannot be written.
void savePng(const std::string& path, const Image& image);

}  // namespace twr
