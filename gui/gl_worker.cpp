#include "gui/gl_worker.h"
#include "gui/debug_views.h"
#include "gui/worker_priority.h"

#include <exception>

namespace twr::gui {

GlWorker::GlWorker(GlOptions options) : options_(std::move(options)), thread_([this] { run(); }) {}

GlWorker::~GlWorker() {
  queue_.stop();
  thread_.join();
}

GlProbe GlWorker::probe(Renderer& renderer, const GlJob& job) const {
  GlProbe result;
  result.pixel = *job.probePixel;
  // Every debug view at the pixel, lines off so they cannot cover it; each a one-pixel render
  // (renderGlPixel), not a frame.
  // Forward, as the CPU side shades the traced fragment (pixel_views.h): a deferred frame's
  // G-buffer is listed on its own rows. No reflections either: a one-pixel render holds no
  // other pixel for a ray to find.
  RenderSettings viewSettings = job.scene->settings;
  viewSettings.tbnLines.enabled = false;
  viewSettings.pipeline = Pipeline::Forward;
  viewSettings.ssr.enabled = false;
  for (std::size_t i = 0; i < kViewCount; ++i) {
    if (queue_.superseded()) return result;
    viewSettings.view = kAllViews[i];
    try {
      const RenderOutput pixel =
          renderGlPixel(renderer, *job.scene, viewSettings, job.width, job.height, result.pixel.x, result.pixel.yTop);
      result.views[i] = sampleAt(pixel, PixelPos{0, 0});
    } catch (const std::exception& e) {
      result.error = e.what();
      return result;
    }
  }
  // A frame with reflections: the pixel's march step by step on GL (one more frame, its
  // reflection pass followed by ssr.frag's probe).
  if (drawsSsr(job.scene->settings)) {
    if (queue_.superseded()) return result;
    try {
      result.ssrMarch = traceGlSsrMarch(renderer, *job.scene, job.scene->settings, job.width, job.height,
                                        result.pixel.x, result.pixel.yTop, job.ssrRay);
    } catch (const std::exception& e) {
      result.ssrMarchError = e.what();
    }
  }
  // A shadowed light: its test tap by tap on GL (one pixel draw per field of the probe).
  if (sceneHasShadows(*job.scene)) {
    if (queue_.superseded()) return result;
    try {
      result.shadowTaps = traceGlShadowTaps(renderer, *job.scene, job.scene->settings, job.width, job.height,
                                            result.pixel.x, result.pixel.yTop);
    } catch (const std::exception& e) {
      result.shadowTapsError = e.what();
    }
  }
  result.complete = true;
  return result;
}

void GlWorker::run() {
  lowerThisThreadPriority();  // before the renderer starts threads of its own
  // The renderer and its contexts live on this thread only; they are made on the first job.
  GlOptions options = options_;
  options.context = GlContextKind::Egl;
  options.currentContextLoader = nullptr;
  std::unique_ptr<Renderer> renderer = makeGlRenderer(options);
  while (std::optional<GlJob> job = queue_.next()) {
    GlFrameResult frame;
    frame.revision = job->revision;
    frame.width = job->width;
    frame.height = job->height;
    frame.rendered = job->renderFrame;
    if (job->renderFrame) {
      try {
        frame.output = std::make_shared<const RenderOutput>(
            renderer->render(*job->scene, job->scene->settings, job->width, job->height));
      } catch (const std::exception& e) {
        frame.error = e.what();
      }
    }
    frame.finishedAt = std::chrono::steady_clock::now();  // the frame's age counts from here
    if (job->probePixel && frame.error.empty()) frame.probe = probe(*renderer, *job);
    queue_.finish(std::move(frame));
  }
}

}  // namespace twr::gui
