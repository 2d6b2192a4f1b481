// The deferred pipeline on the CPU (softrender/deferred.h): the position stored or rebuilt from depth,
// the per-lane Phong exponent, the G-buffer's contents, the teaching and fast paths' bits, and
// deferred frames against forward ones on scenes of every kind (the suite compares both
// renderers' deferred frames, tests/compare/test_scene_suite.cpp).
#include "softrender/deferred.h"

#include "scene/camera.h"
#include "scene/scene_file.h"
#include "softrender/cpu_renderer.h"
#include "softrender/vertex.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <string>

namespace twr {
namespace {

Scene loadScene(const std::string& name) {
  return loadSceneFile(std::string(TWINRASTER_SOURCE_DIR) + "/assets/scenes/" + name);
}

RenderOutput renderWith(const Scene& scene, Pipeline pipeline, CpuPath path, int width = 160, int height = 120,
                        GBufferPosition position = GBufferPosition::Stored) {
  RenderSettings settings = scene.settings;
  settings.pipeline = pipeline;
  settings.gbufferPosition = position;
  CpuOptions options;
  options.path = path;
  options.threads = 2;
  return makeCpuRenderer(options)->render(scene, settings, width, height);
}

TEST(Deferred, WorldFromWindowRebuildsAProjectedPoint) {
  const Scene scene = loadScene("default.json");
  const int width = 640, height = 480;
  const mat4 clipFromWorld = clipFromWorldFor(scene.camera, width, height);
  const mat4 worldFromClip = worldFromClipOf(clipFromWorld);
  for (const vec3 p : {vec3(0.0f), vec3(0.3f, -0.2f, 0.4f), vec3(-0.5f, 0.5f, -0.5f)}) {
    const vec4 clip = clipFromWorld * vec4(p, 1.0f);
    const vec3 ndc = vec3(clip) / clip.w;
    // A pixel centre's window position: the point itself, moved to the centre it lies in.
    const float px = std::floor((ndc.x * 0.5f + 0.5f) * width), py = std::floor((ndc.y * 0.5f + 0.5f) * height);
    const float depth = ndc.z * 0.5f + 0.5f;
    const vec3 back = lanes::worldFromWindow<float>(worldFromClip, vec2(width, height), px, py, depth);
    // The rebuilt point lies on the pixel centre's ray at the point's depth: within a pixel's
    // footprint (under 0.01 world units here) of it.
    EXPECT_LT(glm::length(back - p), 0.01f) << p.x << ", " << p.y << ", " << p.z;
    const vec4 again = clipFromWorld * vec4(back, 1.0f);
    EXPECT_NEAR(again.z / again.w * 0.5f + 0.5f, depth, 1e-6f);
  }
}

TEST(Deferred, PerLaneExponentGivesPhongPowsBits) {
  for (const float s : {0.0f, 1.0f, 8.0f, 32.0f, 255.0f, 7.5f, 700.0f}) {
    for (const float x : {0.0f, 1e-30f, 0.25f, 0.5f, 0.999f, 1.0f, -0.5f, INFINITY}) {
      const float a = lanes::phongPow<float>(x, s), b = lanes::phongPowPerLane<float>(x, s);
      EXPECT_EQ(std::memcmp(&a, &b, sizeof a), 0) << x << "^" << s;
    }
  }
}

TEST(Deferred, ForwardFramesHaveNoGBufferDeferredOnesDo) {
  const Scene scene = loadScene("default.json");
  EXPECT_EQ(renderWith(scene, Pipeline::Forward, CpuPath::Fast).gbuffer, nullptr);
  const RenderOutput out = renderWith(scene, Pipeline::Deferred, CpuPath::Fast);
  ASSERT_NE(out.gbuffer, nullptr);
  const GBuffer& g = *out.gbuffer;
  ASSERT_EQ(g.normal.size(), static_cast<std::size_t>(out.width * out.height));
  std::size_t covered = 0;
  for (std::size_t i = 0; i < g.normal.size(); ++i) {
    if (out.depth[i] < 1.0f) {
      ++covered;
      EXPECT_NEAR(glm::length(vec3(g.normal[i])), 1.0f, 1e-5f) << "pixel " << i;
      EXPECT_NEAR(glm::length(vec3(g.geometric[i])), 1.0f, 1e-5f) << "pixel " << i;
      EXPECT_EQ(g.position[i].w, 1.0f) << "pixel " << i;
    } else {
      EXPECT_EQ(g.normal[i], vec4(0.0f)) << "pixel " << i << ": nothing drawn there";
      EXPECT_EQ(g.emission[i], vec4(0.0f)) << "pixel " << i;
    }
  }
  EXPECT_GT(covered, 1000u);
  EXPECT_GT(out.stats.lightingMilliseconds, 0.0);
  // Rebuilt from depth: no position target.
  const RenderOutput fromDepth =
      renderWith(scene, Pipeline::Deferred, CpuPath::Fast, 160, 120, GBufferPosition::Depth);
  ASSERT_NE(fromDepth.gbuffer, nullptr);
  EXPECT_TRUE(fromDepth.gbuffer->position.empty());
}

// The stored position is where the pixel's depth puts it: on the pixel centre's ray at its depth,
// within the depth's rounding and the distance from the centre to where the fragment's
// attributes are interpolated (none: both are the centre's), under 1e-3 world units here.
TEST(Deferred, StoredPositionLiesWhereTheDepthSaysItDoes) {
  const Scene scene = loadScene("default.json");
  const int width = 160, height = 120;
  const RenderOutput out = renderWith(scene, Pipeline::Deferred, CpuPath::Fast, width, height);
  ASSERT_TRUE(out.gbuffer);
  const mat4 worldFromClip = worldFromClipOf(clipFromWorldFor(scene.camera, width, height));
  std::size_t checked = 0;
  for (int row = 0; row < height; ++row) {
    for (int px = 0; px < width; ++px) {
      const std::size_t i = static_cast<std::size_t>(row) * width + static_cast<std::size_t>(px);
      if (!(out.depth[i] < 1.0f)) continue;
      const float py = static_cast<float>(height - 1 - row);  // window rows count from the bottom
      const vec3 rebuilt = lanes::worldFromWindow<float>(worldFromClip, vec2(width, height), static_cast<float>(px), py,
                                                         out.depth[i]);
      EXPECT_LT(glm::length(rebuilt - vec3(out.gbuffer->position[i])), 1e-3f) << "pixel " << px << ", " << row;
      ++checked;
    }
  }
  EXPECT_GT(checked, 1000u);
}

TEST(Deferred, DebugViewsDrawForward) {
  Scene scene = loadScene("default.json");
  scene.settings.view = View::Normal;
  const RenderOutput deferred = renderWith(scene, Pipeline::Deferred, CpuPath::Fast);
  const RenderOutput forward = renderWith(scene, Pipeline::Forward, CpuPath::Fast);
  EXPECT_EQ(deferred.gbuffer, nullptr);
  EXPECT_EQ(deferred.rgba, forward.rgba);
}

// The fast path's G-buffer and lighting passes give the teaching path's bits.
class DeferredPaths : public ::testing::TestWithParam<const char*> {};
TEST_P(DeferredPaths, FastMatchesTeachingBitForBit) {
  const Scene scene = loadScene(GetParam());
  const RenderOutput teaching = renderWith(scene, Pipeline::Deferred, CpuPath::Teaching);
  const RenderOutput fast = renderWith(scene, Pipeline::Deferred, CpuPath::Fast);
  ASSERT_TRUE(teaching.gbuffer && fast.gbuffer);
  EXPECT_EQ(teaching.rgba, fast.rgba);
  EXPECT_EQ(teaching.depth, fast.depth);
  EXPECT_EQ(teaching.triangleId, fast.triangleId);
  const auto same = [](const std::vector<vec4>& a, const std::vector<vec4>& b) {
    return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(vec4)) == 0;
  };
  EXPECT_TRUE(same(teaching.gbuffer->normal, fast.gbuffer->normal));
  EXPECT_TRUE(same(teaching.gbuffer->geometric, fast.gbuffer->geometric));
  EXPECT_TRUE(same(teaching.gbuffer->albedo, fast.gbuffer->albedo));
  EXPECT_TRUE(same(teaching.gbuffer->specular, fast.gbuffer->specular));
  EXPECT_TRUE(same(teaching.gbuffer->emission, fast.gbuffer->emission));
  EXPECT_TRUE(same(teaching.gbuffer->position, fast.gbuffer->position));
  EXPECT_FALSE(teaching.gbuffer->position.empty());
  // Rebuilt from depth, the two paths agree too.
  const RenderOutput teachingDepth =
      renderWith(scene, Pipeline::Deferred, CpuPath::Teaching, 160, 120, GBufferPosition::Depth);
  const RenderOutput fastDepth = renderWith(scene, Pipeline::Deferred, CpuPath::Fast, 160, 120, GBufferPosition::Depth);
  EXPECT_EQ(teachingDepth.rgba, fastDepth.rgba);
}
INSTANTIATE_TEST_SUITE_P(Scenes, DeferredPaths,
                         ::testing::Values("default.json", "tangent_space.json", "shadow_point_cube.json",
                                           "env_glass_sphere.json", "height_bump_emboss.json", "many_lights.json"));

// Deferred against forward on the same renderer, with the stored position: within a level where
// the G-buffer holds the surface (the world-space lighting of a tangent-space material and the
// environment's folded mix round differently), the same bits where nothing differs (a material
// lit in the G-buffer pass), on the shadowed scenes and a light touching the surface too, where
// a position rebuilt from depth jumps (below).
struct ForwardCase {
  const char* scene;
  int maxLevels;
};
class DeferredForward : public ::testing::TestWithParam<ForwardCase> {};
TEST_P(DeferredForward, DeferredMatchesForward) {
  const Scene scene = loadScene(GetParam().scene);
  const RenderOutput forward = renderWith(scene, Pipeline::Forward, CpuPath::Fast, 320, 240);
  const RenderOutput deferred = renderWith(scene, Pipeline::Deferred, CpuPath::Fast, 320, 240);
  ASSERT_TRUE(deferred.gbuffer && !deferred.gbuffer->position.empty());
  ASSERT_EQ(deferred.rgba.size(), forward.rgba.size());
  int maxLevels = 0;
  std::size_t covered = 0;
  for (std::size_t i = 0; i < forward.depth.size(); ++i) {
    EXPECT_EQ(deferred.triangleId[i], forward.triangleId[i]) << "pixel " << i;
    if (forward.triangleId[i] == kNoTriangle) continue;
    ++covered;
    for (std::size_t c = 0; c < 4; ++c) {
      maxLevels = std::max(maxLevels, std::abs(int(deferred.rgba[4 * i + c]) - int(forward.rgba[4 * i + c])));
    }
  }
  EXPECT_LE(maxLevels, GetParam().maxLevels) << GetParam().scene;
  EXPECT_GT(covered, 0u);
}
INSTANTIATE_TEST_SUITE_P(Scenes, DeferredForward,
                         ::testing::Values(ForwardCase{"default.json", 1}, ForwardCase{"many_lights.json", 1},
                                           ForwardCase{"shadow_directional.json", 1},
                                           ForwardCase{"shadow_point_cube.json", 1},
                                           ForwardCase{"shadow_peter_panning.json", 1},
                                           ForwardCase{"light_touching.json", 1},
                                           ForwardCase{"env_mirror_sphere.json", 1},
                                           ForwardCase{"env_glass_sphere.json", 1},
                                           ForwardCase{"env_diffuse_light.json", 1},
                                           ForwardCase{"height_bump_emboss.json", 0}));

}  // namespace
}  // namespace twr
