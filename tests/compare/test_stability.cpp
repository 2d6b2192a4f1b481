// The numerical stability suite (issue 7): hard cases where numbers get hard, each with its
// exact expected outcome, on the CPU pipeline, on GL (llvmpipe) and, where it says something,
// on the double-precision reference. Images of the cases that are worth looking at (z-fighting)
// go to TWINRASTER_TEST_OUT/stability/. See docs/stability.md for what each case proves.
#include "compare/metrics.h"
#include "glrender/context_osmesa.h"
#include "glrender/gl_context.h"
#include "glrender/gl_renderer.h"
#include "scene/errors.h"
#include "scene/image.h"
#include "scene/primitives.h"
#include "scene/scene_file.h"
#include "scene/tangents.h"
#include "scene/texture.h"
#include "softrender/clip.h"
#include "softrender/cpu_renderer.h"
#include "softrender/raster.h"
#include "softrender/reference_renderer.h"
#include "softrender/setup.h"
#include "softrender/vertex.h"

#include <glad/gl.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <limits>
#include <memory>
#include <string>
#include <vector>

namespace twr {
namespace {

constexpr int kSide = 64;  // image width and height of most cases, pixels
const std::string kAssets = std::string(TWINRASTER_SOURCE_DIR) + "/assets";
const std::string kOut = std::string(TWINRASTER_TEST_OUT) + "/stability";

// ---- scenes built in code ----

// Camera at the origin looking down -Z with a 90 degree field of view on a square image: its
// viewFromWorld is the identity, so clip x = f x, y = f y, w = -z (f = 1 / tan 45 deg).
Scene frontScene(float near = 0.1f, float far = 100.0f) {
  Scene scene;
  scene.camera.position = vec3(0.0f);
  scene.camera.target = vec3(0.0f, 0.0f, -1.0f);
  scene.camera.fovDeg = 90.0f;
  scene.camera.near = near;
  scene.camera.far = far;
  scene.output.background = vec4(0.0f, 0.0f, 0.0f, 1.0f);
  scene.settings.cull = CullMode::None;
  scene.settings.view = View::Albedo;  // colour = kd: flat, so coverage and ties are easy to read
  return scene;
}

int addMaterial(Scene& scene, vec3 kd) {
  Material m;
  m.kd = kd;
  scene.materials.push_back(m);
  return static_cast<int>(scene.materials.size()) - 1;
}

void addMesh(Scene& scene, Mesh mesh, int material, const std::string& name, vec3 scale = vec3(1.0f)) {
  MeshDesc desc;
  desc.type = MeshType::Triangles;
  scene.meshDescs.push_back(desc);
  scene.meshes.push_back(std::move(mesh));
  Node node;
  node.name = name;
  node.meshIndex = static_cast<int>(scene.meshes.size()) - 1;
  node.materialIndex = material;
  node.scale = scale;
  scene.nodes.push_back(node);
}

Mesh quadZ(float halfSize, float z) {
  return makeTriangles({{-halfSize, -halfSize, z}, {halfSize, -halfSize, z}, {halfSize, halfSize, z},
                        {-halfSize, -halfSize, z}, {halfSize, halfSize, z}, {-halfSize, halfSize, z}},
                       {}, {});
}

std::shared_ptr<const Texture> texture(const std::string& name) {
  return std::make_shared<const Texture>(loadTexture(kAssets + "/textures/" + name));
}

// ---- rendering both backends ----

// One GL renderer and one blend harness for the whole test process, never destroyed: Mesa's
// own exit handlers run before static destructors would, and a context torn down after them
// crashes in OSMesaMakeCurrent.
Renderer& glRenderer() {
  static Renderer* const renderer = makeGlRenderer().release();
  return *renderer;
}

struct Both {
  RenderOutput cpu, gl;
  CompareMetrics cpuVsGl;
};

Both renderBoth(const Scene& scene, const RenderSettings& settings, int width = kSide, int height = kSide) {
  Both b;
  b.cpu = makeCpuRenderer()->render(scene, settings, width, height);
  b.gl = glRenderer().render(scene, settings, width, height);
  b.cpuVsGl = compare(b.cpu, b.gl);
  return b;
}

std::size_t coveredCount(const RenderOutput& out) {
  std::size_t n = 0;
  for (std::size_t i = 0; i < out.depth.size(); ++i) n += coveredAt(out, i) ? 1 : 0;
  return n;
}

bool covered(const RenderOutput& out, int x, int yTop) {
  return coveredAt(out, static_cast<std::size_t>(yTop) * static_cast<std::size_t>(out.width) + static_cast<std::size_t>(x));
}

const std::uint8_t* pixelAt(const RenderOutput& out, int x, int yTop) {
  return &out.rgba[(static_cast<std::size_t>(yTop) * out.width + x) * 4];
}

// No NaN or Inf in any depth value, and every depth within [0, 1].
void expectFiniteDepth(const RenderOutput& out, const std::string& what) {
  std::size_t bad = 0;
  for (float d : out.depth) bad += (std::isfinite(d) && d >= 0.0f && d <= 1.0f) ? 0 : 1;
  EXPECT_EQ(bad, 0u) << what << ": depth values outside [0, 1] or not finite";
}

// The project's CPU-versus-llvmpipe targets (issue 5): coverage mismatch 0 (at most 1 per
// 10,000 covered pixels where triangles are clipped), max diff <= 3 levels, over_1 <= 0.1 %.
void expectTargets(const Both& b, const std::string& what) {
  const CompareMetrics& m = b.cpuVsGl;
  if (b.cpu.stats.trianglesClipped > 0) {
    EXPECT_LE(m.coverageMismatchPer10k(), 1.0) << what;
  } else {
    EXPECT_EQ(m.coverageMismatch, 0u) << what;
  }
  EXPECT_LE(m.maxAbsDiff, 3) << what;
  EXPECT_LE(m.over1Pct(), 0.1) << what;
  EXPECT_EQ(m.nanPixels, 0u) << what;
  expectFiniteDepth(b.cpu, what + " (cpu)");
  expectFiniteDepth(b.gl, what + " (gl)");
}

// ---- triangles crossing w = 0, vertices on planes, six planes ----

// A ground triangle at y = -1 reaching 1000 units behind the camera (w < 0 there) and far
// beyond the far plane, its side edges outside the view: the far plane cuts it at view depth
// 100, i.e. at window y = 32 (1 - f / 100) = 31.68, so exactly the 32 bottom rows are covered.
Scene groundThroughCamera() {
  Scene scene = frontScene();
  addMesh(scene, makeTriangles({{-1000, -1, 1000}, {1000, -1, 1000}, {0, -1, -1000}}, {}, {}),
          addMaterial(scene, vec3(1.0f)), "ground");
  return scene;
}

TEST(Stability, TriangleCrossingWZeroCoversExactlyTheRowsBelowTheFarLine) {
  Scene scene = groundThroughCamera();
  for (const bool nearOn : {true, false}) {
    RenderSettings settings = scene.settings;
    settings.clip.near = nearOn;  // off: the w >= kMinClipW plane and GL depth clamp take over
    const Both b = renderBoth(scene, settings);
    const std::string what = nearOn ? "near on" : "near off";
    EXPECT_EQ(b.cpu.stats.trianglesClipped, 1u) << what;
    EXPECT_EQ(coveredCount(b.cpu), 32u * kSide) << what;
    EXPECT_EQ(coveredCount(b.gl), 32u * kSide) << what;
    for (int x = 0; x < kSide; ++x) {
      ASSERT_FALSE(covered(b.cpu, x, 31)) << what;  // GL row 32, centre 32.5 > 31.68
      ASSERT_TRUE(covered(b.cpu, x, 32)) << what;   // GL row 31, centre 31.5 < 31.68
    }
    expectTargets(b, what);
  }
  // The reference's 4 x 4 samples in GL row 31 sit at 31.125 .. 31.875: three rows of four
  // below 31.68, so alpha is 12/16 of 255 there (over a transparent background, alpha is
  // the coverage fraction).
  scene.output.background.a = 0.0f;
  const RenderOutput reference = makeReferenceRenderer({4, 1})->render(scene, scene.settings, kSide, kSide);
  EXPECT_EQ(coveredCount(reference), 32u * kSide);
  EXPECT_EQ(pixelAt(reference, 10, 32)[3], static_cast<int>(std::lround(255.0 * 12.0 / 16.0)));
  EXPECT_EQ(pixelAt(reference, 10, 33)[3], 255);
}

// The float x with fl(m * x) == target, found from target / m by stepping one ulp at a time
// (the product is monotonic in x), so a vertex lands exactly on a clip plane.
float solveExactProduct(float m, float target) {
  float x = target / m;
  for (int step = 0; step < 8 && m * x != target; ++step) {
    x = std::nextafter(x, m * x < target ? std::numeric_limits<float>::infinity() : -std::numeric_limits<float>::infinity());
  }
  return x;
}

TEST(Stability, VerticesExactlyOnTheRightAndTopPlanesAreInside) {
  Scene scene = frontScene();
  const mat4 clipFromWorld = clipFromWorldFor(scene.camera, kSide, kSide);
  constexpr float kDepth = 2.0f;  // view depth: w = 2 exactly
  const float xOnRight = solveExactProduct(clipFromWorld[0][0], kDepth);
  const float yOnTop = solveExactProduct(clipFromWorld[1][1], kDepth);
  const std::vector<vec3> positions{{0, 0, -kDepth}, {xOnRight, 0, -kDepth}, {0, yOnTop, -kDepth}};
  for (const vec3& p : positions) {
    const vec4 clip = transformPoint(clipFromWorld, p);
    ASSERT_EQ(clip.w, kDepth);
    ASSERT_TRUE(clip.x == 0.0f || clip.x == clip.w) << "vertex not exactly on the right plane";
    ASSERT_TRUE(clip.y == 0.0f || clip.y == clip.w) << "vertex not exactly on the top plane";
  }
  addMesh(scene, makeTriangles(positions, {}, {}), addMaterial(scene, vec3(1.0f)), "corner");
  const Both b = renderBoth(scene, scene.settings);
  // Inside means not clipped at all.
  EXPECT_EQ(b.cpu.stats.trianglesClipped, 0u);
  // Window corners (32, 32), (64, 32), (32, 64). Pixel centres (32 + a + 0.5, 32 + b + 0.5)
  // with a, b >= 0 are inside when a + b + 1 < 32; a + b + 1 = 32 lies on the hypotenuse, a
  // top-right edge that does not own its pixels. So a + b <= 30: 31 * 32 / 2 = 496 pixels.
  EXPECT_EQ(coveredCount(b.cpu), 496u);
  EXPECT_EQ(coveredCount(b.gl), 496u);
  expectTargets(b, "vertices on planes");
}

TEST(Stability, TriangleGainsAVertexFromEachOfTheSixPlanes) {
  // near 1, far 2: z_ndc = +-1.84 must map to points in front of the camera, which needs
  // (far + near) / (far - near) = 3 > 1.84 (with far >> near, z_ndc above ~1 is behind the eye).
  Scene scene = frontScene(1.0f, 2.0f);
  // In NDC the plane x + y + z = 0 cuts the cube |x|, |y|, |z| <= 1 in a hexagon; a triangle in
  // that plane whose edges run 1.3 from the centre (inside the hexagon's circumradius sqrt 2)
  // has each corner cut off by two planes: 3 + 6 = 9 vertices. Its corners, taken back to
  // world space through the inverse camera matrix (in double), make the scene's triangle.
  const mat4 clipFromWorld = clipFromWorldFor(scene.camera, kSide, kSide);
  const glm::dmat4 worldFromClip = glm::inverse(glm::dmat4(clipFromWorld));
  const double r = 2.6 / std::sqrt(2.0);
  std::vector<vec3> positions;
  for (const glm::dvec4& ndc : {glm::dvec4(-r, r, 0, 1), glm::dvec4(0, -r, r, 1), glm::dvec4(r, 0, -r, 1)}) {
    const glm::dvec4 world = worldFromClip * ndc;
    ASSERT_GT(world.w, 0.0);
    positions.push_back(vec3(glm::dvec3(world) / world.w));
  }
  VertexUniforms uniforms;
  uniforms.clipFromWorld = clipFromWorld;
  std::array<ClipVertex, 3> v;
  for (std::size_t i = 0; i < 3; ++i) {
    Vertex vertex;
    vertex.posModel = positions[i];
    v[i] = runVertexStage(vertex, uniforms);
  }
  ClipPolygon polygon, scratch;
  const std::uint32_t cut = clipTriangle(v[0], v[1], v[2], makeClipConfig(ClipSwitches{}, 0, kSide, kSide), polygon, scratch);
  constexpr std::uint32_t kSixPlanes = 0x3F;
  ASSERT_EQ(cut, kSixPlanes) << "each of right, left, top, bottom, near and far cuts the triangle";
  ASSERT_EQ(polygon.count, 3 + 6) << "each plane cut adds one vertex";
  for (int i = 0; i < polygon.count; ++i) {
    const vec4& p = polygon.v[static_cast<std::size_t>(i)].posClip;
    ASSERT_TRUE(std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z) && std::isfinite(p.w));
    ASSERT_GT(p.w, 0.0f);
  }

  addMesh(scene, makeTriangles(positions, {}, {}), addMaterial(scene, vec3(1.0f)), "six planes");
  const Both b = renderBoth(scene, scene.settings);
  EXPECT_EQ(b.cpu.stats.trianglesClipped, 1u);
  // The 9-gon is drawn as a fan of 7 triangles, each either drawn or of zero snapped area.
  EXPECT_EQ(b.cpu.stats.trianglesProduced + b.cpu.stats.trianglesCulled, 7u);
  EXPECT_GT(coveredCount(b.cpu), 0u);
  expectTargets(b, "six planes");
}

// ---- shared edges: a GL harness that counts fragments with additive blending ----

// Draws window-space triangles into an RGBA8 target with glBlendFunc(GL_ONE, GL_ONE), each
// fragment adding 1/255 to red: red is the number of times llvmpipe covered the pixel.
class BlendCounter {
 public:
  explicit BlendCounter(int side) : side_(side), context_(OsMesaContextDesc{}) {
    bind();
    const char* vertexSource =
        "#version 330 core\nlayout(location = 0) in vec2 posNdc;\n"
        "void main() { gl_Position = vec4(posNdc, 0.0, 1.0); }\n";
    const char* fragmentSource =
        "#version 330 core\nout vec4 colour;\nvoid main() { colour = vec4(1.0 / 255.0, 0.0, 0.0, 1.0); }\n";
    program_ = glCreateProgram();
    for (auto [type, source] : {std::pair{GL_VERTEX_SHADER, vertexSource}, std::pair{GL_FRAGMENT_SHADER, fragmentSource}}) {
      const GLuint shader = glCreateShader(type);
      glShaderSource(shader, 1, &source, nullptr);
      glCompileShader(shader);
      GLint ok = 0;
      glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
      EXPECT_TRUE(ok) << "harness shader";
      glAttachShader(program_, shader);
      glDeleteShader(shader);
    }
    glLinkProgram(program_);
    glGenFramebuffers(1, &framebuffer_);
    glGenRenderbuffers(1, &colour_);
    glBindRenderbuffer(GL_RENDERBUFFER, colour_);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, side, side);
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, colour_);
    EXPECT_EQ(glCheckFramebufferStatus(GL_FRAMEBUFFER), static_cast<GLenum>(GL_FRAMEBUFFER_COMPLETE));
    glGenVertexArrays(1, &vao_);
    glGenBuffers(1, &buffer_);
  }

  // Counts per pixel, GL order (row 0 at the bottom), for triangles in window coordinates.
  std::vector<int> count(const std::vector<std::array<vec2, 3>>& triangles) {
    bind();
    std::vector<float> ndc;
    for (const auto& t : triangles) {
      for (const vec2& p : t) {
        ndc.push_back(p.x / (0.5f * side_) - 1.0f);
        ndc.push_back(p.y / (0.5f * side_) - 1.0f);
      }
    }
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
    glViewport(0, 0, side_, side_);
    glClearColor(0, 0, 0, 0);
    glClear(GL_COLOR_BUFFER_BIT);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_CULL_FACE);
    glEnable(GL_BLEND);
    glBlendFunc(GL_ONE, GL_ONE);
    glUseProgram(program_);
    glBindVertexArray(vao_);
    glBindBuffer(GL_ARRAY_BUFFER, buffer_);
    glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(ndc.size() * sizeof(float)), ndc.data(), GL_STREAM_DRAW);
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, 0, nullptr);
    glDrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(ndc.size() / 2));
    std::vector<std::uint8_t> rgba(static_cast<std::size_t>(side_) * side_ * 4);
    glReadPixels(0, 0, side_, side_, GL_RGBA, GL_UNSIGNED_BYTE, rgba.data());
    glDisable(GL_BLEND);
    std::vector<int> counts(static_cast<std::size_t>(side_) * side_);
    for (std::size_t i = 0; i < counts.size(); ++i) counts[i] = rgba[i * 4];
    return counts;
  }

 private:
  void bind() {
    context_.makeCurrent();
    loadCoreGl([this](const char* name) { return context_.procAddress(name); }, "stability blend harness");
  }

  int side_;
  OsMesaContext context_;
  GLuint program_ = 0, framebuffer_ = 0, colour_ = 0, vao_ = 0, buffer_ = 0;
};

// The same triangles through the CPU's setup and rasterizer (the positions go through
// windowFromClip with w = 1, as vertex-stage vertices do), counted per pixel, GL order.
std::vector<int> cpuCounts(const std::vector<std::array<vec2, 3>>& triangles, int side) {
  std::vector<int> counts(static_cast<std::size_t>(side) * side, 0);
  const Viewport viewport{side, side};
  for (const auto& t : triangles) {
    std::array<WindowVertex, 3> window;
    for (std::size_t i = 0; i < 3; ++i) {
      const vec4 clip(t[i].x / (0.5f * side) - 1.0f, t[i].y / (0.5f * side) - 1.0f, 0.0f, 1.0f);
      window[i] = windowFromClip(clip, viewport, true);
    }
    TriangleSetup setup;
    if (setupTriangle(window, CullMode::None, FrontFace::Ccw, viewport, setup) != SetupResult::Ready) continue;
    rasterizeTriangle(setup, 0, side, [&](int py, Span span) {
      for (int px = span.xBegin; px < span.xEnd; ++px) ++counts[static_cast<std::size_t>(py) * side + px];
    });
  }
  return counts;
}

BlendCounter& blendCounter() {
  static BlendCounter* const counter = new BlendCounter(kSide);  // never destroyed, see glRenderer()
  return *counter;
}

// A fan of `n` triangles around `centre` whose rim points lie on a circle; consecutive
// triangles share an edge, and all share the centre.
std::vector<std::array<vec2, 3>> fan(vec2 centre, float radius, int n, float phase) {
  std::vector<std::array<vec2, 3>> out;
  constexpr float kTwoPi = 6.28318530718f;
  auto rim = [&](int i) {
    const float a = phase + kTwoPi * static_cast<float>(i % n) / static_cast<float>(n);
    return centre + radius * vec2(std::cos(a), std::sin(a));
  };
  for (int i = 0; i < n; ++i) out.push_back({centre, rim(i), rim(i + 1)});
  return out;
}

TEST(Stability, SharedEdgeFansAreCoveredExactlyOnceOnBothBackends) {
  struct FanCase {
    const char* name;
    vec2 centre;
    float radius;
    int triangles;
    float phase;
  };
  // A generic centre, a centre exactly on a pixel centre (all edges meet where the fill rule
  // decides), and a fine fan of slivers.
  const FanCase cases[] = {{"generic", {31.3f, 29.7f}, 25.0f, 12, 0.1f},
                           {"on a pixel centre", {32.5f, 32.5f}, 28.0f, 16, 0.0f},
                           {"64 slivers", {30.0f, 33.0f}, 27.0f, 64, 0.37f}};
  for (const FanCase& c : cases) {
    const auto triangles = fan(c.centre, c.radius, c.triangles, c.phase);
    const std::vector<int> cpu = cpuCounts(triangles, kSide);
    const std::vector<int> gl = blendCounter().count(triangles);
    int cpuMax = 0, glMax = 0;
    std::size_t differ = 0, holes = 0;
    for (std::size_t i = 0; i < cpu.size(); ++i) {
      cpuMax = std::max(cpuMax, cpu[i]);
      glMax = std::max(glMax, gl[i]);
      differ += cpu[i] != gl[i] ? 1 : 0;
      // Pixel centres well inside the rim polygon (0.5 px from the inscribed circle) must be
      // covered: no cracks between the fan's triangles.
      const int px = static_cast<int>(i % kSide), py = static_cast<int>(i / kSide);
      const vec2 centre(static_cast<float>(px) + 0.5f, static_cast<float>(py) + 0.5f);
      const float inscribed = c.radius * std::cos(3.14159265f / static_cast<float>(c.triangles)) - 0.5f;
      if (glm::length(centre - c.centre) < inscribed && cpu[i] != 1) ++holes;
    }
    EXPECT_EQ(cpuMax, 1) << c.name << ": a pixel drawn twice on the CPU";
    EXPECT_EQ(glMax, 1) << c.name << ": a pixel drawn twice on GL";
    EXPECT_EQ(holes, 0u) << c.name << ": cracks inside the fan";
    EXPECT_EQ(differ, 0u) << c.name << ": CPU and GL cover different pixels";
  }
}

TEST(Stability, SliverWithZeroSnappedAreaVanishesOnBothBackends) {
  // Float area 0.5 * 52 * (1/1024) > 0, but 20.25 + 1/1024 snaps to the same 1/256 step as
  // 20.25 ((20.25 - 0.5) * 256 = 5056, 5056.25 rounds to 5056): collinear after snapping.
  const std::vector<std::array<vec2, 3>> sliver = {{vec2(4.25f, 20.25f), vec2(30.25f, 20.25f + 1.0f / 1024.0f), vec2(56.25f, 20.25f)}};
  const Viewport viewport{kSide, kSide};
  std::array<WindowVertex, 3> window;
  for (std::size_t i = 0; i < 3; ++i) {
    window[i] = windowFromClip(vec4(sliver[0][i].x / 32.0f - 1.0f, sliver[0][i].y / 32.0f - 1.0f, 0.0f, 1.0f), viewport, true);
  }
  TriangleSetup setup;
  EXPECT_EQ(setupTriangle(window, CullMode::None, FrontFace::Ccw, viewport, setup), SetupResult::ZeroArea);
  const std::vector<int> cpu = cpuCounts(sliver, kSide);
  const std::vector<int> gl = blendCounter().count(sliver);
  EXPECT_EQ(std::count(cpu.begin(), cpu.end(), 0), kSide * kSide);
  EXPECT_EQ(std::count(gl.begin(), gl.end(), 0), kSide * kSide) << "llvmpipe snaps to the same 8 sub-pixel bits";
  // One step (1/256 px) taller it has area and both draw the same pixels.
  const std::vector<std::array<vec2, 3>> thin = {{vec2(4.25f, 20.25f), vec2(30.25f, 20.25f + 1.0f / 256.0f), vec2(56.25f, 20.25f)}};
  EXPECT_EQ(cpuCounts(thin, kSide), blendCounter().count(thin));
}

// ---- huge triangles ----

TEST(Stability, TriangleHundredsOfTimesLargerThanTheScreenCoversEveryPixelOnce) {
  // At depth 2 the view spans [-2, 2]; the triangle spans 2000 units: 500 screens.
  Scene scene = frontScene();
  addMesh(scene, makeTriangles({{-1000, -1000, -2}, {1000, -1000, -2}, {0, 1000, -2}}, {}, {}),
          addMaterial(scene, vec3(1.0f)), "huge");
  for (const bool sidesOn : {true, false}) {
    RenderSettings settings = scene.settings;
    settings.clip.left = settings.clip.right = settings.clip.top = settings.clip.bottom = sidesOn;
    const Both b = renderBoth(scene, settings);
    const std::string what = sidesOn ? "side planes on" : "guard band";
    EXPECT_EQ(coveredCount(b.cpu), static_cast<std::size_t>(kSide * kSide)) << what;
    EXPECT_EQ(coveredCount(b.gl), static_cast<std::size_t>(kSide * kSide)) << what;
    // Depth at view distance 2: z_ndc = (f + n - 2 f n / 2) / (f - n)... = ((f + n) 2 - 2 f n) / (2 (f - n)).
    const double n = scene.camera.near, f = scene.camera.far;
    const double expected = 0.5 * ((f + n) * 2.0 - 2.0 * f * n) / (2.0 * (f - n)) + 0.5;
    for (float d : b.cpu.depth) ASSERT_NEAR(d, expected, 1e-6) << what;
    expectTargets(b, what);
  }
}

// ---- near = 1e-4, far = 1e5: z-fighting shown, not hidden ----

// Two triangles of the plane z = zCentre + 0.5 y (tilted towards the camera at the top),
// covering the whole view of the front camera: view rays meet it at y in [-200, 67].
Mesh slopeZ(float zCentre) {
  constexpr float kSlope = 0.5f, kHalfWidth = 250.0f, kBottom = -250.0f, kTop = 150.0f;
  auto at = [&](float x, float y) { return vec3(x, y, zCentre + kSlope * y); };
  return makeTriangles({at(-kHalfWidth, kBottom), at(kHalfWidth, kBottom), at(kHalfWidth, kTop),
                        at(-kHalfWidth, kBottom), at(kHalfWidth, kTop), at(-kHalfWidth, kTop)},
                       {}, {});
}

// Writes a top-first mask image: white where `fights` is set.
void saveMask(const std::string& path, const std::vector<bool>& fights, int side) {
  Image image = makeImage(side, side, 0x000000FFu);
  for (int y = 0; y < side; ++y) {
    for (int x = 0; x < side; ++x) {
      if (fights[static_cast<std::size_t>(y) * side + x]) {
        std::uint8_t* p = image.pixel(x, y);
        p[0] = p[1] = p[2] = 255;
      }
    }
  }
  savePng(path, image);
}

TEST(Stability, ZFightingAtDistance100WithNear1e4IsReportedPixelByPixel) {
  // Green drawn first, red second, both sloping planes covering the whole view, red 0.5 nearer
  // along the view axis (100 away at the centre). In exact arithmetic red is nearer everywhere.
  // Window depth is about 1 - near / d: at d = 100 the two differ by near (1/100 - 1/100.5) =
  // 5e-9, below one float step at 1 (6e-8) and far below 24-bit steps (6e-8 as well): where
  // they round to the same value GL_LESS keeps the first (green). The slope makes the depth
  // vary across the image, so rounding boundaries fall between the two on some pixels only.
  // Pixels where green shows "fight"; the test reports them instead of hiding them.
  auto scene = [](float near) {
    Scene s = frontScene(near, 1e5f);
    addMesh(s, slopeZ(-100.5f), addMaterial(s, vec3(0, 1, 0)), "green, 100.5 away");
    addMesh(s, slopeZ(-100.0f), addMaterial(s, vec3(1, 0, 0)), "red, 100 away");
    return s;
  };
  auto fightMask = [](const RenderOutput& out) {
    std::vector<bool> fights(static_cast<std::size_t>(out.width) * out.height);
    for (std::size_t i = 0; i < fights.size(); ++i) fights[i] = out.rgba[i * 4 + 1] > out.rgba[i * 4 + 0];
    return fights;
  };
  auto countOf = [](const std::vector<bool>& v) { return static_cast<std::size_t>(std::count(v.begin(), v.end(), true)); };

  const Scene tiny = scene(1e-4f);
  const Both b = renderBoth(tiny, tiny.settings);
  const std::vector<bool> cpuFights = fightMask(b.cpu), glFights = fightMask(b.gl);
  std::filesystem::create_directories(kOut);
  saveMask(kOut + "/zfight_near1e-4_cpu.png", cpuFights, kSide);
  saveMask(kOut + "/zfight_near1e-4_gl.png", glFights, kSide);
  std::size_t both = 0;
  for (std::size_t i = 0; i < cpuFights.size(); ++i) both += cpuFights[i] && glFights[i] ? 1 : 0;
  std::cout << "z-fighting, near 1e-4, far 1e5, surfaces at 100 and 100.5: cpu " << countOf(cpuFights) << " of "
            << kSide * kSide << " pixels fight, gl " << countOf(glFights) << ", both " << both << "; masks in " << kOut
            << "/zfight_near1e-4_{cpu,gl}.png\n";
  RecordProperty("zfight_cpu_pixels", static_cast<int>(countOf(cpuFights)));
  RecordProperty("zfight_gl_pixels", static_cast<int>(countOf(glFights)));
  EXPECT_GT(countOf(cpuFights), 0u) << "float depth cannot separate 5e-9: the CPU must show fighting";
  EXPECT_GT(countOf(glFights), 0u) << "24-bit depth cannot separate 5e-9: GL must show fighting";

  // Depth is llvmpipe's (its float plane, rounded to 24 bits), so the same pixels fight.
  EXPECT_EQ(cpuFights, glFights);

  // Every CPU fight is a tie or the float plane's rounding, not a bug: there the depth the red
  // plane alone gets is not below the green plane's.
  Scene redOnly = tiny;
  redOnly.nodes.erase(redOnly.nodes.begin());
  Scene greenOnly = tiny;
  greenOnly.nodes.pop_back();
  const RenderOutput red = makeCpuRenderer()->render(redOnly, redOnly.settings, kSide, kSide);
  const RenderOutput green = makeCpuRenderer()->render(greenOnly, greenOnly.settings, kSide, kSide);
  for (std::size_t i = 0; i < cpuFights.size(); ++i) {
    if (cpuFights[i]) {
      ASSERT_GE(red.depth[i], green.depth[i]) << "pixel " << i;
    } else {
      ASSERT_LT(red.depth[i], green.depth[i]) << "pixel " << i;
    }
  }

  // The double-precision reference separates them everywhere: red wins on every pixel.
  const RenderOutput reference = makeReferenceRenderer({1, 1})->render(tiny, tiny.settings, kSide, kSide);
  EXPECT_EQ(countOf(fightMask(reference)), 0u);

  // With near = 0.1 the depths differ by at least 0.1 * 0.5 / 200^2 = 1.25e-6 (20 float steps,
  // 20 24-bit steps): no fighting.
  const Scene sane = scene(0.1f);
  const Both s = renderBoth(sane, sane.settings);
  EXPECT_EQ(countOf(fightMask(s.cpu)), 0u);
  EXPECT_EQ(countOf(fightMask(s.gl)), 0u);
}

// ---- texture coordinates, poles, tangents, scales ----

Scene litScene() {
  Scene scene;
  scene.camera.position = vec3(0.0f, 0.4f, 2.6f);
  scene.camera.target = vec3(0.0f);
  scene.camera.fovDeg = 50.0f;
  scene.output.background = vec4(0.05f, 0.05f, 0.05f, 1.0f);
  Light light;
  light.posWorld = vec3(1.5f, 2.0f, 2.5f);
  scene.lights.push_back(light);
  return scene;
}

int addMappedMaterial(Scene& scene) {
  Material m;
  m.ks = vec3(0.4f);
  m.diffuseMap = texture("bricks_diffuse.png");
  m.normalMap = texture("bricks_normal.png");
  scene.materials.push_back(m);
  return static_cast<int>(scene.materials.size()) - 1;
}

// Every tangent finite, unit length, perpendicular to its normal, handedness +-1.
void expectUsableTangents(const Mesh& mesh, const std::string& what) {
  for (const Vertex& v : mesh.vertices) {
    const vec3 t(v.tangentModel);
    ASSERT_TRUE(std::isfinite(t.x) && std::isfinite(t.y) && std::isfinite(t.z)) << what;
    ASSERT_NEAR(glm::length(t), 1.0f, 1e-5f) << what;
    ASSERT_NEAR(glm::dot(t, glm::normalize(v.nModel)), 0.0f, 1e-5f) << what;
    ASSERT_TRUE(v.tangentModel.w == 1.0f || v.tangentModel.w == -1.0f) << what;
  }
}

TEST(Stability, DegenerateCollinearAndMirroredUvsGiveUsableTangentsAndAgree) {
  const std::vector<vec3> quad{{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, -1, 0}, {1, 1, 0}, {-1, 1, 0}};
  struct UvCase {
    const char* name;
    std::vector<vec2> uvs;
    float handedness;  // expected tangent w, 0 when either is acceptable (fallback)
  };
  const UvCase cases[] = {
      {"degenerate (one uv)", std::vector<vec2>(6, vec2(0.3f, 0.7f)), 0.0f},
      {"collinear", {{0, 0}, {0.5f, 0.5f}, {1, 1}, {0, 0}, {1, 1}, {0.25f, 0.25f}}, 0.0f},
      {"regular", {{0, 0}, {1, 0}, {1, 1}, {0, 0}, {1, 1}, {0, 1}}, 1.0f},
      {"mirrored in u", {{1, 0}, {0, 0}, {0, 1}, {1, 0}, {0, 1}, {1, 1}}, -1.0f},
  };
  for (const UvCase& c : cases) {
    Scene scene = litScene();
    Mesh mesh = makeTriangles(quad, c.uvs, {});
    expectUsableTangents(mesh, c.name);
    if (c.handedness != 0.0f) {
      for (const Vertex& v : mesh.vertices) ASSERT_EQ(v.tangentModel.w, c.handedness) << c.name;
    }
    addMesh(scene, std::move(mesh), addMappedMaterial(scene), c.name);
    for (View view : {View::Shaded, View::Tangent, View::Bitangent, View::MappedNormal}) {
      RenderSettings settings = scene.settings;
      settings.view = view;
      for (LightingSpace space : {LightingSpace::World, LightingSpace::Tangent}) {
        settings.lightingSpace = space;
        const Both b = renderBoth(scene, settings);
        EXPECT_GT(coveredCount(b.cpu), 500u) << c.name;
        expectTargets(b, std::string(c.name) + ", view " + std::string(toString(view)) + ", " +
                             std::string(toString(space)));
      }
    }
  }
}

TEST(Stability, SpherePolesAreFiniteAndAgreeSeenFromAbove) {
  const Scene scene = loadSceneFile(kAssets + "/scenes/stability_poles.json");
  const Mesh& sphere = scene.meshes.at(0);
  const MeshDesc& desc = scene.meshDescs.at(0);
  // The pole triangles of the first and last stack have zero area and are left out.
  EXPECT_EQ(sphere.triangleCount(), static_cast<std::size_t>(desc.slices) * (2 * desc.stacks - 2));
  expectUsableTangents(sphere, "sphere");
  for (View view : {View::Shaded, View::Normal, View::Tangent, View::Bitangent, View::MappedNormal, View::Uv}) {
    RenderSettings settings = scene.settings;
    settings.view = view;
    const Both b = renderBoth(scene, settings, 96, 96);
    EXPECT_GT(coveredCount(b.cpu), 2000u);
    expectTargets(b, "poles, view " + std::string(toString(view)));
  }
}

TEST(Stability, TangentParallelToNormalFallsBackToTheSameFrameOnBothBackends) {
  Scene scene = litScene();
  Mesh mesh = makeTriangles({{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, -1, 0}, {1, 1, 0}, {-1, 1, 0}},
                            {{0, 0}, {1, 0}, {1, 1}, {0, 0}, {1, 1}, {0, 1}}, {});
  for (Vertex& v : mesh.vertices) v.tangentModel = vec4(v.nModel, 1.0f);  // T = N: B = N x T = 0
  addMesh(scene, std::move(mesh), addMappedMaterial(scene), "t parallel n");
  RenderSettings settings = scene.settings;
  settings.view = View::Bitangent;
  const Both b = renderBoth(scene, settings);
  // B = 0 everywhere; safeNormalize falls back to (0, 0, 1), shown as (0.5, 0.5, 1).
  std::size_t checked = 0;
  for (const RenderOutput* out : {&b.cpu, &b.gl}) {
    for (std::size_t i = 0; i + 3 < out->rgba.size(); i += 4) {
      if (!coveredAt(*out, i / 4)) continue;
      ASSERT_NEAR(out->rgba[i + 0], 128, 1);
      ASSERT_NEAR(out->rgba[i + 1], 128, 1);
      ASSERT_EQ(out->rgba[i + 2], 255);
      ++checked;
    }
  }
  EXPECT_GT(checked, 1000u);
  for (View view : {View::Shaded, View::MappedNormal, View::LightTangent}) {
    settings.view = view;
    for (LightingSpace space : {LightingSpace::World, LightingSpace::Tangent}) {
      settings.lightingSpace = space;
      expectTargets(renderBoth(scene, settings), "T parallel to N, view " + std::string(toString(view)));
    }
  }
}

TEST(Stability, NonUniformAndMirroringScalesAgreeAndFlipTheBitangent) {
  const Scene scene = loadSceneFile(kAssets + "/scenes/stability_scales.json");
  // The mirrored node's bitangent is the unmirrored one reflected: the vertex stage flips the
  // handedness sign with det < 0.
  const std::vector<DrawItem> items = flattenScene(scene);
  bool sawMirror = false;
  for (const DrawItem& item : items) {
    const VertexUniforms u = makeVertexUniforms(item.worldFromModel, mat4(1.0f), scene, scene.settings);
    const bool mirrored = glm::determinant(mat3(item.worldFromModel)) < 0.0f;
    EXPECT_EQ(u.mirrorSign, mirrored ? -1.0f : 1.0f) << item.nodeName;
    sawMirror = sawMirror || mirrored;
    const Vertex& v = item.mesh->vertices.front();
    const ClipVertex out = runVertexStage(v, u);
    const vec3 expected = (mirrored ? -1.0f : 1.0f) * v.tangentModel.w * glm::cross(out.nWorld, out.tWorld);
    EXPECT_NEAR(glm::length(out.bWorld - expected), 0.0f, 1e-5f) << item.nodeName;
  }
  EXPECT_TRUE(sawMirror);
  for (TangentTransform transform : {TangentTransform::Model, TangentTransform::InverseTranspose}) {
    for (View view : {View::Shaded, View::Normal, View::Tangent, View::Bitangent}) {
      RenderSettings settings = scene.settings;
      settings.tangentTransform = transform;
      settings.view = view;
      expectTargets(renderBoth(scene, settings, 96, 72),
                    "scales, " + std::string(toString(transform)) + ", view " + std::string(toString(view)));
    }
  }
}

// ---- lighting edge cases ----

TEST(Stability, LightExactlyOnTheSurfaceStaysFinite) {
  Scene scene = litScene();
  scene.camera.position = vec3(0.0f, 2.0f, 1.0f);
  scene.lights[0].posWorld = vec3(0.0f);  // on the plane y = 0, at its centre
  scene.lights[0].attenuation = vec3(1.0f, 0.0f, 0.0f);
  Material m;
  m.ks = vec3(0.5f);
  scene.materials.push_back(m);
  MeshDesc desc;
  desc.type = MeshType::Plane;
  desc.planeSize = vec2(3.0f);
  scene.meshDescs.push_back(desc);
  scene.meshes.push_back(buildMesh(desc));
  Node node;
  node.meshIndex = 0;
  node.materialIndex = 0;
  scene.nodes.push_back(node);
  for (LightingSpace space : {LightingSpace::World, LightingSpace::Tangent}) {
    RenderSettings settings = scene.settings;
    settings.lightingSpace = space;
    const Both b = renderBoth(scene, settings);
    EXPECT_GT(coveredCount(b.cpu), 1000u);
    expectTargets(b, "light on the surface, " + std::string(toString(space)));
  }
}

TEST(Stability, ShininessZeroAddsKsEverywhereLitAndHugeShininessAddsNothing) {
  // A plane facing the camera, the light at the eye: N.L > 0 on every pixel, R.V = cos(2 theta).
  auto scene = [](float shininess, float ks) {
    Scene s = frontScene();
    s.settings.view = View::Shaded;
    s.ambient = vec3(0.0f);
    Light light;
    light.posWorld = vec3(0.0f);
    light.attenuation = vec3(1.0f, 0.0f, 0.0f);
    s.lights.push_back(light);
    Material m;
    m.kd = vec3(0.5f);
    m.ks = vec3(ks);
    m.shininess = shininess;
    s.materials.push_back(m);
    addMesh(s, quadZ(10.0f, -2.0f), 0, "plane");
    return s;
  };
  constexpr float kKs = 0.25f;  // adds 0.25 * 255 = 63.75 levels where the term is 1
  const Scene diffuseOnly = scene(32.0f, 0.0f);
  const Both base = renderBoth(diffuseOnly, diffuseOnly.settings);
  const Scene zero = scene(0.0f, kKs);
  const Both z = renderBoth(zero, zero.settings);
  const Scene huge = scene(1e6f, kKs);
  const Both h = renderBoth(huge, huge.settings);
  for (const auto& [backend, basePixels, zeroPixels, hugePixels] :
       {std::tuple{"cpu", &base.cpu, &z.cpu, &h.cpu}, std::tuple{"gl", &base.gl, &z.gl, &h.gl}}) {
    for (std::size_t i = 0; i < basePixels->rgba.size(); i += 4) {
      // Shininess 0: (R.V)^0 = 1 wherever N.L > 0, so every pixel gains ks = 63.75 levels.
      const int gain = zeroPixels->rgba[i] - basePixels->rgba[i];
      ASSERT_TRUE(gain == 63 || gain == 64) << backend << " pixel " << i / 4 << " gained " << gain;
      // Shininess 1e6: (R.V)^1e6 underflows to 0 away from the exact mirror direction; no pixel
      // centre sits on it, so nothing is added (GL may round one level differently).
      ASSERT_NEAR(hugePixels->rgba[i], basePixels->rgba[i], std::string(backend) == "cpu" ? 0 : 1) << backend;
    }
  }
  expectTargets(z, "shininess 0");
  expectTargets(h, "shininess 1e6");
}

// ---- bad input vertices ----

TEST(Stability, ZeroAreaAndNanVerticesAreDroppedAndNeverReachAPixel) {
  Scene scene = frontScene();
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const float inf = std::numeric_limits<float>::infinity();
  Mesh mesh;
  auto vertex = [](vec3 p) {
    Vertex v;
    v.posModel = p;
    v.nModel = vec3(0, 0, 1);
    return v;
  };
  // 0-2: a good triangle on the left half; 3-5: zero area (two equal vertices); 6-8: a NaN
  // vertex; 9-11: an infinite vertex.
  for (const vec3& p : std::vector<vec3>{{-1.5f, -1.0f, -2}, {-0.2f, -1.0f, -2}, {-1.5f, 1.0f, -2},
                                         {0.5f, 0.5f, -2},   {0.5f, 0.5f, -2},   {1.5f, 1.0f, -2},
                                         {0.2f, -1.0f, -2},  {nan, 0.0f, -2},    {1.5f, 1.0f, -2},
                                         {0.2f, 1.0f, -2},   {1.5f, -1.0f, -2},  {inf, 1.0f, -2}}) {
    mesh.vertices.push_back(vertex(p));
  }
  for (std::uint32_t i = 0; i < 12; ++i) mesh.indices.push_back(i);
  addMesh(scene, std::move(mesh), addMaterial(scene, vec3(1.0f)), "bad vertices");

  Scene goodOnly = frontScene();
  addMesh(goodOnly, makeTriangles({{-1.5f, -1.0f, -2}, {-0.2f, -1.0f, -2}, {-1.5f, 1.0f, -2}}, {}, {}),
          addMaterial(goodOnly, vec3(1.0f)), "good");

  const Both b = renderBoth(scene, scene.settings);
  const Both good = renderBoth(goodOnly, goodOnly.settings);
  // CPU: the NaN and Inf triangles leave the clipper empty (counted as clipped), the zero-area
  // one is rejected by setup (counted as culled), the good one is drawn as if alone.
  EXPECT_EQ(b.cpu.stats.trianglesIn, 4u);
  EXPECT_EQ(b.cpu.stats.trianglesClipped, 2u);
  EXPECT_EQ(b.cpu.stats.trianglesCulled, 1u);
  EXPECT_EQ(b.cpu.stats.trianglesProduced, 1u);
  EXPECT_EQ(b.cpu.rgba, good.cpu.rgba);
  EXPECT_EQ(b.cpu.depth, good.cpu.depth);
  // GL: the same pixels as the good triangle alone, and no NaN anywhere.
  EXPECT_EQ(coveredCount(b.gl), coveredCount(good.gl));
  EXPECT_EQ(compare(b.gl, good.gl).coverageMismatch, 0u);
  expectFiniteDepth(b.cpu, "bad vertices (cpu)");
  expectFiniteDepth(b.gl, "bad vertices (gl)");
  expectTargets(good, "good triangle");
}

// ---- the stability scenes of assets/scenes/ ----

TEST(Stability, StabilityScenesAreFiniteOnBothBackendsInEveryView) {
  std::vector<std::filesystem::path> scenes;
  for (const auto& entry : std::filesystem::directory_iterator(kAssets + "/scenes")) {
    if (entry.path().filename().string().rfind("stability_", 0) == 0) scenes.push_back(entry.path());
  }
  // The shipped stability scenes (docs/stability.md): finding fewer means the loop tested less.
  ASSERT_GE(scenes.size(), 3u) << "fewer than the three stability_*.json (poles, scales, w_zero) under " << kAssets << "/scenes";
  std::sort(scenes.begin(), scenes.end());
  for (const std::filesystem::path& path : scenes) {
    const std::string name = path.filename().string();
    const Scene scene = loadSceneFile(path.string());
    for (View view : kAllViews) {
      RenderSettings settings = scene.settings;
      settings.view = view;
      const Both b = renderBoth(scene, settings, 80, 60);
      expectTargets(b, name + ", view " + std::string(toString(view)));
    }
  }
}

}  // namespace
}  // namespace twr
