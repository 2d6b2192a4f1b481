// The cube cross (compare/cube_cross.h): each face lands in its cell, and the cells that meet
// in the cross hold faces whose shared edges look along the same directions in GL's table.
#include "compare/cube_cross.h"
#include "scene/environment.h"
#include "scene/errors.h"

#include <gtest/gtest.h>

namespace twr {
namespace {

Image solid(int side, std::uint8_t value) {
  Image image;
  image.width = image.height = side;
  image.rgba.assign(static_cast<std::size_t>(side) * side * 4, value);
  return image;
}

TEST(CubeCross, EachFaceFillsItsCellAndTheRestIsEmpty) {
  constexpr int kSide = 4;
  std::array<Image, 6> faces;
  for (int f = 0; f < 6; ++f) faces[static_cast<std::size_t>(f)] = solid(kSide, static_cast<std::uint8_t>(100 + f));
  const Image cross = cubeCrossFromFaces(faces);
  ASSERT_EQ(cross.width, 4 * kSide);
  ASSERT_EQ(cross.height, 3 * kSide);
  int filled = 0;
  for (int row = 0; row < 3; ++row) {
    for (int column = 0; column < 4; ++column) {
      int face = -1;
      for (int f = 0; f < 6; ++f) {
        if (crossCellOfFace(f).column == column && crossCellOfFace(f).row == row) face = f;
      }
      const std::uint8_t* p = cross.pixel(column * kSide + 1, row * kSide + 2);
      if (face < 0) {
        EXPECT_EQ(p[0], kCubeCrossEmpty[0]);
      } else {
        EXPECT_EQ(p[0], 100 + face) << kCubeFaceNames[face];
        ++filled;
      }
    }
  }
  EXPECT_EQ(filled, 6);
}

// Neighbouring cells share an edge: the edge texels of both look along nearly one direction.
TEST(CubeCross, NeighbouringCellsMeetAlongTheEdgeTheyShareOnTheCube) {
  constexpr int kSide = 64;
  const auto direction = [&](int face, int x, int y) {
    return glm::normalize(directionFromCubeCoord(face, (x + 0.5) / kSide, (y + 0.5) / kSide));
  };
  int pairs = 0;
  for (int a = 0; a < 6; ++a) {
    for (int b = 0; b < 6; ++b) {
      const CrossCell ca = crossCellOfFace(a), cb = crossCellOfFace(b);
      for (int i = 0; i < kSide; ++i) {
        if (cb.column == ca.column + 1 && cb.row == ca.row) {  // b right of a
          EXPECT_GT(glm::dot(direction(a, kSide - 1, i), direction(b, 0, i)), 0.999) << kCubeFaceNames[a] << kCubeFaceNames[b];
          pairs += i == 0;
        }
        if (cb.row == ca.row + 1 && cb.column == ca.column) {  // b below a
          EXPECT_GT(glm::dot(direction(a, i, kSide - 1), direction(b, i, 0)), 0.999) << kCubeFaceNames[a] << kCubeFaceNames[b];
          pairs += i == 0;
        }
      }
    }
  }
  EXPECT_EQ(pairs, 5);  // -X|+Z, +Z|+X, +X|-Z across; +Y over +Z, +Z over -Y
}

TEST(CubeCross, FacesOfDifferentSizesAreRefused) {
  std::array<Image, 6> faces;
  for (auto& f : faces) f = solid(4, 1);
  faces[3] = solid(8, 1);
  EXPECT_THROW(cubeCrossFromFaces(faces), InputError);
}

}  // namespace
}  // namespace twr
