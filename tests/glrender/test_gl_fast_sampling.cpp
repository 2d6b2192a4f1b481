// llvmpipe's sampling mode is fixed per process by the first context (it reads
// GALLIVM_PERF once). This executable holds one test so that it owns its process: fast
// sampling leaves GALLIVM_PERF alone, and a later precise request is refused, not ignored.
#include "gl_test_scenes.h"
#include "glrender/gl_renderer.h"
#include "scene/errors.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <string>

namespace twr {
namespace {

TEST(GlFastSampling, FirstContextFixesTheModeForTheProcess) {
  unsetenv("GALLIVM_PERF");
  Scene scene = gltest::emptyScene();
  gltest::addNode(scene, gltest::quadAt(-2.0f, -1.0f, -1.0f, 1.0f, 1.0f), "quad");
  GlOptions fast;
  fast.fastSampling = true;
  const RenderOutput out = makeGlRenderer(fast)->render(scene, scene.settings, gltest::kSide, gltest::kSide);
  EXPECT_TRUE(gltest::covered(out, 32, 32));
  EXPECT_EQ(glSamplingMode(), "fast");
  EXPECT_EQ(std::getenv("GALLIVM_PERF"), nullptr);

  bool refused = false;
  try {
    makeGlRenderer()->render(scene, scene.settings, gltest::kSide, gltest::kSide);
  } catch (const InputError& error) {
    refused = std::string(error.what()).find("new process") != std::string::npos;
  }
  EXPECT_TRUE(refused);
  EXPECT_EQ(glSamplingMode(), "fast");
}

}  // namespace
}  // namespace twr
