#include "glrender/gl_context.h"

#include "scene/errors.h"

#include <glad/gl.h>

#include <atomic>
#include <mutex>

namespace twr {
namespace {

// glVersionString() and friends answer for the last context created in the process, so
// the answer is process state; the lock makes concurrent renderers safe.
struct LastContext {
  std::mutex mutex;
  GlContextInfo info;
};

LastContext& lastContext() {
  static LastContext last;
  return last;
}

GLADapiproc callProcFunction(void* userPointer, const char* name) {
  return (*static_cast<const GlProcFunction*>(userPointer))(name);
}

std::string glString(GLenum name) {
  const GLubyte* text = glGetString(name);
  return text ? reinterpret_cast<const char*>(text) : "";
}

std::atomic<std::uint64_t> gCoreGlLoads{0};

}  // namespace

std::uint64_t coreGlLoadCount() { return gCoreGlLoads.load(); }

std::uint64_t loadCoreGl(const GlProcFunction& procAddress, const std::string& what) {
  GlProcFunction copy = procAddress;
  const int version = gladLoadGLUserPtr(callProcFunction, &copy);
  if (version == 0) throw InputError("GL: could not load OpenGL entry points from the " + what);
  constexpr int kRequiredMajor = 3;
  constexpr int kRequiredMinor = 3;
  if (GLAD_VERSION_MAJOR(version) < kRequiredMajor ||
      (GLAD_VERSION_MAJOR(version) == kRequiredMajor && GLAD_VERSION_MINOR(version) < kRequiredMinor)) {
    throw InputError("GL: the " + what + " offers OpenGL " + std::to_string(GLAD_VERSION_MAJOR(version)) + "." +
                     std::to_string(GLAD_VERSION_MINOR(version)) + ", 3.3 is required");
  }
  return ++gCoreGlLoads;
}

GlContextInfo describeCurrentContext(const std::string& context) {
  GlContextInfo info;
  info.context = context;
  info.version = glString(GL_VERSION);
  info.renderer = glString(GL_RENDERER);
  info.vendor = glString(GL_VENDOR);
  GLint profileMask = 0;
  glGetIntegerv(GL_CONTEXT_PROFILE_MASK, &profileMask);
  info.compatibility = (profileMask & GL_CONTEXT_COMPATIBILITY_PROFILE_BIT) != 0;
  LastContext& last = lastContext();
  const std::lock_guard lock(last.mutex);
  last.info = info;
  return info;
}

std::string glVersionString() {
  LastContext& last = lastContext();
  const std::lock_guard lock(last.mutex);
  return last.info.version;
}

std::string glRendererString() {
  LastContext& last = lastContext();
  const std::lock_guard lock(last.mutex);
  return last.info.renderer;
}

std::string glContextString() {
  LastContext& last = lastContext();
  const std::lock_guard lock(last.mutex);
  return last.info.context;
}

std::string glVendorString() {
  LastContext& last = lastContext();
  const std::lock_guard lock(last.mutex);
  return last.info.vendor;
}

}  // namespace twr
