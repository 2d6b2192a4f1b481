// The CPU pipeline glued together: for every draw item, vertex -> clip -> (fan) -> setup ->
// raster -> interpolate -> depth test -> shade -> output merge, then the TBN debug lines.
#include "softrender/cpu_renderer.h"

#include "scene/errors.h"
#include "scene/image.h"
#include "softrender/clip.h"
#include "softrender/debug_lines.h"
#include "softrender/framebuffer.h"
#include "softrender/interpolate.h"
#include "softrender/output_merge.h"
#include "softrender/raster.h"
#include "softrender/setup.h"
#include "softrender/shade.h"
#include "softrender/vertex.h"

#include <algorithm>
#include <chrono>
#include <functional>
#include <string>
#include <thread>
#include <vector>

namespace twr {

namespace {

// Most worker threads a render uses (inclusive); more would only split rows finer.
constexpr int kMaxThreads = 64;

void validateSize(int width, int height) {
  if (width < 1 || width > kMaxImageSide || height < 1 || height > kMaxImageSide) {
    throw InputError("cpu renderer: image size " + std::to_string(width) + "x" + std::to_string(height) +
                     " must be within 1.." + std::to_string(kMaxImageSide) + " on each side");
  }
}

void validateIndices(const DrawItem& item) {
  const std::size_t vertexCount = item.mesh->vertices.size();
  for (std::size_t i = 0; i < item.mesh->indices.size(); ++i) {
    if (item.mesh->indices[i] >= vertexCount) {
      throw InputError("node '" + item.nodeName + "': mesh index " + std::to_string(i) + " is " +
                       std::to_string(item.mesh->indices[i]) + ", expected < vertex count " +
                       std::to_string(vertexCount));
    }
  }
}

// Everything one draw item's triangles share (read-only while drawing).
struct DrawState {
  const DrawItem* item = nullptr;
  std::vector<ClipVertex> vertices;  // vertex stage output, one per mesh vertex
  ShaderKey shaderKey;
  ShadeUniforms shade;
  ClipConfig clip;
  CullMode cull = CullMode::Back;
  FrontFace frontFace = FrontFace::Ccw;
  Viewport viewport;
  bool tangentLighting = false;
};

// The rows one worker owns, [rowBegin, rowEnd) (exclusive end). Every band sees every
// triangle in submission order, so the image does not depend on the number of bands; only
// band 0 counts triangles, so the statistics do not either.
struct Band {
  int rowBegin = 0;
  int rowEnd = 0;
  bool countsTriangles = true;
};

// Rasterizes and shades one triangle that survived clipping (v0, v1, v2 in fan order).
template <typename Features>
void drawClippedTriangle(const DrawState& s, const ClipVertex& v0, const ClipVertex& v1, const ClipVertex& v2,
                         std::uint32_t triangleId, const Band& band, Framebuffer& fb, RenderStats& stats) {
  const std::array<WindowVertex, 3> window{windowFromClip(v0, s.viewport), windowFromClip(v1, s.viewport),
                                           windowFromClip(v2, s.viewport)};
  TriangleSetup setup;
  if (setupTriangle(window, s.cull, s.frontFace, s.viewport, setup) != SetupResult::Ready) {
    if (band.countsTriangles) ++stats.trianglesCulled;
    return;
  }
  if (band.countsTriangles) ++stats.trianglesProduced;
  if (setup.y1 < band.rowBegin || setup.y0 >= band.rowEnd) return;
  const InterpolationSetup interpolation = makeInterpolationSetup(window, setup);
  const int tangentLights = s.tangentLighting ? s.shade.lightCount : 0;
  rasterizeTriangle(setup, band.rowBegin, band.rowEnd, [&](int py, Span span) {
    for (int px = span.xBegin; px < span.xEnd; ++px) {
      const PixelWeights weights = pixelWeights(interpolation, px, py);
      if (!depthTestLess(weights.depth, fb.depth[fb.index(px, py)])) continue;
      const Fragment fragment = interpolateFragment(v0, v1, v2, weights, s.tangentLighting, tangentLights);
      const vec4 colour = shadeFragment<Features>(fragment, s.shade, nullptr);
      writeFragment(fb, px, py, colour, weights.depth, triangleId);
      ++stats.pixelsShaded;
    }
  });
}

template <typename Features>
void drawItemTriangles(const DrawState& s, const Band& band, Framebuffer& fb, RenderStats& stats) {
  const Mesh& mesh = *s.item->mesh;
  const std::vector<ClipVertex>& vertices = s.vertices;
  ClipPolygon polygon, scratch;
  for (std::size_t t = 0; t < mesh.triangleCount(); ++t) {
    if (band.countsTriangles) ++stats.trianglesIn;
    const ClipVertex& a = vertices[mesh.indices[3 * t + 0]];
    const ClipVertex& b = vertices[mesh.indices[3 * t + 1]];
    const ClipVertex& c = vertices[mesh.indices[3 * t + 2]];
    const std::uint32_t planesCut = clipTriangle(a, b, c, s.clip, polygon, scratch);
    if (planesCut != 0 && band.countsTriangles) ++stats.trianglesClipped;
    const std::uint32_t triangleId = s.item->firstTriangleId + static_cast<std::uint32_t>(t);
    // Fan triangulation of the convex clipped polygon around its first vertex.
    for (int i = 1; i + 1 < polygon.count; ++i) {
      drawClippedTriangle<Features>(s, polygon.v[0], polygon.v[static_cast<std::size_t>(i)],
                                    polygon.v[static_cast<std::size_t>(i + 1)], triangleId, band, fb, stats);
    }
  }
}

class CpuRenderer final : public Renderer {
 public:
  explicit CpuRenderer(const CpuOptions& options) : options_(options) {}
  std::string name() const override { return "cpu"; }

  RenderOutput render(const Scene& scene, const RenderSettings& settings, int width, int height) override {
    validateSize(width, height);
    const auto start = std::chrono::steady_clock::now();
    RenderStats stats;
    Framebuffer fb = makeFramebuffer(width, height, scene.output.background);
    const Viewport viewport{width, height};
    const mat4 clipFromWorld = clipFromWorldFor(scene.camera, width, height);
    const std::vector<DrawItem> items = flattenScene(scene);

    // Vertex stage once per draw item, shared by all bands.
    std::vector<DrawState> states(items.size());
    for (std::size_t k = 0; k < items.size(); ++k) {
      const DrawItem& item = items[k];
      validateIndices(item);
      DrawState& s = states[k];
      const VertexUniforms vertexUniforms = makeVertexUniforms(item.worldFromModel, clipFromWorld, scene, settings);
      s.item = &item;
      s.vertices.resize(item.mesh->vertices.size());
      for (std::size_t i = 0; i < s.vertices.size(); ++i) s.vertices[i] = runVertexStage(item.mesh->vertices[i], vertexUniforms);
      s.shade = makeShadeUniforms(*item.material, scene, settings);
      s.shaderKey = shaderKeyFor(s.shade, settings);
      s.clip = makeClipConfig(settings.clip, vertexUniforms.userClipPlaneCount, width, height);
      s.cull = settings.cull;
      s.frontFace = settings.frontFace;
      s.viewport = viewport;
      s.tangentLighting = vertexUniforms.tangentLighting;
    }

    auto drawBand = [&](const Band& band, RenderStats& bandStats) {
      for (const DrawState& s : states) {
        withShaderFeatures(s.shaderKey, [&]<typename Features>() { drawItemTriangles<Features>(s, band, fb, bandStats); });
      }
    };
    const int bandCount = std::clamp(options_.threads, 1, std::min(height, kMaxThreads));
    std::vector<RenderStats> bandStats(static_cast<std::size_t>(bandCount));
    std::vector<std::thread> workers;
    for (int b = 0; b < bandCount; ++b) {
      const Band band{height * b / bandCount, height * (b + 1) / bandCount, b == 0};
      if (b + 1 == bandCount) {
        drawBand(band, bandStats[static_cast<std::size_t>(b)]);  // the calling thread takes the last band
      } else {
        workers.emplace_back(drawBand, band, std::ref(bandStats[static_cast<std::size_t>(b)]));
      }
    }
    for (std::thread& worker : workers) worker.join();
    for (const RenderStats& b : bandStats) {
      stats.trianglesIn += b.trianglesIn;
      stats.trianglesClipped += b.trianglesClipped;
      stats.trianglesCulled += b.trianglesCulled;
      stats.trianglesProduced += b.trianglesProduced;
      stats.pixelsShaded += b.pixelsShaded;
    }

    if (settings.tbnLines.enabled) {
      for (const DrawItem& item : items) {
        const VertexUniforms vertexUniforms = makeVertexUniforms(item.worldFromModel, clipFromWorld, scene, settings);
        const ClipConfig clip = makeClipConfig(settings.clip, vertexUniforms.userClipPlaneCount, width, height);
        for (const Vertex& vertex : item.mesh->vertices) {
          drawTbnLines(fb, runVertexStage(vertex, vertexUniforms), settings.tbnLines.length, vertexUniforms, clip,
                       viewport);
        }
      }
    }

    RenderOutput out = toRenderOutput(fb);
    stats.milliseconds = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    out.stats = stats;
    return out;
  }

 private:
  CpuOptions options_;
};

}  // namespace

std::unique_ptr<Renderer> makeCpuRenderer(const CpuOptions& options) { return std::make_unique<CpuRenderer>(options); }

}  // namespace twr
