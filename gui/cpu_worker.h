// Renders CPU frames on a worker thread so a slow frame never blocks the UI. Each job shares
// an immutable copy of the scene (no mutable state is shared with the UI thread); the
// newest submitted job wins (job_queue.h): a job not yet started is replaced by a newer one,
// and a pixel probe still running stops early when a newer job is queued.
#pragma once

#include "gui/job_queue.h"
#include "gui/pixel_probe.h"
#include "scene/renderer.h"
#include "scene/shadow_trace.h"
#include "scene/ssr_trace.h"
#include "softrender/cpu_renderer.h"
#include "softrender/pixel_trace.h"

#include <chrono>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <thread>

namespace twr::gui {

using Clock = std::chrono::steady_clock;

struct CpuJob {
  std::uint64_t revision = 0;          // the UI's edit counter when the scene was copied
  std::shared_ptr<const Scene> scene;  // shared with the GL job of the same edit, never changed
  RenderSettings settings;
  int width = 0;   // pixels
  int height = 0;  // pixels
  CpuPath path = CpuPath::Fast;  // the renderer to draw with (the worker makes a new one on a change)
  CpuIsa isa = CpuIsa::Auto;     // a supported target (the UI offers no other)
  bool renderFrame = true;           // false: only the probe (a new pinned pixel, same frame)
  std::optional<PixelPos> probePixel;  // trace this pixel and read it in every debug view
  int ssrRay = kSsrMirrorRay;          // the ray whose SSR march the probe traces (a sample the settings have)
  // Probe-only jobs: this edit's frame, already drawn by `path` (the trace's final pixel comes
  // from it); null: the probe draws the frame once more.
  std::shared_ptr<const RenderOutput> frame;
};

struct CpuProbe {
  PixelPos pixel;
  std::shared_ptr<const PixelTrace> trace;  // null when tracing threw
  std::string traceError;
  ViewSamples views;  // the CPU image at the pixel in each debug view (TBN lines off)
  bool complete = false;  // false when a newer job cut the views short
  // A frame with reflections: the pixel's march of the job's ray step by step
  // (softrender/ssr.h's traceSsrMarch), or why not.
  std::optional<SsrMarchTrace> ssrMarch;
  std::string ssrMarchError;
  // Each shadowed light's test at the pixel tap by tap, from the trace (shadowTapTracesOf).
  std::vector<ShadowTapTrace> shadowTaps;
};

struct CpuFrame {
  std::uint64_t revision = 0;
  int width = 0, height = 0;
  bool rendered = false;                       // renderFrame was set (output or error is new)
  std::shared_ptr<const RenderOutput> output;  // null when the render threw or was not asked for
  std::string error;                           // what the render threw, else empty
  std::string cpuPath;                         // what drew it: "teaching" or "fast (avx2)"
  std::optional<CpuProbe> probe;
  Clock::time_point finishedAt{};  // when the render (not the probe) finished
};

class CpuWorker {
 public:
  CpuWorker();
  ~CpuWorker();  // finishes the running render, drops a queued job, joins
  CpuWorker(const CpuWorker&) = delete;
  CpuWorker& operator=(const CpuWorker&) = delete;

  // Queues `job`, replacing a queued job that has not started.
  void submit(CpuJob job) { queue_.submit(std::move(job)); }
  // True when no job is queued or running.
  bool idle() const { return queue_.idle(); }
  // True when a job waits for the running one to finish.
  bool hasQueued() const { return queue_.hasQueued(); }
  // True when a finished job waits to be taken (an idle UI draws a frame for it).
  bool hasFinished() const { return queue_.hasFinished(); }
  // Finished jobs not yet taken, oldest first (at most a few: the UI takes them every frame).
  std::vector<CpuFrame> takeFinished() { return queue_.takeFinished(); }
  // Blocks until idle or `timeout` passes; true when idle.
  bool waitIdle(std::chrono::milliseconds timeout) const { return queue_.waitIdle(timeout); }

 private:
  void run();
  CpuProbe probe(Renderer& renderer, const CpuJob& job, const RenderOutput* frameOutput) const;

  JobQueue<CpuJob, CpuFrame> queue_;
  std::thread thread_;  // last member: starts once the others exist
};

}  // namespace twr::gui
