// Renders GL frames on a worker thread in a headless context of its own, so a slow frame
// never blocks the UI (issue 20, defect 9). The context is EGL's (Mesa's surfaceless
// platform: llvmpipe, as the window's GLX context): EGL and GLX hand out the same libglvnd
// dispatch stubs, so the worker and the UI thread share glad's global entry points, each
// calling into its own current context. OSMesa's entry points are its own library's, which
// would pull the UI thread's GL away from the window, so it is not used here.
//
// Each job shares an immutable copy of the scene; a frame is read back whole before it is
// handed over, so the UI never sees a half-drawn one. The newest job wins (job_queue.h), and
// a pixel probe still running stops early when a newer job waits.
#pragma once

#include "gui/job_queue.h"
#include "gui/pixel_probe.h"
#include "glrender/gl_renderer.h"
#include "scene/renderer.h"
#include "scene/shadow_trace.h"
#include "scene/ssr_trace.h"

#include <chrono>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <thread>

namespace twr::gui {

struct GlJob {
  std::uint64_t revision = 0;          // the UI's edit counter when the scene was copied
  std::shared_ptr<const Scene> scene;  // drawn with scene->settings
  int width = 0;                       // pixels
  int height = 0;                      // pixels
  bool renderFrame = true;             // false: only the probe (a new pinned pixel, same frame)
  std::optional<PixelPos> probePixel;  // read this pixel in every debug view
  int ssrRay = kSsrMirrorRay;          // the ray whose SSR march the probe traces (a sample the settings have)
};

struct GlProbe {
  PixelPos pixel;
  ViewSamples views;      // the GL image at the pixel in each debug view (TBN lines off)
  std::string error;      // what a view's render threw, else empty
  bool complete = false;  // false when a newer job cut the views short
  // A frame with reflections: the pixel's march of the job's ray step by step on GL
  // (traceGlSsrMarch), or why not.
  std::optional<SsrMarchTrace> ssrMarch;
  std::string ssrMarchError;
  // A shadowed light: its test at the pixel tap by tap on GL (traceGlShadowTaps), or why not.
  std::vector<ShadowTapTrace> shadowTaps;
  std::string shadowTapsError;
};

struct GlFrameResult {
  std::uint64_t revision = 0;
  int width = 0, height = 0;
  bool rendered = false;                       // renderFrame was set (output or error is new)
  std::shared_ptr<const RenderOutput> output;  // null when the render threw or was not asked for
  std::string error;                           // what the render threw, else empty
  std::optional<GlProbe> probe;
  std::chrono::steady_clock::time_point finishedAt{};  // when the render (not the probe) finished
};

class GlWorker {
 public:
  // `options.context` and currentContextLoader are overridden (EGL, headless).
  explicit GlWorker(GlOptions options);
  ~GlWorker();  // finishes the running render, drops a queued job, joins
  GlWorker(const GlWorker&) = delete;
  GlWorker& operator=(const GlWorker&) = delete;

  void submit(GlJob job) { queue_.submit(std::move(job)); }
  bool idle() const { return queue_.idle(); }
  bool hasQueued() const { return queue_.hasQueued(); }
  bool hasFinished() const { return queue_.hasFinished(); }
  std::vector<GlFrameResult> takeFinished() { return queue_.takeFinished(); }
  bool waitIdle(std::chrono::milliseconds timeout) const { return queue_.waitIdle(timeout); }

 private:
  void run();
  GlProbe probe(Renderer& renderer, const GlJob& job) const;

  GlOptions options_;
  JobQueue<GlJob, GlFrameResult> queue_;
  std::thread thread_;  // last member: starts once the others exist
};

}  // namespace twr::gui
