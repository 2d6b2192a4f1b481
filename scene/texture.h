// A texture as both renderers see it: RGBA8, rows stored bottom row first (row 0 is v = 0),
// exactly the bytes glTexImage2D receives. Sampling rules live in softrender/texture_sample.*
// (GL_REPEAT, texel centres at +0.5, GL's bilinear weights).
#pragma once

#include "scene/image.h"

#include <cstdint>
#include <string>
#include <vector>

namespace twr {

struct Texture {
  std::string path;  // where it came from, for messages and the UI
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> rgba;  // width * height * 4, bottom row first

  const std::uint8_t* texel(int x, int y) const {
    return &rgba[(static_cast<std::size_t>(y) * width + x) * 4];
  }
};

// Flips an image file's top-first rows into texture order.
Texture textureFromImage(const Image& image, const std::string& path);
// Most texel memory one scene may load (inclusive, bytes of RGBA8, each file counted once):
// one 16384^2 texture or sixteen 4096^2 ones.
inline constexpr std::uintmax_t kMaxSceneTextureBytes = 1024ull * 1024 * 1024;

// loadPng + textureFromImage; throws InputError naming the file.
Texture loadTexture(const std::string& path);
// The same, counted against a budget: the size in the image's header is checked first, so an
// image whose texels (width * height * 4 bytes) exceed `budgetBytes` is refused before it is
// decoded; on success `budgetBytes` shrinks by that much.
Texture loadTexture(const std::string& path, std::uintmax_t& budgetBytes);

}  // namespace twr
