// Editing a material's map options from the UI (issue 15, item 6), with no window: each edit
// gives the material a new Texture (read again when the texels change, copied otherwise),
// leaves every other use of the old one alone, refuses what a scene file refuses, and both
// renderers, kept alive across the edit as the app keeps them, draw exactly what fresh ones
// draw from the edited scene (no stale GL upload, no stale tiled copy on the CPU fast path).
// And the height field's keys (issue 16): kept in the scene file's ranges, refused where it
// refuses them, and every edit that outdates the horizon map says so, until a map built for
// exactly the current keys is installed.
#include "gui/debug_views.h"
#include "gui/material_maps.h"
#include "gui/scene_doc.h"
#include "glrender/gl_renderer.h"
#include "scene/errors.h"
#include "softrender/cpu_renderer.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
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

// A bricks floor with a height map ("relief", drawn with `method` and self_shadow `shadow`) and
// a cube whose material "plain" has no height map, seen at 45 degrees.
fs::path writeHeightScene(const std::string& name, const std::string& method, const std::string& shadow) {
  const fs::path dir = fs::path(TWINRASTER_TEST_OUT) / "material_maps" / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  fs::copy_file(kTextures / "bricks_diffuse.png", dir / "diffuse.png");
  fs::copy_file(kTextures / "bricks_height.png", dir / "height.png");
  std::ofstream(dir / "scene.json") << R"({
    "camera": {"position": [0, 1.6, 1.6], "target": [0, 0, 0]},
    "lights": [{"position": [1.5, 1.0, 0.5]}],
    "materials": {"relief": {"diffuse_map": "diffuse.png", "height_map": "height.png", "height_scale": 0.05,
                             "surface_detail": ")" << method << R"(", "self_shadow": ")" << shadow << R"("},
                  "plain": {"kd": [0.8, 0.8, 0.8]}},
    "nodes": [{"name": "floor", "material": "relief", "mesh": {"type": "plane", "size": [2, 2], "uv_scale": 2}},
              {"name": "box", "material": "plain", "mesh": {"type": "cube", "size": 0.3}, "translate": [0.7, 0.15, 0.7]}]
  })";
  return dir / "scene.json";
}

constexpr std::size_t kRelief = 0, kPlain = 1;

TEST(HeightField, ClampKeepsTheSceneFilesRanges) {
  const HeightFieldSettings before;  // layers [8, 32]
  HeightFieldSettings s = before;
  s.heightScale = 5.0f;
  EXPECT_EQ(clampHeightField(s, before).heightScale, kMaxHeightScale) << "typed beyond the slider: at most 1";
  s.heightScale = -0.1f;
  EXPECT_EQ(clampHeightField(s, before).heightScale, 0.0f);
  s.heightScale = std::numeric_limits<float>::quiet_NaN();
  EXPECT_EQ(clampHeightField(s, before).heightScale, before.heightScale);

  s = before;
  s.parallaxLayers = {40, 32};  // min dragged past max: max follows
  EXPECT_EQ(clampHeightField(s, before).parallaxLayers, ivec2(40, 40));
  s.parallaxLayers = {8, 4};  // max dragged below min: min follows
  EXPECT_EQ(clampHeightField(s, before).parallaxLayers, ivec2(4, 4));
  s.parallaxLayers = {0, 999};
  EXPECT_EQ(clampHeightField(s, before).parallaxLayers, ivec2(1, kMaxParallaxLayers));

  s = before;
  s.reliefRefinementSteps = 99;
  EXPECT_EQ(clampHeightField(s, before).reliefRefinementSteps, kMaxReliefRefinementSteps);
  s.reliefRefinementSteps = -3;
  EXPECT_EQ(clampHeightField(s, before).reliefRefinementSteps, 0);
  for (const auto& [typed, kept] : {std::pair{7, 8}, {6, 8}, {5, 4}, {2, 4}, {0, 4}, {13, 12}, {99, 16}}) {
    s.horizonDirections = typed;
    EXPECT_EQ(clampHeightField(s, before).horizonDirections, kept) << typed;
  }
}

TEST(HeightField, MethodsThatReadAHeightMapAreRefusedWithoutOne) {
  SceneDoc doc = loadSceneDoc(writeHeightScene("refused", "bump_blinn", "none").string());
  const std::uint64_t revision = doc.revision;
  HeightFieldSettings s = heightFieldOf(doc.scene.materials[kPlain]);
  for (const SurfaceDetail method : kAllSurfaceDetails) {
    if (!readsHeightMap(method)) continue;
    s.surfaceDetail = method;
    EXPECT_THROW(setHeightField(doc, kPlain, s), InputError) << toString(method);
  }
  s = heightFieldOf(doc.scene.materials[kPlain]);
  s.selfShadow = SelfShadow::HeightMarch;
  EXPECT_THROW(setHeightField(doc, kPlain, s), InputError);
  EXPECT_EQ(doc.revision, revision) << "a refused edit changes nothing";
  EXPECT_EQ(doc.scene.materials[kPlain].surfaceDetail, SurfaceDetail::NormalMap);
  EXPECT_THROW(setHeightField(doc, 9, s), InputError) << "no such material";

  // The knobs themselves are harmless on normal_map (read by nothing, as in the scene file).
  s = heightFieldOf(doc.scene.materials[kPlain]);
  s.heightScale = 0.1f;
  EXPECT_TRUE(setHeightField(doc, kPlain, s).changed);
  EXPECT_GT(doc.revision, revision);

  // A height map switched off in the UI still counts: the method waits for it to come back.
  ASSERT_TRUE(setMapOn(doc, kRelief, MapSlot::Height, false));
  s = heightFieldOf(doc.scene.materials[kRelief]);
  s.surfaceDetail = SurfaceDetail::Relief;
  EXPECT_NO_THROW(setHeightField(doc, kRelief, s));
  EXPECT_EQ(doc.scene.materials[kRelief].surfaceDetail, SurfaceDetail::Relief);
}

// Builds what staleHorizonMap asks for, as the app's worker does, and installs it.
void rebuildHorizonMap(SceneDoc& doc) {
  const std::optional<HorizonRequest> request = staleHorizonMap(doc);
  ASSERT_TRUE(request.has_value());
  const std::uint64_t revision = doc.revision;
  auto map = std::make_shared<const HorizonMap>(makeHorizonMap(*request->heightMap, request->heightScale, request->directions));
  ASSERT_TRUE(installHorizonMap(doc, *request, map));
  EXPECT_EQ(doc.scene.materials[request->material].horizonMap, map);
  EXPECT_GT(doc.revision, revision) << "both renderers must draw the new map";
  EXPECT_FALSE(staleHorizonMap(doc).has_value());
}

TEST(HeightField, EditsSayWhenTheHorizonMapMustBeBuiltAgain) {
  SceneDoc doc = loadSceneDoc(writeHeightScene("horizon", "parallax_occlusion", "horizon_map").string());
  const Material& relief = doc.scene.materials[kRelief];
  ASSERT_TRUE(relief.horizonMap) << "the loader built it";
  EXPECT_FALSE(horizonMapStale(doc, kRelief)) << "built from the keys the file gave";
  const auto edit = [&](const std::function<void(HeightFieldSettings&)>& change) {
    HeightFieldSettings s = heightFieldOf(relief);
    change(s);
    return setHeightField(doc, kRelief, s);
  };

  HeightFieldEdit e = edit([](HeightFieldSettings& s) { s.parallaxLayers = {4, 64}; });
  EXPECT_TRUE(e.changed);
  EXPECT_FALSE(e.horizonMapStale) << "the march's layers are not in the horizon map";
  e = edit([](HeightFieldSettings& s) { s.surfaceDetail = SurfaceDetail::Relief; });
  EXPECT_FALSE(e.horizonMapStale);
  EXPECT_FALSE(edit([](HeightFieldSettings&) {}).changed) << "no change, no new frame";

  e = edit([](HeightFieldSettings& s) { s.heightScale = 0.08f; });
  EXPECT_TRUE(e.horizonMapStale) << "height_scale";
  const std::optional<HorizonRequest> outdated = staleHorizonMap(doc);
  ASSERT_TRUE(outdated.has_value());
  EXPECT_EQ(outdated->material, kRelief);
  EXPECT_EQ(outdated->heightScale, 0.08f);
  // The user moves on while it builds: that result is dropped, the current keys are asked for.
  e = edit([](HeightFieldSettings& s) { s.heightScale = 0.1f; });
  const auto old = relief.horizonMap;
  EXPECT_FALSE(installHorizonMap(
      doc, *outdated,
      std::make_shared<const HorizonMap>(makeHorizonMap(*outdated->heightMap, outdated->heightScale, outdated->directions))));
  EXPECT_EQ(relief.horizonMap, old);
  rebuildHorizonMap(doc);

  e = edit([](HeightFieldSettings& s) { s.horizonDirections = 16; });
  EXPECT_TRUE(e.horizonMapStale) << "horizon_directions";
  rebuildHorizonMap(doc);
  EXPECT_EQ(relief.horizonMap->directions, 16);

  // A new height map (flip_v reads the file again into a new Texture).
  TextureOptions flipped = loadedMap(doc, kRelief, MapSlot::Height)->options;
  flipped.flipV = true;
  setMapOptions(doc, kRelief, MapSlot::Height, flipped);
  EXPECT_TRUE(horizonMapStale(doc, kRelief)) << "the height map";
  rebuildHorizonMap(doc);

  // Not drawn, so not wanted: no self-shadow, normal_map, or the height map off.
  e = edit([](HeightFieldSettings& s) {
    s.selfShadow = SelfShadow::HeightMarch;
    s.heightScale = 0.02f;
  });
  EXPECT_FALSE(e.horizonMapStale);
  e = edit([](HeightFieldSettings& s) { s.selfShadow = SelfShadow::HorizonMap; });
  EXPECT_TRUE(e.horizonMapStale) << "back to horizon_map with another depth";
  e = edit([](HeightFieldSettings& s) { s.surfaceDetail = SurfaceDetail::NormalMap; });
  EXPECT_FALSE(horizonMapStale(doc, kRelief)) << "normal_map draws no self-shadow";
  e = edit([](HeightFieldSettings& s) { s.surfaceDetail = SurfaceDetail::SteepParallax; });
  ASSERT_TRUE(setMapOn(doc, kRelief, MapSlot::Height, false));
  EXPECT_FALSE(horizonMapStale(doc, kRelief)) << "height map off";
  ASSERT_TRUE(setMapOn(doc, kRelief, MapSlot::Height, true));
  rebuildHorizonMap(doc);
}

// What the app does for one edit: apply it, rebuild the horizon map when it says so. The
// renderers, kept alive as the app keeps them, draw what fresh ones draw, and the edit shows.
void expectHeightEditsRenderFresh(const std::function<std::unique_ptr<Renderer>()>& makeRenderer, const char* what) {
  SCOPED_TRACE(what);
  SceneDoc doc = loadSceneDoc(writeHeightScene(std::string("height_render_") + what, "bump_blinn", "none").string());
  const std::unique_ptr<Renderer> kept = makeRenderer();
  RenderOutput before = kept->render(doc.scene, doc.scene.settings, kWidth, kHeight);
  const auto edit = [&](const char* name, const std::function<void(HeightFieldSettings&)>& change) {
    SCOPED_TRACE(name);
    HeightFieldSettings s = heightFieldOf(doc.scene.materials[kRelief]);
    change(s);
    if (setHeightField(doc, kRelief, s).horizonMapStale) rebuildHorizonMap(doc);
    const RenderOutput after = kept->render(doc.scene, doc.scene.settings, kWidth, kHeight);
    const RenderOutput fresh = makeRenderer()->render(doc.scene, doc.scene.settings, kWidth, kHeight);
    EXPECT_EQ(after.rgba, fresh.rgba) << "the kept renderer drew a stale copy";
    EXPECT_NE(after.rgba, before.rgba) << "the edit changed nothing on screen";
    before = after;
  };
  edit("parallax_occlusion", [](HeightFieldSettings& s) { s.surfaceDetail = SurfaceDetail::ParallaxOcclusion; });
  edit("height_scale", [](HeightFieldSettings& s) { s.heightScale = 0.1f; });
  edit("horizon_map", [](HeightFieldSettings& s) { s.selfShadow = SelfShadow::HorizonMap; });
  edit("horizon_directions", [](HeightFieldSettings& s) { s.horizonDirections = 4; });
  edit("height_scale with a horizon map", [](HeightFieldSettings& s) { s.heightScale = 0.03f; });
  edit("relief", [](HeightFieldSettings& s) {
    s.surfaceDetail = SurfaceDetail::Relief;
    s.reliefRefinementSteps = 0;
  });
  edit("relief_refinement_steps", [](HeightFieldSettings& s) { s.reliefRefinementSteps = 8; });
}

TEST(HeightField, EditsRenderFreshOnTheCpuFastPath) {
  expectHeightEditsRenderFresh([] { return makeCpuRenderer(); }, "cpu_fast");
}

TEST(HeightField, EditsRenderFreshOnGl) { expectHeightEditsRenderFresh([] { return makeGlRenderer(); }, "gl"); }

// The legend's ramp is the view's: every pixel the parallax_steps view draws on the relief is,
// to a level, parallaxStepsColour(k / parallaxStepsMost) for a whole number of steps k.
TEST(HeightField, TheParallaxStepsLegendMatchesTheView) {
  SceneDoc doc = loadSceneDoc(writeHeightScene("steps_legend", "relief", "none").string());
  doc.scene.settings.view = View::ParallaxSteps;
  const Material& relief = doc.scene.materials[kRelief];
  const int most = parallaxStepsMost(relief);
  EXPECT_EQ(most, relief.parallaxLayers.y + relief.reliefRefinementSteps);
  for (const bool gl : {false, true}) {
    SCOPED_TRACE(gl ? "gl" : "cpu");
    const std::unique_ptr<Renderer> renderer = gl ? makeGlRenderer() : makeCpuRenderer();
    const RenderOutput out = renderer->render(doc.scene, doc.scene.settings, kWidth, kHeight);
    int checked = 0, worst = 0;
    for (std::size_t i = 0; i < out.depth.size(); ++i) {
      if (!drawnAt(out, i)) continue;  // the box has no height map: 0 steps, dark blue
      int best = 255;
      for (int k = 0; k <= most; ++k) {
        const vec3 c = parallaxStepsColour(static_cast<float>(k) / static_cast<float>(most));
        int far = 0;
        for (int ch = 0; ch < 3; ++ch) {
          far = std::max(far, std::abs(static_cast<int>(out.rgba[i * 4 + static_cast<std::size_t>(ch)]) -
                                       static_cast<int>(std::lround(c[ch] * 255.0f))));
        }
        best = std::min(best, far);
      }
      worst = std::max(worst, best);
      ++checked;
    }
    EXPECT_GT(checked, kWidth * kHeight / 4);
    EXPECT_LE(worst, 1) << "a colour the legend does not have";
  }
}

}  // namespace
}  // namespace twr::gui
