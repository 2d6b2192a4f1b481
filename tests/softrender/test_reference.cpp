// The reference renderer: the pipeline's stages in double with N x N samples. Coverage
// fractions and colours of a quad whose edge sits at a known window position, the N = 1 case
// against the float pipeline, thread independence, transforms in double, bad options.
#include "softrender/reference_renderer.h"

#include "softrender/cpu_renderer.h"

#include "scene/errors.h"
#include "scene/primitives.h"

#include <gtest/gtest.h>

#include <tuple>

#include <cmath>

namespace twr {
namespace {

constexpr int kSide = 32;  // image width and height, pixels

// Camera at z = 1 looking at the origin with a 90 degree field of view: on the plane z = 0,
// x_ndc = x and window x = (x + 1) * kSide / 2 (the same for y).
// The background is transparent unless asked: the reference's alpha is then its coverage fraction.
Scene quadScene(float leftEdgeX, float backgroundAlpha = 0.0f) {
  Scene scene;
  scene.camera.position = vec3(0, 0, 1);
  scene.camera.target = vec3(0, 0, 0);
  scene.camera.fovDeg = 90.0f;
  scene.output.background = vec4(0.0f, 0.0f, 0.0f, backgroundAlpha);
  // Two triangles from x = leftEdgeX to 2 (beyond the right border), y from -2 to 2.
  const std::vector<vec3> positions{{leftEdgeX, -2, 0}, {2, -2, 0}, {2, 2, 0},
                                    {leftEdgeX, -2, 0}, {2, 2, 0},  {leftEdgeX, 2, 0}};
  scene.meshes.push_back(makeTriangles(positions, {}, {}));
  Material red;
  red.kd = vec3(1.0f, 0.0f, 0.0f);
  scene.materials.push_back(red);
  Node node;
  node.name = "quad";
  node.meshIndex = 0;
  node.materialIndex = 0;
  scene.nodes.push_back(node);
  scene.settings.view = View::Albedo;  // colour = kd: red 1 where covered
  return scene;
}

// Window x of the left edge: 10.25 pixels, between samples 10.125 and 10.375 of N = 4.
constexpr float kEdgeWindowX = 10.25f;
constexpr float kEdgeX = kEdgeWindowX / (kSide / 2.0f) - 1.0f;  // -0.359375, exact in binary

std::size_t topFirst(int x, int yTop) { return static_cast<std::size_t>(yTop) * kSide + static_cast<std::size_t>(x); }

TEST(Reference, CoverageIsTheFractionOfSamplesAndColourTheBoxFilter) {
  const Scene scene = quadScene(kEdgeX);
  const RenderOutput out = makeReferenceRenderer({4, 1})->render(scene, scene.settings, kSide, kSide);
  ASSERT_EQ(out.rgba.size(), static_cast<std::size_t>(kSide * kSide * 4));
  const int row = kSide / 2;
  // Pixel 9 (centre 9.5): no sample right of 10.25. Pixel 10: samples at x 10.375, 10.625 and
  // 10.875 are, 10.125 is not: 3 of 4 columns, 12 of 16 samples. Pixel 11: all.
  const std::size_t p9 = topFirst(9, row), p10 = topFirst(10, row), p11 = topFirst(11, row);
  EXPECT_EQ(out.rgba[p9 * 4 + 3], 0);
  EXPECT_EQ(out.rgba[p9 * 4 + 0], 0);
  EXPECT_EQ(out.triangleId[p9], kNoTriangle);
  EXPECT_EQ(out.depth[p9], 1.0f);
  const int threeQuarters = static_cast<int>(std::lround(255.0 * 12.0 / 16.0));  // 191
  EXPECT_EQ(out.rgba[p10 * 4 + 3], threeQuarters);
  EXPECT_EQ(out.rgba[p10 * 4 + 0], threeQuarters);  // red 1 on 12 samples, background 0 on 4
  EXPECT_EQ(out.rgba[p10 * 4 + 1], 0);
  EXPECT_NE(out.triangleId[p10], kNoTriangle);
  EXPECT_EQ(out.rgba[p11 * 4 + 3], 255);
  EXPECT_EQ(out.rgba[p11 * 4 + 0], 255);
  // Depth at view distance 1 with near 0.1, far 100: z_ndc = (f + n - 2 f n) / (f - n).
  const double nearPlane = scene.camera.near, farPlane = scene.camera.far;
  const double zNdc = (farPlane + nearPlane - 2.0 * farPlane * nearPlane) / (farPlane - nearPlane);
  EXPECT_NEAR(out.depth[p11], 0.5 * zNdc + 0.5, 1e-7);
  EXPECT_NEAR(out.depth[p10], 0.5 * zNdc + 0.5, 1e-7);
  // Every row crosses the edge the same way, and the quad's inner diagonal is covered once:
  // all interior pixels are fully red.
  for (int y = 0; y < kSide; ++y) {
    for (int x = 11; x < kSide; ++x) ASSERT_EQ(out.rgba[topFirst(x, y) * 4 + 0], 255) << x << "," << y;
    ASSERT_EQ(out.rgba[topFirst(10, y) * 4 + 3], threeQuarters) << "row " << y;
  }
}

TEST(Reference, AlphaIsTheBoxFilterOfTheSamplesAlpha) {
  // Pixel 10 has 12 of 16 samples on the (opaque) quad, 4 on the background.
  const std::size_t p9 = topFirst(9, kSide / 2), p10 = topFirst(10, kSide / 2);
  for (const auto& [alpha, empty, edge] : {std::tuple{1.0f, 255, 255}, std::tuple{0.5f, 128, 223},  // (12 + 4 * 0.5) / 16
                                           std::tuple{0.3f, 76, 210}}) {  // clear: 76.5 to even; (12 + 1.2) / 16 * 255 = 210.4
    const Scene scene = quadScene(kEdgeX, alpha);
    const RenderOutput out = makeReferenceRenderer({4, 1})->render(scene, scene.settings, kSide, kSide);
    EXPECT_EQ(out.rgba[p9 * 4 + 3], empty) << alpha;
    EXPECT_EQ(out.rgba[p10 * 4 + 3], edge) << alpha;
    EXPECT_EQ(out.triangleId[p9], kNoTriangle) << "coverage is the id, whatever the alpha";
    EXPECT_NE(out.triangleId[p10], kNoTriangle);
  }
}

TEST(Reference, OneSampleIsTheDoublePipelineAndMatchesTheFloatOneHere) {
  // Edge at 10.25 and interior far from any pixel centre: float and double agree exactly,
  // the background's alpha included (0.3 is a rounding tie, 76.5).
  for (const float alpha : {0.0f, 1.0f, 0.3f}) {
    SCOPED_TRACE(alpha);
    const Scene scene = quadScene(kEdgeX, alpha);
    const RenderOutput reference = makeReferenceRenderer({1, 1})->render(scene, scene.settings, kSide, kSide);
    const RenderOutput cpu = makeCpuRenderer()->render(scene, scene.settings, kSide, kSide);
    ASSERT_EQ(reference.rgba.size(), cpu.rgba.size());
    for (std::size_t i = 0; i < cpu.rgba.size(); ++i) ASSERT_EQ(reference.rgba[i], cpu.rgba[i]) << "byte " << i;
    for (std::size_t i = 0; i < cpu.triangleId.size(); ++i) {
      ASSERT_EQ(reference.triangleId[i], cpu.triangleId[i]) << "pixel " << i;
      ASSERT_NEAR(reference.depth[i], cpu.depth[i], 1e-6) << "pixel " << i;
    }
    EXPECT_EQ(reference.stats.trianglesIn, 2u);
    EXPECT_EQ(reference.stats.pixelsShaded, cpu.stats.pixelsShaded);
    // The same loop with the float stages (used to time float against double) draws it too.
    const RenderOutput floatLoop = makeReferenceRenderer({1, 1, false})->render(scene, scene.settings, kSide, kSide);
    EXPECT_EQ(floatLoop.rgba, cpu.rgba);
    EXPECT_EQ(floatLoop.triangleId, cpu.triangleId);
  }
}

TEST(Reference, SampleCountsAndPixelsShadedAddUpOverPasses) {
  const Scene scene = quadScene(kEdgeX);
  const RenderOutput one = makeReferenceRenderer({1, 1})->render(scene, scene.settings, kSide, kSide);
  const RenderOutput nine = makeReferenceRenderer({3, 1})->render(scene, scene.settings, kSide, kSide);
  // N = 3: sample columns at x + 1/6, 1/2, 5/6; pixel 10 gets 10.5 and 10.83 (2 of 3 columns).
  EXPECT_EQ(nine.rgba[topFirst(10, 3) * 4 + 3], static_cast<int>(std::lround(255.0 * 6.0 / 9.0)));
  // Columns 11..31 (21 pixels) on all 9 passes, pixel 10 on 6 of them, 32 rows.
  EXPECT_EQ(nine.stats.pixelsShaded, static_cast<std::uint64_t>((21 * 9 + 6) * kSide));
  // N = 1: one sample at the centre, 10.5 is right of the edge, so columns 10..31.
  EXPECT_EQ(one.stats.pixelsShaded, static_cast<std::uint64_t>(22 * kSide));
  EXPECT_EQ(nine.stats.trianglesIn, 2u);  // counted on the first pass only
}

TEST(Reference, ImageDoesNotDependOnThreadCount) {
  Scene scene;
  scene.camera.position = vec3(0.3f, 1.2f, 3.0f);
  scene.meshes.push_back(makeSphere(1.0f, 12, 24));
  Material material;
  material.ks = vec3(0.5f);
  scene.materials.push_back(material);
  scene.lights.push_back(Light{});
  Node node;
  node.meshIndex = 0;
  node.materialIndex = 0;
  scene.nodes.push_back(node);
  const RenderOutput a = makeReferenceRenderer({3, 1})->render(scene, scene.settings, 40, 30);
  const RenderOutput b = makeReferenceRenderer({3, 3})->render(scene, scene.settings, 40, 30);
  EXPECT_EQ(a.rgba, b.rgba);
  EXPECT_EQ(a.depth, b.depth);
  EXPECT_EQ(a.triangleId, b.triangleId);
  EXPECT_EQ(a.stats.pixelsShaded, b.stats.pixelsShaded);
  EXPECT_EQ(a.stats.trianglesIn, b.stats.trianglesIn);
}

TEST(Reference, TransformsInDoubleFollowTheSceneGraph) {
  Scene scene;
  scene.meshes.push_back(makeCube(1.0f));
  Node parent;
  parent.translate = vec3(1, 2, 3);
  parent.rotateDeg = vec3(10, 20, 30);
  parent.scale = vec3(2, 1, -1);
  parent.meshIndex = 0;
  Node child;
  child.translate = vec3(-1, 0, 0.5f);
  child.rotateDeg = vec3(0, 90, 0);
  child.meshIndex = 0;
  Node empty;  // no mesh: no draw item, but its children still are
  empty.translate = vec3(5, 0, 0);
  empty.children.push_back(child);
  parent.children.push_back(child);
  scene.nodes.push_back(parent);
  scene.nodes.push_back(empty);
  const std::vector<DrawItem> items = flattenScene(scene);
  const std::vector<glm::dmat4> doubles = referenceWorldFromModel(scene);
  ASSERT_EQ(doubles.size(), items.size());
  ASSERT_EQ(doubles.size(), 3u);
  for (std::size_t k = 0; k < items.size(); ++k) {
    for (int c = 0; c < 4; ++c) {
      for (int r = 0; r < 4; ++r) EXPECT_NEAR(doubles[k][c][r], items[k].worldFromModel[c][r], 1e-5) << k;
    }
  }
  const Camera camera;
  const glm::dmat4 clipFromWorld = referenceClipFromWorld(camera, 64, 48);
  const mat4 clipFromWorldFloat = clipFromView(camera, 64.0f / 48.0f) * viewFromWorld(camera);
  for (int c = 0; c < 4; ++c) {
    for (int r = 0; r < 4; ++r) EXPECT_NEAR(clipFromWorld[c][r], clipFromWorldFloat[c][r], 1e-5);
  }
}

TEST(Reference, RejectsBadOptionsAndSizes) {
  EXPECT_THROW(makeReferenceRenderer({0, 1}), InputError);
  EXPECT_THROW(makeReferenceRenderer({kMaxReferenceSamplesPerAxis + 1, 1}), InputError);
  const Scene scene = quadScene(kEdgeX);
  EXPECT_THROW(makeReferenceRenderer({1, 1})->render(scene, scene.settings, 0, 10), InputError);
  Scene badCamera = scene;
  badCamera.camera.near = 0.0f;
  EXPECT_THROW(makeReferenceRenderer({1, 1})->render(badCamera, badCamera.settings, 8, 8), InputError);
}

}  // namespace
}  // namespace twr
