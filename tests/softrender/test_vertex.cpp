// Vertex stage: hand-computed positions, normals, tangents, bitangents and varyings.
#include "softrender/vertex.h"

#include <gtest/gtest.h>
#include <glm/gtc/matrix_transform.hpp>

#include <cmath>

namespace twr {
namespace {

constexpr float kEps = 1e-6f;

void expectNear(vec3 a, vec3 b, float eps = kEps) {
  EXPECT_NEAR(a.x, b.x, eps);
  EXPECT_NEAR(a.y, b.y, eps);
  EXPECT_NEAR(a.z, b.z, eps);
}

TEST(Vertex, TransformPointAddsColumnsFromTheLeft) {
  mat4 m(1.0f);
  m[0] = vec4(2, 0, 0, 0);
  m[1] = vec4(0, 3, 0, 0);
  m[2] = vec4(0, 0, 4, 0);
  m[3] = vec4(1, 2, 3, 1);
  const vec4 p = transformPoint(m, vec3(1, 1, 1));
  EXPECT_EQ(p, vec4(3, 5, 7, 1));
  // ((c0 x + c1 y) + c2 z) + c3 in float: 1e8 + 1 - 1e8 loses the 1 when added left to right.
  mat4 n(0.0f);
  n[0] = vec4(1e8f, 0, 0, 0);
  n[1] = vec4(1.0f, 0, 0, 0);
  n[2] = vec4(-1e8f, 0, 0, 0);
  EXPECT_EQ(transformPoint(n, vec3(1, 1, 1)).x, 0.0f);
}

TEST(Vertex, PositionsGoThroughWorldToClip) {
  VertexUniforms u;
  u.worldFromModel = glm::translate(mat4(1.0f), vec3(1, 2, 3));
  u.clipFromWorld = glm::scale(mat4(1.0f), vec3(2, 2, 2));
  Vertex v;
  v.posModel = vec3(1, 0, 0);
  const ClipVertex out = runVertexStage(v, u);
  expectNear(out.posWorld, vec3(2, 2, 3));
  EXPECT_EQ(out.posClip, vec4(4, 4, 6, 1));
  EXPECT_FALSE(out.fromClipper);
}

TEST(Vertex, NormalsUseTheInverseTransposeUnderNonUniformScale) {
  // Scale x by 2: a 45-degree normal (1, 1, 0) must tilt towards y: inverse transpose diag(1/2, 1, 1).
  const mat4 worldFromModel = glm::scale(mat4(1.0f), vec3(2, 1, 1));
  const mat3 normalFromModel = normalMatrixFrom(worldFromModel);
  expectNear(transformVector(normalFromModel, vec3(1, 1, 0)), vec3(0.5f, 1.0f, 0.0f));
  // The surface tangent (1, -1, 0) stretched by the model matrix stays perpendicular to it.
  const vec3 tangent = transformVector(mat3(worldFromModel), vec3(1, -1, 0));
  EXPECT_NEAR(glm::dot(tangent, vec3(0.5f, 1.0f, 0.0f)), 0.0f, kEps);
}

TEST(Vertex, SingularModelMatrixGivesFiniteNormals) {
  const mat3 m = normalMatrixFrom(glm::scale(mat4(1.0f), vec3(1, 0, 1)));  // flattened in y
  const vec3 n = transformVector(m, vec3(0, 1, 0));
  EXPECT_TRUE(std::isfinite(n.x) && std::isfinite(n.y) && std::isfinite(n.z));
  EXPECT_GT(std::fabs(n.y), 0.0f);  // the flattened plane's normal is still +-y
}

TEST(Vertex, MirroringTransformFlipsTheBitangentSign) {
  Scene scene;
  RenderSettings settings;
  Vertex v;
  v.nModel = vec3(0, 0, 1);
  v.tangentModel = vec4(1, 0, 0, 1);  // B = cross(N, T) = (0, 1, 0)
  const VertexUniforms plain = makeVertexUniforms(mat4(1.0f), mat4(1.0f), scene, settings);
  expectNear(runVertexStage(v, plain).bWorld, vec3(0, 1, 0));
  // Mirror x: T -> (-1, 0, 0), N stays; cross(N, T) would be (0, -1, 0), but the frame's
  // handedness flipped, so B must stay the mirror image of (0, 1, 0), which is (0, 1, 0).
  const mat4 mirror = glm::scale(mat4(1.0f), vec3(-1, 1, 1));
  const VertexUniforms mirrored = makeVertexUniforms(mirror, mat4(1.0f), scene, settings);
  EXPECT_EQ(mirrored.mirrorSign, -1.0f);
  const ClipVertex out = runVertexStage(v, mirrored);
  expectNear(out.tWorld, vec3(-1, 0, 0));
  expectNear(out.nWorld, vec3(0, 0, 1));
  expectNear(out.bWorld, vec3(0, 1, 0));
  // A tangent with handedness -1 gives the opposite bitangent.
  v.tangentModel.w = -1.0f;
  expectNear(runVertexStage(v, mirrored).bWorld, vec3(0, -1, 0));
}

TEST(Vertex, TangentTransformSettingChoosesTheMatrix) {
  Scene scene;
  RenderSettings settings;
  Vertex v;
  v.tangentModel = vec4(1, 1, 0, 1);
  const mat4 stretch = glm::scale(mat4(1.0f), vec3(2, 1, 1));
  settings.tangentTransform = TangentTransform::Model;
  expectNear(runVertexStage(v, makeVertexUniforms(stretch, mat4(1.0f), scene, settings)).tWorld, vec3(2, 1, 0));
  settings.tangentTransform = TangentTransform::InverseTranspose;  // the course's variant
  expectNear(runVertexStage(v, makeVertexUniforms(stretch, mat4(1.0f), scene, settings)).tWorld, vec3(0.5f, 1, 0));
}

TEST(Vertex, TangentLightingMovesLightAndEyeIntoTheVertexFrame) {
  Scene scene;
  scene.camera.position = vec3(0, 0, 5);
  Light light;
  light.posWorld = vec3(3, 4, 1);
  scene.lights.push_back(light);
  RenderSettings settings;
  settings.lightingSpace = LightingSpace::Tangent;
  Vertex v;
  v.posModel = vec3(1, 0, 0);
  v.nModel = vec3(0, 1, 0);
  v.tangentModel = vec4(0, 0, 1, 1);  // T = z, N = y, B = cross(N, T) = x
  const ClipVertex out = runVertexStage(v, makeVertexUniforms(mat4(1.0f), mat4(1.0f), scene, settings));
  // Lw = (3,4,1) - (1,0,0) = (2, 4, 1): (T.Lw, B.Lw, N.Lw) = (1, 2, 4), not normalised.
  expectNear(out.lightDirTangent[0], vec3(1, 2, 4));
  // Ew = (0,0,5) - (1,0,0) = (-1, 0, 5): (5, -1, 0).
  expectNear(out.eyeDirTangent, vec3(5, -1, 0));
}

TEST(Vertex, UserClipDistancesAreWorldSpacePlanes) {
  Scene scene;
  RenderSettings settings;
  settings.userClipPlanes = {vec4(1, 0, 0, -0.5f), vec4(0, 0, 2, 1)};
  Vertex v;
  v.posModel = vec3(1, 2, 3);
  const VertexUniforms u =
      makeVertexUniforms(glm::translate(mat4(1.0f), vec3(1, 0, 0)), mat4(1.0f), scene, settings);
  EXPECT_EQ(u.userClipPlaneCount, 2);
  const ClipVertex out = runVertexStage(v, u);  // posWorld (2, 2, 3)
  EXPECT_NEAR(out.clipDistance[0], 1.5f, kEps);
  EXPECT_NEAR(out.clipDistance[1], 7.0f, kEps);
}

}  // namespace
}  // namespace twr
