// Keeping both backends' frames, the diff and the pinned pixel's probes in step with the
// scene. Both render on workers (gl_worker.h, cpu_worker.h); this (the UI) thread only copies
// the scene for them, takes their finished frames and uploads them as textures.
#include "app/gui/app.h"
#include "gui/text_concat.h"
#include "gui/debug_views.h"

#include "compare/heatmap.h"
#include "compare/side_by_side.h"
#include "scene/camera.h"
#include "scene/errors.h"
#include "scene/projection_checks.h"
#include "scene/sky_view.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>

namespace twr::gui {
namespace {

// Smallest side a render may have, pixels (inclusive): below it the images say nothing.
constexpr int kMinRenderSide = 8;

int scaledSide(float side, float scale) {
  const long rounded = std::lround(static_cast<double>(side) * static_cast<double>(scale));
  return static_cast<int>(std::clamp<long>(rounded, kMinRenderSide, kMaxImageSide));
}


}  // namespace

void GuiApp::syncRenders() {
  takeCpuFrames();
  takeGlFrames();
  syncHorizonMaps();

  int width = 0, height = 0;
  if (prefs_.resolution == ResolutionSource::FitView && imagePanelPixels_.x > 0.0f && imagePanelPixels_.y > 0.0f) {
    width = scaledSide(imagePanelPixels_.x, prefs_.resolutionScale);
    height = scaledSide(imagePanelPixels_.y, prefs_.resolutionScale);
  } else {
    width = scaledSide(static_cast<float>(doc_.scene.output.width), prefs_.resolutionScale);
    height = scaledSide(static_cast<float>(doc_.scene.output.height), prefs_.resolutionScale);
  }
  if (width != renderWidth_ || height != renderHeight_) {
    // Keep a pinned pixel on the same spot of the picture.
    if (pin_.pixel && renderWidth_ > 0 && renderHeight_ > 0) {
      pin_.pixel->x = std::min(width - 1, pin_.pixel->x * width / renderWidth_);
      pin_.pixel->yTop = std::min(height - 1, pin_.pixel->yTop * height / renderHeight_);
    }
    renderWidth_ = width;
    renderHeight_ = height;
    doc_.touch();
  }
  if (width != timedWidth_ || height != timedHeight_) {
    // Times at another size are another workload: start the medians again.
    // The first size of a run keeps the reason it had ("scene loaded").
    if (timedWidth_ != 0) {
      const std::string reason = concat("render size ", width, " x ", height);
      cpuMs_.restart(reason);
      glMs_.restart(reason);
    }
    timedWidth_ = width;
    timedHeight_ = height;
  }
  if (pin_.pixel && (pin_.pixel->x < 0 || pin_.pixel->x >= width || pin_.pixel->yTop < 0 || pin_.pixel->yTop >= height)) {
    if (!commandLinePinChecked_ && options_.pin && *pin_.pixel == *options_.pin) {
      // Said, not silently dropped: the render size is only known now.
      pinWarning_ = concat("--pin ", pin_.pixel->x, ',', pin_.pixel->yTop, " is outside the ", width, " x ", height,
                           " px render (x in [0, ", width - 1, "], y in [0, ", height - 1, "]): nothing is pinned.");
      std::cerr << "twinraster-gui: warning: " << pinWarning_ << "\n";
    }
    pinPixel(std::nullopt);
  }
  commandLinePinChecked_ = true;

  refreshRenderBlocker();
  if (renderBlocker_.empty()) {
    submitGl();
    submitCpu();
    updateDiff();
  }
  // A new buffer re-diffs the frames on screen at once, whatever else is pending.
  if (diff_.cpu && diff_.gl && diff_.buffer != shownBuffer_) computeDiff();
  refreshTextures();
}

namespace {

bool sameRequest(const HorizonRequest& a, const HorizonRequest& b) {
  return a.material == b.material && a.heightMap == b.heightMap && a.heightScale == b.heightScale &&
         a.directions == b.directions;
}

// The stale horizon maps the app should build: every one but a build that already threw.
std::optional<HorizonRequest> nextHorizonToBuild(const SceneDoc& doc, const std::optional<HorizonRequest>& failed) {
  for (std::size_t m = 0; m < doc.scene.materials.size(); ++m) {
    if (!horizonMapStale(doc, m)) continue;
    const Material& material = doc.scene.materials[m];
    HorizonRequest request{m, material.heightMap, material.heightScale, material.horizonDirections};
    if (failed && sameRequest(*failed, request)) continue;
    return request;
  }
  return std::nullopt;
}

}  // namespace

void GuiApp::syncHorizonMaps() {
  std::vector<HorizonBuilt> finished = horizonWorker_.takeFinished();
  if (!finished.empty()) noteEvent();  // as takeCpuFrames
  for (HorizonBuilt& built : finished) {
    horizonBuilding_.reset();
    const std::size_t m = built.request.material;
    const std::string name = m < doc_.scene.materials.size() ? doc_.scene.materials[m].name : std::string("?");
    if (!built.map) {
      horizonFailed_ = built.request;
      horizonError_ = concat("the horizon map of '", name, "' could not be built: ", built.error);
      std::cerr << "twinraster-gui: " << horizonError_ << "\n";
      continue;
    }
    // Outdated by an edit made meanwhile: dropped, and the current keys are built next.
    if (installHorizonMap(doc_, built.request, std::move(built.map))) {
      char seconds[32];
      std::snprintf(seconds, sizeof seconds, "%.2f", built.seconds);
      horizonLastBuild_ = concat("'", name, "': ", built.request.directions, " directions in ", seconds, " s");
      horizonError_.clear();
      horizonFailed_.reset();
    }
  }
  // One build at a time, and only once the edit ends (a slider released, a typed value
  // entered): a drag of height_scale would otherwise start a build per frame.
  if (horizonBuilding_ || ImGui::IsAnyItemActive()) return;
  if (std::optional<HorizonRequest> request = nextHorizonToBuild(doc_, horizonFailed_)) {
    horizonWorker_.submit(*request);
    horizonBuilding_ = std::move(request);
  }
}

bool GuiApp::horizonMapsPending() const {
  return horizonBuilding_.has_value() || nextHorizonToBuild(doc_, horizonFailed_).has_value();
}

std::string GuiApp::horizonStatus() const {
  if (!horizonError_.empty()) return horizonError_;
  const auto describe = [this](const HorizonRequest& r) {
    const std::string name = r.material < doc_.scene.materials.size() ? doc_.scene.materials[r.material].name : "?";
    const int width = r.heightMap ? r.heightMap->width : 0, height = r.heightMap ? r.heightMap->height : 0;
    return concat("'", name, "' (", r.directions, " directions, ", width, " x ", height, " texels)");
  };
  if (horizonBuilding_) {
    const std::size_t m = horizonBuilding_->material;
    const bool previous = m < doc_.scene.materials.size() && doc_.scene.materials[m].horizonMap;
    return concat("Building the horizon map of ", describe(*horizonBuilding_), "; until it is in, both renderers ",
                  previous ? "shadow with the previous one." : "draw it unshadowed.");
  }
  if (const std::optional<HorizonRequest> next = nextHorizonToBuild(doc_, horizonFailed_)) {
    return concat("The horizon map of ", describe(*next), " is out of date: it is built again when the edit ends.");
  }
  return "";
}

void GuiApp::refreshRenderBlocker() {
  renderBlocker_ = validateCamera(doc_.scene.camera);
  if (!renderBlocker_.empty()) {
    renderBlocker_ = "camera: " + renderBlocker_;
    return;
  }
  if (renderWidth_ <= 0 || renderHeight_ <= 0) return;
  // What float cannot draw is refused by both renderers too; here it is said once, beside the
  // camera, and nothing is sent. The warnings walk every vertex: both only when the scene or
  // the size changed.
  if (projectionCheckedRevision_ != doc_.revision || projectionCheckedWidth_ != renderWidth_ ||
      projectionCheckedHeight_ != renderHeight_) {
    projectionProblem_ = projectionProblem(doc_.scene, renderWidth_, renderHeight_);
    projectionWarnings_ = projectionProblem_.empty() ? projectionWarnings(doc_.scene, renderWidth_, renderHeight_)
                                                     : std::vector<std::string>{};
    projectionCheckedRevision_ = doc_.revision;
    projectionCheckedWidth_ = renderWidth_;
    projectionCheckedHeight_ = renderHeight_;
  }
  renderBlocker_ = projectionProblem_;
}

ShownRevisions GuiApp::shownRevisions() const {
  ShownRevisions shown;
  const auto atSize = [this](const std::shared_ptr<const RenderOutput>& output) {
    return output && output->width == renderWidth_ && output->height == renderHeight_;
  };
  shown.cpu = atSize(cpuFrame_.output) ? cpuFrame_.revision : 0;
  shown.gl = atSize(glFrame_.output) ? glFrame_.revision : 0;
  shown.diff = diff_.result ? diff_.revision : 0;
  return shown;
}

void GuiApp::pinPixel(std::optional<PixelPos> pixel) {
  pin_ = PinState{};
  explorerVisit_ = -1;  // the new pixel's explorer follows the triangle that wrote it, its order not stepped
  explorerRasterStep_ = -1;
  if (pixel) pinWarning_.clear();
  pin_.pixel = pixel;
}

void GuiApp::takeCpuFrames() {
  std::vector<CpuFrame> frames = worker_.takeFinished();
  // Something new to show: drawn and settled, even when a frame only laid out for the test
  // probe (app.cpp, run) took it.
  if (!frames.empty()) noteEvent();
  for (CpuFrame& frame : frames) {
    if (frame.rendered) {
      std::erase_if(cpuPending_, [&frame](std::uint64_t revision) { return revision <= frame.revision; });
      cpuFrame_.revision = frame.revision;
      cpuFrame_.output = frame.output;
      cpuFrame_.error = frame.error;
      cpuFrame_.finishedAt = frame.finishedAt;
      cpuFrame_.cpuPath = frame.cpuPath;
      if (frame.output && frame.width == timedWidth_ && frame.height == timedHeight_ &&
          frame.revision >= timingsFromRevision_) {
        if (frame.cpuPath != timedCpuPath_) {
          if (!timedCpuPath_.empty()) cpuMs_.restart("CPU path " + frame.cpuPath);
          timedCpuPath_ = frame.cpuPath;
        }
        cpuMs_.add(frame.output->stats.milliseconds);
      }
      cpuTextureStale_ = true;
    }
    if (frame.probe && pin_.pixel && frame.probe->pixel == *pin_.pixel && frame.width == renderWidth_ &&
        frame.height == renderHeight_) {
      pin_.cpu = std::move(frame.probe);
      pin_.cpuRevision = frame.revision;
    }
  }
}

void GuiApp::takeGlFrames() {
  if (!glWorker_) return;
  std::vector<GlFrameResult> frames = glWorker_->takeFinished();
  if (!frames.empty()) noteEvent();  // as takeCpuFrames
  for (GlFrameResult& frame : frames) {
    if (frame.rendered) {
      glFrame_ = BackendFrame{};
      glFrame_.revision = frame.revision;
      glFrame_.output = frame.output;
      glFrame_.error = frame.error;
      glFrame_.finishedAt = frame.finishedAt;
      if (frame.output && frame.width == timedWidth_ && frame.height == timedHeight_ &&
          frame.revision >= timingsFromRevision_) {
        glMs_.add(frame.output->stats.milliseconds);
      }
      glTextureStale_ = true;
      glForCpu_[frame.revision] = frame.output;
      keepGlTwins();
    }
    if (frame.probe && pin_.pixel && frame.probe->pixel == *pin_.pixel && frame.width == renderWidth_ &&
        frame.height == renderHeight_) {
      pin_.gl = frame.probe->views;
      pin_.glError = frame.probe->error;
      pin_.glMarch = frame.probe->ssrMarch;
      pin_.glMarchError = frame.probe->ssrMarchError;
      pin_.glShadowTaps = frame.probe->shadowTaps;
      pin_.glShadowTapsError = frame.probe->shadowTapsError;
      pin_.glRevision = frame.revision;
    }
  }
}

void GuiApp::keepGlTwins() {
  // A GL frame is kept only while its CPU twin waits for it or may still come (a CPU job
  // asked for, or the snapshot the CPU takes next). The rest would pile up while the CPU lags.
  std::erase_if(glForCpu_, [this](const auto& entry) {
    const std::uint64_t revision = entry.first;
    const bool twinWaits = revision == cpuFrame_.revision && diff_.revision != revision;
    const bool twinMayCome =
        revision > cpuFrame_.revision && (cpuPending_.count(revision) != 0 || revision == glSnapshot_.revision);
    return !twinWaits && !twinMayCome;
  });
}

void GuiApp::submitGl() {
  // As submitCpu: one job runs and at most one waits, and a waiting job is never replaced, so
  // every snapshot the CPU may draw is drawn by GL too.
  if (!glWorker_ || glWorker_->hasQueued()) return;
  const std::uint64_t now = doc_.revision;
  const bool needFrame = glSnapshot_.revision != now;
  // The per-view reads wait while the user drags or types: each is a GL render of the whole
  // scene (one pixel drawn), and the next frame matters more.
  const bool probeNow = pin_.pixel && !interacting_;
  const int ray = ssrTraceRayOf(doc_.scene.settings);
  const bool needProbe = probeNow && (pin_.glAskedRevision != now || pin_.glAskedPixel != pin_.pixel ||
                                      pin_.glAskedRay != ray);
  if (!needFrame && !needProbe) return;
  if (needFrame) {
    glSnapshot_ = SceneSnapshot{now, std::make_shared<const Scene>(doc_.scene), renderWidth_, renderHeight_};
    keepGlTwins();
  }
  GlJob job;
  job.revision = now;
  job.scene = glSnapshot_.scene;
  job.width = glSnapshot_.width;
  job.height = glSnapshot_.height;
  job.renderFrame = needFrame;
  if (probeNow) {
    job.probePixel = pin_.pixel;
    job.ssrRay = ray;
    pin_.glAskedRevision = now;
    pin_.glAskedPixel = pin_.pixel;
    pin_.glAskedRay = ray;
  }
  glWorker_->submit(std::move(job));
}

void GuiApp::submitCpu() {
  // One job runs and at most one waits: the scene is copied once per snapshot, not once per
  // UI frame while a slider is dragged. The CPU draws the edit GL drew last (at most one GL
  // frame behind the newest), so each CPU frame meets a GL frame of the same edit.
  if (worker_.hasQueued() || glSnapshot_.revision == 0) return;
  const SceneSnapshot& snapshot = glSnapshot_;
  const bool needFrame = cpuSubmitted_ != snapshot.revision;
  // The pinned pixel is at the current render size; an older snapshot may have another.
  const bool probeFits = pin_.pixel && snapshot.width == renderWidth_ && snapshot.height == renderHeight_;
  const int ray = ssrTraceRayOf(snapshot.scene->settings);
  const bool needProbe = probeFits && (pin_.cpuAskedRevision != snapshot.revision ||
                                       pin_.cpuAskedPixel != pin_.pixel || pin_.cpuAskedRay != ray);
  if (!needFrame && !needProbe) return;
  CpuJob job;
  job.revision = snapshot.revision;
  job.scene = snapshot.scene;
  job.settings = snapshot.scene->settings;
  job.width = snapshot.width;
  job.height = snapshot.height;
  job.path = prefs_.cpuPath;
  job.isa = prefs_.cpuIsa;
  job.renderFrame = needFrame;
  if (probeFits) {
    job.probePixel = pin_.pixel;
    job.ssrRay = ray;
    pin_.cpuAskedRevision = snapshot.revision;
    pin_.cpuAskedPixel = pin_.pixel;
    pin_.cpuAskedRay = ray;
    // A new path or target is a new edit (panel_render.cpp), so this edit's frame is the path's.
    if (!needFrame && cpuFrame_.revision == snapshot.revision) job.frame = cpuFrame_.output;
  }
  if (needFrame) {
    cpuSubmitted_ = snapshot.revision;
    cpuPending_.insert(snapshot.revision);
  }
  worker_.submit(std::move(job));
}

void GuiApp::updateDiff() {
  if (cpuFrame_.revision == 0 || cpuFrame_.revision == diff_.revision) return;
  const auto twin = glForCpu_.find(cpuFrame_.revision);
  // GL draws every edit the CPU draws, usually first; when the CPU won, wait for its twin.
  if (twin == glForCpu_.end() && glFrame_.revision < cpuFrame_.revision) return;
  const std::shared_ptr<const RenderOutput> gl = twin != glForCpu_.end() ? twin->second : nullptr;
  diff_.revision = cpuFrame_.revision;
  keepGlTwins();  // this twin is used, older GL frames can no longer meet theirs
  diff_.cpu = cpuFrame_.output;
  diff_.gl = gl;
  computeDiff();
}

void GuiApp::computeDiff() {
  diff_.buffer = shownBuffer_;
  diff_.texturesStale = true;
  diff_.result.reset();
  diff_.error.clear();
  if (!diff_.cpu || !diff_.gl) {
    diff_.error = "no diff: one backend has no image for this frame (see its error)";
    return;
  }
  try {
    // Under a sky box the pixels no triangle covers are compared too (in the frame itself).
    CompareOptions options;
    options.compareBackground = shownBuffer_ == PassBuffer::Final && drawsSky(doc_.scene, doc_.scene.settings);
    diff_.result = compareDetailed(shownBufferOf(*diff_.cpu), shownBufferOf(*diff_.gl), options);
  } catch (const std::exception& e) {
    diff_.error = e.what();
  }
}

RenderOutput GuiApp::shownBufferOf(const RenderOutput& frame) const {
  if (shownBuffer_ == PassBuffer::Final) return frame;
  std::optional<RenderOutput> shown = bufferAsOutput(frame, shownBuffer_);
  return shown ? std::move(*shown) : frame;
}

void GuiApp::refreshTextures() {
  const BackgroundMode background = prefs_.checkerBackground ? BackgroundMode::Checker : BackgroundMode::RendererColour;
  // The Depth view linearised for display only: the diff and the read-backs keep window depth.
  const Camera& camera = doc_.scene.camera;
  const bool linear = doc_.scene.settings.view == View::Depth && prefs_.linearDepth;
  if (linear && (cpuTextureStale_ || glTextureStale_)) {
    // One mapping for both images, from the nearest to the farthest drawn pixel of either.
    linearDepthRange_ = drawnEyeRange({cpuFrame_.output.get(), glFrame_.output.get()}, camera.near, camera.far);
    cpuTextureStale_ = glTextureStale_ = true;
  }
  const auto shown = [&](const RenderOutput& frame) {
    if (shownBuffer_ != PassBuffer::Final) return viewImage(shownBufferOf(frame), background);
    return linear ? viewImage(withLinearDepth(frame, camera.near, camera.far, linearDepthRange_), background)
                  : viewImage(frame, background);
  };
  if (cpuTextureStale_) {
    if (cpuFrame_.output) cpuTexture_.upload(shown(*cpuFrame_.output));
    cpuTextureStale_ = false;
  }
  if (glTextureStale_) {
    if (glFrame_.output) glTexture_.upload(shown(*glFrame_.output));
    glTextureStale_ = false;
  }
  if (diff_.texturesStale) {
    if (diff_.result) {
      HeatMapOptions heatOptions;
      heatOptions.ramp = HeatRamp{prefs_.heatMaxLevels, prefs_.heatScale};
      heatOptions.legend = false;
      heatTexture_.upload(makeHeatMap(diff_.result->pixels, heatOptions));
      ClassMapOptions classOptions;
      classOptions.legend = false;
      classTexture_.upload(makeClassMap(diff_.result->pixels, classOptions));
    } else {
      heatTexture_.reset();
      classTexture_.reset();
    }
    diff_.texturesStale = false;
  }
}

}  // namespace twr::gui
