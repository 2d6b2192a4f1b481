// Target "image_file": the bytes written to a file, then loadPng, loadTexture (default options
// and flipV + srgb) and decodeHdrImage on them.
#include "fuzz/support.h"
#include "fuzz/targets.h"

#include "scene/block_compression.h"
#include "scene/image.h"
#include "scene/texture.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <fstream>

namespace twr::fuzz {
namespace {

// The promises scene/texture.h makes about any texture loadTexture returns.
void checkTexture(const Texture& texture, const std::string& what) {
  require(texture.width >= 1 && texture.height >= 1 && texture.width <= kMaxImageSide && texture.height <= kMaxImageSide,
          what + ": texture is " + std::to_string(texture.width) + "x" + std::to_string(texture.height));
  int width = texture.width, height = texture.height;
  for (int level = 0; level < texture.levelCount(); ++level) {
    require(texture.levelWidth(level) == width && texture.levelHeight(level) == height,
            what + ": level " + std::to_string(level) + " is " + std::to_string(texture.levelWidth(level)) + "x" +
                std::to_string(texture.levelHeight(level)) + ", expected " + std::to_string(width) + "x" +
                std::to_string(height));
    require(texture.levelTexels(level).size() == static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 4,
            what + ": level " + std::to_string(level) + " has the wrong number of texel bytes");
    width = std::max(1, width / 2);
    height = std::max(1, height / 2);
  }
  // A chain, when there is one, goes down to 1x1 (built) or stops where the file stops.
  if (texture.mipSource == MipSource::Built) {
    require(texture.levelWidth(texture.levelCount() - 1) == 1 && texture.levelHeight(texture.levelCount() - 1) == 1,
            what + ": a built chain does not end at 1x1");
  }
  require((texture.mipSource == MipSource::None) == texture.mips.empty(), what + ": mipSource disagrees with the levels");
  if (texture.blockFormat) {
    require(texture.blockLevels.size() == static_cast<std::size_t>(texture.levelCount()),
            what + ": " + std::to_string(texture.blockLevels.size()) + " block levels for " +
                std::to_string(texture.levelCount()) + " levels");
    for (int level = 0; level < texture.levelCount(); ++level) {
      const int w = texture.levelWidth(level), h = texture.levelHeight(level);
      const std::vector<std::uint8_t>& blocks = texture.blockLevels[static_cast<std::size_t>(level)];
      require(blocks.size() == blockLevelBytes(*texture.blockFormat, w, h),
              what + ": block level " + std::to_string(level) + " has the wrong size");
      require(decodeBlockLevel(*texture.blockFormat, w, h, blocks.data()) == texture.levelTexels(level),
              what + ": block level " + std::to_string(level) + " does not decode to the level's texels");
    }
  } else {
    require(texture.blockLevels.empty(), what + ": block levels without a block format");
  }
}

}  // namespace

void fuzzImageFile(const Workspace& workspace, const std::uint8_t* data, std::size_t size) {
  const std::string path = (workspace.dir() / "fuzz.png").string();
  {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
    require(static_cast<bool>(out), "cannot write " + path);
  }

  // Radiance HDR: floats, finite and not negative (RGBE holds no sign), alpha 1.
  try {
    const ImageF hdr = decodeHdrImage(data, size, path);
    require(hdr.width >= 1 && hdr.height >= 1 && hdr.width <= kMaxImageSide && hdr.height <= kMaxImageSide,
            "decodeHdrImage accepted a " + std::to_string(hdr.width) + "x" + std::to_string(hdr.height) + " image");
    require(hdr.rgba.size() == static_cast<std::size_t>(hdr.width) * static_cast<std::size_t>(hdr.height) * 4,
            "HDR image buffer has the wrong size");
    for (std::size_t i = 0; i < hdr.rgba.size(); ++i) {
      require(std::isfinite(hdr.rgba[i]) && hdr.rgba[i] >= 0.0f, "HDR texel component is negative or not finite");
      if (i % 4 == 3) require(hdr.rgba[i] == 1.0f, "HDR alpha is not 1");
    }
  } catch (const InputError& error) {
    requireNamesInput(error, path);
  }

  Image image;
  try {
    image = loadPng(path);
  } catch (const InputError& error) {
    requireNamesInput(error, path);
    // loadTexture refuses what loadPng refuses (DDS included: level 0 is the same parse).
    try {
      (void)loadTexture(path);
    } catch (const InputError& textureError) {
      requireNamesInput(textureError, path);
      return;
    }
    require(false, "loadTexture accepted a file loadPng refuses: " + std::string(error.what()));
  }
  require(image.width >= 1 && image.height >= 1 && image.width <= kMaxImageSide && image.height <= kMaxImageSide,
          "loadPng accepted a " + std::to_string(image.width) + "x" + std::to_string(image.height) + " image");
  const std::size_t rowBytes = static_cast<std::size_t>(image.width) * 4;
  require(image.rgba.size() == rowBytes * static_cast<std::size_t>(image.height), "image buffer has the wrong size");

  // The same file as a texture: same size, rows in the opposite order.
  const Texture texture = loadTexture(path);
  checkTexture(texture, "default options");
  require(texture.width == image.width && texture.height == image.height, "texture size differs from the image's");
  require(texture.rgba.size() == image.rgba.size(), "texture buffer has the wrong size");
  for (int y = 0; y < image.height; ++y) {
    const std::size_t textureRow = static_cast<std::size_t>(y) * rowBytes;
    const std::size_t imageRow = static_cast<std::size_t>(image.height - 1 - y) * rowBytes;
    require(std::memcmp(&texture.rgba[textureRow], &image.rgba[imageRow], rowBytes) == 0,
            "texture row " + std::to_string(y) + " is not image row " + std::to_string(image.height - 1 - y));
  }

  // flipV + srgb: rows as the file has them, every level the default texture's level turned
  // around when the file brings its own chain (a built chain averages differently in sRGB).
  TextureOptions options;
  options.flipV = true;
  options.srgb = true;
  std::uintmax_t budget = kMaxSceneTextureBytes;
  const Texture flipped = loadTexture(path, options, budget);
  checkTexture(flipped, "flipV + srgb");
  require(flipped.width == image.width && flipped.height == image.height, "flipped texture size differs");
  require(flipped.rgba == image.rgba, "with flipV the texture's rows are not the file's rows");
  require(flipped.levelCount() == texture.levelCount(), "flipV changes the number of levels");
  require(budget == kMaxSceneTextureBytes - textureTexelBytes(flipped), "the budget did not shrink by the texels");
  if (texture.mipSource == MipSource::File) {
    for (int level = 1; level < texture.levelCount(); ++level) {
      const std::vector<std::uint8_t>& a = texture.levelTexels(level);
      const std::vector<std::uint8_t>& b = flipped.levelTexels(level);
      const int w = texture.levelWidth(level), h = texture.levelHeight(level);
      const std::size_t levelRow = static_cast<std::size_t>(w) * 4;
      for (int y = 0; y < h; ++y) {
        require(std::memcmp(&a[static_cast<std::size_t>(y) * levelRow], &b[static_cast<std::size_t>(h - 1 - y) * levelRow],
                            levelRow) == 0,
                "file level " + std::to_string(level) + " row " + std::to_string(y) + " is not turned around by flipV");
      }
    }
  }
}

}  // namespace twr::fuzz
