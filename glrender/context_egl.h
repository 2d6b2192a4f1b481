// Headless GL contexts through EGL, beside OSMesa: Mesa's surfaceless platform
// (EGL_MESA_platform_surfaceless: llvmpipe, or a GPU's Mesa driver, no display) or one of the
// devices EGL lists (EGL_EXT_platform_device: every GPU a driver offers, NVIDIA's included).
// libEGL is opened at run time with dlopen, like OSMesa, so a machine without it still runs
// the CPU side and OSMesa, and asking for EGL there is a clear InputError (exit 2).
// No window surface: the context is made current with EGL_NO_SURFACE
// (EGL_KHR_surfaceless_context) and the renderer draws into its own framebuffers.
#pragma once

#include "glrender/headless_context.h"

#include <memory>
#include <string>
#include <vector>

namespace twr {

struct EglContextDesc {
  std::string library = "libEGL.so.1";
  int device = kEglSurfaceless;  // kEglSurfaceless, or an index into listEglDevices()
  bool compatibility = false;    // 3.3 compatibility profile (immediate mode) instead of core
  bool fastSampling = false;     // see GlOptions::fastSampling (llvmpipe only)
};

// One device as eglQueryDevicesEXT lists it.
struct EglDeviceInfo {
  int index = 0;               // what --gl-device takes
  std::string extensions;      // the device's EGL_EXTENSIONS
  std::string drmDeviceFile;   // EGL_DRM_DEVICE_FILE_EXT, "" when it has none
  std::string renderNodeFile;  // EGL_DRM_RENDER_NODE_FILE_EXT, "" when it has none
  bool software = false;       // EGL_MESA_device_software: Mesa's llvmpipe / softpipe device
};

// The devices EGL lists, in its order. Throws InputError when the library is missing or
// offers no device enumeration (EGL_EXT_device_enumeration).
std::vector<EglDeviceInfo> listEglDevices(const std::string& library = "libEGL.so.1");

// "" when `library` loads and has eglGetProcAddress, else why not (for tests that skip).
std::string eglLibraryProblem(const std::string& library = "libEGL.so.1");

class EglContext final : public HeadlessGlContext {
 public:
  // Throws InputError naming what is missing: the library, the platform extension, device
  // N, desktop OpenGL, surfaceless contexts or a 3.3 context of the requested profile.
  explicit EglContext(const EglContextDesc& desc);
  ~EglContext() override;
  EglContext(const EglContext&) = delete;
  EglContext& operator=(const EglContext&) = delete;

  void makeCurrent() override;
  void release() noexcept override;
  GlProc procAddress(const char* name) const override;
  bool compatibility() const override { return compatibility_; }
  std::string description() const override;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
  bool compatibility_ = false;
};

}  // namespace twr
