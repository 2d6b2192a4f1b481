// Headless OSMesa renders of small scenes with hand-computed expectations: coverage,
// background, depth read-back, triangle ids, culling, user clip planes, depth clamp,
// texture orientation, every view and material permutation.
#include "gl_test_scenes.h"
#include "glrender/gl_renderer.h"
#include "scene/errors.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <string>
#include <utility>

namespace twr {
namespace {

using gltest::addNode;
using gltest::covered;
using gltest::emptyScene;
using gltest::index;
using gltest::kSide;
using gltest::pixel;
using gltest::quadAt;

// Pixel (x, top-first row) containing the world point (x, y, z) for the front camera
// (90 degree fov, square image): ndc = (x, y) / -z, window = (ndc + 1) / 2 * kSide.
struct PixelPos {
  int x, row;
};
PixelPos project(float x, float y, float z) {
  const float windowX = (x / -z + 1.0f) * 0.5f * static_cast<float>(kSide);
  const float windowY = (y / -z + 1.0f) * 0.5f * static_cast<float>(kSide);
  return {static_cast<int>(std::floor(windowX)), kSide - 1 - static_cast<int>(std::floor(windowY))};
}

RenderOutput renderGl(const Scene& scene, const RenderSettings& settings) {
  const auto renderer = makeGlRenderer();
  return renderer->render(scene, settings, kSide, kSide);
}

TEST(GlRender, BackgroundIsClearedWithTheSceneAlphaAndGeometryHasAlphaOne) {
  Scene scene = emptyScene();
  addNode(scene, quadAt(-2.0f, -1.0f, -1.0f, 1.0f, 1.0f), "quad");
  const RenderOutput out = renderGl(scene, scene.settings);
  ASSERT_EQ(out.width, kSide);
  ASSERT_EQ(out.height, kSide);
  ASSERT_EQ(out.rgba.size(), static_cast<std::size_t>(kSide * kSide * 4));
  // The quad spans ndc [-0.5, 0.5]: pixels 16..47 both ways.
  EXPECT_TRUE(covered(out, 32, 32));
  EXPECT_TRUE(covered(out, 16, 16));
  EXPECT_TRUE(covered(out, 47, 47));
  EXPECT_FALSE(covered(out, 15, 32));
  EXPECT_FALSE(covered(out, 48, 32));
  EXPECT_EQ(gltest::coveredCount(out), 32u * 32u);
  // Background (0.2, 0.4, 0.6, 1) -> round(c * 255) = 51, 102, 153, 255: opaque by default.
  const std::uint8_t* corner = pixel(out, 0, 0);
  EXPECT_EQ(corner[0], 51);
  EXPECT_EQ(corner[1], 102);
  EXPECT_EQ(corner[2], 153);
  EXPECT_EQ(corner[3], 255);
  EXPECT_EQ(pixel(out, 32, 32)[3], 255);
  EXPECT_EQ(out.depth[index(out, 0, 0)], 1.0f);
  EXPECT_EQ(out.triangleId[index(out, 0, 0)], kNoTriangle);
  EXPECT_EQ(out.stats.trianglesIn, 2u);
  EXPECT_EQ(out.stats.pixelsShaded, 32u * 32u);
  EXPECT_GT(out.stats.milliseconds, 0.0);

  // Transparent and half-transparent backgrounds: only the empty pixels' alpha moves.
  for (const auto& [alpha, byte] : {std::pair{0.0f, 0}, std::pair{0.5f, 128}}) {
    scene.output.background.a = alpha;
    const RenderOutput other = renderGl(scene, scene.settings);
    EXPECT_EQ(pixel(other, 0, 0)[3], byte) << alpha;
    EXPECT_EQ(pixel(other, 32, 32)[3], 255) << alpha;
    EXPECT_EQ(gltest::coveredCount(other), 32u * 32u) << alpha;
    for (std::size_t i = 0; i < out.triangleId.size(); ++i) {
      for (std::size_t c = 0; c < 3; ++c) ASSERT_EQ(other.rgba[i * 4 + c], out.rgba[i * 4 + c]) << i;
      ASSERT_EQ(other.rgba[i * 4 + 3], out.triangleId[i] != kNoTriangle ? 255 : byte) << i;
      ASSERT_EQ(other.triangleId[i], out.triangleId[i]) << i;
    }
  }
}

TEST(GlRender, DepthReadBackIsWindowDepthOfAPlaneAtKnownDistance) {
  Scene scene = emptyScene();
  addNode(scene, quadAt(-3.0f, -4.0f, -4.0f, 4.0f, 4.0f), "wall");
  const RenderOutput out = renderGl(scene, scene.settings);
  // n = 1, f = 10, z_view = -3: z_ndc = (f + n) / (f - n) + 2 f n / ((f - n) z_view)
  // = 11/9 - 20/27 = 13/27; window depth = 0.5 * 13/27 + 0.5 = 20/27.
  const float expected = 20.0f / 27.0f;
  constexpr float kDepthTolerance = 1.0f / (1 << 20);  // 24-bit storage plus float transforms
  for (int y = 0; y < kSide; ++y) {
    for (int x = 0; x < kSide; ++x) {
      ASSERT_TRUE(covered(out, x, y)) << x << "," << y;
      ASSERT_NEAR(out.depth[index(out, x, y)], expected, kDepthTolerance) << x << "," << y;
    }
  }
}

TEST(GlRender, TriangleIdsAreGlobalAcrossTheDrawList) {
  Scene scene = emptyScene();
  addNode(scene, quadAt(-2.0f, -1.8f, -1.0f, -0.2f, 1.0f), "left");  // triangles 0 and 1
  addNode(scene, makeTriangles({{0.5f, -1.0f, -2.0f}, {1.8f, -1.0f, -2.0f}, {1.2f, 1.0f, -2.0f}}, {}, {}),
          "right");  // triangle 2
  const RenderOutput out = renderGl(scene, scene.settings);
  // quadAt's first triangle is the lower-right half (x0,y0)-(x1,y0)-(x1,y1).
  const PixelPos lowerRight = project(-0.5f, -0.8f, -2.0f);
  const PixelPos upperLeft = project(-1.5f, 0.8f, -2.0f);
  const PixelPos right = project(1.2f, -0.5f, -2.0f);
  EXPECT_EQ(out.triangleId[index(out, lowerRight.x, lowerRight.row)], 0u);
  EXPECT_EQ(out.triangleId[index(out, upperLeft.x, upperLeft.row)], 1u);
  EXPECT_EQ(out.triangleId[index(out, right.x, right.row)], 2u);
  EXPECT_EQ(out.triangleId[index(out, 32, 2)], kNoTriangle);
  // With the default opaque background every alpha is 255; with a transparent one alpha is
  // 255 exactly where an id was written, and the ids do not move.
  Scene clear = scene;
  clear.output.background.a = 0.0f;
  const RenderOutput transparent = renderGl(clear, clear.settings);
  for (int y = 0; y < kSide; ++y) {
    for (int x = 0; x < kSide; ++x) {
      EXPECT_EQ(pixel(out, x, y)[3], 255);
      EXPECT_EQ(transparent.triangleId[index(out, x, y)], out.triangleId[index(out, x, y)]);
      EXPECT_EQ(out.triangleId[index(out, x, y)] != kNoTriangle, pixel(transparent, x, y)[3] == 255);
    }
  }
}

struct CullCase {
  CullMode cull;
  FrontFace frontFace;
  bool visible;  // for a triangle counter-clockwise on screen
};

class GlCulling : public ::testing::TestWithParam<CullCase> {};

TEST_P(GlCulling, SingleCounterClockwiseTriangle) {
  const CullCase c = GetParam();
  Scene scene = emptyScene();
  addNode(scene, makeTriangles({{-1.0f, -1.0f, -2.0f}, {1.0f, -1.0f, -2.0f}, {0.0f, 1.0f, -2.0f}}, {}, {}), "tri");
  RenderSettings settings = scene.settings;
  settings.cull = c.cull;
  settings.frontFace = c.frontFace;
  const RenderOutput out = renderGl(scene, settings);
  const PixelPos centre = project(0.0f, -0.3f, -2.0f);
  EXPECT_EQ(covered(out, centre.x, centre.row), c.visible);
  EXPECT_EQ(gltest::coveredCount(out) > 0, c.visible);
}

INSTANTIATE_TEST_SUITE_P(AllModes, GlCulling,
                         ::testing::Values(CullCase{CullMode::None, FrontFace::Ccw, true},
                                           CullCase{CullMode::None, FrontFace::Cw, true},
                                           CullCase{CullMode::Back, FrontFace::Ccw, true},
                                           CullCase{CullMode::Back, FrontFace::Cw, false},
                                           CullCase{CullMode::Front, FrontFace::Ccw, false},
                                           CullCase{CullMode::Front, FrontFace::Cw, true}));

TEST(GlRender, UserClipPlanesCutGeometry) {
  Scene scene = emptyScene();
  addNode(scene, quadAt(-2.0f, -3.0f, -3.0f, 3.0f, 3.0f), "wall");
  RenderSettings settings = scene.settings;
  settings.userClipPlanes = {vec4(1.0f, 0.0f, 0.0f, 0.0f)};  // keeps x >= 0
  RenderOutput out = renderGl(scene, settings);
  // x = 0 is the image's middle column boundary: columns 0..31 cut, 32..63 kept.
  for (int y = 0; y < kSide; ++y) {
    EXPECT_FALSE(covered(out, 31, y)) << y;
    EXPECT_TRUE(covered(out, 32, y)) << y;
  }
  EXPECT_EQ(gltest::coveredCount(out), static_cast<std::size_t>(kSide * kSide / 2));

  settings.userClipPlanes.push_back(vec4(0.0f, -1.0f, 0.0f, 0.5f));  // and y <= 0.5
  out = renderGl(scene, settings);
  const PixelPos kept = project(1.0f, 0.0f, -2.0f);
  const PixelPos cutAbove = project(1.0f, 1.0f, -2.0f);
  EXPECT_TRUE(covered(out, kept.x, kept.row));
  EXPECT_FALSE(covered(out, cutAbove.x, cutAbove.row));
}

TEST(GlRender, NearPlaneOffClampsDepthInsteadOfClipping) {
  Scene scene = emptyScene();
  addNode(scene, quadAt(-0.5f, -3.0f, -3.0f, 3.0f, 3.0f), "too close");  // near is 1
  RenderSettings settings = scene.settings;
  RenderOutput out = renderGl(scene, settings);
  EXPECT_EQ(gltest::coveredCount(out), 0u);
  settings.clip.near = false;
  out = renderGl(scene, settings);
  EXPECT_EQ(gltest::coveredCount(out), static_cast<std::size_t>(kSide * kSide));
  EXPECT_EQ(out.depth[index(out, 32, 32)], 0.0f);
}

// GL has no switch for one of near/far alone: with far off the near plane must still cut
// (it returns as a clip distance), and with near off the far plane still... is GL_LESS
// against the cleared depth 1, which hides what depth clamp pushes to 1.
TEST(GlRender, NearAndFarSwitchAlone) {
  Scene scene = emptyScene();
  // A floor at y = -0.5 from z = -0.2 (in front of near = 1) to z = -20 (beyond far = 10).
  addNode(scene,
          makeTriangles({{-2.0f, -0.5f, -0.2f}, {2.0f, -0.5f, -0.2f}, {2.0f, -0.5f, -20.0f},
                         {-2.0f, -0.5f, -0.2f}, {2.0f, -0.5f, -20.0f}, {-2.0f, -0.5f, -20.0f}},
                        {}, {}),
          "floor");
  scene.settings.cull = CullMode::None;
  const auto renderer = makeGlRenderer();
  const RenderOutput bothOn = renderer->render(scene, scene.settings, kSide, kSide);
  RenderSettings farOff = scene.settings;
  farOff.clip.far = false;
  const RenderOutput onlyNear = renderer->render(scene, farOff, kSide, kSide);
  RenderSettings nearOff = scene.settings;
  nearOff.clip.near = false;
  const RenderOutput onlyFar = renderer->render(scene, nearOff, kSide, kSide);

  EXPECT_EQ(onlyNear.rgba, bothOn.rgba);
  // Depth agrees to rounding: where the far plane cut, the triangles interpolate from
  // the clipper's new vertices instead of the original ones.
  constexpr float kDepthTolerance = 1.0f / (1 << 20);
  for (std::size_t i = 0; i < bothOn.depth.size(); ++i) {
    ASSERT_NEAR(onlyNear.depth[i], bothOn.depth[i], kDepthTolerance) << i;
  }
  // Near off draws the floor down to the image's bottom row, where near on cut it: the
  // near plane meets the floor at y_ndc = -0.5 / 1 -> rows below 63 - 16 = 47 are empty.
  EXPECT_FALSE(covered(bothOn, 32, 60));
  EXPECT_TRUE(covered(onlyFar, 32, 60));
  EXPECT_EQ(onlyFar.depth[index(onlyFar, 32, 60)], 0.0f);
  EXPECT_GT(gltest::coveredCount(onlyFar), gltest::coveredCount(bothOn));
}

TEST(GlRender, TexturesAreUploadedBottomRowFirstAndSampledNearest) {
  auto texture = std::make_shared<Texture>();
  texture->path = "2x2 in code";
  texture->width = 2;
  texture->height = 2;
  // Row 0 (v = 0, bottom): red, green; row 1 (top): blue, white.
  texture->rgba = {255, 0, 0, 255, 0, 255, 0, 255, 0, 0, 255, 255, 255, 255, 255, 255};
  Scene scene = emptyScene();
  Material material;
  material.kd = vec3(1.0f);
  material.diffuseMap = texture;
  scene.materials.push_back(material);
  addNode(scene, quadAt(-2.0f, -2.0f, -2.0f, 2.0f, 2.0f), "textured", 0);
  RenderSettings settings = scene.settings;
  settings.view = View::Albedo;
  settings.textureFilter = TextureFilter::Nearest;
  const RenderOutput out = renderGl(scene, settings);
  const auto expectColour = [&](int x, int row, int r, int g, int b) {
    const std::uint8_t* p = pixel(out, x, row);
    EXPECT_EQ(p[0], r) << x << "," << row;
    EXPECT_EQ(p[1], g) << x << "," << row;
    EXPECT_EQ(p[2], b) << x << "," << row;
    EXPECT_EQ(p[3], 255) << x << "," << row;
  };
  expectColour(8, 56, 255, 0, 0);      // bottom left
  expectColour(56, 56, 0, 255, 0);     // bottom right
  expectColour(8, 8, 0, 0, 255);       // top left
  expectColour(56, 8, 255, 255, 255);  // top right
}

std::shared_ptr<Texture> solid(const std::string& name, std::uint8_t r, std::uint8_t g, std::uint8_t b) {
  auto texture = std::make_shared<Texture>();
  texture->path = name;
  texture->width = 2;
  texture->height = 2;
  for (int i = 0; i < 4; ++i) texture->rgba.insert(texture->rgba.end(), {r, g, b, 255});
  return texture;
}

// Each map reaches its own sampler: albedo shows the diffuse map, mapped_normal the
// normal map, shaded with only specular light the specular map.
TEST(GlRender, EachMaterialMapIsBoundToItsOwnSampler) {
  Scene scene = emptyScene();
  Material material;
  material.ka = vec3(0.0f);
  material.kd = vec3(1.0f);
  material.ks = vec3(0.0f);
  material.diffuseMap = solid("diffuse", 200, 40, 10);
  material.normalMap = solid("normal", 128, 128, 255);
  material.specularMap = solid("specular", 30, 90, 250);
  scene.materials.push_back(material);
  addNode(scene, quadAt(-2.0f, -2.0f, -2.0f, 2.0f, 2.0f), "mapped", 0);
  const auto renderer = makeGlRenderer();
  RenderSettings settings = scene.settings;
  settings.view = View::Albedo;
  RenderOutput out = renderer->render(scene, settings, kSide, kSide);
  EXPECT_EQ(pixel(out, 32, 32)[0], 200);
  EXPECT_EQ(pixel(out, 32, 32)[1], 40);
  EXPECT_EQ(pixel(out, 32, 32)[2], 10);

  // Normal texel (128, 128, 255): 2 * c / 255 - 1 = (0.00392, 0.00392, 1), normalised
  // (0.00392, 0.00392, 0.99998), encoded (0.50196, 0.50196, 0.99999) -> 128, 128, 255.
  settings.view = View::MappedNormal;
  settings.lightingSpace = LightingSpace::Tangent;
  out = renderer->render(scene, settings, kSide, kSide);
  EXPECT_EQ(pixel(out, 32, 32)[0], 128);
  EXPECT_EQ(pixel(out, 32, 32)[1], 128);
  EXPECT_EQ(pixel(out, 32, 32)[2], 255);

  // Only specular: ks = 1, shininess 0 makes pow(RdotV, 0) = 1 wherever N.L > 0, the light
  // at the eye with If = 1: colour = specScale = the specular texel.
  scene.materials[0].kd = vec3(0.0f);
  scene.materials[0].ks = vec3(1.0f);
  scene.materials[0].shininess = 0.0f;
  settings.view = View::Shaded;
  out = renderer->render(scene, settings, kSide, kSide);
  EXPECT_EQ(pixel(out, 32, 32)[0], 30);
  EXPECT_EQ(pixel(out, 32, 32)[1], 90);
  EXPECT_EQ(pixel(out, 32, 32)[2], 250);
}

std::shared_ptr<Texture> checker(const std::string& name, std::uint8_t a, std::uint8_t b) {
  auto texture = std::make_shared<Texture>();
  texture->path = name;
  texture->width = 4;
  texture->height = 4;
  for (int y = 0; y < 4; ++y) {
    for (int x = 0; x < 4; ++x) {
      const std::uint8_t v = ((x + y) % 2 == 0) ? a : b;
      texture->rgba.insert(texture->rgba.end(), {v, v, 255, 255});
    }
  }
  return texture;
}

// Every view, both lighting spaces, with and without all material maps: the permutation
// compiles, the sphere covers the centre and not the corners, and every pixel is finite
// colour (alpha 255 exactly where the sphere is).
TEST(GlRender, EveryViewAndPermutationRenders) {
  Scene scene = emptyScene();
  scene.lights[0].posWorld = vec3(1.0f, 1.0f, 0.0f);
  Material plain;
  plain.kd = vec3(0.5f, 0.25f, 1.0f);
  plain.ks = vec3(0.5f);
  Material mapped = plain;
  mapped.diffuseMap = checker("diffuse", 200, 100);
  mapped.normalMap = checker("normal", 128, 160);
  mapped.specularMap = checker("specular", 255, 0);
  scene.materials = {plain, mapped};
  const auto renderer = makeGlRenderer();
  for (int materialIndex : {0, 1}) {
    scene.meshes.clear();
    scene.meshDescs.clear();
    scene.nodes.clear();
    addNode(scene, makeSphere(1.0f, 12, 24), "sphere", materialIndex);
    scene.nodes[0].translate = vec3(0.0f, 0.0f, -3.0f);
    for (LightingSpace space : {LightingSpace::World, LightingSpace::Tangent}) {
      for (View view : kAllViews) {
        RenderSettings settings = scene.settings;
        settings.view = view;
        settings.lightingSpace = space;
        const RenderOutput out = renderer->render(scene, settings, kSide, kSide);
        SCOPED_TRACE(std::string(toString(view)) + " " + std::string(toString(space)) + " material " +
                     std::to_string(materialIndex));
        EXPECT_TRUE(covered(out, 32, 32));
        EXPECT_FALSE(covered(out, 0, 0));
        EXPECT_FALSE(covered(out, 63, 63));
        // A sphere of radius 1 at distance 3 covers ndc radius ~ 1/sqrt(8) = 0.354: about
        // pi (0.354 * 32)^2 = 402 pixels.
        EXPECT_NEAR(static_cast<double>(gltest::coveredCount(out)), 402.0, 40.0);
        if (view == View::Normal) {
          // Pixel (32, row 32) has its centre at ndc (1/64, -1/64): the ray meets the sphere
          // near (0.031, -0.031, -2), normal ~ (0.031, -0.031, 1), encoded 131.5, 123.5, 255
          // (the 12 x 24 tessellation interpolates normals, hence the tolerance).
          const std::uint8_t* p = pixel(out, 32, 32);
          EXPECT_NEAR(p[0], 131.5, 3.0);
          EXPECT_NEAR(p[1], 123.5, 3.0);
          EXPECT_EQ(p[2], 255);
        }
        if (view == View::Depth) {
          // Front of the sphere at z_view ~ -2: z_ndc = 11/9 - 20/18 = 1/9, depth 5/9 -> 142.
          EXPECT_NEAR(pixel(out, 32, 32)[0], 142, 2);
        }
        if (view == View::Albedo && materialIndex == 0) {
          const std::uint8_t* p = pixel(out, 32, 32);  // kd = (0.5, 0.25, 1) -> 128, 64, 255
          EXPECT_EQ(p[0], 128);
          EXPECT_EQ(p[1], 64);
          EXPECT_EQ(p[2], 255);
        }
      }
    }
  }
}

TEST(GlRender, ReportsContextAndPreciseSampling) {
  Scene scene = emptyScene();
  addNode(scene, quadAt(-2.0f, -1.0f, -1.0f, 1.0f, 1.0f), "quad");
  renderGl(scene, scene.settings);
  EXPECT_NE(glVersionString().find("Mesa"), std::string::npos) << glVersionString();
  EXPECT_NE(glRendererString().find("llvmpipe"), std::string::npos) << glRendererString();
  EXPECT_EQ(glSamplingMode(), "precise");
  const char* perf = std::getenv("GALLIVM_PERF");
  ASSERT_NE(perf, nullptr);
  EXPECT_NE(std::string(perf).find("no_aos_sampling"), std::string::npos);
  EXPECT_NE(std::string(perf).find("no_quad_lod"), std::string::npos);
}

}  // namespace
}  // namespace twr
