// Options shared by the subcommands that render: scene loading and setting overrides.
#pragma once

#include "glrender/gl_renderer.h"
#include "scene/scene.h"
#include "softrender/cpu_renderer.h"

#include <CLI/CLI.hpp>

#include <optional>
#include <string>
#include <vector>

namespace twr::cli {

struct RenderRequest {
  std::string scenePath;
  std::optional<int> width, height;  // default: the scene's output size
  std::string view;                   // default: the scene's settings.view
  std::string cull, frontFace, lightingSpace, tangentTransform, textureFilter, pipeline, gbufferPosition;  // optional overrides
  std::string interpolation;  // optional override of settings.interpolation
  // settings.ssr overrides: --ssr on|off, --ssr-march, --ssr-max-steps, --ssr-thickness.
  std::string ssr, ssrMarch;
  std::optional<int> ssrMaxSteps;
  std::optional<float> ssrThickness;
  bool verbose = false;
};

// Adds SCENE, --width/--height, --view and the setting overrides to `cmd`.
void addRenderOptions(CLI::App& cmd, RenderRequest& request);
// The overrides `request` holds as command-line arguments ("--pipeline", "deferred", ...), for
// a child process that renders the same request.
std::vector<std::string> overrideArguments(const RenderRequest& request);

// Loads the scene and applies the overrides; throws InputError (exit 2) on bad input.
// "warning: ..." on stderr for each of the scene's warnings (scene.h) and for settings it
// reads but neither renderer draws yet.
void printSceneWarnings(const Scene& scene);
Scene loadRequestedScene(const RenderRequest& request);

// "warning: nothing was drawn: ..." on stderr when `frame` covers no pixel and the scene does
// not set output.expect_empty (compare/empty_frame.h; `clipStats`: the frame is the CPU's, whose
// statistics say what its clipper and culler removed).
void warnIfEmpty(const Scene& scene, const RenderOutput& frame, bool clipStats);
int requestedWidth(const RenderRequest& request, const Scene& scene);
int requestedHeight(const RenderRequest& request, const Scene& scene);

// --cpu-path and --cpu-isa, for the subcommands that run the CPU pipeline.
struct CpuRequest {
  std::string path = "fast";       // teaching|fast
  std::optional<std::string> isa;  // the fast path's target; default auto
};

// Adds --cpu-path and --cpu-isa to `cmd` and returns the --cpu-isa option (for excludes()).
// Both are checked while the command line is parsed, before anything renders: an unknown
// name, or a target this binary or this CPU cannot run, exits 2 with
// cpuIsaUnsupportedReason()'s message.
CLI::Option* addCpuOptions(CLI::App& cmd, CpuRequest& request);

// The renderer options the request names. Throws InputError (exit 2) for --cpu-isa with
// --cpu-path teaching (the teaching path runs no Highway kernels, so a target there would
// be measured as if it mattered) and, again, for a target this CPU cannot run.
CpuOptions requestedCpuOptions(const CpuRequest& request, int threads = 1);

// The fast path's target the options run on ("avx2"), or "" for the teaching path.
std::string resolvedCpuIsaName(const CpuOptions& options);

// --gl-context and --gl-device, for the subcommands that draw with GL.
struct GlRequest {
  std::string context = "osmesa";  // osmesa|egl|auto
  std::optional<int> device;       // an EGL device (info --gl lists them); default: surfaceless
};

// Adds --gl-context and --gl-device to `cmd`.
void addGlOptions(CLI::App& cmd, GlRequest& request);

// The GlOptions fields the request sets (context kind and EGL device); the rest stay at their
// defaults. Throws InputError (exit 2) for --gl-device with --gl-context osmesa: OSMesa has
// no devices.
GlOptions requestedGlOptions(const GlRequest& request);

// The same request as arguments for a child process of this executable ("--gl-context", ...).
std::vector<std::string> glRequestArguments(const GlRequest& request);

}  // namespace twr::cli
