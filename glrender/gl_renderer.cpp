// The GL renderer: owns its contexts (OSMesa or EGL core, and compatibility once
// immediate-mode lines are asked for) or borrows the caller's, and runs one frame per render():
// clear, surfaces, TBN lines (colour and line mask in one pass), read-back. A lean frame
// (GlOptions::frame) runs the same steps on colour + depth only and reads back the colour.
#include "glrender/gl_renderer.h"

#include "scene/environment_capture.h"
#include "scene/mip_level_view.h"
#include "scene/projection_checks.h"

#include "glrender/context_egl.h"
#include "glrender/context_osmesa.h"
#include "glrender/gl_clip_state.h"
#include "glrender/gl_context.h"
#include "glrender/gl_program.h"
#include "glrender/gl_scene_draw.h"
#include "glrender/gl_gbuffer.h"
#include "glrender/gl_shadow_pass.h"
#include "glrender/gl_targets.h"
#include "glrender/llvmpipe_sampling.h"
#include "glrender/tbn_lines.h"
#include "glrender/tbn_lines_core.h"
#include "glrender/tbn_lines_immediate.h"
#include "scene/camera.h"
#include "scene/errors.h"
#include "scene/image.h"

#include <glad/gl.h>

#include <array>
#include <chrono>
#include <functional>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <optional>
#include <stdexcept>

namespace twr {
namespace {

// shadow.glsl's SHADOW_PROBE fields: the compared depth, the depth, the bias, the visibility,
// the stored depth, the packed texel.
constexpr int kShadowProbeFields = 6;
constexpr std::uint32_t kShadowProbeUntested = 0xffffffffu;  // the light was not tested there

float floatOfBits(std::uint32_t bits) {
  float f = 0.0f;
  std::memcpy(&f, &bits, sizeof f);
  return f;
}

// The trace of light `light` from its probe's fields (`covered`: a triangle was drawn at the
// pixel), the taps read from GL's own map.
ShadowTapTrace shadowTapTraceFromProbe(int light, const std::array<std::uint32_t, kShadowProbeFields>& bits,
                                       bool covered, const ShadowMap* map) {
  constexpr std::uint32_t kTexelMask = 0xfffu, kLayerMask = 0x7u;  // 12 bits a coordinate, 3 the layer
  static_assert(kMaxShadowMapSize - 1 <= int(kTexelMask) && kCubeShadowLayers - 1 <= int(kLayerMask),
                "shadow.glsl's probe packs a texel into 12 + 12 bits and its layer into 3");
  ShadowTapTrace t;
  t.light = light;
  if (map) t.pcf = map->projection.pcf;
  if (!covered || !map || bits[0] == kShadowProbeUntested) return t;
  t.tested = true;
  t.reference = floatOfBits(bits[0]);
  t.depth = floatOfBits(bits[1]);
  t.bias = floatOfBits(bits[2]);
  t.visibility = floatOfBits(bits[3]);
  t.stored = floatOfBits(bits[4]);
  const std::uint32_t packed = bits[5];
  t.texel = glm::ivec3(static_cast<int>(packed & kTexelMask), static_cast<int>((packed >> 12) & kTexelMask),
                       static_cast<int>((packed >> 24) & kLayerMask));
  t.inside = ((packed >> 27) & 1u) != 0;
  if (t.inside) t.taps = shadowTapsOf(*map, t.texel, t.reference);
  return t;
}

// Everything that belongs to one GL context: GL objects die with their context.
struct GlDevice {
  std::unique_ptr<HeadlessGlContext> headless;  // null when drawing in the caller's context
  GlProcFunction procAddress;
  GlContextInfo info;
  ProgramCache programs;
  GlUploadCache uploads;  // meshes and textures kept across renders
  RenderTargets targets;
  GlShadowMaps shadows;  // the shadow pass's depth textures, kept across frames
  GlGBuffer gbuffer;     // the deferred pipeline's targets, kept across frames
  std::unique_ptr<ImmediateTbnLines> immediateLines;  // loaded on first use

  GlDevice(std::unique_ptr<HeadlessGlContext> context, GlProcFunction proc, const std::string& shaderDir,
           GlFrame frame)
      : headless(std::move(context)),
        procAddress(std::move(proc)),
        programs(ShaderLibrary(shaderDir)),
        targets(frame) {}
  GlDevice(const GlDevice&) = delete;
  GlDevice& operator=(const GlDevice&) = delete;
  ~GlDevice() {
    // The members' GL objects are deleted after this body, in this context.
    if (!headless) return;
    try {
      headless->makeCurrent();
      loadCoreGl(procAddress, headless->description());
    } catch (const std::exception&) {
      // Nothing sensible to do in a destructor; the context goes with the objects.
    }
  }

  // Binds the context and points glad's global functions at it when another context (a
  // GLFW window, the other headless library, another renderer) has loaded them since.
  void makeCurrent() {
    if (headless) headless->makeCurrent();
    if (loadNumber != 0 && loadNumber == coreGlLoadCount()) return;
    loadNumber = loadCoreGl(procAddress, headless ? headless->description() : "current context");
  }
  std::uint64_t loadNumber = 0;  // this device's last loadCoreGl, 0: none yet
};

// A headless context of the kind `options` names (Auto resolved by the caller).
std::unique_ptr<HeadlessGlContext> makeHeadlessContext(const GlOptions& options, GlContextKind kind,
                                                       bool compatibility) {
  if (kind == GlContextKind::Egl) {
    EglContextDesc desc;
    desc.library = options.eglLibrary;
    desc.device = options.eglDevice;
    desc.compatibility = compatibility;
    desc.fastSampling = options.fastSampling;
    return std::make_unique<EglContext>(desc);
  }
  OsMesaContextDesc desc;
  desc.library = options.osmesaLibrary;
  desc.compatibility = compatibility;
  desc.fastSampling = options.fastSampling;
  return std::make_unique<OsMesaContext>(desc);
}

// Auto: OSMesa where its library loads, else EGL. A device number means EGL.
GlContextKind resolveContextKind(const GlOptions& options) {
  if (options.context != GlContextKind::Auto) return options.context;
  if (options.eglDevice != kEglSurfaceless) return GlContextKind::Egl;
  return osmesaLibraryLoads(options.osmesaLibrary) ? GlContextKind::OsMesa : GlContextKind::Egl;
}

// A device for `context`: made current, glad loaded, its strings read.
std::unique_ptr<GlDevice> makeHeadlessDevice(std::unique_ptr<HeadlessGlContext> context, const GlOptions& options) {
  HeadlessGlContext* raw = context.get();
  auto device = std::make_unique<GlDevice>(std::move(context),
                                           [raw](const char* name) { return raw->procAddress(name); },
                                           options.shaderDir, options.frame);
  device->makeCurrent();
  device->info = describeCurrentContext(device->headless->description());
  return device;
}

std::string describeError(GLenum error) {
  switch (error) {
    case GL_INVALID_ENUM: return "GL_INVALID_ENUM";
    case GL_INVALID_VALUE: return "GL_INVALID_VALUE";
    case GL_INVALID_OPERATION: return "GL_INVALID_OPERATION";
    case GL_INVALID_FRAMEBUFFER_OPERATION: return "GL_INVALID_FRAMEBUFFER_OPERATION";
    case GL_OUT_OF_MEMORY: return "GL_OUT_OF_MEMORY";
    default: return "GL error " + std::to_string(error);
  }
}

// A GL error here is a bug in this renderer, not bad input.
void checkGlErrors(const char* where) {
  const GLenum error = glGetError();
  if (error != GL_NO_ERROR) throw std::logic_error(std::string("GL: ") + describeError(error) + " after " + where);
}

void validateRequest(const Scene& scene, const RenderSettings& settings, int width, int height) {
  if (const std::string problem = renderSizeProblem(width, height); !problem.empty()) throw InputError("GL: " + problem);
  if (scene.lights.size() > static_cast<std::size_t>(kMaxLights)) {
    throw InputError("GL: scene '" + scene.sourcePath + "' has " + std::to_string(scene.lights.size()) +
                     " lights, at most " + std::to_string(kMaxLights) + " are supported");
  }
  if (settings.userClipPlanes.size() > static_cast<std::size_t>(kMaxUserClipPlanes)) {
    throw InputError("GL: scene '" + scene.sourcePath + "' has " + std::to_string(settings.userClipPlanes.size()) +
                     " user clip planes, at most " + std::to_string(kMaxUserClipPlanes) + " are supported");
  }
  if (const std::string problem = clipSlotProblem(settings); !problem.empty()) throw InputError("GL: " + problem);
  if (drawsSsr(settings)) {
    if (const std::string problem = ssrSizeProblem(width, height); !problem.empty()) throw InputError("GL: " + problem);
    if (const std::string problem = ssrSettingsProblem(settings.ssr); !problem.empty()) throw InputError("GL: " + problem);
  }
  if (const std::string problem = projectionProblem(scene, width, height); !problem.empty()) {
    throw InputError("GL: " + problem);
  }
  if (settings.tbnLines.enabled && !(settings.tbnLines.length >= 0.0f && std::isfinite(settings.tbnLines.length))) {
    throw InputError("GL: tbn_lines.length " + std::to_string(settings.tbnLines.length) +
                     ", expected a finite length >= 0 in world units");
  }
}

// Puts back what a caller drawing in its own context (the GUI) relies on, also when a
// render throws: framebuffer bindings and viewport; and switches off what the caller's
// shaders do not expect (clip distances, depth clamp, our program).
class CallerStateGuard {
 public:
  CallerStateGuard() {
    glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &drawFramebuffer_);
    glGetIntegerv(GL_READ_FRAMEBUFFER_BINDING, &readFramebuffer_);
    glGetIntegerv(GL_VIEWPORT, viewport_.data());
  }
  ~CallerStateGuard() {
    resetGlClipState();
    glUseProgram(0);
    glBindVertexArray(0);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, static_cast<GLuint>(drawFramebuffer_));
    glBindFramebuffer(GL_READ_FRAMEBUFFER, static_cast<GLuint>(readFramebuffer_));
    glViewport(viewport_[0], viewport_[1], viewport_[2], viewport_[3]);
  }
  CallerStateGuard(const CallerStateGuard&) = delete;
  CallerStateGuard& operator=(const CallerStateGuard&) = delete;

 private:
  GLint drawFramebuffer_ = 0;
  GLint readFramebuffer_ = 0;
  std::array<GLint, 4> viewport_{};
};

// Releases a headless context at the end of a render (HeadlessGlContext::release).
class ReleaseAfterRender {
 public:
  explicit ReleaseAfterRender(HeadlessGlContext* context) : context_(context) {}
  ~ReleaseAfterRender() {
    if (context_) context_->release();
  }
  ReleaseAfterRender(const ReleaseAfterRender&) = delete;
  ReleaseAfterRender& operator=(const ReleaseAfterRender&) = delete;

 private:
  HeadlessGlContext* context_;
};

class GlRenderer final : public Renderer {
 public:
  explicit GlRenderer(const GlOptions& options) : options_(options) {}

  std::string name() const override { return "gl"; }

  RenderOutput render(const Scene& scene, const RenderSettings& settings, int width, int height) override {
    return draw(scene, settings, width, height, std::nullopt);
  }
  // The attachments read back into out's buffers (glReadPixels into memory already mapped).
  void renderInto(const Scene& scene, const RenderSettings& settings, int width, int height,
                  RenderOutput& out) override {
    RenderOutput buffers = imageBuffersOf(std::move(out));
    out = RenderOutput{};  // nothing of the last frame is left if this one throws
    out = draw(scene, settings, width, height, std::nullopt, std::move(buffers));
  }

  RenderOutput renderPixel(const Scene& scene, const RenderSettings& settings, int width, int height, int x,
                           int yTop) {
    if (options_.frame != GlFrame::Full) throw InputError("GL: a pixel render needs the full frame's attachments");
    if (x < 0 || x >= width || yTop < 0 || yTop >= height) {
      throw InputError("GL: pixel (" + std::to_string(x) + ", " + std::to_string(yTop) + ") is outside the " +
                       std::to_string(width) + " x " + std::to_string(height) + " frame");
    }
    // A reflection reads other pixels of the lit frame, which a one-pixel render never draws.
    if (drawsSsr(settings)) {
      throw InputError("GL: a pixel render cannot draw screen-space reflections (they read the whole frame); "
                       "turn settings.ssr off for it");
    }
    return draw(scene, settings, width, height, std::array<int, 2>{x, height - 1 - yTop});
  }

  SsrMarchTrace traceSsrMarch(const Scene& scene, const RenderSettings& settings, int width, int height, int x,
                              int yTop, int ray) {
    if (options_.frame != GlFrame::Full) throw InputError("GL: a march trace needs the full frame's attachments");
    if (x < 0 || x >= width || yTop < 0 || yTop >= height) {
      throw InputError("GL: pixel (" + std::to_string(x) + ", " + std::to_string(yTop) + ") is outside the " +
                       std::to_string(width) + " x " + std::to_string(height) + " frame");
    }
    if (!drawsSsr(settings)) {
      throw InputError("GL: a march trace needs screen-space reflections (settings.ssr on, or an SSR view)");
    }
    checkSsrRay(settings, ray);
    // The frame as render() draws it, the probe run after its reflection pass.
    struct Reset {
      std::optional<std::array<int, 3>>& probe;
      ~Reset() { probe.reset(); }
    } reset{ssrProbe_};
    ssrProbe_ = std::array<int, 3>{x, height - 1 - yTop, ray};
    probed_ = SsrMarchTrace{};
    const RenderOutput out = draw(scene, settings, width, height, std::nullopt);
    SsrMarchTrace trace;
    trace.ray = ray;
    const std::size_t i = static_cast<std::size_t>(yTop) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x);
    trace.marched = out.triangleId[i] != kNoTriangle && out.gbuffer;
    if (!trace.marched) return trace;
    trace.origin = probed_.origin;  // GL's own, as the probe marched them
    trace.direction = probed_.direction;
    trace.weight = probed_.weight;
    trace.steps = std::move(probed_.steps);
    return trace;
  }

  std::vector<ShadowTapTrace> traceShadowTaps(const Scene& scene, const RenderSettings& settings, int width,
                                              int height, int x, int yTop) {
    if (options_.frame != GlFrame::Full) throw InputError("GL: a shadow tap trace needs the full frame's attachments");
    // The pixel's fragment shaded forward, as the CPU's trace replays it (a deferred frame's
    // lighting pass runs the same test on the stored position: the same bits).
    RenderSettings forward = settings;
    forward.view = View::Shaded;
    forward.pipeline = Pipeline::Forward;
    forward.ssr.enabled = false;
    forward.tbnLines.enabled = false;
    struct Reset {
      std::optional<GlShadowMaps::Probe>& probe;
      bool& readsMaps;
      ~Reset() {
        probe.reset();
        readsMaps = false;
      }
    } reset{shadowProbe_, probeReadsMaps_};
    std::vector<ShadowTapTrace> traces;
    ShadowMaps maps;
    for (std::size_t i = 0; i < scene.lights.size(); ++i) {
      if (!scene.lights[i].shadow) continue;
      std::array<std::uint32_t, kShadowProbeFields> bits{};
      bool covered = false;
      for (int field = 0; field < kShadowProbeFields; ++field) {
        shadowProbe_ = GlShadowMaps::Probe{static_cast<int>(i), field};
        probeReadsMaps_ = maps.empty();  // the first draw reads GL's maps back, for the taps
        RenderOutput out = renderPixel(scene, forward, width, height, x, yTop);
        if (probeReadsMaps_) maps = std::move(out.shadowMaps);
        covered = out.triangleId[0] != kNoTriangle;
        for (std::size_t b = 0; b < 4; ++b) bits[static_cast<std::size_t>(field)] |= std::uint32_t{out.rgba[b]} << (8 * b);
      }
      const ShadowMap* map = i < maps.size() ? maps[i].get() : nullptr;
      traces.push_back(shadowTapTraceFromProbe(static_cast<int>(i), bits, covered, map));
    }
    return traces;
  }

 private:
  std::optional<GlShadowMaps::Probe> shadowProbe_;  // traceShadowTaps' light and field
  bool probeReadsMaps_ = false;                      // a pixel render that reads the maps back too
  std::optional<std::array<int, 3>> ssrProbe_;  // traceSsrMarch's pixel (GL window coordinates) and ray
  SsrMarchTrace probed_;                        // what the probe read back

  // A frame, or with `onlyPixel` (x, y in GL window coordinates) the same draws under a
  // one-pixel scissor and that pixel read back as a 1 x 1 output.
  // `buffers`: image buffers to read back into (renderInto).
  RenderOutput draw(const Scene& scene, const RenderSettings& settings, int width, int height,
                    const std::optional<std::array<int, 2>>& onlyPixel, RenderOutput buffers = {}) {
    if (needsEnvironmentCapture(scene)) {  // drawn by this renderer itself (full frames), then the frame with it
      const CapturedEnvironment captured = captureEnvironment(scene, settings, *this);
      RenderOutput out = draw(captured.scene, settings, width, height, onlyPixel, std::move(buffers));
      attachCapture(out, captured);
      return out;
    }
    validateRequest(scene, settings, width, height);
    const bool immediateLines = settings.tbnLines.enabled && settings.tbnLines.mode == LineMode::Immediate;
    GlDevice& device = deviceFor(immediateLines);
    // Declared before the state guard, so it runs after the guard's last GL call, also
    // when the render throws.
    const ReleaseAfterRender release(device.headless.get());
    device.makeCurrent();
    if (immediateLines && !device.immediateLines) {
      device.immediateLines = std::make_unique<ImmediateTbnLines>(device.procAddress);
    }

    const CallerStateGuard callerState;

    const auto start = std::chrono::steady_clock::now();
    const float aspect = static_cast<float>(width) / static_cast<float>(height);
    const mat4 viewFromWorldMatrix = viewFromWorld(scene.camera);
    const mat4 clipFromViewMatrix = clipFromView(scene.camera, aspect);
    const mat4 clipFromWorld = clipFromViewMatrix * viewFromWorldMatrix;
    std::vector<DrawItem> items = flattenScene(scene);
    RenderSettings drawSettings = settings;
    const MipLevelView mipLevelView = applyMipLevelView(items, drawSettings);  // owns stand-ins while drawn

    // The shadow pass first (gl_shadow_pass.h): the maps are read back for compare only in a
    // full frame.
    const auto shadowStart = std::chrono::steady_clock::now();
    ShadowMaps shadowMaps = device.shadows.draw(device.programs, device.uploads, scene, drawSettings, items,
                                                options_.frame == GlFrame::Full && (!onlyPixel || probeReadsMaps_));
    device.shadows.setProbe(shadowProbe_);
    checkGlErrors("drawing the shadow maps");
    const double shadowMilliseconds =
        shadowMaps.empty() ? 0.0
                           : std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - shadowStart).count();

    device.targets.prepare(width, height);
    device.targets.bind();
    // Set before the clear, which the scissor limits too. Fragments are still shaded in 2x2
    // quads across the scissor's edge, so derivatives (and the LOD) are the full frame's.
    if (onlyPixel) {
      glEnable(GL_SCISSOR_TEST);
      glScissor((*onlyPixel)[0], (*onlyPixel)[1], 1, 1);
    } else {
      glDisable(GL_SCISSOR_TEST);
    }
    device.targets.clear(scene.output.background);
    const GlClipState clipState = makeGlClipState(drawSettings, scene.camera);
    const bool deferred = drawsDeferred(drawSettings);
    double gbufferMilliseconds = 0.0, lightingMilliseconds = 0.0, ssrMilliseconds = 0.0;
    std::function<void()> lighting;
    auto passStart = std::chrono::steady_clock::now();
    if (deferred) {
      // The G-buffer pass, then the lighting pass before the sky (gl_gbuffer.h); each pass's
      // time is measured to its glFinish, only when a full frame is read back.
      device.gbuffer.bindForSurfaces(device.targets, options_.frame, storesGBufferPosition(drawSettings));
      lighting = [&] {
        if (options_.frame == GlFrame::Full) glFinish();
        const auto lightingStart = std::chrono::steady_clock::now();
        gbufferMilliseconds = std::chrono::duration<double, std::milli>(lightingStart - passStart).count();
        device.gbuffer.light(device.programs, scene, &device.shadows, clipFromWorld, device.targets);
        if (options_.frame == GlFrame::Full) glFinish();
        const auto lightingEnd = std::chrono::steady_clock::now();
        lightingMilliseconds = std::chrono::duration<double, std::milli>(lightingEnd - lightingStart).count();
        if (drawsSsr(drawSettings)) {
          device.gbuffer.reflect(device.programs, scene, drawSettings, clipFromWorld, device.targets);
          if (options_.frame == GlFrame::Full) glFinish();
          ssrMilliseconds =
              std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - lightingEnd).count();
          if (ssrProbe_) {
            device.gbuffer.probeReflection(device.programs, scene, drawSettings, clipFromWorld, (*ssrProbe_)[0],
                                           (*ssrProbe_)[1], (*ssrProbe_)[2], probed_);
          }
        }
      };
    } else {
      device.targets.drawSurfaces();
    }
    const SceneDrawStats drawStats = drawScene(device.programs, device.uploads, scene, drawSettings, clipState, items,
                                               clipFromWorld, width, height, options_.frame, &device.shadows, lighting);
    checkGlErrors(deferred ? "drawing the G-buffer and lighting passes" : "drawing the scene");

    if (settings.tbnLines.enabled) {
      drawLines(device, items, settings, clipState, viewFromWorldMatrix, clipFromViewMatrix, clipFromWorld);
      checkGlErrors("drawing the TBN lines");
    }
    glFinish();
    const auto drawn = std::chrono::steady_clock::now();

    RenderOutput out = std::move(buffers);
    if (onlyPixel) {
      device.targets.readPixel((*onlyPixel)[0], (*onlyPixel)[1], out);
      glDisable(GL_SCISSOR_TEST);
    } else {
      device.targets.readBack(out);
      if (deferred && options_.frame == GlFrame::Full) out.gbuffer = device.gbuffer.readBack();
    }
    checkGlErrors("reading back");
    out.stats.readbackMilliseconds =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - drawn).count();

    out.stats.shadowMilliseconds = shadowMilliseconds;
    out.stats.gbufferMilliseconds = gbufferMilliseconds;
    out.stats.ssrMilliseconds = ssrMilliseconds;
    out.stats.lightingMilliseconds = lightingMilliseconds;
    out.shadowMaps = std::move(shadowMaps);
    out.stats.trianglesIn = drawStats.trianglesIn;
    out.stats.pixelsShaded = drawStats.samplesPassed;
    out.stats.milliseconds =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    return out;
  }

  GlDevice& deviceFor(bool compatibility) {
    if (options_.currentContextLoader) {
      if (!current_) {
        const GlProcLoader loader = options_.currentContextLoader;
        current_ = std::make_unique<GlDevice>(nullptr, [loader](const char* name) { return loader(name); },
                                              options_.shaderDir, options_.frame);
        current_->makeCurrent();
        current_->info = describeCurrentContext("current context");
        report(*current_, "current context");
      }
      return *current_;
    }
    std::unique_ptr<GlDevice>& slot = compatibility ? compatibility_ : core_;
    if (!slot) {
      // Both contexts of one renderer are of one kind: Auto is decided once.
      if (!kind_) kind_ = resolveContextKind(options_);
      auto device = makeHeadlessDevice(makeHeadlessContext(options_, *kind_, compatibility), options_);
      report(*device, device->headless->description().c_str());
      slot = std::move(device);
    }
    return *slot;
  }

  void report(const GlDevice& device, const char* what) const {
    if (!options_.verbose) return;
    const char* perf = std::getenv("GALLIVM_PERF");
    std::fprintf(stderr, "gl: %s: GL_VERSION %s, GL_RENDERER %s, %s profile; texture sampling %s (GALLIVM_PERF=%s)\n",
                 what, device.info.version.c_str(), device.info.renderer.c_str(),
                 device.info.compatibility ? "compatibility" : "core",
                 device.headless && isLlvmpipe(device.info.renderer) ? llvmpipeSamplingMode().c_str()
                                                                     : "as the driver chooses",
                 perf ? perf : "");
  }

  void drawLines(GlDevice& device, const std::vector<DrawItem>& items, const RenderSettings& settings,
                 const GlClipState& clipState, const mat4& viewFromWorldMatrix, const mat4& clipFromViewMatrix,
                 const mat4& clipFromWorld) {
    const std::vector<TbnLineVertex> lines = buildTbnLines(items, settings);
    if (lines.empty()) return;
    // The surfaces' state carries over, as in the tutorial: GL_LESS with depth writes,
    // the same clip planes and depth clamp (softrender/debug_lines.h does the same).
    device.targets.bindForLines();
    if (settings.tbnLines.mode == LineMode::Immediate) {
      device.immediateLines->draw(lines, clipFromViewMatrix, viewFromWorldMatrix, clipState, settings.userClipPlanes);
    } else {
      const CoreTbnLines coreLines(lines);
      coreLines.draw(device.programs, clipFromWorld, clipState, settings.userClipPlanes);
    }
  }

  GlOptions options_;
  std::optional<GlContextKind> kind_;        // OsMesa or Egl, once the first context exists
  std::unique_ptr<GlDevice> core_;           // headless core profile
  std::unique_ptr<GlDevice> compatibility_;  // headless compatibility profile
  std::unique_ptr<GlDevice> current_;        // the caller's context
};

}  // namespace

std::unique_ptr<Renderer> makeGlRenderer(const GlOptions& options) { return std::make_unique<GlRenderer>(options); }

std::string glSamplingMode() { return llvmpipeSamplingMode(); }

bool isLlvmpipe(const std::string& glRenderer) { return glRenderer.find("llvmpipe") != std::string::npos; }

const char* toString(GlContextKind kind) {
  switch (kind) {
    case GlContextKind::OsMesa: return "osmesa";
    case GlContextKind::Egl: return "egl";
    case GlContextKind::Auto: return "auto";
  }
  return "?";
}

bool parse(const std::string& text, GlContextKind& kind) {
  for (const GlContextKind candidate : {GlContextKind::OsMesa, GlContextKind::Egl, GlContextKind::Auto}) {
    if (text == toString(candidate)) {
      kind = candidate;
      return true;
    }
  }
  return false;
}

namespace {

// One context kind on one device: a core context's strings, then whether a compatibility
// context can be made too. Every failure is recorded, not thrown.
GlContextProbe probeOne(const GlOptions& base, GlContextKind kind, int eglDevice, std::string deviceDetail) {
  GlContextProbe probe;
  probe.kind = kind;
  probe.eglDevice = eglDevice;
  probe.deviceDetail = std::move(deviceDetail);
  GlOptions options = base;
  options.eglDevice = eglDevice;
  try {
    const std::unique_ptr<GlDevice> core = makeHeadlessDevice(makeHeadlessContext(options, kind, false), options);
    probe.description = core->headless->description();
    probe.vendor = core->info.vendor;
    probe.renderer = core->info.renderer;
    probe.version = core->info.version;
  } catch (const InputError& error) {
    probe.error = error.what();
    return probe;
  }
  try {
    const std::unique_ptr<GlDevice> compatibility =
        makeHeadlessDevice(makeHeadlessContext(options, kind, true), options);
    probe.compatibility = compatibility->info.compatibility;
  } catch (const InputError&) {
    probe.compatibility = false;  // core only: immediate-mode lines are refused there
  }
  return probe;
}

}  // namespace

std::vector<GlContextProbe> probeGlContexts(const GlOptions& options) {
  std::vector<GlContextProbe> probes;
  probes.push_back(probeOne(options, GlContextKind::OsMesa, kEglSurfaceless, ""));
  probes.push_back(probeOne(options, GlContextKind::Egl, kEglSurfaceless, "Mesa's surfaceless platform"));
  const std::string missing = eglLibraryProblem(options.eglLibrary);
  if (!missing.empty()) return probes;  // the surfaceless entry already says why
  std::vector<EglDeviceInfo> devices;
  try {
    devices = listEglDevices(options.eglLibrary);
  } catch (const InputError& error) {
    GlContextProbe probe;
    probe.kind = GlContextKind::Egl;
    probe.eglDevice = 0;
    probe.error = error.what();
    probes.push_back(probe);
    return probes;
  }
  for (const EglDeviceInfo& device : devices) {
    std::string detail = device.software ? "software" : "";
    for (const std::string& file : {device.drmDeviceFile, device.renderNodeFile}) {
      if (!file.empty()) detail += (detail.empty() ? "" : ", ") + file;
    }
    detail += (detail.empty() ? "" : "; ") + std::string("extensions: ") + device.extensions;
    probes.push_back(probeOne(options, GlContextKind::Egl, device.index, detail));
  }
  return probes;
}

RenderOutput renderGlPixel(Renderer& renderer, const Scene& scene, const RenderSettings& settings, int width,
                           int height, int x, int yTop) {
  auto* gl = dynamic_cast<GlRenderer*>(&renderer);
  if (!gl) throw InputError("renderGlPixel: the renderer '" + renderer.name() + "' is not the GL renderer");
  return gl->renderPixel(scene, settings, width, height, x, yTop);
}

std::vector<ShadowTapTrace> traceGlShadowTaps(Renderer& renderer, const Scene& scene, const RenderSettings& settings,
                                              int width, int height, int x, int yTop) {
  auto* gl = dynamic_cast<GlRenderer*>(&renderer);
  if (!gl) throw InputError("traceGlShadowTaps: the renderer '" + renderer.name() + "' is not the GL renderer");
  return gl->traceShadowTaps(scene, settings, width, height, x, yTop);
}

SsrMarchTrace traceGlSsrMarch(Renderer& renderer, const Scene& scene, const RenderSettings& settings, int width,
                              int height, int x, int yTop, int ray) {
  auto* gl = dynamic_cast<GlRenderer*>(&renderer);
  if (!gl) throw InputError("traceGlSsrMarch: the renderer '" + renderer.name() + "' is not the GL renderer");
  return gl->traceSsrMarch(scene, settings, width, height, x, yTop, ray);
}

}  // namespace twr
