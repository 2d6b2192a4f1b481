#include "raytrace/ssr_reference.h"

#include "scene/errors.h"
#include "softrender/shade.h"
#include "softrender/ssr.h"
#include "softrender/vertex.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <thread>

namespace twr {

const char* toString(SsrTruth truth) {
  switch (truth) {
    case SsrTruth::None: return "none";
    case SsrTruth::Sky: return "sky";
    case SsrTruth::Visible: return "visible";
    case SsrTruth::OffScreen: return "off_screen";
    case SsrTruth::Occluded: return "occluded";
  }
  return "?";
}

const char* toString(SsrErrorClass c) {
  switch (c) {
    case SsrErrorClass::Sky: return "sky";
    case SsrErrorClass::Visible: return "visible";
    case SsrErrorClass::OffScreen: return "off_screen";
    case SsrErrorClass::Occluded: return "occluded";
    case SsrErrorClass::IndirectOnly: return "indirect_only";
  }
  return "?";
}

std::array<std::uint8_t, 3> ssrErrorClassColour(SsrErrorClass c) {
  switch (c) {
    case SsrErrorClass::Sky: return {150, 150, 150};
    case SsrErrorClass::Visible: return {50, 200, 60};
    case SsrErrorClass::OffScreen: return {240, 215, 30};
    case SsrErrorClass::Occluded: return {225, 40, 40};
    case SsrErrorClass::IndirectOnly: return {50, 90, 230};
  }
  return {0, 0, 0};
}

RenderSettings ssrBaseSettings(const RenderSettings& settings) {
  RenderSettings base = settings;
  base.ssr.enabled = false;
  base.pipeline = Pipeline::Deferred;
  base.view = View::Shaded;
  base.tbnLines.enabled = false;
  return base;
}

struct HitShader::Items {
  // The draw items and their shading, in flattenScene's order (first triangle ids ascending).
  struct Item {
    const DrawItem* item = nullptr;
    VertexUniforms vertex;
    ShadeUniforms shade;
    ShaderKey key;
  };
  std::vector<DrawItem> items;
  std::vector<Item> shading;
};

HitShader::HitShader(const Scene& scene, const RenderSettings& settings, const ShadowMaps& shadows, int width,
                     int height)
    : items_(std::make_unique<Items>()) {
  items_->items = flattenScene(scene);
  RenderSettings forward = ssrBaseSettings(settings);
  forward.pipeline = Pipeline::Forward;
  const mat4 clipFromWorld = clipFromWorldFor(scene.camera, width, height);
  items_->shading.reserve(items_->items.size());
  for (const DrawItem& item : items_->items) {
    Items::Item s;
    s.item = &item;
    s.vertex = makeVertexUniforms(item.worldFromModel, clipFromWorld, scene, forward);
    s.shade = makeShadeUniforms(*item.material, scene, forward);
    setShadowUniforms(s.shade, shadows);
    s.key = shaderKeyFor(s.shade, forward);
    items_->shading.push_back(s);
  }
}

HitShader::~HitShader() = default;

glm::dvec3 HitShader::litAt(const RayHit& hit) const {
  const std::vector<DrawItem>& items = items_->items;
  const auto after = std::upper_bound(items.begin(), items.end(), hit.triangleId,
                                      [](std::uint32_t id, const DrawItem& item) { return id < item.firstTriangleId; });
  if (after == items.begin()) return glm::dvec3(0.0);
  const Items::Item& s = items_->shading[static_cast<std::size_t>(after - items.begin()) - 1];
  const Mesh& mesh = *s.item->mesh;
  const std::size_t t = hit.triangleId - s.item->firstTriangleId;
  if (t >= mesh.triangleCount()) return glm::dvec3(0.0);
  std::array<ClipVertex, 3> v;
  for (std::size_t c = 0; c < 3; ++c) v[c] = runVertexStage(mesh.vertices[mesh.indices[3 * t + c]], s.vertex);
  const float w0 = static_cast<float>(1.0 - hit.u - hit.v), w1 = static_cast<float>(hit.u),
              w2 = static_cast<float>(hit.v);
  Fragment f;
  f.posWorld = v[0].posWorld * w0 + v[1].posWorld * w1 + v[2].posWorld * w2;
  f.nWorld = v[0].nWorld * w0 + v[1].nWorld * w1 + v[2].nWorld * w2;
  f.tWorld = v[0].tWorld * w0 + v[1].tWorld * w1 + v[2].tWorld * w2;
  f.bWorld = v[0].bWorld * w0 + v[1].bWorld * w1 + v[2].bWorld * w2;
  f.uv = v[0].uv * w0 + v[1].uv * w1 + v[2].uv * w2;
  for (std::size_t l = 0; l < kMaxLights; ++l) {
    f.lightDirTangent[l] = v[0].lightDirTangent[l] * w0 + v[1].lightDirTangent[l] * w1 + v[2].lightDirTangent[l] * w2;
  }
  f.eyeDirTangent = v[0].eyeDirTangent * w0 + v[1].eyeDirTangent * w1 + v[2].eyeDirTangent * w2;
  const vec4 c = shadeFragmentDynamic(s.key, f, s.shade, nullptr);
  return glm::clamp(glm::dvec3(c.x, c.y, c.z), 0.0, 1.0);
}

namespace {

// What one traced ray met and the light it brings (linear [0, 1] colour; 0 for the sky).
struct TracedRay {
  SsrTruth truth = SsrTruth::Sky;
  glm::dvec3 light{0.0};
};

class Tracer {
 public:
  Tracer(const Scene& scene, const RenderSettings& settings, const RenderOutput& base, const RayScene& rays)
      : base_(base), rays_(rays), shader_(scene, settings, base.shadowMaps, base.width, base.height),
        width_(base.width), height_(base.height) {
    clipFromWorld_ = glm::dmat4(clipFromWorldFor(scene.camera, width_, height_));
    worldFromClip_ = glm::inverse(clipFromWorld_);
    eye_ = glm::dvec3(scene.camera.position);
    tMin_ = kSsrRayStartShare * std::max(rays.extent(), 1e-3);
  }

  // The world position of pixel i (top row first): the G-buffer's, or rebuilt from the depth.
  glm::dvec3 positionAt(std::size_t i, int x, int yTop) const {
    const GBuffer& g = *base_.gbuffer;
    if (!g.position.empty()) return glm::dvec3(vec3(g.position[i]));
    const double yGl = static_cast<double>(height_ - 1 - yTop);
    const glm::dvec4 ndc((static_cast<double>(x) + 0.5) / width_ * 2.0 - 1.0, (yGl + 0.5) / height_ * 2.0 - 1.0,
                         2.0 * static_cast<double>(base_.depth[i]) - 1.0, 1.0);
    const glm::dvec4 p = worldFromClip_ * ndc;
    return glm::dvec3(p) / p.w;
  }

  TracedRay trace(const glm::dvec3& origin, const glm::dvec3& dir) const {
    TracedRay out;
    const RayHit hit = rays_.intersect(origin, dir, tMin_, std::numeric_limits<double>::infinity());
    if (!hit.hit) return out;
    const glm::dvec3 p = origin + dir * hit.t;
    const glm::dvec4 clip = clipFromWorld_ * glm::dvec4(p, 1.0);
    const glm::dvec3 ndc = glm::dvec3(clip) / clip.w;
    const bool inside = clip.w > 0.0 && std::abs(ndc.x) <= 1.0 && std::abs(ndc.y) <= 1.0 && std::abs(ndc.z) <= 1.0;
    if (inside) {
      const int x = std::clamp(static_cast<int>(std::floor((ndc.x * 0.5 + 0.5) * width_)), 0, width_ - 1);
      const int yGl = std::clamp(static_cast<int>(std::floor((ndc.y * 0.5 + 0.5) * height_)), 0, height_ - 1);
      const int yTop = height_ - 1 - yGl;
      const std::size_t i = static_cast<std::size_t>(yTop) * static_cast<std::size_t>(width_) + static_cast<std::size_t>(x);
      bool shown = base_.triangleId[i] == hit.triangleId;
      if (!shown && base_.triangleId[i] != kNoTriangle) {
        const glm::dvec4 there = clipFromWorld_ * glm::dvec4(positionAt(i, x, yTop), 1.0);
        shown = std::abs(there.w - clip.w) <= kSsrVisibleDistanceShare * clip.w;
      }
      if (shown) {
        out.truth = SsrTruth::Visible;
        for (int c = 0; c < 3; ++c) out.light[c] = base_.rgba[4 * i + static_cast<std::size_t>(c)] / 255.0;
        return out;
      }
      out.truth = SsrTruth::Occluded;
    } else {
      out.truth = SsrTruth::OffScreen;
    }
    out.light = shader_.litAt(hit);
    return out;
  }

  glm::dvec3 eye() const { return eye_; }

 private:
  const RenderOutput& base_;
  const RayScene& rays_;
  HitShader shader_;
  int width_, height_;
  glm::dmat4 clipFromWorld_{1.0}, worldFromClip_{1.0};
  glm::dvec3 eye_{0.0};
  double tMin_ = 0.0;
};

std::uint8_t byteOf(double c) {
  return static_cast<std::uint8_t>(std::floor(std::clamp(c, 0.0, 1.0) * 255.0 + 0.5));
}

}  // namespace

SsrReference traceSsrReference(const Scene& scene, const RenderSettings& settings, const RenderOutput& base,
                               const RayScene& rays, const SsrReferenceOptions& options) {
  if (!settings.ssr.enabled) {
    throw InputError("ray-traced reference: settings.ssr.enabled is false, so there are no reflections to trace "
                     "(--ssr on turns them on)");
  }
  if (settings.view != View::Shaded) {
    throw InputError(std::string("ray-traced reference: it measures the shaded frame, and the view is '") +
                     std::string(toString(settings.view)) + "'");
  }
  const int samples = options.indirectSamples < 0 ? settings.ssr.indirectSamples : options.indirectSamples;
  if (samples > kMaxSsrReferenceSamples) {
    throw InputError("ray-traced reference: indirect samples " + std::to_string(samples) + " is over the limit of " +
                     std::to_string(kMaxSsrReferenceSamples));
  }
  const std::size_t pixels = static_cast<std::size_t>(base.width) * static_cast<std::size_t>(base.height);
  if (!base.gbuffer || base.gbuffer->normal.size() != pixels || base.rgba.size() != 4 * pixels ||
      base.depth.size() != pixels || base.triangleId.size() != pixels) {
    throw InputError("ray-traced reference: the base frame has no G-buffer (draw it with ssrBaseSettings on the CPU "
                     "renderer)");
  }
  const auto start = std::chrono::steady_clock::now();
  const Tracer tracer(scene, settings, base, rays);
  const GBuffer& g = *base.gbuffer;
  SsrReference ref;
  ref.frame = base;
  ref.mirror.assign(pixels, SsrTruth::None);
  ref.indirectOnly.assign(pixels, 0);
  ref.indirectSamples = samples;
  SsrUniformsT<double> hemisphere;  // hemisphere reads the distribution only
  hemisphere.distribution = settings.ssr.sampleDistribution;
  const double strength = settings.ssr.reflectStrength;

  const int threads = std::max(1, options.threads > 0 ? options.threads
                                                      : static_cast<int>(std::thread::hardware_concurrency()));
  std::vector<std::array<std::uint64_t, kSsrTruthCount>> mirrorRays(static_cast<std::size_t>(threads)),
      indirectRays(static_cast<std::size_t>(threads));
  auto band = [&](int part) {
    auto& mirrorCount = mirrorRays[static_cast<std::size_t>(part)];
    auto& indirectCount = indirectRays[static_cast<std::size_t>(part)];
    mirrorCount.fill(0);
    indirectCount.fill(0);
    for (int yTop = part; yTop < base.height; yTop += threads) {  // interleaved rows share the cost
      for (int x = 0; x < base.width; ++x) {
        const std::size_t i = static_cast<std::size_t>(yTop) * static_cast<std::size_t>(base.width) + static_cast<std::size_t>(x);
        if (base.triangleId[i] == kNoTriangle) continue;
        const double reflect = g.specular[i].w;
        if (!(reflect > 0.0) && samples == 0) continue;
        const glm::dvec3 p = tracer.positionAt(i, x, yTop);
        const glm::dvec3 n(vec3(g.normal[i]));
        glm::dvec3 total(base.rgba[4 * i] / 255.0, base.rgba[4 * i + 1] / 255.0, base.rgba[4 * i + 2] / 255.0);
        bool changed = false;
        if (reflect > 0.0) {
          const glm::dvec3 wo = glm::normalize(tracer.eye() - p);
          const glm::dvec3 r = glm::normalize((2.0 * glm::dot(n, wo)) * n - wo);
          const TracedRay m = tracer.trace(p, r);
          ref.mirror[i] = m.truth;
          ++mirrorCount[static_cast<std::size_t>(m.truth)];
          if (m.truth != SsrTruth::Sky) {
            total += m.light * (strength * reflect);
            changed = true;
          }
        } else {
          ref.indirectOnly[i] = 1;
        }
        if (samples > 0) {
          glm::dvec3 sum(0.0);
          const auto yGl = static_cast<std::uint32_t>(base.height - 1 - yTop);
          for (int k = 0; k < samples; ++k) {
            const vec2 xi = ssrRandomPairOf(static_cast<std::uint32_t>(x), yGl, static_cast<std::uint32_t>(k));
            double weight = 0.0;
            const glm::dvec3 dir = lanes::hemisphere<double>(hemisphere, n, glm::dvec2(xi), weight);
            const TracedRay s = tracer.trace(p, dir);
            ++indirectCount[static_cast<std::size_t>(s.truth)];
            sum += s.light * weight;
          }
          total += glm::dvec3(vec3(g.albedo[i])) * (sum / static_cast<double>(samples));
          changed = true;
        }
        if (changed) {
          for (int c = 0; c < 3; ++c) ref.frame.rgba[4 * i + static_cast<std::size_t>(c)] = byteOf(total[c]);
        }
      }
    }
  };
  std::vector<std::thread> workers;
  for (int part = 1; part < threads; ++part) workers.emplace_back(band, part);
  band(0);
  for (std::thread& w : workers) w.join();
  for (int part = 0; part < threads; ++part) {
    for (std::size_t c = 0; c < kSsrTruthCount; ++c) {
      ref.mirrorRays[c] += mirrorRays[static_cast<std::size_t>(part)][c];
      ref.indirectRays[c] += indirectRays[static_cast<std::size_t>(part)][c];
    }
  }
  ref.milliseconds = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  return ref;
}

namespace {

// The class a pixel's error counts in; false where nothing reflects there.
bool errorClassAt(const SsrReference& ref, std::size_t i, SsrErrorClass& c) {
  switch (ref.mirror[i]) {
    case SsrTruth::Sky: c = SsrErrorClass::Sky; return true;
    case SsrTruth::Visible: c = SsrErrorClass::Visible; return true;
    case SsrTruth::OffScreen: c = SsrErrorClass::OffScreen; return true;
    case SsrTruth::Occluded: c = SsrErrorClass::Occluded; return true;
    case SsrTruth::None: break;
  }
  if (ref.indirectOnly[i]) {
    c = SsrErrorClass::IndirectOnly;
    return true;
  }
  return false;
}

void addTo(SsrErrorRow& row, int diff) {
  ++row.pixels;
  row.sumAbs += diff;
  row.maxAbs = std::max(row.maxAbs, diff);
  if (diff > 3) ++row.over3;
}

}  // namespace

SsrReferenceError measureSsrError(const SsrReference& reference, const RenderOutput& frame) {
  const RenderOutput& ref = reference.frame;
  if (frame.width != ref.width || frame.height != ref.height || frame.rgba.size() != ref.rgba.size()) {
    throw InputError("ray-traced reference: the frame is " + std::to_string(frame.width) + "x" +
                     std::to_string(frame.height) + ", the reference " + std::to_string(ref.width) + "x" +
                     std::to_string(ref.height));
  }
  SsrReferenceError e;
  const std::size_t pixels = reference.mirror.size();
  e.pixelError.assign(pixels, 0);
  for (std::size_t i = 0; i < pixels; ++i) {
    SsrErrorClass c{};
    if (!errorClassAt(reference, i, c)) continue;
    int diff = 0;
    for (std::size_t ch = 0; ch < 3; ++ch) diff = std::max(diff, std::abs(int(frame.rgba[4 * i + ch]) - int(ref.rgba[4 * i + ch])));
    e.pixelError[i] = static_cast<std::uint8_t>(diff);
    addTo(e.byClass[static_cast<std::size_t>(c)], diff);
    addTo(e.all, diff);
  }
  for (SsrErrorRow* row = e.byClass.data(); row != e.byClass.data() + e.byClass.size(); ++row) {
    row->meanAbs = row->pixels ? row->sumAbs / static_cast<double>(row->pixels) : 0.0;
  }
  e.all.meanAbs = e.all.pixels ? e.all.sumAbs / static_cast<double>(e.all.pixels) : 0.0;
  return e;
}

std::vector<std::uint8_t> ssrTruthImage(const SsrReference& reference) {
  std::vector<std::uint8_t> rgba(reference.mirror.size() * 4, 0);
  for (std::size_t i = 0; i < reference.mirror.size(); ++i) {
    rgba[4 * i + 3] = 255;
    SsrErrorClass c{};
    if (!errorClassAt(reference, i, c)) continue;
    const std::array<std::uint8_t, 3> colour = ssrErrorClassColour(c);
    for (std::size_t ch = 0; ch < 3; ++ch) rgba[4 * i + ch] = colour[ch];
  }
  return rgba;
}

}  // namespace twr
