// The CPU software pipeline behind the Renderer interface.
#pragma once

#include "scene/renderer.h"

#include <memory>

namespace twr {

struct CpuOptions {
  int threads = 1;  // worker threads (later issues: tiles on both cores); >= 1
};

std::unique_ptr<Renderer> makeCpuRenderer(const CpuOptions& options = {});

}  // namespace twr
