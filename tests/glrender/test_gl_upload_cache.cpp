// The GL upload cache: meshes and textures stay uploaded across renders, and a render still
// shows every change a caller makes between renders (a mesh edited in place, a mesh rebuilt
// at the same address, a texture replaced, the filter switched), because a reused entry must
// prove it is unchanged.
#include "gl_test_scenes.h"
#include "glrender/context_osmesa.h"
#include "glrender/gl_context.h"
#include "glrender/gl_renderer.h"
#include "glrender/gl_upload_cache.h"

#include <gtest/gtest.h>

#include <memory>
#include <string>

namespace twr {
namespace {

using gltest::addNode;
using gltest::covered;
using gltest::emptyScene;
using gltest::kSide;
using gltest::pixel;
using gltest::quadAt;

std::shared_ptr<Texture> solid(const std::string& name, std::uint8_t r, std::uint8_t g, std::uint8_t b) {
  auto texture = std::make_shared<Texture>();
  texture->path = name;
  texture->width = 2;
  texture->height = 2;
  for (int i = 0; i < 4; ++i) texture->rgba.insert(texture->rgba.end(), {r, g, b, 255});
  return texture;
}

// The quad at depth 2 spans x in [x0, x1] world units: with the 90 degree camera, pixel
// column = (x / 2 + 1) / 2 * 64, so [-2, 0] covers columns 0..31 and [0, 2] columns 32..63.
TEST(GlUploadCache, MeshEditedInPlaceBetweenRendersIsRedrawn) {
  Scene scene = emptyScene();
  addNode(scene, quadAt(-2.0f, -2.0f, -2.0f, 0.0f, 2.0f), "left half");
  const auto renderer = makeGlRenderer();
  const RenderOutput before = renderer->render(scene, scene.settings, kSide, kSide);
  EXPECT_TRUE(covered(before, 16, 32));
  EXPECT_FALSE(covered(before, 48, 32));

  // Same Mesh object, same vertex count, new positions: only the bytes changed.
  for (Vertex& v : scene.meshes[0].vertices) v.posModel.x += 2.0f;
  const RenderOutput after = renderer->render(scene, scene.settings, kSide, kSide);
  EXPECT_FALSE(covered(after, 16, 32));
  EXPECT_TRUE(covered(after, 48, 32));

  // A rebuilt mesh assigned into the same slot (the GUI does this) lands at the same address.
  scene.meshes[0] = quadAt(-2.0f, -2.0f, -2.0f, 2.0f, 2.0f);
  const RenderOutput rebuilt = renderer->render(scene, scene.settings, kSide, kSide);
  EXPECT_TRUE(covered(rebuilt, 16, 32));
  EXPECT_TRUE(covered(rebuilt, 48, 32));
}

TEST(GlUploadCache, ReplacedTextureAndChangedFilterAreUsed) {
  Scene scene = emptyScene();
  Material material;
  material.diffuseMap = solid("red", 255, 0, 0);
  scene.materials.push_back(material);
  addNode(scene, quadAt(-2.0f, -2.0f, -2.0f, 2.0f, 2.0f), "quad", 0);
  RenderSettings settings = scene.settings;
  settings.view = View::Albedo;
  const auto renderer = makeGlRenderer();
  EXPECT_EQ(pixel(renderer->render(scene, settings, kSide, kSide), 32, 32)[0], 255);

  scene.materials[0].diffuseMap = solid("green", 0, 255, 0);
  const RenderOutput green = renderer->render(scene, settings, kSide, kSide);
  EXPECT_EQ(pixel(green, 32, 32)[0], 0);
  EXPECT_EQ(pixel(green, 32, 32)[1], 255);

  // A 2 x 1 texture black | white over the quad: nearest gives pure black or white at the
  // quarter points, bilinear blends them (u = 0.25 is a texel centre, so check the middle).
  auto ramp = std::make_shared<Texture>();
  ramp->path = "black|white";
  ramp->width = 2;
  ramp->height = 1;
  ramp->rgba = {0, 0, 0, 255, 255, 255, 255, 255};
  scene.materials[0].diffuseMap = ramp;
  settings.textureFilter = TextureFilter::Nearest;
  const RenderOutput nearest = renderer->render(scene, settings, kSide, kSide);
  settings.textureFilter = TextureFilter::Bilinear;
  const RenderOutput bilinear = renderer->render(scene, settings, kSide, kSide);
  const RenderOutput fresh = makeGlRenderer()->render(scene, settings, kSide, kSide);
  // Column 31 is just left of u = 0.5: nearest black, bilinear nearly half grey.
  EXPECT_EQ(pixel(nearest, 31, 32)[0], 0);
  EXPECT_GT(pixel(bilinear, 31, 32)[0], 100);
  EXPECT_EQ(bilinear.rgba, fresh.rgba);
}

// The cache itself, in an OSMesa context of its own: how often it uploads.
class GlUploadCacheCounts : public ::testing::Test {
 protected:
  void SetUp() override {
    OsMesaContextDesc desc;
    context_ = std::make_unique<OsMesaContext>(desc);
    context_->makeCurrent();
    OsMesaContext* raw = context_.get();
    loadCoreGl([raw](const char* name) { return raw->procAddress(name); }, "test context");
    cache_ = std::make_unique<GlUploadCache>();
  }
  void TearDown() override {
    cache_.reset();  // GL objects die while their context is current
    context_.reset();
  }
  std::unique_ptr<OsMesaContext> context_;
  std::unique_ptr<GlUploadCache> cache_;
};

TEST_F(GlUploadCacheCounts, UnchangedDataUploadsOnceChangedDataAgain) {
  Mesh mesh = quadAt(-2.0f, -1.0f, -1.0f, 1.0f, 1.0f);
  const std::shared_ptr<const Texture> texture = solid("t", 1, 2, 3);
  for (int frame = 0; frame < 3; ++frame) {
    cache_->beginFrame();
    EXPECT_EQ(cache_->mesh(mesh).indexCount, 6);
    EXPECT_NE(cache_->texture(texture, TextureFilter::Bilinear), 0u);
    cache_->endFrame();
  }
  EXPECT_EQ(cache_->meshUploads(), 1u);
  EXPECT_EQ(cache_->textureUploads(), 1u);
  EXPECT_EQ(texture.use_count(), 2) << "the cache holds the texture so its address stays unique";

  mesh.indices.resize(3);  // one triangle fewer
  cache_->beginFrame();
  EXPECT_EQ(cache_->mesh(mesh).indexCount, 3);
  cache_->endFrame();
  EXPECT_EQ(cache_->meshUploads(), 2u);
  EXPECT_EQ(texture.use_count(), 1) << "a frame that did not use the texture drops it";

  cache_->beginFrame();
  cache_->texture(texture, TextureFilter::Nearest);
  cache_->endFrame();
  EXPECT_EQ(cache_->textureUploads(), 2u);
}

}  // namespace
}  // namespace twr
