// A windowed GL context for the GUI: a GLFW window with an OpenGL 3.3 core context (or
// compatibility, for immediate-mode TBN lines), glad loaded for it. Draw the scene into
// it with makeGlRenderer(GlOptions{.currentContextLoader = glfwProcAddress()}).
// One GlfwContext at a time: it initialises GLFW and terminates it when destroyed.
#pragma once

#include "glrender/gl_renderer.h"

#include <string>

struct GLFWwindow;

namespace twr {

struct GlfwWindowDesc {
  int width = 1280;   // window size in screen coordinates
  int height = 800;
  std::string title = "twinraster";
  bool compatibility = false;  // 3.3 compatibility profile instead of core
  bool visible = true;
  bool vsync = true;
};

class GlfwContext {
 public:
  // Throws InputError when GLFW cannot start (no display) or the context cannot be made.
  explicit GlfwContext(const GlfwWindowDesc& desc);
  ~GlfwContext();
  GlfwContext(const GlfwContext&) = delete;
  GlfwContext& operator=(const GlfwContext&) = delete;

  GLFWwindow* window() const { return window_; }
  bool compatibility() const { return compatibility_; }
  // Makes the window's context current and reloads glad's global pointers for it (a
  // headless render through OSMesa points them elsewhere).
  void makeCurrent() const;
  std::string glVersion() const { return version_; }
  std::string glRenderer() const { return renderer_; }

 private:
  GLFWwindow* window_ = nullptr;
  bool compatibility_ = false;
  std::string version_;
  std::string renderer_;
};

// glfwGetProcAddress, for GlOptions::currentContextLoader.
GlProcLoader glfwProcAddress();

}  // namespace twr
