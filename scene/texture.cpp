#include "scene/texture.h"

#include <cstring>

namespace twr {

Texture textureFromImage(const Image& image, const std::string& path) {
  Texture texture;
  texture.path = path;
  texture.width = image.width;
  texture.height = image.height;
  texture.rgba.resize(image.rgba.size());
  const std::size_t rowBytes = static_cast<std::size_t>(image.width) * 4;
  for (int y = 0; y < image.height; ++y) {
    std::memcpy(&texture.rgba[static_cast<std::size_t>(y) * rowBytes],
                &image.rgba[static_cast<std::size_t>(image.height - 1 - y) * rowBytes], rowBytes);
  }
  return texture;
}

Texture loadTexture(const std::string& path) { return textureFromImage(loadPng(path), path); }

}  // namespace twr
