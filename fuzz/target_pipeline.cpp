// Target "pipeline": random scenes through the CPU renderer, and raw clip-space triangles
// through the clip, setup, raster and interpolation stages.
//
// Every value is read in its own statement or braced list: the order of function arguments
// is unspecified, and gcc (replay) and clang (libFuzzer) must decode an input alike.
//
// Scene values stay inside what the scene loader accepts (finite positions, non-negative
// colours within kMaxColourValue, non-zero scales, a valid camera), because that is the
// renderer's contract; within it they are as hostile as possible. The clip-space half has
// no such limit: the clipper must cope with any finite position, w <= 0 included.
#include "fuzz/support.h"
#include "fuzz/targets.h"

#include "scene/primitives.h"
#include "scene/projection_checks.h"
#include "scene/scene_file.h"
#include "softrender/clip.h"
#include "softrender/cpu_renderer.h"
#include "softrender/framebuffer.h"
#include "softrender/interpolate.h"
#include "softrender/pixel_trace.h"
#include "softrender/raster.h"
#include "softrender/setup.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <cstdio>
#include <memory>

namespace twr::fuzz {

namespace {

constexpr int kMaxRenderSide = 40;       // pixels, inclusive: rendered images stay cheap
constexpr int kMaxTriangles = 16;        // per random mesh, inclusive
constexpr int kMaxNodes = 3;             // instances of the mesh, inclusive
constexpr int kMaxTextureSide = 4;       // texels, inclusive, for the random maps
constexpr int kMaxTracedPixels = 3;      // pixel traces per input, inclusive
constexpr int kMaxStageViewportSide = kMaxImageSide;  // the clip-space half has no framebuffer

ClipSwitches switchesFrom(std::uint8_t bits) {
  ClipSwitches s;
  s.left = (bits & 1u) != 0;
  s.right = (bits & 2u) != 0;
  s.bottom = (bits & 4u) != 0;
  s.top = (bits & 8u) != 0;
  s.near = (bits & 16u) != 0;
  s.far = (bits & 32u) != 0;
  return s;
}

// A colour the loader accepts: each component in [0, kMaxColourValue].
vec3 loaderColour(ByteReader& r) {
  vec3 c;
  for (int i = 0; i < 3; ++i) c[i] = std::min(r.nonNegativeFloat(), kMaxColourValue);
  return c;
}

std::shared_ptr<const Texture> randomTexture(ByteReader& r) {
  if (!r.flag()) return nullptr;
  const int width = r.intIn(1, kMaxTextureSide);
  const int height = r.intIn(1, kMaxTextureSide);
  Image image = makeImage(width, height);
  for (std::uint8_t& b : image.rgba) b = r.byte();
  return std::make_shared<const Texture>(textureFromImage(image, "fuzz texture"));
}

RenderSettings randomSettings(ByteReader& r) {
  RenderSettings s;
  s.cull = static_cast<CullMode>(r.intIn(0, 2));
  s.frontFace = static_cast<FrontFace>(r.intIn(0, 1));
  s.clip = switchesFrom(r.byte());
  const int planes = r.intIn(0, kMaxUserClipPlanes);
  for (int i = 0; i < planes; ++i) {
    vec4 plane{r.hostileFloat(), r.hostileFloat(), r.hostileFloat(), r.hostileFloat()};
    if (vec3(plane) == vec3(0.0f)) plane.z = 1.0f;  // the loader refuses a zero normal
    s.userClipPlanes.push_back(plane);
  }
  // Settings GL cannot draw are refused by both renderers (clipSlotProblem); keep to those
  // they draw, as the scene loader does.
  while (!clipSlotProblem(s).empty()) s.userClipPlanes.pop_back();
  s.view = kAllViews[static_cast<std::size_t>(r.intIn(0, static_cast<int>(std::size(kAllViews)) - 1))];
  s.lightingSpace = static_cast<LightingSpace>(r.intIn(0, 1));
  s.tangentTransform = static_cast<TangentTransform>(r.intIn(0, 1));
  s.textureFilter = static_cast<TextureFilter>(r.intIn(0, 1));
  s.tbnLines.enabled = r.flag();
  const float length = r.nonNegativeFloat();
  s.tbnLines.length = length > 0.0f ? length : 0.1f;  // the loader wants > 0
  s.pipeline = static_cast<Pipeline>(r.intIn(0, 1));
  s.gbufferPosition = static_cast<GBufferPosition>(r.intIn(0, 1));
  // Reflections as the loader admits them: every march, few steps and indirect samples (the
  // fuzzer's frames are tiny), a step and thickness > 0 from hostile values.
  s.ssr.enabled = r.flag();
  s.ssr.march = static_cast<SsrMarch>(r.intIn(0, 3));
  s.ssr.indirectSamples = r.intIn(0, 2);
  s.ssr.sampleDistribution = static_cast<SampleDistribution>(r.intIn(0, 1));
  s.ssr.maxSteps = r.intIn(1, 16);
  const float step = r.nonNegativeFloat(), thickness = r.nonNegativeFloat();
  s.ssr.step = step > 0.0f ? step : 0.05f;
  s.ssr.thickness = thickness > 0.0f ? thickness : 0.1f;
  s.ssr.reflectStrength = static_cast<float>(r.intIn(0, 4));
  return s;
}

Camera randomCamera(ByteReader& r) {
  Camera camera;
  if (!r.flag()) return camera;  // half the inputs keep the default view so geometry is seen
  camera.position = r.flag() ? r.hostileVec3() : r.tameVec3();
  camera.target = r.flag() ? r.hostileVec3() : r.tameVec3();
  camera.fovDeg = r.flag() ? r.hostileFloat() : static_cast<float>(r.intIn(1, 179));
  camera.near = r.flag() ? r.hostileFloat() : 0.1f;
  camera.far = r.flag() ? r.hostileFloat() : 100.0f;
  return camera;
}

// Triangles near the view (tame) or anywhere (hostile), per triangle.
Mesh randomMesh(ByteReader& r) {
  const int triangles = r.intIn(1, kMaxTriangles);
  std::vector<vec3> positions;
  for (int t = 0; t < triangles; ++t) {
    const bool hostile = r.flag();
    for (int k = 0; k < 3; ++k) {
      positions.push_back(hostile ? r.hostileVec3() : r.tameVec3());
    }
  }
  std::vector<vec2> uvs;
  if (r.flag()) {
    for (std::size_t i = 0; i < positions.size(); ++i) uvs.push_back(vec2{r.hostileFloat(), r.hostileFloat()});
  }
  std::vector<vec3> normals;
  if (r.flag()) {
    for (std::size_t i = 0; i < positions.size(); ++i) {
      vec3 n = r.hostileVec3();
      if (!(glm::dot(n, n) > kMinLengthSquared)) n = vec3(0.0f, 0.0f, 1.0f);  // the loader refuses these
      normals.push_back(n);
    }
  }
  return makeTriangles(positions, uvs, normals);
}

Node randomNode(ByteReader& r, const std::string& name) {
  Node node;
  node.name = name;
  node.meshIndex = 0;
  node.materialIndex = r.flag() ? 0 : -1;
  if (r.flag()) node.translate = r.hostileVec3();
  if (r.flag()) node.rotateDeg = r.hostileVec3();
  if (r.flag()) {
    node.scale = r.hostileVec3();
    for (int i = 0; i < 3; ++i) {
      if (node.scale[i] == 0.0f) node.scale[i] = 1.0f;  // the loader refuses a zero scale
    }
  }
  return node;
}

Scene randomScene(ByteReader& r) {
  Scene scene;
  scene.camera = randomCamera(r);
  scene.ambient = loaderColour(r);
  scene.settings = randomSettings(r);
  const int lights = r.intIn(0, kMaxLights);
  for (int i = 0; i < lights; ++i) {
    Light light;
    light.posWorld = r.flag() ? r.hostileVec3() : r.tameVec3();
    light.diffuse = loaderColour(r);
    light.specular = loaderColour(r);
    light.attenuation = vec3{r.nonNegativeFloat(), r.nonNegativeFloat(), r.nonNegativeFloat()};
    if (light.attenuation == vec3(0.0f)) light.attenuation.x = 1.0f;  // the loader refuses all zero
    if (r.flag()) {  // directional, unit length as the loader leaves it
      const glm::dvec3 d(r.tameVec3());
      if (glm::length(d) > 0.0) {
        light.type = LightType::Directional;
        light.directionWorld = vec3(d / glm::length(d));
      }
    }
    if (light.type == LightType::Point && r.flag()) {  // a spot cone, within the loader's bounds
      const glm::dvec3 d(r.tameVec3());
      SpotCone spot;
      if (glm::length(d) > 0.0) spot.directionWorld = vec3(d / glm::length(d));
      spot.outerDeg = static_cast<float>(r.intIn(1, static_cast<int>(kMaxSpotOuterDeg) - 1));
      spot.innerDeg = static_cast<float>(r.intIn(0, static_cast<int>(spot.outerDeg)));
      light.spot = spot;
    }
    if (r.flag() && std::count_if(scene.lights.begin(), scene.lights.end(),
                                  [](const Light& l) { return l.shadow.has_value(); }) < kMaxShadowedLights) {
      ShadowDesc shadow;  // small maps: the pass's code is the same at any size
      shadow.size = r.intIn(kMinShadowMapSize, 2 * kMinShadowMapSize);
      shadow.bias = vec2(r.nonNegativeFloat(), r.nonNegativeFloat());
      shadow.pcf = 1 + 2 * r.intIn(0, 2);
      shadow.extent = r.flag() ? r.nonNegativeFloat() : 0.0f;
      light.shadow = shadow;
    }
    scene.lights.push_back(light);
  }
  Material material;
  material.name = "fuzz";
  material.ka = loaderColour(r);
  material.kd = loaderColour(r);
  material.ks = loaderColour(r);
  material.shininess = r.nonNegativeFloat();
  material.ssrReflect = static_cast<float>(r.intIn(0, 4)) / 4.0f;
  material.diffuseMap = randomTexture(r);
  material.normalMap = randomTexture(r);
  material.specularMap = randomTexture(r);
  scene.materials.push_back(std::move(material));
  scene.meshes.push_back(randomMesh(r));
  scene.meshDescs.emplace_back();
  const int nodes = r.intIn(1, kMaxNodes);
  for (int i = 0; i < nodes; ++i) {
    Node node = randomNode(r, "node" + std::to_string(i));
    if (i > 0 && r.flag()) {
      scene.nodes.back().children.push_back(std::move(node));  // nested: transforms compose
    } else {
      scene.nodes.push_back(std::move(node));
    }
  }
  return scene;
}

void checkTrace(const PixelTrace& trace, const RenderOutput& output) {
  const std::string where = "trace of pixel (" + std::to_string(trace.x) + ", " + std::to_string(trace.yTop) + ")";
  const TriangleVisit* last = nullptr;
  for (const TriangleVisit& visit : trace.visits) {
    if (visit.outcome != TraceOutcome::Shaded) continue;
    require(isFinite(visit.terms.colour), where + ": shaded colour is not finite (triangle " +
                                              std::to_string(visit.triangleId) + ")");
    require(std::isfinite(visit.weights.depth) && visit.weights.depth >= 0.0f && visit.weights.depth <= 1.0f,
            where + ": fragment depth outside [0, 1]");
    for (int i = 0; i < 3; ++i) {
      require(std::isfinite(visit.weights.screen[static_cast<std::size_t>(i)]) &&
                  std::isfinite(visit.weights.perspective[static_cast<std::size_t>(i)]),
              where + ": non-finite barycentric weight");
    }
    last = &visit;
  }
  const std::size_t pixel = static_cast<std::size_t>(trace.yTop) * static_cast<std::size_t>(output.width) +
                            static_cast<std::size_t>(trace.x);
  if (last && !trace.debugLine) {
    // The trace promises that the last shaded visit is what the renderer wrote.
    for (int c = 0; c < 3; ++c) {
      require(unitToByte(last->terms.colour[c]) == output.rgba[4 * pixel + static_cast<std::size_t>(c)],
              where + ": the last shaded visit's colour is not the rendered one");
    }
    require(last->weights.depth == output.depth[pixel], where + ": the last shaded visit's depth is not the rendered one");
  }
}

void renderRandomScene(ByteReader& r) {
  const int width = r.intIn(1, kMaxRenderSide);
  const int height = r.intIn(1, kMaxRenderSide);
  CpuOptions options;
  options.threads = r.intIn(1, 3);
  Scene scene = randomScene(r);
  if (!projectionProblem(scene, width, height).empty()) {  // includes validateCamera
    try {
      makeCpuRenderer(options)->render(scene, scene.settings, width, height);
    } catch (const InputError&) {
      return;  // refused, as it should be
    }
    throw InvariantViolation("the renderer drew a scene projectionProblem refuses");
  }
  const std::size_t triangles = countTriangles(scene);
  const RenderOutput output = makeCpuRenderer(options)->render(scene, scene.settings, width, height);
  checkRenderOutput(output, width, height, triangles, clearByte(scene.output.background.a), "render");
  require(output.stats.trianglesIn == triangles, "stats.trianglesIn differs from the scene's triangle count");
  const int traces = r.intIn(0, kMaxTracedPixels);
  for (int i = 0; i < traces; ++i) {
    const int x = r.intIn(0, width - 1);
    const int y = r.intIn(0, height - 1);
    checkTrace(tracePixel(scene, scene.settings, width, height, x, y), output);
  }
}

// ---- the clip-space half ----

// (x, y, z, w) with every digit a float holds (std::to_string prints 1e-40 as 0.000000).
std::string exact(const vec4& p) {
  char text[160];
  std::snprintf(text, sizeof text, "(%.9g, %.9g, %.9g, %.9g)", static_cast<double>(p.x), static_cast<double>(p.y),
                static_cast<double>(p.z), static_cast<double>(p.w));
  return text;
}

float clipW(ByteReader& r) {
  // w near 0 from both sides, at the clipper's epsilon, and huge, besides hostileFloat().
  static constexpr std::array<float, 8> kW{0.0f, 1e-38f, -1e-38f, kMinClipW, kMinClipW * 0.999f, -kMinClipW,
                                           1e-12f, 3e38f};
  return r.flag() ? kW[r.byte() % kW.size()] : r.hostileFloat();
}

ClipVertex randomClipVertex(ByteReader& r, int userPlanes) {
  ClipVertex v;
  v.posClip = vec4{r.hostileFloat(), r.hostileFloat(), r.hostileFloat(), clipW(r)};
  v.uv = vec2{r.tameFloat(), r.tameFloat()};
  v.nWorld = r.tameVec3();
  for (int j = 0; j < userPlanes; ++j) v.clipDistance[static_cast<std::size_t>(j)] = r.hostileFloat();
  return v;
}

void checkWeights(const PixelWeights& w, const std::string& where) {
  for (std::size_t i = 0; i < 3; ++i) {
    require(std::isfinite(w.screen[i]) && std::isfinite(w.perspective[i]), where + ": non-finite weight");
  }
  require(std::isfinite(w.depth) && w.depth >= 0.0f && w.depth <= 1.0f,
          where + ": depth " + std::to_string(w.depth) + " outside [0, 1]");
}

void rasterizeFanTriangle(const std::array<WindowVertex, 3>& window, const ClipVertex& v0, const ClipVertex& v1,
                          const ClipVertex& v2, CullMode cull, FrontFace frontFace, const Viewport& viewport) {
  TriangleSetup setup;
  if (setupTriangle(window, cull, frontFace, viewport, setup) != SetupResult::Ready) return;
  require(setup.doubleAreaFixed > 0, "a ready triangle without positive area");
  if (setup.x0 > setup.x1 || setup.y0 > setup.y1) return;
  require(setup.x0 >= 0 && setup.x1 < viewport.width && setup.y0 >= 0 && setup.y1 < viewport.height,
          "bounding box outside the viewport");
  const InterpolationSetup interpolation = makeInterpolationSetup(window, {v0.uv, v1.uv, v2.uv}, setup);
  const VaryingPlanes varyings = makeVaryingPlanes(window, v0, v1, v2, false, 0, setup);
  rasterizeTriangle(setup, 0, viewport.height, [&](int py, Span span) {
    const std::string where = "row " + std::to_string(py);
    require(py >= setup.y0 && py <= setup.y1, where + ": outside the bounding box");
    require(span.xBegin >= setup.x0 && span.xEnd <= setup.x1 + 1, where + ": span outside the bounding box");
    // The span is exact: its ends are covered, the pixels just outside are not.
    require(coversPixel(setup, span.xBegin, py) && coversPixel(setup, span.xEnd - 1, py), where + ": span end not covered");
    require(span.xBegin == setup.x0 || !coversPixel(setup, span.xBegin - 1, py), where + ": span starts late");
    require(span.xEnd == setup.x1 + 1 || !coversPixel(setup, span.xEnd, py), where + ": span ends early");
    for (int px : {span.xBegin, span.xEnd - 1}) {
      const PixelWeights weights = pixelWeights(interpolation, px, py);
      checkWeights(weights, where + ", pixel " + std::to_string(px));
      const Fragment fragment = interpolateFragment(varyings, px, py, weights.depth);
      require(isFinite(fragment.uv) && isFinite(fragment.nWorld), where + ": non-finite varying");
    }
  });
}

void clipRandomTriangle(ByteReader& r) {
  const Viewport viewport{r.flag() ? r.intIn(1, kMaxStageViewportSide) : r.intIn(1, 64),
                          r.flag() ? r.intIn(1, kMaxStageViewportSide) : r.intIn(1, 64)};
  const int userPlanes = r.intIn(0, kMaxUserClipPlanes);
  const ClipConfig config = makeClipConfig(switchesFrom(r.byte()), userPlanes, viewport.width, viewport.height);
  const CullMode cull = static_cast<CullMode>(r.intIn(0, 2));
  const FrontFace frontFace = static_cast<FrontFace>(r.intIn(0, 1));
  const ClipVertex a = randomClipVertex(r, userPlanes);
  const ClipVertex b = randomClipVertex(r, userPlanes);
  const ClipVertex c = randomClipVertex(r, userPlanes);

  ClipPolygon polygon, scratch;
  clipTriangle(a, b, c, config, polygon, scratch);
  require(polygon.count == 0 || (polygon.count >= 3 && polygon.count <= kMaxClipVertices),
          "clipped polygon has " + std::to_string(polygon.count) + " vertices");
  for (int i = 0; i < polygon.count; ++i) {
    const vec4& p = polygon.v[static_cast<std::size_t>(i)].posClip;
    require(isFinite(p), "clipped vertex " + std::to_string(i) + " is not finite");
    // w > 0, except that with the near plane on a vertex may sit on the frustum's apex (w = 0,
    // inside every plane by distance 0, or a cut vertex a rounding away from it, e.g. x = 1e-45):
    // the triangle is degenerate there and windowFromClip takes w under FLT_MIN as the apex
    // (clip.h). The window-position check below still applies.
    const bool apex = config.frustum.near && std::fabs(p.w) < std::numeric_limits<float>::min();
    require(p.w > 0.0f || apex, "clipped vertex " + std::to_string(i) + " " + exact(p) + " has w <= 0 (near plane " +
                                    (config.frustum.near ? "on" : "off") + ")");
  }
  for (int i = 1; i + 1 < polygon.count; ++i) {
    const ClipVertex& v0 = polygon.v[0];
    const ClipVertex& v1 = polygon.v[static_cast<std::size_t>(i)];
    const ClipVertex& v2 = polygon.v[static_cast<std::size_t>(i + 1)];
    const std::array<WindowVertex, 3> window{windowFromClip(v0, viewport), windowFromClip(v1, viewport),
                                             windowFromClip(v2, viewport)};
    for (std::size_t k = 0; k < window.size(); ++k) {
      const WindowVertex& w = window[k];
      const vec4 p = (k == 0 ? v0 : k == 1 ? v1 : v2).posClip;
      require(std::isfinite(w.x) && std::isfinite(w.y) && std::isfinite(w.z) && std::isfinite(w.invW),
              "window vertex (" + std::to_string(w.x) + ", " + std::to_string(w.y) + ", " + std::to_string(w.z) +
                  ", 1/w " + std::to_string(w.invW) + ") from clip (" + std::to_string(p.x) + ", " +
                  std::to_string(p.y) + ", " + std::to_string(p.z) + ", " + std::to_string(p.w) +
                  ") is not finite");
    }
    rasterizeFanTriangle(window, v0, v1, v2, cull, frontFace, viewport);
  }
}

}  // namespace

void fuzzPipeline(const std::uint8_t* data, std::size_t size) {
  ByteReader r(data, size);
  if (r.flag()) {
    renderRandomScene(r);
  } else {
    clipRandomTriangle(r);
  }
}

}  // namespace twr::fuzz
