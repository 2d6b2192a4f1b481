// What the camera's projection can resolve in float (issue 22, classes 7-9): refused when no
// faithful picture can be drawn, warned about when the picture is OpenGL's but not what the
// scene describes, silent for ordinary scenes.
#include "scene/projection_checks.h"

#include "scene/primitives.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace twr {
namespace {

// A unit cube at `centre` scaled by `scale`, seen from `distance` away along +z.
Scene cubeScene(float scale = 1.0f, vec3 centre = vec3(0.0f), float distance = 4.0f) {
  Scene scene;
  scene.meshes.push_back(makeCube(1.0f));
  scene.meshDescs.emplace_back();
  Node node;
  node.name = "cube";
  node.meshIndex = 0;
  node.translate = centre;
  node.scale = vec3(scale);
  scene.nodes.push_back(node);
  scene.camera.target = centre;
  scene.camera.position = centre + vec3(0.3f, 1.0f, distance) * scale;
  scene.camera.fovDeg = 50.0f;
  scene.camera.near = 0.1f * scale;
  scene.camera.far = 100.0f * scale;
  Light light;
  light.posWorld = centre + vec3(2.0f, 3.0f, 4.0f) * scale;
  scene.lights.push_back(light);
  return scene;
}

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

bool anyContains(const std::vector<std::string>& lines, const std::string& part) {
  for (const std::string& line : lines) {
    if (contains(line, part)) return true;
  }
  return false;
}

TEST(ProjectionChecks, OrdinaryScenesPassSilently) {
  for (const float scale : {1e-3f, 1.0f, 1e3f, 1e6f}) {
    const Scene scene = cubeScene(scale);
    for (const int height : {1, 48, 480, 16384}) {
      EXPECT_EQ(projectionProblem(scene, 640, height), "") << "scale " << scale << ", height " << height;
      EXPECT_TRUE(projectionWarnings(scene, 640, height).empty()) << "scale " << scale << ", height " << height;
    }
  }
}

// The whole view narrower than one float step of the coordinates: refused, naming fov_deg and
// the smallest usable value, at any image height.
TEST(ProjectionChecks, FieldOfViewBelowFloatResolutionIsRefused) {
  for (const float fov : {1e-30f, 1e-20f, 1e-12f, 1e-8f}) {
    for (const int height : {1, 100, 480, 4096}) {
      Scene scene = cubeScene();
      scene.camera.fovDeg = fov;
      const std::string problem = projectionProblem(scene, 640, height);
      EXPECT_TRUE(contains(problem, "camera: fov_deg")) << fov << " " << height << ": " << problem;
      EXPECT_TRUE(contains(problem, "Use fov_deg >=")) << problem;
    }
  }
}

// A camera far from the origin looking at something near it: the same limit, reached by the
// coordinates' magnitude instead of the angle.
TEST(ProjectionChecks, CameraFarFromOriginLookingCloseIsRefused) {
  Scene scene = cubeScene(1.0f, vec3(1e9f, 0.0f, 0.0f), 4.0f);
  EXPECT_TRUE(contains(projectionProblem(scene, 640, 480), "move the camera and target nearer the origin"));
}

// Between one float step per pixel and one per image: drawn (both renderers round alike), with
// a warning saying how coarse.
TEST(ProjectionChecks, CoarseFieldOfViewWarns) {
  Scene scene = cubeScene();
  scene.camera.fovDeg = 1e-4f;
  EXPECT_EQ(projectionProblem(scene, 640, 480), "");
  EXPECT_TRUE(anyContains(projectionWarnings(scene, 640, 480), "float positions resolve only to about"));
  scene.camera.fovDeg = 1.0f;
  EXPECT_TRUE(projectionWarnings(scene, 640, 480).empty());
}

TEST(ProjectionChecks, FloatStepInPixelsScalesWithFieldOfViewAndHeight) {
  Scene scene = cubeScene();
  const double wide = floatStepInPixels(scene.camera, 480);
  scene.camera.fovDeg = 5.0f;
  const double narrow = floatStepInPixels(scene.camera, 480);
  EXPECT_GT(narrow, 9.0 * wide);  // tan(25 deg) / tan(2.5 deg) is about 10.7
  EXPECT_NEAR(floatStepInPixels(scene.camera, 960), 2.0 * narrow, 1e-12 * narrow);
}

// A far plane near float's range: the depth terms are formed in double, so the projection is
// finite and the scene draws; only terms that do not fit in float are refused.
TEST(ProjectionChecks, FarPlaneNearFloatMaxIsDrawable) {
  Scene scene = cubeScene();
  scene.camera.near = 1e-3f;
  scene.camera.far = 3e38f;
  EXPECT_EQ(projectionProblem(scene, 640, 480), "");
  const mat4 m = clipFromView(scene.camera, 4.0f / 3.0f);
  EXPECT_TRUE(std::isfinite(m[3][2]));
  EXPECT_NEAR(m[3][2], -2e-3f, 1e-9f);
  scene.camera.near = 2e38f;
  const std::string problem = projectionProblem(scene, 640, 480);
  EXPECT_TRUE(contains(problem, "camera: near 2e+38 and far 3e+38")) << problem;
}

// A scene in units of 1e20 draws like the unit one (its camera, normalised in double, no
// longer overflows), but its lighting squares distances past float's range: a warning.
TEST(ProjectionChecks, HugeSceneDrawsWithAShadingWarning) {
  const Scene scene = cubeScene(1e20f);
  EXPECT_EQ(validateCamera(scene.camera), "");
  EXPECT_EQ(projectionProblem(scene, 640, 480), "");
  EXPECT_TRUE(anyContains(projectionWarnings(scene, 640, 480), "lighting: geometry lies"));
  const mat4 view = viewFromWorld(scene.camera);
  for (int c = 0; c < 4; ++c) {
    for (int r = 0; r < 4; ++r) EXPECT_TRUE(std::isfinite(view[c][r]));
  }
}

// A node whose transform overflows float has no vertex positions at all: refused, naming the
// node. One whose vertices reach past float's range in clip space is drawn (triangles through
// them are dropped, as in OpenGL), with a warning naming it.
TEST(ProjectionChecks, NodesBeyondFloatRange) {
  Scene scene = cubeScene();
  scene.nodes[0].scale = vec3(1e38f);
  EXPECT_EQ(projectionProblem(scene, 640, 480), "");
  EXPECT_TRUE(anyContains(projectionWarnings(scene, 640, 480), "node 'cube': its vertices reach"));
  scene.nodes[0].scale = vec3(1e30f);
  scene.nodes[0].children.push_back(scene.nodes[0]);
  scene.nodes[0].children[0].name = "child";
  scene.nodes[0].children[0].children.clear();
  const std::string problem = projectionProblem(scene, 640, 480);
  EXPECT_TRUE(contains(problem, "node 'child': its transform")) << problem;
}

// Vertices that are not finite (only scenes built in code have them; the loaders refuse them)
// are dropped by both renderers, and do not count.
TEST(ProjectionChecks, NonFiniteVerticesAreIgnored) {
  Scene scene = cubeScene();
  scene.meshes[0].vertices[0].posModel.x = std::nanf("");
  scene.meshes[0].vertices[1].posModel.y = INFINITY;
  EXPECT_EQ(projectionProblem(scene, 640, 480), "");
  EXPECT_TRUE(projectionWarnings(scene, 640, 480).empty());
}

// near so small that the geometry's window depth rounds to the cleared 1.0: drawn as OpenGL
// draws it (nothing), with a warning naming the nodes and a near that works.
TEST(ProjectionChecks, DepthRoundingToClearValueWarns) {
  Scene scene = cubeScene();
  scene.camera.near = 1e-8f;
  EXPECT_EQ(projectionProblem(scene, 640, 480), "");
  const std::vector<std::string> warnings = projectionWarnings(scene, 640, 480);
  EXPECT_TRUE(anyContains(warnings, "every vertex in view ('cube' 100 %)")) << (warnings.empty() ? "" : warnings[0]);
  EXPECT_TRUE(anyContains(warnings, "nothing is drawn"));
  EXPECT_TRUE(anyContains(warnings, "raise near to about"));
}

// Depth steps wider than 1 % of the distance: surfaces fight; a warning, not a refusal.
TEST(ProjectionChecks, CoarseDepthWarns) {
  Scene scene = cubeScene();
  scene.camera.near = 2e-5f;
  EXPECT_EQ(projectionProblem(scene, 640, 480), "");
  const std::vector<std::string> warnings = projectionWarnings(scene, 640, 480);
  EXPECT_TRUE(anyContains(warnings, "one step of float depth spans")) << warnings.size();
  EXPECT_FALSE(anyContains(warnings, "window depth 1.0"));
}

}  // namespace
}  // namespace twr
