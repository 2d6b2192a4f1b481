// Headless GL contexts through OSMesa (Mesa's llvmpipe). The library is opened at run
// time with dlopen, so a machine without it gets a clear InputError instead of a dynamic
// loader failure before main(). GL entry points come through procAddress().
#pragma once

#include "glrender/headless_context.h"

#include <memory>
#include <string>

namespace twr {

struct OsMesaContextDesc {
  std::string library = "libOSMesa.so.8";
  bool compatibility = false;  // 3.3 compatibility profile (immediate mode) instead of core
  bool fastSampling = false;   // see GlOptions::fastSampling
};

class OsMesaContext final : public HeadlessGlContext {
 public:
  // Throws InputError when the library is missing or the context cannot be created.
  explicit OsMesaContext(const OsMesaContextDesc& desc);
  ~OsMesaContext() override;
  OsMesaContext(const OsMesaContext&) = delete;
  OsMesaContext& operator=(const OsMesaContext&) = delete;

  // Binds the context to this thread (throws InputError on failure).
  void makeCurrent() override;
  GlProc procAddress(const char* name) const override;
  bool compatibility() const override { return compatibility_; }
  std::string description() const override;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
  bool compatibility_ = false;
};

// True when `library` opens with dlopen (GlContextKind::Auto's test). It stays loaded.
bool osmesaLibraryLoads(const std::string& library);

}  // namespace twr
