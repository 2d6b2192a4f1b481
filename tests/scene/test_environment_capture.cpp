// The environment captured from the scene (scene/environment_capture.h), with a renderer made
// here that paints each pixel with its own view direction: the captured cube must then hold,
// at every texel, the direction GL's face table gives that texel (face cameras and the row
// flip right for all six faces), and the scene each face was drawn from must lack the node and
// the environment.
#include "scene/environment_capture.h"
#include "scene/environment_light.h"
#include "scene/errors.h"
#include "scene/primitives.h"
#include "scene/scene_file.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

namespace twr {
namespace {

// Colour level of a direction component d in [-1, 1]: 127.5 (d + 1), rounded.
std::uint8_t levelOf(double d) { return static_cast<std::uint8_t>(std::lround(127.5 * (d + 1.0))); }

// Paints pixel (x, y) with its ray's world direction; remembers what it was asked to draw.
class DirectionRenderer final : public Renderer {
 public:
  std::string name() const override { return "directions"; }
  RenderOutput render(const Scene& scene, const RenderSettings& settings, int width, int height) override {
    scenes.push_back(scene);
    views.push_back(settings.view);
    const glm::dmat3 worldFromView = glm::transpose(glm::dmat3(glm::dmat4(viewFromWorld(scene.camera))));
    const double tanHalf = std::tan(0.5 * glm::radians(static_cast<double>(scene.camera.fovDeg)));
    const double aspect = static_cast<double>(width) / height;
    RenderOutput out;
    out.width = width;
    out.height = height;
    out.rgba.resize(static_cast<std::size_t>(width) * height * 4);
    out.depth.assign(static_cast<std::size_t>(width) * height, 1.0f);
    out.triangleId.assign(static_cast<std::size_t>(width) * height, kNoTriangle);
    for (int y = 0; y < height; ++y) {
      for (int x = 0; x < width; ++x) {
        const double ndcX = 2.0 * (x + 0.5) / width - 1.0, ndcY = 1.0 - 2.0 * (y + 0.5) / height;  // row 0 on top
        const glm::dvec3 d = glm::normalize(worldFromView * glm::dvec3(ndcX * tanHalf * aspect, ndcY * tanHalf, -1.0));
        std::uint8_t* p = &out.rgba[(static_cast<std::size_t>(y) * width + x) * 4];
        p[0] = levelOf(d.x);
        p[1] = levelOf(d.y);
        p[2] = levelOf(d.z);
        p[3] = 255;
      }
    }
    return out;
  }
  std::vector<Scene> scenes;
  std::vector<View> views;
};

Scene probeScene(int size) {
  Scene scene;
  scene.meshes.push_back(makeSphere(0.5f, 8, 16));
  scene.meshes.push_back(makeCube(1.0f));
  Node probe;
  probe.name = "probe";
  probe.meshIndex = 0;
  probe.translate = vec3(1.0f, 2.0f, 3.0f);
  Node child;
  child.name = "probe's child";
  child.meshIndex = 1;
  probe.children.push_back(child);
  Node other;
  other.name = "box";
  other.meshIndex = 1;
  other.translate = vec3(0.0f, 0.0f, -4.0f);
  scene.nodes = {other, probe};
  Environment env;
  env.capture = EnvironmentCapture{"probe", size};
  scene.environment = env;
  return scene;
}

TEST(EnvironmentCapture, EveryTexelHoldsTheDirectionGlsFaceTableGivesIt) {
  constexpr int kSize = 16;
  Scene scene = probeScene(kSize);
  ASSERT_TRUE(needsEnvironmentCapture(scene));
  DirectionRenderer renderer;
  scene.settings.view = View::Normal;  // the faces are drawn shaded whatever the frame's view
  const CapturedEnvironment captured = captureEnvironment(scene, scene.settings, renderer);
  ASSERT_EQ(renderer.scenes.size(), 6u);
  const CubeMap& cube = *captured.scene.environment->cube;
  ASSERT_EQ(cube.size(), kSize);
  ASSERT_EQ(cube.levelCount(), 5);  // 16, 8, 4, 2, 1
  int worst = 0;
  for (int f = 0; f < kCubeFaces; ++f) {
    EXPECT_EQ(renderer.views[static_cast<std::size_t>(f)], View::Shaded);
    for (int y = 0; y < kSize; ++y) {
      for (int x = 0; x < kSize; ++x) {
        const glm::dvec3 d = glm::normalize(directionFromCubeCoord(f, (x + 0.5) / kSize, (y + 0.5) / kSize));
        const vec3 texel = cube.levels[0].texel(f, x, y);
        for (int c = 0; c < 3; ++c) {
          const int got = static_cast<int>(std::lround(texel[c] * 255.0f));
          worst = std::max(worst, std::abs(got - levelOf(d[c])));
        }
      }
    }
  }
  // The renderer above and the table computed in double: equal to one level of rounding.
  EXPECT_LE(worst, 1) << "a face camera or the row flip disagrees with GL's face table";
  EXPECT_FALSE(needsEnvironmentCapture(captured.scene));
  ASSERT_TRUE(captured.faces);
  EXPECT_EQ(captured.faces->faces[2].width, kSize);
  EXPECT_EQ(captured.faces->centreWorld, vec3(1.0f, 2.0f, 3.0f));
}

TEST(EnvironmentCapture, FacesAreDrawnWithoutTheNodeItsChildrenAndTheEnvironment) {
  Scene scene = probeScene(4);
  scene.camera.near = 0.25f;
  scene.camera.far = 40.0f;
  DirectionRenderer renderer;
  captureEnvironment(scene, scene.settings, renderer);
  ASSERT_EQ(renderer.scenes.size(), 6u);
  for (const Scene& drawn : renderer.scenes) {
    EXPECT_FALSE(drawn.environment.has_value());
    ASSERT_EQ(drawn.nodes.size(), 1u);
    EXPECT_EQ(drawn.nodes[0].name, "box");
    EXPECT_EQ(drawn.camera.position, vec3(1.0f, 2.0f, 3.0f));
    EXPECT_EQ(drawn.camera.fovDeg, 90.0f);
    EXPECT_EQ(drawn.camera.near, 0.25f);  // the scene camera's range: the scene's own scale
    EXPECT_EQ(drawn.camera.far, 40.0f);
  }
}

TEST(EnvironmentCapture, CentreIsTheMiddleOfTheMeshBoundsInWorldSpace) {
  Scene scene = probeScene(4);
  // A mesh modelled off its origin: the probe stands at its middle, not at the node's origin.
  for (Vertex& v : scene.meshes[0].vertices) v.posModel += vec3(2.0f, 0.0f, 0.0f);
  scene.nodes[1].scale = vec3(2.0f);
  const vec3 centre = captureCentre(scene, "probe");
  EXPECT_NEAR(centre.x, 1.0f + 4.0f, 1e-5f);
  EXPECT_NEAR(centre.y, 2.0f, 1e-5f);
  EXPECT_NEAR(centre.z, 3.0f, 1e-5f);
  // A node without a mesh: its origin.
  EXPECT_EQ(captureCentre(scene, "box"), vec3(0.0f, 0.0f, -4.0f));
  try {
    captureCentre(scene, "nobody");
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("no node is named \"nobody\""), std::string::npos) << e.what();
  }
}

TEST(EnvironmentCapture, WhatTheMaterialsReadIsBuiltFromTheCapture) {
  Scene scene = probeScene(8);
  scene.environment->parameterization = EnvironmentParameterization::Sphere;
  scene.environment->size = 16;
  Material m;
  m.reflectivity = 0.5f;
  m.environmentSpecular = EnvironmentSpecular::Prefiltered;
  m.environmentDiffuse = EnvironmentDiffuse::Sh9;
  scene.materials.push_back(m);
  DirectionRenderer renderer;
  const CapturedEnvironment captured = captureEnvironment(scene, scene.settings, renderer);
  const Environment& env = *captured.scene.environment;
  ASSERT_TRUE(env.layers);
  EXPECT_EQ(env.layers->size(), 16);
  EXPECT_TRUE(env.specular);
  EXPECT_TRUE(env.specularLayers);
  EXPECT_TRUE(env.sh9);
  EXPECT_FALSE(env.irradiance);  // no material asks for the irradiance map
  // The input scene is left as it was: every frame captures anew.
  EXPECT_TRUE(needsEnvironmentCapture(scene));
}

TEST(EnvironmentCapture, FlipRowsReversesEveryBufferAndTwiceIsIdentity) {
  RenderOutput out;
  out.width = 2;
  out.height = 3;
  for (int i = 0; i < 6; ++i) {
    for (int c = 0; c < 4; ++c) out.rgba.push_back(static_cast<std::uint8_t>(10 * i + c));
    out.depth.push_back(0.1f * static_cast<float>(i));
    out.triangleId.push_back(static_cast<std::uint32_t>(i));
  }
  const RenderOutput flipped = flipRows(out);
  EXPECT_EQ(flipped.triangleId, (std::vector<std::uint32_t>{4, 5, 2, 3, 0, 1}));
  EXPECT_EQ(flipped.rgba[0], 40);
  EXPECT_FLOAT_EQ(flipped.depth[5], 0.1f);
  EXPECT_TRUE(flipped.lineMask.empty());
  const RenderOutput back = flipRows(flipped);
  EXPECT_EQ(back.rgba, out.rgba);
  EXPECT_EQ(back.triangleId, out.triangleId);
}

TEST(EnvironmentCapture, SceneFileNamesTheNodeAndSizeAndLeavesTheCubeToTheRenderer) {
  const Scene scene = parseScene(R"({"environment": {"capture": {"node": "ball", "size": 32}},
      "materials": {"m": {"reflectivity": 1}},
      "nodes": [{"name": "ball", "material": "m", "mesh": {"type": "sphere"}}]})",
                                 "capture.json", ".");
  ASSERT_TRUE(scene.environment && scene.environment->capture);
  EXPECT_EQ(scene.environment->capture->node, "ball");
  EXPECT_EQ(scene.environment->capture->size, 32);
  EXPECT_FALSE(scene.environment->cube);
  EXPECT_TRUE(needsEnvironmentCapture(scene));
  EXPECT_TRUE(scene.warnings.empty());
}

}  // namespace
}  // namespace twr
