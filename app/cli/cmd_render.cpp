// `twinraster render SCENE --backend cpu|gl --out FILE.png`: one image from one backend; the
// CPU one on the path and target --cpu-path and --cpu-isa name (default fast, auto).
#include "app/cli/commands.h"
#include "app/cli/common.h"
#include "glrender/gl_renderer.h"
#include "scene/errors.h"
#include "scene/image.h"
#include "softrender/cpu_renderer.h"

#include <cstring>
#include <iostream>
#include <memory>

namespace twr::cli {
namespace {

struct RenderArgs {
  RenderRequest request;
  CpuRequest cpu;
  GlRequest gl;
  std::string backend = "cpu";
  std::string outPath;
  bool glFastSampling = false;
};

Image imageFromOutput(const RenderOutput& output) {
  Image image = makeImage(output.width, output.height);
  std::memcpy(image.rgba.data(), output.rgba.data(), image.rgba.size());
  return image;
}

void runRender(const RenderArgs& args) {
  const CpuOptions cpuOptions = requestedCpuOptions(args.cpu);
  GlOptions glOptions = requestedGlOptions(args.gl);
  Scene scene = loadRequestedScene(args.request);
  const int width = requestedWidth(args.request, scene);
  const int height = requestedHeight(args.request, scene);
  std::unique_ptr<Renderer> renderer;
  std::string rendererName = "gl";
  if (args.backend == "cpu") {
    renderer = makeCpuRenderer(cpuOptions);
    rendererName = "cpu " + cpuPathName(cpuOptions);
  } else {
    glOptions.verbose = args.request.verbose;
    glOptions.fastSampling = args.glFastSampling;
    renderer = makeGlRenderer(glOptions);
  }
  const RenderOutput output = renderer->render(scene, scene.settings, width, height);
  savePng(args.outPath, imageFromOutput(output));
  warnIfEmpty(scene, output, args.backend == "cpu");
  if (args.request.verbose) {
    const RenderStats& s = output.stats;
    std::cerr << rendererName << ": " << width << "x" << height << ", " << s.milliseconds << " ms, triangles in "
              << s.trianglesIn;
    // GL does not report its clipper's and culler's counts; only the CPU pipeline knows them.
    if (args.backend == "cpu") {
      std::cerr << ", clipped " << s.trianglesClipped << ", culled " << s.trianglesCulled << ", drawn "
                << s.trianglesProduced;
    }
    std::cerr << ", pixels shaded " << s.pixelsShaded << "\n";
  }
  std::cout << "wrote " << args.outPath << " (" << width << "x" << height << ", " << rendererName << ")\n";
}

const bool renderRegistered = registerCommand(20, [](CLI::App& app) {
  auto args = std::make_shared<RenderArgs>();
  CLI::App* cmd = app.add_subcommand("render", "Render a scene with one backend into a PNG (top row first)");
  addRenderOptions(*cmd, args->request);
  cmd->add_option("--backend,-b", args->backend,
                  "cpu (the software pipeline) or gl (OpenGL 3.3 headless, OSMesa or EGL: --gl-context)")
      ->check(CLI::IsMember({"cpu", "gl"}))
      ->capture_default_str();
  cmd->add_option("--out,-o", args->outPath, "Output PNG file")->required();
  addCpuOptions(*cmd, args->cpu);
  addGlOptions(*cmd, args->gl);
  cmd->add_flag("--gl-fast-sampling", args->glFastSampling,
                "Let llvmpipe use its fast 8-bit bilinear path (default: the precise mode, see docs/compare.md)");
  cmd->callback([args] { runRender(*args); });
});

}  // namespace
}  // namespace twr::cli
