// The CPU pipeline glued together. The teaching traversal, for every draw item: vertex ->
// clip -> (fan) -> setup -> raster -> interpolate -> depth test -> shade -> output merge
// (draw_loop.h, shared with the reference renderer), then the TBN debug lines. The fast
// traversal of the same stages is fast_pipeline.cpp.
#include "softrender/cpu_renderer.h"

#include "scene/environment_capture.h"
#include "scene/errors.h"
#include "scene/image.h"
#include "scene/mip_level_view.h"
#include "scene/projection_checks.h"
#include "softrender/clip.h"
#include "softrender/debug_lines.h"
#include "softrender/deferred.h"
#include "softrender/ssr.h"
#include "softrender/draw_list.h"
#include "softrender/draw_loop.h"
#include "softrender/fast_pipeline.h"
#include "softrender/framebuffer.h"
#include "softrender/output_merge.h"
#include "softrender/interpolate.h"
#include "softrender/setup.h"
#include "softrender/shadow_pass.h"
#include "softrender/shade.h"
#include "softrender/sky.h"
#include "softrender/vertex.h"

#include <algorithm>
#include <chrono>
#include <functional>
#include <string>
#include <thread>
#include <vector>

namespace twr {

namespace {

// The teaching path's target: the RGBA8 framebuffer (output_merge.h).
struct FramebufferTarget {
  Framebuffer& fb;
  float storedDepth(int px, int py) const { return fb.depth[fb.index(px, py)]; }
  DepthFormat depthFormat() const { return fb.depthFormat; }
  void write(int px, int py, const vec4& colour, float depth, std::uint32_t triangleId) {
    writeFragment(fb, px, py, colour, depth, triangleId);
  }
};

// The G-buffer pass's target on the teaching path: depth and ids in the framebuffer, each
// fragment's surface in the G-buffer (draw_loop.h's kWritesSurface).
struct GBufferTarget {
  static constexpr bool kWritesSurface = true;
  Framebuffer& fb;
  GBuffer& g;
  float storedDepth(int px, int py) const { return fb.depth[fb.index(px, py)]; }
  DepthFormat depthFormat() const { return fb.depthFormat; }
  void writeSurface(int px, int py, const lanes::GBufferTexelL<float>& s, float depth, std::uint32_t triangleId) {
    const std::size_t i = fb.index(px, py);
    fb.depth[i] = depth;
    fb.triangleId[i] = triangleId;
    g.normal[i] = vec4(s.nl, s.shininess);
    g.geometric[i] = vec4(s.n, 1.0f);
    g.albedo[i] = vec4(s.kdAlbedo, 1.0f);
    g.specular[i] = vec4(s.ksSpec, s.ssrReflect);
    g.emission[i] = vec4(s.emission, 1.0f);
    if (!g.position.empty()) g.position[i] = vec4(s.posWorld, 1.0f);
  }
};

// The teaching loop's items: each item's vertex stage run, its state copied.
std::vector<LoopItemT<float>> teachingLoopItems(const std::vector<ItemState>& items) {
  std::vector<LoopItemT<float>> loopItems(items.size());
  for (std::size_t k = 0; k < items.size(); ++k) {
    const ItemState& s = items[k];
    LoopItemT<float>& d = loopItems[k];
    d.mesh = s.item->mesh;
    d.firstTriangleId = s.item->firstTriangleId;
    d.vertices.resize(d.mesh->vertices.size());
    for (std::size_t i = 0; i < d.vertices.size(); ++i) d.vertices[i] = runVertexStage(d.mesh->vertices[i], s.vertexUniforms);
    d.shade = s.shade;
    d.shaderKey = s.shaderKey;
    d.clip = s.clip;
    d.cull = s.cull;
    d.frontFace = s.frontFace;
    d.viewport = s.viewport;
    d.tangentLighting = s.tangentLighting;
    d.interpolation = s.interpolation;
  }
  return loopItems;
}

class CpuRenderer final : public Renderer {
 public:
  explicit CpuRenderer(const CpuOptions& options) : options_(options) {
    options_.threads = std::clamp(options_.threads, 1, kMaxDrawThreads);
  }
  std::string name() const override { return "cpu"; }

  RenderOutput render(const Scene& scene, const RenderSettings& settings, int width, int height) override {
    return renderReusing(scene, settings, width, height, {});
  }
  void renderInto(const Scene& scene, const RenderSettings& settings, int width, int height,
                  RenderOutput& out) override {
    Framebuffer reuse = framebufferFrom(std::move(out));
    out = RenderOutput{};  // nothing of the last frame is left if this one throws
    out = renderReusing(scene, settings, width, height, std::move(reuse));
  }

 private:
  RenderOutput renderReusing(const Scene& scene, const RenderSettings& settings, int width, int height,
                             Framebuffer reuse) {
    if (needsEnvironmentCapture(scene)) {  // drawn by this renderer itself, then the frame with it
      const CapturedEnvironment captured = captureEnvironment(scene, settings, *this);
      RenderOutput out = renderReusing(captured.scene, settings, width, height, std::move(reuse));
      attachCapture(out, captured);
      return out;
    }
    validateImageSize(width, height);
    // What GL cannot draw is refused here too, so the two never draw different scenes.
    if (const std::string problem = clipSlotProblem(settings); !problem.empty()) throw InputError("CPU: " + problem);
    if (drawsSsr(settings)) {
      if (const std::string problem = ssrSizeProblem(width, height); !problem.empty()) throw InputError("CPU: " + problem);
      if (const std::string problem = ssrSettingsProblem(settings.ssr); !problem.empty()) {
        throw InputError("CPU: " + problem);
      }
    }
    if (const std::string problem = projectionProblem(scene, width, height); !problem.empty()) {
      throw InputError("CPU: " + problem);
    }
    const auto start = std::chrono::steady_clock::now();
    RenderStats stats;
    if (options_.path == CpuPath::Fast && !fast_) {
      fast_ = std::make_unique<FastPipeline>(options_.threads, resolveCpuIsa(options_.isa));
    }
    // The fast path's workers awake for the frame's draws, asleep after it (also on a throw).
    struct FrameWorkers {
      FastPipeline* fast;
      explicit FrameWorkers(FastPipeline* f) : fast(f) {
        if (fast) fast->frameBegins();
      }
      ~FrameWorkers() {
        if (fast) fast->frameEnds();
      }
      FrameWorkers(const FrameWorkers&) = delete;
      FrameWorkers& operator=(const FrameWorkers&) = delete;
    } frameWorkers(fast_.get());
    // The shadow pass first (shadow_pass.h), with the traversal the frame uses; its statistics
    // are its own, not the frame's.
    double shadowMilliseconds = 0.0;
    const ShadowMaps shadows = renderShadowMaps(
        scene, settings,
        [&](const std::vector<ItemState>& passItems, int size) -> const Framebuffer& {
          RenderStats passStats;
          if (fast_) {
            if (shadowTarget_.width != size) {
              shadowTarget_ = fast_->allocateDepthTarget(size, size);
            }
            fast_->draw(passItems, scene.output.background, shadowTarget_, passStats, true);
          } else {
            shadowTarget_ = makeShadowFramebuffer(size, scene.output.background);
            drawTeachingItems(passItems, options_.threads, shadowTarget_, passStats);
          }
          return shadowTarget_;
        },
        shadowMilliseconds, &shadowPool_);
    stats.shadowMilliseconds = shadowMilliseconds;

    Framebuffer fb = fast_ ? fast_->allocateFramebuffer(width, height, std::move(reuse))  // draw() clears it bin by bin
                           : makeFramebuffer(width, height, scene.output.background);
    const mat4 clipFromWorld = clipFromWorldFor(scene.camera, width, height);
    std::vector<DrawItem> drawItems = flattenScene(scene);
    RenderSettings drawSettings = settings;
    const MipLevelView mipLevelView = applyMipLevelView(drawItems, drawSettings);  // owns stand-ins while drawn
    std::vector<ItemState> items;
    items.reserve(drawItems.size());
    for (const DrawItem& item : drawItems) {
      if (options_.path == CpuPath::Teaching) validateIndices(item);  // the fast path's front end checks them
      items.push_back(makeItemState(item, clipFromWorld, scene, drawSettings, width, height));
      setShadowUniforms(items.back().shade, shadows);
    }

    std::shared_ptr<GBuffer> gbuffer;
    if (!drawsDeferred(settings)) {
      if (options_.path == CpuPath::Teaching) {
        drawTeachingItems(items, options_.threads, fb, stats);
      } else {
        fast_->draw(items, scene.output.background, fb, stats);
      }
    } else {
      // Deferred (deferred.h): the G-buffer pass with the frame's own traversal, then the
      // lighting pass over its pixels.
      const auto gbufferStart = std::chrono::steady_clock::now();
      gbuffer = std::make_shared<GBuffer>();
      // The fast pass writes every texel, the teaching loop only the drawn ones.
      resizeGBuffer(*gbuffer, width, height, options_.path == CpuPath::Teaching, storesGBufferPosition(drawSettings));
      if (options_.path == CpuPath::Teaching) {
        const std::vector<LoopItemT<float>> loopItems = teachingLoopItems(items);
        GBufferTarget target{fb, *gbuffer};
        drawInBands(
            options_.threads, fb.height, true,
            [&](const RowBand& band, RenderStats& bandStats) { drawBand(loopItems, band, target, bandStats); }, stats);
      } else {
        fast_->draw(items, scene.output.background, fb, stats, false, gbuffer.get());
      }
      const auto lightingStart = std::chrono::steady_clock::now();
      const DeferredUniforms lighting = makeDeferredUniforms(scene, drawSettings, width, height, shadows);
      if (options_.path == CpuPath::Teaching) {
        lightGBufferTeaching(*gbuffer, lighting, options_.threads, fb);
      } else {
        fast_->light(*gbuffer, lighting, fb);
      }
      const auto lightingEnd = std::chrono::steady_clock::now();
      stats.gbufferMilliseconds = std::chrono::duration<double, std::milli>(lightingStart - gbufferStart).count();
      stats.lightingMilliseconds = std::chrono::duration<double, std::milli>(lightingEnd - lightingStart).count();
      if (drawsSsr(drawSettings)) {
        // Screen-space reflections (ssr.h) read the lit frame, before the sky.
        const SsrUniforms ssr = makeSsrUniforms(scene, drawSettings, width, height);
        const bool positionStored = storesGBufferPosition(drawSettings);
        if (options_.path == CpuPath::Teaching) {
          reflectTeaching(*gbuffer, ssr, lighting.worldFromClip, positionStored, options_.threads, fb);
        } else {
          fast_->reflect(*gbuffer, ssr, lighting.worldFromClip, positionStored, fb);
        }
        stats.ssrMilliseconds =
            std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - lightingEnd).count();
      }
    }

    // The sky box where no triangle was drawn (the environment's background), in the shaded
    // view, before the debug lines, as GL draws it after the scene's triangles.
    drawSky(makeSkyUniforms(scene, width, height, settings.view), fb, options_.threads);

    if (settings.tbnLines.enabled) {
      for (const ItemState& s : items) {
        for (const Vertex& vertex : s.item->mesh->vertices) {
          drawTbnLines(fb, runVertexStage(vertex, s.vertexUniforms), settings.tbnLines.length, s.vertexUniforms,
                       s.clip, s.viewport);
        }
      }
    }

    RenderOutput out = toRenderOutput(std::move(fb));
    stats.milliseconds = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    out.stats = stats;
    out.shadowMaps = shadows;
    out.gbuffer = std::move(gbuffer);
    return out;
  }

  CpuOptions options_;
  std::unique_ptr<FastPipeline> fast_;  // made on the first fast render, kept for its threads and buffers
  Framebuffer shadowTarget_;            // the shadow pass's layers are drawn here, kept across frames
  ShadowMapPool shadowPool_;            // the maps' storage, reused once no output holds it
};

}  // namespace

void drawTeachingItems(const std::vector<ItemState>& items, int threads, Framebuffer& fb, RenderStats& stats) {
  const std::vector<LoopItemT<float>> loopItems = teachingLoopItems(items);
  FramebufferTarget target{fb};
  drawInBands(
      threads, fb.height, true,
      [&](const RowBand& band, RenderStats& bandStats) { drawBand(loopItems, band, target, bandStats); }, stats);
}

std::unique_ptr<Renderer> makeCpuRenderer(const CpuOptions& options) {
  if (options.path == CpuPath::Fast && !cpuIsaSupported(options.isa)) {
    throw InputError("cpu renderer: --cpu-isa " + cpuIsaUnsupportedReason(options.isa));
  }
  return std::make_unique<CpuRenderer>(options);
}

std::string cpuPathName(const CpuOptions& options) {
  if (options.path == CpuPath::Teaching) return "teaching";
  return "fast (" + std::string(toString(resolveCpuIsa(options.isa))) + ")";
}

}  // namespace twr
