// Environment maps (scene/environment.h): GL's cube table both ways, the seamless neighbour
// table against the one measured on llvmpipe, face images and equirects made into cubes with
// their mip chains, and every class of bad face set refused with the face's file.
#include "scene/environment.h"
#include "scene/errors.h"
#include "scene/image.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <random>
#include <string>

namespace twr {
namespace {

const std::filesystem::path kOut = std::filesystem::path(TWINRASTER_TEST_OUT) / "environment";

FaceImage constantFace(int width, int height, vec3 colour) {
  FaceImage f;
  f.width = width;
  f.height = height;
  for (int i = 0; i < width * height; ++i) {
    f.rgb.push_back(colour.r);
    f.rgb.push_back(colour.g);
    f.rgb.push_back(colour.b);
  }
  return f;
}

std::array<std::string, kCubeFaces> facePaths() {
  return {"px.png", "nx.png", "py.png", "ny.png", "pz.png", "nz.png"};
}

TEST(CubeCoord, EveryTexelCentreRoundTripsThroughItsDirection) {
  constexpr int kSize = 16;
  for (int face = 0; face < kCubeFaces; ++face) {
    for (int y = 0; y < kSize; ++y) {
      for (int x = 0; x < kSize; ++x) {
        const double s = (x + 0.5) / kSize, t = (y + 0.5) / kSize;
        const CubeCoord c = cubeCoordFromDirection(directionFromCubeCoord(face, s, t) * 3.7);
        EXPECT_EQ(c.face, face);
        EXPECT_NEAR(c.s, s, 1e-12);
        EXPECT_NEAR(c.t, t, 1e-12);
      }
    }
  }
}

// The GL table's faces for the axes, and the tie rule llvmpipe follows (measured: z wins a
// tie, then y; a zero vector reads +Z; docs/environment.md).
TEST(CubeCoord, AxesAndTiesPickTheFacesLlvmpipePicks) {
  EXPECT_EQ(cubeCoordFromDirection({1, 0, 0}).face, 0);
  EXPECT_EQ(cubeCoordFromDirection({-1, 0, 0}).face, 1);
  EXPECT_EQ(cubeCoordFromDirection({0, 1, 0}).face, 2);
  EXPECT_EQ(cubeCoordFromDirection({0, -1, 0}).face, 3);
  EXPECT_EQ(cubeCoordFromDirection({0, 0, 1}).face, 4);
  EXPECT_EQ(cubeCoordFromDirection({0, 0, -1}).face, 5);
  EXPECT_EQ(cubeCoordFromDirection({1, 1, 0.3}).face, 2);
  EXPECT_EQ(cubeCoordFromDirection({1, -1, 0}).face, 3);
  EXPECT_EQ(cubeCoordFromDirection({1, 1, 1}).face, 4);
  EXPECT_EQ(cubeCoordFromDirection({1, -1, -1}).face, 5);
  EXPECT_EQ(cubeCoordFromDirection({0, 0, 0}).face, 4);
  // The +X face seen from inside: s runs towards -Z, t towards -Y (the GL table).
  const CubeCoord c = cubeCoordFromDirection({1, -0.5, -0.5});
  EXPECT_EQ(c.face, 0);
  EXPECT_DOUBLE_EQ(c.s, 0.75);
  EXPECT_DOUBLE_EQ(c.t, 0.75);
}

// The neighbour across each edge, as measured on llvmpipe's seamless filter (m = size - 1,
// `along` = the coordinate that stays): written out here independently of the derivation.
TEST(CubeEdgeTable, MatchesTheNeighboursMeasuredOnLlvmpipe) {
  struct Expected {
    int face;
    float xAtLast, xPerAlong, yAtLast, yPerAlong;
  };
  // Rows: source face +X, -X, +Y, -Y, +Z, -Z; columns: edge x < 0, x > m, y < 0, y > m.
  const Expected expected[kCubeFaces][4] = {
      {{4, 1, 0, 0, 1}, {5, 0, 0, 0, 1}, {2, 1, 0, 1, -1}, {3, 1, 0, 0, 1}},    // +X
      {{5, 1, 0, 0, 1}, {4, 0, 0, 0, 1}, {2, 0, 0, 0, 1}, {3, 0, 0, 1, -1}},    // -X
      {{1, 0, 1, 0, 0}, {0, 1, -1, 0, 0}, {5, 1, -1, 0, 0}, {4, 0, 1, 0, 0}},   // +Y
      {{1, 1, -1, 1, 0}, {0, 0, 1, 1, 0}, {4, 0, 1, 1, 0}, {5, 1, -1, 1, 0}},   // -Y
      {{1, 1, 0, 0, 1}, {0, 0, 0, 0, 1}, {2, 0, 1, 1, 0}, {3, 0, 1, 0, 0}},     // +Z
      {{0, 1, 0, 0, 1}, {1, 0, 0, 0, 1}, {2, 1, -1, 0, 0}, {3, 1, -1, 1, 0}},   // -Z
  };
  const CubeEdgeTable& t = cubeEdgeTable();
  for (int face = 0; face < kCubeFaces; ++face) {
    for (int edge = 0; edge < 4; ++edge) {
      const std::size_t k = static_cast<std::size_t>(4 * face + edge);
      const Expected& e = expected[face][edge];
      SCOPED_TRACE("face " + std::string(kCubeFaceNames[face]) + ", edge " + std::to_string(edge));
      EXPECT_EQ(t.face[k], static_cast<float>(e.face));
      EXPECT_EQ(t.xAtLast[k], e.xAtLast);
      EXPECT_EQ(t.xPerAlong[k], e.xPerAlong);
      EXPECT_EQ(t.yAtLast[k], e.yAtLast);
      EXPECT_EQ(t.yPerAlong[k], e.yPerAlong);
    }
  }
}

TEST(CubeMapFromFaces, KeepsEveryTexelInGlOrderAndBuildsTheChain) {
  std::array<FaceImage, kCubeFaces> faces;
  for (int f = 0; f < kCubeFaces; ++f) faces[static_cast<std::size_t>(f)] = constantFace(8, 8, vec3(0.1f * f, 0.5f, 1.0f));
  faces[0].rgb[0] = 0.25f;  // face +X, top-left texel of the image: row 0 (t = 0), column 0
  std::vector<std::string> warnings;
  const CubeMap cube = cubeMapFromFaces(faces, facePaths(), warnings);
  EXPECT_TRUE(warnings.empty());
  ASSERT_EQ(cube.levelCount(), 4);  // 8, 4, 2, 1
  EXPECT_EQ(cube.levels[3].size, 1);
  EXPECT_EQ(cube.levels[0].texel(0, 0, 0).r, 0.25f);
  EXPECT_EQ(cube.levels[0].texel(3, 5, 2), vec3(0.3f, 0.5f, 1.0f));
  // Level 1's first texel of +X: the mean of its 2x2 block, in double.
  EXPECT_EQ(cube.levels[1].texel(0, 0, 0).r, static_cast<float>((0.25 + 3.0 * 0.0) / 4.0));
  EXPECT_EQ(cube.levels[3].texel(5, 0, 0).g, 0.5f);
}

TEST(CubeMapFromFaces, RefusesFacesThatCannotMakeACube) {
  const auto attempt = [](std::array<FaceImage, kCubeFaces> faces) -> std::string {
    std::vector<std::string> warnings;
    try {
      cubeMapFromFaces(faces, facePaths(), warnings);
    } catch (const InputError& e) {
      return e.what();
    }
    return "";
  };
  std::array<FaceImage, kCubeFaces> faces;
  for (FaceImage& f : faces) f = constantFace(8, 8, vec3(1.0f));
  faces[3] = constantFace(8, 4, vec3(1.0f));
  std::string message = attempt(faces);
  EXPECT_NE(message.find("ny.png"), std::string::npos) << message;
  EXPECT_NE(message.find("square"), std::string::npos) << message;
  faces[3] = constantFace(4, 4, vec3(1.0f));
  message = attempt(faces);
  EXPECT_NE(message.find("ny.png"), std::string::npos) << message;
  EXPECT_NE(message.find("one size"), std::string::npos) << message;
  for (FaceImage& f : faces) f = constantFace(6, 6, vec3(1.0f));
  message = attempt(faces);
  EXPECT_NE(message.find("power-of-two"), std::string::npos) << message;
}

TEST(CubeMapFromFaces, ReducesAFaceLargerThanTheLimitWithAWarning) {
  std::array<FaceImage, kCubeFaces> faces;
  for (FaceImage& f : faces) f = constantFace(2 * kMaxCubeFaceSize, 2 * kMaxCubeFaceSize, vec3(0.5f, 0.25f, 1.0f));
  std::vector<std::string> warnings;
  const CubeMap cube = cubeMapFromFaces(faces, facePaths(), warnings);
  EXPECT_EQ(cube.size(), kMaxCubeFaceSize);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].find("px.png"), std::string::npos) << warnings[0];
  EXPECT_EQ(cube.levels[0].texel(2, 7, 9), vec3(0.5f, 0.25f, 1.0f));
}

// Each face texel of a cube made from an equirect is the equirect's value in its direction:
// with an image whose colour is the direction's (u, v), the texel holds its own direction.
TEST(CubeMapFromEquirect, EveryTexelLooksWhereItsDirectionPoints) {
  constexpr int kWidth = 256, kHeight = 128, kSize = 16;
  FaceImage equirect;
  equirect.width = kWidth;
  equirect.height = kHeight;
  for (int y = 0; y < kHeight; ++y) {
    for (int x = 0; x < kWidth; ++x) {
      equirect.rgb.push_back((x + 0.5f) / kWidth);
      equirect.rgb.push_back((y + 0.5f) / kHeight);
      equirect.rgb.push_back(0.0f);
    }
  }
  const CubeMap cube = cubeMapFromEquirect(equirect, kSize, "sky.hdr");
  ASSERT_EQ(cube.size(), kSize);
  for (int face = 0; face < kCubeFaces; ++face) {
    for (int y = 0; y < kSize; ++y) {
      for (int x = 0; x < kSize; ++x) {
        const glm::dvec2 uv = equirectUvFromDirection(directionFromCubeCoord(face, (x + 0.5) / kSize, (y + 0.5) / kSize));
        const vec3 texel = cube.levels[0].texel(face, x, y);
        // Away from the seam at u = 0 / 1 (where the bilinear read wraps) and the poles.
        if (uv.x < 0.02 || uv.x > 0.98 || uv.y < 0.02 || uv.y > 0.98) continue;
        EXPECT_NEAR(texel.r, uv.x, 1e-5) << "face " << face << " texel " << x << ", " << y;
        EXPECT_NEAR(texel.g, uv.y, 1e-5) << "face " << face << " texel " << x << ", " << y;
      }
    }
  }
  // -Z looks at the image's centre, +Y at its top row.
  EXPECT_NEAR(equirectUvFromDirection({0, 0, -1}).x, 0.5, 1e-12);
  EXPECT_NEAR(equirectUvFromDirection({1, 0, 0}).x, 0.75, 1e-12);
  EXPECT_NEAR(equirectUvFromDirection({0, 1, 0}).y, 0.0, 1e-12);
  EXPECT_EQ(defaultCubeSizeForEquirect(2048), 512);
  EXPECT_EQ(defaultCubeSizeForEquirect(1000), 256);
  EXPECT_EQ(defaultCubeSizeForEquirect(16384), kMaxCubeFaceSize);
}

TEST(LoadEnvironmentImage, ReadsBytesAsUnitFloatsAndNamesAMissingFile) {
  std::filesystem::create_directories(kOut);
  Image image = makeImage(2, 1, 0xFF8000FFu);  // r = 255, g = 128, b = 0, a = 255
  const std::string path = (kOut / "face.png").string();
  savePng(path, image);
  const FaceImage face = loadEnvironmentImage(path);
  ASSERT_EQ(face.width, 2);
  EXPECT_EQ(face.rgb[0], 255.0f * (1.0f / 255.0f));
  EXPECT_EQ(face.rgb[1], 128.0f * (1.0f / 255.0f));
  EXPECT_EQ(face.rgb[2], 0.0f);
  try {
    loadEnvironmentImage((kOut / "missing.png").string());
    ADD_FAILURE() << "a missing file was read";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("missing.png"), std::string::npos) << e.what();
  }
}

// The sphere and paraboloid formulas both ways: every direction a map can hold comes back
// from its own coordinate (the sphere map's -Z, its rim, is one point; a hair away it holds).
TEST(MapCoord, DirectionsRoundTripThroughEachParameterization) {
  std::mt19937 random(17);
  std::normal_distribution<double> gaussian;
  for (EnvironmentParameterization kind : {EnvironmentParameterization::Sphere, EnvironmentParameterization::DualParaboloid}) {
    for (int i = 0; i < 2000; ++i) {
      glm::dvec3 r(gaussian(random), gaussian(random), gaussian(random));
      r = glm::normalize(r);
      if (kind == EnvironmentParameterization::Sphere && r.z < -0.999) continue;
      const MapCoord c = mapCoordFromDirection(kind, r * 3.0);  // any length
      ASSERT_GE(c.u, 0.0);
      ASSERT_LE(c.u, 1.0);
      const glm::dvec3 back = directionFromMapCoord(kind, c.layer, c.u, c.v);
      EXPECT_NEAR(glm::length(back - r), 0.0, 1e-9) << toString(kind) << " r " << r.x << ", " << r.y << ", " << r.z;
    }
  }
  // The sphere map's centre is +Z and its rim -Z; a paraboloid's layer 0 holds +Z, layer 1 -Z.
  const MapCoord centre = mapCoordFromDirection(EnvironmentParameterization::Sphere, {0, 0, 1});
  EXPECT_DOUBLE_EQ(centre.u, 0.5);
  EXPECT_DOUBLE_EQ(centre.v, 0.5);
  EXPECT_NEAR(mapCoordFromDirection(EnvironmentParameterization::Sphere, {1, 0, -1e-9}).u, 0.5 + 0.5 / std::sqrt(2.0), 1e-6);
  EXPECT_EQ(mapCoordFromDirection(EnvironmentParameterization::DualParaboloid, {0, 0, -1}).layer, 1);
  EXPECT_EQ(mapCoordFromDirection(EnvironmentParameterization::DualParaboloid, {0, 1, 0}).layer, 0);
  EXPECT_DOUBLE_EQ(mapCoordFromDirection(EnvironmentParameterization::DualParaboloid, {0, 1, 0}).v, 1.0);
  EXPECT_EQ(layerCount(EnvironmentParameterization::Sphere), 1);
  EXPECT_EQ(layerCount(EnvironmentParameterization::DualParaboloid), 2);
}

// A cube whose faces are six flat colours: a built map holds each face's colour where its
// directions are, its chain halves to 1, and bilinear reads of map and cube agree away from
// face edges.
TEST(ParameterizedMap, BuiltFromTheCubeHoldsEachFaceWhereItsDirectionsAre) {
  const std::array<vec3, kCubeFaces> colours = {vec3(1, 0, 0), vec3(0, 1, 0), vec3(0, 0, 1),
                                                vec3(1, 1, 0), vec3(0, 1, 1), vec3(1, 0, 1)};
  std::array<FaceImage, kCubeFaces> faces;
  for (int f = 0; f < kCubeFaces; ++f) faces[static_cast<std::size_t>(f)] = constantFace(8, 8, colours[static_cast<std::size_t>(f)]);
  std::vector<std::string> warnings;
  const CubeMap cube = cubeMapFromFaces(faces, facePaths(), warnings);
  const ParameterizedMap sphere = parameterizedMapFromCube(cube, EnvironmentParameterization::Sphere, 32);
  EXPECT_EQ(sphere.levelCount(), 6);
  EXPECT_EQ(sphere.levels.back().size, 1);
  EXPECT_EQ(sphere.levels[0].r.size(), 32u * 32u);
  // Centre: +Z (face 4); the corners, outside the disk: -Z (face 5).
  EXPECT_EQ(sphere.levels[0].texel(0, 16, 16), colours[4]);
  EXPECT_EQ(sphere.levels[0].texel(0, 0, 0), colours[5]);
  const ParameterizedMap paraboloid = parameterizedMapFromCube(cube, EnvironmentParameterization::DualParaboloid, 32);
  EXPECT_EQ(paraboloid.layers, 2);
  EXPECT_EQ(paraboloid.levels[0].texel(0, 16, 16), colours[4]);
  EXPECT_EQ(paraboloid.levels[0].texel(1, 16, 16), colours[5]);
  // Layer 0's right edge looks along +X, its top row (v = 1) along +Y.
  EXPECT_EQ(paraboloid.levels[0].texel(0, 31, 16), colours[0]);
  EXPECT_EQ(paraboloid.levels[0].texel(0, 16, 31), colours[2]);
  for (const glm::dvec3& r : {glm::dvec3(0.2, 0.1, 1), glm::dvec3(1, 0.3, -0.2), glm::dvec3(-0.1, -1, 0.3)}) {
    for (const ParameterizedMap* map : {&sphere, &paraboloid}) {
      const glm::dvec3 fromMap = mapBilinear(*map, 0, mapCoordFromDirection(map->kind, r));
      const glm::dvec3 fromCube = cubeBilinear(cube, r);
      EXPECT_NEAR(glm::length(fromMap - fromCube), 0.0, 1e-6) << toString(map->kind);
    }
  }
  EXPECT_THROW(parameterizedMapFromCube(cube, EnvironmentParameterization::Sphere, 48), InputError);
  EXPECT_THROW(parameterizedMapFromCube(cube, EnvironmentParameterization::Cube, 32), InputError);
}

// cubeBilinear is seamless: across an edge it blends the two faces, at a corner the three.
TEST(CubeBilinear, BlendsAcrossEdgesAndCorners) {
  const std::array<vec3, kCubeFaces> colours = {vec3(1, 0, 0), vec3(0, 1, 0), vec3(0, 0, 1),
                                                vec3(1, 1, 0), vec3(0, 1, 1), vec3(1, 0, 1)};
  std::array<FaceImage, kCubeFaces> faces;
  for (int f = 0; f < kCubeFaces; ++f) faces[static_cast<std::size_t>(f)] = constantFace(4, 4, colours[static_cast<std::size_t>(f)]);
  std::vector<std::string> warnings;
  const CubeMap cube = cubeMapFromFaces(faces, facePaths(), warnings);
  // On the +X / +Z edge, half of each.
  const glm::dvec3 edge = cubeBilinear(cube, {1, 0, 1 + 1e-12});
  EXPECT_NEAR(edge.x, 0.5, 1e-6);
  EXPECT_NEAR(edge.y, 0.5, 1e-6);
  EXPECT_NEAR(edge.z, 0.5, 1e-6);
  // At the +X +Y +Z corner, a third of each.
  const glm::dvec3 corner = cubeBilinear(cube, {1, 1, 1});
  const glm::dvec3 third = (glm::dvec3(1, 0, 0) + glm::dvec3(0, 0, 1) + glm::dvec3(0, 1, 1)) / 3.0;
  EXPECT_NEAR(glm::length(corner - third), 0.0, 1e-6);
  // A face's centre is its own colour.
  EXPECT_NEAR(glm::length(cubeBilinear(cube, {0, -1, 0}) - glm::dvec3(1, 1, 0)), 0.0, 1e-12);
}

}  // namespace
}  // namespace twr
