// The shadow-map test over lanes (softrender/shadow-inl.h) on maps made here, where every
// answer is known: which texel a point reads, the comparison with its bias, PCF's share at an
// edge, the outside of the map, a cube map's face; float and double alike.
#include "softrender/shade.h"

#include "scene/shadow_map.h"
#include "softrender/shadow_pass.h"
#include "scene/scene_file.h"
#include "softrender/cpu_renderer.h"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <string>

namespace twr {
namespace {

constexpr int kSize = 8;

// An orthographic map whose clip space is world space (s = 0.5 x + 0.5, depth = 0.5 z + 0.5):
// texels with x < kSize / 2 hold `near` (an occluder), the others 1 (nothing).
ShadowMap halfOccludedMap(float near, int pcf, vec2 bias) {
  ShadowMap map;
  map.projection.kind = ShadowKind::Orthographic;
  map.projection.size = kSize;
  map.projection.layers = 1;
  map.projection.clipFromWorld[0] = mat4(1.0f);
  map.projection.pcf = pcf;
  map.projection.bias = bias;
  map.projection.texelWorld = 2.0f / kSize;  // clip space is world space: 2 units over kSize texels
  map.projection.depthPerWorld = 0.5f;       // depth = 0.5 z + 0.5
  map.depth.assign(kSize * kSize, 1.0f);
  for (int y = 0; y < kSize; ++y) {
    for (int x = 0; x < kSize / 2; ++x) map.depth[static_cast<std::size_t>(y * kSize + x)] = near;
  }
  return map;
}

// World x of texel column x's centre.
float worldXOf(int texel) { return (static_cast<float>(texel) + 0.5f) / kSize * 2.0f - 1.0f; }

template <typename T>
lanes::ShadowTestL<T> testAt(const ShadowMap& map, vec3 p, vec3 n = vec3(0, 0, 1), vec3 l = vec3(0, 0, 1)) {
  return lanes::shadowTest<T>(makeShadowUniform<T>(&map), Vec3T<T>(p), Vec3T<T>(n), Vec3T<T>(l));
}

TEST(ShadowTest, BehindTheOccluderIsShadowedInFrontIsLit) {
  const ShadowMap map = halfOccludedMap(0.5f, 1, vec2(0.001f, 0.0f));
  const float x = worldXOf(1);
  const lanes::ShadowTestL<float> behind = testAt<float>(map, vec3(x, 0.0f, 0.2f));  // depth 0.6
  EXPECT_EQ(behind.visibility, 0.0f);
  EXPECT_FLOAT_EQ(behind.depth, 0.6f);
  EXPECT_EQ(behind.stored, 0.5f);
  EXPECT_EQ(behind.inside, 1.0f);
  EXPECT_EQ(testAt<float>(map, vec3(x, 0.0f, -0.2f)).visibility, 1.0f);  // depth 0.4, nearer than the map
  EXPECT_EQ(testAt<float>(map, vec3(worldXOf(6), 0.0f, 0.2f)).visibility, 1.0f);  // no occluder there
}

TEST(ShadowTest, TheBiasDecidesAtTheOccludersOwnDepth) {
  // A surface exactly at the stored depth: shadowed by itself without bias (acne), lit with it.
  const vec3 onSurface(worldXOf(1), 0.0f, 0.0f);  // depth 0.5, the occluder's
  EXPECT_EQ(testAt<float>(halfOccludedMap(0.5f - 1e-4f, 1, vec2(0.0f)), onSurface).visibility, 0.0f);
  EXPECT_EQ(testAt<float>(halfOccludedMap(0.5f - 1e-4f, 1, vec2(1e-3f, 0.0f)), onSurface).visibility, 1.0f);
  // bias = (constant + slope tan(theta) texel (1 + pcf / 2)) depth per world unit: the
  // constant in world units, the slope in texels of the surface's rise over the kernel.
  const vec3 n(0.0f, 0.0f, 1.0f);
  const float texel = 2.0f / kSize, depthPerWorld = 0.5f;
  EXPECT_FLOAT_EQ(testAt<float>(halfOccludedMap(0.5f, 1, vec2(0.01f, 2.0f)), onSurface, n, n).bias,
                  0.01f * depthPerWorld);
  const vec3 at60(std::sin(glm::radians(60.0f)), 0.0f, 0.5f);  // cos 0.5: tan sqrt(3)
  EXPECT_NEAR(testAt<float>(halfOccludedMap(0.5f, 1, vec2(0.01f, 2.0f)), onSurface, n, at60).bias,
              (0.01f + 2.0f * std::sqrt(3.0f) * texel) * depthPerWorld, 1e-6f);
  EXPECT_NEAR(testAt<float>(halfOccludedMap(0.5f, 5, vec2(0.01f, 2.0f)), onSurface, n, at60).bias,
              (0.01f + 2.0f * std::sqrt(3.0f) * texel * 3.0f) * depthPerWorld, 1e-6f);  // a 5 x 5 kernel reaches 3
  // Edge-on: the tangent is clamped.
  EXPECT_NEAR(testAt<float>(halfOccludedMap(0.5f, 1, vec2(0.0f, 1.0f)), onSurface, n, vec3(1, 0, 0)).bias,
              kMaxShadowSlopeTangent * texel * depthPerWorld, 1e-6f);
}

TEST(ShadowTest, PcfAveragesTheKernelAtAnEdge) {
  // Column kSize / 2 is the first lit one: a 3 x 3 kernel there reads one shadowed column.
  const vec3 p(worldXOf(kSize / 2), 0.0f, 0.2f);
  EXPECT_EQ(testAt<float>(halfOccludedMap(0.5f, 1, vec2(0.0f)), p).visibility, 1.0f);
  EXPECT_FLOAT_EQ(testAt<float>(halfOccludedMap(0.5f, 3, vec2(0.0f)), p).visibility, 6.0f / 9.0f);
  EXPECT_FLOAT_EQ(testAt<float>(halfOccludedMap(0.5f, 5, vec2(0.0f)), p).visibility, 15.0f / 25.0f);
  // At the map's border the kernel is clamped to the edge texels (no wrap to the other side).
  const vec3 border(worldXOf(kSize - 1), worldXOf(0), 0.2f);
  EXPECT_EQ(testAt<float>(halfOccludedMap(0.5f, 5, vec2(0.0f)), border).visibility, 1.0f);
}

TEST(ShadowTest, OutsideTheMapIsLit) {
  const ShadowMap map = halfOccludedMap(0.0f, 3, vec2(0.0f));
  for (const vec3 p : {vec3(1.5f, 0.0f, 0.2f), vec3(-1.01f, 0.0f, 0.2f), vec3(worldXOf(1), 1.2f, 0.2f),
                       vec3(worldXOf(1), 0.0f, 1.5f)}) {
    const lanes::ShadowTestL<float> t = testAt<float>(map, p);
    EXPECT_EQ(t.visibility, 1.0f) << p.x << " " << p.y << " " << p.z;
    EXPECT_EQ(t.inside, 0.0f);
    EXPECT_EQ(t.stored, 1.0f);
  }
}

TEST(ShadowTest, DoubleLanesAgreeWithFloat) {
  const ShadowMap map = halfOccludedMap(0.5f, 3, vec2(0.0005f, 0.002f));
  for (int i = 0; i < 64; ++i) {
    const vec3 p(-1.0f + 2.0f * static_cast<float>(i) / 63.0f, 0.3f, 0.1f * static_cast<float>(i % 5) - 0.2f);
    const vec3 l = glm::normalize(vec3(0.2f, 0.1f, 1.0f));
    const lanes::ShadowTestL<float> f = testAt<float>(map, p, vec3(0, 0, 1), l);
    const lanes::ShadowTestL<double> d = testAt<double>(map, p, vec3(0, 0, 1), l);
    EXPECT_NEAR(d.visibility, f.visibility, 1e-6) << i;
    EXPECT_NEAR(d.depth, f.depth, 1e-6) << i;
  }
}

TEST(ShadowTest, CubeMapReadsTheFaceOfTheDirection) {
  Light light;
  light.posWorld = vec3(0.0f);
  light.shadow = ShadowDesc{kSize, vec2(0.0f), 1, 10.0f};
  WorldBounds bounds{vec3(-5.0f), vec3(5.0f)};
  ShadowMap map;
  map.projection = shadowProjectionFor(light, bounds);
  ASSERT_EQ(map.projection.kind, ShadowKind::Cube);
  // Layer f holds an occluder at distance 1 on face 4 (+Z) only; the others hold nothing.
  map.depth.assign(static_cast<std::size_t>(kCubeShadowLayers * kSize * kSize), 1.0f);
  const float occluder = cubeShadowDepth(map.projection, 1.0f);
  std::fill(map.depth.begin() + 4 * kSize * kSize, map.depth.begin() + 5 * kSize * kSize, occluder);
  const vec3 n(0.0f, 0.0f, -1.0f);
  EXPECT_EQ(testAt<float>(map, vec3(0.3f, -0.2f, 2.0f), n, -n).visibility, 0.0f);  // +Z, behind the occluder
  EXPECT_EQ(testAt<float>(map, vec3(0.3f, -0.2f, 0.5f), n, -n).visibility, 1.0f);  // +Z, in front of it
  EXPECT_EQ(testAt<float>(map, vec3(0.3f, -0.2f, -2.0f), n, -n).visibility, 1.0f);  // -Z
  EXPECT_EQ(testAt<float>(map, vec3(3.0f, -0.2f, 2.0f), n, -n).visibility, 1.0f);   // +X
  EXPECT_FLOAT_EQ(testAt<float>(map, vec3(0.3f, -0.2f, 2.0f), n, -n).depth, cubeShadowDepth(map.projection, 2.0f));
}

TEST(ShadowTest, SpotMapCoversTheConeAndNothingBehindTheLight) {
  Light light;
  light.posWorld = vec3(0.0f, 3.0f, 0.0f);
  light.spot = SpotCone{vec3(0.0f, -1.0f, 0.0f), 20.0f, 30.0f};
  light.shadow = ShadowDesc{kSize, vec2(0.0f), 1, 10.0f};
  ShadowMap map;
  map.projection = shadowProjectionFor(light, WorldBounds{vec3(-5.0f), vec3(5.0f)});
  ASSERT_EQ(map.projection.kind, ShadowKind::Perspective);
  ASSERT_EQ(map.projection.layers, 1);
  // An occluder 1 unit below the light everywhere in the map.
  map.depth.assign(static_cast<std::size_t>(kSize * kSize), cubeShadowDepth(map.projection, 1.0f));
  const vec3 n(0.0f, 1.0f, 0.0f);
  EXPECT_EQ(testAt<float>(map, vec3(0.2f, 1.0f, -0.1f), n, n).visibility, 0.0f);  // 2 below: behind the occluder
  EXPECT_EQ(testAt<float>(map, vec3(0.1f, 2.5f, 0.1f), n, n).visibility, 1.0f);   // 0.5 below: in front of it
  // The depth along the axis is a cube face's at the same distance; the cone's edge (30 degrees
  // off the axis) lies inside the map, a point 40 degrees off it outside.
  EXPECT_FLOAT_EQ(testAt<float>(map, vec3(0.0f, 1.0f, 0.0f), n, n).depth, cubeShadowDepth(map.projection, 2.0f));
  const float edge = 2.0f * std::tan(29.0f * 3.14159265f / 180.0f), beyond = 2.0f * std::tan(40.0f * 3.14159265f / 180.0f);
  EXPECT_EQ(testAt<float>(map, vec3(edge, 1.0f, 0.0f), n, n).inside, 1.0f);
  EXPECT_EQ(testAt<float>(map, vec3(beyond, 1.0f, 0.0f), n, n).inside, 0.0f);
  // Behind the light: outside the map (and lit), never projected through it.
  const lanes::ShadowTestL<float> behind = testAt<float>(map, vec3(0.2f, 4.0f, 0.1f), n, n);
  EXPECT_EQ(behind.inside, 0.0f);
  EXPECT_EQ(behind.visibility, 1.0f);
  // Double lanes read the same texels.
  EXPECT_EQ(testAt<double>(map, vec3(0.2f, 1.0f, -0.1f), n, n).visibility, 0.0);
}

}  // namespace
}  // namespace twr

namespace twr {
namespace {

TEST(ShadowMapPool, ReusesOnlyAMapNobodyHolds) {
  ShadowMapPool pool;
  std::shared_ptr<ShadowMap> a = pool.acquire(16);
  ASSERT_EQ(a->depth.size(), 16u);
  a->depth[3] = 0.25f;
  a->milliseconds = 5.0;
  const ShadowMap* first = a.get();
  // Held by a frame's output: a second acquire gets another map.
  std::shared_ptr<const ShadowMap> held = a;
  a.reset();
  std::shared_ptr<ShadowMap> b = pool.acquire(16);
  EXPECT_NE(b.get(), first);
  const ShadowMap* second = b.get();
  // Released: stored maps come back (no third allocation), bookkeeping reset (the texels are
  // the pass's to write).
  held.reset();
  b.reset();
  std::shared_ptr<ShadowMap> c = pool.acquire(16);
  EXPECT_TRUE(c.get() == first || c.get() == second);
  EXPECT_EQ(c->milliseconds, 0.0);
  std::shared_ptr<ShadowMap> d = pool.acquire(16);
  EXPECT_TRUE(d.get() == first || d.get() == second);
  EXPECT_NE(c.get(), d.get());
  // Another size never reuses it.
  EXPECT_EQ(pool.acquire(64)->depth.size(), 64u);
}

TEST(ShadowMapPool, FramesShareNoMapAndDrawTheSame) {
  // One renderer, three frames: while the first frame's output is held the second draws into
  // other storage; once both are dropped the third reuses one, and every frame's map and image
  // are the same (nothing of the storage's earlier contents leaks in).
  const Scene scene = loadSceneFile(std::string(TWINRASTER_SOURCE_DIR) + "/assets/scenes/shadow_directional.json");
  std::unique_ptr<Renderer> cpu = makeCpuRenderer();
  RenderOutput first = cpu->render(scene, scene.settings, 96, 72);
  RenderOutput second = cpu->render(scene, scene.settings, 96, 72);
  ASSERT_EQ(first.shadowMaps.size(), 1u);
  ASSERT_TRUE(first.shadowMaps[0] && second.shadowMaps[0]);
  EXPECT_NE(first.shadowMaps[0].get(), second.shadowMaps[0].get());
  EXPECT_EQ(first.shadowMaps[0]->depth, second.shadowMaps[0]->depth);
  const std::vector<float> depth = first.shadowMaps[0]->depth;
  const std::vector<std::uint8_t> rgba = first.rgba;
  const ShadowMap* reused[] = {first.shadowMaps[0].get(), second.shadowMaps[0].get()};
  first = RenderOutput{};
  second = RenderOutput{};
  const RenderOutput third = cpu->render(scene, scene.settings, 96, 72);
  EXPECT_TRUE(third.shadowMaps[0].get() == reused[0] || third.shadowMaps[0].get() == reused[1]);
  EXPECT_EQ(third.shadowMaps[0]->depth, depth);
  EXPECT_EQ(third.rgba, rgba);
}

}  // namespace
}  // namespace twr
