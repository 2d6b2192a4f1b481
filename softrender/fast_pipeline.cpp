#include "softrender/fast_pipeline.h"

#include "scene/errors.h"
#include "softrender/draw_triangle.h"
#include "softrender/fast_shade_avx512.h"
#include "softrender/interpolate.h"
#include "softrender/setup.h"

#include <algorithm>
#include <cmath>
#include <cstring>

namespace twr {

namespace {

// Vertices per vertex-stage task: large enough to amortise handing out a task, small enough
// to balance two threads on a 2,000-vertex mesh.
constexpr std::size_t kVerticesPerTask = 1024;

bool finitePosition(const vec4& p) {
  return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z) && std::isfinite(p.w);
}

}  // namespace

FastPipeline::FastPipeline(int threads, bool simd)
    : pool_(threads), simd_(simd), frontEnds_(static_cast<std::size_t>(pool_.threads())) {}

Framebuffer FastPipeline::clearedFramebuffer(int width, int height, vec3 background) {
  Framebuffer fb;
  fb.width = width;
  fb.height = height;
  const std::size_t count = static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
  const std::uint32_t word = backgroundWord(background);
  pool_.run(4, [&](int buffer, int) {
    switch (buffer) {
      case 0:
        fb.rgba.resize(count * 4);
        for (std::size_t i = 0; i < count; ++i) std::memcpy(&fb.rgba[i * 4], &word, sizeof(word));
        break;
      case 1: fb.depth.assign(count, kClearDepth); break;
      case 2: fb.triangleId.assign(count, kNoTriangle); break;
      default: fb.lineMask.assign(count, 0); break;
    }
  });
  return fb;
}

void FastPipeline::runVertexStage(const std::vector<ItemState>& items) {
  vertices_.resize(items.size());
  struct Chunk {
    std::size_t item, begin, end;
  };
  std::vector<Chunk> chunks;
  for (std::size_t k = 0; k < items.size(); ++k) {
    const std::size_t count = items[k].item->mesh->vertices.size();
    vertices_[k].resize(count);
    for (std::size_t begin = 0; begin < count; begin += kVerticesPerTask) {
      chunks.push_back({k, begin, std::min(count, begin + kVerticesPerTask)});
    }
  }
  pool_.run(static_cast<int>(chunks.size()), [&](int task, int) {
    const Chunk& chunk = chunks[static_cast<std::size_t>(task)];
    const ItemState& s = items[chunk.item];
    const std::vector<Vertex>& meshVertices = s.item->mesh->vertices;
    std::vector<FastVertex>& out = vertices_[chunk.item];
    for (std::size_t i = chunk.begin; i < chunk.end; ++i) {
      FastVertex& v = out[i];
      v.clip = twr::runVertexStage(meshVertices[i], s.vertexUniforms);
      v.window = windowFromClip(v.clip, s.viewport);
      v.xFixed = snapToSubpixel(v.window.x);
      v.yFixed = snapToSubpixel(v.window.y);
      v.outcode = finitePosition(v.clip.posClip) ? outcode(v.clip, s.clip) : kClipNonFiniteBit;
    }
  });
}

void FastPipeline::emit(const ItemState& s, std::uint32_t item, std::uint32_t triangleId, const FastVertex& a,
                        const FastVertex& b, const FastVertex& c, FrontEnd& out) {
  TriangleSetup setup;
  if (setupSnappedTriangle({a.xFixed, b.xFixed, c.xFixed}, {a.yFixed, b.yFixed, c.yFixed}, s.cull, s.frontFace,
                           s.viewport, setup) != SetupResult::Ready) {
    ++out.stats.trianglesCulled;
    return;
  }
  ++out.stats.trianglesProduced;
  if (setup.x0 > setup.x1 || setup.y0 > setup.y1) return;  // wholly in the guard band
  const std::uint32_t index = static_cast<std::uint32_t>(out.triangles.size());
  out.triangles.push_back(RasterTriangle{{&a, &b, &c}, triangleId, item});
  for (int bin = setup.y0 / kBinRows; bin <= setup.y1 / kBinRows; ++bin) {
    out.bins[static_cast<std::size_t>(bin)].push_back(index);
  }
}

void FastPipeline::frontEndRange(const std::vector<ItemState>& items, std::size_t begin, std::size_t end,
                                 FrontEnd& out) {
  // Triangle g of the submission order is triangle g - first of the item holding it.
  std::size_t first = 0;
  for (std::size_t k = 0; k < items.size() && first < end; ++k) {
    const ItemState& s = items[k];
    const Mesh& mesh = *s.item->mesh;
    const std::size_t count = mesh.triangleCount();
    const std::size_t from = std::max(begin, first), to = std::min(end, first + count);
    const std::vector<FastVertex>& vertices = vertices_[k];
    const std::uint32_t item = static_cast<std::uint32_t>(k);
    for (std::size_t g = from; g < to; ++g) {
      const std::size_t t = g - first;
      ++out.stats.trianglesIn;
      const FastVertex& a = vertices[mesh.indices[3 * t + 0]];
      const FastVertex& b = vertices[mesh.indices[3 * t + 1]];
      const FastVertex& c = vertices[mesh.indices[3 * t + 2]];
      const std::uint32_t triangleId = s.item->firstTriangleId + static_cast<std::uint32_t>(t);
      if ((a.outcode | b.outcode | c.outcode) == 0) {  // inside every plane: no clipping
        emit(s, item, triangleId, a, b, c, out);
        continue;
      }
      if (clipTriangle(a.clip, b.clip, c.clip, s.clip, out.polygon, out.scratch) != 0) ++out.stats.trianglesClipped;
      // The clipped polygon's vertices (original ones copied, new ones from the clipper) with
      // their window positions, then its fan around vertex 0, as the teaching path draws it.
      const std::size_t base = out.clipped.size();
      for (int i = 0; i < out.polygon.count; ++i) {
        FastVertex& v = out.clipped.emplace_back();
        v.clip = out.polygon.v[static_cast<std::size_t>(i)];
        v.window = windowFromClip(v.clip, s.viewport);
        v.xFixed = snapToSubpixel(v.window.x);
        v.yFixed = snapToSubpixel(v.window.y);
      }
      for (int i = 1; i + 1 < out.polygon.count; ++i) {
        emit(s, item, triangleId, out.clipped[base], out.clipped[base + static_cast<std::size_t>(i)],
             out.clipped[base + static_cast<std::size_t>(i + 1)], out);
      }
    }
    first += count;
  }
}

void FastPipeline::runFrontEnd(const std::vector<ItemState>& items, int binCount) {
  std::size_t total = 0;
  for (const ItemState& s : items) total += s.item->mesh->triangleCount();
  const std::size_t threads = frontEnds_.size();
  pool_.run(static_cast<int>(threads), [&](int task, int) {
    FrontEnd& out = frontEnds_[static_cast<std::size_t>(task)];
    out.clipped.clear();
    out.triangles.clear();
    out.bins.resize(static_cast<std::size_t>(binCount));
    for (std::vector<std::uint32_t>& bin : out.bins) bin.clear();
    out.stats = RenderStats{};
    // Contiguous ranges, so thread order is submission order.
    const std::size_t t = static_cast<std::size_t>(task);
    frontEndRange(items, total * t / threads, total * (t + 1) / threads, out);
  });
}

std::uint64_t FastPipeline::drawBin(const std::vector<ItemState>& items, int bin, Framebuffer& fb) {
  const int rowBegin = bin * kBinRows;
  const int rowEnd = std::min(fb.height, rowBegin + kBinRows);
  std::uint64_t shaded = 0;
  for (const FrontEnd& frontEnd : frontEnds_) {
    for (const std::uint32_t index : frontEnd.bins[static_cast<std::size_t>(bin)]) {
      const RasterTriangle& r = frontEnd.triangles[index];
      const ItemState& s = items[r.item];
      const FastVertex& a = *r.v[0];
      const FastVertex& b = *r.v[1];
      const FastVertex& c = *r.v[2];
      TriangleSetup setup;  // accepted by the front end with the same inputs
      setupSnappedTriangle({a.xFixed, b.xFixed, c.xFixed}, {a.yFixed, b.yFixed, c.yFixed}, s.cull, s.frontFace,
                           s.viewport, setup);
      const InterpolationSetup interpolation = makeInterpolationSetup<float>({a.window, b.window, c.window}, setup);
      const TriangleKernel kernel = simd_ ? avx512KernelFor(s.shaderKey) : nullptr;
      if (kernel) {
        shaded += kernel(setup, interpolation, a.clip, b.clip, c.clip, s.shade, r.triangleId, rowBegin, rowEnd, fb);
      } else {
        withShaderFeatures(s.shaderKey, [&]<typename Features>() {
          shaded += shadeTriangleRows<Features>(setup, interpolation, a.clip, b.clip, c.clip, s.shade,
                                                s.tangentLighting, r.triangleId, rowBegin, rowEnd, fb);
        });
      }
    }
  }
  return shaded;
}

void FastPipeline::draw(const std::vector<ItemState>& items, Framebuffer& fb, RenderStats& stats) {
  runVertexStage(items);
  const int binCount = (fb.height + kBinRows - 1) / kBinRows;
  runFrontEnd(items, binCount);
  std::vector<std::uint64_t> shaded(static_cast<std::size_t>(binCount), 0);
  pool_.run(binCount, [&](int bin, int) { shaded[static_cast<std::size_t>(bin)] = drawBin(items, bin, fb); });
  for (const FrontEnd& frontEnd : frontEnds_) {
    stats.trianglesIn += frontEnd.stats.trianglesIn;
    stats.trianglesClipped += frontEnd.stats.trianglesClipped;
    stats.trianglesCulled += frontEnd.stats.trianglesCulled;
    stats.trianglesProduced += frontEnd.stats.trianglesProduced;
  }
  for (const std::uint64_t n : shaded) stats.pixelsShaded += n;
}

}  // namespace twr
