// Target "scene_file": parseScene on the raw bytes, then a small CPU render of what it accepts.
#include "fuzz/support.h"
#include "fuzz/targets.h"

#include "scene/scene_file.h"
#include "softrender/cpu_renderer.h"
#include "softrender/framebuffer.h"

#include <algorithm>

namespace twr::fuzz {

namespace {

// The name parseScene reports for the input.
constexpr const char* kInputName = "fuzz.json";
// Render size for accepted scenes (pixels): enough for a few triangles to cover pixels,
// small enough to keep thousands of executions per second.
constexpr int kRenderWidth = 12;
constexpr int kRenderHeight = 9;
// Accepted scenes with more triangles than this (inclusive bound on what is rendered) are
// only parsed: a 16M-triangle sphere is legal but would turn one execution into seconds.
constexpr std::size_t kMaxRenderedTriangles = 200'000;
// Largest shadow map drawn, texels per side.
constexpr int kMaxShadowMapSizeDrawn = 32;
// Largest captured-environment face drawn, texels per side.
constexpr int kMaxCaptureSize = 8;

}  // namespace

void fuzzSceneFile(const Workspace& workspace, const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  Scene scene;
  try {
    scene = parseScene(text, kInputName, workspace.dir().string());
  } catch (const InputError& error) {
    requireNamesInput(error, kInputName);
    return;
  }
  for (const Mesh& mesh : scene.meshes) {
    for (std::uint32_t index : mesh.indices) require(index < mesh.vertices.size(), "mesh index out of range");
    for (const Vertex& v : mesh.vertices) {
      require(isFinite(v.posModel) && isFinite(v.nModel) && isFinite(v.tangentModel) && isFinite(v.uv),
              "a built mesh has a non-finite vertex attribute");
    }
  }
  const std::size_t triangles = countTriangles(scene);
  if (triangles > kMaxRenderedTriangles) return;
  // A captured environment renders six faces of up to 1024^2 first: drawn small here, so one
  // execution stays short (the capture's code is the same at any size).
  if (scene.environment && scene.environment->capture) {
    scene.environment->capture->size = std::min(scene.environment->capture->size, kMaxCaptureSize);
  }
  // Shadow maps likewise: up to 4096^2 (six 1024^2 for a point light) drawn small.
  for (Light& light : scene.lights) {
    if (light.shadow) light.shadow->size = std::min(light.shadow->size, kMaxShadowMapSizeDrawn);
  }
  RenderOutput output;
  try {
    output = makeCpuRenderer()->render(scene, scene.settings, kRenderWidth, kRenderHeight);
  } catch (const InputError& error) {
    throw InvariantViolation(std::string("a scene the loader accepted cannot be rendered: ") + error.what());
  }
  checkRenderOutput(output, kRenderWidth, kRenderHeight, triangles, clearByte(scene.output.background.a),
                    "scene render");
}

}  // namespace twr::fuzz
