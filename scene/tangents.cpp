#include "scene/tangents.h"

#include <cmath>

namespace twr {

namespace {

// |det| of the 2x2 UV matrix below this fraction of its two products counts as degenerate:
// the two products cancel to rounding noise, so 1/det would amplify noise into a tangent.
// Relative, so small triangles of a dense mesh (det ~ 1e-8) still count as good.
constexpr float kMinRelativeUvDeterminant = 1e-6f;
// An accumulated tangent whose component perpendicular to N is shorter than this fraction
// of the accumulated length is treated as vanishing or parallel to N (unitless).
constexpr float kMinPerpendicularFraction = 1e-4f;

bool isFinite(vec3 v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

// The part of v perpendicular to n (unit n), normalised; false when it is too short to
// carry a direction relative to |v|.
bool perpendicularDirection(vec3 v, vec3 n, vec3& out) {
  const float lengthSquared = glm::dot(v, v);
  if (!(lengthSquared > kMinLengthSquared) || !std::isfinite(lengthSquared)) return false;
  const vec3 perpendicular = v - n * glm::dot(n, v);
  const float perpendicularSquared = glm::dot(perpendicular, perpendicular);
  const float minSquared = kMinPerpendicularFraction * kMinPerpendicularFraction * lengthSquared;
  if (!(perpendicularSquared > minSquared) || !(perpendicularSquared > kMinLengthSquared)) return false;
  out = perpendicular / std::sqrt(perpendicularSquared);
  return isFinite(out);
}

}  // namespace

vec3 anyPerpendicular(vec3 n) {
  // Duff et al. 2017, "Building an Orthonormal Basis, Revisited": continuous except on the
  // plane z = 0's sign flip, exactly unit length for unit n, and never divides by zero
  // because sign + n.z has magnitude >= 1 when sign matches n.z.
  const float sign = std::copysign(1.0f, n.z);
  const float a = -1.0f / (sign + n.z);
  const float b = n.x * n.y * a;
  const vec3 t(1.0f + sign * n.x * n.x * a, sign * b, -sign * n.x);
  // Renormalise: n may be only approximately unit length.
  return safeNormalize(t, vec3(1.0f, 0.0f, 0.0f));
}

void computeTangents(Mesh& mesh) {
  const std::size_t vertexCount = mesh.vertices.size();
  // Per vertex, sums over its triangles of dP/du (tangent) and dP/dv (bitangent).
  std::vector<vec3> tangentSum(vertexCount, vec3(0.0f));
  std::vector<vec3> bitangentSum(vertexCount, vec3(0.0f));

  for (std::size_t first = 0; first + 2 < mesh.indices.size(); first += 3) {
    const std::uint32_t i0 = mesh.indices[first];
    const std::uint32_t i1 = mesh.indices[first + 1];
    const std::uint32_t i2 = mesh.indices[first + 2];
    if (i0 >= vertexCount || i1 >= vertexCount || i2 >= vertexCount) continue;
    const Vertex& v0 = mesh.vertices[i0];
    const Vertex& v1 = mesh.vertices[i1];
    const Vertex& v2 = mesh.vertices[i2];

    // deltaPos1 = deltaUV1.x * T + deltaUV1.y * B, deltaPos2 likewise (the tutorial).
    const vec3 deltaPos1 = v1.posModel - v0.posModel;
    const vec3 deltaPos2 = v2.posModel - v0.posModel;
    const vec2 deltaUv1 = v1.uv - v0.uv;
    const vec2 deltaUv2 = v2.uv - v0.uv;
    const float product1 = deltaUv1.x * deltaUv2.y;
    const float product2 = deltaUv1.y * deltaUv2.x;
    const float det = product1 - product2;
    const float scale = std::fabs(product1) + std::fabs(product2);
    if (!(std::fabs(det) > kMinRelativeUvDeterminant * scale) || det == 0.0f) continue;
    const float r = 1.0f / det;
    const vec3 tangent = (deltaPos1 * deltaUv2.y - deltaPos2 * deltaUv1.y) * r;
    const vec3 bitangent = (deltaPos2 * deltaUv1.x - deltaPos1 * deltaUv2.x) * r;
    if (!isFinite(tangent) || !isFinite(bitangent)) continue;
    for (std::uint32_t index : {i0, i1, i2}) {
      tangentSum[index] += tangent;
      bitangentSum[index] += bitangent;
    }
  }

  for (std::size_t i = 0; i < vertexCount; ++i) {
    Vertex& vertex = mesh.vertices[i];
    const vec3 n = safeNormalize(vertex.nModel, vec3(0.0f, 1.0f, 0.0f));
    vec3 t;
    vec3 b;
    const bool hasTangent = perpendicularDirection(tangentSum[i], n, t);
    const bool hasBitangent = perpendicularDirection(bitangentSum[i], n, b);
    float handedness = 1.0f;
    if (hasTangent) {
      // Gram-Schmidt happened in perpendicularDirection; the sign says whether
      // cross(N, T) points along +v (right-handed TBN) or against it (mirrored UVs).
      if (hasBitangent && glm::dot(glm::cross(n, t), b) < 0.0f) handedness = -1.0f;
    } else if (hasBitangent) {
      // dP/du vanished but dP/dv did not: T = cross(B, N) keeps B along +v with w = +1.
      t = safeNormalize(glm::cross(b, n), anyPerpendicular(n));
    } else {
      t = anyPerpendicular(n);
    }
    vertex.tangentModel = vec4(t, handedness);
  }
}

void computeNormals(Mesh& mesh) {
  const std::size_t vertexCount = mesh.vertices.size();
  std::vector<vec3> normalSum(vertexCount, vec3(0.0f));
  for (std::size_t first = 0; first + 2 < mesh.indices.size(); first += 3) {
    const std::uint32_t i0 = mesh.indices[first];
    const std::uint32_t i1 = mesh.indices[first + 1];
    const std::uint32_t i2 = mesh.indices[first + 2];
    if (i0 >= vertexCount || i1 >= vertexCount || i2 >= vertexCount) continue;
    // |cross| is twice the triangle's area, so the sum is area-weighted.
    const vec3 areaNormal = glm::cross(mesh.vertices[i1].posModel - mesh.vertices[i0].posModel,
                                       mesh.vertices[i2].posModel - mesh.vertices[i0].posModel);
    if (!isFinite(areaNormal)) continue;
    normalSum[i0] += areaNormal;
    normalSum[i1] += areaNormal;
    normalSum[i2] += areaNormal;
  }
  for (std::size_t i = 0; i < vertexCount; ++i) {
    mesh.vertices[i].nModel = safeNormalize(normalSum[i], vec3(0.0f, 1.0f, 0.0f));
  }
}

}  // namespace twr
