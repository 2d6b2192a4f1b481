// The windowed path (GlfwContext + GlOptions::currentContextLoader) draws what OSMesa
// draws. Needs a display: run under `xvfb-run -a ctest -R GlWindow`; skipped without one.
#include "gl_test_scenes.h"
#include "glrender/context_glfw.h"
#include "glrender/gl_renderer.h"
#include "scene/errors.h"
#include "tests/missing_dependency.h"

#include <gtest/gtest.h>

#include <cstdlib>

namespace twr {
namespace {

class GlWindow : public ::testing::TestWithParam<LineMode> {};

TEST_P(GlWindow, MatchesHeadlessPixelForPixel) {
  if (!std::getenv("DISPLAY")) TWR_MISSING_DEPENDENCY("a display (xvfb-run)") << "no DISPLAY: run under xvfb-run (Debian packages xvfb and xauth)";
  Scene scene = gltest::emptyScene();
  gltest::addNode(scene, makeSphere(1.0f, 8, 16), "sphere");
  scene.nodes[0].translate = vec3(0.0f, 0.0f, -3.0f);
  RenderSettings settings = scene.settings;
  settings.tbnLines.enabled = true;
  settings.tbnLines.length = 0.3f;
  settings.tbnLines.mode = GetParam();
  const RenderOutput headless = makeGlRenderer()->render(scene, settings, gltest::kSide, gltest::kSide);

  GlfwWindowDesc desc;
  desc.visible = false;
  desc.compatibility = GetParam() == LineMode::Immediate;
  GlfwContext window(desc);
  GlOptions options;
  options.currentContextLoader = glfwProcAddress();
  auto renderer = makeGlRenderer(options);
  window.makeCurrent();
  const RenderOutput windowed = renderer->render(scene, settings, gltest::kSide, gltest::kSide);
  EXPECT_GT(gltest::coveredCount(windowed), 0u);
  EXPECT_EQ(windowed.rgba, headless.rgba);
  EXPECT_EQ(windowed.lineMask, headless.lineMask);
  EXPECT_EQ(windowed.triangleId, headless.triangleId);
  renderer.reset();  // its GL objects go while the window's context is current
}

INSTANTIATE_TEST_SUITE_P(BothLineModes, GlWindow, ::testing::Values(LineMode::Core, LineMode::Immediate),
                         [](const auto& info) { return std::string(toString(info.param)); });

TEST(GlWindowCore, ImmediateLinesInACoreWindowAreAnInputError) {
  if (!std::getenv("DISPLAY")) TWR_MISSING_DEPENDENCY("a display (xvfb-run)") << "no DISPLAY: run under xvfb-run (Debian packages xvfb and xauth)";
  Scene scene = gltest::emptyScene();
  gltest::addNode(scene, gltest::quadAt(-2.0f, -1.0f, -1.0f, 1.0f, 1.0f), "quad");
  RenderSettings settings = scene.settings;
  settings.tbnLines.enabled = true;
  settings.tbnLines.mode = LineMode::Immediate;
  GlfwWindowDesc desc;
  desc.visible = false;
  GlfwContext window(desc);
  GlOptions options;
  options.currentContextLoader = glfwProcAddress();
  auto renderer = makeGlRenderer(options);
  window.makeCurrent();
  EXPECT_THROW(renderer->render(scene, settings, gltest::kSide, gltest::kSide), InputError);
  renderer.reset();
}

}  // namespace
}  // namespace twr
