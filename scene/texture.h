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
// loadPng + textureFromImage; throws InputError naming the file.
Texture loadTexture(const std::string& path);

}  // namespace twr
