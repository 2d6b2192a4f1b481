// OSMesa through dlopen. No glad here: <GL/osmesa.h> brings the system <GL/gl.h>, which
// must never meet glad's headers in one translation unit.
#include "glrender/context_osmesa.h"

#include "glrender/llvmpipe_sampling.h"
#include "scene/errors.h"

#include <GL/osmesa.h>
#include <dlfcn.h>

#include <array>
#include <cstdint>

namespace twr {

struct OsMesaContext::Impl {
  using CreateContextAttribsFn = decltype(&OSMesaCreateContextAttribs);
  using DestroyContextFn = decltype(&OSMesaDestroyContext);
  using MakeCurrentFn = decltype(&OSMesaMakeCurrent);
  using GetProcAddressFn = decltype(&OSMesaGetProcAddress);

  CreateContextAttribsFn createContextAttribs = nullptr;
  DestroyContextFn destroyContext = nullptr;
  MakeCurrentFn makeCurrent = nullptr;
  GetProcAddressFn getProcAddress = nullptr;
  OSMesaContext context = nullptr;
  // OSMesa insists on a window-system buffer; rendering goes to FBOs, so one pixel.
  std::array<std::uint8_t, 4> defaultBuffer{};
};

OsMesaContext::OsMesaContext(const OsMesaContextDesc& desc)
    : impl_(std::make_unique<Impl>()), compatibility_(desc.compatibility) {
  // Never dlclose'd: Mesa and LLVM register exit handlers that must find their code.
  void* library = dlopen(desc.library.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (!library) {
    const char* reason = dlerror();
    throw InputError("GL: cannot load the OSMesa library '" + desc.library + "' (" +
                     (reason ? reason : "unknown reason") +
                     "); install libosmesa6 (Debian) for headless rendering, or use the EGL context "
                     "(--gl-context egl)");
  }
  auto symbol = [&](const char* name) {
    void* address = dlsym(library, name);
    if (!address) throw InputError("GL: '" + desc.library + "' has no " + name + "; is it OSMesa?");
    return address;
  };
  impl_->createContextAttribs = reinterpret_cast<Impl::CreateContextAttribsFn>(symbol("OSMesaCreateContextAttribs"));
  impl_->destroyContext = reinterpret_cast<Impl::DestroyContextFn>(symbol("OSMesaDestroyContext"));
  impl_->makeCurrent = reinterpret_cast<Impl::MakeCurrentFn>(symbol("OSMesaMakeCurrent"));
  impl_->getProcAddress = reinterpret_cast<Impl::GetProcAddressFn>(symbol("OSMesaGetProcAddress"));

  prepareLlvmpipeSampling(desc.fastSampling);

  constexpr int kDepthBits = 24;  // the window buffer's; the FBO has its own 24-bit depth
  constexpr int kMajorVersion = 3;
  constexpr int kMinorVersion = 3;
  const int attributes[] = {OSMESA_FORMAT,
                            OSMESA_RGBA,
                            OSMESA_DEPTH_BITS,
                            kDepthBits,
                            OSMESA_STENCIL_BITS,
                            0,
                            OSMESA_ACCUM_BITS,
                            0,
                            OSMESA_PROFILE,
                            desc.compatibility ? OSMESA_COMPAT_PROFILE : OSMESA_CORE_PROFILE,
                            OSMESA_CONTEXT_MAJOR_VERSION,
                            kMajorVersion,
                            OSMESA_CONTEXT_MINOR_VERSION,
                            kMinorVersion,
                            0};
  impl_->context = impl_->createContextAttribs(attributes, nullptr);
  if (!impl_->context) {
    throw InputError(std::string("GL: OSMesa could not create a 3.3 ") +
                     (desc.compatibility ? "compatibility" : "core") + " profile context");
  }
}

OsMesaContext::~OsMesaContext() {
  if (impl_ && impl_->context) impl_->destroyContext(impl_->context);
}

void OsMesaContext::makeCurrent() {
  if (!impl_->makeCurrent(impl_->context, impl_->defaultBuffer.data(), GL_UNSIGNED_BYTE, 1, 1)) {
    throw InputError("GL: OSMesaMakeCurrent failed");
  }
}

GlProc OsMesaContext::procAddress(const char* name) const { return impl_->getProcAddress(name); }

bool osmesaLibraryLoads(const std::string& library) {
  // Never dlclose'd, like the context's handle: the next dlopen of it is then free.
  return dlopen(library.c_str(), RTLD_NOW | RTLD_LOCAL) != nullptr;
}

std::string OsMesaContext::description() const {
  return std::string("OSMesa 3.3 ") + (compatibility_ ? "compatibility" : "core") + " context";
}

}  // namespace twr
