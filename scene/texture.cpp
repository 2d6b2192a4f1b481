#include "scene/texture.h"

#include "scene/errors.h"
#include "scene/read_file.h"

#include <algorithm>
#include <cstring>
#include <filesystem>
#include <limits>

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

Texture loadTexture(const std::string& path, std::uintmax_t& budgetBytes) {
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) throw InputError(path + ": image file not found");
  const std::string bytes = readFileCapped(path, kMaxImageFileBytes, "image file");
  const auto* data = reinterpret_cast<const std::uint8_t*>(bytes.data());
  int width = 0, height = 0;
  if (readImageHeader(data, bytes.size(), width, height) && width > 0 && height > 0) {
    const std::uintmax_t texelBytes = static_cast<std::uintmax_t>(width) * static_cast<std::uintmax_t>(height) * 4;
    if (texelBytes > budgetBytes) {
      throw InputError(path + ": image is " + std::to_string(width) + "x" + std::to_string(height) + " (" +
                       describeBytes(texelBytes) + " of texels), more than the " + describeBytes(budgetBytes) +
                       " left of the scene's texture memory limit of " + describeBytes(kMaxSceneTextureBytes));
    }
  }
  // Flipped in place and moved, not copied: a 16384^2 texture is 1 GiB.
  Image image = decodeImage(data, bytes.size(), path);
  const std::size_t rowBytes = static_cast<std::size_t>(image.width) * 4;
  for (int top = 0, bottom = image.height - 1; top < bottom; ++top, --bottom) {
    const auto row = [&](int y) { return image.rgba.begin() + static_cast<std::ptrdiff_t>(static_cast<std::size_t>(y) * rowBytes); };
    std::swap_ranges(row(top), row(top + 1), row(bottom));
  }
  budgetBytes -= std::min<std::uintmax_t>(budgetBytes, image.rgba.size());
  Texture texture;
  texture.path = path;
  texture.width = image.width;
  texture.height = image.height;
  texture.rgba = std::move(image.rgba);
  return texture;
}

Texture loadTexture(const std::string& path) {
  std::uintmax_t unlimited = std::numeric_limits<std::uintmax_t>::max();
  return loadTexture(path, unlimited);
}

}  // namespace twr
