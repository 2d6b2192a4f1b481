// Target "image_file": loadPng and loadTexture on the bytes written to a file.
#include "fuzz/support.h"
#include "fuzz/targets.h"

#include "scene/image.h"
#include "scene/texture.h"

#include <cstring>
#include <fstream>

namespace twr::fuzz {

void fuzzImageFile(const Workspace& workspace, const std::uint8_t* data, std::size_t size) {
  const std::string path = (workspace.dir() / "fuzz.png").string();
  {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
    require(static_cast<bool>(out), "cannot write " + path);
  }
  Image image;
  try {
    image = loadPng(path);
  } catch (const InputError& error) {
    requireNamesInput(error, path);
    return;
  }
  require(image.width >= 1 && image.height >= 1 && image.width <= kMaxImageSide && image.height <= kMaxImageSide,
          "loadPng accepted a " + std::to_string(image.width) + "x" + std::to_string(image.height) + " image");
  const std::size_t rowBytes = static_cast<std::size_t>(image.width) * 4;
  require(image.rgba.size() == rowBytes * static_cast<std::size_t>(image.height), "image buffer has the wrong size");

  // The same file as a texture: same size, rows in the opposite order.
  const Texture texture = loadTexture(path);
  require(texture.width == image.width && texture.height == image.height, "texture size differs from the image's");
  require(texture.rgba.size() == image.rgba.size(), "texture buffer has the wrong size");
  for (int y = 0; y < image.height; ++y) {
    const std::size_t textureRow = static_cast<std::size_t>(y) * rowBytes;
    const std::size_t imageRow = static_cast<std::size_t>(image.height - 1 - y) * rowBytes;
    require(std::memcmp(&texture.rgba[textureRow], &image.rgba[imageRow], rowBytes) == 0,
            "texture row " + std::to_string(y) + " is not image row " + std::to_string(image.height - 1 - y));
  }
}

}  // namespace twr::fuzz
