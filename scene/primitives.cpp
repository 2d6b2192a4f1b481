#include "scene/primitives.h"

#include "scene/errors.h"
#include "scene/height_field.h"
#include "scene/obj_loader.h"
#include "scene/tangents.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <string>

namespace twr {

namespace {
constexpr double kTwoPi = 2.0 * kPi;

// Fewest segments that still enclose a volume (inclusive lower bounds).
constexpr int kMinSphereStacks = 2;
constexpr int kMinRoundSegments = 3;  // sphere slices, cylinder slices, torus rings and sides
// Relative slack (unitless) before rounding a texel count up: a float uv_scale such as 0.3
// is 0.30000001, and 100 texels * 0.30000001 must still give 30 segments, not 31.
constexpr double kTexelCountSlack = 1e-6;

bool isFinite(vec3 v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }
bool isFinite(vec2 v) { return std::isfinite(v.x) && std::isfinite(v.y); }

void requirePositive(const char* key, float value) {
  if (!(value > 0.0f) || !std::isfinite(value)) {
    throw InputError(std::string(key) + " must be a finite number > 0, got " + std::to_string(value));
  }
}

void requireSegments(const char* key, int value, int minimum) {
  if (value < minimum || value > kMaxSegments) {
    throw InputError(std::string(key) + " must be an integer in [" + std::to_string(minimum) + ", " +
                     std::to_string(kMaxSegments) + "] (inclusive), got " + std::to_string(value));
  }
}

void requireTriangleBudget(const char* what, std::size_t triangles) {
  if (triangles > kMaxSceneTriangles) {
    throw InputError(std::string(what) + " would have " + std::to_string(triangles) +
                     " triangles, more than the limit of " + std::to_string(kMaxSceneTriangles));
  }
}

std::uint32_t index32(std::size_t index) { return static_cast<std::uint32_t>(index); }

void addTriangle(Mesh& mesh, std::size_t a, std::size_t b, std::size_t c) {
  mesh.indices.push_back(index32(a));
  mesh.indices.push_back(index32(b));
  mesh.indices.push_back(index32(c));
}

Vertex makeVertex(vec3 posModel, vec3 nModel, vec3 tangentModel, float handedness, vec2 uv) {
  Vertex vertex;
  vertex.posModel = posModel;
  vertex.nModel = nModel;
  vertex.tangentModel = vec4(tangentModel, handedness);
  vertex.uv = uv;
  return vertex;
}

// Appends a (columns + 1) x (rows + 1) vertex grid's triangles, vertex (column, row) at
// base + row * (columns + 1) + column. Columns run along +u (T), rows along +v (B), and
// cross(T, B) is the outward normal, so (a, b, c) and (a, c, d) are counter-clockwise.
void addGridTriangles(Mesh& mesh, std::size_t base, int columns, int rows) {
  const std::size_t stride = static_cast<std::size_t>(columns) + 1;
  for (int row = 0; row < rows; ++row) {
    for (int column = 0; column < columns; ++column) {
      const std::size_t a = base + row * stride + column;
      const std::size_t b = a + 1;
      const std::size_t c = a + stride + 1;
      const std::size_t d = a + stride;
      addTriangle(mesh, a, b, c);
      addTriangle(mesh, a, c, d);
    }
  }
}

}  // namespace

Mesh makeCube(float size) {
  requirePositive("cube.size", size);
  struct Face {
    vec3 normal;
    vec3 tangent;  // +u; +v is cross(normal, tangent), so every face has w = +1
  };
  // Side faces have +v up; the top has +v towards -Z, the bottom towards +Z.
  const std::array<Face, 6> faces{{
      {{1, 0, 0}, {0, 0, -1}},
      {{-1, 0, 0}, {0, 0, 1}},
      {{0, 1, 0}, {1, 0, 0}},
      {{0, -1, 0}, {1, 0, 0}},
      {{0, 0, 1}, {1, 0, 0}},
      {{0, 0, -1}, {-1, 0, 0}},
  }};
  // Corners in uv order (0,0), (1,0), (1,1), (0,1): signs along T and B.
  const std::array<vec2, 4> cornerUv{{{0, 0}, {1, 0}, {1, 1}, {0, 1}}};
  const float half = 0.5f * size;

  Mesh mesh;
  mesh.vertices.reserve(24);
  mesh.indices.reserve(36);
  for (const Face& face : faces) {
    const vec3 bitangent = glm::cross(face.normal, face.tangent);
    const std::size_t base = mesh.vertices.size();
    for (const vec2& uv : cornerUv) {
      const vec3 posModel =
          half * (face.normal + (2.0f * uv.x - 1.0f) * face.tangent + (2.0f * uv.y - 1.0f) * bitangent);
      mesh.vertices.push_back(makeVertex(posModel, face.normal, face.tangent, 1.0f, uv));
    }
    addTriangle(mesh, base, base + 1, base + 2);
    addTriangle(mesh, base, base + 2, base + 3);
  }
  return mesh;
}

Mesh makeSphere(float radius, int stacks, int slices) {
  requirePositive("sphere.radius", radius);
  requireSegments("sphere.stacks", stacks, kMinSphereStacks);
  requireSegments("sphere.slices", slices, kMinRoundSegments);
  // The first and last stack lose one triangle per slice (see the pole note below).
  const std::size_t triangleCount = static_cast<std::size_t>(slices) * (2 * static_cast<std::size_t>(stacks) - 2);
  requireTriangleBudget("sphere", triangleCount);

  Mesh mesh;
  mesh.vertices.reserve(static_cast<std::size_t>(stacks + 1) * (slices + 1));
  mesh.indices.reserve(3 * triangleCount);
  for (int stack = 0; stack <= stacks; ++stack) {
    const double psi = kPi * stack / stacks;
    // Exact poles: sin(pi) in floating point is not 0.
    const double sinPsi = (stack == 0 || stack == stacks) ? 0.0 : std::sin(psi);
    const double cosPsi = stack == 0 ? 1.0 : (stack == stacks ? -1.0 : std::cos(psi));
    for (int slice = 0; slice <= slices; ++slice) {
      // The seam column repeats column 0's position bit for bit (u = 1 instead of 0).
      const double phi = kTwoPi * (slice % slices) / slices;
      const double sinPhi = std::sin(phi);
      const double cosPhi = std::cos(phi);
      const vec3 nModel(static_cast<float>(sinPsi * cosPhi), static_cast<float>(cosPsi),
                        static_cast<float>(sinPsi * sinPhi));
      // d/dphi = R sin(psi) (-sin phi, 0, cos phi); its direction, (-sin phi, 0, cos phi),
      // is also the limit at the poles where the derivative itself vanishes.
      const vec3 tangentModel(static_cast<float>(-sinPhi), 0.0f, static_cast<float>(cosPhi));
      // +v = -d/dpsi = -cross(N, T): this parametrisation is mirrored seen from outside,
      // so the handedness is -1 everywhere (B = w * cross(N, T) points along +v).
      const float handedness = -1.0f;
      const vec2 uv(static_cast<float>(slice) / static_cast<float>(slices),
                    1.0f - static_cast<float>(stack) / static_cast<float>(stacks));
      mesh.vertices.push_back(makeVertex(radius * nModel, nModel, tangentModel, handedness, uv));
    }
  }

  // Quad (stack, slice): a top-left, d top-right (next phi), b bottom-left (next psi),
  // c bottom-right. cross(d/dphi, d/dpsi) points outward, so (a, d, b) and (d, c, b) are
  // counter-clockwise seen from outside. At the north pole a == d in position and at the
  // south pole b == c, so those triangles have zero area and are skipped.
  const std::size_t stride = static_cast<std::size_t>(slices) + 1;
  for (int stack = 0; stack < stacks; ++stack) {
    for (int slice = 0; slice < slices; ++slice) {
      const std::size_t a = stack * stride + slice;
      const std::size_t d = a + 1;
      const std::size_t b = a + stride;
      const std::size_t c = b + 1;
      if (stack != 0) addTriangle(mesh, a, d, b);
      if (stack != stacks - 1) addTriangle(mesh, d, c, b);
    }
  }
  return mesh;
}

Mesh makePlane(vec2 size, float uvScale) {
  requirePositive("plane.size[0]", size.x);
  requirePositive("plane.size[1]", size.y);
  requirePositive("plane.uv_scale", uvScale);
  const float halfWidth = 0.5f * size.x;
  const float halfDepth = 0.5f * size.y;
  const vec3 nModel(0.0f, 1.0f, 0.0f);
  const vec3 tangentModel(1.0f, 0.0f, 0.0f);  // +u along +X; +v = cross(N, T) = -Z
  Mesh mesh;
  mesh.vertices = {
      makeVertex({-halfWidth, 0.0f, halfDepth}, nModel, tangentModel, 1.0f, {0.0f, 0.0f}),
      makeVertex({halfWidth, 0.0f, halfDepth}, nModel, tangentModel, 1.0f, {uvScale, 0.0f}),
      makeVertex({halfWidth, 0.0f, -halfDepth}, nModel, tangentModel, 1.0f, {uvScale, uvScale}),
      makeVertex({-halfWidth, 0.0f, -halfDepth}, nModel, tangentModel, 1.0f, {0.0f, uvScale}),
  };
  mesh.indices = {0, 1, 2, 0, 2, 3};
  return mesh;
}

ivec2 defaultHeightfieldSegments(const Texture& heightMap, float uvScale, bool* capped) {
  // Texels across [0, uvScale] along one axis, through the map's own uv scale.
  const auto texelsAcross = [&](int texels, float mapUvScale) {
    const double across = static_cast<double>(texels) * std::fabs(static_cast<double>(mapUvScale)) *
                          std::fabs(static_cast<double>(uvScale));
    const double wanted = std::ceil(across * (1.0 - kTexelCountSlack));
    return std::isfinite(wanted) ? std::max(wanted, 1.0) : static_cast<double>(kMaxSegments) + 1.0;
  };
  const double wantedX = texelsAcross(heightMap.width, heightMap.options.uvScale.x);
  const double wantedZ = texelsAcross(heightMap.height, heightMap.options.uvScale.y);
  double segmentsX = std::min(wantedX, static_cast<double>(kMaxSegments));
  double segmentsZ = std::min(wantedZ, static_cast<double>(kMaxSegments));
  const double triangles = 2.0 * segmentsX * segmentsZ;
  if (triangles > static_cast<double>(kMaxSceneTriangles)) {
    const double shrink = std::sqrt(static_cast<double>(kMaxSceneTriangles) / triangles);
    segmentsX = std::max(1.0, std::floor(segmentsX * shrink));
    segmentsZ = std::max(1.0, std::floor(segmentsZ * shrink));
  }
  if (capped) *capped = segmentsX < wantedX || segmentsZ < wantedZ;
  return ivec2(static_cast<int>(segmentsX), static_cast<int>(segmentsZ));
}

Mesh makeHeightfield(vec2 size, float uvScale, const Texture& heightMap, float heightScale, ivec2 segments) {
  requirePositive("heightfield.size[0]", size.x);
  requirePositive("heightfield.size[1]", size.y);
  requirePositive("heightfield.uv_scale", uvScale);
  if (!(heightScale >= 0.0f) || !std::isfinite(heightScale)) {
    throw InputError("heightfield.height_scale must be a finite number >= 0, got " + std::to_string(heightScale));
  }
  const std::size_t texelCount = heightMap.width > 0 && heightMap.height > 0
                                     ? static_cast<std::size_t>(heightMap.width) * static_cast<std::size_t>(heightMap.height)
                                     : 0;
  if (texelCount == 0 || heightMap.rgba.size() < 4 * texelCount) {
    throw InputError("heightfield.height_map " + heightMap.path + " holds no texels");
  }
  requireSegments("heightfield.resolution[0]", segments.x, 1);
  requireSegments("heightfield.resolution[1]", segments.y, 1);
  const std::size_t columns = static_cast<std::size_t>(segments.x);
  const std::size_t rows = static_cast<std::size_t>(segments.y);
  const std::size_t triangleCount = 2 * columns * rows;
  requireTriangleBudget("heightfield", triangleCount);

  // World length of one uv unit along x (u) and z (v); the depth is measured in the first.
  const double worldPerU = static_cast<double>(size.x) / uvScale;
  const double worldPerV = static_cast<double>(size.y) / uvScale;
  const double depthWorld = static_cast<double>(heightScale) * worldPerU;  // height 1 -> 0
  if (!std::isfinite(static_cast<float>(depthWorld))) {
    throw InputError("heightfield: height_scale * size[0] / uv_scale = " + std::to_string(depthWorld) +
                     " world units is outside the float range");
  }

  // Heights on the grid plus a ring one step outside it, so every vertex, border included,
  // gets a central difference; the ring reads the map through its wrap mode. Grid indices
  // run over [-1, n + 1] (signed); the vertices are [0, n].
  const std::ptrdiff_t columnCount = segments.x, rowCount = segments.y;
  const std::ptrdiff_t ringStride = columnCount + 3;
  const auto gridU = [&](std::ptrdiff_t column) {
    return static_cast<double>(uvScale) * static_cast<double>(column) / static_cast<double>(columnCount);
  };
  const auto gridV = [&](std::ptrdiff_t row) {
    return static_cast<double>(uvScale) * static_cast<double>(row) / static_cast<double>(rowCount);
  };
  std::vector<double> ringHeights(static_cast<std::size_t>(ringStride * (rowCount + 3)));
  const auto gridHeight = [&](std::ptrdiff_t column, std::ptrdiff_t row) -> double& {
    return ringHeights[static_cast<std::size_t>((row + 1) * ringStride + column + 1)];
  };
  for (std::ptrdiff_t row = -1; row <= rowCount + 1; ++row) {
    for (std::ptrdiff_t column = -1; column <= columnCount + 1; ++column) {
      gridHeight(column, row) = heightAt(heightMap, glm::dvec2(gridU(column), gridV(row)));
    }
  }

  Mesh mesh;
  mesh.vertices.reserve((columns + 1) * (rows + 1));
  mesh.indices.reserve(3 * triangleCount);
  const double uStep = static_cast<double>(uvScale) / static_cast<double>(columnCount);
  const double vStep = static_cast<double>(uvScale) / static_cast<double>(rowCount);
  for (std::ptrdiff_t row = 0; row <= rowCount; ++row) {
    for (std::ptrdiff_t column = 0; column <= columnCount; ++column) {
      // As makePlane: uv (0, 0) at (-x, +z), u along +X, v along -Z. The corners land exactly
      // on +-size / 2 (size * -0.5 and size * 0.5 are exact).
      const double across = static_cast<double>(column) / static_cast<double>(columnCount);  // 0 .. 1 along u
      const double deep = static_cast<double>(row) / static_cast<double>(rowCount);          // 0 .. 1 along v
      const double xModel = static_cast<double>(size.x) * (across - 0.5);
      const double zModel = static_cast<double>(size.y) * (0.5 - deep);
      const double yModel = (gridHeight(column, row) - 1.0) * depthWorld;
      // dP/du = (worldPerU, dy/du, 0) and dP/dv = (0, dy/dv, -worldPerV), dy from the neighbours.
      const double dyDu = (gridHeight(column + 1, row) - gridHeight(column - 1, row)) * depthWorld / (2.0 * uStep);
      const double dyDv = (gridHeight(column, row + 1) - gridHeight(column, row - 1)) * depthWorld / (2.0 * vStep);
      const glm::dvec3 dPdu(worldPerU, dyDu, 0.0);
      const glm::dvec3 dPdv(0.0, dyDv, -worldPerV);
      const glm::dvec3 normal = glm::cross(dPdu, dPdv);
      const double normalLength = glm::length(normal);
      const double tangentLength = glm::length(dPdu);
      // Never NaN: a product past the double range falls back to the flat plane's frame.
      const bool usable = normalLength > 0.0 && std::isfinite(normalLength) && std::isfinite(tangentLength);
      const vec3 nModel = usable ? vec3(normal / normalLength) : vec3(0.0f, 1.0f, 0.0f);
      const vec3 tangentModel = usable ? vec3(dPdu / tangentLength) : vec3(1.0f, 0.0f, 0.0f);
      const vec3 posModel(static_cast<float>(xModel), static_cast<float>(yModel), static_cast<float>(zModel));
      const vec2 uv(static_cast<float>(gridU(column)), static_cast<float>(gridV(row)));
      mesh.vertices.push_back(makeVertex(posModel, nModel, tangentModel, 1.0f, uv));
    }
  }
  addGridTriangles(mesh, 0, segments.x, segments.y);
  return mesh;
}

Mesh makeCylinder(float radius, float height, int slices) {
  requirePositive("cylinder.radius", radius);
  requirePositive("cylinder.height", height);
  requireSegments("cylinder.slices", slices, kMinRoundSegments);
  // Side: 2 per slice; each cap: 1 per slice.
  const std::size_t triangleCount = 4 * static_cast<std::size_t>(slices);
  requireTriangleBudget("cylinder", triangleCount);
  const float halfHeight = 0.5f * height;

  // Angle theta around Y from +Z towards +X: x = r sin(theta), z = r cos(theta), so u grows
  // to the right seen from outside (not mirrored, w = +1).
  std::vector<vec3> ringDirection(static_cast<std::size_t>(slices) + 1);
  for (int slice = 0; slice <= slices; ++slice) {
    const double theta = kTwoPi * (slice % slices) / slices;
    ringDirection[slice] = vec3(static_cast<float>(std::sin(theta)), 0.0f, static_cast<float>(std::cos(theta)));
  }

  Mesh mesh;
  mesh.vertices.reserve(2 * (static_cast<std::size_t>(slices) + 1) + 2 * (static_cast<std::size_t>(slices) + 1));
  mesh.indices.reserve(3 * triangleCount);

  // Side: row 0 at the bottom (v = 0), row 1 at the top (v = 1); B = +Y = cross(N, T).
  for (int row = 0; row <= 1; ++row) {
    const float y = row == 0 ? -halfHeight : halfHeight;
    for (int slice = 0; slice <= slices; ++slice) {
      const vec3 nModel = ringDirection[slice];
      const vec3 tangentModel(nModel.z, 0.0f, -nModel.x);  // d/dtheta direction
      const vec3 posModel(radius * nModel.x, y, radius * nModel.z);
      const vec2 uv(static_cast<float>(slice) / static_cast<float>(slices), static_cast<float>(row));
      mesh.vertices.push_back(makeVertex(posModel, nModel, tangentModel, 1.0f, uv));
    }
  }
  addGridTriangles(mesh, 0, slices, 1);

  // Caps: a centre and a ring of their own vertices (own normal), uv projected from above
  // (top: +u = +X, +v = -Z) or below (bottom: +u = +X, +v = +Z), like the cube's faces.
  for (int cap = 0; cap < 2; ++cap) {
    const bool top = cap == 1;
    const float y = top ? halfHeight : -halfHeight;
    const vec3 nModel(0.0f, top ? 1.0f : -1.0f, 0.0f);
    const vec3 tangentModel(1.0f, 0.0f, 0.0f);
    const float vFromZ = top ? -0.5f : 0.5f;
    const std::size_t centre = mesh.vertices.size();
    mesh.vertices.push_back(makeVertex({0.0f, y, 0.0f}, nModel, tangentModel, 1.0f, {0.5f, 0.5f}));
    for (int slice = 0; slice < slices; ++slice) {
      const vec3 direction = ringDirection[slice];
      const vec3 posModel(radius * direction.x, y, radius * direction.z);
      const vec2 uv(0.5f + 0.5f * direction.x, 0.5f + vFromZ * direction.z);
      mesh.vertices.push_back(makeVertex(posModel, nModel, tangentModel, 1.0f, uv));
    }
    // Theta grows counter-clockwise seen from +Y, so (centre, k, k+1) faces up.
    for (int slice = 0; slice < slices; ++slice) {
      const std::size_t current = centre + 1 + slice;
      const std::size_t next = centre + 1 + (slice + 1) % slices;
      if (top) {
        addTriangle(mesh, centre, current, next);
      } else {
        addTriangle(mesh, centre, next, current);
      }
    }
  }
  return mesh;
}

Mesh makeTorus(float major, float minor, int rings, int sides) {
  requirePositive("torus.major", major);
  requirePositive("torus.minor", minor);
  if (!(minor < major)) {
    throw InputError("torus.minor must be < torus.major (a self-intersecting torus has no well-defined outside), got minor " +
                     std::to_string(minor) + " and major " + std::to_string(major));
  }
  requireSegments("torus.rings", rings, kMinRoundSegments);
  requireSegments("torus.sides", sides, kMinRoundSegments);
  const std::size_t triangleCount = 2 * static_cast<std::size_t>(rings) * static_cast<std::size_t>(sides);
  requireTriangleBudget("torus", triangleCount);

  // theta around Y (as the cylinder: from +Z towards +X) along u; phi around the tube from
  // the outer equator towards +Y along v. N = cos(phi) radial + sin(phi) Y,
  // T = d/dtheta direction, cross(N, T) = d/dphi direction, so w = +1.
  Mesh mesh;
  mesh.vertices.reserve(static_cast<std::size_t>(rings + 1) * (sides + 1));
  mesh.indices.reserve(3 * triangleCount);
  for (int side = 0; side <= sides; ++side) {
    const double phi = kTwoPi * (side % sides) / sides;
    const double cosPhi = std::cos(phi);
    const double sinPhi = std::sin(phi);
    for (int ring = 0; ring <= rings; ++ring) {
      const double theta = kTwoPi * (ring % rings) / rings;
      const double sinTheta = std::sin(theta);
      const double cosTheta = std::cos(theta);
      const vec3 nModel(static_cast<float>(cosPhi * sinTheta), static_cast<float>(sinPhi),
                        static_cast<float>(cosPhi * cosTheta));
      const double distanceFromAxis = major + minor * cosPhi;
      const vec3 posModel(static_cast<float>(distanceFromAxis * sinTheta), static_cast<float>(minor * sinPhi),
                          static_cast<float>(distanceFromAxis * cosTheta));
      const vec3 tangentModel(static_cast<float>(cosTheta), 0.0f, static_cast<float>(-sinTheta));
      const vec2 uv(static_cast<float>(ring) / static_cast<float>(rings),
                    static_cast<float>(side) / static_cast<float>(sides));
      mesh.vertices.push_back(makeVertex(posModel, nModel, tangentModel, 1.0f, uv));
    }
  }
  addGridTriangles(mesh, 0, rings, sides);
  return mesh;
}

Mesh makeTriangles(const std::vector<vec3>& positions, const std::vector<vec2>& uvs,
                   const std::vector<vec3>& normals) {
  if (positions.empty() || positions.size() % 3 != 0) {
    throw InputError("triangles.positions must hold a positive multiple of 3 points, got " +
                     std::to_string(positions.size()));
  }
  requireTriangleBudget("triangles", positions.size() / 3);
  if (!uvs.empty() && uvs.size() != positions.size()) {
    throw InputError("triangles.uvs must be empty or hold one uv per position (" + std::to_string(positions.size()) +
                     "), got " + std::to_string(uvs.size()));
  }
  if (!normals.empty() && normals.size() != positions.size()) {
    throw InputError("triangles.normals must be empty or hold one normal per position (" +
                     std::to_string(positions.size()) + "), got " + std::to_string(normals.size()));
  }
  for (std::size_t i = 0; i < positions.size(); ++i) {
    if (!isFinite(positions[i])) throw InputError("triangles.positions[" + std::to_string(i) + "] is not finite");
    if (!uvs.empty() && !isFinite(uvs[i])) throw InputError("triangles.uvs[" + std::to_string(i) + "] is not finite");
    if (!normals.empty() && !isFinite(normals[i])) {
      throw InputError("triangles.normals[" + std::to_string(i) + "] is not finite");
    }
  }

  Mesh mesh;
  mesh.vertices.resize(positions.size());
  mesh.indices.resize(positions.size());
  for (std::size_t first = 0; first < positions.size(); first += 3) {
    const vec3 faceNormal = safeNormalize(
        glm::cross(positions[first + 1] - positions[first], positions[first + 2] - positions[first]),
        vec3(0.0f, 1.0f, 0.0f));
    for (std::size_t i = first; i < first + 3; ++i) {
      Vertex& vertex = mesh.vertices[i];
      vertex.posModel = positions[i];
      vertex.uv = uvs.empty() ? vec2(0.0f) : uvs[i];
      // A zero given normal falls back to the face normal rather than to NaN.
      vertex.nModel = normals.empty() ? faceNormal : safeNormalize(normals[i], faceNormal);
      mesh.indices[i] = index32(i);
    }
  }
  computeTangents(mesh);
  return mesh;
}

Mesh buildMesh(const MeshDesc& desc) {
  switch (desc.type) {
    case MeshType::Cube:
      return makeCube(desc.size);
    case MeshType::Sphere:
      return makeSphere(desc.radius, desc.stacks, desc.slices);
    case MeshType::Plane:
      return makePlane(desc.planeSize, desc.uvScale);
    case MeshType::Cylinder:
      return makeCylinder(desc.radius, desc.height, desc.slices);
    case MeshType::Torus:
      return makeTorus(desc.major, desc.minor, desc.rings, desc.sides);
    case MeshType::Triangles:
      return makeTriangles(desc.positions, desc.uvs, desc.normals);
    case MeshType::Heightfield: {
      if (!desc.heightMap) throw InputError("heightfield.height_map: missing; a heightfield needs a height map");
      const ivec2 segments =
          desc.gridSegments == ivec2(0) ? defaultHeightfieldSegments(*desc.heightMap, desc.uvScale) : desc.gridSegments;
      return makeHeightfield(desc.planeSize, desc.uvScale, *desc.heightMap, desc.heightScale, segments);
    }
    case MeshType::Obj: {
      ObjReadOptions read;  // geometry only: parts follow the MTL's materials, no map is read
      read.readMtl = desc.objMtl;
      read.loadMaps = false;
      ObjModel model = loadObj(desc.path, {}, read);
      if (desc.objPart >= 0) {
        if (desc.objPart >= static_cast<int>(model.meshes.size())) {
          throw InputError(desc.path + ": has " + std::to_string(model.meshes.size()) + " parts, part " +
                           std::to_string(desc.objPart) + " was asked for");
        }
        return std::move(model.meshes[static_cast<std::size_t>(desc.objPart)]);
      }
      Mesh merged;
      for (const Mesh& part : model.meshes) {
        const std::uint32_t base = index32(merged.vertices.size());
        merged.vertices.insert(merged.vertices.end(), part.vertices.begin(), part.vertices.end());
        for (std::uint32_t index : part.indices) merged.indices.push_back(base + index);
      }
      return merged;
    }
  }
  throw InputError("mesh: unknown mesh type");
}

}  // namespace twr
