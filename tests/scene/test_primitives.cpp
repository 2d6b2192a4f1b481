// Primitives: counts, closed-ness and consistent winding (on positions welded bit for bit),
// unit outward normals, orthonormal tangent frames whose T and B follow +u and +v, the
// sphere's exact parametrisation, and every rejected parameter.
#include "scene/errors.h"
#include "scene/primitives.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>
#include <map>
#include <set>
#include <tuple>

namespace twr {
namespace {

constexpr float kUnitTolerance = 1e-5f;     // |length - 1| of a stored unit vector
constexpr float kOrthoTolerance = 1e-5f;    // |dot| of two stored perpendicular unit vectors
constexpr double kPi = 3.14159265358979323846;

bool isFinite(vec3 v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

// Every stored attribute is finite, N and T are unit and perpendicular, w is +-1.
void expectValidFrames(const Mesh& mesh) {
  for (std::size_t i = 0; i < mesh.vertices.size(); ++i) {
    const Vertex& v = mesh.vertices[i];
    ASSERT_TRUE(isFinite(v.posModel)) << "vertex " << i;
    ASSERT_TRUE(isFinite(v.nModel)) << "vertex " << i;
    ASSERT_TRUE(isFinite(vec3(v.tangentModel))) << "vertex " << i;
    ASSERT_TRUE(std::isfinite(v.uv.x) && std::isfinite(v.uv.y)) << "vertex " << i;
    EXPECT_NEAR(glm::length(v.nModel), 1.0f, kUnitTolerance) << "vertex " << i;
    EXPECT_NEAR(glm::length(vec3(v.tangentModel)), 1.0f, kUnitTolerance) << "vertex " << i;
    EXPECT_NEAR(glm::dot(v.nModel, vec3(v.tangentModel)), 0.0f, kOrthoTolerance) << "vertex " << i;
    EXPECT_TRUE(v.tangentModel.w == 1.0f || v.tangentModel.w == -1.0f) << "vertex " << i;
  }
  for (std::uint32_t index : mesh.indices) ASSERT_LT(index, mesh.vertices.size());
  ASSERT_EQ(mesh.indices.size() % 3, 0u);
}

// For each triangle with usable uvs, the tutorial's dP/du and dP/dv from the triangle
// itself: T must point along dP/du and B = w cross(N, T) along dP/dv at every corner.
// This is what makes a normal map look right (and catches a wrong handedness sign).
void expectFramesFollowUv(const Mesh& mesh) {
  int checked = 0;
  for (std::size_t first = 0; first < mesh.indices.size(); first += 3) {
    const Vertex& v0 = mesh.vertices[mesh.indices[first]];
    const Vertex& v1 = mesh.vertices[mesh.indices[first + 1]];
    const Vertex& v2 = mesh.vertices[mesh.indices[first + 2]];
    const vec3 e1 = v1.posModel - v0.posModel, e2 = v2.posModel - v0.posModel;
    const vec2 d1 = v1.uv - v0.uv, d2 = v2.uv - v0.uv;
    const float det = d1.x * d2.y - d1.y * d2.x;
    if (std::fabs(det) < 1e-8f || glm::length(glm::cross(e1, e2)) < 1e-8f) continue;
    const vec3 dPdu = (e1 * d2.y - e2 * d1.y) / det;
    const vec3 dPdv = (e2 * d1.x - e1 * d2.x) / det;
    for (const Vertex* v : {&v0, &v1, &v2}) {
      const vec3 t(v->tangentModel);
      const vec3 b = v->tangentModel.w * glm::cross(v->nModel, t);
      EXPECT_GT(glm::dot(t, glm::normalize(dPdu)), 0.5f) << "triangle " << first / 3;
      EXPECT_GT(glm::dot(b, glm::normalize(dPdv)), 0.5f) << "triangle " << first / 3;
    }
    ++checked;
  }
  EXPECT_GT(checked, 0);
}

// Welds vertices by exact position (+0 and -0 equal) and returns a welded id per vertex.
std::vector<int> weldByPosition(const Mesh& mesh) {
  std::map<std::tuple<float, float, float>, int> ids;
  std::vector<int> welded;
  for (const Vertex& v : mesh.vertices) {
    const auto key = std::make_tuple(v.posModel.x + 0.0f, v.posModel.y + 0.0f, v.posModel.z + 0.0f);
    welded.push_back(ids.try_emplace(key, static_cast<int>(ids.size())).first->second);
  }
  return welded;
}

struct Topology {
  std::size_t weldedVertices = 0;
  std::size_t edges = 0;
  std::size_t faces = 0;
};

// Closed and consistently wound: after welding, every directed edge (a, b) occurs exactly
// once and its reverse (b, a) exactly once, so every edge is shared by two triangles that
// traverse it in opposite directions. No triangle may collapse to a welded edge.
Topology expectClosedAndConsistent(const Mesh& mesh) {
  const std::vector<int> welded = weldByPosition(mesh);
  std::map<std::pair<int, int>, int> directedCount;
  for (std::size_t first = 0; first < mesh.indices.size(); first += 3) {
    const int a = welded[mesh.indices[first]], b = welded[mesh.indices[first + 1]], c = welded[mesh.indices[first + 2]];
    EXPECT_TRUE(a != b && b != c && c != a) << "triangle " << first / 3 << " is degenerate";
    ++directedCount[{a, b}];
    ++directedCount[{b, c}];
    ++directedCount[{c, a}];
  }
  for (const auto& [edge, count] : directedCount) {
    EXPECT_EQ(count, 1) << "directed edge " << edge.first << "->" << edge.second;
    const auto reverse = directedCount.find({edge.second, edge.first});
    EXPECT_TRUE(reverse != directedCount.end()) << "edge " << edge.first << "-" << edge.second << " is open";
  }
  std::set<int> distinct(welded.begin(), welded.end());
  return {distinct.size(), directedCount.size() / 2, mesh.triangleCount()};
}

long long eulerCharacteristic(const Topology& t) {
  return static_cast<long long>(t.weldedVertices) - static_cast<long long>(t.edges) + static_cast<long long>(t.faces);
}

// Every triangle is counter-clockwise seen from the side its vertex normals point to, and
// those normals point away from `insidePoint(position)` (the centre, or the tube's axis).
void expectOutwardCcw(const Mesh& mesh, const std::function<vec3(vec3)>& insidePoint) {
  for (std::size_t first = 0; first < mesh.indices.size(); first += 3) {
    const Vertex& v0 = mesh.vertices[mesh.indices[first]];
    const Vertex& v1 = mesh.vertices[mesh.indices[first + 1]];
    const Vertex& v2 = mesh.vertices[mesh.indices[first + 2]];
    const vec3 faceNormal = glm::cross(v1.posModel - v0.posModel, v2.posModel - v0.posModel);
    const vec3 centroid = (v0.posModel + v1.posModel + v2.posModel) / 3.0f;
    const vec3 outward = centroid - insidePoint(centroid);
    EXPECT_GT(glm::dot(faceNormal, outward), 0.0f) << "triangle " << first / 3 << " is clockwise from outside";
    for (const Vertex* v : {&v0, &v1, &v2}) {
      EXPECT_GT(glm::dot(v->nModel, v->posModel - insidePoint(v->posModel)), 0.0f)
          << "triangle " << first / 3 << " has an inward normal";
    }
  }
}

const auto kCentre = [](vec3) { return vec3(0.0f); };

// ---- cube ----

TEST(Cube, CountsAndTopology) {
  const Mesh cube = makeCube(2.0f);
  EXPECT_EQ(cube.vertices.size(), 24u);
  EXPECT_EQ(cube.triangleCount(), 12u);
  expectValidFrames(cube);
  const Topology topology = expectClosedAndConsistent(cube);
  EXPECT_EQ(topology.weldedVertices, 8u);  // 24 corners weld to the 8 cube corners
  EXPECT_EQ(eulerCharacteristic(topology), 2);
  expectOutwardCcw(cube, kCentre);
  expectFramesFollowUv(cube);
}

TEST(Cube, FaceNormalsAndUvRange) {
  const float size = 3.0f;
  const Mesh cube = makeCube(size);
  std::map<std::tuple<float, float, float>, int> cornersPerNormal;
  for (const Vertex& v : cube.vertices) {
    ++cornersPerNormal[{v.nModel.x, v.nModel.y, v.nModel.z}];
    // The normal is an axis; the vertex lies on that face's plane at distance size / 2.
    EXPECT_FLOAT_EQ(glm::dot(v.posModel, v.nModel), 0.5f * size);
    for (int axis = 0; axis < 3; ++axis) EXPECT_FLOAT_EQ(std::fabs(v.posModel[axis]), 0.5f * size);
    EXPECT_TRUE(v.uv.x == 0.0f || v.uv.x == 1.0f);
    EXPECT_TRUE(v.uv.y == 0.0f || v.uv.y == 1.0f);
    EXPECT_EQ(v.tangentModel.w, 1.0f);
  }
  ASSERT_EQ(cornersPerNormal.size(), 6u);
  for (const auto& [normal, count] : cornersPerNormal) EXPECT_EQ(count, 4);
}

TEST(Cube, SideFacesHaveVUp) {
  // On the four side faces +v points up (+Y), so a brick texture's rows stay horizontal.
  const Mesh cube = makeCube(1.0f);
  for (const Vertex& v : cube.vertices) {
    if (v.nModel.y != 0.0f) continue;
    const vec3 b = v.tangentModel.w * glm::cross(v.nModel, vec3(v.tangentModel));
    EXPECT_NEAR(b.y, 1.0f, kUnitTolerance);
  }
}

// ---- sphere ----

TEST(Sphere, CountsAndTopology) {
  const int stacks = 8, slices = 12;
  const Mesh sphere = makeSphere(1.5f, stacks, slices);
  EXPECT_EQ(sphere.vertices.size(), static_cast<std::size_t>((stacks + 1) * (slices + 1)));
  // Zero-area pole triangles are skipped: one per slice in the first and the last stack.
  EXPECT_EQ(sphere.triangleCount(), static_cast<std::size_t>(slices * (2 * stacks - 2)));
  expectValidFrames(sphere);
  const Topology topology = expectClosedAndConsistent(sphere);
  // Welded: one vertex per pole plus slices per inner ring.
  EXPECT_EQ(topology.weldedVertices, static_cast<std::size_t>(2 + (stacks - 1) * slices));
  EXPECT_EQ(eulerCharacteristic(topology), 2);
  expectOutwardCcw(sphere, kCentre);
  expectFramesFollowUv(sphere);
}

TEST(Sphere, SmallestSphereIsClosed) {
  const Mesh sphere = makeSphere(1.0f, 2, 3);
  expectValidFrames(sphere);
  EXPECT_EQ(eulerCharacteristic(expectClosedAndConsistent(sphere)), 2);
  expectOutwardCcw(sphere, kCentre);
}

TEST(Sphere, FollowsTheCourseParametrisation) {
  const int stacks = 6, slices = 8;
  const float radius = 2.0f;
  const Mesh sphere = makeSphere(radius, stacks, slices);
  for (int stack = 0; stack <= stacks; ++stack) {
    for (int slice = 0; slice <= slices; ++slice) {
      const Vertex& v = sphere.vertices[static_cast<std::size_t>(stack * (slices + 1) + slice)];
      const double psi = kPi * stack / stacks;
      const double phi = 2.0 * kPi * slice / slices;
      // x = R sin(psi) cos(phi), y = R cos(psi), z = R sin(psi) sin(phi).
      EXPECT_NEAR(v.posModel.x, radius * std::sin(psi) * std::cos(phi), 1e-5) << stack << "," << slice;
      EXPECT_NEAR(v.posModel.y, radius * std::cos(psi), 1e-5) << stack << "," << slice;
      EXPECT_NEAR(v.posModel.z, radius * std::sin(psi) * std::sin(phi), 1e-5) << stack << "," << slice;
      // u = phi / 2pi, v = 1 - psi / pi.
      EXPECT_FLOAT_EQ(v.uv.x, static_cast<float>(slice) / slices);
      EXPECT_FLOAT_EQ(v.uv.y, 1.0f - static_cast<float>(stack) / stacks);
      // Tangent = normalised d/dphi = (-sin phi, 0, cos phi), also at the poles (its limit).
      EXPECT_NEAR(v.tangentModel.x, -std::sin(phi), 1e-5);
      EXPECT_NEAR(v.tangentModel.y, 0.0, 1e-6);
      EXPECT_NEAR(v.tangentModel.z, std::cos(phi), 1e-5);
      // B = w cross(N, T) must be along +v = -d/dpsi = (-cos psi cos phi, sin psi, -cos psi sin phi).
      const vec3 b = v.tangentModel.w * glm::cross(v.nModel, vec3(v.tangentModel));
      EXPECT_NEAR(b.x, -std::cos(psi) * std::cos(phi), 1e-5);
      EXPECT_NEAR(b.y, std::sin(psi), 1e-5);
      EXPECT_NEAR(b.z, -std::cos(psi) * std::sin(phi), 1e-5);
    }
  }
  // v = 1 at the north pole (+Y), 0 at the south pole.
  EXPECT_EQ(sphere.vertices.front().uv.y, 1.0f);
  EXPECT_GT(sphere.vertices.front().posModel.y, 0.0f);
  EXPECT_EQ(sphere.vertices.back().uv.y, 0.0f);
  // The parametrisation is mirrored seen from outside, so w = -1 throughout.
  for (const Vertex& v : sphere.vertices) EXPECT_EQ(v.tangentModel.w, -1.0f);
}

TEST(Sphere, SeamColumnRepeatsTheFirstColumnExactly) {
  const int stacks = 5, slices = 7;
  const Mesh sphere = makeSphere(1.0f, stacks, slices);
  for (int stack = 0; stack <= stacks; ++stack) {
    const Vertex& first = sphere.vertices[static_cast<std::size_t>(stack * (slices + 1))];
    const Vertex& seam = sphere.vertices[static_cast<std::size_t>(stack * (slices + 1) + slices)];
    EXPECT_EQ(first.posModel, seam.posModel);
    EXPECT_EQ(first.nModel, seam.nModel);
    EXPECT_EQ(first.uv.x, 0.0f);
    EXPECT_EQ(seam.uv.x, 1.0f);
  }
}

// ---- plane ----

TEST(Plane, FacesUpWithUvScale) {
  const Mesh plane = makePlane({4.0f, 2.0f}, 3.0f);
  EXPECT_EQ(plane.vertices.size(), 4u);
  EXPECT_EQ(plane.triangleCount(), 2u);
  expectValidFrames(plane);
  expectFramesFollowUv(plane);
  vec3 low(1e9f), high(-1e9f);
  vec2 uvLow(1e9f), uvHigh(-1e9f);
  for (const Vertex& v : plane.vertices) {
    EXPECT_EQ(v.nModel, vec3(0, 1, 0));
    low = glm::min(low, v.posModel);
    high = glm::max(high, v.posModel);
    uvLow = glm::min(uvLow, v.uv);
    uvHigh = glm::max(uvHigh, v.uv);
  }
  EXPECT_EQ(low, vec3(-2.0f, 0.0f, -1.0f));
  EXPECT_EQ(high, vec3(2.0f, 0.0f, 1.0f));
  EXPECT_EQ(uvLow, vec2(0.0f));
  EXPECT_EQ(uvHigh, vec2(3.0f));
  // Counter-clockwise seen from above: face normals point to +Y.
  expectOutwardCcw(plane, [](vec3 p) { return vec3(p.x, -1.0f, p.z); });
}

// ---- cylinder ----

TEST(Cylinder, CountsAndTopology) {
  const int slices = 10;
  const Mesh cylinder = makeCylinder(0.5f, 2.0f, slices);
  // Side: 2 rings of slices + 1; each cap: centre + slices.
  EXPECT_EQ(cylinder.vertices.size(), static_cast<std::size_t>(2 * (slices + 1) + 2 * (slices + 1)));
  EXPECT_EQ(cylinder.triangleCount(), static_cast<std::size_t>(4 * slices));
  expectValidFrames(cylinder);
  const Topology topology = expectClosedAndConsistent(cylinder);
  EXPECT_EQ(topology.weldedVertices, static_cast<std::size_t>(2 * slices + 2));
  EXPECT_EQ(eulerCharacteristic(topology), 2);
  expectOutwardCcw(cylinder, kCentre);
  expectFramesFollowUv(cylinder);
}

TEST(Cylinder, CapsHaveTheirOwnNormals) {
  const Mesh cylinder = makeCylinder(1.0f, 3.0f, 6);
  int up = 0, down = 0, side = 0;
  for (const Vertex& v : cylinder.vertices) {
    if (v.nModel == vec3(0, 1, 0)) {
      ++up;
      EXPECT_FLOAT_EQ(v.posModel.y, 1.5f);
    } else if (v.nModel == vec3(0, -1, 0)) {
      ++down;
      EXPECT_FLOAT_EQ(v.posModel.y, -1.5f);
    } else {
      ++side;
      EXPECT_NEAR(v.nModel.y, 0.0f, 1e-7f);
      // Side normals are radial: the position's horizontal direction.
      EXPECT_NEAR(glm::length(vec3(v.posModel.x, 0, v.posModel.z) - v.nModel), 0.0f, 1e-5f);
    }
  }
  EXPECT_EQ(up, 7);
  EXPECT_EQ(down, 7);
  EXPECT_EQ(side, 14);
}

// ---- torus ----

TEST(Torus, CountsAndTopology) {
  const int rings = 12, sides = 6;
  const float major = 1.0f, minor = 0.3f;
  const Mesh torus = makeTorus(major, minor, rings, sides);
  EXPECT_EQ(torus.vertices.size(), static_cast<std::size_t>((rings + 1) * (sides + 1)));
  EXPECT_EQ(torus.triangleCount(), static_cast<std::size_t>(2 * rings * sides));
  expectValidFrames(torus);
  const Topology topology = expectClosedAndConsistent(torus);
  EXPECT_EQ(topology.weldedVertices, static_cast<std::size_t>(rings * sides));
  EXPECT_EQ(eulerCharacteristic(topology), 0);  // genus 1
  // "Inside" is the nearest point of the tube's centre circle.
  expectOutwardCcw(torus, [major](vec3 p) {
    const vec3 horizontal(p.x, 0.0f, p.z);
    return major * glm::normalize(horizontal);
  });
  expectFramesFollowUv(torus);
  for (const Vertex& v : torus.vertices) {
    // Every point is minor away from the centre circle, along its normal.
    const vec3 centre = major * glm::normalize(vec3(v.posModel.x, 0.0f, v.posModel.z));
    EXPECT_NEAR(glm::length(v.posModel - centre), minor, 1e-5f);
    EXPECT_NEAR(glm::length((v.posModel - centre) / minor - v.nModel), 0.0f, 1e-4f);
  }
}

// ---- raw triangles ----

TEST(Triangles, FaceNormalsWhenMissing) {
  // Counter-clockwise seen from +Z: face normal +Z.
  const Mesh mesh = makeTriangles({{0, 0, 0}, {2, 0, 0}, {0, 1, 0}}, {}, {});
  ASSERT_EQ(mesh.vertices.size(), 3u);
  ASSERT_EQ(mesh.triangleCount(), 1u);
  for (const Vertex& v : mesh.vertices) {
    EXPECT_EQ(v.nModel, vec3(0, 0, 1));
    EXPECT_EQ(v.uv, vec2(0.0f));
  }
  // Without uvs the tangent frame comes from N alone: still finite and orthonormal.
  expectValidFrames(mesh);
}

TEST(Triangles, GivenNormalsAreNormalisedAndTangentsFollowUv) {
  const Mesh mesh = makeTriangles({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {{0, 0}, {1, 0}, {0, 1}},
                                  {{0, 0, 2}, {0, 0, 3}, {0, 0, 0.5f}});
  expectValidFrames(mesh);
  for (const Vertex& v : mesh.vertices) {
    EXPECT_NEAR(glm::length(v.nModel - vec3(0, 0, 1)), 0.0f, kUnitTolerance);
    EXPECT_NEAR(glm::length(vec3(v.tangentModel) - vec3(1, 0, 0)), 0.0f, kUnitTolerance);
    EXPECT_EQ(v.tangentModel.w, 1.0f);
  }
}

TEST(Triangles, RejectsMalformedInput) {
  EXPECT_THROW(makeTriangles({}, {}, {}), InputError);
  EXPECT_THROW(makeTriangles({{0, 0, 0}, {1, 0, 0}}, {}, {}), InputError);
  const std::vector<vec3> triangle{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  EXPECT_THROW(makeTriangles(triangle, {{0, 0}}, {}), InputError);
  EXPECT_THROW(makeTriangles(triangle, {}, {{0, 0, 1}}), InputError);
  const float nan = std::numeric_limits<float>::quiet_NaN();
  EXPECT_THROW(makeTriangles({{0, 0, 0}, {1, nan, 0}, {0, 1, 0}}, {}, {}), InputError);
  EXPECT_THROW(makeTriangles(triangle, {{0, 0}, {1, 0}, {0, std::numeric_limits<float>::infinity()}}, {}),
               InputError);
}

// ---- rejected parameters ----

// The message must name the key and the allowed range.
void expectRejected(const std::function<void()>& make, const std::string& key) {
  try {
    make();
    ADD_FAILURE() << "expected InputError naming " << key;
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find(key), std::string::npos) << error.what();
  }
}

TEST(PrimitiveLimits, RejectsBadSizes) {
  const float nan = std::numeric_limits<float>::quiet_NaN();
  expectRejected([] { makeCube(0.0f); }, "cube.size");
  expectRejected([] { makeCube(-1.0f); }, "cube.size");
  expectRejected([nan] { makeCube(nan); }, "cube.size");
  expectRejected([] { makeSphere(0.0f, 8, 8); }, "sphere.radius");
  expectRejected([] { makePlane({0.0f, 1.0f}, 1.0f); }, "plane.size");
  expectRejected([] { makePlane({1.0f, -1.0f}, 1.0f); }, "plane.size");
  expectRejected([] { makePlane({1.0f, 1.0f}, 0.0f); }, "plane.uv_scale");
  expectRejected([] { makeCylinder(1.0f, 0.0f, 8); }, "cylinder.height");
  expectRejected([] { makeCylinder(-1.0f, 1.0f, 8); }, "cylinder.radius");
  expectRejected([] { makeTorus(1.0f, 0.0f, 8, 8); }, "torus.minor");
  expectRejected([] { makeTorus(1.0f, 1.0f, 8, 8); }, "torus.minor");
  expectRejected([] { makeTorus(1.0f, 2.0f, 8, 8); }, "torus.minor");
}

TEST(PrimitiveLimits, RejectsSegmentCountsOutsideBounds) {
  expectRejected([] { makeSphere(1.0f, 1, 8); }, "sphere.stacks");
  expectRejected([] { makeSphere(1.0f, 8, 2); }, "sphere.slices");
  expectRejected([] { makeSphere(1.0f, kMaxSegments + 1, 8); }, "sphere.stacks");
  expectRejected([] { makeSphere(1.0f, 8, kMaxSegments + 1); }, "sphere.slices");
  expectRejected([] { makeCylinder(1.0f, 1.0f, 2); }, "cylinder.slices");
  expectRejected([] { makeCylinder(1.0f, 1.0f, -5); }, "cylinder.slices");
  expectRejected([] { makeTorus(1.0f, 0.5f, 2, 8); }, "torus.rings");
  expectRejected([] { makeTorus(1.0f, 0.5f, 8, 2); }, "torus.sides");
  expectRejected([] { makeTorus(1.0f, 0.5f, 8, kMaxSegments + 1); }, "torus.sides");
  // The inclusive upper bound itself is accepted where the triangle budget allows it.
  EXPECT_NO_THROW(makeCylinder(1.0f, 1.0f, kMaxSegments));
}

TEST(PrimitiveLimits, RejectsMoreTrianglesThanTheSceneBudget) {
  // 4096 x 4096 sphere: 4096 * (2 * 4096 - 2) = 33.5 million > 20 million triangles.
  expectRejected([] { makeSphere(1.0f, kMaxSegments, kMaxSegments); }, "triangles");
  // 4096 x 4096 torus: 33.5 million as well.
  expectRejected([] { makeTorus(1.0f, 0.5f, kMaxSegments, kMaxSegments); }, "triangles");
}

// ---- buildMesh ----

TEST(BuildMesh, DispatchesOnType) {
  MeshDesc desc;
  desc.type = MeshType::Cube;
  EXPECT_EQ(buildMesh(desc).vertices.size(), 24u);
  desc.type = MeshType::Sphere;
  desc.stacks = 4;
  desc.slices = 6;
  EXPECT_EQ(buildMesh(desc).triangleCount(), static_cast<std::size_t>(6 * (2 * 4 - 2)));
  desc.type = MeshType::Plane;
  EXPECT_EQ(buildMesh(desc).triangleCount(), 2u);
  desc.type = MeshType::Cylinder;
  EXPECT_EQ(buildMesh(desc).triangleCount(), static_cast<std::size_t>(4 * 6));
  desc.type = MeshType::Torus;
  desc.rings = 5;
  desc.sides = 3;
  EXPECT_EQ(buildMesh(desc).triangleCount(), static_cast<std::size_t>(2 * 5 * 3));
  desc.type = MeshType::Triangles;
  desc.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  EXPECT_EQ(buildMesh(desc).triangleCount(), 1u);
  desc.type = MeshType::Obj;
  desc.path = "/nonexistent/file.obj";
  EXPECT_THROW(buildMesh(desc), InputError);
}

}  // namespace
}  // namespace twr
