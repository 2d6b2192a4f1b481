// The CPU pipeline glued together. The teaching traversal, for every draw item: vertex ->
// clip -> (fan) -> setup -> raster -> interpolate -> depth test -> shade -> output merge,
// then the TBN debug lines. The fast traversal of the same stages is fast_pipeline.cpp.
#include "softrender/cpu_renderer.h"

#include "scene/errors.h"
#include "scene/image.h"
#include "softrender/clip.h"
#include "softrender/debug_lines.h"
#include "softrender/draw_list.h"
#include "softrender/draw_triangle.h"
#include "softrender/fast_pipeline.h"
#include "softrender/framebuffer.h"
#include "softrender/interpolate.h"
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

// One draw item and its vertex stage output, shared by all bands.
struct DrawState {
  ItemState s;
  std::vector<ClipVertex> vertices;  // one per mesh vertex
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
void drawClippedTriangle(const ItemState& s, const ClipVertex& v0, const ClipVertex& v1, const ClipVertex& v2,
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
  stats.pixelsShaded += shadeTriangleRows<Features>(setup, interpolation, v0, v1, v2, s.shade, s.tangentLighting,
                                                    triangleId, band.rowBegin, band.rowEnd, fb);
}

template <typename Features>
void drawItemTriangles(const DrawState& d, const Band& band, Framebuffer& fb, RenderStats& stats) {
  const ItemState& s = d.s;
  const Mesh& mesh = *s.item->mesh;
  ClipPolygon polygon, scratch;
  for (std::size_t t = 0; t < mesh.triangleCount(); ++t) {
    if (band.countsTriangles) ++stats.trianglesIn;
    const ClipVertex& a = d.vertices[mesh.indices[3 * t + 0]];
    const ClipVertex& b = d.vertices[mesh.indices[3 * t + 1]];
    const ClipVertex& c = d.vertices[mesh.indices[3 * t + 2]];
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

void addStats(RenderStats& into, const RenderStats& from) {
  into.trianglesIn += from.trianglesIn;
  into.trianglesClipped += from.trianglesClipped;
  into.trianglesCulled += from.trianglesCulled;
  into.trianglesProduced += from.trianglesProduced;
  into.pixelsShaded += from.pixelsShaded;
}

// The teaching traversal: vertex stage per item, then one band of rows per thread.
void drawTeaching(const std::vector<ItemState>& items, int threads, Framebuffer& fb, RenderStats& stats) {
  std::vector<DrawState> states(items.size());
  for (std::size_t k = 0; k < items.size(); ++k) {
    DrawState& d = states[k];
    d.s = items[k];
    const Mesh& mesh = *d.s.item->mesh;
    d.vertices.resize(mesh.vertices.size());
    for (std::size_t i = 0; i < d.vertices.size(); ++i) {
      d.vertices[i] = runVertexStage(mesh.vertices[i], d.s.vertexUniforms);
    }
  }
  auto drawBand = [&](const Band& band, RenderStats& bandStats) {
    for (const DrawState& d : states) {
      withShaderFeatures(d.s.shaderKey,
                         [&]<typename Features>() { drawItemTriangles<Features>(d, band, fb, bandStats); });
    }
  };
  const int bandCount = std::clamp(threads, 1, std::min(fb.height, kMaxThreads));
  std::vector<RenderStats> bandStats(static_cast<std::size_t>(bandCount));
  std::vector<std::thread> workers;
  for (int b = 0; b < bandCount; ++b) {
    const Band band{fb.height * b / bandCount, fb.height * (b + 1) / bandCount, b == 0};
    if (b + 1 == bandCount) {
      drawBand(band, bandStats[static_cast<std::size_t>(b)]);  // the calling thread takes the last band
    } else {
      workers.emplace_back(drawBand, band, std::ref(bandStats[static_cast<std::size_t>(b)]));
    }
  }
  for (std::thread& worker : workers) worker.join();
  for (const RenderStats& b : bandStats) addStats(stats, b);
}

class CpuRenderer final : public Renderer {
 public:
  explicit CpuRenderer(const CpuOptions& options) : options_(options) {
    options_.threads = std::clamp(options_.threads, 1, kMaxThreads);
  }
  std::string name() const override { return "cpu"; }

  RenderOutput render(const Scene& scene, const RenderSettings& settings, int width, int height) override {
    validateImageSize(width, height);
    const auto start = std::chrono::steady_clock::now();
    RenderStats stats;
    if (options_.path == CpuPath::Fast && !fast_) {
      fast_ = std::make_unique<FastPipeline>(options_.threads, resolveCpuIsa(options_.isa));
    }
    Framebuffer fb = fast_ ? fast_->allocateFramebuffer(width, height)  // draw() clears it bin by bin
                           : makeFramebuffer(width, height, scene.output.background);
    const mat4 clipFromWorld = clipFromWorldFor(scene.camera, width, height);
    const std::vector<DrawItem> drawItems = flattenScene(scene);
    std::vector<ItemState> items;
    items.reserve(drawItems.size());
    for (const DrawItem& item : drawItems) {
      validateIndices(item);
      items.push_back(makeItemState(item, clipFromWorld, scene, settings, width, height));
    }

    if (options_.path == CpuPath::Teaching) {
      drawTeaching(items, options_.threads, fb, stats);
    } else {
      fast_->draw(items, scene.output.background, fb, stats);
    }

    if (settings.tbnLines.enabled) {
      for (const ItemState& s : items) {
        for (const Vertex& vertex : s.item->mesh->vertices) {
          drawTbnLines(fb, runVertexStage(vertex, s.vertexUniforms), settings.tbnLines.length, s.vertexUniforms,
                       s.clip, s.viewport);
        }
      }
    }

    RenderOutput out = toRenderOutput(std::move(fb));
    stats.milliseconds = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    out.stats = stats;
    return out;
  }

 private:
  CpuOptions options_;
  std::unique_ptr<FastPipeline> fast_;  // made on the first fast render, kept for its threads and buffers
};

}  // namespace

std::unique_ptr<Renderer> makeCpuRenderer(const CpuOptions& options) {
  if (options.path == CpuPath::Fast && !cpuIsaSupported(options.isa)) {
    throw InputError("cpu renderer: --cpu-isa " + cpuIsaUnsupportedReason(options.isa));
  }
  return std::make_unique<CpuRenderer>(options);
}

std::string cpuPathName(const CpuOptions& options) {
  if (options.path == CpuPath::Teaching) return "teaching";
  return "fast (" + std::string(toString(resolveCpuIsa(options.isa))) + ")";
}

}  // namespace twr
