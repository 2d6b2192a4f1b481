#include "softrender/pixel_trace.h"


#include "scene/environment_capture.h"
#include "scene/errors.h"
#include "scene/mip_level_view.h"
#include "scene/sky_view.h"
#include "softrender/cpu_renderer.h"
#include "softrender/draw_list.h"
#include "softrender/framebuffer.h"
#include "softrender/output_merge.h"
#include "softrender/raster.h"
#include "softrender/shadow_pass.h"
#include "softrender/sky-inl.h"
#include "softrender/vertex.h"

#include <cstdio>
#include <nlohmann/json.hpp>
#include <sstream>

namespace twr {

const char* toString(TraceOutcome outcome) {
  switch (outcome) {
    case TraceOutcome::Shaded: return "shaded";
    case TraceOutcome::FailedDepthTest: return "failed the depth test (GL_LESS)";
    case TraceOutcome::CulledBack: return "culled (back face)";
    case TraceOutcome::CulledFront: return "culled (front face)";
    case TraceOutcome::ClippedAway: return "clipped away at this pixel";
  }
  return "?";
}

namespace {

// Window positions of a fan triangle, as the renderer computes them.
std::array<WindowVertex, 3> windowTriangle(const ClipVertex& a, const ClipVertex& b, const ClipVertex& c,
                                           const Viewport& viewport) {
  return {windowFromClip(a, viewport), windowFromClip(b, viewport), windowFromClip(c, viewport)};
}

// The triangles of the mesh that share an edge with triangle t (two corners at equal model
// positions, so seams with split vertices count), the first one found per edge.
std::vector<EdgeNeighbour> edgeNeighboursOf(const Mesh& mesh, std::size_t t, const VertexUniforms& vertexUniforms,
                                            std::uint32_t firstTriangleId) {
  const auto positionOf = [&](std::size_t triangle, std::size_t k) -> const vec3& {
    return mesh.vertices[mesh.indices[3 * triangle + k]].posModel;
  };
  std::vector<EdgeNeighbour> neighbours;
  std::array<bool, 3> found{};  // edge (k, k + 1) has its neighbour
  for (std::size_t other = 0; other < mesh.triangleCount() && neighbours.size() < 3; ++other) {
    if (other == t) continue;
    std::array<int, 2> shared{};
    int count = 0;
    for (int k = 0; k < 3 && count < 3; ++k) {
      for (std::size_t j = 0; j < 3; ++j) {
        if (positionOf(t, static_cast<std::size_t>(k)) == positionOf(other, j)) {
          if (count < 2) shared[static_cast<std::size_t>(count)] = k;
          ++count;
          break;
        }
      }
    }
    if (count != 2) continue;  // a corner only, or the same three corners (a degenerate copy)
    const vec3 &p0 = positionOf(other, 0), &p1 = positionOf(other, 1), &p2 = positionOf(other, 2);
    if (p0 == p1 || p1 == p2 || p2 == p0) continue;  // no area: no edge to share
    const std::size_t edge = (shared[0] == 0 && shared[1] == 2) ? 2 : static_cast<std::size_t>(shared[0]);
    if (found[edge]) continue;
    found[edge] = true;
    EdgeNeighbour n;
    n.triangleId = firstTriangleId + static_cast<std::uint32_t>(other);
    n.sharedCorners = shared;
    for (std::size_t j = 0; j < 3; ++j) n.posClip[j] = runVertexStage(mesh.vertices[mesh.indices[3 * other + j]], vertexUniforms).posClip;
    neighbours.push_back(n);
  }
  return neighbours;
}

// Replays one triangle of a draw item for pixel (x, yGl); appends a visit when the triangle
// reaches the pixel and updates `depth` as the depth buffer would be.
void traceTriangle(const DrawItem& item, std::size_t t, const VertexUniforms& vertexUniforms,
                   const ShadeUniforms& shadeUniforms, const ShaderKey& key, const ClipConfig& clipConfig,
                   const RenderSettings& settings, const Viewport& viewport, int x, int yGl, float& depth,
                   std::vector<TriangleVisit>& visits) {
  const Mesh& mesh = *item.mesh;
  std::array<ClipVertex, 3> v;
  TriangleVisit visit;
  visit.triangleId = item.firstTriangleId + static_cast<std::uint32_t>(t);
  visit.nodeName = item.nodeName;
  visit.triangleInMesh = t;
  for (std::size_t k = 0; k < 3; ++k) {
    const Vertex& vertex = mesh.vertices[mesh.indices[3 * t + k]];
    v[k] = runVertexStage(vertex, vertexUniforms);
    visit.posModel[k] = vertex.posModel;
    visit.posClip[k] = v[k].posClip;
  }
  ClipPolygon polygon, scratch;
  visit.planesCut = clipTriangle(v[0], v[1], v[2], clipConfig, polygon, scratch);
  visit.clipSteps = clipTriangleSteps(v[0], v[1], v[2], clipConfig);
  for (int i = 0; i < polygon.count; ++i) visit.clippedPolygon.push_back(polygon.v[static_cast<std::size_t>(i)].posClip);

  const bool tangentLighting = vertexUniforms.tangentLighting;
  for (int i = 1; i + 1 < polygon.count; ++i) {
    const std::array<int, 3> corners = fanTriangleCorners(i - 1, visit.planesCut != 0);
    const ClipVertex& a = polygon.v[static_cast<std::size_t>(corners[0])];
    const ClipVertex& b = polygon.v[static_cast<std::size_t>(corners[1])];
    const ClipVertex& c = polygon.v[static_cast<std::size_t>(corners[2])];
    const std::array<WindowVertex, 3> window = windowTriangle(a, b, c, viewport);
    TriangleSetup setup;
    // Coverage does not depend on culling, so set up without it and decide culling after.
    if (setupTriangle(window, CullMode::None, settings.frontFace, viewport, setup) != SetupResult::Ready) continue;
    if (!coversPixel(setup, x, yGl)) continue;
    visit.fanTriangle = i;
    visit.fanCorners = corners;
    visit.window = window;
    visit.xFixed = setup.xFixed;
    visit.yFixed = setup.yFixed;
    for (std::size_t e = 0; e < 3; ++e) visit.edgeValue[e] = setup.edges[e].at(x, yGl);
    visit.frontFacing = setup.frontFacing;
    const InterpolationSetup interpolation =
        makeInterpolationSetup(window, {a.uv, b.uv, c.uv}, setup, settings.interpolation);
    visit.weights = pixelWeights(interpolation, x, yGl);
    const VaryingPlanes varyings =
        makeVaryingPlanes(window, a, b, c, tangentLighting, shadeUniforms.lightCount, setup, settings.interpolation);
    visit.fragment = interpolateFragment(varyings, x, yGl, visit.weights.depth);
    visit.varyings = varyings;
    if (shadeUniforms.needsQuadDifferences()) {
      // The LOD (or the anisotropic ellipse) from the pixel's 2x2 quad, as the renderers take it.
      lanes::setQuadUvDifferences<float>(interpolation.uv, static_cast<float>(x & ~1), static_cast<float>(yGl & ~1),
                                         visit.fragment);
      if (shadeUniforms.heightMap) {
        lanes::setFineUvDifferences<float>(interpolation.uv, static_cast<float>(x & ~1), static_cast<float>(yGl & ~1),
                                           static_cast<float>(x), static_cast<float>(yGl), visit.fragment);
      }
    }
    setEnvironmentDifferencesDynamic(key, varyings, x, yGl, shadeUniforms, visit.fragment);
    visit.depthBefore = depth;
    if (settings.cull == CullMode::Back && !setup.frontFacing) {
      visit.outcome = TraceOutcome::CulledBack;
    } else if (settings.cull == CullMode::Front && setup.frontFacing) {
      visit.outcome = TraceOutcome::CulledFront;
    } else if (!depthTestLess(visit.weights.depth, depth)) {
      visit.outcome = TraceOutcome::FailedDepthTest;
    } else {
      visit.outcome = TraceOutcome::Shaded;
      visit.heightMap = shadeUniforms.heightMap != nullptr;
      visit.surfaceDetail = shadeUniforms.surfaceDetail;
      visit.environmentDiffuse = shadeUniforms.environment.diffuse;
      shadeFragmentDynamic(key, visit.fragment, shadeUniforms, &visit.terms);
      depth = visit.weights.depth;
    }
    // The explorer shows a clipped triangle's fill rule on its own fan, so only an unclipped
    // one needs the mesh searched.
    if (visit.planesCut == 0) visit.neighbours = edgeNeighboursOf(mesh, t, vertexUniforms, item.firstTriangleId);
    visits.push_back(std::move(visit));
    return;  // the fill rule gives a pixel to exactly one fan triangle
  }

  // Not covered after clipping: say so if the unclipped triangle (all w > 0, so it can be
  // projected) would have covered the pixel.
  if (visit.planesCut == 0 || !(v[0].posClip.w > 0.0f && v[1].posClip.w > 0.0f && v[2].posClip.w > 0.0f)) return;
  const std::array<WindowVertex, 3> window = windowTriangle(v[0], v[1], v[2], viewport);
  TriangleSetup setup;
  if (setupTriangle(window, CullMode::None, settings.frontFace, viewport, setup) != SetupResult::Ready) return;
  if (!coversPixel(setup, x, yGl)) return;
  visit.window = window;
  visit.xFixed = setup.xFixed;
  visit.yFixed = setup.yFixed;
  for (std::size_t e = 0; e < 3; ++e) visit.edgeValue[e] = setup.edges[e].at(x, yGl);
  visit.frontFacing = setup.frontFacing;
  visit.depthBefore = depth;
  visit.outcome = TraceOutcome::ClippedAway;
  visits.push_back(std::move(visit));
}

std::string fmt(float v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", static_cast<double>(v));
  return buf;
}
template <int N>
std::string fmt(const glm::vec<N, float>& v) {
  std::string s = "(";
  for (int i = 0; i < N; ++i) s += (i ? ", " : "") + fmt(v[i]);
  return s + ")";
}

std::string planeList(std::uint32_t mask) {
  if (mask == 0) return "none";
  if (mask & kClipNonFiniteBit) return "removed: a clip position non-finite or beyond kMaxClipCoordinate (1e30), or cut to w <= 0";
  std::string s;
  for (int p = 0; p < kClipPlaneCount; ++p) {
    if (mask & (1u << p)) s += (s.empty() ? "" : ", ") + std::string(clipPlaneName(p));
  }
  return s;
}

template <int N>
nlohmann::json toJson(const glm::vec<N, float>& v) {
  nlohmann::json a = nlohmann::json::array();
  for (int i = 0; i < N; ++i) a.push_back(v[i]);
  return a;
}

}  // namespace

PixelTrace tracePixelVisits(const Scene& scene, const RenderSettings& requested, int width, int height, int x,
                            int yTop, const ShadowMaps* shadows) {
  if (needsEnvironmentCapture(scene)) {  // the cube the CPU's frame is drawn with, captured as it does
    return tracePixelVisits(captureEnvironment(scene, requested, *makeCpuRenderer()).scene, requested, width, height, x,
                            yTop, shadows);
  }
  // What the renderer would refuse, refused here too: the replay indexes the meshes.
  validateImageSize(width, height, "trace");
  if (const std::string problem = clipSlotProblem(requested); !problem.empty()) throw InputError("trace: " + problem);
  if (x < 0 || x >= width || yTop < 0 || yTop >= height) {
    throw InputError("trace: pixel (" + std::to_string(x) + ", " + std::to_string(yTop) + ") is outside the " +
                     std::to_string(width) + "x" + std::to_string(height) + " image (x in [0, " +
                     std::to_string(width) + "), y in [0, " + std::to_string(height) + "))");
  }
  RenderSettings settings = requested;  // mip_level: albedo of stand-ins, below
  PixelTrace trace;
  trace.x = x;
  trace.yTop = yTop;
  trace.yGl = height - 1 - yTop;
  trace.width = width;
  trace.height = height;
  trace.view = requested.view;
  trace.lightingSpace = settings.lightingSpace;
  trace.interpolation = settings.interpolation;

  const Viewport viewport{width, height};
  const mat4 clipFromWorld = clipFromWorldFor(scene.camera, width, height);
  trace.clipFromWorld = clipFromWorld;
  trace.clip = makeClipConfig(settings.clip, 0, width, height, settings.interpolation);
  float depth = kClearDepth;
  std::vector<DrawItem> items = flattenScene(scene);
  for (const DrawItem& item : items) validateIndices(item);
  const MipLevelView mipLevelView = applyMipLevelView(items, settings);  // owns stand-ins while traced
  if (shadows) {
    trace.shadowMaps = *shadows;
  } else {
    Framebuffer shadowTarget;
    double shadowMilliseconds = 0.0;
    trace.shadowMaps = renderShadowMaps(
        scene, requested,
        [&](const std::vector<ItemState>& passItems, int size) -> const Framebuffer& {
          shadowTarget = makeShadowFramebuffer(size, scene.output.background);
          RenderStats passStats;
          drawTeachingItems(passItems, 1, shadowTarget, passStats);
          return shadowTarget;
        },
        shadowMilliseconds);
  }
  for (const DrawItem& item : items) {
    const VertexUniforms vertexUniforms = makeVertexUniforms(item.worldFromModel, clipFromWorld, scene, settings);
    ShadeUniforms shadeUniforms = makeShadeUniforms(*item.material, scene, settings);
    setShadowUniforms(shadeUniforms, trace.shadowMaps);
    const ShaderKey key = shaderKeyFor(shadeUniforms, settings);
    const ClipConfig clipConfig =
        makeClipConfig(settings.clip, vertexUniforms.userClipPlaneCount, width, height, settings.interpolation);
    for (std::size_t t = 0; t < item.mesh->triangleCount(); ++t) {
      traceTriangle(item, t, vertexUniforms, shadeUniforms, key, clipConfig, settings, viewport, x, trace.yGl, depth,
                    trace.visits);
    }
  }
  return trace;
}

PixelTrace tracePixel(const Scene& scene, const RenderSettings& requested, int width, int height, int x, int yTop) {
  if (needsEnvironmentCapture(scene)) {  // captured once, for the frame and the replay alike
    return tracePixel(captureEnvironment(scene, requested, *makeCpuRenderer()).scene, requested, width, height, x, yTop);
  }
  // The full render gives the final pixel (and validates the size and the meshes).
  const RenderOutput output = makeCpuRenderer()->render(scene, requested, width, height);
  PixelTrace trace = tracePixelVisits(scene, requested, width, height, x, yTop, &output.shadowMaps);
  const std::size_t i = static_cast<std::size_t>(yTop) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x);
  for (std::size_t c = 0; c < 4; ++c) trace.rgba[c] = output.rgba[i * 4 + c];
  trace.depth = output.depth[i];
  trace.triangleId = output.triangleId[i];
  if (trace.triangleId == kNoTriangle && drawsSky(scene, requested)) {
    const SkyUniformsT<float> sky = makeSkyUniforms(scene, width, height, requested.view);
    const lanes::SkyReadL<float> read = lanes::skyRead<float>(sky, static_cast<float>(x), static_cast<float>(trace.yGl));
    trace.sky = true;
    trace.skyDirection = read.dir;
    if (sky.layers) {
      const lanes::MapCoordL<float> coord = lanes::environmentCoord<float>(sky.layers->kind, read.dir);
      trace.skyParameterization = sky.layers->kind;
      trace.skyFace = static_cast<int>(coord.layer);
      trace.skyFaceCoord = vec2(coord.u, coord.v);
      trace.skyLod = lanes::mapLod<float>(vec2(read.dx.x, read.dx.y), vec2(read.dy.x, read.dy.y), sky.layers->size());
    } else {
      const lanes::CubeCoordL<float> coord = lanes::cubeCoord<float>(read.dir);
      trace.skyFace = static_cast<int>(coord.face);
      trace.skyFaceCoord = vec2(coord.s, coord.t);
      trace.skyLod = lanes::cubeLod<float>(read.dir, read.dx, read.dy, sky.cube->size());
    }
  }
  trace.debugLine = output.lineMask[i] != 0;
  return trace;
}

namespace {

// A parameterized map's layer as the trace names it.
const char* layerName(const PixelTrace& tr) {
  if (tr.skyParameterization == EnvironmentParameterization::Sphere) return "sphere";
  return tr.skyFace == 0 ? "+Z half" : "-Z half";
}
// Where the sky was read, before its coordinate.
std::string skyWhere(const PixelTrace& tr) {
  if (tr.skyParameterization == EnvironmentParameterization::Cube) return std::string("face ") + kCubeFaceNames[tr.skyFace] + " at s, t";
  if (tr.skyParameterization == EnvironmentParameterization::Sphere) return "sphere map at u, v";
  return std::string("dual paraboloid, layer ") + std::to_string(tr.skyFace) + " (" + layerName(tr) + ") at u, v";
}

}  // namespace

std::vector<ShadowTapTrace> shadowTapTracesOf(const PixelTrace& trace, const Scene& scene) {
  std::vector<ShadowTapTrace> out;
  const TriangleVisit* shown = nullptr;  // the last shaded visit drew the pixel
  for (const TriangleVisit& v : trace.visits) {
    if (v.outcome == TraceOutcome::Shaded) shown = &v;
  }
  for (std::size_t i = 0; i < scene.lights.size() && i < static_cast<std::size_t>(kMaxLights); ++i) {
    const ShadowMap* map = i < trace.shadowMaps.size() ? trace.shadowMaps[i].get() : nullptr;
    if (!scene.lights[i].shadow || !map) continue;
    ShadowTapTrace t;
    t.light = static_cast<int>(i);
    t.pcf = map->projection.pcf;
    const LightTerms* terms = shown ? &shown->terms.lights[i] : nullptr;
    if (terms && terms->shadowOn) {
      t.tested = true;
      t.inside = terms->shadowInside;
      t.texel = glm::ivec3(terms->shadowTexel);
      t.depth = terms->shadowDepth;
      t.bias = terms->shadowBias;
      t.reference = terms->shadowReference;
      t.visibility = terms->shadowVisibility;
      t.stored = terms->shadowStored;
      if (t.inside) t.taps = shadowTapsOf(*map, t.texel, t.reference);
    }
    out.push_back(std::move(t));
  }
  return out;
}

std::string formatPixelTrace(const PixelTrace& tr) {
  std::ostringstream o;
  o << "pixel (" << tr.x << ", " << tr.yTop << ") of " << tr.width << "x" << tr.height
    << " (x from the left, y from the top as in the image; GL window row " << tr.yGl << ", centre ("
    << tr.x + 0.5 << ", " << tr.yGl + 0.5 << "))\n";
  o << "view " << toString(tr.view) << ", lighting space " << toString(tr.lightingSpace) << ", interpolation "
    << toString(tr.interpolation)
    << (tr.interpolation == Interpolation::Affine ? " (every corner's 1/w taken as 1: varyings linear on the screen)"
                                                  : "")
    << "\n";
  o << "final: rgba (" << int(tr.rgba[0]) << ", " << int(tr.rgba[1]) << ", " << int(tr.rgba[2]) << ", "
    << int(tr.rgba[3]) << "), depth " << fmt(tr.depth) << ", triangle "
    << (tr.triangleId == kNoTriangle ? std::string("none (background)") : std::to_string(tr.triangleId))
    << (tr.debugLine ? ", a TBN debug line was drawn over it" : "") << "\n";
  if (tr.visits.empty()) o << "no triangle reaches this pixel\n";
  if (tr.sky) {
    o << "sky box: direction (world) " << fmt(tr.skyDirection) << ", " << skyWhere(tr) << " " << fmt(tr.skyFaceCoord)
      << ", LOD " << fmt(tr.skyLod)
      << (tr.skyParameterization == EnvironmentParameterization::Cube ? " (from the direction's quad differences)\n"
                                                                       : " (from u, v's quad differences)\n");
  }
  for (std::size_t n = 0; n < tr.visits.size(); ++n) {
    const TriangleVisit& v = tr.visits[n];
    o << "\n#" << n + 1 << " triangle " << v.triangleId << " (node '" << v.nodeName << "', triangle "
      << v.triangleInMesh << " of its mesh): " << toString(v.outcome) << "\n";
    for (std::size_t k = 0; k < 3; ++k) {
      o << "  v" << k << " posModel " << fmt(v.posModel[k]) << " -> posClip " << fmt(v.posClip[k]) << "\n";
    }
    o << "  clip planes that cut it: " << planeList(v.planesCut) << "\n";
    for (const ClipStep& step : v.clipSteps) {
      o << "    " << clipPlaneName(step.plane) << ": " << step.before.size() << " -> " << step.after.size()
        << " vertices";
      for (const ClipCut& cut : step.cuts) {
        o << "; cut edge (" << cut.nearer << ", " << cut.farther << ") at t " << cut.t;
        if (tr.interpolation == Interpolation::Affine) o << ", varyings at its screen t " << cut.tVaryings + 0.0f;
      }
      o << "\n";
    }
    if (v.planesCut != 0) {
      o << "  clipped polygon (" << v.clippedPolygon.size() << " vertices):";
      for (const vec4& p : v.clippedPolygon) o << " " << fmt(p);
      o << "\n";
    }
    if (v.fanTriangle >= 0 && v.planesCut != 0) {
      o << "  covered by fan triangle (0, " << v.fanTriangle << ", " << v.fanTriangle + 1 << "), corners in setup order ("
        << v.fanCorners[0] << ", " << v.fanCorners[1] << ", " << v.fanCorners[2] << ")\n";
    }
    for (std::size_t k = 0; k < 3; ++k) {
      o << "  window v" << k << " (" << fmt(v.window[k].x) << ", " << fmt(v.window[k].y) << ") z "
        << fmt(v.window[k].z) << " 1/w " << fmt(v.window[k].invW) << "\n";
    }
    o << "  snapped corners (1/256 px, centre offset removed, clockwise):";
    for (std::size_t k = 0; k < 3; ++k) o << " (" << v.xFixed[k] << ", " << v.yFixed[k] << ")";
    o << "\n  edge functions at the pixel (covered when all > 0): " << v.edgeValue[0] << ", " << v.edgeValue[1]
      << ", " << v.edgeValue[2] << "\n";
    o << "  faces the camera: " << (v.frontFacing ? "front" : "back") << "\n";
    if (v.outcome == TraceOutcome::ClippedAway) continue;
    o << "  barycentrics (screen) " << fmt(v.weights.screen[0]) << ", " << fmt(v.weights.screen[1]) << ", "
      << fmt(v.weights.screen[2]) << "; perspective weights " << fmt(v.weights.perspective[0]) << ", "
      << fmt(v.weights.perspective[1]) << ", " << fmt(v.weights.perspective[2]) << "\n";
    o << "  depth " << fmt(v.weights.depth) << " vs stored " << fmt(v.depthBefore) << "\n";
    const Fragment& f = v.fragment;
    o << "  posWorld " << fmt(f.posWorld) << " uv " << fmt(f.uv) << "\n";
    if (f.uvDx != vec2(0.0f) || f.uvDy != vec2(0.0f)) {
      o << "  quad uv differences (top-left pixel to its right, and to the pixel above): d/dx " << fmt(f.uvDx)
        << " d/dy " << fmt(f.uvDy) << "\n";
    }
    o << "  nWorld " << fmt(f.nWorld) << " tWorld " << fmt(f.tWorld) << " bWorld " << fmt(f.bWorld) << "\n";
    if (v.outcome != TraceOutcome::Shaded) continue;
    const ShadeTerms& s = v.terms;
    o << "  N " << fmt(s.n) << " T " << fmt(s.t) << " B " << fmt(s.b) << "\n";
    o << "  albedo " << fmt(s.albedo) << " specScale " << fmt(s.specScale) << " normal texel " << fmt(s.normalTexel)
      << " mapped (tangent) " << fmt(s.mappedTangent) << "\n";
    if (v.heightMap) {
      o << "  surface detail " << toString(v.surfaceDetail) << ": maps read at uv " << fmt(s.uvShifted) << ", height "
        << fmt(s.height) << ", layers marched " << fmt(s.parallaxSteps) << "\n";
    }
    o << "  Nl (lighting normal) " << fmt(s.nl) << "\n";
    if (isShadedView(tr.view)) {
      o << "  ambient ka*albedo*Ia " << fmt(s.ambient) << "\n";
      for (int l = 0; l < s.lightCount; ++l) {
        const LightTerms& t = s.lights[static_cast<std::size_t>(l)];
        o << "  light " << l << ": d " << fmt(t.distance) << " L " << fmt(t.l) << " V " << fmt(t.v) << " R " << fmt(t.r)
          << "\n           N.L " << fmt(t.nDotL) << " R.V " << fmt(t.rDotV) << " If " << fmt(t.attenuation)
          << " diffuse " << fmt(t.diffuse) << " specular " << fmt(t.specular) << "\n";
        if (t.shadowOn) {
          o << "           shadow map: depth from the light " << fmt(t.shadowDepth) << " - bias " << fmt(t.shadowBias)
            << " vs map " << fmt(t.shadowStored) << ", visibility " << fmt(t.shadowVisibility) << "\n";
        }
      }
      if (s.environmentDiffuseOn) {
        o << "  environment diffuse light (" << toString(v.environmentDiffuse) << ") at Nl " << fmt(s.environmentDiffuse)
          << ", times kd*albedo added\n";
      }
      if (isPhongTermView(tr.view)) {
        o << "  summed over the lights with If and shadow (the " << toString(tr.view) << " view): diffuse "
          << fmt(s.diffuseSum) << " specular " << fmt(s.specularSum) << "\n";
      }
      if (s.environmentOn) {
        o << "  environment: Phong colour " << fmt(s.phongColour) << ", reflect (world) " << fmt(s.reflectWorld)
          << " read " << fmt(s.environmentReflected)
          << (s.environmentPrefiltered ? " from the prefiltered map at the shininess's LOD "
                                       : " with texture() at LOD ")
          << fmt(s.environmentReflectLod) << "\n           refract (world) " << fmt(s.refractWorld)
          << (s.totalInternalReflection ? " (total internal reflection)" : "") << ", transmitted "
          << fmt(s.environmentTransmitted) << ", reflected share " << fmt(s.environmentShare) << "\n";
      }
    }
    o << "  colour " << fmt(s.colour) << "\n";
  }
  return o.str();
}

nlohmann::json pixelTraceToJson(const PixelTrace& tr) {
  using nlohmann::json;
  json j;
  j["x"] = tr.x;
  j["y"] = tr.yTop;
  j["y_gl"] = tr.yGl;
  j["width"] = tr.width;
  j["height"] = tr.height;
  j["view"] = std::string(toString(tr.view));
  j["lighting_space"] = std::string(toString(tr.lightingSpace));
  j["interpolation"] = std::string(toString(tr.interpolation));
  j["final"] = {{"rgba", {tr.rgba[0], tr.rgba[1], tr.rgba[2], tr.rgba[3]}},
                {"depth", tr.depth},
                {"triangle", tr.triangleId == kNoTriangle ? json(nullptr) : json(tr.triangleId)},
                {"debug_line", tr.debugLine}};
  json visits = json::array();
  for (const TriangleVisit& v : tr.visits) {
    json jv;
    jv["triangle"] = v.triangleId;
    jv["node"] = v.nodeName;
    jv["triangle_in_mesh"] = v.triangleInMesh;
    jv["outcome"] = std::string(toString(v.outcome));
    json verts = json::array();
    for (std::size_t k = 0; k < 3; ++k) verts.push_back({{"pos_model", toJson(v.posModel[k])}, {"pos_clip", toJson(v.posClip[k])}});
    jv["vertices"] = verts;
    json planes = json::array();
    for (int p = 0; p < kClipPlaneCount; ++p)
      if (v.planesCut & (1u << p)) planes.push_back(clipPlaneName(p));
    jv["clip_planes"] = planes;
    json poly = json::array();
    for (const vec4& p : v.clippedPolygon) poly.push_back(toJson(p));
    jv["clipped_polygon"] = poly;
    json steps = json::array();
    for (const ClipStep& step : v.clipSteps) {
      json after = json::array(), cuts = json::array();
      for (const vec4& p : step.after) after.push_back(toJson(p));
      for (const ClipCut& cut : step.cuts) {
        cuts.push_back({{"edge", {cut.nearer, cut.farther}}, {"t", cut.t}, {"t_varyings", cut.tVaryings}});
      }
      steps.push_back({{"plane", clipPlaneName(step.plane)}, {"distances", step.distances}, {"polygon", after},
                       {"new_vertices", cuts}});
    }
    jv["clip_steps"] = steps;
    jv["fan_triangle"] = v.fanTriangle;
    jv["fan_corners"] = {v.fanCorners[0], v.fanCorners[1], v.fanCorners[2]};
    json window = json::array(), snapped = json::array();
    for (std::size_t k = 0; k < 3; ++k) {
      window.push_back({v.window[k].x, v.window[k].y, v.window[k].z, v.window[k].invW});
      snapped.push_back({v.xFixed[k], v.yFixed[k]});
    }
    jv["window_xyz_invw"] = window;
    jv["snapped_fixed_8"] = snapped;
    jv["edge_values"] = {v.edgeValue[0], v.edgeValue[1], v.edgeValue[2]};
    jv["front_facing"] = v.frontFacing;
    jv["depth_before"] = v.depthBefore;
    if (v.outcome != TraceOutcome::ClippedAway) {
      jv["barycentrics"] = {v.weights.screen[0], v.weights.screen[1], v.weights.screen[2]};
      jv["perspective_weights"] = {v.weights.perspective[0], v.weights.perspective[1], v.weights.perspective[2]};
      jv["depth"] = v.weights.depth;
      jv["pos_world"] = toJson(v.fragment.posWorld);
      jv["uv"] = toJson(v.fragment.uv);
      jv["uv_dx"] = toJson(v.fragment.uvDx);
      jv["uv_dy"] = toJson(v.fragment.uvDy);
      jv["n_world"] = toJson(v.fragment.nWorld);
      jv["t_world"] = toJson(v.fragment.tWorld);
      jv["b_world"] = toJson(v.fragment.bWorld);
    }
    if (v.outcome == TraceOutcome::Shaded) {
      const ShadeTerms& s = v.terms;
      json js;
      js["N"] = toJson(s.n);
      js["T"] = toJson(s.t);
      js["B"] = toJson(s.b);
      js["albedo"] = toJson(s.albedo);
      js["spec_scale"] = toJson(s.specScale);
      js["normal_texel"] = toJson(s.normalTexel);
      js["mapped_tangent"] = toJson(s.mappedTangent);
      js["Nl"] = toJson(s.nl);
      if (v.heightMap) {
        js["surface_detail"] = {{"method", std::string(toString(v.surfaceDetail))},
                                {"uv_shifted", toJson(s.uvShifted)},
                                {"height", s.height},
                                {"layers_marched", s.parallaxSteps}};
      }
      js["ambient"] = toJson(s.ambient);
      json lights = json::array();
      for (int l = 0; l < s.lightCount; ++l) {
        const LightTerms& t = s.lights[static_cast<std::size_t>(l)];
        lights.push_back({{"distance", t.distance}, {"L", toJson(t.l)}, {"V", toJson(t.v)}, {"R", toJson(t.r)},
                          {"NdotL", t.nDotL}, {"RdotV", t.rDotV}, {"attenuation", t.attenuation},
                          {"diffuse", toJson(t.diffuse)}, {"specular", toJson(t.specular)}});
        if (t.shadowOn) {
          lights.back()["shadow"] = {{"depth", t.shadowDepth},
                                     {"bias", t.shadowBias},
                                     {"map_depth", t.shadowStored},
                                     {"visibility", t.shadowVisibility}};
        }
      }
      js["lights"] = lights;
      if (isPhongTermView(tr.view)) {
        js["diffuse_sum"] = toJson(s.diffuseSum);
        js["specular_sum"] = toJson(s.specularSum);
      }
      if (s.environmentDiffuseOn) {
        js["environment_diffuse"] = {{"kind", std::string(toString(v.environmentDiffuse))},
                                     {"light", toJson(s.environmentDiffuse)}};
      }
      if (s.environmentOn) {
        js["environment"] = {{"phong_colour", toJson(s.phongColour)},
                             {"reflect_world", toJson(s.reflectWorld)},
                             {"reflected", toJson(s.environmentReflected)},
                             {"reflection_read", s.environmentPrefiltered ? "prefiltered" : "texture"},
                             {"reflection_lod", s.environmentReflectLod},
                             {"refract_world", toJson(s.refractWorld)},
                             {"total_internal_reflection", s.totalInternalReflection},
                             {"transmitted", toJson(s.environmentTransmitted)},
                             {"reflected_share", s.environmentShare}};
      }
      js["colour"] = toJson(s.colour);
      jv["shading"] = js;
    }
    visits.push_back(jv);
  }
  j["triangles"] = visits;
  if (tr.sky) {
    j["sky"] = {{"direction_world", toJson(tr.skyDirection)},
                {"parameterization", std::string(toString(tr.skyParameterization))},
                {"face", tr.skyParameterization == EnvironmentParameterization::Cube ? kCubeFaceNames[tr.skyFace]
                                                                                       : layerName(tr)},
                {"face_coord", toJson(tr.skyFaceCoord)},
                {"lod", tr.skyLod}};
  }
  return j;
}

}  // namespace twr
