// The inspector's per-view pixel from one trace (softrender/pixel_views.h) must be the pixel
// of that view's full render: colour, depth and triangle id, for covered pixels, edges and
// the background, in world and tangent lighting space, with mipmapped and anisotropic
// filtering (their LOD comes from the traced quad differences) and in the mip-level view
// (its stand-in textures).
#include "softrender/cpu_renderer.h"
#include "softrender/pixel_views.h"

#include "scene/errors.h"
#include "scene/scene_file.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace twr {
namespace {

// Small frames keep the test fast under the sanitizers; pixels, width x height.
constexpr int kWidth = 48;
constexpr int kHeight = 36;
// Pixels probed per frame: every kStep-th column and row, offset so edges of the objects fall
// between probes as well as on them (pixels).
constexpr int kStep = 5;

Scene loadAsset(const std::string& name) {
  return loadSceneFile(std::string(TWINRASTER_SOURCE_DIR) + "/assets/scenes/" + name);
}

void expectViewsMatchRenders(const Scene& scene, const RenderSettings& settings) {
  std::unique_ptr<Renderer> renderer = makeCpuRenderer();
  std::vector<RenderOutput> renders;
  for (const View view : kAllViews) {
    RenderSettings viewSettings = settings;
    viewSettings.view = view;
    viewSettings.tbnLines.enabled = false;
    renders.push_back(renderer->render(scene, viewSettings, kWidth, kHeight));
  }
  int covered = 0;
  for (int yTop = 2; yTop < kHeight; yTop += kStep) {
    for (int x = 1; x < kWidth; x += kStep) {
      const PixelTrace trace = tracePixelVisits(scene, settings, kWidth, kHeight, x, yTop);
      const std::size_t i = static_cast<std::size_t>(yTop) * kWidth + static_cast<std::size_t>(x);
      for (std::size_t v = 0; v < std::size(kAllViews); ++v) {
        const ViewPixel pixel = shadeTracedPixel(scene, settings, trace, kAllViews[v]);
        const RenderOutput& render = renders[v];
        SCOPED_TRACE("pixel (" + std::to_string(x) + ", " + std::to_string(yTop) + ") view " +
                     std::string(toString(kAllViews[v])));
        for (std::size_t c = 0; c < 4; ++c) EXPECT_EQ(pixel.rgba[c], render.rgba[i * 4 + c]) << "channel " << c;
        EXPECT_EQ(pixel.depth, render.depth[i]);
        EXPECT_EQ(pixel.triangleId, render.triangleId[i]);
      }
      if (renders.front().triangleId[i] != kNoTriangle) ++covered;
    }
  }
  EXPECT_GT(covered, 3) << "too few probes land on geometry to mean anything";
}

TEST(PixelViews, DefaultSceneWorldLighting) {
  const Scene scene = loadAsset("default.json");
  expectViewsMatchRenders(scene, scene.settings);
}

TEST(PixelViews, TangentLightingTrilinearAnisotropic) {
  const Scene scene = loadAsset("tangent_space.json");
  RenderSettings settings = scene.settings;
  ASSERT_EQ(settings.lightingSpace, LightingSpace::Tangent);
  settings.textureFilter = TextureFilter::Trilinear;
  settings.anisotropy = 4.0f;
  expectViewsMatchRenders(scene, settings);
}

TEST(PixelViews, CullNoneNearestMipmap) {
  const Scene scene = loadAsset("culling.json");
  RenderSettings settings = scene.settings;
  settings.cull = CullMode::None;
  settings.textureFilter = TextureFilter::NearestMipmapLinear;
  expectViewsMatchRenders(scene, settings);
}

TEST(PixelViews, TraceFromAnotherLightingSpaceIsRefused) {
  const Scene scene = loadAsset("default.json");
  RenderSettings settings = scene.settings;
  settings.lightingSpace = LightingSpace::World;
  const PixelTrace trace = tracePixelVisits(scene, settings, kWidth, kHeight, kWidth / 2, kHeight / 2);
  settings.lightingSpace = LightingSpace::Tangent;
  EXPECT_THROW(shadeTracedPixel(scene, settings, trace, View::Shaded), InputError);
}

}  // namespace
}  // namespace twr
