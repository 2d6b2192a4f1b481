// Cube maps made in code for the environment tests: any colour as a function of direction.
#pragma once

#include "scene/environment.h"

#include <array>
#include <string>
#include <vector>

namespace twr {

// A cube of side `size` (with its mip chain) whose texel (x, y) at direction r holds colour(r, x, y).
template <typename Colour>
CubeMap cubeOf(int size, Colour colour) {
  std::array<FaceImage, kCubeFaces> faces;
  for (int f = 0; f < kCubeFaces; ++f) {
    FaceImage& face = faces[static_cast<std::size_t>(f)];
    face.width = face.height = size;
    for (int y = 0; y < size; ++y) {
      for (int x = 0; x < size; ++x) {
        const glm::dvec3 c = colour(glm::normalize(directionFromCubeCoord(f, (x + 0.5) / size, (y + 0.5) / size)), x, y);
        face.rgb.insert(face.rgb.end(), {static_cast<float>(c.x), static_cast<float>(c.y), static_cast<float>(c.z)});
      }
    }
  }
  std::vector<std::string> warnings;
  return cubeMapFromFaces(faces, {"a", "b", "c", "d", "e", "f"}, warnings);
}

}  // namespace twr
