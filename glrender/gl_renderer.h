// The OpenGL 3.3 renderer behind the Renderer interface. Headless through OSMesa
// (llvmpipe) by default or through EGL (Mesa's surfaceless platform or a listed device, see
// glrender/context_egl.h); the GUI can instead draw in its own current GLFW context
// (GlOptions::currentContextLoader, see glrender/context_glfw.h). docs/gl-path.md compares them.
#pragma once

#include "scene/renderer.h"
#include "scene/shadow_trace.h"
#include "scene/ssr_trace.h"

#include <memory>
#include <string>
#include <vector>

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

// Which headless context the renderer makes (when it does not borrow the caller's).
//   OsMesa  libOSMesa.so.8: Mesa's llvmpipe, the default on Debian 12.
//   Egl     libEGL.so.1: GlOptions::eglDevice picks Mesa's surfaceless platform or a device.
//   Auto    OSMesa when its library loads, else EGL's surfaceless platform (Mesa 25.1 and
//           later ship no OSMesa).
enum class GlContextKind { OsMesa, Egl, Auto };

// GlOptions::eglDevice for EGL_MESA_platform_surfaceless: no device named, Mesa picks its
// driver (llvmpipe on a machine without a GPU).
inline constexpr int kEglSurfaceless = -1;

struct GlOptions {
  bool verbose = false;  // print GL_VERSION / GL_RENDERER on stderr
  // llvmpipe's fast texture path (8-bit bilinear weights, one LOD per quad). Off by default
  // for a fair comparison: GALLIVM_PERF=no_aos_sampling,no_quad_lod is set before the
  // first context is created unless this is true. llvmpipe reads the variable once per
  // process, so the first OSMesa context fixes the mode for the whole process.
  bool fastSampling = false;
  std::string shaderDir;  // empty: embedded shaders; else load shaders from this folder
  GlContextKind context = GlContextKind::OsMesa;
  // EGL only: kEglSurfaceless, or N >= 0 for the N-th device eglQueryDevicesEXT lists
  // (EGL_EXT_platform_device; `twinraster info --gl` lists them).
  int eglDevice = kEglSurfaceless;
  // The libraries, opened at run time so a missing one is a clean error.
  std::string osmesaLibrary = "libOSMesa.so.8";
  std::string eglLibrary = "libEGL.so.1";
  // Non-null: draw in the caller's current context (e.g. a GLFW window) loaded through
  // this function instead of creating OSMesa contexts. Immediate-mode TBN lines then
  // need that context to be a compatibility profile.
  GlProcLoader currentContextLoader = nullptr;
  GlFrame frame = GlFrame::Full;
};

// Throws InputError (exit 2) when the context's library (OSMesa, EGL) or the EGL device is
// missing, the context cannot be created or a shader fails to compile or link (with the GLSL
// log and file/line). Contexts are created on the first render (core 3.3; compatibility 3.3
// once immediate-mode lines are asked for).
std::unique_ptr<Renderer> makeGlRenderer(const GlOptions& options = {});

// Pixel (x, yTop) (top-left image coordinates) of the frame renderer.render(scene, settings,
// width, height) draws, as a 1 x 1 RenderOutput, bit for bit (tests/glrender/test_gl_pixel.cpp):
// the same programs, state and draw calls under a one-pixel scissor, so llvmpipe rasterizes
// and shades only that pixel's quad, and one texel of each attachment read back instead of
// four whole buffers. Its stats count that pixel only. For the GUI's pixel probe, which reads
// one pixel in every debug view. Throws InputError when `renderer` is not from makeGlRenderer,
// draws GlFrame::Lean, or the pixel is outside the frame; otherwise as render().
RenderOutput renderGlPixel(Renderer& renderer, const Scene& scene, const RenderSettings& settings, int width,
                           int height, int x, int yTop);

// GL_VERSION, GL_RENDERER and GL_VENDOR of the last created context ("" before one exists).
std::string glVersionString();
std::string glRendererString();
std::string glVendorString();
// Which context that was: "OSMesa 3.3 core context", "EGL surfaceless platform (driver swrast)
// 3.3 core context", "EGL device 1 (/dev/dri/card1) 3.3 core context", "GLFW window", ...
std::string glContextString();
// "precise" or "fast": how llvmpipe samples textures in this process ("" before the first
// headless context exists). Precise means GALLIVM_PERF held no_aos_sampling and no_quad_lod.
// Only llvmpipe reads the variable: another driver samples as it chooses.
std::string glSamplingMode();

// True when GL_RENDERER names Mesa's llvmpipe, the rasteriser the project's CPU-vs-GL
// targets (compare --targets) are measured against.
bool isLlvmpipe(const std::string& glRenderer);

// "osmesa", "egl" or "auto" (what --gl-context takes), and back; parse returns false for
// anything else.
const char* toString(GlContextKind kind);
bool parse(const std::string& text, GlContextKind& kind);

// One headless context `twinraster info --gl` tried: what it is and what GL it gave.
struct GlContextProbe {
  GlContextKind kind = GlContextKind::OsMesa;
  int eglDevice = kEglSurfaceless;  // EGL: the device index, kEglSurfaceless for the platform
  std::string description;          // "OSMesa 3.3 core context", "EGL device 0 ... context"
  std::string deviceDetail;         // EGL devices: DRM device file, "software", extensions
  std::string vendor, renderer, version;  // of its 3.3 core context; "" when `error` is set
  bool compatibility = false;       // a 3.3 compatibility context can be made too
  std::string error;                // why no 3.3 core context ("" when there is one)
};

// Makes a 3.3 core (and a compatibility) context on OSMesa, on EGL's surfaceless platform and
// on every EGL device, and reports each; a missing library becomes one entry with `error`.
// Sets llvmpipe's sampling mode for the process like a render would (options.fastSampling).
std::vector<GlContextProbe> probeGlContexts(const GlOptions& options = {});

// Pixel (x, yTop)'s shadow test on GL, tap by tap (scene/shadow_trace.h), one entry per light
// of the scene with "shadow": the fragment drawn forward and shaded (whatever the view and the
// pipeline; no reflections, no lines), phong.frag's SHADOW_PROBE variant reading the light's
// test one field per one-pixel draw (shadow.glsl), the taps from GL's own map read back.
// Throws InputError where renderGlPixel would.
std::vector<ShadowTapTrace> traceGlShadowTaps(Renderer& renderer, const Scene& scene, const RenderSettings& settings,
                                              int width, int height, int x, int yTop);

// Pixel (x, yTop)'s march on GL, step by step (scene/ssr_trace.h): of its mirror ray, or with
// `ray` k >= 0 of its indirect light's sample k. The frame render() draws, then ssr.frag's
// SSR_PROBE variant marching that pixel's ray once per step (docs/ssr.md, "One pixel's
// march"). Throws InputError when the settings draw no reflections or have no sample k, the
// renderer is not the GL one or draws GlFrame::Lean, or the pixel is outside the frame.
SsrMarchTrace traceGlSsrMarch(Renderer& renderer, const Scene& scene, const RenderSettings& settings, int width,
                              int height, int x, int yTop, int ray = kSsrMirrorRay);

}  // namespace twr
