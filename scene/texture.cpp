#include "scene/texture.h"

#include "scene/dds.h"
#include "scene/errors.h"
#include "scene/read_file.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <limits>

namespace twr {
namespace {

constexpr std::array<std::pair<TextureWrap, std::string_view>, 3> kWrapNames{{
    {TextureWrap::Repeat, "repeat"}, {TextureWrap::MirroredRepeat, "mirrored_repeat"}, {TextureWrap::ClampToEdge, "clamp_to_edge"}}};
constexpr std::array<std::pair<GreenAxis, std::string_view>, 2> kGreenNames{{{GreenAxis::Up, "up"}, {GreenAxis::Down, "down"}}};

// Rows reversed in place (image files are top row first, textures bottom row first).
void flipRows(std::vector<std::uint8_t>& rgba, int width, int height) {
  const std::size_t rowBytes = static_cast<std::size_t>(width) * 4;
  for (int top = 0, bottom = height - 1; top < bottom; ++top, --bottom) {
    std::swap_ranges(rgba.begin() + static_cast<std::ptrdiff_t>(top * rowBytes),
                     rgba.begin() + static_cast<std::ptrdiff_t>((top + 1) * rowBytes),
                     rgba.begin() + static_cast<std::ptrdiff_t>(bottom * rowBytes));
  }
}

// The source texels one destination texel covers along a side of n -> m texels (m =
// max(1, n / 2)): destination i spans [i n / m, (i + 1) n / m) in source texels; weights are
// the overlap of each source texel with that span.
struct Footprint {
  int first = 0;
  std::vector<double> weights;  // for source texels first, first + 1, ...
};

std::vector<Footprint> footprintsAlong(int n, int m) {
  std::vector<Footprint> out(static_cast<std::size_t>(m));
  const double ratio = static_cast<double>(n) / m;
  for (int i = 0; i < m; ++i) {
    const double begin = i * ratio, end = (i + 1) * ratio;
    Footprint& f = out[static_cast<std::size_t>(i)];
    f.first = static_cast<int>(std::floor(begin));
    for (int s = f.first; s < n && s < end; ++s) {
      const double overlap = std::min(end, s + 1.0) - std::max(begin, static_cast<double>(s));
      if (overlap > 0.0) f.weights.push_back(overlap / ratio);
    }
  }
  return out;
}

TextureLevel halvedLevel(int width, int height, const std::vector<std::uint8_t>& rgba, bool srgb) {
  TextureLevel out;
  out.width = std::max(1, width / 2);
  out.height = std::max(1, height / 2);
  out.rgba.resize(static_cast<std::size_t>(out.width) * out.height * 4);
  const std::vector<Footprint> across = footprintsAlong(width, out.width);
  const std::vector<Footprint> down = footprintsAlong(height, out.height);
  // Each source byte as averaged: the byte itself, or with srgb its linear light (0..1).
  std::array<double, 256> linear{};
  for (int c = 0; c < 256; ++c) linear[static_cast<std::size_t>(c)] = srgb ? linearFromSrgb(c / 255.0) : c;
  for (int y = 0; y < out.height; ++y) {
    const Footprint& fy = down[static_cast<std::size_t>(y)];
    for (int x = 0; x < out.width; ++x) {
      const Footprint& fx = across[static_cast<std::size_t>(x)];
      std::array<double, 4> sum{};
      for (std::size_t j = 0; j < fy.weights.size(); ++j) {
        for (std::size_t i = 0; i < fx.weights.size(); ++i) {
          const double w = fy.weights[j] * fx.weights[i];
          const std::uint8_t* t =
              &rgba[(static_cast<std::size_t>(fy.first + static_cast<int>(j)) * width + fx.first + static_cast<int>(i)) * 4];
          for (int c = 0; c < 3; ++c) sum[static_cast<std::size_t>(c)] += w * linear[t[c]];
          sum[3] += w * t[3];
        }
      }
      std::uint8_t* o = &out.rgba[(static_cast<std::size_t>(y) * out.width + x) * 4];
      for (int c = 0; c < 4; ++c) {
        const double v = srgb && c < 3 ? srgbFromLinear(std::clamp(sum[static_cast<std::size_t>(c)], 0.0, 1.0)) * 255.0
                                       : sum[static_cast<std::size_t>(c)];
        o[c] = static_cast<std::uint8_t>(std::lround(std::clamp(v, 0.0, 255.0)));
      }
    }
  }
  return out;
}

// Checked on the header's size, before decoding: level 0 and, as every texture gets one, a
// chain of at most a third more.
void checkBudget(const std::string& path, int width, int height, std::uintmax_t budgetBytes) {
  const std::uintmax_t level0 = static_cast<std::uintmax_t>(width) * static_cast<std::uintmax_t>(height) * 4;
  const std::uintmax_t texelBytes = level0 + level0 / 3;
  if (texelBytes > budgetBytes) {
    throw InputError(path + ": image is " + std::to_string(width) + "x" + std::to_string(height) + " (" +
                     describeBytes(texelBytes) + " of texels with its mip chain), more than the " +
                     describeBytes(budgetBytes) +
                     " left of the scene's texture memory limit of " + describeBytes(kMaxSceneTextureBytes));
  }
}

// A DDS file into `texture` (levels from the file, blocks kept for GL when they can be turned
// around block-wise; otherwise GL gets the decoded texels).
void fillFromDds(Texture& texture, const std::uint8_t* bytes, std::size_t size, const std::string& path) {
  DdsFile file = parseDds(bytes, size, path);
  for (const std::string& w : file.warnings) texture.warnings.push_back(path + ": " + w);
  texture.formatName = "DDS " + file.formatName;
  const bool flip = !texture.options.flipV;
  if (file.blockFormat == BlockFormat::Bc4) texture.channels = TextureChannels::Red;
  if (file.blockFormat == BlockFormat::Bc5) texture.channels = TextureChannels::RedGreen;
  if (file.srgbInFile && !texture.options.srgb) {
    texture.warnings.push_back(path + ": the DDS format is marked sRGB; read as linear, as the texture's \"srgb\" "
                                      "is false");
  }
  bool keepBlocks = file.blockFormat.has_value() && file.levels.size() > 1;
  for (std::size_t i = 0; i < file.levels.size(); ++i) {
    DdsLevel& level = file.levels[i];
    TextureLevel out;
    out.width = level.width;
    out.height = level.height;
    if (file.blockFormat) {
      out.rgba = decodeBlockLevel(*file.blockFormat, level.width, level.height, level.data.data());
      if (keepBlocks) {
        if (flip) {
          std::optional<std::vector<std::uint8_t>> flipped =
              flipBlockLevelRows(*file.blockFormat, level.width, level.height, level.data.data());
          if (flipped) {
            texture.blockLevels.push_back(std::move(*flipped));
          } else {
            keepBlocks = false;
          }
        } else {
          texture.blockLevels.push_back(std::move(level.data));
        }
      }
    } else {
      out.rgba = std::move(level.data);
    }
    if (flip) flipRows(out.rgba, out.width, out.height);
    if (i == 0) {
      texture.width = out.width;
      texture.height = out.height;
      texture.rgba = std::move(out.rgba);
    } else {
      texture.mips.push_back(std::move(out));
    }
  }
  if (keepBlocks) {
    texture.blockFormat = file.blockFormat;
  } else {
    texture.blockLevels.clear();
  }
  texture.mipSource = texture.mips.empty() ? MipSource::None : MipSource::File;
}

}  // namespace

std::string_view toString(TextureWrap v) {
  for (const auto& [value, name] : kWrapNames) {
    if (value == v) return name;
  }
  return "?";
}
std::string_view toString(GreenAxis v) {
  for (const auto& [value, name] : kGreenNames) {
    if (value == v) return name;
  }
  return "?";
}
bool parse(std::string_view s, TextureWrap& out) {
  for (const auto& [value, name] : kWrapNames) {
    if (name == s) {
      out = value;
      return true;
    }
  }
  return false;
}
bool parse(std::string_view s, GreenAxis& out) {
  for (const auto& [value, name] : kGreenNames) {
    if (name == s) {
      out = value;
      return true;
    }
  }
  return false;
}

double linearFromSrgb(double c) { return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4); }
double srgbFromLinear(double linear) {
  return linear <= 0.0031308 ? linear * 12.92 : 1.055 * std::pow(linear, 1.0 / 2.4) - 0.055;
}

Texture textureFromImage(const Image& image, const std::string& path) {
  Texture texture;
  texture.path = path;
  texture.width = image.width;
  texture.height = image.height;
  texture.rgba = image.rgba;
  flipRows(texture.rgba, texture.width, texture.height);
  return texture;
}

void buildMipChain(Texture& texture) {
  texture.mips.clear();
  int width = texture.width, height = texture.height;
  const std::vector<std::uint8_t>* previous = &texture.rgba;
  while (width > 1 || height > 1) {
    texture.mips.push_back(halvedLevel(width, height, *previous, texture.options.srgb));
    width = texture.mips.back().width;
    height = texture.mips.back().height;
    previous = &texture.mips.back().rgba;
  }
  texture.mipSource = texture.mips.empty() ? MipSource::None : MipSource::Built;
}

std::uintmax_t textureTexelBytes(const Texture& texture) {
  std::uintmax_t bytes = texture.rgba.size();
  for (const TextureLevel& level : texture.mips) bytes += level.rgba.size();
  return bytes;
}

Texture loadTexture(const std::string& path, const TextureOptions& options, std::uintmax_t& budgetBytes) {
  std::error_code ec;
  // Not there at all; a path that cannot be looked up (a symlink loop, a name too long) is
  // left to readFileCapped, which says why.
  if (!std::filesystem::exists(path, ec) && !ec) throw InputError(path + ": image file not found");
  const std::string bytes = readFileCapped(path, kMaxImageFileBytes, "image file");
  const auto* data = reinterpret_cast<const std::uint8_t*>(bytes.data());
  int width = 0, height = 0;
  if (readImageHeader(data, bytes.size(), width, height) && width > 0 && height > 0) {
    checkBudget(path, width, height, budgetBytes);
  }
  Texture texture;
  texture.path = path;
  texture.options = options;
  const ImageFileFormat format = imageFileFormat(data, bytes.size());
  if (format == ImageFileFormat::Dds) {
    fillFromDds(texture, data, bytes.size(), path);
  } else {
    // Flipped in place and moved, not copied: a 16384^2 texture is 1 GiB.
    Image image = decodeImage(data, bytes.size(), path);
    texture.formatName = std::string(toString(format));
    texture.width = image.width;
    texture.height = image.height;
    texture.rgba = std::move(image.rgba);
    if (!options.flipV) flipRows(texture.rgba, texture.width, texture.height);
  }
  if (options.srgb && texture.channels != TextureChannels::Rgba) {
    texture.warnings.push_back(path + ": \"srgb\" is ignored: a one- or two-channel format (BC4/BC5) holds data, "
                                      "and GL has no sRGB form of it");
    texture.options.srgb = false;
  }
  if (texture.mips.empty()) {
    // The chain must fit too (a third more than level 0).
    const std::uintmax_t level0 = texture.rgba.size();
    if (level0 + level0 / 3 > budgetBytes) {
      throw InputError(path + ": image is " + std::to_string(texture.width) + "x" + std::to_string(texture.height) +
                       " (" + describeBytes(level0 + level0 / 3) + " of texels with its mip chain), more than the " +
                       describeBytes(budgetBytes) + " left of the scene's texture memory limit of " +
                       describeBytes(kMaxSceneTextureBytes));
    }
    buildMipChain(texture);
  }
  const std::uintmax_t total = textureTexelBytes(texture);
  if (total > budgetBytes) {
    throw InputError(path + ": " + describeBytes(total) + " of texels over all mip levels, more than the " +
                     describeBytes(budgetBytes) + " left of the scene's texture memory limit of " +
                     describeBytes(kMaxSceneTextureBytes));
  }
  budgetBytes -= total;
  return texture;
}

Texture loadTexture(const std::string& path, std::uintmax_t& budgetBytes) { return loadTexture(path, {}, budgetBytes); }

Texture loadTexture(const std::string& path) {
  std::uintmax_t unlimited = std::numeric_limits<std::uintmax_t>::max();
  return loadTexture(path, unlimited);
}

}  // namespace twr
