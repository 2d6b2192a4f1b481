// Tangent bases for meshes that come without them, as in the normal-mapping tutorial:
// per triangle from the UV deltas, accumulated on shared vertices, Gram-Schmidt against N,
// handedness sign from dot(cross(N, T), B). Never NaN: degenerate UVs (det = 0), vanishing
// tangents and T parallel to N fall back to a basis built from N alone.
#pragma once

#include "scene/mesh.h"

namespace twr {

// Any unit vector perpendicular to n (n must be unit length).
vec3 anyPerpendicular(vec3 n);
// Fills tangentModel of every vertex from positions, normals and uvs.
void computeTangents(Mesh& mesh);
// Area-weighted vertex normals for meshes without them.
void computeNormals(Mesh& mesh);

}  // namespace twr
