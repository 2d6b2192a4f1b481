#include "compare/decisions.h"

#include "scene/errors.h"
#include "scene/shadow_map.h"

#include <algorithm>
#include <cstdlib>
#include <string>

namespace twr {
namespace {

constexpr int kColourChannels = 3;  // RGB; alpha is the background's

bool marchesHeight(const Scene& scene) {
  return std::any_of(scene.materials.begin(), scene.materials.end(), [](const Material& m) {
    return m.heightMap && marchesLayers(m.surfaceDetail);
  });
}

bool textured(const Scene& scene) {
  return std::any_of(scene.materials.begin(), scene.materials.end(), [](const Material& m) {
    return m.diffuseMap || m.normalMap || m.specularMap || m.heightMap;
  });
}

// Throws InputError unless both sides hold one width x height RGBA8 output per view, of the
// same views.
void validatePair(const DecisionViews& cpu, const DecisionViews& gl) {
  if (cpu.views != gl.views || cpu.width != gl.width || cpu.height != gl.height) {
    throw InputError("compare: the two renderers' decision views were drawn at other sizes or in other views");
  }
  const std::size_t pixels = static_cast<std::size_t>(cpu.width) * static_cast<std::size_t>(cpu.height);
  for (const DecisionViews* side : {&cpu, &gl}) {
    if (side->outputs.size() != side->views.size()) {
      throw InputError("compare: " + std::to_string(side->outputs.size()) + " decision images for " +
                       std::to_string(side->views.size()) + " views");
    }
    for (const RenderOutput& out : side->outputs) {
      if (out.width != cpu.width || out.height != cpu.height || out.rgba.size() != pixels * 4 ||
          (!out.triangleId.empty() && out.triangleId.size() != pixels)) {
        throw InputError("compare: a decision view's image is not " + std::to_string(cpu.width) + "x" +
                         std::to_string(cpu.height) + " RGBA8");
      }
    }
  }
}

// decisionDiffersAt on a validated pair.
bool differsAt(const DecisionViews& cpu, const DecisionViews& gl, std::size_t i) {
  for (std::size_t v = 0; v < cpu.outputs.size(); ++v) {
    const RenderOutput& a = cpu.outputs[v];
    const RenderOutput& b = gl.outputs[v];
    if (coveredAt(a, i) != coveredAt(b, i)) return true;
    for (int c = 0; c < kColourChannels; ++c) {
      const std::size_t k = i * 4 + static_cast<std::size_t>(c);
      if (std::abs(int(a.rgba[k]) - int(b.rgba[k])) > kDecisionViewLevels) return true;
    }
  }
  return false;
}

}  // namespace

std::vector<View> decisionViewsFor(const Scene& scene, const RenderSettings& settings) {
  std::vector<View> views;
  if (settings.view != View::Shaded) return views;
  if (sceneHasShadows(scene)) views.push_back(View::Shadow);
  if (drawsSsr(settings)) views.push_back(View::SsrHit);
  if (marchesHeight(scene)) views.push_back(View::ParallaxSteps);
  if (usesMipmaps(settings.textureFilter) && textured(scene)) views.push_back(View::MipLevel);
  return views;
}

DecisionViews renderDecisionViews(Renderer& renderer, const Scene& scene, const RenderSettings& settings,
                                  const std::vector<View>& views, int width, int height) {
  DecisionViews out;
  out.width = width;
  out.height = height;
  out.views = views;
  for (const View view : views) {
    RenderSettings s = settings;
    s.view = view;
    s.tbnLines.enabled = false;
    out.outputs.push_back(renderer.render(scene, s, width, height));
  }
  return out;
}

bool decisionDiffersAt(const DecisionViews& cpu, const DecisionViews& gl, std::size_t i) {
  validatePair(cpu, gl);
  if (i >= static_cast<std::size_t>(cpu.width) * static_cast<std::size_t>(cpu.height)) {
    throw InputError("compare: pixel " + std::to_string(i) + " is outside the decision views");
  }
  return differsAt(cpu, gl, i);
}

std::uint64_t classifyDecisions(CompareResult& result, const DecisionViews& cpu, const DecisionViews& gl) {
  PixelAnalysis& pixels = result.pixels;
  validatePair(cpu, gl);
  if (cpu.width != pixels.width || cpu.height != pixels.height) {
    throw InputError("compare: decision views of " + std::to_string(cpu.width) + "x" + std::to_string(cpu.height) +
                     " for a frame of " + std::to_string(pixels.width) + "x" + std::to_string(pixels.height));
  }
  const std::size_t count = static_cast<std::size_t>(pixels.width) * static_cast<std::size_t>(pixels.height);
  std::uint64_t moved = 0;
  for (std::size_t i = 0; i < count; ++i) {
    if (pixels.pixelClass[i] != PixelClass::Shading || !differsAt(cpu, gl, i)) continue;
    pixels.pixelClass[i] = PixelClass::Decision;
    ++moved;
  }
  result.metrics.classShading -= moved;
  result.metrics.classDecision += moved;
  return moved;
}

}  // namespace twr
