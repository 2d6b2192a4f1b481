// Node transforms: rotation order (X, then Y, then Z), T * R * S, parent * child, and the
// normal transform under non-uniform scale.
#include "scene/scene.h"

#include <gtest/gtest.h>
#include <glm/gtc/matrix_inverse.hpp>

#include <cmath>

namespace twr {
namespace {

constexpr float kTolerance = 1e-5f;
constexpr float kRadiansToDegrees = 180.0f / 3.14159265358979323846f;

void expectVecNear(vec3 actual, vec3 expected) {
  EXPECT_NEAR(actual.x, expected.x, kTolerance) << "x";
  EXPECT_NEAR(actual.y, expected.y, kTolerance) << "y";
  EXPECT_NEAR(actual.z, expected.z, kTolerance) << "z";
}

vec3 transformPoint(const mat4& m, vec3 p) { return vec3(m * vec4(p, 1.0f)); }
vec3 transformDirection(const mat4& m, vec3 d) { return vec3(m * vec4(d, 0.0f)); }

TEST(NodeTransform, SingleAxisRotationsAreRightHanded) {
  // Right-handed 90 degrees: about X, Y -> Z; about Y, Z -> X; about Z, X -> Y.
  expectVecNear(transformDirection(localFromNodeTrs(vec3(0), {90, 0, 0}, vec3(1)), {0, 1, 0}), {0, 0, 1});
  expectVecNear(transformDirection(localFromNodeTrs(vec3(0), {0, 90, 0}, vec3(1)), {0, 0, 1}), {1, 0, 0});
  expectVecNear(transformDirection(localFromNodeTrs(vec3(0), {0, 0, 90}, vec3(1)), {1, 0, 0}), {0, 1, 0});
}

TEST(NodeTransform, RotatesAboutXThenYThenZ) {
  // (1,0,0): X(90) leaves it, Y(90) takes X -> -Z, Z(90) leaves -Z: result (0,0,-1).
  // The reverse order (Z, Y, X) would give X -> Y -> Y -> +Z, so the sign tells them apart.
  const mat4 m = localFromNodeTrs(vec3(0), {90, 90, 90}, vec3(1));
  expectVecNear(transformDirection(m, {1, 0, 0}), {0, 0, -1});
  // (0,1,0): X(90) -> (0,0,1), Y(90) -> (1,0,0), Z(90) -> (0,1,0).
  expectVecNear(transformDirection(m, {0, 1, 0}), {0, 1, 0});
  // Two axes only: (0,1,0) under X(90) then Y(90) is (1,0,0); Y first would give (0,0,1).
  expectVecNear(transformDirection(localFromNodeTrs(vec3(0), {90, 90, 0}, vec3(1)), {0, 1, 0}), {1, 0, 0});
}

TEST(NodeTransform, ScalesThenRotatesThenTranslates) {
  // (1,0,0) scaled by (2,1,1) -> (2,0,0), Y(90) -> (0,0,-2), + (10,0,0) -> (10,0,-2).
  const mat4 m = localFromNodeTrs({10, 0, 0}, {0, 90, 0}, {2, 1, 1});
  expectVecNear(transformPoint(m, {1, 0, 0}), {10, 0, -2});
}

TEST(NodeTransform, WorldIsParentTimesChild) {
  Scene scene;
  scene.meshes.push_back(Mesh{});
  Node parent;
  parent.name = "parent";
  parent.translate = {1, 0, 0};
  parent.rotateDeg = {0, 90, 0};
  parent.meshIndex = 0;
  Node child;
  child.name = "child";
  child.translate = {0, 0, 1};
  child.meshIndex = 0;
  parent.children.push_back(child);
  scene.nodes.push_back(parent);

  const std::vector<DrawItem> items = flattenScene(scene);
  ASSERT_EQ(items.size(), 2u);
  EXPECT_EQ(items[0].nodeName, "parent");
  EXPECT_EQ(items[1].nodeName, "child");
  // The child's origin: (0,0,1) in the parent, Y(90) -> (1,0,0), + (1,0,0) = (2,0,0).
  // child * parent would give (1,0,1) instead.
  expectVecNear(transformPoint(items[1].worldFromModel, vec3(0)), {2, 0, 0});
  // The child inherits the parent's rotation: its +Z axis points along world +X.
  expectVecNear(transformDirection(items[1].worldFromModel, {0, 0, 1}), {1, 0, 0});
}

TEST(NormalTransform, NonUniformScaleNeedsTheInverseTranspose) {
  // diag(4,1,1) applied to the surface x + y = c: its normal (1,1,0)/sqrt2 must become
  // inverse-transpose * n = (1/4, 1, 0), normalised: atan(1 / 0.25) = 75.96 degrees from +X.
  const mat4 worldFromModel = localFromNodeTrs(vec3(0), vec3(0), {4, 1, 1});
  const vec3 nModel = glm::normalize(vec3(1, 1, 0));
  const vec3 nWorld = glm::normalize(glm::inverseTranspose(mat3(worldFromModel)) * nModel);
  const float angleFromX = std::acos(glm::dot(nWorld, vec3(1, 0, 0))) * kRadiansToDegrees;
  const float expectedAngle = std::atan2(1.0f, 0.25f) * kRadiansToDegrees;
  EXPECT_NEAR(expectedAngle, 75.96f, 0.01f);
  EXPECT_NEAR(angleFromX, expectedAngle, 0.01f);

  // It stays perpendicular to the transformed surface: tangent (1,-1,0) -> (4,-1,0).
  const vec3 tWorld = mat3(worldFromModel) * vec3(1, -1, 0);
  EXPECT_NEAR(glm::dot(nWorld, glm::normalize(tWorld)), 0.0f, kTolerance);

  // The model matrix itself would give (4,1,0): 14.04 degrees from +X, not perpendicular.
  const vec3 wrongWorld = glm::normalize(mat3(worldFromModel) * nModel);
  EXPECT_NEAR(std::acos(wrongWorld.x) * kRadiansToDegrees, std::atan2(1.0f, 4.0f) * kRadiansToDegrees, 0.01f);
  EXPECT_GT(std::fabs(glm::dot(wrongWorld, glm::normalize(tWorld))), 0.4f);
}

}  // namespace
}  // namespace twr
