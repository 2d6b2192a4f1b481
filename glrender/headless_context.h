// What the renderer needs from a headless GL context it owns (OSMesa or EGL): bind it to
// the calling thread and find GL entry points in it. Both libraries are opened at run time.
#pragma once

#include "glrender/gl_renderer.h"

#include <string>

namespace twr {

class HeadlessGlContext {
 public:
  virtual ~HeadlessGlContext() = default;
  // Binds the context to this thread (throws InputError on failure).
  virtual void makeCurrent() = 0;
  // Unbinds it from this thread after a render, where that matters (EGL: libglvnd lets one
  // window-system API have a current context per thread, so a GLX window could not be made
  // current again while an EGL context is). Never throws.
  virtual void release() noexcept {}
  virtual GlProc procAddress(const char* name) const = 0;
  virtual bool compatibility() const = 0;
  // For messages and --verbose: "OSMesa 3.3 core context", "EGL surfaceless 3.3 core context".
  virtual std::string description() const = 0;
};

}  // namespace twr
