// normalMapFromHeight: the formula by hand, the encoding of a flat map, the sign convention,
// the wrap modes one texel past the border, agreement with makeHeightfield's vertex normals,
// and the refusals.
#include "scene/errors.h"
#include "scene/height_field.h"
#include "scene/primitives.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <vector>

namespace twr {
namespace {

// One 8-bit step of a decoded component: c / 255 * 2 - 1 moves by 2 / 255 per level.
constexpr double kDecodeStep = 2.0 / 255.0;

// `reds` row by row, bottom row (v = 0) first; g, b = 0, a = 255.
Texture heights(int width, int height, const std::vector<std::uint8_t>& reds, TextureWrap wrap = TextureWrap::Repeat) {
  Texture t;
  t.path = "heights-in-code";
  t.width = width;
  t.height = height;
  for (std::uint8_t red : reds) t.rgba.insert(t.rgba.end(), {red, 0, 0, 255});
  t.options.wrap = wrap;
  return t;
}

glm::dvec3 decoded(const Texture& normal, int x, int y) {
  const std::uint8_t* p = normal.texel(x, y);
  return {p[0] / 255.0 * 2.0 - 1.0, p[1] / 255.0 * 2.0 - 1.0, p[2] / 255.0 * 2.0 - 1.0};
}

TEST(NormalMapFromHeight, FlatMapIsStraightUpWithAMipChain) {
  const Texture n = normalMapFromHeight(heights(4, 4, std::vector<std::uint8_t>(16, 200)), 0.3);
  ASSERT_EQ(n.width, 4);
  ASSERT_EQ(n.height, 4);
  for (int y = 0; y < 4; ++y) {
    for (int x = 0; x < 4; ++x) {
      // 0.5 * 255 = 127.5 rounds up.
      EXPECT_EQ(n.texel(x, y)[0], 128);
      EXPECT_EQ(n.texel(x, y)[1], 128);
      EXPECT_EQ(n.texel(x, y)[2], 255);
      EXPECT_EQ(n.texel(x, y)[3], 255);
    }
  }
  EXPECT_EQ(n.levelCount(), 3);  // 4, 2, 1
}

// Heights rising along u (left to right) lean the normal to -x; along v (rows bottom first)
// to -y; the size of the lean is the formula's.
TEST(NormalMapFromHeight, FormulaAndSignsByHand) {
  // 4 x 1, clamp: 0, 51, 102, 153 (steps of 0.2). Texel 1: dh/du = (102 - 0) / 255 / (2 / 4) = 0.8.
  const double s = 0.25;
  const Texture ramp = normalMapFromHeight(heights(4, 1, {0, 51, 102, 153}, TextureWrap::ClampToEdge), s);
  const double nx = -s * 0.8, length = std::sqrt(nx * nx + 1.0);
  const glm::dvec3 n1 = decoded(ramp, 1, 0);
  EXPECT_NEAR(n1.x, nx / length, kDecodeStep);
  EXPECT_NEAR(n1.y, 0.0, kDecodeStep);
  EXPECT_NEAR(n1.z, 1.0 / length, kDecodeStep);
  EXPECT_LT(ramp.texel(1, 0)[0], 128);
  // Texel 0 with clamp reads itself on the left: dh/du = (51 - 0) / 255 / 0.5 = 0.4.
  EXPECT_NEAR(decoded(ramp, 0, 0).x, -s * 0.4 / std::sqrt(s * s * 0.16 + 1.0), kDecodeStep);

  // 1 x 4 along v: rows bottom first, so heights rise with v and the normal leans to -y.
  const Texture up = normalMapFromHeight(heights(1, 4, {0, 51, 102, 153}, TextureWrap::ClampToEdge), s);
  EXPECT_LT(up.texel(0, 1)[1], 128);
  EXPECT_NEAR(decoded(up, 0, 1).y, nx / length, kDecodeStep);
  // Depth 0: flat whatever the heights.
  const Texture flat = normalMapFromHeight(heights(4, 1, {0, 51, 102, 153}), 0.0);
  EXPECT_EQ(flat.texel(1, 0)[0], 128);
}

TEST(NormalMapFromHeight, WrapModesOneTexelPastTheBorder) {
  // 3 x 1: 0, 0, 255. Texel 0's left neighbour: texel 2 (repeat: the slope falls, +x), texel 0
  // (clamp and mirror: (0 - 0), flat).
  const std::vector<std::uint8_t> reds = {0, 0, 255};
  EXPECT_GT(normalMapFromHeight(heights(3, 1, reds, TextureWrap::Repeat), 0.1).texel(0, 0)[0], 128);
  EXPECT_EQ(normalMapFromHeight(heights(3, 1, reds, TextureWrap::ClampToEdge), 0.1).texel(0, 0)[0], 128);
  EXPECT_EQ(normalMapFromHeight(heights(3, 1, reds, TextureWrap::MirroredRepeat), 0.1).texel(0, 0)[0], 128);
  // Texel 2's right neighbour: texel 0 under repeat (falls to 0 again: (0 - 0) / ..., flat),
  // itself under clamp and mirror ((255 - 0): rising, -x).
  EXPECT_EQ(normalMapFromHeight(heights(3, 1, reds, TextureWrap::Repeat), 0.1).texel(2, 0)[0], 128);
  EXPECT_LT(normalMapFromHeight(heights(3, 1, reds, TextureWrap::ClampToEdge), 0.1).texel(2, 0)[0], 128);
  EXPECT_LT(normalMapFromHeight(heights(3, 1, reds, TextureWrap::MirroredRepeat), 0.1).texel(2, 0)[0], 128);
}

// On a height field that is linear in u and v (a tilted plane, repeat-free interior), the
// normal map and the displaced mesh agree: the tangent-space normal (T = +u, B = +v, N) of the
// mesh is the map's normal, within the 8-bit encoding.
TEST(NormalMapFromHeight, AgreesWithTheDisplacedMesh) {
  const int n = 8;
  std::vector<std::uint8_t> reds;
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) reds.push_back(static_cast<std::uint8_t>(20 * x + 10 * y));
  const Texture h = heights(n, n, reds, TextureWrap::ClampToEdge);
  const float s = 0.4f;  // slopes of 0.63 and 0.31 per uv: a normal 14 degrees off +z
  const Texture normal = normalMapFromHeight(h, s);
  // A 2 x 2 plane, uv_scale 1: world per uv 2; vertices on texel corners, one per texel.
  const Mesh mesh = makeHeightfield(vec2(2.0f), 1.0f, h, s, ivec2(n, n));
  // Vertex (4, 4) sits at uv (0.5, 0.5), between texels 3 and 4, where both slopes are constant.
  const Vertex& v = mesh.vertices[4 * (n + 1) + 4];
  ASSERT_NEAR(v.uv.x, 0.5f, 1e-6f);
  ASSERT_NEAR(v.uv.y, 0.5f, 1e-6f);
  // Model space: T = +X is +u, -Z is +v (makePlane), +Y out of the surface.
  const glm::dvec3 meshTangentSpace(v.nModel.x, -v.nModel.z, v.nModel.y);
  const glm::dvec3 map = decoded(normal, 4, 4);
  EXPECT_NEAR(map.x, meshTangentSpace.x, kDecodeStep);
  EXPECT_NEAR(map.y, meshTangentSpace.y, kDecodeStep);
  EXPECT_NEAR(map.z, meshTangentSpace.z, kDecodeStep);
  EXPECT_LT(map.x, -0.1);  // the case checks something
}

TEST(NormalMapFromHeight, Refusals) {
  EXPECT_THROW(normalMapFromHeight(Texture{}, 0.05), InputError);
  EXPECT_THROW(normalMapFromHeight(heights(1, 1, {0}), -0.1), InputError);
  EXPECT_THROW(normalMapFromHeight(heights(1, 1, {0}), std::nan("")), InputError);
}

}  // namespace
}  // namespace twr
