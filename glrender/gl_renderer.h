// The OpenGL 3.3 renderer behind the Renderer interface. Headless through OSMesa
// (llvmpipe); the GUI renders through its own GLFW context instead.
#pragma once

#include "scene/renderer.h"

#include <memory>
#include <string>

namespace twr {

struct GlOptions {
  bool verbose = false;  // print GL_VERSION / GL_RENDERER on stderr
  // llvmpipe's fast texture path (8-bit bilinear weights, one LOD per quad). Off by default
  // for a fair comparison: GALLIVM_PERF=no_aos_sampling,no_quad_lod is set before the
  // first context is created unless this is true.
  bool fastSampling = false;
  std::string shaderDir;  // empty: embedded shaders; else load shaders from this folder
};

// Throws InputError (exit 2) when OSMesa is missing, the context cannot be created or a
// shader fails to compile or link (with the GLSL log and file/line).
std::unique_ptr<Renderer> makeGlRenderer(const GlOptions& options = {});

// GL_VERSION and GL_RENDERER of the last created context ("" before one exists).
std::string glVersionString();
std::string glRendererString();

}  // namespace twr
