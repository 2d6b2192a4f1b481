#include "scene/image.h"

#include "scene/errors.h"

#include <stb_image.h>
#include <stb_image_write.h>

#include <cstring>
#include <filesystem>
#include <memory>

namespace twr {

Image makeImage(int width, int height, std::uint32_t fillRgba) {
  Image image;
  image.width = width;
  image.height = height;
  image.rgba.resize(static_cast<std::size_t>(width) * height * 4);
  for (std::size_t i = 0; i < image.rgba.size(); i += 4) {
    image.rgba[i + 0] = static_cast<std::uint8_t>(fillRgba >> 24);
    image.rgba[i + 1] = static_cast<std::uint8_t>(fillRgba >> 16);
    image.rgba[i + 2] = static_cast<std::uint8_t>(fillRgba >> 8);
    image.rgba[i + 3] = static_cast<std::uint8_t>(fillRgba);
  }
  return image;
}

Image loadPng(const std::string& path) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) {
    throw InputError(path + ": image file not found");
  }
  int width = 0, height = 0, channels = 0;
  // Check the header first so a huge declared size is refused before any allocation.
  if (!stbi_info(path.c_str(), &width, &height, &channels)) {
    const char* reason = stbi_failure_reason();
    throw InputError(path + ": not a readable image (" + (reason ? reason : "unknown") + ")");
  }
  if (width <= 0 || height <= 0 || width > kMaxImageSide || height > kMaxImageSide) {
    throw InputError(path + ": image is " + std::to_string(width) + "x" + std::to_string(height) +
                     ", expected each side in [1, " + std::to_string(kMaxImageSide) + "]");
  }
  std::unique_ptr<stbi_uc, void (*)(void*)> data(
      stbi_load(path.c_str(), &width, &height, &channels, 4), stbi_image_free);
  if (!data) {
    const char* reason = stbi_failure_reason();
    throw InputError(path + ": cannot decode image (" + (reason ? reason : "unknown") + ")");
  }
  Image image = makeImage(width, height);
  std::memcpy(image.rgba.data(), data.get(), image.rgba.size());
  return image;
}

void savePng(const std::string& path, const Image& image) {
  const std::filesystem::path parent = std::filesystem::path(path).parent_path();
  std::error_code ec;
  if (!parent.empty()) std::filesystem::create_directories(parent, ec);
  if (image.width <= 0 || image.height <= 0 ||
      !stbi_write_png(path.c_str(), image.width, image.height, 4, image.rgba.data(), image.width * 4)) {
    throw InputError(path + ": cannot write PNG");
  }
}

}  // namespace twr
