// Environment maps (docs/environment.md): what surrounds the scene, as a cube map both
// renderers sample the same texels of. A scene's `environment` is six face images in GL order
// or one equirectangular image, turned at load into a CubeMap: linear RGB floats (an 8-bit
// file's bytes read as c / 255, a Radiance HDR file's floats as they are), the same array GL
// receives as GL_RGB32F, so no driver conversion stands between the two renderers.
//
// Cube-map faces and their (s, t) follow the GL spec's table (section 8.13): the major axis of
// the direction r picks the face, and
//   face  major   sc    tc         face  major   sc    tc
//   +X    +rx    -rz   -ry         -X    -rx    +rz   -ry
//   +Y    +ry    +rx   +rz         -Y    -ry    +rx   -rz
//   +Z    +rz    +rx   -ry         -Z    -rz    -rx   -ry
//   s = (sc / |ma| + 1) / 2,  t = (tc / |ma| + 1) / 2.
// Row 0 of a face is t = 0: the top row of a face image, as sky boxes are made (they are
// uploaded top row first, unflipped, by every GL tutorial).
#pragma once

#include "scene/conventions.h"
#include "scene/image.h"

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace twr {

// How directions become a 2D texture (the slides' three mappings). Cube is sampled directly;
// sphere and dual_paraboloid are built from the cube at `size` (ParameterizedMap below).
enum class EnvironmentParameterization { Cube, Sphere, DualParaboloid };
std::string_view toString(EnvironmentParameterization v);
bool parse(std::string_view s, EnvironmentParameterization& out);

// Face order, GL's: GL_TEXTURE_CUBE_MAP_POSITIVE_X + face.
inline constexpr int kCubeFaces = 6;
inline constexpr const char* kCubeFaceNames[kCubeFaces] = {"+X", "-X", "+Y", "-Y", "+Z", "-Z"};

// The env_face view's colours, per face in GL order (RGB in [0, 1]): red for x, green for y,
// blue for z, the positive face bright and the negative dark; a sphere or paraboloid map's
// +Z and -Z hemispheres take +Z's and -Z's.
// Written as k / 255 for whole levels: a colour halfway between two levels would round either
// way on the two renderers.
inline constexpr float kCubeFaceViewColours[kCubeFaces][3] = {
    {1.0f, 80.0f / 255.0f, 80.0f / 255.0f}, {128.0f / 255.0f, 0.0f, 0.0f},
    {80.0f / 255.0f, 1.0f, 80.0f / 255.0f}, {0.0f, 128.0f / 255.0f, 0.0f},
    {80.0f / 255.0f, 80.0f / 255.0f, 1.0f}, {0.0f, 0.0f, 128.0f / 255.0f}};
// The env_lod view's heat ramp spans LOD 0 to this (inclusive): an 11-level chain, a 1024-texel
// face's, reaches 10 at its last level.
inline constexpr float kEnvironmentLodViewMax = 10.0f;

// Largest radiance an HDR texel keeps (inclusive; linear RGB, 1 = an 8-bit file's white):
// half-float's largest value. Times the largest intensity (kMaxColourValue, 1e4) it stays far
// from float's range, so no read, product or mix can reach Inf or NaN.
inline constexpr float kMaxEnvironmentRadiance = 65504.0f;

// Largest face side, texels (inclusive): six 1024^2 RGB float faces with their chains are
// 100 MB on each side of the comparison. A larger face is read at the first level of its own
// chain that fits (with a warning).
inline constexpr int kMaxCubeFaceSize = 1024;
// Smallest cube side, texels (inclusive), and the side Environment::size starts at (a built
// map's, when the scene gives none; an equirect's default is defaultCubeSizeForEquirect's).
inline constexpr int kMinCubeFaceSize = 1;
inline constexpr int kDefaultEnvironmentSize = 256;

// One mip level of the six faces, planar: channel c of texel (x, y) of `face` at
// c[(face * size + y) * size + x]. Planar floats are what the lane code gathers (one index per
// channel, exact in float for every index below 2^24: 6 * 1024^2 is 6.3 million).
struct CubeMapLevel {
  int size = 0;  // texels per side
  std::vector<float> r, g, b;
  std::size_t index(int face, int x, int y) const {
    return (static_cast<std::size_t>(face) * static_cast<std::size_t>(size) + static_cast<std::size_t>(y)) *
               static_cast<std::size_t>(size) +
           static_cast<std::size_t>(x);
  }
  vec3 texel(int face, int x, int y) const {
    const std::size_t i = index(face, x, y);
    return vec3(r[i], g[i], b[i]);
  }
};

struct CubeMap {
  std::string source;                // where the texels came from, for messages and the UI
  std::vector<CubeMapLevel> levels;  // level 0 first; each side half the one before, down to 1
  int size() const { return levels.empty() ? 0 : levels.front().size; }
  int levelCount() const { return static_cast<int>(levels.size()); }
};

// A face as read: the texels of one face image, top row first (as the file stores it), RGB.
struct FaceImage {
  int width = 0, height = 0;
  std::vector<float> rgb;  // width * height * 3
};

// Reads an image file (PNG, JPEG, BMP, TGA, DDS level 0 as c / 255; Radiance HDR as floats).
// Throws InputError naming the file.
FaceImage loadEnvironmentImage(const std::string& path);

// The cube of six square faces of one size (GL order), with its mip chain. Throws InputError
// naming the face (`paths`, for messages) when a face is not square or the sizes differ.
// `warnings` receives a line when a face larger than kMaxCubeFaceSize is reduced.
CubeMap cubeMapFromFaces(std::array<FaceImage, kCubeFaces> faces, const std::array<std::string, kCubeFaces>& paths,
                         std::vector<std::string>& warnings);
// An image file's width and height from its header, nothing decoded (false when it has none):
// six faces are checked against each other before any is decoded.
bool readEnvironmentImageSize(const std::string& path, int& width, int& height);
// `face` halved by 2x2 means until its side is at most kMaxCubeFaceSize (each face is reduced
// as soon as it is read, so six large faces are never held at full size together).
FaceImage faceWithinCubeLimit(FaceImage face);
// The cube of side `size` resampled from an equirectangular image (longitude along x, the
// -Z direction at the centre, +X a quarter to the right; latitude along y, +Y at the top row),
// each face texel the bilinear value at its centre's direction, in double; with its mip chain.
CubeMap cubeMapFromEquirect(const FaceImage& equirect, int size, const std::string& path);
// The cube side an equirect is made into when the scene gives no `size`: the power of two
// nearest a quarter of the image's width (a face spans a quarter of its 360 degrees), within
// [kMinCubeFaceSize, kMaxCubeFaceSize].
int defaultCubeSizeForEquirect(int equirectWidth);

// Level i + 1 from level i for every face: each texel the mean of its 2x2 block (sides are
// powers of two after cubeMapFromFaces), in double rounded to float, as a box-filtered
// glGenerateMipmap would; built once here and given to GL level by level.
void buildCubeMipChain(CubeMap& cube);

// The GL table above, in double: the face of direction r (the largest |component|; on a tie z
// wins, then y, as llvmpipe selects; a zero vector reads +Z, -0 in z -Z) and its s, t in [0, 1].
struct CubeCoord {
  int face = 0;
  double s = 0.5, t = 0.5;
};
CubeCoord cubeCoordFromDirection(const glm::dvec3& r);
// The direction through (s, t) of `face` (not normalised; the inverse of the table).
glm::dvec3 directionFromCubeCoord(int face, double s, double t);

// Seamless filtering's neighbours (GL_TEXTURE_CUBE_MAP_SEAMLESS): the texel one step past an
// edge of a face is an edge texel of the face that shares the edge. For face f and edge e
// (0: x = -1, 1: x = size, 2: y = -1, 3: y = size), entry 4 f + e says which face and where:
// with `along` the coordinate that stays in range (y for edges 0 and 1, x for 2 and 3),
//   x' = xAtLast * (size - 1) + xPerAlong * along,  y' = yAtLast * (size - 1) + yPerAlong * along
// (each factor 0, 1 or -1). Derived once from the table above, in double. Floats, as the lane
// code gathers them.
struct CubeEdgeTable {
  std::array<float, 4 * kCubeFaces> face{}, xAtLast{}, xPerAlong{}, yAtLast{}, yPerAlong{};
};
const CubeEdgeTable& cubeEdgeTable();

// The equirect convention above: the image coordinate (u right, v down, both in [0, 1]) a
// direction looks at, and back.
glm::dvec2 equirectUvFromDirection(const glm::dvec3& r);

// ---- Sphere and dual-paraboloid maps (docs/environment.md) ----
// Square layers of side `size` built from the cube at load, which both renderers read as a 2D
// array texture (one layer for a sphere map, two for a dual paraboloid), r a unit direction:
//   sphere:           m = 2 sqrt(rx^2 + ry^2 + (rz + 1)^2),   (u, v) = (rx, ry) / m + 1/2
//                     the picture of a mirror ball seen from far along +Z: its centre is +Z,
//                     its rim -Z (where the map is most distorted)
//   dual paraboloid:  (u, v) = (rx, ry) / (1 + |rz|) / 2 + 1/2,   layer 0 for rz >= 0, 1 below
// Texel (x, y) of a layer is centred at ((x + 1/2) / size, (y + 1/2) / size); row 0 is v = 0,
// uploaded first as the cube's faces are. The texels a layer holds beyond its disk: a
// paraboloid's continue the formula into the other hemisphere, a sphere map's hold -Z.
struct ParameterizedMap {
  EnvironmentParameterization kind = EnvironmentParameterization::Sphere;
  int layers = 1;
  std::vector<CubeMapLevel> levels;  // each holds `layers` squares where a cube level holds six faces
  int size() const { return levels.empty() ? 0 : levels.front().size; }
  int levelCount() const { return static_cast<int>(levels.size()); }
};
int layerCount(EnvironmentParameterization kind);  // 1 sphere, 2 dual paraboloid (6 cube faces)

// The formulas above in double: where direction r (any length) is read, and back (the
// direction a layer's (u, v) holds, unit length).
struct MapCoord {
  int layer = 0;
  double u = 0.5, v = 0.5;
};
MapCoord mapCoordFromDirection(EnvironmentParameterization kind, const glm::dvec3& r);
glm::dvec3 directionFromMapCoord(EnvironmentParameterization kind, int layer, double u, double v);

// The cube in direction r at level `level` (0 unless given), bilinear and seamless across faces
// (GL's rule: a corner's missing texel weighs as the mean of the other three), in double: the
// source a parameterized map is built from and measured against.
glm::dvec3 cubeBilinear(const CubeMap& cube, const glm::dvec3& r, int level = 0);
// A layer of a parameterized map at level `level` and (u, v), bilinear with clamp to edge, in
// double (the parameterization's error is measured with it).
glm::dvec3 mapBilinear(const ParameterizedMap& map, int level, const MapCoord& c);

// The map of `kind` (sphere or dual_paraboloid) at side `size` (a power of two, at most
// kMaxCubeFaceSize): each texel the cube at its centre's direction (cubeBilinear), with the mip
// chain built as the cube's (2x2 means in double).
ParameterizedMap parameterizedMapFromCube(const CubeMap& cube, EnvironmentParameterization kind, int size);
// The same, but every level l (side size / 2^l) made from the cube's level l instead of 2x2
// means of the level above: for a cube whose levels are not each other's means (the
// prefiltered specular cube, scene/environment_specular.h). As many levels as the cube has.
ParameterizedMap parameterizedMapFromCubeLevels(const CubeMap& cube, EnvironmentParameterization kind, int size);

struct Sh9Irradiance;  // scene/environment_light.h

// Side of a captured cube's faces when the scene gives no capture.size, texels.
inline constexpr int kDefaultCaptureSize = 128;

// An environment captured from the scene instead of loaded (scene/environment_capture.h).
struct EnvironmentCapture {
  std::string node;                // the node it is captured from (hidden in the capture)
  int size = kDefaultCaptureSize;  // texels per face side, a power of two
};

// The scene's environment (the scene file's top-level "environment").
struct Environment {
  std::array<std::string, kCubeFaces> facePaths;  // set when read from six images
  std::string equirectPath;                       // set when read from one
  float intensity = 1.0f;                         // scales every environment read (unitless)
  bool background = true;                         // drawn as the sky box where no triangle is
  EnvironmentParameterization parameterization = EnvironmentParameterization::Cube;
  int size = kDefaultEnvironmentSize;  // texels: the built map's side (an equirect's cube, or a sphere or paraboloid map)
  bool sizeGiven = false;
  // Set when captured from the scene: `cube` is then null as loaded, and each renderer draws
  // its own (captureEnvironment) before it draws the frame.
  std::optional<EnvironmentCapture> capture;
  std::shared_ptr<const CubeMap> cube;
  // Built from the cube when the parameterization is not "cube" (null otherwise): both
  // renderers then read it instead of the cube, on surfaces and in the sky box.
  std::shared_ptr<const ParameterizedMap> layers;
  // The diffuse light (scene/environment_light.h), built from the cube at load when a material
  // asks for it, null otherwise: the irradiance cube (one level), its sphere or paraboloid map
  // when the parameterization is not "cube", and the nine SH coefficients.
  std::shared_ptr<const CubeMap> irradiance;
  std::shared_ptr<const ParameterizedMap> irradianceLayers;
  std::shared_ptr<const Sh9Irradiance> sh9;
  // The glossy reflection (scene/environment_specular.h), built from the cube at load when a
  // material's environment_specular is prefiltered, null otherwise: the cube with a Phong lobe
  // per level, and its sphere or paraboloid map (each level from the cube's same level) when
  // the parameterization is not "cube".
  std::shared_ptr<const CubeMap> specular;
  std::shared_ptr<const ParameterizedMap> specularLayers;
};

}  // namespace twr
