// renderGlPixel (glrender/gl_renderer.h), the GUI probe's one-pixel GL render, must give the
// pixel of the full frame bit for bit: colour, depth, triangle id and line mask, in several
// debug views, with mipmapped and anisotropic sampling (their derivatives come from 2x2 quads
// across the scissor's edge).
#include "glrender/gl_renderer.h"
#include "scene/errors.h"
#include "scene/scene_file.h"

#include <gtest/gtest.h>

#include <string>

namespace twr {
namespace {

// Small frames keep the test fast; pixels.
constexpr int kWidth = 48;
constexpr int kHeight = 36;
// Every kStep-th column and row is probed (pixels).
constexpr int kStep = 7;

Scene loadAsset(const std::string& name) {
  return loadSceneFile(std::string(TWINRASTER_SOURCE_DIR) + "/assets/scenes/" + name);
}

void expectPixelsMatchFrames(const Scene& scene, RenderSettings settings) {
  const auto renderer = makeGlRenderer();
  for (const View view : {View::Shaded, View::Uv, View::Depth, View::MipLevel}) {
    settings.view = view;
    const RenderOutput frame = renderer->render(scene, settings, kWidth, kHeight);
    for (int yTop = 1; yTop < kHeight; yTop += kStep) {
      for (int x = 3; x < kWidth; x += kStep) {
        const RenderOutput pixel = renderGlPixel(*renderer, scene, settings, kWidth, kHeight, x, yTop);
        SCOPED_TRACE("pixel (" + std::to_string(x) + ", " + std::to_string(yTop) + ") view " +
                     std::string(toString(view)));
        ASSERT_EQ(pixel.width, 1);
        ASSERT_EQ(pixel.height, 1);
        const std::size_t i = static_cast<std::size_t>(yTop) * kWidth + static_cast<std::size_t>(x);
        for (std::size_t c = 0; c < 4; ++c) EXPECT_EQ(pixel.rgba[c], frame.rgba[i * 4 + c]) << "channel " << c;
        EXPECT_EQ(pixel.depth[0], frame.depth[i]);
        EXPECT_EQ(pixel.triangleId[0], frame.triangleId[i]);
        EXPECT_EQ(pixel.lineMask[0], frame.lineMask[i]);
      }
    }
  }
}

TEST(GlPixel, DefaultSceneMatchesFrames) {
  const Scene scene = loadAsset("default.json");
  expectPixelsMatchFrames(scene, scene.settings);
}

TEST(GlPixel, TrilinearAnisotropicWithLinesMatchesFrames) {
  const Scene scene = loadAsset("tangent_space.json");
  RenderSettings settings = scene.settings;
  settings.textureFilter = TextureFilter::Trilinear;
  settings.anisotropy = 4.0f;
  settings.tbnLines.enabled = true;
  expectPixelsMatchFrames(scene, settings);
}

TEST(GlPixel, RefusesPixelsOutsideTheFrameAndOtherRenderers) {
  const Scene scene = loadAsset("default.json");
  const auto renderer = makeGlRenderer();
  EXPECT_THROW(renderGlPixel(*renderer, scene, scene.settings, kWidth, kHeight, kWidth, 0), InputError);
  EXPECT_THROW(renderGlPixel(*renderer, scene, scene.settings, kWidth, kHeight, 0, -1), InputError);
  GlOptions lean;
  lean.frame = GlFrame::Lean;
  const auto leanRenderer = makeGlRenderer(lean);
  EXPECT_THROW(renderGlPixel(*leanRenderer, scene, scene.settings, kWidth, kHeight, 0, 0), InputError);
}

}  // namespace
}  // namespace twr
