// EGL through dlopen. No glad and no GL header here (as in context_osmesa.cpp): EGL's own
// headers only, with EGL_NO_X11 so eglplatform.h does not pull in Xlib's macros.
#define EGL_NO_X11
#include "glrender/context_egl.h"

#include "glrender/llvmpipe_sampling.h"
#include "scene/errors.h"

#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <dlfcn.h>

#include <map>
#include <mutex>
#include <sstream>

namespace twr {
namespace {

constexpr EGLint kMajorVersion = 3;
constexpr EGLint kMinorVersion = 3;
// EGL 1.5 made EGL_KHR_create_context's attributes (versions, profile mask) core.
constexpr EGLint kEglCreateContextMajor = 1;
constexpr EGLint kEglCreateContextMinor = 5;

bool hasExtension(const char* list, const std::string& name) {
  if (!list) return false;
  std::istringstream stream(list);
  std::string item;
  while (stream >> item) {
    if (item == name) return true;
  }
  return false;
}

std::string errorName(EGLint error) {
  switch (error) {
    case EGL_SUCCESS: return "EGL_SUCCESS";
    case EGL_NOT_INITIALIZED: return "EGL_NOT_INITIALIZED";
    case EGL_BAD_ACCESS: return "EGL_BAD_ACCESS";
    case EGL_BAD_ALLOC: return "EGL_BAD_ALLOC";
    case EGL_BAD_ATTRIBUTE: return "EGL_BAD_ATTRIBUTE";
    case EGL_BAD_CONFIG: return "EGL_BAD_CONFIG";
    case EGL_BAD_CONTEXT: return "EGL_BAD_CONTEXT";
    case EGL_BAD_CURRENT_SURFACE: return "EGL_BAD_CURRENT_SURFACE";
    case EGL_BAD_DISPLAY: return "EGL_BAD_DISPLAY";
    case EGL_BAD_MATCH: return "EGL_BAD_MATCH";
    case EGL_BAD_NATIVE_PIXMAP: return "EGL_BAD_NATIVE_PIXMAP";
    case EGL_BAD_NATIVE_WINDOW: return "EGL_BAD_NATIVE_WINDOW";
    case EGL_BAD_PARAMETER: return "EGL_BAD_PARAMETER";
    case EGL_BAD_SURFACE: return "EGL_BAD_SURFACE";
    case EGL_CONTEXT_LOST: return "EGL_CONTEXT_LOST";
    default: {
      std::ostringstream text;
      text << "EGL error 0x" << std::hex << error;
      return text.str();
    }
  }
}

// The entry points this file uses: EGL 1.4 ones from the library, extension ones through
// eglGetProcAddress (null when the extension is absent).
struct EglApi {
  std::string library;
  PFNEGLGETPROCADDRESSPROC getProcAddress = nullptr;
  PFNEGLGETERRORPROC getError = nullptr;
  PFNEGLQUERYSTRINGPROC queryString = nullptr;
  PFNEGLINITIALIZEPROC initialize = nullptr;
  PFNEGLBINDAPIPROC bindApi = nullptr;
  PFNEGLCHOOSECONFIGPROC chooseConfig = nullptr;
  PFNEGLCREATECONTEXTPROC createContext = nullptr;
  PFNEGLDESTROYCONTEXTPROC destroyContext = nullptr;
  PFNEGLMAKECURRENTPROC makeCurrent = nullptr;
  PFNEGLGETCURRENTCONTEXTPROC getCurrentContext = nullptr;
  std::string clientExtensions;  // eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS)
  PFNEGLGETPLATFORMDISPLAYEXTPROC getPlatformDisplay = nullptr;
  PFNEGLQUERYDEVICESEXTPROC queryDevices = nullptr;
  PFNEGLQUERYDEVICESTRINGEXTPROC queryDeviceString = nullptr;
  PFNEGLGETDISPLAYDRIVERNAMEPROC getDisplayDriverName = nullptr;  // EGL_MESA_query_driver

  std::string lastError() const { return errorName(getError()); }
};

template <typename Fn>
Fn extensionFunction(const EglApi& api, const char* name) {
  return reinterpret_cast<Fn>(api.getProcAddress(name));
}

// One EglApi per library name, loaded on first use. Never dlclose'd: Mesa and LLVM register
// exit handlers that must find their code. The lock guards the process-wide table.
const EglApi& eglApi(const std::string& library) {
  static std::mutex mutex;
  static std::map<std::string, EglApi> loaded;
  const std::lock_guard lock(mutex);
  const auto found = loaded.find(library);
  if (found != loaded.end()) return found->second;

  void* handle = dlopen(library.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (!handle) {
    const char* reason = dlerror();
    throw InputError("GL: cannot load the EGL library '" + library + "' (" + (reason ? reason : "unknown reason") +
                     "); install libegl1 and libegl-mesa0 (Debian) for EGL headless rendering");
  }
  auto symbol = [&](const char* name) {
    void* address = dlsym(handle, name);
    if (!address) throw InputError("GL: '" + library + "' has no " + name + "; is it libEGL?");
    return address;
  };
  EglApi api;
  api.library = library;
  api.getProcAddress = reinterpret_cast<PFNEGLGETPROCADDRESSPROC>(symbol("eglGetProcAddress"));
  api.getError = reinterpret_cast<PFNEGLGETERRORPROC>(symbol("eglGetError"));
  api.queryString = reinterpret_cast<PFNEGLQUERYSTRINGPROC>(symbol("eglQueryString"));
  api.initialize = reinterpret_cast<PFNEGLINITIALIZEPROC>(symbol("eglInitialize"));
  api.bindApi = reinterpret_cast<PFNEGLBINDAPIPROC>(symbol("eglBindAPI"));
  api.chooseConfig = reinterpret_cast<PFNEGLCHOOSECONFIGPROC>(symbol("eglChooseConfig"));
  api.createContext = reinterpret_cast<PFNEGLCREATECONTEXTPROC>(symbol("eglCreateContext"));
  api.destroyContext = reinterpret_cast<PFNEGLDESTROYCONTEXTPROC>(symbol("eglDestroyContext"));
  api.makeCurrent = reinterpret_cast<PFNEGLMAKECURRENTPROC>(symbol("eglMakeCurrent"));
  api.getCurrentContext = reinterpret_cast<PFNEGLGETCURRENTCONTEXTPROC>(symbol("eglGetCurrentContext"));
  // Client extensions (EGL_EXT_client_extensions); null on an EGL 1.4 without them.
  const char* client = api.queryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
  api.clientExtensions = client ? client : "";
  if (hasExtension(client, "EGL_EXT_platform_base")) {
    api.getPlatformDisplay = extensionFunction<PFNEGLGETPLATFORMDISPLAYEXTPROC>(api, "eglGetPlatformDisplayEXT");
  }
  if (hasExtension(client, "EGL_EXT_device_enumeration") || hasExtension(client, "EGL_EXT_device_base")) {
    api.queryDevices = extensionFunction<PFNEGLQUERYDEVICESEXTPROC>(api, "eglQueryDevicesEXT");
  }
  if (hasExtension(client, "EGL_EXT_device_query") || hasExtension(client, "EGL_EXT_device_base")) {
    api.queryDeviceString = extensionFunction<PFNEGLQUERYDEVICESTRINGEXTPROC>(api, "eglQueryDeviceStringEXT");
  }
  api.getDisplayDriverName = extensionFunction<PFNEGLGETDISPLAYDRIVERNAMEPROC>(api, "eglGetDisplayDriverName");
  return loaded.emplace(library, std::move(api)).first->second;
}

std::vector<EGLDeviceEXT> queryDevices(const EglApi& api) {
  if (!api.queryDevices) {
    throw InputError("GL: the EGL library '" + api.library +
                     "' has no EGL_EXT_device_enumeration, so it lists no devices");
  }
  EGLint count = 0;
  if (!api.queryDevices(0, nullptr, &count)) {
    throw InputError("GL: eglQueryDevicesEXT failed (" + api.lastError() + ")");
  }
  std::vector<EGLDeviceEXT> devices(static_cast<std::size_t>(count));
  if (count > 0 && !api.queryDevices(count, devices.data(), &count)) {
    throw InputError("GL: eglQueryDevicesEXT failed (" + api.lastError() + ")");
  }
  devices.resize(static_cast<std::size_t>(count));
  return devices;
}

std::string deviceString(const EglApi& api, EGLDeviceEXT device, EGLint name) {
  if (!api.queryDeviceString) return {};
  const char* text = api.queryDeviceString(device, name);
  return text ? text : "";
}

}  // namespace

std::vector<EglDeviceInfo> listEglDevices(const std::string& library) {
  const EglApi& api = eglApi(library);
  const std::vector<EGLDeviceEXT> devices = queryDevices(api);
  std::vector<EglDeviceInfo> infos;
  for (std::size_t i = 0; i < devices.size(); ++i) {
    EglDeviceInfo info;
    info.index = static_cast<int>(i);
    info.extensions = deviceString(api, devices[i], EGL_EXTENSIONS);
    // Querying a name the device has no extension for is an EGL error; ask only for those.
    if (hasExtension(info.extensions.c_str(), "EGL_EXT_device_drm")) {
      info.drmDeviceFile = deviceString(api, devices[i], EGL_DRM_DEVICE_FILE_EXT);
    }
    if (hasExtension(info.extensions.c_str(), "EGL_EXT_device_drm_render_node")) {
      info.renderNodeFile = deviceString(api, devices[i], EGL_DRM_RENDER_NODE_FILE_EXT);
    }
    info.software = hasExtension(info.extensions.c_str(), "EGL_MESA_device_software");
    infos.push_back(std::move(info));
  }
  return infos;
}

std::string eglLibraryProblem(const std::string& library) {
  try {
    eglApi(library);
    return {};
  } catch (const InputError& error) {
    return error.what();
  }
}

struct EglContext::Impl {
  const EglApi* api = nullptr;
  EGLDisplay display = EGL_NO_DISPLAY;
  EGLContext context = EGL_NO_CONTEXT;
  std::string where;   // "EGL surfaceless platform", "EGL device 1 (/dev/dri/card0)"
  std::string driver;  // EGL_MESA_query_driver's name, "" when not offered
};

EglContext::EglContext(const EglContextDesc& desc)
    : impl_(std::make_unique<Impl>()), compatibility_(desc.compatibility) {
  const EglApi& api = eglApi(desc.library);
  impl_->api = &api;
  if (!api.getPlatformDisplay) {
    throw InputError("GL: the EGL library '" + desc.library +
                     "' has no EGL_EXT_platform_base, so it cannot open a display without a window system");
  }
  if (desc.device == kEglSurfaceless) {
    if (!hasExtension(api.clientExtensions.c_str(), "EGL_MESA_platform_surfaceless")) {
      throw InputError("GL: the EGL library '" + desc.library +
                       "' has no EGL_MESA_platform_surfaceless (Mesa's); pick one of its devices instead "
                       "(--gl-device N, `twinraster info --gl` lists them)");
    }
    impl_->where = "EGL surfaceless platform";
    impl_->display = api.getPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
  } else {
    if (!hasExtension(api.clientExtensions.c_str(), "EGL_EXT_platform_device")) {
      throw InputError("GL: the EGL library '" + desc.library + "' has no EGL_EXT_platform_device, so EGL device " +
                       std::to_string(desc.device) + " cannot be opened");
    }
    const std::vector<EGLDeviceEXT> devices = queryDevices(api);
    if (desc.device < 0 || desc.device >= static_cast<int>(devices.size())) {
      throw InputError("GL: no EGL device " + std::to_string(desc.device) + ": EGL lists " +
                       std::to_string(devices.size()) + " device(s)" +
                       (devices.empty() ? std::string() : ", numbered 0 to " + std::to_string(devices.size() - 1)) +
                       " (`twinraster info --gl` lists them)");
    }
    const EGLDeviceEXT device = devices[static_cast<std::size_t>(desc.device)];
    const std::string deviceExtensions = deviceString(api, device, EGL_EXTENSIONS);
    const std::string file = hasExtension(deviceExtensions.c_str(), "EGL_EXT_device_drm")
                                 ? deviceString(api, device, EGL_DRM_DEVICE_FILE_EXT)
                                 : std::string();
    impl_->where = "EGL device " + std::to_string(desc.device) + (file.empty() ? "" : " (" + file + ")");
    impl_->display = api.getPlatformDisplay(EGL_PLATFORM_DEVICE_EXT, device, nullptr);
  }
  if (impl_->display == EGL_NO_DISPLAY) {
    throw InputError("GL: the " + impl_->where + " gives no display (" + api.lastError() + ")");
  }

  // Before eglInitialize: that is when llvmpipe reads GALLIVM_PERF.
  prepareLlvmpipeSampling(desc.fastSampling);

  // The display is never terminated: the process's contexts share it, and EGL tears it down
  // at exit. Initialising an initialised display is allowed and changes nothing.
  EGLint eglMajor = 0, eglMinor = 0;
  if (!api.initialize(impl_->display, &eglMajor, &eglMinor)) {
    throw InputError("GL: eglInitialize failed on the " + impl_->where + " (" + api.lastError() + ")");
  }
  const char* extensions = api.queryString(impl_->display, EGL_EXTENSIONS);
  if (hasExtension(extensions, "EGL_MESA_query_driver") && api.getDisplayDriverName) {
    const char* driver = api.getDisplayDriverName(impl_->display);
    impl_->driver = driver ? driver : "";
  }
  const bool createContext15 = eglMajor > kEglCreateContextMajor ||
                               (eglMajor == kEglCreateContextMajor && eglMinor >= kEglCreateContextMinor);
  if (!createContext15 && !hasExtension(extensions, "EGL_KHR_create_context")) {
    throw InputError("GL: the " + impl_->where + " (EGL " + std::to_string(eglMajor) + "." +
                     std::to_string(eglMinor) +
                     ") has neither EGL 1.5 nor EGL_KHR_create_context, so no 3.3 core context can be asked for");
  }
  if (!hasExtension(extensions, "EGL_KHR_surfaceless_context")) {
    throw InputError("GL: the " + impl_->where +
                     " has no EGL_KHR_surfaceless_context (a context current without a surface)");
  }
  if (!api.bindApi(EGL_OPENGL_API)) {
    const char* apis = api.queryString(impl_->display, EGL_CLIENT_APIS);
    throw InputError("GL: the " + impl_->where + " offers no desktop OpenGL (client APIs: " +
                     (apis ? apis : "none listed") + ")");
  }

  // Any config that renders desktop GL: nothing is drawn into a surface of it.
  EGLConfig config = EGL_NO_CONFIG_KHR;
  if (!hasExtension(extensions, "EGL_KHR_no_config_context")) {
    const EGLint configAttributes[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_SURFACE_TYPE, EGL_DONT_CARE, EGL_NONE};
    EGLint found = 0;
    if (!api.chooseConfig(impl_->display, configAttributes, &config, 1, &found) || found < 1) {
      throw InputError("GL: the " + impl_->where + " has no config that renders OpenGL (" + api.lastError() + ")");
    }
  }
  const EGLint contextAttributes[] = {EGL_CONTEXT_MAJOR_VERSION,
                                      kMajorVersion,
                                      EGL_CONTEXT_MINOR_VERSION,
                                      kMinorVersion,
                                      EGL_CONTEXT_OPENGL_PROFILE_MASK,
                                      desc.compatibility ? EGL_CONTEXT_OPENGL_COMPATIBILITY_PROFILE_BIT
                                                         : EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                                      EGL_NONE};
  impl_->context = api.createContext(impl_->display, config, EGL_NO_CONTEXT, contextAttributes);
  if (impl_->context == EGL_NO_CONTEXT) {
    throw InputError("GL: the " + impl_->where + " could not create a 3.3 " +
                     (desc.compatibility ? "compatibility" : "core") + " profile context (" + api.lastError() + ")");
  }
}

EglContext::~EglContext() {
  if (!impl_ || impl_->context == EGL_NO_CONTEXT) return;
  const EglApi& api = *impl_->api;
  // A context current on this thread is only marked for deletion; release it so it goes now.
  if (api.getCurrentContext() == impl_->context) {
    api.makeCurrent(impl_->display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
  }
  api.destroyContext(impl_->display, impl_->context);
}

void EglContext::makeCurrent() {
  const EglApi& api = *impl_->api;
  // The bound API is per thread: a renderer may be used from another thread than it was made on.
  api.bindApi(EGL_OPENGL_API);
  if (!api.makeCurrent(impl_->display, EGL_NO_SURFACE, EGL_NO_SURFACE, impl_->context)) {
    const EGLint error = api.getError();
    std::string hint;
    if (error == EGL_BAD_ACCESS) {
      hint = "; another context is current on this thread (libglvnd refuses EGL while a GLX context, "
             "e.g. a GLFW window's, is current: release that one first)";
    }
    throw InputError("GL: eglMakeCurrent failed on the " + impl_->where + " (" + errorName(error) + ")" + hint);
  }
}

void EglContext::release() noexcept {
  const EglApi& api = *impl_->api;
  if (api.getCurrentContext() == impl_->context) {
    api.makeCurrent(impl_->display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
  }
}

GlProc EglContext::procAddress(const char* name) const {
  // Core GL functions come through eglGetProcAddress too (EGL 1.5,
  // EGL_KHR_get_all_proc_addresses); both Mesa and NVIDIA offer that.
  return impl_->api->getProcAddress(name);
}

std::string EglContext::description() const {
  return impl_->where + (impl_->driver.empty() ? "" : " (driver " + impl_->driver + ")") + " 3.3 " +
         (compatibility_ ? "compatibility" : "core") + " context";
}

}  // namespace twr
