#include "gui/cpu_worker.h"
#include "softrender/ssr.h"
#include "gui/debug_views.h"
#include "gui/worker_priority.h"

#include "softrender/cpu_renderer.h"
#include "softrender/pixel_views.h"

#include <algorithm>
#include <exception>
#include <thread>

namespace twr::gui {

CpuWorker::CpuWorker() : thread_([this] { run(); }) {}

CpuWorker::~CpuWorker() {
  queue_.stop();
  thread_.join();
}

CpuProbe CpuWorker::probe(Renderer& renderer, const CpuJob& job, const RenderOutput* frameOutput) const {
  CpuProbe result;
  result.pixel = *job.probePixel;
  std::shared_ptr<PixelTrace> trace;
  try {
    // The final pixel as the chosen renderer drew it: this job's frame, the frame the UI
    // already has for this edit, else one more render.
    RenderOutput own;
    if (!frameOutput) frameOutput = job.frame.get();
    if (!frameOutput || frameOutput->width != job.width || frameOutput->height != job.height) {
      own = renderer.render(*job.scene, job.settings, job.width, job.height);
      frameOutput = &own;
    }
    // The replay shades with that frame's shadow maps rather than drawing them again on the
    // teaching path (a 2048^2 map on one thread, for every pinned pixel).
    trace = std::make_shared<PixelTrace>(tracePixelVisits(
        *job.scene, job.settings, job.width, job.height, result.pixel.x, result.pixel.yTop,
        frameOutput->shadowMaps.empty() ? nullptr : &frameOutput->shadowMaps));
    const std::size_t i = static_cast<std::size_t>(result.pixel.yTop) * static_cast<std::size_t>(job.width) +
                          static_cast<std::size_t>(result.pixel.x);
    for (std::size_t c = 0; c < 4; ++c) trace->rgba[c] = frameOutput->rgba[i * 4 + c];
    trace->depth = frameOutput->depth[i];
    trace->triangleId = frameOutput->triangleId[i];
    trace->debugLine = frameOutput->lineMask[i] != 0;
    result.trace = trace;
    result.shadowTaps = shadowTapTracesOf(*trace, *job.scene);
    // A frame with reflections: the pixel's march, step by step, from that frame's G-buffer.
    if (drawsSsr(job.settings)) {
      try {
        result.ssrMarch =
            traceSsrMarch(*job.scene, job.settings, *frameOutput, result.pixel.x, result.pixel.yTop, job.ssrRay);
      } catch (const std::exception& e) {
        result.ssrMarchError = e.what();
      }
    }
  } catch (const std::exception& e) {
    result.traceError = e.what();
    return result;
  }
  // Every debug view at the pixel: the traced fragment shaded once per view, not a frame
  // per view (softrender/pixel_views.h), lines off so they cannot cover it.
  for (std::size_t i = 0; i < kViewCount; ++i) {
    if (queue_.superseded()) return result;
    try {
      const ViewPixel pixel = shadeTracedPixel(*job.scene, job.settings, *trace, kAllViews[i]);
      PixelSample sample;
      sample.rgba = pixel.rgba;
      sample.depth = pixel.depth;
      sample.drawn = pixel.triangleId != kNoTriangle;
      result.views[i] = sample;
    } catch (const std::exception&) {
      return result;  // the trace or the frame's own render reports the error
    }
  }
  result.complete = true;
  return result;
}

void CpuWorker::run() {
  lowerThisThreadPriority();  // before the renderer starts threads of its own
  // The renderer lives on this thread only; it draws on every online CPU (as llvmpipe does),
  // which keeps 1280 x 720 frames interactive. A job asking for another path or target gets
  // a new renderer.
  CpuOptions options;
  options.threads = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  std::unique_ptr<Renderer> renderer;
  std::string rendererError;  // why the renderer for `options` could not be made
  while (std::optional<CpuJob> job = queue_.next()) {
    CpuFrame frame;
    frame.revision = job->revision;
    frame.width = job->width;
    frame.height = job->height;
    frame.rendered = job->renderFrame;
    if (!renderer || job->path != options.path || job->isa != options.isa) {
      options.path = job->path;
      options.isa = job->isa;
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
    } else if (job->renderFrame) {
      try {
        frame.output =
            std::make_shared<const RenderOutput>(renderer->render(*job->scene, job->settings, job->width, job->height));
      } catch (const std::exception& e) {
        frame.error = e.what();
      }
    }
    frame.finishedAt = Clock::now();  // the frame's age counts from here, not from the probe's end
    if (job->probePixel && frame.error.empty()) frame.probe = probe(*renderer, *job, frame.output.get());
    queue_.finish(std::move(frame));
  }
}

}  // namespace twr::gui
