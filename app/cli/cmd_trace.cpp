// `twinraster trace SCENE X Y`: the story of one pixel through the CPU pipeline.
#include "app/cli/commands.h"
#include "app/cli/common.h"
#include "scene/errors.h"
#include "softrender/pixel_trace.h"

#include <iostream>
#include <memory>

namespace twr::cli {
namespace {

struct TraceArgs {
  RenderRequest request;
  int x = 0;
  int y = 0;
  bool json = false;
};

void runTrace(const TraceArgs& args) {
  const Scene scene = loadRequestedScene(args.request);
  const int width = requestedWidth(args.request, scene);
  const int height = requestedHeight(args.request, scene);
  if (args.x < 0 || args.x >= width || args.y < 0 || args.y >= height) {
    throw InputError("trace: pixel (" + std::to_string(args.x) + ", " + std::to_string(args.y) + ") is outside the " +
                     std::to_string(width) + "x" + std::to_string(height) + " image; expected 0 <= X < " +
                     std::to_string(width) + " and 0 <= Y < " + std::to_string(height));
  }
  const PixelTrace trace = tracePixel(scene, scene.settings, width, height, args.x, args.y);
  if (args.json) {
    std::cout << pixelTraceToJson(trace).dump(2) << "\n";
  } else {
    std::cout << formatPixelTrace(trace);
  }
}

const bool registered = registerCommand(40, [](CLI::App& app) {
  auto args = std::make_shared<TraceArgs>();
  CLI::App* cmd = app.add_subcommand(
      "trace",
      "Trace one pixel through the CPU pipeline: the triangles that reach it, the clip planes, snapped "
      "positions and edge functions, barycentrics, interpolated varyings, every shading term, the depth test");
  addRenderOptions(*cmd, args->request);
  cmd->add_option("x", args->x, "Pixel column, 0 at the left edge of the image")->required();
  cmd->add_option("y", args->y, "Pixel row, 0 at the TOP edge of the image (as in the PNG files, not GL's bottom-left)")
      ->required();
  cmd->add_flag("--json", args->json, "Print the trace as JSON instead of text");
  cmd->callback([args] { runTrace(*args); });
});

}  // namespace
}  // namespace twr::cli
