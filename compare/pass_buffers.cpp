#include "compare/pass_buffers.h"

#include "compare/colours.h"

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>

namespace twr {

namespace {

constexpr std::pair<PassBuffer, std::string_view> kNames[] = {
    {PassBuffer::ShadowMap, "shadow_map"},       {PassBuffer::GbufferDepth, "gbuffer_depth"},
    {PassBuffer::GbufferNormal, "gbuffer_normal"}, {PassBuffer::GbufferAlbedo, "gbuffer_albedo"},
    {PassBuffer::GbufferSpecular, "gbuffer_specular"}, {PassBuffer::GbufferEmission, "gbuffer_emission"},
    {PassBuffer::GbufferPosition, "gbuffer_position"},
    {PassBuffer::Lighting, "lighting"},          {PassBuffer::Final, "final"}};

// Gap between two layers in the side-by-side images, pixels.
constexpr int kLayerGapPx = 4;
constexpr std::uint32_t kGapRgba = 0x202020FFu;  // dark grey, opaque (0xRRGGBBAA)

// The texel of layer l at (x, y), rows bottom first.
std::size_t texelIndex(int x, int y, int layer, int width, int height) {
  return (static_cast<std::size_t>(layer) * static_cast<std::size_t>(height) + static_cast<std::size_t>(y)) *
             static_cast<std::size_t>(width) +
         static_cast<std::size_t>(x);
}

template <typename Colour>
Image layersImage(int width, int height, int layers, const Colour& colour) {
  Image image = makeImage(layers * width + (layers - 1) * kLayerGapPx, height, kGapRgba);
  for (int l = 0; l < layers; ++l) {
    for (int y = 0; y < height; ++y) {
      for (int x = 0; x < width; ++x) {
        const Rgb8 c = colour(texelIndex(x, y, l, width, height));
        std::uint8_t* p = image.pixel(l * (width + kLayerGapPx) + x, height - 1 - y);  // top row first
        p[0] = c.r;
        p[1] = c.g;
        p[2] = c.b;
        p[3] = 255;
      }
    }
  }
  return image;
}

// One channel of a G-buffer target as gbufferImage shows it, before clamping to [0, 1].
float shownChannel(float x, PassBuffer buffer) {
  if (buffer == PassBuffer::GbufferNormal) return 0.5f + 0.5f * x;
  if (buffer == PassBuffer::GbufferPosition) return std::fabs(2.0f * (0.5f * x - std::floor(0.5f * x)) - 1.0f);
  return x;
}

}  // namespace

std::string_view toString(PassBuffer buffer) {
  for (const auto& [b, name] : kNames) {
    if (b == buffer) return name;
  }
  return "?";
}

bool parse(std::string_view name, PassBuffer& out) {
  for (const auto& [b, n] : kNames) {
    if (n == name) {
      out = b;
      return true;
    }
  }
  return false;
}

std::string allPassBufferNames() {
  std::string names;
  for (const auto& [b, n] : kNames) names += (names.empty() ? "" : "|") + std::string(n);
  return names;
}

View viewOfBuffer(PassBuffer buffer, View sceneView) {
  if (buffer == PassBuffer::GbufferNormal) return View::Normal;
  if (buffer == PassBuffer::GbufferAlbedo) return View::Albedo;
  return sceneView;
}

std::string_view passOfBuffer(PassBuffer buffer) {
  switch (buffer) {
    case PassBuffer::ShadowMap: return "shadow";
    case PassBuffer::GbufferDepth:
    case PassBuffer::GbufferNormal:
    case PassBuffer::GbufferAlbedo:
    case PassBuffer::GbufferSpecular:
    case PassBuffer::GbufferEmission:
    case PassBuffer::GbufferPosition: return "gbuffer";
    case PassBuffer::Lighting: return "lighting";
    case PassBuffer::Final: return "final";
  }
  return "?";
}

const std::vector<vec4>* gbufferTargetOf(const GBuffer& g, PassBuffer buffer) {
  switch (buffer) {
    case PassBuffer::GbufferNormal: return &g.normal;
    case PassBuffer::GbufferAlbedo: return &g.albedo;
    case PassBuffer::GbufferSpecular: return &g.specular;
    case PassBuffer::GbufferEmission: return &g.emission;
    case PassBuffer::GbufferPosition: return g.position.empty() ? nullptr : &g.position;
    default: return nullptr;
  }
}

std::vector<float> gbufferPlanes(const std::vector<vec4>& target, int width, int height) {
  std::vector<float> planes(static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 3, 0.0f);
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      const std::size_t top = static_cast<std::size_t>(height - 1 - y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x);
      if (top >= target.size()) continue;
      for (int c = 0; c < 3; ++c) planes[texelIndex(x, y, c, width, height)] = target[top][c];
    }
  }
  return planes;
}

Image gbufferImage(const std::vector<vec4>& target, int width, int height, PassBuffer buffer) {
  Image image = makeImage(width, height, kGapRgba);
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      const std::size_t i = static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x);
      const vec4 v = i < target.size() ? target[i] : vec4(0.0f);
      std::uint8_t* p = image.pixel(x, y);
      // A position target's w is 1 where a surface was drawn: black elsewhere, not the wave's 1.
      const bool empty = buffer == PassBuffer::GbufferPosition && v.w == 0.0f;
      for (int c = 0; c < 3; ++c) {
        const float value = empty ? 0.0f : shownChannel(v[c], buffer);
        p[c] = static_cast<std::uint8_t>(std::lround(std::clamp(std::isfinite(value) ? value : 0.0f, 0.0f, 1.0f) * 255.0f));
      }
      p[3] = 255;
    }
  }
  return image;
}

std::optional<RenderOutput> bufferAsOutput(const RenderOutput& frame, PassBuffer buffer) {
  if (buffer == PassBuffer::Final) return frame;
  const std::vector<vec4>* target = frame.gbuffer ? gbufferTargetOf(*frame.gbuffer, buffer) : nullptr;
  if (buffer != PassBuffer::GbufferDepth && !target) return std::nullopt;
  RenderOutput out;
  out.width = frame.width;
  out.height = frame.height;
  out.depth = frame.depth;
  out.triangleId = frame.triangleId;
  out.lineMask = frame.lineMask;
  out.stats = frame.stats;
  if (target) {
    const Image image = gbufferImage(*target, frame.width, frame.height, buffer);
    out.rgba = image.rgba;
  } else {
    out.rgba.resize(frame.depth.size() * 4);
    for (std::size_t i = 0; i < frame.depth.size(); ++i) {
      const float d = frame.depth[i];
      const auto g = static_cast<std::uint8_t>(std::lround(std::clamp(std::isfinite(d) ? d : 0.0f, 0.0f, 1.0f) * 255.0f));
      out.rgba[4 * i + 0] = out.rgba[4 * i + 1] = out.rgba[4 * i + 2] = g;
      out.rgba[4 * i + 3] = 255;
    }
  }
  return out;
}

DepthBufferMetrics compareDepthBuffers(const std::vector<float>& a, const std::vector<float>& b, int width, int height,
                                       int layers, double tolerance) {
  DepthBufferMetrics m;
  m.width = width;
  m.height = height;
  m.layers = layers;
  m.tolerance = tolerance;
  double sum = 0.0;
  for (int l = 0; l < layers; ++l) {
    for (int y = 0; y < height; ++y) {
      for (int x = 0; x < width; ++x) {
        const std::size_t i = texelIndex(x, y, l, width, height);
        if (i >= a.size() || i >= b.size()) continue;
        if (!std::isfinite(a[i]) || !std::isfinite(b[i])) {
          ++m.nonFinite;
          continue;
        }
        const double d = std::fabs(static_cast<double>(a[i]) - static_cast<double>(b[i]));
        ++m.compared;
        sum += d;
        if (d > tolerance) ++m.overTolerance;
        if (d > m.maxAbsDiff) {
          m.maxAbsDiff = d;
          m.maxX = x;
          m.maxY = y;
          m.maxLayer = l;
        }
      }
    }
  }
  m.meanAbsDiff = m.compared > 0 ? sum / static_cast<double>(m.compared) : 0.0;
  return m;
}

Image depthLayersImage(const std::vector<float>& depth, int width, int height, int layers) {
  // Stretched over the depths drawn (below the clear value 1): a perspective map's depths
  // crowd near 1 and would all look white.
  float lo = 1.0f, hi = 0.0f;
  for (const float d : depth) {
    if (!std::isfinite(d) || d >= 1.0f) continue;
    lo = std::min(lo, d);
    hi = std::max(hi, d);
  }
  const float range = hi > lo ? hi - lo : 1.0f;
  return layersImage(width, height, layers, [&](std::size_t i) {
    const float d = i < depth.size() ? depth[i] : 1.0f;
    if (!std::isfinite(d)) return kColourCpuOnly;
    const float t = d >= 1.0f ? 1.0f : std::clamp((d - lo) / range, 0.0f, 1.0f);
    const auto g = static_cast<std::uint8_t>(std::lround(t * 255.0f));
    return Rgb8{g, g, g};
  });
}

Image depthDiffImage(const std::vector<float>& a, const std::vector<float>& b, int width, int height, int layers,
                     double tolerance) {
  const HeatRamp ramp;
  return layersImage(width, height, layers, [&](std::size_t i) {
    if (i >= a.size() || i >= b.size() || !std::isfinite(a[i]) || !std::isfinite(b[i])) return kColourCpuOnly;
    const double d = std::fabs(static_cast<double>(a[i]) - static_cast<double>(b[i]));
    // A difference of `tolerance` reaches the top of the ramp; any difference shows.
    const int levels = d == 0.0 ? 0 : std::clamp(static_cast<int>(std::ceil(255.0 * d / tolerance)), 1, 255);
    return heatColour(levels, ramp);
  });
}

nlohmann::json bufferRowToJson(const BufferRow& row) {
  nlohmann::json j = {{"buffer", std::string(toString(row.buffer))},
                      {"pass", std::string(passOfBuffer(row.buffer))},
                      {"available", row.available},
                      {"kind", row.floats ? "float" : row.depth ? "depth" : "colour"}};
  if (row.light >= 0) j["light"] = row.light;
  if (!row.available) {
    j["note"] = row.note;
    j["passes"] = nullptr;
    return j;
  }
  if (row.depth) {
    const DepthBufferMetrics& m = row.depthMetrics;
    j["width"] = m.width;
    j["height"] = m.height;
    j["layers"] = m.layers;
    j["compared"] = m.compared;
    j["non_finite"] = m.nonFinite;
    const std::string prefix = row.floats ? "" : "depth_";  // a G-buffer row: "max_diff" ...
    j[prefix + "max_diff"] = m.maxAbsDiff;
    j[prefix + "mean_diff"] = m.meanAbsDiff;
    j[prefix + "tolerance"] = m.tolerance;
    j["over_tolerance"] = m.overTolerance;
    j["max_at"] = {{"x", m.maxX}, {"y", m.maxY}, {"layer", m.maxLayer}};
  } else {
    const CompareMetrics& m = row.colourMetrics;
    j["width"] = m.width;
    j["height"] = m.height;
    j["max_abs_diff"] = m.maxAbsDiff;
    j["mean_abs_diff"] = m.meanAbsDiff;
    j["over_1"] = m.over1;
    j["over_3"] = m.over3;
    j["coverage_mismatch"] = m.coverageMismatch;
    j["depth_max_diff"] = m.depthMaxDiff;
  }
  j["passes"] = row.passes;
  return j;
}

}  // namespace twr
