#include "glrender/context_glfw.h"

#include "glrender/gl_context.h"
#include "scene/errors.h"

#include <glad/gl.h>
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

namespace twr {
namespace {

std::string lastGlfwError() {
  const char* description = nullptr;
  const int code = glfwGetError(&description);
  if (code == GLFW_NO_ERROR) return "no details";
  return description ? description : "error " + std::to_string(code);
}

}  // namespace

GlfwContext::GlfwContext(const GlfwWindowDesc& desc) : compatibility_(desc.compatibility) {
  if (glfwInit() != GLFW_TRUE) {
    throw InputError("GL: GLFW could not start (" + lastGlfwError() + "); is there a display?");
  }
  glfwDefaultWindowHints();
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
  glfwWindowHint(GLFW_OPENGL_PROFILE, desc.compatibility ? GLFW_OPENGL_COMPAT_PROFILE : GLFW_OPENGL_CORE_PROFILE);
  glfwWindowHint(GLFW_VISIBLE, desc.visible ? GLFW_TRUE : GLFW_FALSE);
  window_ = glfwCreateWindow(desc.width, desc.height, desc.title.c_str(), nullptr, nullptr);
  if (!window_) {
    const std::string reason = lastGlfwError();
    glfwTerminate();
    throw InputError(std::string("GL: GLFW could not create a window with an OpenGL 3.3 ") +
                     (desc.compatibility ? "compatibility" : "core") + " profile context (" + reason + ")");
  }
  try {
    makeCurrent();
    glfwSwapInterval(desc.vsync ? 1 : 0);
    const GlContextInfo info = describeCurrentContext("GLFW window");
    version_ = info.version;
    renderer_ = info.renderer;
  } catch (...) {
    glfwDestroyWindow(window_);
    glfwTerminate();
    throw;
  }
}

GlfwContext::~GlfwContext() {
  glfwDestroyWindow(window_);
  glfwTerminate();
}

void GlfwContext::makeCurrent() const {
  glfwMakeContextCurrent(window_);
  loadCoreGl([](const char* name) { return glfwGetProcAddress(name); }, "GLFW window's context");
}

GlProcLoader glfwProcAddress() { return &glfwGetProcAddress; }

}  // namespace twr
