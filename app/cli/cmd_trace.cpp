// `twinraster trace SCENE X Y`: the story of one pixel through the CPU pipeline (and, with
// screen-space reflections, its mirror ray's or an indirect sample's march step by step on both
// renderers; with shadowed lights, each one's test tap by tap on both).
// The replay of the stages is the teaching code (softrender/pixel_trace.cpp); the final
// pixel it reports comes from a full render on --cpu-path / --cpu-isa (default fast, auto).
// tracePixel() takes no renderer options and renders on the default fast path itself, so
// for any other choice the final pixel is rendered again here on the requested path and
// replaces it (one extra frame; every path draws the same bits, the tests check it).
#include "app/cli/commands.h"
#include "scene/json_text.h"
#include "app/cli/common.h"
#include "scene/errors.h"
#include "softrender/cpu_renderer.h"
#include "glrender/gl_renderer.h"
#include "scene/ssr_trace_report.h"
#include "softrender/pixel_trace.h"
#include "softrender/stage_pictures.h"
#include "softrender/ssr.h"

#include <algorithm>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>

namespace twr::cli {
namespace {

struct TraceArgs {
  RenderRequest request;
  CpuRequest cpu;
  GlRequest gl;
  int x = 0;
  int y = 0;
  bool json = false;
  std::string ssrRay = "mirror";  // --ssr-ray: mirror, or an indirect sample's index
  std::string stagesDir;          // --stages: the stage pictures' folder
};

// --ssr-ray's value: kSsrMirrorRay for "mirror", else a sample index (checked against the
// scene's indirect_samples by checkSsrRay).
int ssrRayOf(const std::string& text) {
  if (text == "mirror") return kSsrMirrorRay;
  // Digits only (std::stoi would take " 3", "+3" and "-0"), at most 4 (samples are at most 64).
  const bool digits = !text.empty() && text.size() <= 4 &&
                      std::all_of(text.begin(), text.end(), [](char c) { return c >= '0' && c <= '9'; });
  if (!digits) {
    throw InputError("--ssr-ray: expected 'mirror' or an indirect sample's index (0, 1, ...), got '" + text + "'");
  }
  return std::stoi(text);
}

// The final pixel of `trace` as a render with `options` draws it.
void takeFinalPixelFrom(const CpuOptions& options, const Scene& scene, int width, int height, PixelTrace& trace) {
  const RenderOutput output = makeCpuRenderer(options)->render(scene, scene.settings, width, height);
  const std::size_t i =
      static_cast<std::size_t>(trace.yTop) * static_cast<std::size_t>(width) + static_cast<std::size_t>(trace.x);
  for (std::size_t c = 0; c < 4; ++c) trace.rgba[c] = output.rgba[i * 4 + c];
  trace.depth = output.depth[i];
  trace.triangleId = output.triangleId[i];
  trace.debugLine = output.lineMask[i] != 0;
}

void runTrace(const TraceArgs& args) {
  const CpuOptions cpuOptions = requestedCpuOptions(args.cpu);
  const Scene scene = loadRequestedScene(args.request);
  const int width = requestedWidth(args.request, scene);
  const int height = requestedHeight(args.request, scene);
  if (args.x < 0 || args.x >= width || args.y < 0 || args.y >= height) {
    throw InputError("trace: pixel (" + std::to_string(args.x) + ", " + std::to_string(args.y) + ") is outside the " +
                     std::to_string(width) + "x" + std::to_string(height) + " image; expected 0 <= X < " +
                     std::to_string(width) + " and 0 <= Y < " + std::to_string(height));
  }
  const int ray = ssrRayOf(args.ssrRay);
  if (!drawsSsr(scene.settings) && ray != kSsrMirrorRay) {
    throw InputError("--ssr-ray " + args.ssrRay + ": the scene draws no screen-space reflections (settings.ssr)");
  }
  if (drawsSsr(scene.settings)) checkSsrRay(scene.settings, ray);
  PixelTrace trace = tracePixel(scene, scene.settings, width, height, args.x, args.y);
  const CpuOptions tracePixelOwn;  // what tracePixel() renders with
  if (cpuOptions.path != tracePixelOwn.path || cpuOptions.isa != tracePixelOwn.isa) {
    takeFinalPixelFrom(cpuOptions, scene, width, height, trace);
  }
  if (!args.stagesDir.empty()) {
    const RenderOutput frame = makeCpuRenderer(cpuOptions)->render(scene, scene.settings, width, height);
    const std::vector<StagePicture> pictures = writeStagePictures(args.stagesDir, trace, frame);
    std::cerr << "twinraster: wrote " << args.stagesDir << "/index.html and " << pictures.size()
              << " stage pictures (" << pictures.front().file << " ... " << pictures.back().file << ")\n";
  }
  // A frame with reflections: the pixel's ray's march step by step on both renderers.
  std::optional<SsrMarchTrace> cpuMarch, glMarch;
  std::string glMarchError;
  if (drawsSsr(scene.settings)) {
    const RenderOutput frame = makeCpuRenderer(cpuOptions)->render(scene, scene.settings, width, height);
    cpuMarch = traceSsrMarch(scene, scene.settings, frame, args.x, args.y, ray);
    try {
      std::unique_ptr<Renderer> gl = makeGlRenderer(requestedGlOptions(args.gl));
      glMarch = traceGlSsrMarch(*gl, scene, scene.settings, width, height, args.x, args.y, ray);
    } catch (const InputError& e) {
      glMarchError = e.what();  // no usable GL here: the CPU's march alone, and why
    }
  }
  // A shadowed light: the pixel's test tap by tap on both renderers.
  const std::vector<ShadowTapTrace> cpuTaps = shadowTapTracesOf(trace, scene);
  std::vector<ShadowTapTrace> glTaps;
  std::string glTapsError;
  if (!cpuTaps.empty()) {
    try {
      std::unique_ptr<Renderer> gl = makeGlRenderer(requestedGlOptions(args.gl));
      glTaps = traceGlShadowTaps(*gl, scene, scene.settings, width, height, args.x, args.y);
    } catch (const InputError& e) {
      glTapsError = e.what();  // no usable GL here: the CPU's taps alone, and why
    }
  }
  const auto glTapsOf = [&](const ShadowTapTrace& cpu) -> const ShadowTapTrace* {
    for (const ShadowTapTrace& g : glTaps) {
      if (g.light == cpu.light) return &g;
    }
    return nullptr;
  };
  const std::string path = cpuPathName(cpuOptions);
  if (args.json) {
    nlohmann::json json = pixelTraceToJson(trace);
    json["cpu_path"] = path;  // the render the final pixel comes from
    if (cpuMarch) {
      const std::optional<std::size_t> parted = glMarch ? firstDifferingStep(*cpuMarch, *glMarch) : std::nullopt;
      json["ssr_march"] = {{"ray", ray == kSsrMirrorRay ? nlohmann::json("mirror") : nlohmann::json(ray)},
                           {"cpu", ssrMarchTraceToJson(*cpuMarch)},
                           {"gl", glMarch ? ssrMarchTraceToJson(*glMarch) : nlohmann::json(nullptr)},
                           {"gl_error", glMarchError.empty() ? nlohmann::json(nullptr) : nlohmann::json(glMarchError)},
                           {"first_differing_step", parted ? nlohmann::json(*parted + 1) : nlohmann::json(nullptr)}};
    } else {
      json["ssr_march"] = nullptr;
    }
    if (cpuTaps.empty()) {
      json["shadow_taps"] = nullptr;
    } else {
      json["shadow_taps"] = nlohmann::json::array();
      for (const ShadowTapTrace& cpu : cpuTaps) {
        const ShadowTapTrace* gl = glTapsOf(cpu);
        const std::string before = gl ? testsPartBeforeTaps("cpu", cpu, "gl", *gl) : "";
        const std::optional<std::size_t> parted = gl && before.empty() ? firstDifferingTap(cpu, *gl) : std::nullopt;
        json["shadow_taps"].push_back(
            {{"light", cpu.light},
             {"cpu", shadowTapTraceToJson(cpu)},
             {"gl", gl ? shadowTapTraceToJson(*gl) : nlohmann::json(nullptr)},
             {"gl_error", glTapsError.empty() ? nlohmann::json(nullptr) : nlohmann::json(glTapsError)},
             {"parted_before_taps", before.empty() ? nlohmann::json(nullptr) : nlohmann::json(before)},
             {"first_differing_tap", parted ? nlohmann::json(*parted + 1) : nlohmann::json(nullptr)}});
      }
    }
    std::cout << jsonText(json, 2) << "\n";
  } else {
    std::cout << formatPixelTrace(trace) << "final pixel rendered by the cpu path: " << path << "\n";
    if (cpuMarch) {
      const SsrSettings& ssr = scene.settings.ssr;
      std::cout << "\nSSR march of this pixel's " << ssrRayName(ray) << " (" << toString(ssr.march) << ", max_steps "
                << ssr.maxSteps
                << ", thickness " << ssr.thickness << "):\n"
                << formatSsrMarchTraces("cpu", *cpuMarch, "gl", glMarch ? &*glMarch : nullptr);
      if (!glMarchError.empty()) std::cout << "  gl: not traced: " << glMarchError << "\n";
    }
    for (const ShadowTapTrace& cpu : cpuTaps) {
      std::cout << "\nshadow test of light " << cpu.light << ", tap by tap (PCF " << cpu.pcf << "):\n"
                << formatShadowTapTraces("cpu", cpu, "gl", glTapsOf(cpu));
      if (!glTapsError.empty()) std::cout << "  gl: not traced: " << glTapsError << "\n";
    }
  }
}

const bool traceRegistered = registerCommand(40, [](CLI::App& app) {
  auto args = std::make_shared<TraceArgs>();
  CLI::App* cmd = app.add_subcommand(
      "trace",
      "Trace one pixel through the CPU pipeline: the triangles that reach it, the clip planes, snapped "
      "positions and edge functions, barycentrics, interpolated varyings, every shading term, the depth test. "
      "The final pixel comes from a full render on --cpu-path and --cpu-isa. With screen-space reflections "
      "(settings.ssr), also the pixel's mirror-ray march (or, with --ssr-ray K, its indirect sample K's) step by "
      "step on both renderers (GL's through ssr.frag's probe), and the first step where they part. With a shadowed "
      "light, its test tap by tap on both renderers (GL's through phong.frag's probe): each PCF tap's texel, the "
      "map's depth there, the fragment's compared depth, the outcome, and the first tap where they part.");
  addRenderOptions(*cmd, args->request);
  cmd->add_option("x", args->x, "Pixel column, 0 at the left edge of the image")->required();
  cmd->add_option("y", args->y, "Pixel row, 0 at the TOP edge of the image (as in the PNG files, not GL's bottom-left)")
      ->required();
  cmd->add_flag("--json", args->json, "Print the trace as JSON instead of text");
  cmd->add_option("--ssr-ray", args->ssrRay,
                  "With screen-space reflections: the ray whose march is traced, mirror (the default) or K, the "
                  "pixel's indirect light sample K (0 .. settings.ssr.indirect_samples - 1)");
  cmd->add_option("--stages", args->stagesDir,
                  "Also draw the triangle that wrote the pixel at each stage into this folder (created), one SVG "
                  "per stage: 0_vertex.svg (its corners' clip positions), 1_clip.svg (the clipped polygon and its "
                  "fan at x/w, y/w, each pass of the clipper), 1_divide.svg (the polygon in window pixels), "
                  "2_setup.svg (the snapped corners, the box, the edges' fill rule), 2_raster.svg (the pixels it "
                  "won), 3_interpolate.svg (screen against perspective weights), 4_shade.svg (Phong's terms stacked "
                  "per channel), and index.html with the trace's numbers");
  addCpuOptions(*cmd, args->cpu);
  addGlOptions(*cmd, args->gl);
  cmd->callback([args] { runTrace(*args); });
});

}  // namespace
}  // namespace twr::cli
