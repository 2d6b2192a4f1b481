// Loading glad's core 3.3 entry points into whatever context is current (OSMesa, EGL or GLFW),
// and what that context says about itself.
#pragma once

#include "glrender/gl_renderer.h"

#include <cstdint>
#include <functional>
#include <string>

namespace twr {

using GlProcFunction = std::function<GlProc(const char* name)>;

// Loads the global glad pointers for the current context. Throws InputError when the
// context does not offer OpenGL 3.3; `what` names the context in the message.
// Returns the load's number (see coreGlLoadCount).
std::uint64_t loadCoreGl(const GlProcFunction& procAddress, const std::string& what);

// How many loads the process has made so far. A renderer whose own load is still the last
// one can skip reloading: glad's pointers are its own. That keeps a renderer on a worker
// thread from rewriting them on every frame while another thread calls through them (the
// GUI: EGL and GLX hand out the same libglvnd dispatch stubs, so both threads can share them).
std::uint64_t coreGlLoadCount();

struct GlContextInfo {
  std::string version;   // GL_VERSION
  std::string renderer;  // GL_RENDERER
  std::string vendor;    // GL_VENDOR
  std::string context;   // which context: "OSMesa 3.3 core context", "GLFW window", ...
  bool compatibility = false;  // GL_CONTEXT_PROFILE_MASK has the compatibility bit
};

// Queries the current context (glad must be loaded) and remembers the answer for
// glVersionString() / glRendererString() / glVendorString().
// `context` says which context it is (GlContextInfo::context, glContextString()).
GlContextInfo describeCurrentContext(const std::string& context);

}  // namespace twr
