#include "app/gui/cpu_worker.h"
#include "app/gui/debug_views.h"

#include "softrender/cpu_renderer.h"

#include <algorithm>
#include <exception>
#include <thread>

namespace twr::gui {

CpuWorker::CpuWorker() : thread_([this] { run(); }) {}

CpuWorker::~CpuWorker() {
  {
    const std::lock_guard lock(mutex_);
    stopping_ = true;
    queued_.reset();
  }
  changed_.notify_all();
  thread_.join();
}

void CpuWorker::submit(CpuJob job) {
  {
    const std::lock_guard lock(mutex_);
    queued_ = std::move(job);
  }
  changed_.notify_all();
}

bool CpuWorker::idle() const {
  const std::lock_guard lock(mutex_);
  return !queued_ && !running_;
}

bool CpuWorker::hasQueued() const {
  const std::lock_guard lock(mutex_);
  return queued_.has_value();
}

std::vector<CpuFrame> CpuWorker::takeFinished() {
  const std::lock_guard lock(mutex_);
  std::vector<CpuFrame> frames = std::move(finished_);
  finished_.clear();
  return frames;
}

bool CpuWorker::waitIdle(std::chrono::milliseconds timeout) const {
  std::unique_lock lock(mutex_);
  return changed_.wait_for(lock, timeout, [this] { return !queued_ && !running_; });
}

bool CpuWorker::superseded() const {
  const std::lock_guard lock(mutex_);
  return queued_.has_value() || stopping_;
}

CpuProbe CpuWorker::probe(Renderer& renderer, const CpuOptions& options, const CpuJob& job,
                          const RenderOutput* frameOutput) const {
  CpuProbe result;
  result.pixel = *job.probePixel;
  try {
    PixelTrace trace = tracePixel(job.scene, job.settings, job.width, job.height, result.pixel.x, result.pixel.yTop);
    // tracePixel() takes its final pixel from a render on the default fast path; show the
    // chosen renderer's instead (this job's frame, else one more render).
    const CpuOptions tracePixelOwn;
    if (options.path != tracePixelOwn.path || options.isa != tracePixelOwn.isa) {
      RenderOutput own;
      if (!frameOutput) {
        own = renderer.render(job.scene, job.settings, job.width, job.height);
        frameOutput = &own;
      }
      const std::size_t i = static_cast<std::size_t>(result.pixel.yTop) * static_cast<std::size_t>(job.width) +
                            static_cast<std::size_t>(result.pixel.x);
      for (std::size_t c = 0; c < 4; ++c) trace.rgba[c] = frameOutput->rgba[i * 4 + c];
      trace.depth = frameOutput->depth[i];
      trace.triangleId = frameOutput->triangleId[i];
      trace.debugLine = frameOutput->lineMask[i] != 0;
    }
    result.trace = std::make_shared<const PixelTrace>(std::move(trace));
  } catch (const std::exception& e) {
    result.traceError = e.what();
    return result;
  }
  // Every debug view at the pixel, lines off so they cannot cover it.
  RenderSettings viewSettings = job.settings;
  viewSettings.tbnLines.enabled = false;
  for (std::size_t i = 0; i < kViewCount; ++i) {
    if (superseded()) return result;
    viewSettings.view = kAllViews[i];
    try {
      result.views[i] = sampleAt(renderer.render(job.scene, viewSettings, job.width, job.height), result.pixel);
    } catch (const std::exception&) {
      return result;  // the frame's own render reports the error
    }
  }
  result.complete = true;
  return result;
}

void CpuWorker::run() {
  // The renderer lives on this thread only; it draws on every online CPU (as llvmpipe does),
  // which keeps 1280 x 720 frames and the inspector's per-view renders interactive. A job
  // asking for another path or target gets a new renderer.
  CpuOptions options;
  options.threads = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  std::unique_ptr<Renderer> renderer;
  std::string rendererError;  // why the renderer for `options` could not be made
  for (;;) {
    CpuJob job;
    {
      std::unique_lock lock(mutex_);
      changed_.wait(lock, [this] { return stopping_ || queued_.has_value(); });
      if (stopping_) return;
      job = std::move(*queued_);
      queued_.reset();
      running_ = true;
    }
    CpuFrame frame;
    frame.revision = job.revision;
    frame.width = job.width;
    frame.height = job.height;
    frame.rendered = job.renderFrame;
    if (!renderer || job.path != options.path || job.isa != options.isa) {
      options.path = job.path;
      options.isa = job.isa;
      try {
        renderer = makeCpuRenderer(options);
        rendererError.clear();
      } catch (const std::exception& e) {
        renderer.reset();
        rendererError = e.what();
      }
    }
    frame.cpuPath = cpuPathName(options);
    if (!renderer) {
      frame.error = rendererError;
    } else if (job.renderFrame) {
      try {
        frame.output =
            std::make_shared<const RenderOutput>(renderer->render(job.scene, job.settings, job.width, job.height));
      } catch (const std::exception& e) {
        frame.error = e.what();
      }
    }
    frame.finishedAt = Clock::now();  // the frame's age counts from here, not from the probe's end
    if (job.probePixel && frame.error.empty()) frame.probe = probe(*renderer, options, job, frame.output.get());
    {
      const std::lock_guard lock(mutex_);
      finished_.push_back(std::move(frame));
      running_ = false;
    }
    changed_.notify_all();
  }
}

}  // namespace twr::gui
