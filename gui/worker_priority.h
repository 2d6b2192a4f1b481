// Render workers run at a lower priority than the UI thread. With more busy threads than
// cores (both renderers draw on every core, as llvmpipe does), equal priorities would give
// the UI thread one share in five or more, and it would redraw a few times a second; lowered,
// the scheduler serves the UI's short frames first and the renderers get every cycle it
// leaves. Threads a worker starts afterwards (the CPU renderer's pool, llvmpipe's rasterizer
// threads of the worker's context) inherit its priority.
#pragma once

#include <sys/resource.h>
#include <unistd.h>

namespace twr::gui {

// Nice value of the render workers, on Linux's scale from -20 (first) to 19 (last); the UI
// thread keeps 0. 10 weighs about a tenth of 0 in the Linux scheduler.
inline constexpr int kWorkerNice = 10;

// Lowers the calling thread (Linux nice values are per thread). Failing is harmless: the
// worker then runs at the UI's priority.
inline void lowerThisThreadPriority() {
  (void)setpriority(PRIO_PROCESS, static_cast<id_t>(gettid()), kWorkerNice);
}

}  // namespace twr::gui
