// The lean GL frame (GlFrame::Lean: colour + depth, no occlusion query, colour read back
// alone) draws the same colour as the full frame bit for bit, so `twinraster bench` may time
// it as the same image. Every test here samples textures in llvmpipe's fast mode, as bench
// does (the mode is fixed per process by the first context).
#include "gl_test_scenes.h"
#include "glrender/gl_renderer.h"
#include "scene/errors.h"
#include "scene/scene_file.h"

#include <gtest/gtest.h>

#include <memory>
#include <string>

namespace twr {
namespace {

const std::string kScenes = std::string(TWINRASTER_SOURCE_DIR) + "/assets/scenes/";

std::unique_ptr<Renderer> makeRenderer(GlFrame frame) {
  GlOptions options;
  options.fastSampling = true;
  options.frame = frame;
  return makeGlRenderer(options);
}

// Renders `scene` with both frames at width x height and checks the colour is identical.
void expectSameColour(const Scene& scene, const RenderSettings& settings, int width, int height,
                      const std::string& what) {
  SCOPED_TRACE(what);
  const RenderOutput full = makeRenderer(GlFrame::Full)->render(scene, settings, width, height);
  const std::unique_ptr<Renderer> leanRenderer = makeRenderer(GlFrame::Lean);
  // Twice: the second frame reuses the framebuffer, programs and uploads of the first.
  for (int frame = 0; frame < 2; ++frame) {
    const RenderOutput lean = leanRenderer->render(scene, settings, width, height);
    ASSERT_EQ(lean.width, width);
    ASSERT_EQ(lean.height, height);
    ASSERT_EQ(lean.rgba.size(), full.rgba.size());
    std::size_t differing = 0, first = full.rgba.size();
    for (std::size_t i = 0; i < full.rgba.size(); ++i) {
      if (lean.rgba[i] == full.rgba[i]) continue;
      if (differing++ == 0) first = i;
    }
    EXPECT_EQ(differing, 0u) << "first differing byte " << first << " (pixel " << first / 4 << ")";
    EXPECT_GT(gltest::coveredCount(full), 0u) << "a blank image proves nothing";
    // Only the colour comes back, and nothing is counted.
    EXPECT_TRUE(lean.depth.empty());
    EXPECT_TRUE(lean.triangleId.empty());
    EXPECT_TRUE(lean.lineMask.empty());
    EXPECT_EQ(lean.stats.pixelsShaded, 0u);
    EXPECT_EQ(lean.stats.trianglesIn, full.stats.trianglesIn);
  }
}

// renderInto reads back into the buffers it is handed, whatever they held: the same output as
// render, for both frames, with buffers of the frame's size and of another.
TEST(GlLeanFrame, RenderIntoAUsedOutputEqualsRender) {
  const Scene scene = loadSceneFile(kScenes + "default.json");
  for (const GlFrame frame : {GlFrame::Full, GlFrame::Lean}) {
    const std::unique_ptr<Renderer> renderer = makeRenderer(frame);
    const RenderOutput fresh = renderer->render(scene, scene.settings, 160, 90);
    ASSERT_GT(gltest::coveredCount(fresh), 0u) << "a blank image proves nothing";
    for (const int side : {160, 40}) {  // the frame's width, and buffers that must grow
      RenderOutput used;
      used.rgba.assign(static_cast<std::size_t>(side) * 90 * 4, 0xA5);
      used.depth.assign(static_cast<std::size_t>(side) * 90, 0.25f);
      used.triangleId.assign(static_cast<std::size_t>(side) * 90, 7u);
      used.lineMask.assign(static_cast<std::size_t>(side) * 90, 1);
      renderer->renderInto(scene, scene.settings, 160, 90, used);
      EXPECT_EQ(used.width, 160);
      EXPECT_EQ(used.rgba, fresh.rgba) << "buffers of width " << side;
      EXPECT_EQ(used.depth, fresh.depth) << "buffers of width " << side;
      EXPECT_EQ(used.triangleId, fresh.triangleId) << "buffers of width " << side;
      EXPECT_EQ(used.lineMask, fresh.lineMask) << "buffers of width " << side;
      EXPECT_EQ(used.stats.trianglesIn, fresh.stats.trianglesIn);
    }
    // A frame that throws leaves the output empty, not holding the last one.
    RenderOutput last = fresh;
    EXPECT_THROW(renderer->renderInto(scene, scene.settings, 0, 90, last), InputError);
    EXPECT_EQ(last.width, 0);
    EXPECT_TRUE(last.rgba.empty() && last.depth.empty());
  }
}

TEST(GlLeanFrame, DefaultSceneColourEqualsTheFullFrame) {
  const Scene scene = loadSceneFile(kScenes + "default.json");
  expectSameColour(scene, scene.settings, 320, 180, "default.json");
}

TEST(GlLeanFrame, MapsLightsAndClipPlanesColourEqualsTheFullFrame) {
  // Normal + diffuse + specular maps from an OBJ's MTL, many lights, user clip planes,
  // tangent-space lighting: other program permutations and fixed-function state.
  for (const char* name : {"obj_model.json", "many_lights.json", "user_clip.json", "tangent_space.json"}) {
    const Scene scene = loadSceneFile(kScenes + name);
    expectSameColour(scene, scene.settings, 200, 150, name);
  }
}

TEST(GlLeanFrame, DebugViewsAndTbnLinesColourEqualsTheFullFrame) {
  const Scene scene = loadSceneFile(kScenes + "tbn_lines.json");
  ASSERT_TRUE(scene.settings.tbnLines.enabled);
  expectSameColour(scene, scene.settings, 160, 120, "tbn_lines.json, core lines");
  RenderSettings immediate = scene.settings;
  immediate.tbnLines.mode = LineMode::Immediate;  // fixed function, compatibility context
  expectSameColour(scene, immediate, 160, 120, "tbn_lines.json, immediate-mode lines");
  RenderSettings view = scene.settings;
  view.tbnLines.enabled = false;
  view.view = View::MappedNormal;
  expectSameColour(scene, view, 160, 120, "tbn_lines.json, view mapped_normal");
}

TEST(GlLeanFrame, ResizingRecreatesOnlyColourAndDepth) {
  Scene scene = gltest::emptyScene();
  // The lean frame reads back no triangle ids: with a transparent background its alpha says
  // which pixels the quad covers.
  scene.output.background.a = 0.0f;
  gltest::addNode(scene, gltest::quadAt(-2.0f, -1.0f, -1.0f, 1.0f, 1.0f), "quad");
  const std::unique_ptr<Renderer> lean = makeRenderer(GlFrame::Lean);
  for (const int side : {gltest::kSide, 2 * gltest::kSide, gltest::kSide}) {
    const RenderOutput out = lean->render(scene, scene.settings, side, side);
    ASSERT_EQ(out.rgba.size(), static_cast<std::size_t>(side * side * 4));
    // The quad spans the middle half of the image both ways.
    EXPECT_EQ(gltest::coveredCount(out), static_cast<std::size_t>(side / 2) * static_cast<std::size_t>(side / 2));
  }
}

}  // namespace
}  // namespace twr
