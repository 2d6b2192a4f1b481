// Six cube faces laid out as the usual horizontal cross, 4 x 3 faces:
//            +Y
//     -X     +Z     +X     -Z
//            -Y
// each face as a sky box file holds it (scene/environment.h: row 0 is t = 0). With GL's face
// table the shared edges then meet: +Z's right column and +X's left column look along the same
// directions, and so on around the row and up and down from +Z.
#pragma once

#include "scene/environment.h"
#include "scene/image.h"

#include <array>

namespace twr {

// Colour of the cross's empty cells, RGBA8.
inline constexpr std::array<std::uint8_t, 4> kCubeCrossEmpty{24, 24, 28, 255};

// Cell (column, row) of face f (GL order) in the cross.
struct CrossCell {
  int column = 0, row = 0;
};
CrossCell crossCellOfFace(int face);

// The cross of six square faces of one side (GL order). Throws InputError when they are not
// square, differ in size or are empty.
Image cubeCrossFromFaces(const std::array<Image, 6>& faces);

// The cross of a cube map's level `level` (clamped to the chain), each texel's linear value
// times 255, rounded and clamped to [0, 255] (an HDR source's brighter texels show white):
// the environment's source as the GUI shows it.
Image cubeCrossFromCube(const CubeMap& cube, int level = 0);

}  // namespace twr
