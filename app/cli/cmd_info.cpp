// `twinraster info SCENE [--json]`: what a scene file holds, after loading it exactly as the
// renderers will (meshes built, textures and OBJ files read), so counts are the real ones.
// It also names the CPU fast path's target on this machine (what --cpu-isa auto runs) and
// every target this binary and this CPU can run; with --gl, every headless GL context this
// machine offers (OSMesa, EGL's surfaceless platform, each EGL device) and what GL it gives.
#include "app/cli/commands.h"
#include "scene/json_text.h"
#include "scene/scene_description.h"
#include "app/cli/common.h"
#include "glrender/gl_renderer.h"
#include "scene/errors.h"
#include "scene/scene.h"
#include "scene/scene_file.h"
#include "softrender/cpu_renderer.h"

#include <nlohmann/json.hpp>

#include <charconv>
#include <cstdlib>
#include <iostream>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

namespace twr::cli {

namespace {

using Json = nlohmann::ordered_json;

// The fast path's target under --cpu-isa auto, and every --cpu-isa this machine runs.
void addCpuJson(Json& j) {
  j["cpu_isa"] = std::string(toString(resolveCpuIsa(CpuIsa::Auto)));
  Json supported = Json::array();
  for (const CpuIsa isa : supportedCpuIsas()) supported.push_back(std::string(toString(isa)));
  j["cpu_isas_supported"] = std::move(supported);
}

void printCpu(std::ostream& out) {
  std::string supported;
  for (const CpuIsa isa : supportedCpuIsas()) supported += (supported.empty() ? "" : ", ") + std::string(toString(isa));
  out << "\ncpu: the fast path runs on " << toString(resolveCpuIsa(CpuIsa::Auto))
      << " here (--cpu-isa auto); targets this machine runs: " << supported << "\n";
}

// --gl-context and --gl-device spelled for one probed context.
std::string contextOptions(const GlContextProbe& probe) {
  if (probe.kind == GlContextKind::OsMesa) return "--gl-context osmesa";
  if (probe.eglDevice == kEglSurfaceless) return "--gl-context egl";
  return "--gl-context egl --gl-device " + std::to_string(probe.eglDevice);
}

Json glContextsJson(const std::vector<GlContextProbe>& probes) {
  Json list = Json::array();
  for (const GlContextProbe& p : probes) {
    const bool ok = p.error.empty();
    list.push_back(Json{{"context", toString(p.kind)},
                        {"device", p.eglDevice == kEglSurfaceless ? Json(nullptr) : Json(p.eglDevice)},
                        {"options", contextOptions(p)},
                        {"description", ok ? Json(p.description) : Json(nullptr)},
                        {"device_detail", p.deviceDetail.empty() ? Json(nullptr) : Json(p.deviceDetail)},
                        {"gl_vendor", ok ? Json(p.vendor) : Json(nullptr)},
                        {"gl_renderer", ok ? Json(p.renderer) : Json(nullptr)},
                        {"gl_version", ok ? Json(p.version) : Json(nullptr)},
                        {"llvmpipe", ok && isLlvmpipe(p.renderer)},
                        {"compatibility_profile", p.compatibility},
                        {"error", ok ? Json(nullptr) : Json(p.error)}});
  }
  return list;
}

void printGlContexts(std::ostream& out, const std::vector<GlContextProbe>& probes) {
  out << "\ngl: headless contexts (a 3.3 core context made on each):\n";
  for (const GlContextProbe& p : probes) {
    out << "  " << contextOptions(p) << ": ";
    if (!p.error.empty()) {
      out << "unavailable: " << p.error << "\n";
      continue;
    }
    out << p.description << "\n    GL_VENDOR " << p.vendor << ", GL_RENDERER " << p.renderer << ", GL_VERSION "
        << p.version << "\n    compatibility profile " << (p.compatibility ? "yes" : "no")
        << (isLlvmpipe(p.renderer) ? "; llvmpipe: compare --targets applies"
                                   : "; not llvmpipe: compare reports metrics without --targets verdicts")
        << "\n";
    if (!p.deviceDetail.empty()) out << "    device: " << p.deviceDetail << "\n";
  }
}

struct InfoRequest {
  std::string scenePath;
  bool json = false;
  bool gl = false;
};

const bool infoRegistered = registerCommand(10, [](CLI::App& app) {
  auto request = std::make_shared<InfoRequest>();
  CLI::App* cmd = app.add_subcommand(
      "info",
      "Load a scene file (building every mesh, reading every texture and OBJ) and print its node tree with "
      "mesh type, triangle and vertex counts and material per node, the totals, the materials with their "
      "maps, the lights, the camera, the output size and the render settings; then the CPU fast path's "
      "target on this machine and every target it runs; with --gl (SCENE then optional), the headless GL "
      "contexts. Exit 2 on a bad scene file.");
  cmd->add_option("scene", request->scenePath, "Scene file (JSON, see docs/scene-format.md); optional with --gl");
  cmd->add_flag("--json", request->json,
                "Print one JSON object instead (keys: scene, nodes, triangles, vertices, materials, lights, "
                "ambient, camera, settings, output, cpu_isa: the CPU fast path's target under --cpu-isa auto, "
                "cpu_isas_supported: every --cpu-isa this machine runs, best first; with --gl, gl_contexts: "
                "[{context, device, options, description, device_detail, gl_vendor, gl_renderer, gl_version, "
                "llvmpipe, compatibility_profile, error}])");
  cmd->add_flag("--gl", request->gl,
                "Also list the headless GL contexts: OSMesa, EGL's surfaceless platform and every EGL device, each "
                "with the --gl-context / --gl-device that picks it and its GL_VENDOR, GL_RENDERER and GL_VERSION "
                "(or why it is unavailable)");
  cmd->callback([request] {
    if (request->scenePath.empty() && !request->gl) {
      throw InputError("info: scene is required (a SCENE file, or --gl alone)");
    }
    std::optional<Scene> scene;
    if (!request->scenePath.empty()) {
      scene = loadSceneFile(request->scenePath);
      printSceneWarnings(*scene);
    }
    std::vector<GlContextProbe> probes;
    if (request->gl) probes = probeGlContexts();
    if (request->json) {
      Json j = scene ? sceneDescriptionJson(*scene) : Json::object();
      addCpuJson(j);
      if (request->gl) j["gl_contexts"] = glContextsJson(probes);
      std::cout << jsonText(j, 2) << "\n";
    } else {
      if (scene) printSceneDescription(std::cout, *scene);
      printCpu(std::cout);
      if (request->gl) printGlContexts(std::cout, probes);
    }
  });
});

}  // namespace

}  // namespace twr::cli
