// Shadow-map projections (scene/shadow_map.h): where a light's map lies, the cube's face
// choice and its depth formula, checked against the face renders' own matrices; and the scene
// file's "shadow" key.
#include "scene/shadow_map.h"

#include "scene/scene.h"
#include "scene/scene_file.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace twr {
namespace {

Scene floorAndBox() {
  return parseScene(R"({"nodes": [{"name": "floor", "mesh": {"type": "plane", "size": [4, 4]}},
                                   {"name": "box", "translate": [0, 0.5, 0], "mesh": {"type": "cube", "size": 1}}]})",
                    "inline.json", ".");
}

// The window coordinates (x, y in [0, 1], z window depth) of p under clipFromWorld.
vec3 windowOf(const mat4& clipFromWorld, const vec3& p) {
  const vec4 c = clipFromWorld * vec4(p, 1.0f);
  return vec3(c) / c.w * 0.5f + 0.5f;
}

TEST(ShadowMap, WorldBoundsCoverEveryVertex) {
  const WorldBounds b = worldBoundsOf(floorAndBox());
  ASSERT_FALSE(b.empty());
  EXPECT_FLOAT_EQ(b.lo.x, -2.0f);
  EXPECT_FLOAT_EQ(b.hi.x, 2.0f);
  EXPECT_FLOAT_EQ(b.lo.y, 0.0f);
  EXPECT_FLOAT_EQ(b.hi.y, 1.0f);
  EXPECT_TRUE(worldBoundsOf(Scene{}).empty());
}

TEST(ShadowMap, DirectionalMapHoldsTheWholeSceneOrderedAlongTheLight) {
  const Scene scene = floorAndBox();
  Light light;
  light.type = LightType::Directional;
  light.directionWorld = glm::normalize(vec3(-0.3f, -1.0f, -0.2f));
  light.shadow = ShadowDesc{};
  const ShadowProjection p = shadowProjectionFor(light, worldBoundsOf(scene));
  EXPECT_EQ(p.kind, ShadowKind::Orthographic);
  EXPECT_EQ(p.layers, 1);
  EXPECT_EQ(p.size, kDefaultShadowMapSize);
  // Every corner of the bounds lands inside the map, in front of its far plane.
  const WorldBounds b = worldBoundsOf(scene);
  for (int corner = 0; corner < 8; ++corner) {
    const vec3 c((corner & 1) ? b.hi.x : b.lo.x, (corner & 2) ? b.hi.y : b.lo.y, (corner & 4) ? b.hi.z : b.lo.z);
    const vec3 w = windowOf(p.clipFromWorld[0], c);
    EXPECT_GT(w.x, 0.0f);
    EXPECT_LT(w.x, 1.0f);
    EXPECT_GT(w.y, 0.0f);
    EXPECT_LT(w.y, 1.0f);
    EXPECT_GT(w.z, 0.0f);
    EXPECT_LT(w.z, 1.0f);
  }
  // Nearer the light is smaller depth; moving across the light's direction keeps the depth.
  const vec3 top = windowOf(p.clipFromWorld[0], vec3(0.0f, 1.0f, 0.0f));
  const vec3 below = windowOf(p.clipFromWorld[0], vec3(0.0f, 1.0f, 0.0f) + light.directionWorld * 0.5f);
  EXPECT_LT(top.z, below.z);
  const vec3 across = glm::normalize(glm::cross(light.directionWorld, vec3(1.0f, 0.0f, 0.0f)));
  EXPECT_NEAR(windowOf(p.clipFromWorld[0], vec3(0.0f, 1.0f, 0.0f) + across * 0.5f).z, top.z, 1e-6f);
  // The map's half-width in world units: the scene's bounding radius, or an explicit extent
  // (the length of clip x's row is 1 / half-width).
  const auto rowLength = [](const mat4& m) { return glm::length(vec3(m[0][0], m[1][0], m[2][0])); };
  EXPECT_NEAR(rowLength(p.clipFromWorld[0]), 1.0f / (0.5f * glm::length(b.hi - b.lo)), 1e-5f);
  light.shadow->extent = 1.0f;
  EXPECT_NEAR(rowLength(shadowProjectionFor(light, b).clipFromWorld[0]), 1.0f, 1e-5f);
}

TEST(ShadowMap, CubeFacesAgreeWithTheFaceRendersAndTheDepthFormula) {
  const Scene scene = floorAndBox();
  Light light;
  light.posWorld = vec3(0.3f, 2.0f, 0.1f);
  light.shadow = ShadowDesc{};
  const ShadowProjection p = shadowProjectionFor(light, worldBoundsOf(scene));
  EXPECT_EQ(p.kind, ShadowKind::Cube);
  EXPECT_EQ(p.layers, kCubeShadowLayers);
  EXPECT_GT(p.far, 0.0f);
  EXPECT_FLOAT_EQ(p.near, p.far * kCubeShadowNearRatio);
  // A point along each face's axis, and off it: the face the lookup picks is the face whose
  // render puts it inside the frame, at the depth the formula gives.
  const vec3 offsets[] = {{1.0f, 0.2f, -0.3f}, {-1.0f, 0.1f, 0.4f}, {0.3f, 1.0f, -0.2f},
                          {-0.2f, -1.0f, 0.25f}, {0.1f, -0.4f, 1.0f}, {0.35f, 0.3f, -1.0f}};
  for (int face = 0; face < kCubeShadowLayers; ++face) {
    const vec3 d = offsets[face] * 1.5f;
    ASSERT_EQ(cubeFaceOf(d), face) << "offset " << face;
    const vec3 w = windowOf(p.clipFromWorld[static_cast<std::size_t>(face)], light.posWorld + d);
    EXPECT_GT(w.x, 0.0f);
    EXPECT_LT(w.x, 1.0f);
    EXPECT_GT(w.y, 0.0f);
    EXPECT_LT(w.y, 1.0f);
    const float m = std::max(std::fabs(d.x), std::max(std::fabs(d.y), std::fabs(d.z)));
    EXPECT_NEAR(cubeShadowDepth(p, m), w.z, 1e-6f) << "face " << face;
  }
  // Ties go to z, then y (llvmpipe's rule).
  EXPECT_EQ(cubeFaceOf(vec3(1.0f, 1.0f, 1.0f)), 4);
  EXPECT_EQ(cubeFaceOf(vec3(-1.0f, 1.0f, 0.0f)), 2);
}

TEST(ShadowMap, SpotMapLooksAlongTheConeWithItsFieldOfView) {
  const Scene scene = floorAndBox();
  Light light;
  light.posWorld = vec3(0.3f, 2.0f, 0.1f);
  light.spot = SpotCone{glm::normalize(vec3(0.2f, -1.0f, 0.1f)), 10.0f, 25.0f};
  light.shadow = ShadowDesc{};
  const ShadowProjection p = shadowProjectionFor(light, worldBoundsOf(scene));
  EXPECT_EQ(p.kind, ShadowKind::Perspective);
  EXPECT_EQ(p.layers, 1);
  EXPECT_FLOAT_EQ(p.near, p.far * kCubeShadowNearRatio);
  // On the axis: the map's centre, at the cube-face depth of its distance.
  const vec3 onAxis = windowOf(p.clipFromWorld[0], light.posWorld + light.spot->directionWorld * 1.5f);
  EXPECT_NEAR(onAxis.x, 0.5f, 1e-5f);
  EXPECT_NEAR(onAxis.y, 0.5f, 1e-5f);
  EXPECT_NEAR(onAxis.z, cubeShadowDepth(p, 1.5f), 1e-6f);
  // 25 degrees off the axis (the outer half-angle) lies on the map's edge circle: half the side
  // from the centre, in any direction across the axis.
  const vec3 axis = light.spot->directionWorld;
  const vec3 across = glm::normalize(glm::cross(axis, vec3(1.0f, 0.0f, 0.0f)));
  const float tanOuter = std::tan(25.0f * 3.14159265f / 180.0f);
  const vec3 edge = windowOf(p.clipFromWorld[0], light.posWorld + (axis + across * tanOuter) * 1.5f);
  EXPECT_NEAR(glm::length(vec2(edge.x, edge.y) - vec2(0.5f)), 0.5f, 1e-4f);
  EXPECT_NEAR(p.texelWorld, 2.0f * tanOuter / static_cast<float>(p.size), 1e-7f);
  EXPECT_EQ(describeShadow(p).rfind("perspective 2048^2", 0), 0u) << describeShadow(p);
}

TEST(ShadowMap, SceneFileReadsShadowKeys) {
  const Scene scene = parseScene(R"({"lights": [
      {"type": "directional", "direction": [0, -1, 0], "shadow": {"size": 1024, "bias": [0.001, 0.003], "pcf": 5, "extent": 3}},
      {"position": [0, 3, 0], "shadow": true},
      {"position": [1, 3, 0], "shadow": false}], "nodes": []})",
                                 "inline.json", ".");
  ASSERT_EQ(scene.lights.size(), 3u);
  ASSERT_TRUE(scene.lights[0].shadow);
  EXPECT_EQ(scene.lights[0].shadow->size, 1024);
  EXPECT_EQ(scene.lights[0].shadow->bias, vec2(0.001f, 0.003f));
  EXPECT_EQ(scene.lights[0].shadow->pcf, 5);
  EXPECT_EQ(scene.lights[0].shadow->extent, 3.0f);
  ASSERT_TRUE(scene.lights[1].shadow);
  EXPECT_EQ(scene.lights[1].shadow->size, kDefaultCubeShadowMapSize);  // a cube's default
  EXPECT_FALSE(scene.lights[2].shadow);
  EXPECT_TRUE(sceneHasShadows(scene));
}

std::string shadowError(const std::string& light) {
  try {
    parseScene(R"({"nodes": [], "lights": [)" + light + "]}", "inline.json", ".");
  } catch (const std::exception& e) {
    return e.what();
  }
  return "";
}

TEST(ShadowMap, SceneFileReadsSpotLights) {
  const Scene scene = parseScene(R"({"lights": [
      {"position": [0, 3, 0], "spot": {"direction": [0, -2, 0], "inner_deg": 10, "outer_deg": 40}, "shadow": true},
      {"position": [0, 3, 0], "spot": {"outer_deg": 12}},
      {"position": [0, 3, 0], "spot": {}, "shadow": {"size": 4096}}], "nodes": []})",
                                 "inline.json", ".");
  ASSERT_EQ(scene.lights.size(), 3u);
  ASSERT_TRUE(scene.lights[0].spot);
  EXPECT_EQ(scene.lights[0].spot->directionWorld, vec3(0.0f, -1.0f, 0.0f));  // normalised
  EXPECT_EQ(scene.lights[0].spot->innerDeg, 10.0f);
  EXPECT_EQ(scene.lights[0].spot->outerDeg, 40.0f);
  EXPECT_EQ(scene.lights[0].shadow->size, kDefaultShadowMapSize);  // one map, not a cube's six
  EXPECT_EQ(scene.lights[1].spot->innerDeg, 12.0f);  // the default inner clamped to the outer
  EXPECT_EQ(scene.lights[2].spot->outerDeg, SpotCone{}.outerDeg);
  EXPECT_EQ(scene.lights[2].shadow->size, 4096);  // a spot map may be as large as a directional one
  const vec2 c = spotCosines(*scene.lights[0].spot);
  EXPECT_FLOAT_EQ(c.x, std::cos(40.0f * 3.14159265f / 180.0f));
  EXPECT_FLOAT_EQ(c.y, std::cos(10.0f * 3.14159265f / 180.0f));
  const SpotUniform u = spotUniformOf(scene.lights[0]);
  EXPECT_EQ(u.axis, vec4(0.0f, -1.0f, 0.0f, 1.0f));
  EXPECT_FLOAT_EQ(u.cone.y, c.y - c.x);
  EXPECT_EQ(spotUniformOf(Light{}).axis.w, 0.0f);  // not a spot: the cone is never read
  // A spot on a directional light is read and ignored, with a warning.
  const Scene warned = parseScene(R"({"lights": [{"type": "directional", "spot": {}}], "nodes": []})", "inline.json", ".");
  EXPECT_FALSE(warned.lights[0].spot);
  ASSERT_EQ(warned.warnings.size(), 1u);
  EXPECT_NE(warned.warnings[0].find("lights[0].spot: ignored"), std::string::npos) << warned.warnings[0];
}

TEST(ShadowMap, SceneFileRefusesBadSpots) {
  EXPECT_NE(shadowError(R"({"spot": {"outer_deg": 90}})").find("lights[0].spot.outer_deg: expected a half-angle from 0.1"),
            std::string::npos)
      << shadowError(R"({"spot": {"outer_deg": 90}})");
  EXPECT_NE(shadowError(R"({"spot": {"outer_deg": 0}})").find("lights[0].spot.outer_deg"), std::string::npos);
  EXPECT_NE(shadowError(R"({"spot": {"outer_deg": 0.01}})").find("lights[0].spot.outer_deg"), std::string::npos);
  EXPECT_NE(shadowError(R"({"spot": {"inner_deg": 35, "outer_deg": 30}})")
                .find("lights[0].spot.inner_deg: expected a half-angle from 0 to outer_deg (30.0), got 35"),
            std::string::npos)
      << shadowError(R"({"spot": {"inner_deg": 35, "outer_deg": 30}})");
  EXPECT_NE(shadowError(R"({"spot": {"direction": [0, 0, 0]}})").find("lights[0].spot.direction: expected a non-zero"),
            std::string::npos);
  EXPECT_NE(shadowError(R"({"spot": {"angle": 30}})").find("lights[0].spot.angle"), std::string::npos);
  EXPECT_NE(shadowError(R"({"spot": 30})").find("lights[0].spot: expected an object"), std::string::npos);
}

TEST(ShadowMap, SceneFileRefusesBadShadows) {
  EXPECT_NE(shadowError(R"({"position": [0, 3, 0], "shadow": {"size": 2048}})")
                .find("lights[0].shadow.size: expected at most 1024 for a point light's cube map"),
            std::string::npos)
      << "a cube map over 1024 texels must be refused, saying why";
  EXPECT_NE(shadowError(R"({"type": "directional", "shadow": {"size": 8192}})")
                .find("lights[0].shadow.size: expected an integer in [16, 4096]"),
            std::string::npos);
  EXPECT_NE(shadowError(R"({"type": "directional", "shadow": {"pcf": 2}})").find("expected 1, 3 or 5"),
            std::string::npos);
  EXPECT_NE(shadowError(R"({"type": "directional", "shadow": {"bias": [-1, 0]}})").find("lights[0].shadow.bias"),
            std::string::npos);
  EXPECT_NE(shadowError(R"({"type": "directional", "shadow": {"sise": 8}})").find("lights[0].shadow.sise"),
            std::string::npos);
  EXPECT_NE(shadowError(R"({"type": "directional", "shadow": 3})").find("expected true, false or an object"),
            std::string::npos);
  const std::string five = R"({"type": "directional", "shadow": true})";
  EXPECT_NE(shadowError(five + "," + five + "," + five + "," + five + "," + five).find("at most 4 lights"),
            std::string::npos);
}

}  // namespace
}  // namespace twr
