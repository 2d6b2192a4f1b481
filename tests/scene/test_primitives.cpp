// Primitives: counts, closed-ness and consistent winding (on positions welded bit for bit),
// unit outward normals, orthonormal tangent frames whose T and B follow +u and +v, the
// sphere's exact parametrisation, the heightfield against the plane and hand-computed
// heights and slopes, and every rejected parameter.
#include "scene/errors.h"
#include "scene/height_field.h"
#include "scene/primitives.h"
#include "scene/scene.h"

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

// ---- heightAt and heightfield ----

// A texture built in code: `reds` row by row, bottom row (v = 0) first; g, b = 0, a = 255.
Texture heightTexture(int width, int height, const std::vector<std::uint8_t>& reds,
                      TextureWrap wrap = TextureWrap::Repeat) {
  Texture texture;
  texture.path = "heights-in-code";
  texture.width = width;
  texture.height = height;
  for (std::uint8_t red : reds) texture.rgba.insert(texture.rgba.end(), {red, 0, 0, 255});
  texture.options.wrap = wrap;
  return texture;
}

// 2 x 2, bottom row 0 and 255, top row 51 and 102: texel centres at u, v = 0.25 and 0.75.
Texture twoByTwo(TextureWrap wrap) { return heightTexture(2, 2, {0, 255, 51, 102}, wrap); }

TEST(HeightAt, BilinearBetweenTexelCentresByHand) {
  const Texture t = twoByTwo(TextureWrap::Repeat);
  EXPECT_EQ(heightAt(t, {0.25, 0.25}), 0.0);          // texel (0, 0)'s centre
  EXPECT_EQ(heightAt(t, {0.75, 0.25}), 1.0);          // texel (1, 0)
  EXPECT_EQ(heightAt(t, {0.25, 0.75}), 51.0 / 255.0);  // texel (0, 1): rows are bottom first
  EXPECT_DOUBLE_EQ(heightAt(t, {0.5, 0.25}), 0.5);    // halfway along u on the bottom row
  EXPECT_DOUBLE_EQ(heightAt(t, {0.5, 0.5}), 102.0 / 255.0);  // (0 + 255 + 51 + 102) / 4 = 102
  // u = 0.375: a quarter of the way from texel 0 to 1; v = 0.25 + 0.5 * 0.25.
  EXPECT_DOUBLE_EQ(heightAt(t, {0.375, 0.375}), (0.75 * 0.75 * 0 + 0.25 * 0.75 * 255 + 0.75 * 0.25 * 51 + 0.25 * 0.25 * 102) / 255.0);
}

TEST(HeightAt, WrapModes) {
  // u = 0 lies halfway between texel 0 and its left neighbour: texel 1 (repeat), texel 0
  // itself (clamp, and mirror, which reflects texel 0 about u = 0).
  EXPECT_DOUBLE_EQ(heightAt(twoByTwo(TextureWrap::Repeat), {0.0, 0.25}), 0.5);
  EXPECT_EQ(heightAt(twoByTwo(TextureWrap::ClampToEdge), {0.0, 0.25}), 0.0);
  EXPECT_EQ(heightAt(twoByTwo(TextureWrap::MirroredRepeat), {0.0, 0.25}), 0.0);
  // Outside [0, 1]: repeat shifts by one, mirror reflects about 1, clamp holds the edge texel.
  EXPECT_EQ(heightAt(twoByTwo(TextureWrap::Repeat), {1.25, 0.25}), 0.0);
  EXPECT_EQ(heightAt(twoByTwo(TextureWrap::Repeat), {-0.75, -0.75}), 0.0);
  EXPECT_EQ(heightAt(twoByTwo(TextureWrap::MirroredRepeat), {1.25, 0.25}), 1.0);
  EXPECT_EQ(heightAt(twoByTwo(TextureWrap::MirroredRepeat), {-0.25, 0.25}), 0.0);
  EXPECT_EQ(heightAt(twoByTwo(TextureWrap::ClampToEdge), {7.0, -3.0}), 1.0);
  // A size that is not a power of two: 3 texels 0, 30, 60; u = 0 is halfway between 60 and 0.
  const Texture three = heightTexture(3, 1, {0, 30, 60});
  EXPECT_DOUBLE_EQ(heightAt(three, {0.0, 0.5}), 30.0 / 255.0);
  EXPECT_DOUBLE_EQ(heightAt(three, {1.0 / 3.0, 0.5}), 15.0 / 255.0);
}

TEST(HeightAt, SrgbUvTransformAndNonFiniteUv) {
  Texture srgb = heightTexture(1, 1, {128});
  EXPECT_EQ(heightAt(srgb, {0.3, 0.7}), 128.0 / 255.0);
  srgb.options.srgb = true;  // the renderers decode it, so the reference does too
  EXPECT_EQ(heightAt(srgb, {0.3, 0.7}), linearFromSrgb(128.0 / 255.0));
  Texture scaled = twoByTwo(TextureWrap::Repeat);
  scaled.options.uvScale = vec2(2.0f);
  scaled.options.uvOffset = vec2(0.5f, 0.0f);
  EXPECT_EQ(heightAt(scaled, {0.125, 0.125}), 1.0);  // looked up at (0.75, 0.25)
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_TRUE(std::isfinite(heightAt(twoByTwo(TextureWrap::Repeat), {nan, 1e300})));
}

TEST(Heightfield, DefaultGridHasOneVertexPerTexel) {
  const Texture t = heightTexture(4, 2, std::vector<std::uint8_t>(8, 0));
  EXPECT_EQ(defaultHeightfieldSegments(t, 1.0f), ivec2(4, 2));
  EXPECT_EQ(defaultHeightfieldSegments(t, 3.0f), ivec2(12, 6));
  Texture hundred;
  hundred.width = hundred.height = 100;
  // 100 * 0.3f = 30.0000012: still 30 segments; 100 * 0.31 = 31.
  EXPECT_EQ(defaultHeightfieldSegments(hundred, 0.3f), ivec2(30, 30));
  EXPECT_EQ(defaultHeightfieldSegments(hundred, 0.305f), ivec2(31, 31));
  EXPECT_EQ(defaultHeightfieldSegments(hundred, 1e-6f), ivec2(1, 1));
  bool capped = true;
  EXPECT_EQ(defaultHeightfieldSegments(hundred, 1.0f, &capped), ivec2(100, 100));
  EXPECT_FALSE(capped);
  // 8192 x 16 texels: the long axis stops at kMaxSegments.
  Texture wide;
  wide.width = 8192;
  wide.height = 16;
  EXPECT_EQ(defaultHeightfieldSegments(wide, 1.0f, &capped), ivec2(kMaxSegments, 16));
  EXPECT_TRUE(capped);
  // 16384^2: 4096^2 per axis would be 33.5 million triangles; both axes shrink to fit 20 million.
  Texture huge;
  huge.width = huge.height = 16384;
  const ivec2 segments = defaultHeightfieldSegments(huge, 1.0f, &capped);
  EXPECT_TRUE(capped);
  EXPECT_EQ(segments.x, segments.y);
  EXPECT_LE(2 * static_cast<std::size_t>(segments.x) * static_cast<std::size_t>(segments.y), kMaxSceneTriangles);
  EXPECT_GT(2 * static_cast<std::size_t>(segments.x + 1) * static_cast<std::size_t>(segments.y + 1), kMaxSceneTriangles);
}

// A constant map: exactly the plane, lowered by (h - 1) heightScale worldPerUv, with the
// plane's own normals and tangents.
TEST(Heightfield, ConstantHeightIsThePlaneShifted) {
  const vec2 size(4.0f, 2.0f);
  const float uvScale = 2.0f, heightScale = 0.25f;
  const Texture t = heightTexture(3, 2, std::vector<std::uint8_t>(6, 153));  // 153 / 255 = 0.6
  const Mesh plane = makePlane(size, uvScale);
  const ivec2 segments(5, 3);
  const Mesh field = makeHeightfield(size, uvScale, t, heightScale, segments);
  ASSERT_EQ(field.vertices.size(), 6u * 4u);
  EXPECT_EQ(field.triangleCount(), 2u * 5u * 3u);
  expectValidFrames(field);
  expectFramesFollowUv(field);
  const double worldPerUv = 4.0 / 2.0;
  const float shift = static_cast<float>((153.0 / 255.0 - 1.0) * heightScale * worldPerUv);
  EXPECT_FLOAT_EQ(shift, -0.2f);
  // The grid's corners in the plane's vertex order: uv (0, 0), (s, 0), (s, s), (0, s).
  const std::size_t stride = static_cast<std::size_t>(segments.x) + 1;
  const std::size_t corners[4] = {0, static_cast<std::size_t>(segments.x), stride * static_cast<std::size_t>(segments.y) + segments.x,
                                  stride * static_cast<std::size_t>(segments.y)};
  for (int i = 0; i < 4; ++i) {
    const Vertex& p = plane.vertices[static_cast<std::size_t>(i)];
    const Vertex& f = field.vertices[corners[i]];
    EXPECT_EQ(f.posModel, p.posModel + vec3(0.0f, shift, 0.0f)) << "corner " << i;
    EXPECT_EQ(f.uv, p.uv) << "corner " << i;
  }
  for (std::size_t i = 0; i < field.vertices.size(); ++i) {
    const Vertex& f = field.vertices[i];
    const double column = static_cast<double>(i % stride), row = static_cast<double>(i / stride);
    EXPECT_EQ(f.posModel.y, shift) << "vertex " << i;
    EXPECT_FLOAT_EQ(f.posModel.x, static_cast<float>(-2.0 + 4.0 * column / 5.0)) << "vertex " << i;
    EXPECT_FLOAT_EQ(f.posModel.z, static_cast<float>(1.0 - 2.0 * row / 3.0)) << "vertex " << i;
    EXPECT_FLOAT_EQ(f.uv.x, static_cast<float>(2.0 * column / 5.0)) << "vertex " << i;
    EXPECT_FLOAT_EQ(f.uv.y, static_cast<float>(2.0 * row / 3.0)) << "vertex " << i;
    EXPECT_EQ(f.nModel, plane.vertices[0].nModel) << "vertex " << i;
    EXPECT_EQ(f.tangentModel, plane.vertices[0].tangentModel) << "vertex " << i;
  }
  // Counter-clockwise seen from +Y, like the plane.
  expectOutwardCcw(field, [](vec3 p) { return vec3(p.x, -10.0f, p.z); });
  // Height 1 everywhere is the plane itself; height scale 0 flattens any map onto it.
  const Mesh top = makeHeightfield(size, uvScale, heightTexture(1, 1, {255}), heightScale, {1, 1});
  const Mesh flattened = makeHeightfield(size, uvScale, twoByTwo(TextureWrap::Repeat), 0.0f, {1, 1});
  const std::size_t oneQuad[4] = {0, 1, 3, 2};  // a 1 x 1 grid in the plane's corner order
  for (int i = 0; i < 4; ++i) {
    EXPECT_EQ(top.vertices[oneQuad[i]].posModel, plane.vertices[static_cast<std::size_t>(i)].posModel);
    EXPECT_EQ(flattened.vertices[oneQuad[i]].posModel, plane.vertices[static_cast<std::size_t>(i)].posModel);
  }
}

// A ramp along u, texels 0, 32, ..., 224 (clamped): between the first and last texel centres
// h(u) = (32 / 255) (8 u - 0.5), so dh/du = 8 * 32 / 255 and the surface rises along +X with
// slope dy/dx = dh/du * heightScale (worldPerUv cancels). N = (-slope, 1, 0) / |.|,
// T = (1, slope, 0) / |.|.
TEST(Heightfield, RampAlongUTiltsTheNormalsByItsSlope) {
  std::vector<std::uint8_t> reds;
  for (int row = 0; row < 2; ++row)
    for (int i = 0; i < 8; ++i) reds.push_back(static_cast<std::uint8_t>(32 * i));
  const Texture ramp = heightTexture(8, 2, reds, TextureWrap::ClampToEdge);
  const vec2 size(3.0f, 3.0f);
  const float heightScale = 0.1f;
  const Mesh field = makeHeightfield(size, 1.0f, ramp, heightScale, defaultHeightfieldSegments(ramp, 1.0f));
  ASSERT_EQ(field.vertices.size(), 9u * 3u);
  expectValidFrames(field);
  expectFramesFollowUv(field);
  expectOutwardCcw(field, [](vec3 p) { return vec3(p.x, -10.0f, p.z); });
  const double slope = 8.0 * 32.0 / 255.0 * static_cast<double>(heightScale);
  const double length = std::sqrt(1.0 + slope * slope);
  const double worldPerUv = 3.0;
  for (std::size_t row = 0; row <= 2; ++row) {
    // Columns 2..6: the vertex and both neighbours lie between the first and last texel centres.
    for (std::size_t column = 2; column <= 6; ++column) {
      const Vertex& v = field.vertices[row * 9 + column];
      const double u = static_cast<double>(column) / 8.0;
      const double h = 32.0 / 255.0 * (8.0 * u - 0.5);
      EXPECT_NEAR(v.posModel.y, (h - 1.0) * heightScale * worldPerUv, 1e-6) << "column " << column;
      EXPECT_NEAR(v.nModel.x, -slope / length, 1e-6) << "column " << column;
      EXPECT_NEAR(v.nModel.y, 1.0 / length, 1e-6) << "column " << column;
      EXPECT_EQ(v.nModel.z, 0.0f) << "column " << column;
      EXPECT_NEAR(v.tangentModel.x, 1.0 / length, 1e-6) << "column " << column;
      EXPECT_NEAR(v.tangentModel.y, slope / length, 1e-6) << "column " << column;
      EXPECT_EQ(v.tangentModel.z, 0.0f) << "column " << column;
      EXPECT_EQ(v.tangentModel.w, 1.0f);
    }
  }
}

// The same ramp along v (towards -Z): the surface rises towards -Z, so N leans towards +Z;
// on a non-square plane the slope in world units is dh/dv heightScale worldPerU / worldPerV.
TEST(Heightfield, RampAlongVLeansTheNormalsTowardsPlusZ) {
  std::vector<std::uint8_t> reds;
  for (int i = 0; i < 8; ++i) reds.insert(reds.end(), {static_cast<std::uint8_t>(32 * i), static_cast<std::uint8_t>(32 * i)});
  const Texture ramp = heightTexture(2, 8, reds, TextureWrap::ClampToEdge);
  const float heightScale = 0.2f;
  const Mesh field = makeHeightfield({2.0f, 4.0f}, 1.0f, ramp, heightScale, {2, 8});
  expectValidFrames(field);
  expectFramesFollowUv(field);
  const double slope = 8.0 * 32.0 / 255.0 * static_cast<double>(heightScale) * 2.0 / 4.0;
  const double length = std::sqrt(1.0 + slope * slope);
  for (std::size_t row = 2; row <= 6; ++row) {
    const Vertex& v = field.vertices[row * 3 + 1];
    EXPECT_EQ(v.nModel.x, 0.0f);
    EXPECT_NEAR(v.nModel.y, 1.0 / length, 1e-6) << "row " << row;
    EXPECT_NEAR(v.nModel.z, slope / length, 1e-6) << "row " << row;
    EXPECT_EQ(vec3(v.tangentModel), vec3(1.0f, 0.0f, 0.0f)) << "row " << row;
  }
}

TEST(Heightfield, RejectsBadParameters) {
  const Texture t = twoByTwo(TextureWrap::Repeat);
  expectRejected([&] { makeHeightfield({0.0f, 1.0f}, 1.0f, t, 0.1f, {1, 1}); }, "heightfield.size[0]");
  expectRejected([&] { makeHeightfield({1.0f, 1.0f}, -1.0f, t, 0.1f, {1, 1}); }, "heightfield.uv_scale");
  expectRejected([&] { makeHeightfield({1.0f, 1.0f}, 1.0f, t, -0.1f, {1, 1}); }, "heightfield.height_scale");
  expectRejected([&] { makeHeightfield({1.0f, 1.0f}, 1.0f, t, 0.1f, {0, 1}); }, "heightfield.resolution[0]");
  expectRejected([&] { makeHeightfield({1.0f, 1.0f}, 1.0f, t, 0.1f, {1, kMaxSegments + 1}); }, "heightfield.resolution[1]");
  expectRejected([&] { makeHeightfield({1.0f, 1.0f}, 1.0f, Texture{}, 0.1f, {1, 1}); }, "heightfield.height_map");
  // 4096 x 4096 quads: 33.5 million triangles > 20 million, refused before any allocation.
  expectRejected([&] { makeHeightfield({1.0f, 1.0f}, 1.0f, t, 0.1f, {kMaxSegments, kMaxSegments}); }, "triangles");
  // A depth past the float range.
  expectRejected([&] { makeHeightfield({3e38f, 1.0f}, 1e-30f, t, 1.0f, {1, 1}); }, "float range");
  MeshDesc desc;
  desc.type = MeshType::Heightfield;
  expectRejected([&] { buildMesh(desc); }, "heightfield.height_map");
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
  desc.type = MeshType::Heightfield;
  desc.heightMap = std::make_shared<const Texture>(twoByTwo(TextureWrap::Repeat));
  EXPECT_EQ(buildMesh(desc).triangleCount(), 2u * 2u * 2u);  // default grid: one vertex per texel
  desc.gridSegments = ivec2(3, 1);
  EXPECT_EQ(buildMesh(desc).triangleCount(), 2u * 3u * 1u);
  // The descriptor's depth is the material's default.
  EXPECT_EQ(MeshDesc{}.heightScale, kDefaultHeightScale);
  desc.type = MeshType::Obj;
  desc.path = "/nonexistent/file.obj";
  EXPECT_THROW(buildMesh(desc), InputError);
}

}  // namespace
}  // namespace twr
