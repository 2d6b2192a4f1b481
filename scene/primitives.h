// Primitives with analytic normals and tangents. All counter-clockwise seen from outside.
#pragma once

#include "scene/mesh.h"

namespace twr {

// 24 vertices (one per face corner, so each face has its own normal), 12 triangles.
Mesh makeCube(float size);
// x = R sin(psi) cos(phi), y = R cos(psi), z = R sin(psi) sin(phi), psi in [0, pi],
// phi in [0, 2 pi]; (stacks + 1) * (slices + 1) vertices; tangent = d/dphi normalised,
// poles use the limit direction so nothing is NaN.
Mesh makeSphere(float radius, int stacks, int slices);
// In XZ facing +Y, centred at the origin; uv from 0 to uvScale across.
Mesh makePlane(vec2 size, float uvScale);
// Side plus two caps, axis along Y, centred at the origin.
Mesh makeCylinder(float radius, float height, int slices);
// Ring in XZ around Y.
Mesh makeTorus(float major, float minor, int rings, int sides);
// Raw triangles: three positions per triangle; uvs/normals optional (empty or one per
// position); missing normals are face normals, tangents from computeTangents.
Mesh makeTriangles(const std::vector<vec3>& positions, const std::vector<vec2>& uvs,
                   const std::vector<vec3>& normals);

// Builds the mesh a description asks for (OBJ through loadObj). Throws InputError.
Mesh buildMesh(const MeshDesc& desc);

}  // namespace twr
