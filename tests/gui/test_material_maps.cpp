// Editing a material's map options from the UI (issue 15, item 6), with no window: each edit
// gives the material a new Texture (read again when the texels change, copied otherwise),
// leaves every other use of the old one alone, refuses what a scene file refuses, and both
// renderers, kept alive across the edit as the app keeps them, draw exactly what fresh ones
// draw from the edited scene (no stale GL upload, no stale tiled copy on the CPU fast path).
#include "app/gui/material_maps.h"
#include "app/gui/scene_doc.h"
#include "glrender/gl_renderer.h"
#include "scene/errors.h"
#include "softrender/cpu_renderer.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <functional>
#include <memory>
#include <string>

namespace twr::gui {
namespace {

namespace fs = std::filesystem;

const fs::path kTextures = fs::path(TWINRASTER_SOURCE_DIR) / "assets" / "textures";
constexpr int kWidth = 96, kHeight = 72;  // render size, pixels

// A scene whose materials "a" and "b" name the same diffuse file with the same options (so the
// loader shares one Texture), "a" also a normal map; a floor drawn with "a", a cube with "b".
// The files are copied beside it, so a test may delete them.
fs::path writeScene(const std::string& name) {
  const fs::path dir = fs::path(TWINRASTER_TEST_OUT) / "material_maps" / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  fs::copy_file(kTextures / "bricks_diffuse.png", dir / "diffuse.png");
  fs::copy_file(kTextures / "bricks_normal.png", dir / "normal.png");
  std::ofstream(dir / "scene.json") << R"({
    "camera": {"position": [0, 1.2, 2.5], "target": [0, 0, 0]},
    "lights": [{"position": [1, 2, 2]}],
    "materials": {"a": {"ks": [0.3, 0.3, 0.3], "diffuse_map": "diffuse.png", "normal_map": "normal.png"},
                  "b": {"diffuse_map": "diffuse.png"}},
    "nodes": [{"name": "floor", "material": "a", "mesh": {"type": "plane", "size": [4, 4], "uv_scale": 1.7},
               "translate": [0, -0.5, 0]},
              {"name": "box", "material": "b", "mesh": {"type": "cube", "size": 0.8}, "rotate_deg": [0, 30, 0]}]
  })";
  return dir / "scene.json";
}

constexpr std::size_t kA = 0, kB = 1;  // material indices, in file order

// Row y of level 0, RGBA8.
std::vector<std::uint8_t> row(const Texture& t, int y) {
  const auto begin = t.rgba.begin() + static_cast<std::ptrdiff_t>(y) * t.width * 4;
  return {begin, begin + t.width * 4};
}

TEST(MaterialMaps, FlipVReadsTheFileAgainIntoANewTextureForThisMaterialOnly) {
  SceneDoc doc = loadSceneDoc(writeScene("flip").string());
  const std::shared_ptr<const Texture> old = doc.scene.materials[kA].diffuseMap;
  ASSERT_TRUE(old);
  ASSERT_EQ(old, doc.scene.materials[kB].diffuseMap) << "the loader shares one file read with the same options";
  const std::vector<std::uint8_t> oldTexels = old->rgba;
  const std::uint64_t revision = doc.revision;

  TextureOptions options = old->options;
  options.flipV = true;
  EXPECT_TRUE(setMapOptions(doc, kA, MapSlot::Diffuse, options).empty());

  const std::shared_ptr<const Texture>& made = doc.scene.materials[kA].diffuseMap;
  ASSERT_TRUE(made);
  EXPECT_NE(made.get(), old.get()) << "a new object: the caches key textures by object";
  EXPECT_TRUE(made->options.flipV);
  EXPECT_EQ(made->path, old->path);
  EXPECT_EQ(doc.loadedMaps[kA][0], made) << "switching the map off and on keeps the edit";
  EXPECT_GT(doc.revision, revision);
  // The rows are turned around, level 0 and the built chain alike.
  ASSERT_EQ(made->width, old->width);
  ASSERT_EQ(made->height, old->height);
  for (int y : {0, 1, old->height / 2, old->height - 1}) EXPECT_EQ(row(*made, y), row(*old, old->height - 1 - y)) << y;
  ASSERT_EQ(made->levelCount(), old->levelCount());
  // Every other use keeps the old object, untouched.
  EXPECT_EQ(doc.scene.materials[kB].diffuseMap, old);
  EXPECT_EQ(doc.loadedMaps[kB][0], old);
  EXPECT_FALSE(old->options.flipV);
  EXPECT_EQ(old->rgba, oldTexels);
}

TEST(MaterialMaps, WrapAndGreenCopyTheTexelsWithoutReadingTheFile) {
  const fs::path scene = writeScene("copy");
  SceneDoc doc = loadSceneDoc(scene.string());
  const std::shared_ptr<const Texture> oldNormal = doc.scene.materials[kA].normalMap;
  ASSERT_TRUE(oldNormal);
  fs::remove(scene.parent_path() / "normal.png");  // a copy needs no file

  TextureOptions options = oldNormal->options;
  options.wrap = TextureWrap::MirroredRepeat;
  options.green = GreenAxis::Down;
  EXPECT_FALSE(optionsChangeTexels(oldNormal->options, options));
  setMapOptions(doc, kA, MapSlot::Normal, options);
  const std::shared_ptr<const Texture>& made = doc.scene.materials[kA].normalMap;
  EXPECT_NE(made.get(), oldNormal.get());
  EXPECT_EQ(made->options.wrap, TextureWrap::MirroredRepeat);
  EXPECT_EQ(made->options.green, GreenAxis::Down);
  EXPECT_EQ(made->rgba, oldNormal->rgba);
  ASSERT_EQ(made->levelCount(), oldNormal->levelCount());
  EXPECT_EQ(made->levelTexels(made->levelCount() - 1), oldNormal->levelTexels(oldNormal->levelCount() - 1));
  EXPECT_EQ(oldNormal->options.wrap, TextureWrap::Repeat);
}

TEST(MaterialMaps, RefusalsLeaveTheDocumentAsItWas) {
  const fs::path scene = writeScene("refusals");
  SceneDoc doc = loadSceneDoc(scene.string());
  const std::shared_ptr<const Texture> old = doc.scene.materials[kA].diffuseMap;
  const std::uint64_t revision = doc.revision;
  TextureOptions green = old->options;
  green.green = GreenAxis::Down;
  EXPECT_THROW(setMapOptions(doc, kA, MapSlot::Diffuse, green), InputError) << "green is a normal-map option";
  EXPECT_THROW(setMapOptions(doc, kB, MapSlot::Normal, TextureOptions{}), InputError) << "b has no normal map";
  EXPECT_THROW(setMapOptions(doc, 7, MapSlot::Diffuse, TextureOptions{}), InputError);

  fs::remove(scene.parent_path() / "diffuse.png");
  TextureOptions flip = old->options;
  flip.flipV = true;
  try {
    setMapOptions(doc, kA, MapSlot::Diffuse, flip);
    FAIL() << "the file is gone";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("diffuse.png"), std::string::npos) << e.what();
  }
  EXPECT_EQ(doc.scene.materials[kA].diffuseMap, old);
  EXPECT_EQ(doc.loadedMaps[kA][0], old);
  EXPECT_EQ(doc.revision, revision);
  // The same options again: nothing to do, nothing read.
  EXPECT_NO_THROW(setMapOptions(doc, kA, MapSlot::Diffuse, old->options));
  EXPECT_EQ(doc.scene.materials[kA].diffuseMap, old);
}

TEST(MaterialMaps, SrgbOnANormalMapWarnsAsTheSceneFileDoes) {
  SceneDoc doc = loadSceneDoc(writeScene("srgb").string());
  TextureOptions options = doc.scene.materials[kA].normalMap->options;
  options.srgb = true;
  const std::vector<std::string> warnings = setMapOptions(doc, kA, MapSlot::Normal, options);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].find("normal.png: a normal map holds directions"), std::string::npos) << warnings[0];
  EXPECT_TRUE(doc.scene.materials[kA].normalMap->options.srgb);
  // An edit that keeps srgb does not repeat the warning.
  options.wrap = TextureWrap::ClampToEdge;
  EXPECT_EQ(setMapOptions(doc, kA, MapSlot::Normal, options).size(), 1u);
}

TEST(MaterialMaps, AnEditWhileTheMapIsOffWaitsForItToComeBack) {
  SceneDoc doc = loadSceneDoc(writeScene("off").string());
  ASSERT_TRUE(setMapOn(doc, kA, MapSlot::Diffuse, false));
  EXPECT_FALSE(mapOn(doc, kA, MapSlot::Diffuse));
  EXPECT_FALSE(doc.scene.materials[kA].diffuseMap);
  const std::uint64_t revision = doc.revision;
  TextureOptions options = loadedMap(doc, kA, MapSlot::Diffuse)->options;
  options.wrap = TextureWrap::ClampToEdge;
  setMapOptions(doc, kA, MapSlot::Diffuse, options);
  EXPECT_FALSE(doc.scene.materials[kA].diffuseMap) << "still off";
  EXPECT_EQ(doc.revision, revision) << "nothing drawn changed";
  ASSERT_TRUE(setMapOn(doc, kA, MapSlot::Diffuse, true));
  EXPECT_EQ(doc.scene.materials[kA].diffuseMap->options.wrap, TextureWrap::ClampToEdge);
  EXPECT_GT(doc.revision, revision);
  EXPECT_FALSE(setMapOn(doc, kB, MapSlot::Normal, true)) << "b has no normal map to switch on";
}

TEST(MaterialMaps, BudgetCountsEveryDistinctTextureOnce) {
  SceneDoc doc = loadSceneDoc(writeScene("budget").string());
  const Texture& diffuse = *doc.scene.materials[kA].diffuseMap;
  const Texture& normal = *doc.scene.materials[kA].normalMap;
  EXPECT_EQ(documentTextureBytes(doc), textureTexelBytes(diffuse) + textureTexelBytes(normal));
  TextureOptions options = diffuse.options;
  options.wrap = TextureWrap::ClampToEdge;
  setMapOptions(doc, kA, MapSlot::Diffuse, options);  // b keeps the shared one: two copies now
  EXPECT_EQ(documentTextureBytes(doc), 2 * textureTexelBytes(*doc.scene.materials[kB].diffuseMap) +
                                           textureTexelBytes(*doc.scene.materials[kA].normalMap));
}

// Renders with one long-lived renderer, as the app does, and checks that after each edit it
// draws what a new renderer draws from the edited scene, and that the edit changed the image.
void expectEditsRenderFresh(const std::function<std::unique_ptr<Renderer>()>& makeRenderer, const char* what) {
  SCOPED_TRACE(what);
  SceneDoc doc = loadSceneDoc(writeScene(std::string("render_") + what).string());
  doc.scene.settings.textureFilter = TextureFilter::Trilinear;  // every mip level matters
  const std::unique_ptr<Renderer> kept = makeRenderer();
  RenderOutput before = kept->render(doc.scene, doc.scene.settings, kWidth, kHeight);
  const auto edit = [&](MapSlot slot, const std::function<void(TextureOptions&)>& change, const char* name) {
    SCOPED_TRACE(name);
    TextureOptions options = loadedMap(doc, kA, slot)->options;
    change(options);
    setMapOptions(doc, kA, slot, options);
    const RenderOutput after = kept->render(doc.scene, doc.scene.settings, kWidth, kHeight);
    const RenderOutput fresh = makeRenderer()->render(doc.scene, doc.scene.settings, kWidth, kHeight);
    EXPECT_EQ(after.rgba, fresh.rgba) << "the kept renderer drew a stale copy";
    EXPECT_NE(after.rgba, before.rgba) << "the edit changed nothing on screen";
    before = after;
  };
  edit(MapSlot::Diffuse, [](TextureOptions& o) { o.flipV = true; }, "flip_v");
  edit(MapSlot::Diffuse, [](TextureOptions& o) { o.wrap = TextureWrap::MirroredRepeat; }, "wrap");
  edit(MapSlot::Diffuse, [](TextureOptions& o) { o.srgb = true; }, "srgb");
  edit(MapSlot::Normal, [](TextureOptions& o) { o.green = GreenAxis::Down; }, "green");
  edit(MapSlot::Diffuse, [](TextureOptions& o) { o.flipV = false; }, "flip_v back");
}

TEST(MaterialMaps, EditsRenderFreshOnTheCpuFastPath) {
  expectEditsRenderFresh([] { return makeCpuRenderer(); }, "cpu_fast");
}

TEST(MaterialMaps, EditsRenderFreshOnGl) {
  // One context per process is plenty; a renderer per call is what "fresh" means here.
  expectEditsRenderFresh([] { return makeGlRenderer(); }, "gl");
}

}  // namespace
}  // namespace twr::gui
