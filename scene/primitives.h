// Primitives with analytic normals and tangents. All counter-clockwise seen from outside.
#pragma once

#include "scene/mesh.h"
#include "scene/texture.h"

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
// The grid a heightfield gets when no segment counts are given: one vertex per height-map
// texel across the uv range [0, uvScale] (uvScale 1 and a W x H map: W x H segments, vertices
// at uv = i / W edge to edge), at least 1 and at most kMaxSegments per axis, and at most
// kMaxSceneTriangles in all (both axes then shrink by the same factor). `capped`, when given,
// says whether the grid came out coarser than the texels.
ivec2 defaultHeightfieldSegments(const Texture& heightMap, float uvScale, bool* capped = nullptr);
// The true displaced surface parallax mapping approximates: makePlane(size, uvScale) (same
// uvs, corners, orientation and winding) on a grid of segments.x by segments.y quads (each in
// [1, kMaxSegments]), every vertex moved along +Y by (h(uv) - 1) heightScale worldPerUv, with
// h = heightAt(heightMap, uv) and worldPerUv = size.x / uvScale, the world length of one uv
// unit along x. So the plane is the top of the relief (height 1) and height 0 lies heightScale
// texture-space units below it, the convention of Material::heightScale; parallax assumes
// square texels in world space (size.x / uvScale == size.y / uvScale). Normals and tangents
// are the displaced surface's: central differences of the grid's heights (read through the
// map's wrap mode one step past the border) give dP/du and dP/dv, N = normalize(dP/du x
// dP/dv), T = normalize(dP/du) (exactly perpendicular to N), w = +1. A constant map gives the
// plane's normals and tangents exactly.
Mesh makeHeightfield(vec2 size, float uvScale, const Texture& heightMap, float heightScale, ivec2 segments);
// Raw triangles: three positions per triangle; uvs/normals optional (empty or one per
// position); missing normals are face normals, tangents from computeTangents.
Mesh makeTriangles(const std::vector<vec3>& positions, const std::vector<vec2>& uvs,
                   const std::vector<vec3>& normals);

// Builds the mesh a description asks for (OBJ through loadObj). Throws InputError.
Mesh buildMesh(const MeshDesc& desc);

}  // namespace twr
