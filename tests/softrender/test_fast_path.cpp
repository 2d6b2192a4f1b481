// The fast path (softrender/fast_pipeline.h, the shared shading source instantiated for each
// Highway target) draws exactly what the teaching path draws: colour, depth, triangle ids,
// line mask and statistics, bit for bit, on every scene of the suite with every view and cull
// mode, at awkward sizes, for any thread count, and on synthetic scenes that push the kernels'
// special cases (texture coordinates beyond their integer range, textures whose sides are not
// powers of two, nearest filtering, every shininess, lights inside the surface, triangles
// crossing w = 0). Every test runs once per Highway target this CPU supports (Highway's
// per-target test mechanism: hwy::TestWithParamTarget makes that target the one dynamic
// dispatch picks), and checks that the target it asked for is the one that drew.
#include "softrender/clip.h"
#include "softrender/cpu_renderer.h"
#include "softrender/cpu_isa_targets.h"
#include "softrender/fast_kernels.h"
#include "softrender/phong_pow.h"
#include "softrender/shade.h"
#include "softrender/vertex.h"

#include "scene/errors.h"
#include "scene/primitives.h"
#include "scene/scene_file.h"
#include "tests/sanitizers.h"

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>
#include <hwy/targets.h>
#include <hwy/tests/hwy_gtest.h>

#include <algorithm>
#include <cstdlib>
#include <bit>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <initializer_list>
#include <sstream>
#include <set>
#include <fstream>
#include <limits>
#include <memory>
#include <random>
#include <ostream>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

namespace twr {
namespace {

const std::string kScenes = std::string(TWINRASTER_SOURCE_DIR) + "/assets/scenes";

CpuOptions teaching() { return CpuOptions{1, CpuPath::Teaching, CpuIsa::Auto}; }
// The fast path on the target the test is running for (dynamic dispatch, mocked per test).
CpuOptions fastSimd(int threads) { return CpuOptions{threads, CpuPath::Fast, CpuIsa::Auto}; }

// The target a per-target test asked for must be the one that draws: fail, never skip.
void expectTargetInUse(std::int64_t target) {
  const FastKernels kernels = fastKernelsFor(CpuIsa::Auto);
  EXPECT_EQ(highwayTargetOf(kernels.isa), target)
      << "asked for " << hwy::TargetName(target) << ", the kernels of " << toString(kernels.isa) << " ran";
}

// Float buffers compare bitwise, so -0 against +0 or two different NaNs would show.
bool sameBits(const std::vector<float>& a, const std::vector<float>& b) {
  return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(float)) == 0);
}

// The first differing pixel, for a readable failure.
std::string firstDifference(const RenderOutput& a, const RenderOutput& b) {
  for (std::size_t i = 0; i < a.triangleId.size() && i < b.triangleId.size(); ++i) {
    const bool same = std::memcmp(&a.rgba[4 * i], &b.rgba[4 * i], 4) == 0 &&
                      std::bit_cast<std::uint32_t>(a.depth[i]) == std::bit_cast<std::uint32_t>(b.depth[i]) &&
                      a.triangleId[i] == b.triangleId[i] && a.lineMask[i] == b.lineMask[i];
    if (same) continue;
    const int x = static_cast<int>(i % static_cast<std::size_t>(a.width));
    const int row = static_cast<int>(i / static_cast<std::size_t>(a.width));
    return "pixel (" + std::to_string(x) + ", row " + std::to_string(row) + "): rgba " +
           std::to_string(a.rgba[4 * i]) + "," + std::to_string(a.rgba[4 * i + 1]) + "," +
           std::to_string(a.rgba[4 * i + 2]) + "," + std::to_string(a.rgba[4 * i + 3]) + " vs " +
           std::to_string(b.rgba[4 * i]) + "," + std::to_string(b.rgba[4 * i + 1]) + "," +
           std::to_string(b.rgba[4 * i + 2]) + "," + std::to_string(b.rgba[4 * i + 3]) + ", depth " +
           std::to_string(a.depth[i]) + " vs " + std::to_string(b.depth[i]) + ", id " +
           std::to_string(a.triangleId[i]) + " vs " + std::to_string(b.triangleId[i]);
  }
  return "sizes differ";
}

void expectIdentical(const RenderOutput& expected, const RenderOutput& actual, const std::string& what) {
  ASSERT_EQ(expected.width, actual.width) << what;
  ASSERT_EQ(expected.height, actual.height) << what;
  const bool same = expected.rgba == actual.rgba && sameBits(expected.depth, actual.depth) &&
                    expected.triangleId == actual.triangleId && expected.lineMask == actual.lineMask;
  EXPECT_TRUE(same) << what << ": " << firstDifference(expected, actual);
  const RenderStats& e = expected.stats;
  const RenderStats& a = actual.stats;
  EXPECT_EQ(e.trianglesIn, a.trianglesIn) << what;
  EXPECT_EQ(e.trianglesClipped, a.trianglesClipped) << what;
  EXPECT_EQ(e.trianglesCulled, a.trianglesCulled) << what;
  EXPECT_EQ(e.trianglesProduced, a.trianglesProduced) << what;
  EXPECT_EQ(e.pixelsShaded, a.pixelsShaded) << what;
}

// Teaching versus fast on the current target (one, two and three threads), at `width` x
// `height`.
void expectPathsAgree(const Scene& scene, const RenderSettings& settings, int width, int height,
                      const std::string& what) {
  const RenderOutput reference = makeCpuRenderer(teaching())->render(scene, settings, width, height);
  ASSERT_GT(reference.stats.trianglesIn, 0u) << what;
  expectIdentical(reference, makeCpuRenderer(fastSimd(1))->render(scene, settings, width, height),
                  what + ", simd 1 thread");
  expectIdentical(reference, makeCpuRenderer(fastSimd(2))->render(scene, settings, width, height), what + ", simd");
  expectIdentical(reference, makeCpuRenderer(fastSimd(3))->render(scene, settings, width, height),
                  what + ", 3 threads");
  // Into an earlier output of the frame's size whose every buffer holds garbage (renderInto
  // keeps buffers of the right size and writes them over): no pixel may keep a stale value.
  RenderOutput used;
  used.rgba.assign(reference.rgba.size(), 0xA5);
  used.depth.assign(reference.depth.size(), 0.25f);
  used.triangleId.assign(reference.triangleId.size(), 7u);
  used.lineMask.assign(reference.lineMask.size(), 1);
  used.stats.pixelsShaded = 12345;
  makeCpuRenderer(fastSimd(2))->renderInto(scene, settings, width, height, used);
  expectIdentical(reference, used, what + ", into a used output");
}

std::vector<std::string> suiteScenes() {
  std::vector<std::string> names;
  for (const auto& entry : std::filesystem::directory_iterator(kScenes)) {
    if (entry.path().extension() == ".json") names.push_back(entry.path().filename().string());
  }
  std::sort(names.begin(), names.end());
  return names;
}

// A suite scene's file name; printed as its stem, which names the test (AVX2_default).
struct SceneFile {
  std::string file;
};
void PrintTo(const SceneFile& scene, std::ostream* out) { *out << scene.file.substr(0, scene.file.find('.')); }
std::vector<SceneFile> suiteSceneFiles() {
  std::vector<SceneFile> files;
  for (const std::string& name : suiteScenes()) files.push_back({name});
  return files;
}

class FastPathSuite : public hwy::TestWithParamTargetAndT<SceneFile> {};
HWY_TARGET_INSTANTIATE_TEST_SUITE_P_T(FastPathSuite, ::testing::ValuesIn(suiteSceneFiles()));

TEST_P(FastPathSuite, SameImageAsTheTeachingPath) {
  expectTargetInUse(std::get<0>(::testing::TestWithParam<std::tuple<std::int64_t, SceneFile>>::GetParam()));
  const std::string file = GetParam().file;
  const Scene scene = loadSceneFile(kScenes + "/" + file);
  // Under the sanitizers at a quarter of the scene's side: the same code paths (every feature,
  // several bins and tiles, 1 to 3 threads) for a sixteenth of the pixels; at full size it was
  // 370 s of their run here, at half size 216 s, at a quarter 140 s; the other builds check
  // the full size.
  constexpr int kSizeDivisor = kUnderSanitizers ? 4 : 1;
  const int width = scene.output.width / kSizeDivisor, height = scene.output.height / kSizeDivisor;
  expectPathsAgree(scene, scene.settings, width, height, file);
  // Sizes that are not multiples of any vector width or of the 32-row bin.
  expectPathsAgree(scene, scene.settings, 61, 47, file + " at 61x47");
}

// The per-target fixture for the tests below.
HWY_BEFORE_TEST(FastPath);

// Shadow maps with no bias at all, where a tap is decided in a depth's last bit: each kind of
// map (the orthographic one at each kernel), the same maps (float depth, docs/shadows.md) and frames on both paths.
TEST_P(FastPath, ShadowMapsAtZeroBias) {
  expectTargetInUse(GetParam());
  for (const char* file : {"shadow_directional.json", "shadow_point_cube.json", "shadow_spot.json"}) {
    const bool directional = std::string(file) == "shadow_directional.json";
    for (const int pcf : {1, 3, 5}) {
      if (!directional && pcf != 3) continue;  // the kernel's loop is the same code for every map
      Scene scene = loadSceneFile(kScenes + "/" + file);
      for (Light& light : scene.lights) {
        if (!light.shadow) continue;
        light.shadow->bias = vec2(0.0f);
        light.shadow->pcf = pcf;
      }
      const std::string what = std::string(file) + " bias 0 pcf " + std::to_string(pcf);
      expectPathsAgree(scene, scene.settings, 160, 120, what);
      const RenderOutput teachingOut = makeCpuRenderer(teaching())->render(scene, scene.settings, 160, 120);
      const RenderOutput fastOut = makeCpuRenderer(fastSimd(2))->render(scene, scene.settings, 160, 120);
      ASSERT_EQ(teachingOut.shadowMaps.size(), fastOut.shadowMaps.size()) << what;
      int compared = 0;
      for (std::size_t i = 0; i < teachingOut.shadowMaps.size(); ++i) {
        if (!teachingOut.shadowMaps[i]) continue;
        ASSERT_TRUE(fastOut.shadowMaps[i]) << what;
        const std::vector<float>& depth = fastOut.shadowMaps[i]->depth;
        EXPECT_TRUE(sameBits(teachingOut.shadowMaps[i]->depth, depth)) << what << ", light " << i;
        ++compared;
        if (!directional) continue;
        // Float depth, as GL's GL_DEPTH_COMPONENT32F maps: below 0.5 most depths are no multiple
        // of a 24-bit unorm step (2^24 - 1 steps over [0, 1]).
        constexpr double kUnormSteps = 16777215.0;
        const auto offStep = std::count_if(depth.begin(), depth.end(), [&](float d) {
          return d < 0.5f && static_cast<float>(std::nearbyint(double(d) * kUnormSteps) / kUnormSteps) != d;
        });
        EXPECT_GT(offStep, 0) << what << ": the map holds 24-bit depths";
      }
      EXPECT_GT(compared, 0) << what << ": no map drawn, nothing compared";
    }
  }
}

// One filter per sampling path: level 0 picked or blended, one mip level by rint(lod), two
// levels blended (the other two mipmapped filters combine the same paths). Every filter
// against llvmpipe: tests/compare.
constexpr TextureFilter kFilterPaths[] = {TextureFilter::Nearest, TextureFilter::Bilinear, TextureFilter::Trilinear,
                                          TextureFilter::NearestMipmapNearest};

TEST_P(FastPath, EveryViewBothLightingSpacesAndFilters) {
  expectTargetInUse(GetParam());
  for (const char* file : {"default.json", "tangent_space.json"}) {
    const Scene scene = loadSceneFile(kScenes + "/" + file);
    for (View view : kAllViews) {
      RenderSettings settings = scene.settings;
      settings.view = view;
      expectPathsAgree(scene, settings, 160, 120, std::string(file) + " view " + std::string(toString(view)));
    }
    for (LightingSpace space : {LightingSpace::World, LightingSpace::Tangent}) {
      for (TextureFilter filter : kFilterPaths) {
        RenderSettings settings = scene.settings;
        settings.lightingSpace = space;
        settings.textureFilter = filter;
        expectPathsAgree(scene, settings, 200, 150,
                         std::string(file) + " " + std::string(toString(space)) + " " + std::string(toString(filter)));
      }
    }
  }
}

// llvmpipe's elliptical filter (anisotropy > 1): its per-lane loops over each lane's own
// bounding box and its per-lane levels, on a mipmapped filter and on level 0.
TEST_P(FastPath, AnisotropicFilter) {
  expectTargetInUse(GetParam());
  const Scene scene = loadSceneFile(kScenes + "/default.json");
  // Small: the teaching path reads every texel of every ellipse one pixel at a time, and on
  // level 0 the floor's far ellipses hold hundreds of texels (under qemu in CI, every second
  // counts). 64 x 48 still puts lanes of different levels and box sizes in one vector.
  // Under the sanitizers (-O0, every vector operation a call) only the mipmapped view: the
  // level-0 view reads every texel the far floor covers whatever the image size (halving the
  // size quadruples each ellipse), 7 to 8 minutes per target here; its loop is the same code,
  // checked at full speed by the other builds.
  std::vector<std::pair<TextureFilter, int>> views{{TextureFilter::Trilinear, 64}};
  if (!kUnderSanitizers) views.push_back({TextureFilter::Nearest, 24});
  for (const auto& [filter, width] : views) {
    RenderSettings settings = scene.settings;
    settings.textureFilter = filter;
    settings.anisotropy = 16.0f;
    expectPathsAgree(scene, settings, width, width * 3 / 4,
                     std::string("anisotropy 16 ") + std::string(toString(filter)));
  }
}

// Affine interpolation on both paths: the planes are set up with every corner's 1/w as 1, so
// the same kernels divide by 1; forward and deferred, both lighting spaces, a mipmapped filter
// (the quad's uv differences come from the affine planes too).
TEST_P(FastPath, AffineInterpolation) {
  expectTargetInUse(GetParam());
  for (const char* file : {"default.json", "tangent_space.json", "inside_near.json", "obj_model.json"}) {
    const Scene scene = loadSceneFile(kScenes + "/" + file);
    for (const Pipeline pipeline : {Pipeline::Forward, Pipeline::Deferred}) {
      RenderSettings settings = scene.settings;
      settings.interpolation = Interpolation::Affine;
      settings.pipeline = pipeline;
      settings.textureFilter = TextureFilter::Trilinear;
      expectPathsAgree(scene, settings, 160, 120, std::string(file) + " affine " + std::string(toString(pipeline)));
    }
  }
}

TEST_P(FastPath, EveryCullModeAndFrontFace) {
  expectTargetInUse(GetParam());
  const Scene scene = loadSceneFile(kScenes + "/culling.json");
  for (CullMode cull : {CullMode::None, CullMode::Back, CullMode::Front}) {
    for (FrontFace front : {FrontFace::Ccw, FrontFace::Cw}) {
      RenderSettings settings = scene.settings;
      settings.cull = cull;
      settings.frontFace = front;
      expectPathsAgree(scene, settings, 240, 180,
                       std::string("culling ") + std::string(toString(cull)) + " " + std::string(toString(front)));
    }
  }
}

TEST_P(FastPath, ThreadCountDoesNotChangeAnything) {
  expectTargetInUse(GetParam());
  const Scene scene = loadSceneFile(kScenes + "/default.json");
  const RenderOutput one = makeCpuRenderer(fastSimd(1))->render(scene, scene.settings, 320, 200);
  for (int threads : {2, 5, 64}) {
    expectIdentical(one, makeCpuRenderer(fastSimd(threads))->render(scene, scene.settings, 320, 200),
                    std::to_string(threads) + " threads");
  }
  // A renderer reused for several frames and sizes keeps giving the same answer.
  const auto renderer = makeCpuRenderer(fastSimd(2));
  renderer->render(scene, scene.settings, 97, 31);
  expectIdentical(one, renderer->render(scene, scene.settings, 320, 200), "second frame of a reused renderer");
  // Frames drawn into the last one's output, at sizes that grow and shrink its buffers.
  RenderOutput out;
  for (const auto& [width, height] : {std::pair{97, 31}, std::pair{320, 200}, std::pair{640, 400}, std::pair{320, 200}}) {
    renderer->renderInto(scene, scene.settings, width, height, out);
    ASSERT_EQ(out.width, width);
    ASSERT_EQ(out.rgba.size(), static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 4);
  }
  expectIdentical(one, out, "into the output of larger and smaller frames");
  // A frame that throws leaves the output empty, not holding half of the last one.
  EXPECT_THROW(renderer->renderInto(scene, scene.settings, 0, 200, out), InputError);
  EXPECT_EQ(out.width, 0);
  EXPECT_TRUE(out.rgba.empty() && out.depth.empty() && out.triangleId.empty() && out.lineMask.empty());
}

// A material with every map, on textures of odd sizes (the kernel's non-power-of-two wrap).
std::shared_ptr<Texture> noiseTexture(int width, int height, std::uint32_t seed) {
  auto texture = std::make_shared<Texture>();
  texture->path = "noise " + std::to_string(width) + "x" + std::to_string(height);
  texture->width = width;
  texture->height = height;
  std::mt19937 rng(seed);
  std::uniform_int_distribution<int> byte(0, 255);
  texture->rgba.resize(static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 4);
  for (std::uint8_t& c : texture->rgba) c = static_cast<std::uint8_t>(byte(rng));
  buildMipChain(*texture);  // odd sides all the way down: the mipmapped filters read every level
  return texture;
}

// A floor quad in XZ (facing +Y) with texture coordinates from uvMin to uvMax.
Mesh floorQuad(vec2 uvMin, vec2 uvMax) {
  const vec3 p00(-2.0f, 0.0f, 2.0f), p10(2.0f, 0.0f, 2.0f), p11(2.0f, 0.0f, -2.0f), p01(-2.0f, 0.0f, -2.0f);
  const vec2 t00 = uvMin, t10(uvMax.x, uvMin.y), t11 = uvMax, t01(uvMin.x, uvMax.y);
  return makeTriangles({p00, p10, p11, p00, p11, p01}, {t00, t10, t11, t00, t11, t01}, {});
}

Scene syntheticScene(vec2 uvMin, vec2 uvMax, int textureWidth, int textureHeight, float shininess) {
  Scene scene;
  scene.camera.position = vec3(0.3f, 1.2f, 3.0f);
  scene.camera.target = vec3(0.0f, 0.0f, 0.0f);
  scene.camera.near = 0.05f;
  scene.ambient = vec3(0.1f);
  scene.lights.push_back(Light{vec3(1.0f, 2.0f, 2.0f), vec3(1.0f), vec3(1.0f), vec3(1.0f, 0.09f, 0.032f),
                               LightType::Point, vec3(0.0f, -1.0f, 0.0f), std::nullopt, std::nullopt});
  // A light inside the sphere's surface and one exactly at a vertex of the plane.
  scene.lights.push_back(Light{vec3(0.0f, 0.2f, 0.0f), vec3(0.5f), vec3(0.8f), vec3(0.0f, 0.0f, 0.0f),
                               LightType::Point, vec3(0.0f, -1.0f, 0.0f), std::nullopt, std::nullopt});
  scene.lights.push_back(Light{vec3(2.0f, -0.5f, 2.0f), vec3(0.3f), vec3(0.4f), vec3(1.0f, 0.0f, 1.0f),
                               LightType::Point, vec3(0.0f, -1.0f, 0.0f), std::nullopt, std::nullopt});
  Material material;
  material.ks = vec3(0.7f);
  material.shininess = shininess;
  material.diffuseMap = noiseTexture(textureWidth, textureHeight, 1);
  material.normalMap = noiseTexture(textureWidth, textureHeight, 2);
  material.specularMap = noiseTexture(textureHeight, textureWidth, 3);  // a different size
  scene.materials.push_back(material);
  scene.meshes.push_back(makeSphere(0.7f, 12, 24));
  scene.meshes.push_back(floorQuad(uvMin, uvMax));
  scene.meshDescs.resize(2);
  Node sphere;
  sphere.name = "sphere";
  sphere.meshIndex = 0;
  sphere.materialIndex = 0;
  sphere.translate = vec3(0.0f, 0.2f, 0.0f);
  Node plane;
  plane.name = "plane";
  plane.meshIndex = 1;
  plane.materialIndex = 0;
  plane.translate = vec3(0.0f, -0.5f, 0.0f);
  scene.nodes = {sphere, plane};
  return scene;
}

TEST_P(FastPath, SyntheticMaterialsTexturesAndExponents) {
  expectTargetInUse(GetParam());
  for (float shininess : {0.0f, 0.5f, 1.0f, 7.3f, 32.0f, 1000.0f}) {
    const Scene scene = syntheticScene(vec2(-1.3f, -0.2f), vec2(2.0f, 3.1f), 37, 20, shininess);
    for (TextureFilter filter : kFilterPaths) {
      for (LightingSpace space : {LightingSpace::World, LightingSpace::Tangent}) {
        RenderSettings settings = scene.settings;
        settings.textureFilter = filter;
        settings.lightingSpace = space;
        settings.cull = CullMode::None;
        expectPathsAgree(scene, settings, 123, 77,
                         "shininess " + std::to_string(shininess) + " " + std::string(toString(filter)) + " " +
                             std::string(toString(space)));
      }
    }
  }
}

// The texture options the sampler branches on: each wrap mode, sRGB decoding, and the
// normal-map conventions (green down, two channels, strength), under the filters that read
// one level, two levels and the quad's LOD.
TEST_P(FastPath, WrapModesSrgbAndNormalMapConventions) {
  expectTargetInUse(GetParam());
  for (TextureWrap wrap : {TextureWrap::Repeat, TextureWrap::MirroredRepeat, TextureWrap::ClampToEdge}) {
    for (bool srgb : {false, true}) {
      Scene scene = syntheticScene(vec2(-2.3f, -1.2f), vec2(3.0f, 2.1f), 37, 20, 12.0f);
      Material& m = scene.materials[0];
      auto diffuse = std::make_shared<Texture>(*m.diffuseMap);
      diffuse->options.wrap = wrap;
      diffuse->options.srgb = srgb;
      auto normal = std::make_shared<Texture>(*m.normalMap);
      normal->options.wrap = wrap;
      normal->options.green = srgb ? GreenAxis::Down : GreenAxis::Up;
      normal->channels = srgb ? TextureChannels::RedGreen : TextureChannels::Rgba;
      m.diffuseMap = diffuse;
      m.normalMap = normal;
      m.normalStrength = srgb ? 0.4f : 1.0f;
      for (TextureFilter filter : {TextureFilter::Nearest, TextureFilter::Bilinear, TextureFilter::Trilinear,
                                   TextureFilter::NearestMipmapNearest}) {
        RenderSettings settings = scene.settings;
        settings.textureFilter = filter;
        settings.cull = CullMode::None;
        expectPathsAgree(scene, settings, 97, 61,
                         std::string(toString(wrap)) + (srgb ? " srgb, green down, xy, strength 0.4" : "") + " " +
                             std::string(toString(filter)));
      }
    }
  }
}

// Height maps as the fast path reads them (one gather per level from the red footprint words,
// the mip levels found once per fragment) against the teaching path's four texel reads per
// level: every wrap mode (clamped and mirrored reads stay on an edge texel, which the words
// must give back), sRGB, odd sizes down to one texel wide or high, each filter, each kind of
// height read (bump, the marches, the march towards the light).
TEST_P(FastPath, HeightMapsUnderEveryWrapModeSizeAndFilter) {
  expectTargetInUse(GetParam());
  for (TextureWrap wrap : {TextureWrap::Repeat, TextureWrap::MirroredRepeat, TextureWrap::ClampToEdge}) {
    for (const ivec2 size : {ivec2(37, 20), ivec2(1, 9), ivec2(16, 1)}) {
      Scene scene = syntheticScene(vec2(-2.3f, -1.2f), vec2(3.0f, 2.1f), 37, 20, 12.0f);
      auto height = noiseTexture(size.x, size.y, 4);
      height->options.wrap = wrap;
      height->options.srgb = wrap == TextureWrap::MirroredRepeat;
      Material& m = scene.materials[0];
      m.heightMap = height;
      m.heightScale = 0.08f;
      m.parallaxLayers = ivec2(4, 12);
      for (SurfaceDetail method : {SurfaceDetail::BumpBlinn, SurfaceDetail::SteepParallax, SurfaceDetail::Relief,
                                   SurfaceDetail::ParallaxOcclusion}) {
        m.surfaceDetail = method;
        m.selfShadow = method == SurfaceDetail::SteepParallax ? SelfShadow::HeightMarch : SelfShadow::None;
        for (TextureFilter filter : {TextureFilter::Nearest, TextureFilter::Bilinear, TextureFilter::Trilinear,
                                     TextureFilter::NearestMipmapLinear}) {
          RenderSettings settings = scene.settings;
          settings.textureFilter = filter;
          settings.cull = CullMode::None;
          expectPathsAgree(scene, settings, 97, 61,
                           std::string(toString(wrap)) + " " + std::to_string(size.x) + "x" + std::to_string(size.y) +
                               " " + std::string(toString(method)) + " " + std::string(toString(filter)));
        }
      }
    }
  }
}

// A renderer keeps its tiled copies across frames, keyed by the Texture object. Options changed
// in place on that object between frames (GlUploadCache allows it too) must be followed, as
// a new renderer would draw them: the tiled texels do not depend on them, the sampler does.
TEST(FastPathCache, TextureOptionsChangedInPlaceAreFollowed) {
  Scene scene = syntheticScene(vec2(-2.3f, -1.2f), vec2(3.0f, 2.1f), 37, 20, 12.0f);
  const std::shared_ptr<Texture> diffuse = noiseTexture(37, 20, 1);
  scene.materials[0].diffuseMap = diffuse;
  RenderSettings settings = scene.settings;
  settings.cull = CullMode::None;
  const std::unique_ptr<Renderer> kept = makeCpuRenderer(fastSimd(2));
  const RenderOutput first = kept->render(scene, settings, 97, 61);
  diffuse->options.wrap = TextureWrap::MirroredRepeat;
  diffuse->options.srgb = true;
  const RenderOutput second = kept->render(scene, settings, 97, 61);
  EXPECT_NE(first.rgba, second.rgba) << "the options change the picture";
  expectIdentical(makeCpuRenderer(fastSimd(2))->render(scene, settings, 97, 61), second, "options changed in place");
}

// A texture the renderer already keeps as a diffuse map, then also read as a height map (its
// red footprint words are made then), and a clamped height map turned to repeat in place: each
// frame as a new renderer draws it.
TEST(FastPathCache, ATextureLaterReadAsAHeightMapIsFollowed) {
  Scene scene = syntheticScene(vec2(-2.3f, -1.2f), vec2(3.0f, 2.1f), 37, 20, 12.0f);
  const std::shared_ptr<Texture> shared = noiseTexture(37, 20, 1);
  shared->options.wrap = TextureWrap::ClampToEdge;
  scene.materials[0].diffuseMap = shared;
  RenderSettings settings = scene.settings;
  settings.cull = CullMode::None;
  const std::unique_ptr<Renderer> kept = makeCpuRenderer(fastSimd(2));
  const RenderOutput first = kept->render(scene, settings, 97, 61);
  scene.materials[0].heightMap = shared;
  scene.materials[0].surfaceDetail = SurfaceDetail::ParallaxOcclusion;
  const RenderOutput second = kept->render(scene, settings, 97, 61);
  EXPECT_NE(first.rgba, second.rgba) << "the march changes the picture";
  expectIdentical(makeCpuRenderer(fastSimd(2))->render(scene, settings, 97, 61), second, "then read as a height map");
  shared->options.wrap = TextureWrap::Repeat;
  const RenderOutput third = kept->render(scene, settings, 97, 61);
  expectIdentical(makeCpuRenderer(fastSimd(2))->render(scene, settings, 97, 61), third, "then turned to repeat");
}

// A texture that sits out a frame (two scenes drawn in turn, as the report times them) keeps
// its tiled copy, and the frame after draws as a new renderer would; a texture no frame uses
// any more is released after a few frames (FastPipeline::kUnusedFramesKept, 4), not kept for
// the renderer's life.
TEST(FastPathCache, ATextureThatSitsOutFramesIsKeptAWhileThenReleased) {
  Scene with = syntheticScene(vec2(-2.3f, -1.2f), vec2(3.0f, 2.1f), 37, 20, 12.0f);
  Scene without = with;
  std::shared_ptr<Texture> height = noiseTexture(37, 20, 3);
  const std::weak_ptr<Texture> watch = height;
  with.materials[0].heightMap = height;
  with.materials[0].surfaceDetail = SurfaceDetail::ParallaxOcclusion;
  height.reset();
  RenderSettings settings = with.settings;
  settings.cull = CullMode::None;
  const std::unique_ptr<Renderer> kept = makeCpuRenderer(fastSimd(2));
  for (int turn = 0; turn < 3; ++turn) {
    const RenderOutput a = kept->render(with, settings, 97, 61);
    expectIdentical(makeCpuRenderer(fastSimd(2))->render(with, settings, 97, 61), a, "in turn, with the height map");
    const RenderOutput b = kept->render(without, settings, 97, 61);
    expectIdentical(makeCpuRenderer(fastSimd(2))->render(without, settings, 97, 61), b, "in turn, without");
  }
  with = Scene{};
  EXPECT_FALSE(watch.expired()) << "the renderer keeps the copy of a texture that sat out one frame";
  for (int frame = 0; frame < 8; ++frame) kept->render(without, settings, 97, 61);
  EXPECT_TRUE(watch.expired()) << "eight frames without it release the texture";
}

// Every view on the synthetic material with all its maps and without any, in both lighting
// spaces and filters, then with user clip planes cutting triangles, then with no light (the
// light direction view shows grey): each view has its own SIMD kernel in the fast path.
TEST_P(FastPath, EveryViewOnSyntheticMaterials) {
  expectTargetInUse(GetParam());
  for (bool maps : {true, false}) {
    Scene scene = syntheticScene(vec2(-1.3f, -0.2f), vec2(2.0f, 3.1f), 37, 20, 12.0f);
    if (!maps) {
      scene.materials[0].diffuseMap.reset();
      scene.materials[0].normalMap.reset();
      scene.materials[0].specularMap.reset();
    }
    const std::string material = maps ? "every map" : "no map";
    for (View view : kAllViews) {
      for (LightingSpace space : {LightingSpace::World, LightingSpace::Tangent}) {
        for (TextureFilter filter : {TextureFilter::Nearest, TextureFilter::Bilinear}) {
          RenderSettings settings = scene.settings;
          settings.view = view;
          settings.lightingSpace = space;
          settings.textureFilter = filter;
          settings.cull = CullMode::None;
          expectPathsAgree(scene, settings, 101, 67,
                           material + " view " + std::string(toString(view)) + " " + std::string(toString(space)) +
                               " " + std::string(toString(filter)));
        }
      }
    }
  }
  Scene scene = syntheticScene(vec2(0.0f), vec2(2.0f), 16, 16, 8.0f);
  for (View view : kAllViews) {
    for (LightingSpace space : {LightingSpace::World, LightingSpace::Tangent}) {
      RenderSettings settings = scene.settings;
      settings.view = view;
      settings.lightingSpace = space;
      settings.userClipPlanes = {vec4(1.0f, 0.2f, 0.0f, 0.1f), vec4(0.0f, -1.0f, 0.3f, 0.4f)};
      expectPathsAgree(scene, settings, 96, 64,
                       "user planes view " + std::string(toString(view)) + " " + std::string(toString(space)));
    }
  }
  scene.lights.clear();
  for (View view : kAllViews) {
    for (LightingSpace space : {LightingSpace::World, LightingSpace::Tangent}) {
      RenderSettings settings = scene.settings;
      settings.view = view;
      settings.lightingSpace = space;
      expectPathsAgree(scene, settings, 96, 64,
                       "no light view " + std::string(toString(view)) + " " + std::string(toString(space)));
    }
  }
}

// The depth view and the flat albedo view read no varyings: check them against hand-made
// expectations too, so agreeing with the teaching path is not the only evidence.
TEST_P(FastPath, DepthAndFlatAlbedoViewsShowTheirValues) {
  expectTargetInUse(GetParam());
  Scene scene = syntheticScene(vec2(0.0f), vec2(1.0f), 16, 16, 8.0f);
  scene.materials[0].diffuseMap.reset();
  scene.materials[0].kd = vec3(0.2f, 0.6f, 1.5f);  // 1.5 clamps to 1
  RenderSettings settings = scene.settings;
  settings.view = View::Albedo;
  const RenderOutput albedo = makeCpuRenderer(fastSimd(2))->render(scene, settings, 64, 48);
  settings.view = View::Depth;
  const RenderOutput depth = makeCpuRenderer(fastSimd(2))->render(scene, settings, 64, 48);
  std::size_t covered = 0;
  for (std::size_t i = 0; i < depth.triangleId.size(); ++i) {
    if (depth.triangleId[i] == kNoTriangle) continue;
    ++covered;
    // unitToByte: round(c * 255), halves up.
    ASSERT_EQ(albedo.rgba[4 * i], 51) << i;  // 0.2 * 255 = 51.0000008
    ASSERT_EQ(albedo.rgba[4 * i + 1], 153) << i;  // 0.6 * 255 = 153.0000023
    ASSERT_EQ(albedo.rgba[4 * i + 2], 255) << i;
    const long grey = std::lround(depth.depth[i] * 255.0f);  // depth is in [0, 1]
    ASSERT_EQ(depth.rgba[4 * i], grey) << i;
    ASSERT_EQ(depth.rgba[4 * i + 1], grey) << i;
    ASSERT_EQ(depth.rgba[4 * i + 2], grey) << i;
    ASSERT_EQ(depth.rgba[4 * i + 3], 255) << i;
  }
  EXPECT_GT(covered, 500u);
}

// Texture coordinates past 2^30 texels (either sign): the kernel hands those lanes to the
// scalar footprint. The last range overflows to infinity in u * width. The uv view takes
// u - floor(u) of the same values (NaN for infinite ones, drawn as 0).
TEST_P(FastPath, HugeTextureCoordinates) {
  expectTargetInUse(GetParam());
  const std::pair<vec2, vec2> ranges[] = {{vec2(-3.0e7f, 1.0e7f), vec2(3.0e7f, 2.0e7f)},
                                          {vec2(-1.0e30f, -5.0f), vec2(1.0e30f, 5.0f)},
                                          {vec2(0.0f, -3.0e38f), vec2(1.0f, 3.0e38f)}};
  for (const auto& [uvMin, uvMax] : ranges) {
    const Scene scene = syntheticScene(uvMin, uvMax, 64, 48, 16.0f);
    for (TextureFilter filter : {TextureFilter::Nearest, TextureFilter::Bilinear}) {
      for (View view : {View::Shaded, View::Albedo, View::MappedNormal, View::Uv}) {
        RenderSettings settings = scene.settings;
        settings.textureFilter = filter;
        settings.view = view;
        expectPathsAgree(scene, settings, 90, 70,
                         "uv from " + std::to_string(uvMin.x) + " " + std::string(toString(filter)) + " view " +
                             std::string(toString(view)));
      }
    }
  }
}

// Near plane off (depth clamp), planes switched off to the guard band, user planes and a
// camera inside the geometry: the clipper's new vertices go through the fast path's pool.
TEST_P(FastPath, ClippedTriangles) {
  expectTargetInUse(GetParam());
  Scene scene = syntheticScene(vec2(0.0f), vec2(2.0f), 16, 16, 8.0f);
  scene.camera.position = vec3(0.0f, 0.1f, 0.3f);  // inside the sphere's bounding box
  scene.camera.near = 0.01f;
  RenderSettings settings = scene.settings;
  settings.cull = CullMode::None;
  expectPathsAgree(scene, settings, 96, 64, "camera near the sphere");
  settings.clip.near = false;
  settings.clip.left = false;
  settings.clip.top = false;
  expectPathsAgree(scene, settings, 96, 64, "near, left, top off");
  settings.userClipPlanes = {vec4(1.0f, 0.2f, 0.0f, 0.1f), vec4(0.0f, -1.0f, 0.3f, 0.4f)};
  expectPathsAgree(scene, settings, 96, 64, "two user planes");
}

// powPositive against libm: within one ulp everywhere, exact where the answer is exact.
TEST_P(FastPath, PowPositiveIsWithinOneUlpOfLibm) {
  expectTargetInUse(GetParam());
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> base(0.0f, 1.05f);
  for (float s : {0.0f, 0.5f, 1.0f, 2.0f, 3.0f, 7.3f, 32.0f, 128.0f, 255.0f, 256.0f, 1000.0f, 1.0e5f}) {
    for (int i = 0; i < 20000; ++i) {
      const float x = base(rng);
      if (!(x > 0.0f)) continue;
      const float ours = powPositive(x, s), libm = std::pow(x, s);
      const auto a = std::bit_cast<std::int32_t>(ours), b = std::bit_cast<std::int32_t>(libm);
      ASSERT_LE(std::abs(a - b), 1) << x << "^" << s << ": " << ours << " vs " << libm;
    }
  }
  EXPECT_EQ(powPositive(0.5f, 2.0f), 0.25f);
  EXPECT_EQ(powPositive(1.0f, 1.0e30f), 1.0f);
  EXPECT_EQ(powPositive(0.3f, 0.0f), 1.0f);
  EXPECT_EQ(powPositive(2.0f, 200.0f), std::numeric_limits<float>::infinity());
  EXPECT_EQ(powPositive(1.0e-30f, 10.0f), 0.0f);
  EXPECT_EQ(powPositive(std::numeric_limits<float>::infinity(), 3.0f), std::numeric_limits<float>::infinity());
  EXPECT_EQ(powPositive(std::numeric_limits<float>::infinity(), 0.0f), 1.0f);
  EXPECT_EQ(powPositive(1.0f, std::numeric_limits<float>::infinity()), 1.0f);
}

// The kernels' pow, lane by lane, is powPositive bit for bit (an ulp here rarely shows in an
// 8-bit image, so it is checked directly), including the lanes phongPow handles without it.
TEST_P(FastPath, SimdPowIsTheScalarPowBitForBit) {
  expectTargetInUse(GetParam());
  std::mt19937 rng(11);
  std::uniform_real_distribution<float> base(0.0f, 1.02f);
  std::vector<float> x(4099);  // not a multiple of any vector width: the last call is partial
  for (float& v : x) v = base(rng);
  x[0] = 0.0f;
  x[1] = -0.0f;
  x[2] = std::numeric_limits<float>::infinity();
  x[3] = std::numeric_limits<float>::denorm_min();
  x[4] = 1.0f;
  x[5] = 1.0e-30f;
  for (float s : {0.0f, 0.25f, 1.0f, 3.0f, 32.0f, 77.7f, 255.0f, 4096.0f, 1.0e30f}) {
    std::vector<float> simd(x.size());
    fastKernelsFor(CpuIsa::Auto).phongPow(x.data(), s, simd.data(), x.size());
    for (std::size_t i = 0; i < x.size(); ++i) {
      const float scalar = lanes::phongPow(x[i], s);
      ASSERT_EQ(std::bit_cast<std::uint32_t>(simd[i]), std::bit_cast<std::uint32_t>(scalar))
          << x[i] << "^" << s << ": " << simd[i] << " vs " << scalar;
    }
  }
}

// The vertex stage a vector of vertices at a time is the scalar stage (runVertexStage,
// windowFromClip, snapToSubpixel, outcode, storeVaryings) bit for bit: for a mirroring model
// matrix, both lighting spaces, user clip planes, the frustum's planes on and off, and vertices
// anywhere (behind the eye, at w = 0, huge, infinite, NaN), a count that no vector width divides.
TEST_P(FastPath, VertexRangeIsTheScalarVertexStageBitForBit) {
  expectTargetInUse(GetParam());
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> unit(-1.0f, 1.0f);
  std::uniform_real_distribution<float> exponent(-40.0f, 40.0f);
  std::vector<Vertex> vertices(1003);
  for (Vertex& v : vertices) {
    const float scale = std::pow(2.0f, exponent(rng) < 30.0f ? unit(rng) * 4.0f : exponent(rng));
    v.posModel = vec3(unit(rng), unit(rng), unit(rng)) * scale;
    v.nModel = vec3(unit(rng), unit(rng), unit(rng));
    v.tangentModel = vec4(unit(rng), unit(rng), unit(rng), unit(rng) < 0.0f ? -1.0f : 1.0f);
    v.uv = vec2(unit(rng), unit(rng)) * 8.0f;
  }
  const float inf = std::numeric_limits<float>::infinity(), nan = std::numeric_limits<float>::quiet_NaN();
  const std::vector<vec3> odd = {vec3(0.0f), vec3(0.3f, 1.7f, 4.4f), vec3(0.3f, 1.7f, 4.5f), vec3(1e30f, 0.0f, 0.0f),
                                 vec3(inf, 0.0f, 0.0f), vec3(0.0f, nan, 0.0f), vec3(-1e-30f, 2e-38f, 1e-40f),
                                 vec3(0.3f, 1.7f, 4.4f - 1e-6f)};
  for (std::size_t i = 0; i < odd.size(); ++i) vertices[10 * i].posModel = odd[i];
  vertices[1].nModel = vec3(0.0f);
  vertices[2].tangentModel = vec4(nan, 0.0f, 0.0f, 1.0f);

  Scene scene;
  scene.camera.position = vec3(0.3f, 1.7f, 4.4f);
  scene.lights.resize(2);
  scene.lights[0].posWorld = vec3(3.5f, 1.8f, 2.5f);
  scene.lights[1].type = LightType::Directional;
  scene.lights[1].directionWorld = glm::normalize(vec3(-0.3f, -1.0f, 0.2f));
  const mat4 worldFromModel =
      glm::scale(glm::rotate(glm::translate(mat4(1.0f), vec3(-1.0f, 0.8f, 0.2f)), 0.6f, vec3(0.2f, 1.0f, 0.1f)),
                 vec3(1.5f, -0.75f, 1.25f));
  const Viewport viewport{1280, 720};
  for (const bool tangentLighting : {false, true}) {
    for (const int userPlanes : {0, 2}) {
      RenderSettings settings;
      settings.lightingSpace = tangentLighting ? LightingSpace::Tangent : LightingSpace::World;
      settings.userClipPlanes = {vec4(0.3f, -1.0f, 0.2f, 0.9f), vec4(-0.7f, 0.1f, 0.5f, 0.1f)};
      settings.userClipPlanes.resize(static_cast<std::size_t>(userPlanes));
      const VertexUniforms u =
          makeVertexUniforms(worldFromModel, clipFromWorldFor(scene.camera, viewport.width, viewport.height), scene, settings);
      ASSERT_LT(u.mirrorSign, 0.0f);
      ClipSwitches frustum;
      frustum.near = !tangentLighting;
      frustum.left = frustum.top = userPlanes == 0;
      const ClipConfig clip = makeClipConfig(frustum, userPlanes, viewport.width, viewport.height);
      const std::size_t stride = static_cast<std::size_t>(varyingCount(tangentLighting, u.lightCount));
      std::vector<FastVertex> out(vertices.size());
      std::vector<SnappedCorner> corners(vertices.size());
      std::vector<float> varyings(vertices.size() * stride);
      fastKernelsFor(CpuIsa::Auto)
          .vertexRange(vertices.data(), vertices.size(), u, viewport, clip, out.data(), corners.data(), varyings.data(), stride);
      std::vector<float> expected(stride);
      const auto bits = [](float x) { return std::bit_cast<std::uint32_t>(x); };
      std::size_t inside = 0, outside = 0, unusable = 0;  // the outcodes' kinds, all exercised
      for (const SnappedCorner& c : corners) {
        (c.outcode == 0 ? inside : c.outcode == kClipNonFiniteBit ? unusable : outside) += 1;
      }
      EXPECT_GT(inside, 100u);
      EXPECT_GT(outside, 100u);
      EXPECT_GT(unusable, 2u);
      for (std::size_t i = 0; i < vertices.size(); ++i) {
        const ClipVertex v = runVertexStage(vertices[i], u);
        const WindowVertex w = windowFromClip(v, viewport);
        const bool finite = std::isfinite(v.posClip.x) && std::isfinite(v.posClip.y) && std::isfinite(v.posClip.z) &&
                            std::isfinite(v.posClip.w);
        SCOPED_TRACE(::testing::Message() << "vertex " << i << ", tangent lighting " << tangentLighting << ", "
                                          << userPlanes << " user planes");
        EXPECT_EQ(bits(out[i].window.x), bits(w.x));
        EXPECT_EQ(bits(out[i].window.y), bits(w.y));
        EXPECT_EQ(bits(out[i].window.z), bits(w.z));
        EXPECT_EQ(bits(out[i].window.invW), bits(w.invW));
        EXPECT_EQ(out[i].xFixed, snapToSubpixel(w.x));
        EXPECT_EQ(out[i].yFixed, snapToSubpixel(w.y));
        EXPECT_EQ(corners[i].xFixed, out[i].xFixed);
        EXPECT_EQ(corners[i].yFixed, out[i].yFixed);
        EXPECT_EQ(corners[i].outcode, finite ? outcode(v, clip) : kClipNonFiniteBit);
        storeVaryings(v, tangentLighting, u.lightCount, expected.data());
        for (std::size_t c = 0; c < stride; ++c) ASSERT_EQ(bits(varyings[i * stride + c]), bits(expected[c])) << "varying " << c;
      }
    }
  }
}

// An index past the vertex count: the fast path checks the indices as its front end reads
// them, and must throw the teaching path's error (the first bad index, whichever thread's
// range holds it), for a triangle's index and for one past the last whole triangle.
TEST_P(FastPath, BadIndicesThrowTheTeachingPathsError) {
  expectTargetInUse(GetParam());
  Scene scene = loadSceneFile(kScenes + "/default.json");
  const std::size_t sphere = 1;  // the scene's second node, most of its triangles
  ASSERT_EQ(scene.nodes[sphere].name, "ball");
  const std::size_t mesh = static_cast<std::size_t>(scene.nodes[sphere].meshIndex);
  const std::size_t count = scene.meshes[mesh].indices.size();
  const auto errorOf = [&](const Scene& broken, const CpuOptions& options) {
    try {
      makeCpuRenderer(options)->render(broken, broken.settings, 64, 48);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  const std::vector<std::vector<std::size_t>> cases = {{5}, {count - 1}, {count - 2, count / 2 + 1}, {count}};
  for (const std::vector<std::size_t>& bad : cases) {
    Scene broken = scene;
    std::vector<std::uint32_t>& indices = broken.meshes[mesh].indices;
    if (bad[0] == count) indices.push_back(0);  // a trailing index, past the last whole triangle
    for (const std::size_t i : bad) indices[i] = 1000000;
    const std::string expected = errorOf(broken, teaching());
    ASSERT_NE(expected.find("mesh index " + std::to_string(*std::min_element(bad.begin(), bad.end()))),
              std::string::npos)
        << expected;
    for (const int threads : {1, 2, 3}) EXPECT_EQ(errorOf(broken, fastSimd(threads)), expected) << threads << " threads";
  }
}

TEST_P(FastPath, PathNames) {
  expectTargetInUse(GetParam());
  EXPECT_EQ(cpuPathName(teaching()), "teaching");
  EXPECT_EQ(cpuPathName(CpuOptions{1, CpuPath::Fast, CpuIsa::Scalar}), "fast (scalar)");
  const std::string name = cpuPathName(fastSimd(1));
  EXPECT_EQ(name, "fast (" + std::string(toString(fastKernelsFor(CpuIsa::Auto).isa)) + ")");
}

// Every target Highway compiled in and this CPU runs is one supportedCpuIsas() lists, so the
// per-target tests above cover every target a user can ask for.
TEST(FastPathTargets, EverySupportedTargetIsTested) {
  std::vector<CpuIsa> tested;
  for (const std::int64_t target : hwy::SupportedAndGeneratedTargets()) {
    // Highway's portable target, compiled without kernels where CMake's TWINRASTER_KERNEL_TARGETS
    // leaves them out (the sanitizer build): not a target a user can ask for.
    if ((fastKernelTargets() & target) == 0) continue;
    bool named = false;
    for (const CpuIsa isa : supportedCpuIsas()) named = named || highwayTargetOf(isa) == target;
    EXPECT_TRUE(named) << hwy::TargetName(target) << " is compiled and supported but has no CpuIsa name";
  }
  for (const CpuIsa isa : supportedCpuIsas()) {
    EXPECT_EQ(fastKernelsFor(isa).isa, isa) << toString(isa);
  }
  EXPECT_FALSE(supportedCpuIsas().empty());
  if (cpuIsaCompiled(CpuIsa::Scalar)) {
    EXPECT_EQ(supportedCpuIsas().back(), CpuIsa::Scalar);
  }
}

// The fast-path targets this CPU's flags in /proc/cpuinfo say it can run: each one's group of
// features as Highway requires them (hwy/targets.cc; the operating system's AVX state is
// implied where the kernel lists the flags). Empty off x86-64 or where /proc/cpuinfo is
// unreadable; scalar runs everywhere and is always required.
std::vector<std::string> cpuinfoTargets() {
  std::vector<std::string> targets = {"scalar"};
#if HWY_ARCH_X86_64
  std::ifstream cpuinfo("/proc/cpuinfo");
  std::string line;
  std::set<std::string> flags;
  while (std::getline(cpuinfo, line)) {
    if (line.rfind("flags", 0) != 0) continue;
    std::istringstream words(line.substr(line.find(':') + 1));
    for (std::string flag; words >> flag;) flags.insert(flag);
    break;  // the first processor's; they all list the same
  }
  const auto has = [&](std::initializer_list<const char*> group) {
    return std::all_of(group.begin(), group.end(), [&](const char* flag) { return flags.count(flag) > 0; });
  };
  const bool sse4 = has({"ssse3", "sse4_1", "sse4_2", "pclmulqdq", "aes"});
  // Without "abm" (LZCNT), which Highway's AVX2 also needs: every AVX2 CPU has it, and Linux
  // under some hypervisors leaves the flag out while CPUID reports it (this AMD EPYC VM does).
  const bool avx2 = sse4 && has({"avx", "avx2", "bmi1", "bmi2", "fma", "f16c"});
  const bool avx512 = avx2 && has({"avx512f", "avx512vl", "avx512dq", "avx512bw"});
  if (sse4) targets.push_back("sse4");
  if (avx2) targets.push_back("avx2");
  if (avx512) targets.push_back("avx512");
#endif
  return targets;
}

// Targets that must be present, so that their per-target tests above run rather than vanish:
// every one /proc/cpuinfo says this CPU runs, and those TWINRASTER_REQUIRE_CPU_ISAS names
// (comma-separated; scripts/cross-aarch64.sh requires neon under qemu-user this way). A
// missing one fails here instead of being skipped.
std::vector<std::string> requiredTargets() {
  std::vector<std::string> required = cpuinfoTargets();
#ifdef TWR_KERNEL_TARGETS
  // A build whose kernels CMake's TWINRASTER_KERNEL_TARGETS chose requires those the CPU runs
  // (the test fails when that leaves none).
  std::erase_if(required, [](const std::string& name) {
    CpuIsa isa = CpuIsa::Auto;
    return parse(name, isa) && (highwayTargetOf(isa) & (TWR_KERNEL_TARGETS)) == 0;
  });
#endif
  const char* listed = std::getenv("TWINRASTER_REQUIRE_CPU_ISAS");
  const std::string list = listed ? listed : "";
  for (std::size_t start = 0; start <= list.size();) {
    const std::size_t end = std::min(list.find(',', start), list.size());
    const std::string name = list.substr(start, end - start);
    start = end + 1;
    if (!name.empty() && std::find(required.begin(), required.end(), name) == required.end()) required.push_back(name);
  }
  return required;
}

TEST(FastPathTargets, RequiredTargetsArePresent) {
  const std::vector<std::string> required = requiredTargets();
  const std::vector<CpuIsa> supported = supportedCpuIsas();
  ASSERT_FALSE(required.empty());
  for (const std::string& name : required) {
    CpuIsa isa = CpuIsa::Auto;
    ASSERT_TRUE(parse(name, isa)) << "TWINRASTER_REQUIRE_CPU_ISAS names an unknown target '" << name << "'";
    EXPECT_TRUE(cpuIsaSupported(isa)) << "required target " << name << " is absent: " << cpuIsaUnsupportedReason(isa);
    EXPECT_NE(std::find(supported.begin(), supported.end(), isa), supported.end())
        << name << " is required but has no per-target tests here";
  }
}

// A target this CPU cannot run is refused with a message naming it.
TEST(FastPathTargets, UnsupportedTargetIsRefused) {
  for (const CpuIsa isa : {CpuIsa::Avx512, CpuIsa::Avx2, CpuIsa::Sse4, CpuIsa::Neon}) {
    if (cpuIsaSupported(isa)) continue;
    try {
      makeCpuRenderer(CpuOptions{1, CpuPath::Fast, isa});
      ADD_FAILURE() << toString(isa) << " was accepted";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(toString(isa)), std::string::npos) << e.what();
    }
  }
}

}  // namespace
}  // namespace twr
