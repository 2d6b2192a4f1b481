// Keeping both backends' frames, the diff and the pinned pixel's probes in step with the
// scene: GL renders on this (the UI) thread in the window's context, the CPU on the worker.
#include "app/gui/app.h"
#include "app/gui/text_concat.h"
#include "app/gui/debug_views.h"

#include "compare/heatmap.h"
#include "compare/side_by_side.h"
#include "scene/camera.h"
#include "scene/errors.h"

#include <algorithm>
#include <cmath>
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
    if (glFrame_.revision != doc_.revision) renderGl();
    submitCpu();
    updateDiff();
    probeGl();
  }
  refreshTextures();
}

void GuiApp::refreshRenderBlocker() {
  renderBlocker_ = validateCamera(doc_.scene.camera);
  if (!renderBlocker_.empty()) renderBlocker_ = "camera: " + renderBlocker_;
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
  if (pixel) pinWarning_.clear();
  pin_.pixel = pixel;
}

void GuiApp::takeCpuFrames() {
  for (CpuFrame& frame : worker_.takeFinished()) {
    if (frame.rendered) {
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

void GuiApp::renderGl() {
  glFrame_ = BackendFrame{};
  glFrame_.revision = doc_.revision;
  try {
    glFrame_.output = std::make_shared<const RenderOutput>(
        glRenderer_->render(doc_.scene, doc_.scene.settings, renderWidth_, renderHeight_));
    if (renderWidth_ == timedWidth_ && renderHeight_ == timedHeight_) glMs_.add(glFrame_.output->stats.milliseconds);
  } catch (const std::exception& e) {
    glFrame_.error = e.what();
  }
  glFrame_.finishedAt = Clock::now();
  glTextureStale_ = true;
}

void GuiApp::submitCpu() {
  // One job runs and at most one waits: the scene is copied once per job start, not once
  // per UI frame while a slider is dragged.
  if (worker_.hasQueued()) return;
  const std::uint64_t now = doc_.revision;
  const bool needFrame = cpuSubmitted_ != now;
  const bool needProbe = pin_.pixel && (pin_.cpuAskedRevision != now || pin_.cpuAskedPixel != pin_.pixel);
  if (!needFrame && !needProbe) return;
  CpuJob job;
  job.revision = now;
  job.scene = doc_.scene;
  job.settings = doc_.scene.settings;
  job.width = renderWidth_;
  job.height = renderHeight_;
  job.path = prefs_.cpuPath;
  job.isa = prefs_.cpuIsa;
  job.renderFrame = needFrame;
  job.probePixel = pin_.pixel;
  if (needFrame) {
    cpuSubmitted_ = now;
    if (glFrame_.revision == now) glForCpu_[now] = glFrame_.output;
  }
  if (pin_.pixel) {
    pin_.cpuAskedRevision = now;
    pin_.cpuAskedPixel = pin_.pixel;
  }
  worker_.submit(std::move(job));
}

void GuiApp::updateDiff() {
  if (cpuFrame_.revision == 0 || cpuFrame_.revision == diff_.revision) return;
  const auto twin = glForCpu_.find(cpuFrame_.revision);
  const std::shared_ptr<const RenderOutput> gl = twin != glForCpu_.end() ? twin->second : nullptr;
  // Older GL frames can no longer meet their CPU twin.
  std::erase_if(glForCpu_, [this](const auto& entry) { return entry.first <= cpuFrame_.revision; });
  diff_.revision = cpuFrame_.revision;
  diff_.texturesStale = true;
  diff_.result.reset();
  diff_.error.clear();
  if (!cpuFrame_.output || !gl) {
    diff_.error = "no diff: one backend has no image for this frame (see its error)";
    return;
  }
  try {
    diff_.result = compareDetailed(*cpuFrame_.output, *gl);
  } catch (const std::exception& e) {
    diff_.error = e.what();
  }
}

PixelSample GuiApp::glSampleAt(View view, PixelPos pixel) {
  RenderSettings settings = doc_.scene.settings;
  settings.view = view;
  settings.tbnLines.enabled = false;  // lines could cover the pixel
  return sampleAt(glRenderer_->render(doc_.scene, settings, renderWidth_, renderHeight_), pixel);
}

void GuiApp::probeGl() {
  if (!pin_.pixel) return;
  // Each view is a full GL frame on this thread: while the user drags or types, the UI
  // frame already renders the main image, so the probe waits until the interaction ends.
  if (interacting_) return;
  if (pin_.glRevision != doc_.revision) {
    pin_.gl = ViewSamples{};
    pin_.glError.clear();
    pin_.glRevision = doc_.revision;
  }
  if (!pin_.glError.empty()) return;
  // One view per UI frame, so pinning never stalls the UI for ten renders at once.
  const auto next = std::find_if(pin_.gl.begin(), pin_.gl.end(), [](const auto& sample) { return !sample; });
  if (next == pin_.gl.end()) return;
  const std::size_t i = static_cast<std::size_t>(next - pin_.gl.begin());
  try {
    pin_.gl[i] = glSampleAt(kAllViews[i], *pin_.pixel);
  } catch (const std::exception& e) {
    pin_.glError = e.what();
  }
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
  const auto shown = [&](const RenderOutput& output) {
    return linear ? viewImage(withLinearDepth(output, camera.near, camera.far, linearDepthRange_), background)
                  : viewImage(output, background);
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
