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
  virtual GlProc procAddress(const char* name) const = 0;
  virtual bool compatibility() const = 0;
  // For messages and --verbose: "OSMesa 3.3 core context", "EGL surfaceless 3.3 core context".
  virtual std::string description() const = 0;
};

}  // namespace twr
