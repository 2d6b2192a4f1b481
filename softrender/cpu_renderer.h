// The CPU software pipeline behind the Renderer interface.
#pragma once

#include "scene/renderer.h"

#include <memory>

namespace twr {

struct CpuOptions {
  // Worker threads, each owning a band of rows (values below 1 mean 1). The image and the
  // statistics are the same for any count: every band sees every triangle in order.
  int threads = 1;
};

std::unique_ptr<Renderer> makeCpuRenderer(const CpuOptions& options = {});

}  // namespace twr
