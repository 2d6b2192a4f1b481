#include "scene/mip_level_view.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <mutex>
#include <sstream>
#include <string>

namespace twr {

namespace {

// One channel changes from each colour to the next (mip_level_view.h).
constexpr std::array<std::array<std::uint8_t, 3>, kMipLevelColourCount> kLevelColours{{
    {0, 0, 255},      // 0 blue
    {0, 255, 255},    // 1 cyan
    {0, 255, 0},      // 2 green
    {255, 255, 0},    // 3 yellow
    {255, 0, 0},      // 4 red
    {255, 0, 255},    // 5 magenta
    {255, 255, 255},  // 6 white
    {170, 170, 170},  // 7 light grey
    {85, 85, 85},     // 8 grey
    {0, 0, 0},        // 9 black
    {0, 0, 128},      // 10 navy
    {128, 0, 128},    // 11 purple
    {128, 0, 0},      // 12 maroon
}};

std::vector<std::uint8_t> solidLevel(int width, int height, const std::array<std::uint8_t, 3>& rgb) {
  std::vector<std::uint8_t> texels(static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 4);
  for (std::size_t i = 0; i < texels.size(); i += 4) {
    texels[i] = rgb[0];
    texels[i + 1] = rgb[1];
    texels[i + 2] = rgb[2];
    texels[i + 3] = 255;
  }
  return texels;
}

const Texture* firstMap(const Material& m) {
  if (m.diffuseMap) return m.diffuseMap.get();
  if (m.normalMap) return m.normalMap.get();
  return m.specularMap.get();
}

}  // namespace

std::array<std::uint8_t, 3> mipLevelColour(int level) {
  return kLevelColours[static_cast<std::size_t>(std::clamp(level, 0, kMipLevelColourCount - 1))];
}

std::optional<float> mipLevelFromColour(const std::array<std::uint8_t, 3>& rgb, int toleranceLevels) {
  std::optional<float> best;
  double bestDistance = static_cast<double>(toleranceLevels);
  for (int k = 0; k + 1 < kMipLevelColourCount; ++k) {
    const auto& a = kLevelColours[static_cast<std::size_t>(k)];
    const auto& b = kLevelColours[static_cast<std::size_t>(k + 1)];
    // The nearest point of segment a -> b: t = (p - a).(b - a) / |b - a|^2, clamped.
    double dot = 0.0, length2 = 0.0;
    for (int c = 0; c < 3; ++c) {
      const double d = static_cast<double>(b[static_cast<std::size_t>(c)]) - a[static_cast<std::size_t>(c)];
      dot += (static_cast<double>(rgb[static_cast<std::size_t>(c)]) - a[static_cast<std::size_t>(c)]) * d;
      length2 += d * d;
    }
    const double t = std::clamp(dot / length2, 0.0, 1.0);
    double distance = 0.0;
    for (int c = 0; c < 3; ++c) {
      const double onSegment = a[static_cast<std::size_t>(c)] +
                               t * (static_cast<double>(b[static_cast<std::size_t>(c)]) - a[static_cast<std::size_t>(c)]);
      distance = std::max(distance, std::fabs(onSegment - rgb[static_cast<std::size_t>(c)]));
    }
    if (distance <= bestDistance) {
      bestDistance = distance;
      best = static_cast<float>(k + t);
    }
  }
  return best;
}

std::shared_ptr<const Texture> mipLevelTexture(const Texture& like) {
  // The key: every level's size and the options that change sampling.
  // (A stream: GCC 12 for aarch64 warns falsely on "literal" + std::string under -Werror.)
  std::ostringstream keyStream;
  keyStream << std::hexfloat << static_cast<int>(like.options.wrap) << ':' << like.options.uvScale.x << ',' << like.options.uvScale.y
            << ',' << like.options.uvOffset.x << ',' << like.options.uvOffset.y;
  for (int level = 0; level < like.levelCount(); ++level) {
    keyStream << ';' << like.levelWidth(level) << 'x' << like.levelHeight(level);
  }
  const std::string key = keyStream.str();
  static std::mutex mutex;
  static std::map<std::string, std::shared_ptr<const Texture>> cache;
  const std::lock_guard<std::mutex> lock(mutex);
  if (const auto found = cache.find(key); found != cache.end()) return found->second;

  auto texture = std::make_shared<Texture>();
  texture->path = like.path;
  texture->path += " (mip_level view)";
  texture->formatName = "mip_level view";
  texture->width = like.width;
  texture->height = like.height;
  texture->rgba = solidLevel(like.width, like.height, mipLevelColour(0));
  for (int level = 1; level < like.levelCount(); ++level) {
    TextureLevel l;
    l.width = like.levelWidth(level);
    l.height = like.levelHeight(level);
    l.rgba = solidLevel(l.width, l.height, mipLevelColour(level));
    texture->mips.push_back(std::move(l));
  }
  texture->mipSource = like.mipSource;
  texture->options.wrap = like.options.wrap;
  texture->options.uvScale = like.options.uvScale;
  texture->options.uvOffset = like.options.uvOffset;
  cache.emplace(key, texture);
  return texture;
}

MipLevelView applyMipLevelView(std::vector<DrawItem>& items, RenderSettings& settings) {
  MipLevelView view;
  if (settings.view != View::MipLevel) return view;
  std::map<const Material*, const Material*> standIns;
  for (DrawItem& item : items) {
    auto [at, inserted] = standIns.emplace(item.material, nullptr);
    if (inserted) {
      auto m = std::make_unique<Material>();
      m->name = item.material->name;
      m->ka = m->kd = vec3(1.0f);
      m->ks = vec3(0.0f);
      if (const Texture* map = firstMap(*item.material)) {
        m->diffuseMap = mipLevelTexture(*map);
      } else {
        m->kd = kNoMapColour;
      }
      at->second = m.get();
      view.materials.push_back(std::move(m));
    }
    item.material = at->second;
  }
  settings.view = View::Albedo;
  return view;
}

}  // namespace twr
