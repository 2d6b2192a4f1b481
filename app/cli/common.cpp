#include "app/cli/common.h"

#include "compare/empty_frame.h"
#include "scene/errors.h"
#include "scene/image.h"
#include "scene/projection_checks.h"
#include "scene/scene_file.h"

#include <array>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <limits>
#include <sstream>
#include <utility>

namespace twr::cli {

namespace {

template <typename E>
void applyOverride(const std::string& text, const char* option, E& target, const std::string& allowed) {
  if (text.empty()) return;
  if (!parse(text, target)) {
    throw InputError(std::string(option) + ": expected one of " + allowed + ", got '" + text + "'");
  }
}

// An override given with an empty value ("--view ''") is a mistake, not "the scene's own":
// refused like any other value that names no setting.
const CLI::Validator kNonEmpty(
    [](std::string& value) { return value.empty() ? std::string("an empty value names no setting") : std::string(); },
    "NONEMPTY");

// A length in world units: finite and > 0, said in those words (CLI::PositiveNumber prints
// the whole double range).
const CLI::Validator kPositiveFinite(
    [](std::string& value) {
      float number = 0.0f;
      if (!CLI::detail::lexical_cast(value, number) || !std::isfinite(number) || !(number > 0.0f)) {
        return "expected a finite number > 0 (world units), got '" + value + "'";
      }
      return std::string();
    },
    "> 0");

}  // namespace

void addRenderOptions(CLI::App& cmd, RenderRequest& request) {
  cmd.add_option("scene", request.scenePath, "Scene file (JSON, see docs/scene-format.md)")->required();
  cmd.add_option("--width", request.width, "Image width in pixels (default: the scene's output.width)")
      ->check(CLI::Range(1, kMaxImageSide));
  cmd.add_option("--height", request.height, "Image height in pixels (default: the scene's output.height)")
      ->check(CLI::Range(1, kMaxImageSide));
  cmd.add_option("--view", request.view, "Debug colour view: " + allViewNames() + " (default: the scene's)")
      ->check(kNonEmpty);
  cmd.add_option("--cull", request.cull, "Override settings.cull: none|back|front")
      ->check(kNonEmpty);
  cmd.add_option("--front-face", request.frontFace, "Override settings.front_face: ccw|cw")
      ->check(kNonEmpty);
  cmd.add_option("--lighting-space", request.lightingSpace, "Override settings.lighting_space: world|tangent")
      ->check(kNonEmpty);
  cmd.add_option("--pipeline", request.pipeline,
                 "Override settings.pipeline: forward|deferred (a G-buffer pass, then a lighting pass)")
      ->check(kNonEmpty);
  cmd.add_option("--gbuffer-position", request.gbufferPosition,
                 "Override settings.gbuffer_position: stored (a G-buffer target, the position forward "
                 "lights) or depth (rebuilt from the window depth)")
      ->check(kNonEmpty);
  cmd.add_option("--tangent-transform", request.tangentTransform,
                 "Override settings.tangent_transform: model|inverse_transpose")
      ->check(kNonEmpty);
  cmd.add_option("--interpolation", request.interpolation,
                 "Override settings.interpolation: perspective (perspective-correct, GLSL's default) or affine "
                 "(linear on the screen, GLSL's noperspective: textures swim on a receding floor)")
      ->check(kNonEmpty);
  cmd.add_option("--filter", request.textureFilter,
                 "Override settings.texture_filter: nearest|bilinear|trilinear|nearest_mipmap_nearest|"
                 "linear_mipmap_nearest|nearest_mipmap_linear")
      ->check(kNonEmpty);
  cmd.add_option("--ssr", request.ssr, "Override settings.ssr.enabled: on|off (screen-space reflections, docs/ssr.md)")
      ->check(CLI::IsMember({"on", "off"}));
  cmd.add_option("--ssr-march", request.ssrMarch,
                 "Override settings.ssr.march: linear_world|adaptive_world (world-space steps)|dda_screen (one pixel "
                 "a step)|hiz (dda_screen's answer over a min-depth mip chain)")
      ->check(kNonEmpty);
  cmd.add_option("--ssr-max-steps", request.ssrMaxSteps, "Override settings.ssr.max_steps")
      ->check(CLI::Range(1, kMaxSsrSteps));
  cmd.add_option("--ssr-thickness", request.ssrThickness, "Override settings.ssr.thickness (world units, > 0)")
      ->check(kPositiveFinite);
  cmd.add_flag("--verbose,-v", request.verbose, "Print GL_VERSION, GL_RENDERER and timings on stderr");
}

std::vector<std::string> overrideArguments(const RenderRequest& r) {
  const std::array<std::pair<const char*, const std::string*>, 11> named = {{
      {"--view", &r.view},
      {"--pipeline", &r.pipeline},
      {"--gbuffer-position", &r.gbufferPosition},
      {"--cull", &r.cull},
      {"--front-face", &r.frontFace},
      {"--lighting-space", &r.lightingSpace},
      {"--tangent-transform", &r.tangentTransform},
      {"--interpolation", &r.interpolation},
      {"--filter", &r.textureFilter},
      {"--ssr", &r.ssr},
      {"--ssr-march", &r.ssrMarch},
  }};
  std::vector<std::string> argv;
  for (const auto& [option, value] : named) {
    if (value->empty()) continue;
    argv.push_back(option);
    argv.push_back(*value);
  }
  if (r.ssrMaxSteps) {
    argv.push_back("--ssr-max-steps");
    argv.push_back(std::to_string(*r.ssrMaxSteps));
  }
  if (r.ssrThickness) {
    std::ostringstream text;
    text << std::setprecision(std::numeric_limits<float>::max_digits10) << *r.ssrThickness;
    argv.push_back("--ssr-thickness");
    argv.push_back(text.str());
  }
  return argv;
}

void printSceneWarnings(const Scene& scene) {
  for (const std::string& w : scene.warnings) std::cerr << "warning: " << w << "\n";
  if (scene.settings.anisotropy > 1.0f) {
    std::cerr << "warning: settings.anisotropy " << scene.settings.anisotropy
              << ": llvmpipe's elliptical filter ignores the ratio, so every value above 1 draws the same "
                 "picture on both renderers (docs/textures.md, \"Anisotropy\")\n";
  }
}

void warnIfEmpty(const Scene& scene, const RenderOutput& frame, bool clipStats) {
  if (scene.output.expectEmpty) return;
  const std::string reason = emptyFrameReason(scene, frame, clipStats);
  if (!reason.empty()) std::cerr << "warning: " << reason << " (output.expect_empty true says it is meant)\n";
}

Scene loadRequestedScene(const RenderRequest& request) {
  Scene scene = loadSceneFile(request.scenePath);
  RenderSettings& s = scene.settings;
  applyOverride(request.view, "--view", s.view, allViewNames());
  applyOverride(request.cull, "--cull", s.cull, "none|back|front");
  applyOverride(request.frontFace, "--front-face", s.frontFace, "ccw|cw");
  applyOverride(request.lightingSpace, "--lighting-space", s.lightingSpace, "world|tangent");
  applyOverride(request.pipeline, "--pipeline", s.pipeline, "forward|deferred");
  applyOverride(request.gbufferPosition, "--gbuffer-position", s.gbufferPosition, "stored|depth");
  applyOverride(request.tangentTransform, "--tangent-transform", s.tangentTransform, "model|inverse_transpose");
  applyOverride(request.interpolation, "--interpolation", s.interpolation, "perspective|affine");
  applyOverride(request.textureFilter, "--filter", s.textureFilter,
                "nearest|bilinear|trilinear|nearest_mipmap_nearest|linear_mipmap_nearest|nearest_mipmap_linear");
  if (!request.ssr.empty()) s.ssr.enabled = request.ssr == "on";
  applyOverride(request.ssrMarch, "--ssr-march", s.ssr.march, "linear_world|adaptive_world|dda_screen|hiz");
  if (request.ssrMaxSteps) s.ssr.maxSteps = *request.ssrMaxSteps;
  if (request.ssrThickness) s.ssr.thickness = *request.ssrThickness;
  printSceneWarnings(scene);
  const int width = request.width.value_or(scene.output.width), height = request.height.value_or(scene.output.height);
  if (const std::string problem = renderSizeProblem(width, height); !problem.empty()) {
    throw InputError("--width/--height: " + problem);
  }
  if (const std::string problem = projectionProblem(scene, width, height); !problem.empty()) {
    throw InputError(request.scenePath + ": " + problem);
  }
  for (const std::string& w : projectionWarnings(scene, width, height)) std::cerr << "warning: " << w << "\n";
  return scene;
}

CLI::Option* addCpuOptions(CLI::App& cmd, CpuRequest& request) {
  cmd.add_option("--cpu-path", request.path,
                 "CPU traversal: fast (binned, SIMD kernels) or teaching (one stage after the other, one pixel at "
                 "a time, as docs/pipeline.md draws it); both draw the same image bit for bit")
      ->check(CLI::IsMember({"fast", "teaching"}))
      ->capture_default_str();
  std::string supported;
  for (const CpuIsa isa : supportedCpuIsas()) supported += (supported.empty() ? "" : ", ") + std::string(toString(isa));
  const CLI::Validator runnable(
      [](std::string& text) -> std::string {
        CpuIsa isa = CpuIsa::Auto;
        if (!parse(text, isa)) return "expected one of " + allCpuIsaNames() + ", got '" + text + "'";
        return cpuIsaSupported(isa) ? std::string() : cpuIsaUnsupportedReason(isa);
      },
      "", "CPU target");
  return cmd
      .add_option("--cpu-isa", request.isa,
                  "Fast path only (refused with --cpu-path teaching): the Highway target its kernels run on, " +
                      allCpuIsaNames() + " (default auto: the best this CPU runs; here " + supported +
                      "). A target this CPU cannot run exits 2. Every target draws the same image.")
      ->check(runnable);
}

CpuOptions requestedCpuOptions(const CpuRequest& request, int threads) {
  CpuOptions options;
  options.threads = threads;
  options.path = request.path == "teaching" ? CpuPath::Teaching : CpuPath::Fast;
  if (request.isa) {
    if (!parse(*request.isa, options.isa)) {
      throw InputError("--cpu-isa: expected one of " + allCpuIsaNames() + ", got '" + *request.isa + "'");
    }
    if (!cpuIsaSupported(options.isa)) throw InputError("--cpu-isa: " + cpuIsaUnsupportedReason(options.isa));
    if (options.path == CpuPath::Teaching && options.isa != CpuIsa::Auto) {
      throw InputError("--cpu-isa " + *request.isa +
                       ": the teaching path runs no SIMD kernels; --cpu-isa applies to --cpu-path fast");
    }
  }
  return options;
}

std::string resolvedCpuIsaName(const CpuOptions& options) {
  if (options.path == CpuPath::Teaching) return {};
  return std::string(toString(resolveCpuIsa(options.isa)));
}

void addGlOptions(CLI::App& cmd, GlRequest& request) {
  cmd.add_option("--gl-context", request.context,
                 "Headless GL context: osmesa (libOSMesa, Mesa's llvmpipe), egl (libEGL: Mesa's surfaceless "
                 "platform, or the device --gl-device names) or auto (OSMesa where its library loads, else EGL); "
                 "docs/gl-path.md")
      ->check(CLI::IsMember({"osmesa", "egl", "auto"}))
      ->capture_default_str();
  cmd.add_option("--gl-device", request.device,
                 "With --gl-context egl: draw on EGL device N (EGL_EXT_platform_device; `twinraster info --gl` lists "
                 "them with their GL_RENDERER) instead of Mesa's surfaceless platform")
      ->check(CLI::NonNegativeNumber)
      ->type_name("N");
}

GlOptions requestedGlOptions(const GlRequest& request) {
  GlOptions options;
  if (!parse(request.context, options.context)) {
    throw InputError("--gl-context: expected one of osmesa, egl, auto, got '" + request.context + "'");
  }
  if (request.device) {
    if (options.context == GlContextKind::OsMesa) {
      throw InputError("--gl-device " + std::to_string(*request.device) +
                       ": devices are EGL's; add --gl-context egl (OSMesa has no devices)");
    }
    options.eglDevice = *request.device;
  }
  return options;
}

std::vector<std::string> glRequestArguments(const GlRequest& request) {
  std::vector<std::string> arguments = {"--gl-context", request.context};
  if (request.device) {
    arguments.push_back("--gl-device");
    arguments.push_back(std::to_string(*request.device));
  }
  return arguments;
}

int requestedWidth(const RenderRequest& request, const Scene& scene) {
  return request.width.value_or(scene.output.width);
}
int requestedHeight(const RenderRequest& request, const Scene& scene) {
  return request.height.value_or(scene.output.height);
}

}  // namespace twr::cli
