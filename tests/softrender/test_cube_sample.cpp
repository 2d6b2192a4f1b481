// Cube-map sampling and the environment terms over the lane type (cube_sample-inl.h,
// environment-inl.h), on the scalar instantiations: texel centres read back exactly, the
// seamless neighbours and the corner rule, the tie rule, explicit LODs, and reflect / refract /
// Schlick at the cases a student checks by hand. The fast path's vectors are held to the same
// bits by the scene tests (test_fast_path.cpp), and GL to them by the suite's env_* scenes.
#include "scene/environment.h"
#include "softrender/shade.h"  // the plain headers, then every -inl.h source (environment-inl.h too)

#include <gtest/gtest.h>

#include <cmath>

namespace twr {
namespace {

constexpr int kSize = 8;

// A cube of kSize whose texel (face, x, y) holds texelColour(face, x, y).
template <typename Colour>
CubeMap cubeOf(Colour texelColour) {
  std::array<FaceImage, kCubeFaces> faces;
  for (int f = 0; f < kCubeFaces; ++f) {
    FaceImage& face = faces[static_cast<std::size_t>(f)];
    face.width = face.height = kSize;
    for (int y = 0; y < kSize; ++y) {
      for (int x = 0; x < kSize; ++x) {
        const vec3 c = texelColour(f, x, y);
        face.rgb.insert(face.rgb.end(), {c.r, c.g, c.b});
      }
    }
  }
  std::vector<std::string> warnings;
  return cubeMapFromFaces(faces, {"a", "b", "c", "d", "e", "f"}, warnings);
}

// Every texel says where it is: r = face, g = x, b = y (exact in float).
CubeMap labelledCube() {
  return cubeOf([](int f, int x, int y) { return vec3(static_cast<float>(f), static_cast<float>(x), static_cast<float>(y)); });
}

// The environment terms of one fragment with no quad differences (every read at level 0).
lanes::EnvironmentTermsL<float> envAt(const EnvironmentUniformsT<float>& e, const Vec3L<float>& nl, const Vec3L<float>& vVec,
                                      const Vec3L<float>& t, const Vec3L<float>& b, const Vec3L<float>& n, bool tangentSpace,
                                      const Vec3L<float>& base) {
  const Fragment f;
  return lanes::environmentMix<float>(e, lanes::environmentDirections<float>(e, nl, vVec, t, b, n, tangentSpace), f, base);
}

Vec3L<float> sample(const CubeMap& cube, glm::dvec3 r, float lod = 0.0f) {
  return lanes::sampleCubeLod<float>(cube, Vec3L<float>(vec3(r)), lod);
}

TEST(CubeSample, ATexelCentreReadsThatTexel) {
  const CubeMap cube = labelledCube();
  for (int f = 0; f < kCubeFaces; ++f) {
    for (int y = 0; y < kSize; ++y) {
      for (int x = 0; x < kSize; ++x) {
        const glm::dvec3 r = directionFromCubeCoord(f, (x + 0.5) / kSize, (y + 0.5) / kSize);
        EXPECT_EQ(sample(cube, r), Vec3L<float>(static_cast<float>(f), static_cast<float>(x), static_cast<float>(y)))
            << "face " << f << " texel " << x << ", " << y;
      }
    }
  }
}

TEST(CubeSample, FaceSelectionFollowsLlvmpipesTieRule) {
  EXPECT_EQ(lanes::cubeCoord<float>(Vec3L<float>(1.0f, 1.0f, 0.3f)).face, 2.0f);   // x = y: y
  EXPECT_EQ(lanes::cubeCoord<float>(Vec3L<float>(1.0f, -1.0f, 0.0f)).face, 3.0f);
  EXPECT_EQ(lanes::cubeCoord<float>(Vec3L<float>(1.0f, 1.0f, 1.0f)).face, 4.0f);   // z wins every tie
  EXPECT_EQ(lanes::cubeCoord<float>(Vec3L<float>(-1.0f, 1.0f, -1.0f)).face, 5.0f);
  EXPECT_EQ(lanes::cubeCoord<float>(Vec3L<float>(0.0f, 0.0f, 0.0f)).face, 4.0f);   // zero: +Z, centre
  EXPECT_EQ(lanes::cubeCoord<float>(Vec3L<float>(0.0f, 0.0f, -0.0f)).face, 5.0f);  // -0: the sign bit
  EXPECT_EQ(lanes::cubeCoord<float>(Vec3L<float>(0.0f, 0.0f, 0.0f)).s, 0.5f);
  // The float path agrees with the double table everywhere off the ties.
  for (int i = 0; i < 1000; ++i) {
    const glm::dvec3 r(std::sin(i * 1.7), std::cos(i * 2.3), std::sin(i * 0.37 + 1.0));
    const CubeCoord exact = cubeCoordFromDirection(r);
    const lanes::CubeCoordL<float> c = lanes::cubeCoord<float>(Vec3L<float>(vec3(r)));
    EXPECT_EQ(c.face, static_cast<float>(exact.face)) << i;
    EXPECT_NEAR(c.s, exact.s, 1e-6) << i;
    EXPECT_NEAR(c.t, exact.t, 1e-6) << i;
  }
}

// Across every edge the filter reads the neighbour face: a direction a hair to either side of
// the edge gives nearly the same colour (a footprint straddling it reads the same texels).
TEST(CubeSample, SeamlessAcrossEveryEdge) {
  // A smooth cube: each texel the direction of its centre, so a tear would show as a jump.
  const CubeMap cube = cubeOf([](int f, int x, int y) {
    return vec3(glm::normalize(directionFromCubeCoord(f, (x + 0.5) / kSize, (y + 0.5) / kSize)));
  });
  constexpr double kHair = 1e-4;      // s units off the edge
  constexpr float kContinuous = 2e-3f;  // colour units: a texel step here is about 0.2
  for (int f = 0; f < kCubeFaces; ++f) {
    for (int k = 0; k < 16; ++k) {
      const double along = (k + 0.5) / 16.0;
      const glm::dvec2 edges[4][2] = {{{kHair, along}, {-kHair, along}},
                                      {{1.0 - kHair, along}, {1.0 + kHair, along}},
                                      {{along, kHair}, {along, -kHair}},
                                      {{along, 1.0 - kHair}, {along, 1.0 + kHair}}};
      for (const auto& [inside, outside] : edges) {
        const Vec3L<float> a = sample(cube, directionFromCubeCoord(f, inside.x, inside.y));
        const Vec3L<float> b = sample(cube, directionFromCubeCoord(f, outside.x, outside.y));
        EXPECT_NEAR(a.x, b.x, kContinuous) << "face " << f << " at " << inside.x << ", " << inside.y;
        EXPECT_NEAR(a.y, b.y, kContinuous) << "face " << f << " at " << inside.x << ", " << inside.y;
        EXPECT_NEAR(a.z, b.z, kContinuous) << "face " << f << " at " << inside.x << ", " << inside.y;
      }
    }
  }
}

// At a corner three faces meet; the fourth texel of the footprint does not exist and its
// weight goes in thirds to the other three: at the corner itself, their mean.
TEST(CubeSample, ACornerReadsTheMeanOfItsThreeTexels) {
  const CubeMap cube = labelledCube();
  constexpr float m = kSize - 1;
  // (+1, +1, +1) is on +Z (z wins ties) at s = 1, t = 0: +Z (m, 0), +X (0, 0), +Y (m, m).
  const Vec3L<float> c = sample(cube, {1.0, 1.0, 1.0});
  const float third = 1.0f / 3.0f;
  constexpr float kRounding = 1e-5f;  // four float products and sums of values up to 7
  EXPECT_NEAR(c.x, (4.0f + 0.0f + 2.0f) * third, kRounding);
  EXPECT_NEAR(c.y, (m + 0.0f + m) * third, kRounding);
  EXPECT_NEAR(c.z, (0.0f + 0.0f + m) * third, kRounding);
}

TEST(CubeSample, AnExplicitLodBlendsTwoLevels) {
  std::array<FaceImage, kCubeFaces> faces;
  for (FaceImage& face : faces) {
    face.width = face.height = 2;
    face.rgb = {1, 1, 1, 0, 0, 0, 0, 0, 0, 1, 1, 1};  // level 1 is their mean, 0.5
  }
  std::vector<std::string> warnings;
  const CubeMap cube = cubeMapFromFaces(faces, {"a", "b", "c", "d", "e", "f"}, warnings);
  const glm::dvec3 texel00 = directionFromCubeCoord(4, 0.25, 0.25);
  EXPECT_EQ(sample(cube, texel00, 0.0f).x, 1.0f);
  // Level 1 is one texel per face: every read is a corner there, a weighted sum of 0.5s.
  EXPECT_FLOAT_EQ(sample(cube, texel00, 1.0f).x, 0.5f);
  EXPECT_FLOAT_EQ(sample(cube, texel00, 0.5f).x, 0.75f);
  EXPECT_FLOAT_EQ(sample(cube, texel00, 7.0f).x, 0.5f);  // clamped to the last level
  EXPECT_EQ(sample(cube, texel00, -3.0f).x, 1.0f);   // magnified: level 0
  EXPECT_EQ(sample(cube, {NAN, 0.0, 1.0}, 0.0f).x, sample(cube, {0.0, 0.0, 1.0}, 0.0f).x);  // NaN reads as 0
}

// texture()'s LOD from the direction's quad differences: at the +Z face's centre, a step of
// 2 / size in x moves one texel (lod 0), twice that two texels (lod 1); a step along the face's
// axis moves s only away from the centre (the quotient rule).
TEST(CubeSample, TheImplicitLodFollowsTheDirectionsDifferences) {
  constexpr int kSide = 64;
  const Vec3L<float> centre(0.0f, 0.0f, 1.0f), none(0.0f);
  const float texel = 2.0f / kSide;
  EXPECT_FLOAT_EQ(lanes::cubeLod<float>(centre, Vec3L<float>(texel, 0.0f, 0.0f), none, kSide), 0.0f);
  EXPECT_FLOAT_EQ(lanes::cubeLod<float>(centre, Vec3L<float>(2.0f * texel, 0.0f, 0.0f), none, kSide), 1.0f);
  EXPECT_FLOAT_EQ(lanes::cubeLod<float>(centre, none, Vec3L<float>(0.0f, 4.0f * texel, 0.0f), kSide), 2.0f);
  // The larger of the two axes decides.
  EXPECT_FLOAT_EQ(lanes::cubeLod<float>(centre, Vec3L<float>(texel, 0.0f, 0.0f), Vec3L<float>(0.0f, 8.0f * texel, 0.0f), kSide),
                  3.0f);
  // On -X (face 1) the same as on +Z: the face's own axes.
  EXPECT_FLOAT_EQ(lanes::cubeLod<float>(Vec3L<float>(-1.0f, 0.0f, 0.0f), Vec3L<float>(0.0f, 0.0f, 2.0f * texel), none, kSide), 1.0f);
  // The quotient rule: at s = 0.75 (x = z / 2) a step dz moves s by -x dz / (2 z^2) = -dz / 4,
  // so 4 texel units of z move two texels: lod 1 (at the centre the same step moves none).
  EXPECT_FLOAT_EQ(lanes::cubeLod<float>(Vec3L<float>(0.5f, 0.0f, 1.0f), Vec3L<float>(0.0f, 0.0f, 4.0f * texel), none, kSide),
                  1.0f);
  // No difference, or a non-finite one: the finest level.
  EXPECT_LT(lanes::cubeLod<float>(centre, none, none, kSide), 0.0f);
  EXPECT_LT(lanes::cubeLod<float>(centre, Vec3L<float>(INFINITY, 0.0f, 0.0f), none, kSide), 0.0f);
}

// The environment terms by hand: looking straight at a surface, R comes back along the view,
// eta 1 goes straight through, Schlick is F0 head-on and 1 at grazing, and rays leaving a
// denser medium past the critical angle are reflected entirely.
TEST(EnvironmentTerms, ReflectRefractSchlickAndTotalInternalReflection) {
  std::array<FaceImage, kCubeFaces> faces;
  for (int f = 0; f < kCubeFaces; ++f) {
    FaceImage& face = faces[static_cast<std::size_t>(f)];
    face.width = face.height = 1;
    face.rgb = {static_cast<float>(f), 0.0f, 0.0f};  // each face its index
  }
  std::vector<std::string> warnings;
  const CubeMap cube = cubeMapFromFaces(faces, {"a", "b", "c", "d", "e", "f"}, warnings);
  EnvironmentUniformsT<float> e;
  e.cube = &cube;
  e.reflects = true;
  e.reflectivity = 0.25f;
  const Vec3L<float> n(0.0f, 0.0f, 1.0f), t(1.0f, 0.0f, 0.0f), b(0.0f, 1.0f, 0.0f), base(10.0f);
  // Head-on: R = +Z (face 4), mixed 1/4 into the base.
  lanes::EnvironmentTermsL<float> head = envAt(e, n, Vec3L<float>(0.0f, 0.0f, 2.0f), t, b, n, false, base);
  EXPECT_EQ(head.reflectWorld, Vec3L<float>(0.0f, 0.0f, 1.0f));
  EXPECT_EQ(head.reflected.x, 4.0f);
  EXPECT_FLOAT_EQ(head.colour.x, 10.0f + (4.0f - 10.0f) * 0.25f);
  // Refraction with eta 1: straight through (-Z, face 5); no Fresnel: the share is reflectivity.
  e.refraction = true;
  e.eta = 1.0f;
  lanes::EnvironmentTermsL<float> through = envAt(e, n, Vec3L<float>(0.0f, 0.0f, 1.0f), t, b, n, false, base);
  EXPECT_EQ(through.refractWorld, Vec3L<float>(0.0f, 0.0f, -1.0f));
  EXPECT_EQ(through.transmitted.x, 5.0f);
  // Schlick with eta 1: F0 = 0, so head-on nothing is reflected; at grazing (V along the
  // surface) all of it.
  e.schlick = true;
  EXPECT_EQ(envAt(e, n, Vec3L<float>(0.0f, 0.0f, 1.0f), t, b, n, false, base).share, 0.0f);
  EXPECT_EQ(envAt(e, n, Vec3L<float>(1.0f, 0.0f, 0.0f), t, b, n, false, base).share, 1.0f);
  // Leaving water (eta 1.33) at 60 degrees from the normal: past the critical angle of 48.8.
  e.eta = 1.33f;
  const float angle = 60.0f * 3.14159265f / 180.0f;
  lanes::EnvironmentTermsL<float> trapped =
      envAt(e, n, Vec3L<float>(std::sin(angle), 0.0f, std::cos(angle)), t, b, n, false, base);
  EXPECT_TRUE(trapped.totalInternal);
  EXPECT_EQ(trapped.transmitted, trapped.reflected);
  // In tangent lighting space the directions are brought to world space by the frame.
  const Vec3L<float> tw(0.0f, 1.0f, 0.0f), bw(0.0f, 0.0f, 1.0f), nw(1.0f, 0.0f, 0.0f);
  e.refraction = false;
  lanes::EnvironmentTermsL<float> tangent = envAt(e, n, Vec3L<float>(0.0f, 0.0f, 1.0f), tw, bw, nw, true, base);
  EXPECT_EQ(tangent.reflectWorld, Vec3L<float>(1.0f, 0.0f, 0.0f));
  EXPECT_EQ(tangent.reflected.x, 0.0f);  // face +X
}

// ---- Sphere and dual-paraboloid maps (layer_sample-inl.h) ----

// The float formulas agree with the double ones; a texel centre reads that texel; the LOD is
// the 2D rule on the coordinate's quad differences; levels blend.
TEST(MapSample, CoordinatesTexelCentresAndLods) {
  const CubeMap cube = labelledCube();
  for (EnvironmentParameterization kind : {EnvironmentParameterization::Sphere, EnvironmentParameterization::DualParaboloid}) {
    const ParameterizedMap map = parameterizedMapFromCube(cube, kind, 16);
    for (const glm::dvec3& r : {glm::dvec3(0.3, -0.2, 0.9), glm::dvec3(-0.8, 0.5, -0.3), glm::dvec3(0.1, 0.99, 0.05)}) {
      const MapCoord exact = mapCoordFromDirection(kind, r);
      const lanes::MapCoordL<float> c = lanes::environmentCoord<float>(kind, Vec3L<float>(vec3(r * 2.0)));
      EXPECT_EQ(static_cast<int>(c.layer), exact.layer) << toString(kind);
      EXPECT_NEAR(c.u, exact.u, 1e-6) << toString(kind);
      EXPECT_NEAR(c.v, exact.v, 1e-6) << toString(kind);
    }
    const CubeMapLevel& level0 = map.levels[0];
    for (int layer = 0; layer < map.layers; ++layer) {
      const lanes::MapCoordL<float> centre{static_cast<float>(layer), 5.5f / 16.0f, 9.5f / 16.0f};
      const Vec3L<float> read = lanes::sampleMapLod<float>(map, centre, 0.0f);
      EXPECT_EQ(vec3(read.x, read.y, read.z), level0.texel(layer, 5, 9)) << toString(kind) << " layer " << layer;
      // Off the edge: clamped to the edge texel.
      const Vec3L<float> past = lanes::sampleMapLod<float>(map, lanes::MapCoordL<float>{static_cast<float>(layer), -0.3f, 1.7f}, 0.0f);
      EXPECT_EQ(vec3(past.x, past.y, past.z), level0.texel(layer, 0, 15));
    }
    // One texel per pixel along u is LOD 0, four texels along v LOD 2 (the larger axis).
    EXPECT_EQ(lanes::mapLod<float>(Vec2L<float>(1.0f / 16.0f, 0.0f), Vec2L<float>(0.0f, 4.0f / 16.0f), 16), 2.0f);
    EXPECT_EQ(lanes::mapLod<float>(Vec2L<float>(1.0f / 16.0f, 0.0f), Vec2L<float>(0.0f, 1.0f / 16.0f), 16), 0.0f);
    // Half way between levels 1 and 2 at a layer's centre: the two levels' centre values blended.
    const lanes::MapCoordL<float> middle{0.0f, 0.5f, 0.5f};
    const Vec3L<float> a = lanes::sampleMapLod<float>(map, middle, 1.0f), b = lanes::sampleMapLod<float>(map, middle, 2.0f);
    const Vec3L<float> blended = lanes::sampleMapLod<float>(map, middle, 1.5f);
    EXPECT_NEAR(blended.x, 0.5f * (a.x + b.x), 1e-5f);
    EXPECT_NEAR(blended.y, 0.5f * (a.y + b.y), 1e-5f);
  }
}

// sampleEnvironment reads the map when there is one, the cube otherwise; the map's
// differences come from the coordinates at the quad's first pixel, its right and above.
TEST(MapSample, TheEnvironmentReadsTheMapWhenThereIsOne) {
  const CubeMap cube = labelledCube();
  const ParameterizedMap map = parameterizedMapFromCube(cube, EnvironmentParameterization::Sphere, 16);
  const Vec3L<float> r(vec3(0.2f, 0.1f, 0.95f));
  const Vec3L<float> zero(vec3(0.0f));
  const Vec3L<float> fromCube = lanes::sampleEnvironment<float>(cube, nullptr, r, zero, zero);
  const Vec3L<float> cubeDirect = lanes::sampleCubeLod<float>(cube, r, 0.0f);
  EXPECT_EQ(vec3(fromCube.x, fromCube.y, fromCube.z), vec3(cubeDirect.x, cubeDirect.y, cubeDirect.z));
  const Vec3L<float> fromMap = lanes::sampleEnvironment<float>(cube, &map, r, zero, zero);
  const Vec3L<float> mapDirect = lanes::sampleMapLod<float>(map, lanes::environmentCoord<float>(map.kind, r), 0.0f);
  EXPECT_EQ(vec3(fromMap.x, fromMap.y, fromMap.z), vec3(mapDirect.x, mapDirect.y, mapDirect.z));
  Vec3L<float> dx(zero), dy(zero);
  const Vec3L<float> right(vec3(0.25f, 0.1f, 0.95f)), above(vec3(0.2f, 0.2f, 0.95f));
  lanes::mapDifferences<float>(map.kind, r, right, above, dx, dy);
  const lanes::MapCoordL<float> c0 = lanes::environmentCoord<float>(map.kind, r), cx = lanes::environmentCoord<float>(map.kind, right),
                         cy = lanes::environmentCoord<float>(map.kind, above);
  EXPECT_EQ(dx.x, cx.u - c0.u);
  EXPECT_EQ(dx.y, cx.v - c0.v);
  EXPECT_EQ(dy.y, cy.v - c0.v);
  EXPECT_EQ(dx.z, 0.0f);
}

}  // namespace
}  // namespace twr
