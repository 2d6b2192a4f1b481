// TBN debug lines in both modes (VBO + tiny shader in a core context; immediate mode in a
// compatibility context): where they appear, what colour, the line mask, user clip planes.
#include "gl_test_scenes.h"
#include "glrender/gl_renderer.h"

#include <gtest/gtest.h>

#include <cmath>

namespace twr {
namespace {

using gltest::addNode;
using gltest::emptyScene;
using gltest::index;
using gltest::kSide;
using gltest::pixel;
using gltest::quadAt;

constexpr float kLineLength = 0.5f;  // world units
constexpr float kQuadDepth = -3.0f;  // view z of the quad

// The quad [-1, 1]^2 at z = -3 facing the camera: N = +Z, T = +X, B = +Y at its corners.
Scene lineScene() {
  Scene scene = emptyScene();
  addNode(scene, quadAt(kQuadDepth, -1.0f, -1.0f, 1.0f, 1.0f), "quad");
  scene.settings.tbnLines.enabled = true;
  scene.settings.tbnLines.length = kLineLength;
  return scene;
}

// Window position (x, top-first row) of a world point for the front camera (90 degrees, square).
vec2 windowPos(vec3 p) {
  return vec2((p.x / -p.z + 1.0f) * 0.5f * kSide, kSide - (p.y / -p.z + 1.0f) * 0.5f * kSide);
}

// True when a pixel within one pixel of world point `p` is a line pixel of colour `rgb`.
bool lineNear(const RenderOutput& out, vec3 p, int r, int g, int b) {
  const vec2 w = windowPos(p);
  const int cx = static_cast<int>(std::floor(w.x));
  const int cy = static_cast<int>(std::floor(w.y));
  for (int y = cy - 1; y <= cy + 1; ++y) {
    for (int x = cx - 1; x <= cx + 1; ++x) {
      if (x < 0 || y < 0 || x >= out.width || y >= out.height) continue;
      const std::uint8_t* c = pixel(out, x, y);
      if (out.lineMask[index(out, x, y)] == 1 && c[0] == r && c[1] == g && c[2] == b && c[3] == 255) return true;
    }
  }
  return false;
}

RenderOutput render(const Scene& scene, const RenderSettings& settings) {
  return makeGlRenderer()->render(scene, settings, kSide, kSide);
}

class GlTbnLines : public ::testing::TestWithParam<LineMode> {};

TEST_P(GlTbnLines, DrawNormalsTangentsBitangentsWhereExpectedAndMaskThem) {
  const Scene scene = lineScene();
  RenderSettings settings = scene.settings;
  settings.tbnLines.mode = GetParam();
  const RenderOutput with = render(scene, settings);
  settings.tbnLines.enabled = false;
  const RenderOutput without = render(scene, settings);

  // N (blue) leaves the corner (1, 1) towards the camera; T (red) and B (green) lie in the
  // quad's plane, hidden by GL_LESS where the quad is, visible beyond its edges.
  EXPECT_TRUE(lineNear(with, vec3(1.0f, 1.0f, kQuadDepth + 0.5f * kLineLength), 0, 0, 255));
  EXPECT_TRUE(lineNear(with, vec3(1.0f + 0.5f * kLineLength, -1.0f, kQuadDepth), 255, 0, 0));
  EXPECT_TRUE(lineNear(with, vec3(-1.0f, 1.0f + 0.5f * kLineLength, kQuadDepth), 0, 255, 0));

  std::size_t maskCount = 0;
  for (int y = 0; y < kSide; ++y) {
    for (int x = 0; x < kSide; ++x) {
      const std::size_t i = index(with, x, y);
      ASSERT_EQ(without.lineMask[i], 0);
      const std::uint8_t* a = pixel(with, x, y);
      const std::uint8_t* b = pixel(without, x, y);
      const bool changed = a[0] != b[0] || a[1] != b[1] || a[2] != b[2] || a[3] != b[3];
      if (changed) {
        EXPECT_EQ(with.lineMask[i], 1) << x << "," << y;
      }
      if (with.lineMask[i] == 1) {
        ++maskCount;
        // Exactly one of the three line colours, alpha 1.
        const int channelsOn = (a[0] == 255) + (a[1] == 255) + (a[2] == 255);
        const int channelsOff = (a[0] == 0) + (a[1] == 0) + (a[2] == 0);
        EXPECT_EQ(channelsOn, 1) << x << "," << y;
        EXPECT_EQ(channelsOff, 2) << x << "," << y;
        EXPECT_EQ(a[3], 255);
      }
    }
  }
  EXPECT_GT(maskCount, 20u);
  // Lines outside the quad are covered pixels too (alpha 1) but carry no triangle id.
  const vec2 t = windowPos(vec3(1.0f + 0.5f * kLineLength, -1.0f, kQuadDepth));
  EXPECT_EQ(with.triangleId[index(with, static_cast<int>(t.x), static_cast<int>(t.y))], kNoTriangle);
}

TEST_P(GlTbnLines, UserClipPlanesCutTheLines) {
  const Scene scene = lineScene();
  RenderSettings settings = scene.settings;
  settings.tbnLines.mode = GetParam();
  settings.userClipPlanes = {vec4(-1.0f, 0.0f, 0.0f, 0.0f)};  // keeps x <= 0
  const RenderOutput out = render(scene, settings);
  EXPECT_FALSE(lineNear(out, vec3(1.0f, 1.0f, kQuadDepth + 0.5f * kLineLength), 0, 0, 255));
  EXPECT_TRUE(lineNear(out, vec3(-1.0f, 1.0f + 0.5f * kLineLength, kQuadDepth), 0, 255, 0));
  for (int y = 0; y < kSide; ++y)
    for (int x = kSide / 2; x < kSide; ++x) EXPECT_EQ(out.lineMask[index(out, x, y)], 0) << x << "," << y;
}

INSTANTIATE_TEST_SUITE_P(BothModes, GlTbnLines, ::testing::Values(LineMode::Core, LineMode::Immediate),
                         [](const auto& info) { return std::string(toString(info.param)); });

// Both modes draw the same segments through the same rasterizer: same pixels.
TEST(GlTbnLinesModes, ImmediateAndCoreDrawTheSamePixels) {
  Scene scene = emptyScene();
  addNode(scene, makeSphere(1.0f, 6, 12), "sphere");
  scene.nodes[0].translate = vec3(0.0f, 0.0f, -3.0f);
  scene.nodes[0].rotateDeg = vec3(20.0f, 30.0f, 0.0f);
  RenderSettings settings = scene.settings;
  settings.tbnLines.enabled = true;
  settings.tbnLines.length = 0.4f;
  const auto renderer = makeGlRenderer();
  settings.tbnLines.mode = LineMode::Core;
  const RenderOutput core = renderer->render(scene, settings, kSide, kSide);
  settings.tbnLines.mode = LineMode::Immediate;
  const RenderOutput immediate = renderer->render(scene, settings, kSide, kSide);
  std::size_t coreLinePixels = 0;
  for (std::uint8_t mask : core.lineMask) coreLinePixels += mask;
  EXPECT_GT(coreLinePixels, 100u);
  std::size_t differing = 0;
  for (std::size_t i = 0; i < core.lineMask.size(); ++i) {
    differing += core.lineMask[i] != immediate.lineMask[i] ? 1 : 0;
    for (std::size_t c = 0; c < 4; ++c) differing += core.rgba[i * 4 + c] != immediate.rgba[i * 4 + c] ? 1 : 0;
  }
  EXPECT_EQ(differing, 0u);
}

}  // namespace
}  // namespace twr
