// The fill rule on llvmpipe's bits: fill_rule.json's square is two triangles whose shared
// diagonal runs through pixel centres (8.5, 8.5) to (40.5, 40.5) in GL window coordinates. A
// centre exactly on the diagonal goes to the triangle for which it is a left or bottom edge,
// on both renderers, and no pixel of the square is drawn twice or left out.
#include "glrender/gl_renderer.h"
#include "scene/scene_file.h"
#include "softrender/cpu_renderer.h"

#include <gtest/gtest.h>

#include <string>

namespace twr {
namespace {

constexpr int kSize = 64;  // the scene's own output size, pixels

std::uint32_t idAt(const RenderOutput& out, int x, int yGl) {
  return out.triangleId[static_cast<std::size_t>(kSize - 1 - yGl) * kSize + static_cast<std::size_t>(x)];
}

TEST(FillRule, PixelCentresOnASharedEdgeGoToTheSameTriangleOnBothRenderers) {
  const Scene scene = loadSceneFile(std::string(TWINRASTER_SOURCE_DIR) + "/assets/scenes/fill_rule.json");
  const RenderOutput cpu = makeCpuRenderer()->render(scene, scene.settings, kSize, kSize);
  const RenderOutput gl = makeGlRenderer()->render(scene, scene.settings, kSize, kSize);
  ASSERT_EQ(cpu.triangleId.size(), static_cast<std::size_t>(kSize * kSize));
  ASSERT_EQ(gl.triangleId.size(), cpu.triangleId.size());
  // Between the square's corners, the diagonal's centres: the lower-right triangle (0), whose
  // left edge the diagonal is, takes them; the upper-left one (1) the pixels above.
  for (int k = 9; k <= 39; ++k) {
    EXPECT_EQ(idAt(cpu, k, k), 0u) << "centre (" << k << ".5, " << k << ".5)";
    EXPECT_EQ(idAt(gl, k, k), 0u) << "centre (" << k << ".5, " << k << ".5)";
    if (k < 39) {  // row 40's centres lie on the square's top edge
      EXPECT_EQ(idAt(cpu, k, k + 1), 1u) << "just above the diagonal";
    }
  }
  int covered = 0, differing = 0;
  for (std::size_t i = 0; i < cpu.triangleId.size(); ++i) {
    covered += cpu.triangleId[i] != kNoTriangle ? 1 : 0;
    differing += cpu.triangleId[i] != gl.triangleId[i] ? 1 : 0;
  }
  EXPECT_EQ(covered, 32 * 32) << "centres 8.5 .. 39.5 on both axes: the top and right edges leave theirs";
  EXPECT_EQ(differing, 0);
}

}  // namespace
}  // namespace twr
