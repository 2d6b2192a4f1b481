// The CPU renderer end to end: buffers, statistics, orientation, every view on every asset
// scene without NaN, edge cases (tiny near plane, planes off, light at the surface,
// degenerate and mirrored UVs, user clip planes, TBN lines), and the pixel trace.
#include "softrender/cpu_renderer.h"
#include "softrender/pixel_trace.h"

#include "scene/errors.h"
#include "scene/primitives.h"
#include "scene/scene_file.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <memory>

namespace twr {
namespace {

Scene sceneWith(Mesh mesh, Material material = Material{}) {
  Scene scene;
  scene.camera.position = vec3(0, 0, 3);
  scene.camera.target = vec3(0, 0, 0);
  Light light;
  light.posWorld = vec3(1, 2, 3);
  scene.lights.push_back(light);
  scene.meshes.push_back(std::move(mesh));
  scene.materials.push_back(std::move(material));
  Node node;
  node.name = "mesh";
  node.meshIndex = 0;
  node.materialIndex = 0;
  scene.nodes.push_back(node);
  return scene;
}

RenderOutput render(const Scene& scene, const RenderSettings& settings, int w = 64, int h = 48) {
  return makeCpuRenderer()->render(scene, settings, w, h);
}

std::size_t coveredCount(const RenderOutput& out) {
  std::size_t n = 0;
  for (std::uint32_t id : out.triangleId) n += id != kNoTriangle ? 1 : 0;
  return n;
}

// Alpha, depth and id agree pixel by pixel and depth is finite in [0, 1]: drawn pixels have
// alpha 255, the others the background's (opaque unless the scene says otherwise).
void expectConsistentBuffers(const RenderOutput& out, std::uint8_t backgroundAlpha = 255) {
  const std::size_t count = static_cast<std::size_t>(out.width) * static_cast<std::size_t>(out.height);
  ASSERT_EQ(out.rgba.size(), count * 4);
  ASSERT_EQ(out.depth.size(), count);
  ASSERT_EQ(out.triangleId.size(), count);
  ASSERT_EQ(out.lineMask.size(), count);
  for (std::size_t i = 0; i < count; ++i) {
    ASSERT_TRUE(std::isfinite(out.depth[i])) << "pixel " << i;
    ASSERT_GE(out.depth[i], 0.0f);
    ASSERT_LE(out.depth[i], 1.0f);
    const bool drawn = out.triangleId[i] != kNoTriangle || out.lineMask[i] != 0;
    ASSERT_EQ(out.rgba[i * 4 + 3], drawn ? 255 : backgroundAlpha) << "pixel " << i;
    if (!drawn) {
      ASSERT_EQ(out.depth[i], 1.0f);
    }
  }
}

TEST(CpuRenderer, CubeBuffersAndStatistics) {
  const Scene scene = sceneWith(makeCube(1.0f));
  const RenderOutput out = render(scene, scene.settings);
  expectConsistentBuffers(out);
  EXPECT_EQ(out.stats.trianglesIn, 12u);
  EXPECT_EQ(out.stats.trianglesClipped, 0u);
  // Unclipped, every triangle reaches setup once: culled + produced = in.
  EXPECT_EQ(out.stats.trianglesCulled + out.stats.trianglesProduced, 12u);
  EXPECT_GE(out.stats.trianglesCulled, 6u);  // the back half at least
  EXPECT_GE(out.stats.pixelsShaded, coveredCount(out));
  EXPECT_GT(coveredCount(out), 100u);
}

TEST(CpuRenderer, BackgroundIsTheSceneColourAndAlpha) {
  for (const CpuPath path : {CpuPath::Fast, CpuPath::Teaching}) {
    SCOPED_TRACE(path == CpuPath::Fast ? "fast" : "teaching");
    CpuOptions options;
    options.path = path;
    Scene scene = sceneWith(makeCube(0.1f));
    scene.output.background = vec4(1.0f, 0.5f, 0.0f, 1.0f);  // opaque, as a file's [r, g, b]
    const RenderOutput opaque = makeCpuRenderer(options)->render(scene, scene.settings, 64, 48);
    EXPECT_EQ(opaque.triangleId[0], kNoTriangle);
    EXPECT_EQ(opaque.rgba[0], 255);
    EXPECT_EQ(opaque.rgba[1], 128);  // round(0.5 * 255) = 128 (127.5 rounds up)
    EXPECT_EQ(opaque.rgba[2], 0);
    EXPECT_EQ(opaque.rgba[3], 255);
    expectConsistentBuffers(opaque, 255);

    scene.output.background.a = 0.0f;
    const RenderOutput clear = makeCpuRenderer(options)->render(scene, scene.settings, 64, 48);
    EXPECT_EQ(clear.rgba[3], 0);
    expectConsistentBuffers(clear, 0);
    scene.output.background.a = 0.5f;
    const RenderOutput half = makeCpuRenderer(options)->render(scene, scene.settings, 64, 48);
    expectConsistentBuffers(half, 128);

    // Only the alpha of empty pixels moves: every RGB, depth and id stays.
    ASSERT_GT(coveredCount(opaque), 0u);
    for (std::size_t i = 0; i < opaque.depth.size(); ++i) {
      for (std::size_t c = 0; c < 3; ++c) ASSERT_EQ(opaque.rgba[i * 4 + c], clear.rgba[i * 4 + c]) << i;
      ASSERT_EQ(opaque.depth[i], clear.depth[i]) << i;
      ASSERT_EQ(opaque.triangleId[i], clear.triangleId[i]) << i;
    }
  }
}

TEST(CpuRenderer, OutputIsTopRowFirst) {
  // A triangle above the view axis only: it must land in the top rows of the output.
  Scene scene = sceneWith(makeTriangles({vec3(-1, 0.2f, 0), vec3(1, 0.2f, 0), vec3(0, 1, 0)}, {}, {}));
  scene.settings.cull = CullMode::None;
  const RenderOutput out = render(scene, scene.settings);
  std::size_t top = 0, bottom = 0;
  for (int y = 0; y < out.height; ++y) {
    for (int x = 0; x < out.width; ++x) {
      const bool covered = out.triangleId[static_cast<std::size_t>(y * out.width + x)] != kNoTriangle;
      (y < out.height / 2 ? top : bottom) += covered ? 1 : 0;
    }
  }
  EXPECT_GT(top, 0u);
  EXPECT_EQ(bottom, 0u);
}

TEST(CpuRenderer, FrontFaceAndCullSettings) {
  Scene scene = sceneWith(makeTriangles({vec3(-1, -1, 0), vec3(1, -1, 0), vec3(0, 1, 0)}, {}, {}));  // CCW towards the camera
  RenderSettings s = scene.settings;
  s.cull = CullMode::Back;
  EXPECT_GT(coveredCount(render(scene, s)), 0u);
  s.frontFace = FrontFace::Cw;
  EXPECT_EQ(coveredCount(render(scene, s)), 0u);
  s.cull = CullMode::Front;
  EXPECT_GT(coveredCount(render(scene, s)), 0u);
  s.cull = CullMode::None;
  EXPECT_EQ(render(scene, s).stats.trianglesCulled, 0u);
}

TEST(CpuRenderer, EveryViewOfEveryAssetSceneIsFinite) {
  const std::filesystem::path dir = std::filesystem::path(TWINRASTER_SOURCE_DIR) / "assets" / "scenes";
  ASSERT_TRUE(std::filesystem::exists(dir));
  int scenes = 0;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    if (entry.path().extension() != ".json") continue;
    SCOPED_TRACE(entry.path().string());
    const Scene scene = loadSceneFile(entry.path().string());
    ++scenes;
    // One renderer per scene, as the app keeps one while the view changes: its textures are
    // tiled once, not once per view (a fresh renderer per view made this test a minute long,
    // most of it spent allocating and tiling the same textures again).
    const auto renderer = makeCpuRenderer();
    for (View view : kAllViews) {
      for (LightingSpace space : {LightingSpace::World, LightingSpace::Tangent}) {
        RenderSettings s = scene.settings;
        s.view = view;
        s.lightingSpace = space;
        const RenderOutput out = renderer->render(scene, s, 40, 30);
        expectConsistentBuffers(out);
      }
    }
  }
  EXPECT_GT(scenes, 0);
}

TEST(CpuRenderer, TinyNearPlane) {
  Scene scene = sceneWith(makeSphere(1.0f, 8, 16));
  scene.camera.near = 1e-5f;
  scene.camera.far = 1e4f;
  const RenderOutput out = render(scene, scene.settings);
  expectConsistentBuffers(out);
  EXPECT_GT(coveredCount(out), 100u);
}

TEST(CpuRenderer, CameraInsideTheMeshWithNearAndFarOff) {
  Scene scene = sceneWith(makeCube(4.0f));
  scene.camera.position = vec3(0.3f, 0.2f, 0.5f);
  scene.settings.cull = CullMode::None;
  for (bool nearOn : {true, false}) {
    for (bool farOn : {true, false}) {
      RenderSettings s = scene.settings;
      s.clip.near = nearOn;
      s.clip.far = farOn;
      const RenderOutput out = render(scene, s);
      expectConsistentBuffers(out);
      EXPECT_EQ(coveredCount(out), static_cast<std::size_t>(64 * 48)) << "inside a closed cube every pixel sees a wall";
    }
  }
}

TEST(CpuRenderer, SidePlanesOffStillFillTheScreenOnce) {
  Scene scene = sceneWith(makePlane(vec2(1000.0f, 1000.0f), 1.0f));  // XZ plane, far larger than the view
  scene.camera.position = vec3(0, 3, 0.01f);
  RenderSettings s = scene.settings;
  s.clip.left = s.clip.right = s.clip.bottom = s.clip.top = false;
  const RenderOutput out = render(scene, s);
  expectConsistentBuffers(out);
  EXPECT_EQ(coveredCount(out), static_cast<std::size_t>(64 * 48));
}

// Affine interpolation moves what the floor of the default scene shows (its bricks and normal
// map swim towards the far edge) but not where it is: the same pixels covered by the same
// triangles at the same depths, since depth is z / w, linear on the screen either way.
TEST(CpuRenderer, AffineInterpolationMovesTheFloorsTextureNotItsCoverage) {
  const Scene scene = loadSceneFile(std::string(TWINRASTER_SOURCE_DIR) + "/assets/scenes/default.json");
  RenderSettings affine = scene.settings;
  affine.interpolation = Interpolation::Affine;
  const RenderOutput a = render(scene, scene.settings, 160, 100);
  const RenderOutput b = render(scene, affine, 160, 100);
  EXPECT_EQ(a.triangleId, b.triangleId);
  EXPECT_EQ(a.depth, b.depth);
  std::size_t covered = 0, moved = 0;
  constexpr int kVisibleLevels = 24;  // of 255: a change anyone sees side by side
  for (std::size_t i = 0; i < a.triangleId.size(); ++i) {
    if (a.triangleId[i] == kNoTriangle) continue;
    ++covered;
    int largest = 0;
    for (std::size_t c = 0; c < 3; ++c) largest = std::max(largest, std::abs(a.rgba[4 * i + c] - b.rgba[4 * i + c]));
    moved += largest > kVisibleLevels ? 1 : 0;
  }
  ASSERT_GT(covered, 0u);
  EXPECT_GT(static_cast<double>(moved) / static_cast<double>(covered), 0.05)
      << moved << " of " << covered << " covered pixels changed by more than " << kVisibleLevels << " levels";
}

TEST(CpuRenderer, LightAtTheSurface) {
  Scene scene = sceneWith(makePlane(vec2(2.0f, 2.0f), 1.0f));
  scene.camera.position = vec3(0, 2, 2);
  scene.lights[0].posWorld = vec3(0, 0, 0);  // on the plane
  scene.lights[0].attenuation = vec3(0, 1, 0);  // If = 1 / d, infinite at d = 0 without the guard
  const RenderOutput out = render(scene, scene.settings);
  expectConsistentBuffers(out);
  EXPECT_GT(coveredCount(out), 0u);
}

Material normalMapped() {
  auto map = std::make_shared<Texture>();
  map->width = 2;
  map->height = 2;
  map->rgba = {200, 128, 230, 255, 128, 200, 230, 255, 60, 128, 230, 255, 128, 60, 230, 255};
  Material m;
  m.normalMap = map;
  m.diffuseMap = map;
  m.ks = vec3(0.5f);
  return m;
}

TEST(CpuRenderer, DegenerateUvsRenderFinite) {
  const std::vector<vec3> pos{vec3(-1, -1, 0), vec3(1, -1, 0), vec3(0, 1, 0)};
  const std::vector<vec2> uv{vec2(0.5f), vec2(0.5f), vec2(0.5f)};
  Scene scene = sceneWith(makeTriangles(pos, uv, {}), normalMapped());
  for (View view : kAllViews) {
    RenderSettings s = scene.settings;
    s.view = view;
    const RenderOutput out = render(scene, s);
    expectConsistentBuffers(out);
    EXPECT_GT(coveredCount(out), 0u);
  }
}

TEST(CpuRenderer, MirroredUvsFlipTheTangentNotTheBitangent) {
  const std::vector<vec3> pos{vec3(-1, -1, 0), vec3(1, -1, 0), vec3(0, 1, 0)};
  const std::vector<vec2> plain{vec2(0, 0), vec2(1, 0), vec2(0.5f, 1)};
  const std::vector<vec2> mirrored{vec2(1, 0), vec2(0, 0), vec2(0.5f, 1)};  // u runs along -x
  auto centreColour = [&](const std::vector<vec2>& uv, View view) {
    Scene scene = sceneWith(makeTriangles(pos, uv, {}), normalMapped());
    RenderSettings s = scene.settings;
    s.view = view;
    const RenderOutput out = render(scene, s);
    expectConsistentBuffers(out);
    const std::size_t i = static_cast<std::size_t>((out.height / 2) * out.width + out.width / 2) * 4;
    return vec3(out.rgba[i], out.rgba[i + 1], out.rgba[i + 2]);
  };
  const vec3 t0 = centreColour(plain, View::Tangent), t1 = centreColour(mirrored, View::Tangent);
  EXPECT_GT(t0.r, 200.0f);  // T = +x shown as red 255
  EXPECT_LT(t1.r, 60.0f);   // T = -x shown as red 0
  EXPECT_EQ(centreColour(plain, View::Bitangent), centreColour(mirrored, View::Bitangent));
  centreColour(mirrored, View::Shaded);  // and shading stays finite
}

TEST(CpuRenderer, UserClipPlaneRemovesTheNegativeSide) {
  Scene scene = sceneWith(makeSphere(1.0f, 16, 32));
  RenderSettings s = scene.settings;
  const std::size_t whole = coveredCount(render(scene, s));
  s.userClipPlanes = {vec4(1, 0, 0, 0)};  // keep x >= 0: the right half of the image
  const RenderOutput half = render(scene, s);
  expectConsistentBuffers(half);
  EXPECT_LT(coveredCount(half), whole * 6 / 10);
  EXPECT_GT(coveredCount(half), whole * 4 / 10);
  for (int y = 0; y < half.height; ++y) {
    for (int x = 0; x < half.width / 2 - 1; ++x) {
      EXPECT_EQ(half.triangleId[static_cast<std::size_t>(y * half.width + x)], kNoTriangle);
    }
  }
}

TEST(CpuRenderer, TbnLinesMarkTheLineMaskInTheirColours) {
  Scene scene = sceneWith(makeCube(1.0f));
  scene.camera.position = vec3(2, 2, 3);
  RenderSettings s = scene.settings;
  s.tbnLines.enabled = true;
  s.tbnLines.length = 0.3f;
  const RenderOutput out = render(scene, s, 128, 96);
  expectConsistentBuffers(out);
  std::size_t lines = 0;
  for (std::size_t i = 0; i < out.lineMask.size(); ++i) {
    if (!out.lineMask[i]) continue;
    ++lines;
    const int r = out.rgba[i * 4], g = out.rgba[i * 4 + 1], b = out.rgba[i * 4 + 2];
    EXPECT_EQ(r + g + b, 255) << "pure red, green or blue";
  }
  EXPECT_GT(lines, 20u);
  s.tbnLines.enabled = false;
  const RenderOutput plain = render(scene, s, 128, 96);
  for (std::uint8_t m : plain.lineMask) ASSERT_EQ(m, 0);
}

TEST(CpuRenderer, ThreadCountDoesNotChangeTheImageOrTheStatistics) {
  Scene scene = sceneWith(makeSphere(1.0f, 12, 24), normalMapped());
  scene.camera.position = vec3(0.5f, 0.3f, 1.6f);  // close enough that triangles are clipped
  scene.settings.tbnLines.enabled = true;
  const RenderOutput one = makeCpuRenderer(CpuOptions{1})->render(scene, scene.settings, 61, 47);
  const RenderOutput three = makeCpuRenderer(CpuOptions{3})->render(scene, scene.settings, 61, 47);
  EXPECT_EQ(one.rgba, three.rgba);
  EXPECT_EQ(one.depth, three.depth);
  EXPECT_EQ(one.triangleId, three.triangleId);
  EXPECT_EQ(one.lineMask, three.lineMask);
  EXPECT_EQ(one.stats.trianglesIn, three.stats.trianglesIn);
  EXPECT_EQ(one.stats.trianglesClipped, three.stats.trianglesClipped);
  EXPECT_GT(one.stats.trianglesClipped, 0u);
  EXPECT_EQ(one.stats.trianglesCulled, three.stats.trianglesCulled);
  EXPECT_EQ(one.stats.trianglesProduced, three.stats.trianglesProduced);
  EXPECT_EQ(one.stats.pixelsShaded, three.stats.pixelsShaded);
  const RenderOutput many = makeCpuRenderer(CpuOptions{1000})->render(scene, scene.settings, 8, 5);  // more threads than rows
  EXPECT_EQ(many.rgba, makeCpuRenderer()->render(scene, scene.settings, 8, 5).rgba);
}

TEST(CpuRenderer, BadInputThrowsInputError) {
  const Scene scene = sceneWith(makeCube(1.0f));
  EXPECT_THROW(render(scene, scene.settings, 0, 10), InputError);
  EXPECT_THROW(render(scene, scene.settings, 10, kMaxImageSide + 1), InputError);
  Scene broken = scene;
  broken.meshes[0].indices[5] = 1000;
  EXPECT_THROW(render(broken, broken.settings), InputError);
}

TEST(PixelTrace, AgreesWithTheRenderedPixel) {
  Scene scene = sceneWith(makeSphere(1.0f, 12, 24));
  scene.meshes.push_back(makeCube(0.8f));
  Node behind;
  behind.name = "cube";
  behind.meshIndex = 1;
  behind.translate = vec3(0.3f, 0.2f, -1.0f);
  scene.nodes.push_back(behind);
  scene.settings.cull = CullMode::None;  // so the trace also sees back faces fail the depth test
  const RenderOutput out = render(scene, scene.settings);
  int traced = 0;
  for (int y = 4; y < out.height; y += 9) {
    for (int x = 3; x < out.width; x += 7) {
      const PixelTrace trace = tracePixel(scene, scene.settings, out.width, out.height, x, y);
      const std::size_t i = static_cast<std::size_t>(y * out.width + x);
      EXPECT_EQ(trace.triangleId, out.triangleId[i]);
      const TriangleVisit* last = nullptr;
      for (const TriangleVisit& v : trace.visits) {
        if (v.outcome == TraceOutcome::Shaded) last = &v;
      }
      if (out.triangleId[i] == kNoTriangle) {
        EXPECT_EQ(last, nullptr);
        continue;
      }
      ASSERT_NE(last, nullptr) << x << "," << y;
      ++traced;
      EXPECT_EQ(last->triangleId, out.triangleId[i]);
      EXPECT_EQ(last->weights.depth, out.depth[i]);
      for (int c = 0; c < 3; ++c) {
        EXPECT_EQ(std::lround(last->terms.colour[c] * 255.0f), out.rgba[i * 4 + static_cast<std::size_t>(c)]);
      }
      for (std::size_t e = 0; e < 3; ++e) EXPECT_GT(last->edgeValue[e], 0);
    }
  }
  EXPECT_GT(traced, 5);
}

// A marching method: the trace reads the height at the shifted uv, which the render skips
// where nothing uses it. The colour must not change, and the trace must show the march.
TEST(PixelTrace, ShowsTheSurfaceDetailOfAMarchAndAgreesWithTheRenderedPixel) {
  auto height = std::make_shared<Texture>();
  height->width = height->height = 16;
  height->rgba.resize(16 * 16 * 4, 255);
  for (int y = 0; y < 16; ++y) {
    for (int x = 0; x < 16; ++x) {
      const std::uint8_t h = ((x / 4 + y / 4) % 2 == 0) ? 255 : 40;  // raised squares in a checker
      for (int c = 0; c < 3; ++c) height->rgba[static_cast<std::size_t>((y * 16 + x) * 4 + c)] = h;
    }
  }
  buildMipChain(*height);
  Material m = normalMapped();
  m.heightMap = height;
  m.heightScale = 0.1f;
  Scene scene = sceneWith(makePlane(vec2(2.0f, 2.0f), 2.0f), m);
  scene.camera.position = vec3(0.3f, 1.5f, 1.6f);
  for (SurfaceDetail method : {SurfaceDetail::ParallaxOcclusion, SurfaceDetail::Relief}) {
    scene.materials[0].surfaceDetail = method;
    const RenderOutput out = render(scene, scene.settings);
    int shifted = 0, marched = 0, traced = 0;
    for (int y = 2; y < out.height; y += 5) {
      for (int x = 1; x < out.width; x += 5) {
        const std::size_t i = static_cast<std::size_t>(y * out.width + x);
        if (out.triangleId[i] == kNoTriangle) continue;
        const PixelTrace trace = tracePixel(scene, scene.settings, out.width, out.height, x, y);
        const TriangleVisit* last = nullptr;
        for (const TriangleVisit& v : trace.visits) {
          if (v.outcome == TraceOutcome::Shaded) last = &v;
        }
        ASSERT_NE(last, nullptr) << x << "," << y;
        ++traced;
        EXPECT_TRUE(last->heightMap);
        EXPECT_EQ(last->surfaceDetail, method);
        for (int c = 0; c < 3; ++c) {
          EXPECT_EQ(std::lround(last->terms.colour[c] * 255.0f), out.rgba[i * 4 + static_cast<std::size_t>(c)])
              << toString(method) << " at " << x << "," << y;
        }
        shifted += last->terms.uvShifted != last->fragment.uv ? 1 : 0;
        marched += last->terms.parallaxSteps > 0.0f ? 1 : 0;
        if (traced == 1) {
          EXPECT_NE(formatPixelTrace(trace).find("surface detail " + std::string(toString(method))), std::string::npos);
          const nlohmann::json j = pixelTraceToJson(trace);
          bool found = false;
          for (const auto& t : j["triangles"]) found = found || (t.contains("shading") && t["shading"].contains("surface_detail"));
          EXPECT_TRUE(found);
        }
      }
    }
    EXPECT_GT(traced, 20);
    EXPECT_GT(shifted, 0) << toString(method);
    EXPECT_GT(marched, 0) << toString(method);
  }
}

// A pixel of the sky box: no triangle, and the trace says where the sky looked (the face and
// s, t of GL's table for its direction) and at which LOD; its colour is the rendered one.
TEST(PixelTrace, ASkyPixelSaysWhereTheSkyLooked) {
  const Scene scene = loadSceneFile(std::string(TWINRASTER_SOURCE_DIR) + "/assets/scenes/env_sky_box.json");
  const PixelTrace tr = tracePixel(scene, scene.settings, 160, 120, 80, 30);
  EXPECT_EQ(tr.triangleId, kNoTriangle);
  ASSERT_TRUE(tr.sky);
  const CubeCoord expected = cubeCoordFromDirection(glm::dvec3(tr.skyDirection));
  EXPECT_EQ(tr.skyFace, expected.face);
  EXPECT_NEAR(tr.skyFaceCoord.x, expected.s, 1e-5);
  EXPECT_NEAR(tr.skyFaceCoord.y, expected.t, 1e-5);
  EXPECT_TRUE(std::isfinite(tr.skyLod));
  // At 160x120 a 100-degree view spreads about 2.4 256-texel faces over 160 pixels: minified.
  EXPECT_GT(tr.skyLod, 0.0f);
  EXPECT_NE(formatPixelTrace(tr).find("sky box: direction (world)"), std::string::npos);
  // A debug view draws no sky, and the trace says none.
  RenderSettings normals = scene.settings;
  normals.view = View::Normal;
  EXPECT_FALSE(tracePixel(scene, normals, 160, 120, 80, 30).sky);
}

// Under a sphere or paraboloid map the trace names the layer and its u, v (the formulas of
// scene/environment.h) and the 2D LOD.
TEST(PixelTrace, ASkyPixelUnderABuiltMapSaysWhichLayerAndWhere) {
  for (const char* file : {"env_sphere_map.json", "env_dual_paraboloid.json"}) {
    const Scene scene = loadSceneFile(std::string(TWINRASTER_SOURCE_DIR) + "/assets/scenes/" + file);
    const PixelTrace tr = tracePixel(scene, scene.settings, 160, 120, 80, 4);
    ASSERT_TRUE(tr.sky) << file;
    EXPECT_EQ(tr.skyParameterization, scene.environment->parameterization) << file;
    const MapCoord expected = mapCoordFromDirection(scene.environment->parameterization, glm::dvec3(tr.skyDirection));
    EXPECT_EQ(tr.skyFace, expected.layer) << file;
    EXPECT_NEAR(tr.skyFaceCoord.x, expected.u, 1e-5) << file;
    EXPECT_NEAR(tr.skyFaceCoord.y, expected.v, 1e-5) << file;
    EXPECT_TRUE(std::isfinite(tr.skyLod)) << file;
    EXPECT_NE(formatPixelTrace(tr).find("at u, v"), std::string::npos) << file;
  }
}

// A surface lit by the environment alone: the trace names the diffuse light it read, whose
// kd * albedo times it is the pixel (no lamps, no ambient, no reflection), and the rendered
// pixel is the trace's colour.
TEST(PixelTrace, ShowsTheEnvironmentsDiffuseLight) {
  const Scene scene = loadSceneFile(std::string(TWINRASTER_SOURCE_DIR) + "/assets/scenes/env_diffuse_light.json");
  const int w = 160, h = 120;
  const RenderOutput out = render(scene, scene.settings, w, h);
  for (const int x : {40, 120}) {  // the irradiance-map sphere, then the SH9 one
    const PixelTrace tr = tracePixel(scene, scene.settings, w, h, x, 60);
    const TriangleVisit* shaded = nullptr;
    for (const TriangleVisit& v : tr.visits) {
      if (v.outcome == TraceOutcome::Shaded) shaded = &v;
    }
    ASSERT_NE(shaded, nullptr) << x;
    EXPECT_EQ(shaded->environmentDiffuse, x < 80 ? EnvironmentDiffuse::IrradianceMap : EnvironmentDiffuse::Sh9);
    EXPECT_TRUE(shaded->terms.environmentDiffuseOn);
    EXPECT_FALSE(shaded->terms.environmentOn);  // no reflection read
    const vec3 expected = vec3(0.9f) * shaded->terms.albedo * shaded->terms.environmentDiffuse;
    for (int c = 0; c < 3; ++c) {
      EXPECT_NEAR(shaded->terms.colour[c], expected[c], 1e-6f) << x;
      EXPECT_GT(shaded->terms.environmentDiffuse[c], 0.05f) << x;
      EXPECT_EQ(std::lround(shaded->terms.colour[c] * 255.0f), out.rgba[static_cast<std::size_t>(60 * w + x) * 4 + static_cast<std::size_t>(c)]);
    }
    EXPECT_NE(formatPixelTrace(tr).find("environment diffuse light"), std::string::npos);
  }
}

TEST(PixelTrace, ReportsCullingDepthFailuresAndClipping) {
  Scene scene = sceneWith(makeSphere(1.0f, 12, 24));
  scene.settings.userClipPlanes = {vec4(0, -1, 0, 0.2f)};  // keep y <= 0.2
  const int w = 64, h = 48;
  // The centre pixel: the sphere's front is shaded, its back is culled.
  const PixelTrace centre = tracePixel(scene, scene.settings, w, h, w / 2, h / 2);
  bool shaded = false, culled = false;
  for (const TriangleVisit& v : centre.visits) {
    shaded = shaded || v.outcome == TraceOutcome::Shaded;
    culled = culled || v.outcome == TraceOutcome::CulledBack;
  }
  EXPECT_TRUE(shaded);
  EXPECT_TRUE(culled);
  // A pixel in the clipped-off cap: the front triangle is reported as clipped away.
  const PixelTrace cap = tracePixel(scene, scene.settings, w, h, w / 2, h / 2 - 9);  // world y ~ 0.6
  bool clipped = false;
  for (const TriangleVisit& v : cap.visits) clipped = clipped || v.outcome == TraceOutcome::ClippedAway;
  EXPECT_TRUE(clipped);
  const nlohmann::json j = pixelTraceToJson(centre);
  EXPECT_EQ(j["x"], w / 2);
  EXPECT_FALSE(j["triangles"].empty());
  EXPECT_TRUE(j["triangles"][0].contains("outcome"));
  EXPECT_NE(formatPixelTrace(centre).find("edge functions"), std::string::npos);
  EXPECT_THROW(tracePixel(scene, scene.settings, w, h, w, 0), InputError);
}

}  // namespace
}  // namespace twr
