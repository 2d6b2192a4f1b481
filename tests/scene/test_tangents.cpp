// computeTangents / computeNormals / anyPerpendicular: hand-computed frames, the analytic
// sphere and cube frames recovered from uvs alone, and every fallback (no NaN, ever).
#include "scene/primitives.h"
#include "scene/tangents.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

namespace twr {
namespace {

constexpr float kTolerance = 1e-5f;
constexpr float kRadiansToDegrees = 180.0f / 3.14159265358979323846f;

bool isFinite(vec4 v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z) && std::isfinite(v.w); }

void expectVecNear(vec3 actual, vec3 expected, float tolerance = kTolerance) {
  EXPECT_NEAR(glm::length(actual - expected), 0.0f, tolerance)
      << "(" << actual.x << ", " << actual.y << ", " << actual.z << ") vs (" << expected.x << ", " << expected.y
      << ", " << expected.z << ")";
}

// Finite, unit T perpendicular to unit N, w = +-1.
void expectOrthonormalFrame(const Vertex& v) {
  ASSERT_TRUE(isFinite(v.tangentModel));
  const vec3 t(v.tangentModel);
  EXPECT_NEAR(glm::length(t), 1.0f, kTolerance);
  EXPECT_NEAR(glm::dot(t, glm::normalize(v.nModel)), 0.0f, kTolerance);
  EXPECT_TRUE(v.tangentModel.w == 1.0f || v.tangentModel.w == -1.0f);
}

vec3 bitangentOf(const Vertex& v) { return v.tangentModel.w * glm::cross(v.nModel, vec3(v.tangentModel)); }

float angleDegrees(vec3 a, vec3 b) {
  return std::acos(std::clamp(glm::dot(glm::normalize(a), glm::normalize(b)), -1.0f, 1.0f)) * kRadiansToDegrees;
}

// One triangle with the given positions, uvs and a shared normal, tangents computed.
Mesh triangle(vec3 p0, vec3 p1, vec3 p2, vec2 uv0, vec2 uv1, vec2 uv2, vec3 normal) {
  Mesh mesh;
  const vec3 positions[3] = {p0, p1, p2};
  const vec2 uvs[3] = {uv0, uv1, uv2};
  for (int i = 0; i < 3; ++i) {
    Vertex v;
    v.posModel = positions[i];
    v.uv = uvs[i];
    v.nModel = normal;
    v.tangentModel = vec4(0.0f);  // must be overwritten
    mesh.vertices.push_back(v);
    mesh.indices.push_back(static_cast<std::uint32_t>(i));
  }
  computeTangents(mesh);
  return mesh;
}

TEST(AnyPerpendicular, UnitAndPerpendicularEverywhere) {
  std::vector<vec3> normals = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  normals.push_back(glm::normalize(vec3(1, 1, 1)));
  normals.push_back(glm::normalize(vec3(1e-7f, 0, -1)));  // near the -Z branch point
  std::mt19937 random(12345);  // fixed seed: reproducible
  std::normal_distribution<float> gaussian(0.0f, 1.0f);
  for (int i = 0; i < 1000; ++i) normals.push_back(glm::normalize(vec3(gaussian(random), gaussian(random), gaussian(random))));
  for (const vec3& n : normals) {
    const vec3 t = anyPerpendicular(n);
    ASSERT_TRUE(std::isfinite(t.x) && std::isfinite(t.y) && std::isfinite(t.z));
    EXPECT_NEAR(glm::length(t), 1.0f, kTolerance);
    EXPECT_NEAR(glm::dot(t, n), 0.0f, kTolerance);
  }
}

TEST(ComputeTangents, HandComputedFrame) {
  // Triangle in the floor (N = +Y): u grows along +X over 2 units, v along -Z over 3 units.
  // dP/du = (2,0,0) / 1, dP/dv = (0,0,-3): T = +X, B = -Z = cross(+Y, +X), so w = +1.
  const Mesh mesh = triangle({0, 0, 0}, {2, 0, 0}, {0, 0, -3}, {0, 0}, {1, 0}, {0, 1}, {0, 1, 0});
  for (const Vertex& v : mesh.vertices) {
    expectOrthonormalFrame(v);
    expectVecNear(vec3(v.tangentModel), {1, 0, 0});
    EXPECT_EQ(v.tangentModel.w, 1.0f);
    expectVecNear(bitangentOf(v), {0, 0, -1});
  }
}

TEST(ComputeTangents, SkewedUvsGiveGramSchmidtTangent) {
  // XY triangle, N = +Z, uv sheared: uv = (x + y, y). Then dP/du = (1,0,0) and
  // dP/dv = (-1,1,0): T = +X exactly, B direction (-1,1,0) has positive dot with
  // cross(N, T) = +Y, so w = +1.
  const Mesh mesh = triangle({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0}, {1, 0}, {1, 1}, {0, 0, 1});
  for (const Vertex& v : mesh.vertices) {
    expectVecNear(vec3(v.tangentModel), {1, 0, 0});
    EXPECT_EQ(v.tangentModel.w, 1.0f);
  }
}

TEST(ComputeTangents, MirroredUvsGiveNegativeHandedness) {
  // u decreases along +X: dP/du = (-1,0,0), dP/dv = (0,1,0). T = -X,
  // cross(N, T) = cross(+Z, -X) = -Y, but +v is +Y: w = -1, and B = w cross(N, T) = +Y.
  const Mesh mesh = triangle({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 0}, {0, 0}, {1, 1}, {0, 0, 1});
  for (const Vertex& v : mesh.vertices) {
    expectOrthonormalFrame(v);
    expectVecNear(vec3(v.tangentModel), {-1, 0, 0});
    EXPECT_EQ(v.tangentModel.w, -1.0f);
    expectVecNear(bitangentOf(v), {0, 1, 0});
  }
}

TEST(ComputeTangents, MirroredTrianglesMatchTheMirroredAsset) {
  // The two triangles of assets/scenes/mirrored_uvs.json's quad: u runs right to left.
  const Mesh mesh = makeTriangles({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 0, 0}, {1, 1, 0}, {0, 1, 0}},
                                  {{1, 0}, {0, 0}, {0, 1}, {1, 0}, {0, 1}, {1, 1}}, {});
  for (const Vertex& v : mesh.vertices) {
    expectVecNear(vec3(v.tangentModel), {-1, 0, 0});
    EXPECT_EQ(v.tangentModel.w, -1.0f);
    expectVecNear(bitangentOf(v), {0, 1, 0});
  }
}

TEST(ComputeTangents, DegenerateUvsFallBackToBasisFromNormal) {
  const vec3 n = glm::normalize(vec3(0.3f, 0.9f, -0.2f));
  // All uvs equal (det = 0 with zero deltas), and collinear uvs (det = 0, nonzero deltas).
  for (const Mesh& mesh : {triangle({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0.5f, 0.5f}, {0.5f, 0.5f}, {0.5f, 0.5f}, n),
                           triangle({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0}, {1, 1}, {2, 2}, n)}) {
    for (const Vertex& v : mesh.vertices) {
      expectOrthonormalFrame(v);
      expectVecNear(vec3(v.tangentModel), anyPerpendicular(n));
      EXPECT_EQ(v.tangentModel.w, 1.0f);
    }
  }
}

TEST(ComputeTangents, ZeroAreaTriangleFallsBack) {
  // Good uvs but all positions equal: dP/du = 0, nothing to Gram-Schmidt.
  const Mesh mesh = triangle({1, 1, 1}, {1, 1, 1}, {1, 1, 1}, {0, 0}, {1, 0}, {0, 1}, {0, 0, 1});
  for (const Vertex& v : mesh.vertices) {
    expectOrthonormalFrame(v);
    expectVecNear(vec3(v.tangentModel), anyPerpendicular({0, 0, 1}));
  }
}

TEST(ComputeTangents, TangentParallelToNormalUsesTheBitangent) {
  // dP/du = +X but the given normal is +X too: Gram-Schmidt leaves nothing. dP/dv = +Y
  // survives, so T = cross(B, N) = cross(+Y, +X) = -Z and w = +1 keeps B along +v.
  const Mesh mesh = triangle({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0}, {1, 0}, {0, 1}, {1, 0, 0});
  for (const Vertex& v : mesh.vertices) {
    expectOrthonormalFrame(v);
    expectVecNear(vec3(v.tangentModel), {0, 0, -1});
    expectVecNear(bitangentOf(v), {0, 1, 0});
  }
}

TEST(ComputeTangents, CancellingTangentsOnASharedVertexFallBack) {
  // Two triangles share all three vertices' positions but one has mirrored uvs, so their
  // dP/du sum to zero at the shared vertices (a mirror seam welded by mistake).
  Mesh mesh;
  const vec3 positions[4] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {-1, 0, 0}};
  const vec2 uvs[4] = {{0, 0}, {1, 0}, {0, 1}, {1, 0}};
  for (int i = 0; i < 4; ++i) {
    Vertex v;
    v.posModel = positions[i];
    v.uv = uvs[i];
    v.nModel = {0, 0, 1};
    mesh.vertices.push_back(v);
  }
  // (0,1,2): dP/du = +X. (0,2,3) is clockwise in uv: dP/du = -X. At vertices 0 and 2
  // they cancel exactly; dP/dv = +Y in both, so T = cross(+Y, +Z) = +X and w = +1.
  mesh.indices = {0, 1, 2, 0, 2, 3};
  computeTangents(mesh);
  for (const Vertex& v : mesh.vertices) expectOrthonormalFrame(v);
  expectVecNear(vec3(mesh.vertices[0].tangentModel), {1, 0, 0});
  expectVecNear(bitangentOf(mesh.vertices[0]), {0, 1, 0});
  expectVecNear(vec3(mesh.vertices[3].tangentModel), {-1, 0, 0});
  EXPECT_EQ(mesh.vertices[3].tangentModel.w, -1.0f);
}

TEST(ComputeTangents, ZeroNormalStaysFinite) {
  const Mesh mesh = triangle({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0}, {1, 0}, {0, 1}, {0, 0, 0});
  for (const Vertex& v : mesh.vertices) ASSERT_TRUE(isFinite(v.tangentModel));
}

TEST(ComputeTangents, RecoversTheAnalyticCubeFrames) {
  // Each cube face is planar with affine uvs, so the computed frame is exact.
  const Mesh analytic = makeCube(2.0f);
  Mesh computed = analytic;
  computeTangents(computed);
  for (std::size_t i = 0; i < analytic.vertices.size(); ++i) {
    expectVecNear(vec3(computed.vertices[i].tangentModel), vec3(analytic.vertices[i].tangentModel));
    EXPECT_EQ(computed.vertices[i].tangentModel.w, analytic.vertices[i].tangentModel.w);
  }
}

// On a sphere tessellated into stacks x slices, the tutorial's per-triangle dP/du is the
// chord direction of a facet; at a vertex the facets around it tilt almost symmetrically
// about d/dphi, so their sum recovers it up to the asymmetry of the neighbourhood (the
// quads' diagonals, and narrower facets on the pole side). That asymmetry grows towards the
// poles: with 32 x 64 (facets of 5.6 degrees) the worst vertex measured 0.93 degrees on
// stack 1 and 0.45 degrees from stack 2 on. So away from the poles (stacks 2 .. stacks - 2)
// and from the seam (where a vertex has facets on one side only, ~2.8 degrees) the computed
// tangent must stay within kMaxAngleDegrees = 0.6 of the analytic one, same handedness.
TEST(ComputeTangents, AgreesWithTheAnalyticSphereAwayFromPolesAndSeam) {
  constexpr int kStacks = 32, kSlices = 64;
  constexpr float kMaxAngleDegrees = 0.6f;
  const Mesh analytic = makeSphere(1.0f, kStacks, kSlices);
  Mesh computed = analytic;
  computeTangents(computed);
  float worst = 0.0f;
  for (int stack = 2; stack <= kStacks - 2; ++stack) {
    for (int slice = 1; slice < kSlices; ++slice) {
      const std::size_t i = static_cast<std::size_t>(stack * (kSlices + 1) + slice);
      const vec4 expected = analytic.vertices[i].tangentModel;
      const vec4 actual = computed.vertices[i].tangentModel;
      const float angle = angleDegrees(vec3(actual), vec3(expected));
      worst = std::max(worst, angle);
      EXPECT_LT(angle, kMaxAngleDegrees) << "stack " << stack << ", slice " << slice;
      EXPECT_EQ(actual.w, expected.w) << "stack " << stack << ", slice " << slice;
    }
  }
  RecordProperty("worstAngleDegrees", std::to_string(worst));
  // Everywhere, poles and seam included: finite and orthonormal; and every vertex that a
  // triangle uses has the analytic handedness. (The pole copies at slice 0 of the north
  // pole and slice `slices` of the south pole belong to skipped zero-area triangles only,
  // so they get the fallback frame.)
  std::vector<bool> used(computed.vertices.size(), false);
  for (std::uint32_t index : computed.indices) used[index] = true;
  for (std::size_t i = 0; i < computed.vertices.size(); ++i) {
    expectOrthonormalFrame(computed.vertices[i]);
    if (used[i]) {
      EXPECT_EQ(computed.vertices[i].tangentModel.w, -1.0f) << "vertex " << i;
    }
  }
}

TEST(ComputeTangents, AgreesWithTheAnalyticTorus) {
  constexpr float kMaxAngleDegrees = 0.5f;
  const Mesh analytic = makeTorus(1.0f, 0.3f, 48, 24);
  Mesh computed = analytic;
  computeTangents(computed);
  for (int side = 1; side < 24; ++side) {
    for (int ring = 1; ring < 48; ++ring) {
      const std::size_t i = static_cast<std::size_t>(side * 49 + ring);
      EXPECT_LT(angleDegrees(vec3(computed.vertices[i].tangentModel), vec3(analytic.vertices[i].tangentModel)),
                kMaxAngleDegrees)
          << "side " << side << ", ring " << ring;
      EXPECT_EQ(computed.vertices[i].tangentModel.w, 1.0f);
    }
  }
}

TEST(ComputeNormals, AreaWeighted) {
  // Vertex 0 is shared by a big triangle in XY (cross = (0,0,4)) and a small one in XZ
  // (cross((0,0,1),(1,0,0)) = (0,1,0)): area-weighted (0,1,4)/sqrt17; an unweighted
  // average would give (0,1,1)/sqrt2.
  Mesh mesh;
  for (vec3 p : {vec3(0, 0, 0), vec3(2, 0, 0), vec3(0, 2, 0), vec3(0, 0, 1), vec3(1, 0, 0)}) {
    Vertex v;
    v.posModel = p;
    mesh.vertices.push_back(v);
  }
  mesh.indices = {0, 1, 2, 0, 3, 4};
  computeNormals(mesh);
  expectVecNear(mesh.vertices[0].nModel, glm::normalize(vec3(0, 1, 4)));
  expectVecNear(mesh.vertices[1].nModel, {0, 0, 1});
  expectVecNear(mesh.vertices[3].nModel, {0, 1, 0});
}

TEST(ComputeNormals, RecoversSphereNormals) {
  // The area-weighted sum of the facets around a sphere vertex points nearly radially; as
  // with tangents, the neighbourhood grows lopsided towards the poles (32 x 64: 0.95 degrees
  // measured on stack 1, 0.48 from stack 2 on). Pole and seam copies see only part of their
  // fan and are skipped.
  constexpr int kStacks = 32, kSlices = 64;
  constexpr float kMaxAngleDegrees = 0.6f;
  Mesh mesh = makeSphere(2.0f, kStacks, kSlices);
  const Mesh analytic = mesh;
  computeNormals(mesh);
  for (int stack = 2; stack <= kStacks - 2; ++stack) {
    for (int slice = 1; slice < kSlices; ++slice) {
      const std::size_t i = static_cast<std::size_t>(stack * (kSlices + 1) + slice);
      EXPECT_LT(angleDegrees(mesh.vertices[i].nModel, analytic.vertices[i].nModel), kMaxAngleDegrees)
          << "stack " << stack << ", slice " << slice;
    }
  }
}

TEST(ComputeNormals, DegenerateTriangleStaysFinite) {
  Mesh mesh;
  for (int i = 0; i < 3; ++i) {
    Vertex v;
    v.posModel = vec3(1.0f);
    v.nModel = vec3(0.0f);
    mesh.vertices.push_back(v);
    mesh.indices.push_back(static_cast<std::uint32_t>(i));
  }
  computeNormals(mesh);
  for (const Vertex& v : mesh.vertices) EXPECT_NEAR(glm::length(v.nModel), 1.0f, kTolerance);
}

}  // namespace
}  // namespace twr
