#include "compare/cube_cross.h"

#include "scene/errors.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace twr {

CrossCell crossCellOfFace(int face) {
  // GL order: +X, -X, +Y, -Y, +Z, -Z.
  constexpr CrossCell kCells[6] = {{2, 1}, {0, 1}, {1, 0}, {1, 2}, {1, 1}, {3, 1}};
  return kCells[std::clamp(face, 0, 5)];
}

Image cubeCrossFromFaces(const std::array<Image, 6>& faces) {
  const int side = faces[0].width;
  for (std::size_t f = 0; f < faces.size(); ++f) {
    if (faces[f].width <= 0 || faces[f].width != faces[f].height || faces[f].width != side) {
      throw InputError("cube cross: face " + std::to_string(f) + " is " + std::to_string(faces[f].width) + "x" +
                       std::to_string(faces[f].height) + "; the six faces must be square and of one size");
    }
  }
  Image cross;
  cross.width = 4 * side;
  cross.height = 3 * side;
  cross.rgba.resize(static_cast<std::size_t>(cross.width) * static_cast<std::size_t>(cross.height) * 4);
  for (std::size_t i = 0; i < cross.rgba.size(); i += 4) std::copy(kCubeCrossEmpty.begin(), kCubeCrossEmpty.end(), &cross.rgba[i]);
  for (int f = 0; f < 6; ++f) {
    const CrossCell cell = crossCellOfFace(f);
    const Image& face = faces[static_cast<std::size_t>(f)];
    for (int y = 0; y < side; ++y) {
      std::copy_n(face.pixel(0, y), static_cast<std::size_t>(side) * 4, cross.pixel(cell.column * side, cell.row * side + y));
    }
  }
  return cross;
}

Image cubeCrossFromCube(const CubeMap& cube, int level) {
  if (cube.levels.empty()) throw InputError("cube cross: the cube map has no levels");
  const CubeMapLevel& l = cube.levels[static_cast<std::size_t>(std::clamp(level, 0, cube.levelCount() - 1))];
  const auto byte = [](float v) {
    return static_cast<std::uint8_t>(std::lround(std::clamp(v, 0.0f, 1.0f) * 255.0f));
  };
  std::array<Image, 6> faces;
  for (int f = 0; f < 6; ++f) {
    Image& face = faces[static_cast<std::size_t>(f)];
    face.width = face.height = l.size;
    face.rgba.resize(static_cast<std::size_t>(l.size) * static_cast<std::size_t>(l.size) * 4);
    for (int y = 0; y < l.size; ++y) {
      for (int x = 0; x < l.size; ++x) {
        const std::size_t i = l.index(f, x, y);
        std::uint8_t* p = face.pixel(x, y);
        p[0] = byte(l.r[i]);
        p[1] = byte(l.g[i]);
        p[2] = byte(l.b[i]);
        p[3] = 255;
      }
    }
  }
  return cubeCrossFromFaces(faces);
}

}  // namespace twr
