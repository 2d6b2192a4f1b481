#include "scene/horizon_map.h"

#include "scene/height_field.h"
#include "scene/scene.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <thread>
#include <vector>

namespace twr {

vec2 horizonDirectionUv(int k, int directions) {
  // Diamond angle a in [0, 4): quadrant floor(a), and the fraction q = |y| / (|x| + |y|).
  const float a = 4.0f * static_cast<float>(k) / static_cast<float>(directions);
  const int quadrant = static_cast<int>(a);
  const float q = a - static_cast<float>(quadrant);
  switch (quadrant) {
    case 0: return vec2(1.0f - q, q);
    case 1: return vec2(-q, 1.0f - q);
    case 2: return vec2(-(1.0f - q), -q);
    default: return vec2(q, -(1.0f - q));
  }
}

HorizonMap makeHorizonMap(const Texture& heightMap, float heightScale, int directions) {
  HorizonMap horizon;
  horizon.directions = directions;
  const int w = heightMap.width, h = heightMap.height;
  // One step is one texel of the finer axis, in uv.
  const double step = 1.0 / std::max(w, h);
  std::vector<Texture> textures(static_cast<std::size_t>(directions / 4));
  for (std::size_t i = 0; i < textures.size(); ++i) {
    Texture& t = textures[i];
    t.path = heightMap.path + " (horizon map, azimuths " + std::to_string(4 * i) + "-" + std::to_string(4 * i + 3) + ")";
    t.width = w;
    t.height = h;
    t.rgba.assign(static_cast<std::size_t>(w) * static_cast<std::size_t>(h) * 4, 0);
    t.options.wrap = heightMap.options.wrap;
    t.options.srgb = false;
    t.formatName = "horizon map (RGBA8, sine of the horizon elevation)";
  }
  // Rows are independent: split across the cores (1.7 s on one core at 512 x 512 x 8).
  const auto buildRows = [&](int rowBegin, int rowEnd) {
    for (int k = 0; k < directions; ++k) {
      const vec2 diamond = horizonDirectionUv(k, directions);
      const double length = std::hypot(static_cast<double>(diamond.x), static_cast<double>(diamond.y));
      const double dx = diamond.x / length, dy = diamond.y / length;
      Texture& target = textures[static_cast<std::size_t>(k / 4)];
      const int channel = k % 4;
      for (int y = rowBegin; y < rowEnd; ++y) {
        for (int x = 0; x < w; ++x) {
          const double u = (x + 0.5) / w, v = (y + 0.5) / h;
          const double h0 = heightAt(heightMap, glm::dvec2(u, v));  // the texel centre
          double slope = 0.0;  // the steepest rise seen, texture-space units per uv unit
          for (int s = 1; s <= kHorizonReachTexels; ++s) {
            const double distance = s * step;
            const double rise = (heightAt(heightMap, glm::dvec2(u + dx * distance, v + dy * distance)) - h0) * heightScale;
            slope = std::max(slope, rise / distance);
          }
          const double sine = slope / std::sqrt(1.0 + slope * slope);
          target.rgba[(static_cast<std::size_t>(y) * w + x) * 4 + channel] =
              static_cast<std::uint8_t>(std::lround(std::clamp(sine, 0.0, 1.0) * 255.0));
        }
      }
    }
  };
  const int threads = std::clamp(static_cast<int>(std::thread::hardware_concurrency()), 1, std::max(1, h));
  std::vector<std::thread> workers;
  for (int i = 1; i < threads; ++i) workers.emplace_back(buildRows, h * i / threads, h * (i + 1) / threads);
  buildRows(0, h / threads);
  for (std::thread& worker : workers) worker.join();
  for (Texture& t : textures) {
    buildMipChain(t);
    horizon.textures.push_back(std::make_shared<const Texture>(std::move(t)));
  }
  return horizon;
}

}  // namespace twr
