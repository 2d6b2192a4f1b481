// The OpenGL 3.3 renderer behind the Renderer interface. Headless through OSMesa
// (llvmpipe) by default; the GUI can instead draw in its own current GLFW context
// (GlOptions::currentContextLoader, see glrender/context_glfw.h).
#pragma once

#include "scene/renderer.h"

#include <memory>
#include <string>

namespace twr {

// A GL entry point and a function that finds one by name (glfwGetProcAddress has this type).
using GlProc = void (*)();
using GlProcLoader = GlProc (*)(const char* name);

// What one frame draws into and reads back.
//   Full  colour, depth, triangle ids and the TBN-line mask, all four read back, and a
//         GL_SAMPLES_PASSED query for RenderStats::pixelsShaded: everything compare, the
//         app and the tests need (glrender/gl_targets.h).
//   Lean  the frame an OpenGL user draws: the same programs (the same #define permutation,
//         plus NO_TRIANGLE_ID: no id output, which llvmpipe pays for even unattached), state
//         and draw calls into colour + depth only, no occlusion query, and one glReadPixels
//         of the colour (rows flipped to top first, as RenderOutput wants).
//         RenderOutput then holds rgba alone (depth, triangleId and lineMask are empty) and
//         stats.pixelsShaded is 0. The colour is bit for bit the Full frame's
//         (tests/glrender/test_gl_lean_frame.cpp). `twinraster bench` times it as the fair
//         reference for the CPU pipeline (gl_lean_* keys).
enum class GlFrame { Full, Lean };

struct GlOptions {
  bool verbose = false;  // print GL_VERSION / GL_RENDERER on stderr
  // llvmpipe's fast texture path (8-bit bilinear weights, one LOD per quad). Off by default
  // for a fair comparison: GALLIVM_PERF=no_aos_sampling,no_quad_lod is set before the
  // first context is created unless this is true. llvmpipe reads the variable once per
  // process, so the first OSMesa context fixes the mode for the whole process.
  bool fastSampling = false;
  std::string shaderDir;  // empty: embedded shaders; else load shaders from this folder
  // The OSMesa library, opened at run time so a missing library is a clean error.
  std::string osmesaLibrary = "libOSMesa.so.8";
  // Non-null: draw in the caller's current context (e.g. a GLFW window) loaded through
  // this function instead of creating OSMesa contexts. Immediate-mode TBN lines then
  // need that context to be a compatibility profile.
  GlProcLoader currentContextLoader = nullptr;
  GlFrame frame = GlFrame::Full;
};

// Throws InputError (exit 2) when OSMesa is missing, the context cannot be created or a
// shader fails to compile or link (with the GLSL log and file/line). Contexts are created
// on the first render (core 3.3; compatibility 3.3 once immediate-mode lines are asked for).
std::unique_ptr<Renderer> makeGlRenderer(const GlOptions& options = {});

// GL_VERSION and GL_RENDERER of the last created context ("" before one exists).
std::string glVersionString();
std::string glRendererString();
// "precise" or "fast": how llvmpipe samples textures in this process ("" before the first
// OSMesa context exists). Precise means GALLIVM_PERF held no_aos_sampling and no_quad_lod.
std::string glSamplingMode();

}  // namespace twr
