#include "softrender/fast_pipeline.h"

#include "scene/horizon_map.h"

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

// Rows [rowBegin, rowEnd) of the depth buffer to kClearDepth and of the line mask to 0. The
// depth rows are copies of `clearDepthRow` (fb.width entries): memcpy stores whole vectors,
// where a fill loop at -O2 stores one float at a time (4 % of a default frame's samples).
void clearRows(int rowBegin, int rowEnd, const std::vector<float>& clearDepthRow, Framebuffer& fb) {
  const std::size_t width = static_cast<std::size_t>(fb.width);
  for (int py = rowBegin; py < rowEnd; ++py) {
    const std::size_t first = fb.index(0, py);
    std::memcpy(&fb.depth[first], clearDepthRow.data(), width * sizeof(float));
    if (!fb.lineMask.empty()) std::memset(&fb.lineMask[first], 0, width);
  }
}

}  // namespace

FastPipeline::FastPipeline(int threads, CpuIsa isa)
    : pool_(threads),
      kernels_(fastKernelsFor(isa)),
      frontEnds_(static_cast<std::size_t>(pool_.threads())),
      backEnds_(static_cast<std::size_t>(pool_.threads())) {}

Framebuffer FastPipeline::allocateFramebuffer(int width, int height, Framebuffer reuse) {
  Framebuffer fb = std::move(reuse);
  fb.depthFormat = DepthFormat::Unorm24;
  fb.width = width;
  fb.height = height;
  const std::size_t count = static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
  if (fb.rgba.size() == count * 4 && fb.depth.size() == count && fb.triangleId.size() == count &&
      fb.lineMask.size() == count) {
    return fb;  // the last frame's buffers: nothing to allocate
  }
  pool_.run(4, [&](int buffer, int) {
    switch (buffer) {
      case 0: fb.rgba.resize(count * 4); break;
      case 1: fb.depth.resize(count); break;
      case 2: fb.triangleId.resize(count); break;
      default: fb.lineMask.resize(count); break;
    }
  });
  return fb;
}

Framebuffer FastPipeline::allocateDepthTarget(int width, int height) {
  Framebuffer fb;
  fb.width = width;
  fb.height = height;
  fb.depthFormat = DepthFormat::Float32;
  fb.depth.resize(static_cast<std::size_t>(width) * static_cast<std::size_t>(height));
  return fb;
}

void FastPipeline::prepareMaps(const std::vector<ItemState>& items) {
  ++frame_;
  maps_.assign(items.size(), ItemMaps{});
  std::vector<TiledEntry*> missing;
  const auto use = [&](const Texture* raw, const std::shared_ptr<const Texture>& owner,
                       bool asHeight = false) -> const TiledTexture* {
    if (!raw) return nullptr;  // the uniforms dropped an unusable map
    auto [found, inserted] = tiled_.try_emplace(raw);
    TiledEntry& entry = found->second;
    if (inserted) {
      entry.texture = owner;
    } else {
      // Options are plain fields an owner may change between frames on the same object (as
      // GlUploadCache allows): the tiled texels do not depend on wrap or srgb, so only the
      // copies of those are refreshed. Texels are const; new texels come as a new Texture.
      entry.tiled.wrap = raw->options.wrap;
      entry.tiled.srgb = raw->options.srgb;
    }
    entry.readAsHeight = entry.readAsHeight || asHeight;
    const bool incomplete = inserted || (entry.readAsHeight && entry.tiled.redFootprints.empty());
    if (incomplete && !entry.queued) {
      entry.queued = true;
      missing.push_back(&entry);
    }
    entry.lastFrame = frame_;
    return &entry.tiled;
  };
  for (std::size_t k = 0; k < items.size(); ++k) {
    const ShadeUniforms& u = items[k].shade;
    const Material& material = *items[k].item->material;
    maps_[k] = ItemMaps{use(u.diffuseMap, material.diffuseMap), use(u.normalMap, material.normalMap),
                        use(u.specularMap, material.specularMap), use(u.heightMap, material.heightMap, true)};
    if (u.horizonDirections > 0 && material.horizonMap) {
      for (std::size_t i = 0; i < material.horizonMap->textures.size() && i < maps_[k].horizon.size(); ++i) {
        maps_[k].horizon[i] = use(u.horizonMaps[i], material.horizonMap->textures[i]);
      }
    }
  }
  pool_.run(static_cast<int>(missing.size()), [&](int task, int) {
    TiledEntry& entry = *missing[static_cast<std::size_t>(task)];
    if (entry.tiled.levels.empty()) entry.tiled = makeTiledTexture(*entry.texture);
    if (entry.readAsHeight && entry.tiled.redFootprints.empty()) entry.tiled.redFootprints = makeRedFootprints(*entry.texture);
    entry.queued = false;
  });
  std::erase_if(tiled_, [this](const auto& entry) { return frame_ - entry.second.lastFrame > kUnusedFramesKept; });
}

void FastPipeline::runVertexStage(const std::vector<ItemState>& items) {
  vertices_.resize(items.size());
  struct Chunk {
    std::size_t item, begin, end;
  };
  std::vector<Chunk> chunks;
  for (std::size_t k = 0; k < items.size(); ++k) {
    const ItemState& s = items[k];
    const std::size_t count = s.item->mesh->vertices.size();
    ItemVertices& out = vertices_[k];
    out.vertices.resize(count);
    out.corners.resize(count);
    out.varyings.resize(count * static_cast<std::size_t>(varyingCount(s.tangentLighting, s.shade.lightCount)));
    for (std::size_t begin = 0; begin < count; begin += kVerticesPerTask) {
      chunks.push_back({k, begin, std::min(count, begin + kVerticesPerTask)});
    }
  }
  pool_.run(static_cast<int>(chunks.size()), [&](int task, int) {
    const Chunk& chunk = chunks[static_cast<std::size_t>(task)];
    const ItemState& s = items[chunk.item];
    ItemVertices& out = vertices_[chunk.item];
    const std::size_t stride = static_cast<std::size_t>(varyingCount(s.tangentLighting, s.shade.lightCount));
    kernels_.vertexRange(&s.item->mesh->vertices[chunk.begin], chunk.end - chunk.begin, s.vertexUniforms, s.viewport,
                         s.clip, &out.vertices[chunk.begin], &out.corners[chunk.begin],
                         &out.varyings[chunk.begin * stride], stride);
  });
}

// Inlined into its two callers: called, its arrays went through the stack, stored as scalars
// and copied as vectors, and each copy waited for the stores (perf put 61 % of the front end's
// loop on one such copy).
[[gnu::always_inline]] inline void FastPipeline::emit(const ItemState& s, std::uint32_t item, std::uint32_t triangleId,
                        const std::array<std::int32_t, 3>& xFixed, const std::array<std::int32_t, 3>& yFixed,
                        std::array<const FastVertex*, 3> v, std::array<const float*, 3> varyings, FrontEnd& out) {
  TriangleSetup setup;
  if (setupSnappedCorners(xFixed[0], yFixed[0], xFixed[1], yFixed[1], xFixed[2], yFixed[2], s.cull, s.frontFace,
                          s.viewport, setup) != SetupResult::Ready) {
    ++out.stats.trianglesCulled;
    return;
  }
  ++out.stats.trianglesProduced;
  // Wholly in the guard band, or (most of a million-triangle mesh at 720p) between pixel centres.
  const PixelBox box = pixelCentreBox(setup);
  if (box.empty()) return;
  const std::uint32_t index = static_cast<std::uint32_t>(out.triangles.size());
  // Stored field by field: a whole temporary would be stored in pieces and read back in wider
  // loads that wait for the stores.
  RasterTriangle& triangle = out.triangles.emplace_back();
  triangle.v = v;
  triangle.varyings = varyings;
  triangle.triangleId = triangleId;
  triangle.item = item;
  for (int bin = box.y0 / kBinRows; bin <= box.y1 / kBinRows; ++bin) {
    out.bins[static_cast<std::size_t>(bin)].push_back(index);
  }
}

void FastPipeline::clipAndEmit(const ItemState& s, std::uint32_t item, std::uint32_t triangleId,
                               const std::array<std::uint32_t, 3>& indices, FrontEnd& out) {
  // The three vertices as the vertex stage returned them, for the teaching clipper: run again
  // (the same function of the same inputs, so the same bits) rather than kept for every vertex
  // of every frame for the few triangles that cross a plane.
  const std::vector<Vertex>& meshVertices = s.item->mesh->vertices;
  std::array<ClipVertex, 3> corners;
  for (std::size_t c = 0; c < 3; ++c) corners[c] = twr::runVertexStage(meshVertices[indices[c]], s.vertexUniforms);
  const bool clipped = clipTriangle(corners[0], corners[1], corners[2], s.clip, out.polygon, out.scratch) != 0;
  if (clipped) ++out.stats.trianglesClipped;
  // The clipped polygon's vertices (original ones copied, new ones from the clipper) with their
  // window positions, then its fan around vertex 0 in llvmpipe's corner order, as the teaching
  // path draws it.
  const std::size_t base = out.clipped.size();
  for (int i = 0; i < out.polygon.count; ++i) {
    const ClipVertex& polygonVertex = out.polygon.v[static_cast<std::size_t>(i)];
    ClippedVertex& v = out.clipped.emplace_back();
    v.vertex.window = windowFromClip(polygonVertex, s.viewport);
    v.vertex.xFixed = snapToSubpixel(v.vertex.window.x);
    v.vertex.yFixed = snapToSubpixel(v.vertex.window.y);
    storeVaryings(polygonVertex, s.tangentLighting, s.shade.lightCount, v.varyings.data());
  }
  for (int k = 0; k + 3 <= out.polygon.count; ++k) {
    const std::array<int, 3> corner = fanTriangleCorners(k, clipped);
    const auto at = [&](std::size_t i) -> const ClippedVertex& {
      return out.clipped[base + static_cast<std::size_t>(corner[i])];
    };
    emit(s, item, triangleId, {at(0).vertex.xFixed, at(1).vertex.xFixed, at(2).vertex.xFixed},
         {at(0).vertex.yFixed, at(1).vertex.yFixed, at(2).vertex.yFixed}, {&at(0).vertex, &at(1).vertex, &at(2).vertex},
         {at(0).varyings.data(), at(1).varyings.data(), at(2).varyings.data()}, out);
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
    const ItemVertices& source = vertices_[k];
    const std::size_t stride = static_cast<std::size_t>(varyingCount(s.tangentLighting, s.shade.lightCount));
    const std::uint32_t item = static_cast<std::uint32_t>(k);
    const std::size_t vertexCount = mesh.vertices.size();
    for (std::size_t g = from; g < to; ++g) {
      const std::size_t t = g - first;
      ++out.stats.trianglesIn;
      const std::array<std::uint32_t, 3> indices = {mesh.indices[3 * t], mesh.indices[3 * t + 1], mesh.indices[3 * t + 2]};
      if (indices[0] >= vertexCount || indices[1] >= vertexCount || indices[2] >= vertexCount) {
        // Not drawn: the range stops at its first bad index, which runFrontEnd reports.
        out.badItem = k;
        out.badIndex = 3 * t + (indices[0] >= vertexCount ? 0 : indices[1] >= vertexCount ? 1 : 2);
        return;
      }
      const SnappedCorner &a = source.corners[indices[0]], &b = source.corners[indices[1]],
                          &c = source.corners[indices[2]];
      const std::uint32_t triangleId = s.item->firstTriangleId + static_cast<std::uint32_t>(t);
      if ((a.outcode | b.outcode | c.outcode) == 0) {  // inside every plane: no clipping
        emit(s, item, triangleId, {a.xFixed, b.xFixed, c.xFixed}, {a.yFixed, b.yFixed, c.yFixed},
             {&source.vertices[indices[0]], &source.vertices[indices[1]], &source.vertices[indices[2]]},
             {&source.varyings[indices[0] * stride], &source.varyings[indices[1] * stride],
              &source.varyings[indices[2] * stride]},
             out);
      } else {
        clipAndEmit(s, item, triangleId, indices, out);
      }
    }
    first += count;
  }
}

void FastPipeline::runFrontEnd(const std::vector<ItemState>& items, int binCount) {
  std::size_t total = 0;
  for (const ItemState& s : items) {
    validateTrailingIndices(*s.item);  // the triangles' indices are checked as they are read
    total += s.item->mesh->triangleCount();
  }
  const std::size_t threads = frontEnds_.size();
  pool_.run(static_cast<int>(threads), [&](int task, int) {
    FrontEnd& out = frontEnds_[static_cast<std::size_t>(task)];
    out.clipped.clear();
    out.triangles.clear();
    out.bins.resize(static_cast<std::size_t>(binCount));
    for (std::vector<std::uint32_t>& bin : out.bins) bin.clear();
    out.stats = RenderStats{};
    out.badItem = kNoBadIndex;
    // Contiguous ranges, so thread order is submission order.
    const std::size_t t = static_cast<std::size_t>(task);
    frontEndRange(items, total * t / threads, total * (t + 1) / threads, out);
  });
  // The first bad index in submission order: the earliest range's.
  for (const FrontEnd& frontEnd : frontEnds_) {
    if (frontEnd.badItem != kNoBadIndex) throwIndexError(*items[frontEnd.badItem].item, frontEnd.badIndex);
  }
}

std::uint64_t FastPipeline::drawBin(const std::vector<ItemState>& items, int bin, std::uint32_t background,
                                        Framebuffer& fb, BackEnd& scratch, bool depthOnly, GBuffer* surfaces) {
  const int rowBegin = bin * kBinRows;
  const int rowEnd = std::min(fb.height, rowBegin + kBinRows);
  scratch.clearDepthRow.resize(static_cast<std::size_t>(fb.width), kClearDepth);
  clearRows(rowBegin, rowEnd, scratch.clearDepthRow, fb);  // colour and ids: the shading pass writes every pixel
  scratch.triangles.clear();
  scratch.exactSumPlanes.clear();
  // Every slot kNoSlot: all bytes 0xFF (memset, for the reason clearRows gives).
  static_assert(kNoSlot == 0xFFFFFFFFu);
  scratch.slots.resize(static_cast<std::size_t>(rowEnd - rowBegin) * static_cast<std::size_t>(fb.width));
  std::memset(scratch.slots.data(), 0xFF, scratch.slots.size() * sizeof(std::uint32_t));
  std::uint64_t passed = 0;
  for (const FrontEnd& frontEnd : frontEnds_) {
    for (const std::uint32_t index : frontEnd.bins[static_cast<std::size_t>(bin)]) {
      const RasterTriangle& r = frontEnd.triangles[index];
      const ItemState& s = items[r.item];
      TriangleSetup setup;  // accepted by the front end with the same inputs
      setupSnappedCorners(r.v[0]->xFixed, r.v[0]->yFixed, r.v[1]->xFixed, r.v[1]->yFixed, r.v[2]->xFixed, r.v[2]->yFixed,
                          s.cull, s.frontFace, s.viewport, setup);
      const std::uint32_t slot = static_cast<std::uint32_t>(scratch.triangles.size());
      bool covered = false;
      const std::array<WindowVertex, 3> window{r.v[0]->window, r.v[1]->window, r.v[2]->window};
      const std::uint64_t passedHere =
          kernels_.visibility(setup, window, slot, rowBegin, rowEnd, fb, scratch.slots.data(), covered);
      passed += passedHere;
      if (!covered || depthOnly) continue;  // no pixel holds this slot, or nothing is shaded
      BinTriangle& t = scratch.triangles.emplace_back();
      t.varyings = makeVaryingPlanes<float>(window, r.varyings, varyingCount(s.tangentLighting, s.shade.lightCount), setup,
                                            s.interpolation);
      t.triangleId = r.triangleId;
      t.item = r.item;
      if (!kernels_.fusesMultiplyAdds) {
        scratch.exactSumPlanes.push_back(passedHere >= kExactSumMinPixels ? exactSumPlaneBits(t) : 0);
      }
    }
  }
  if (depthOnly) return passed;
  const std::uint64_t* exactSumPlanes = kernels_.fusesMultiplyAdds ? nullptr : scratch.exactSumPlanes.data();
  if (surfaces) {
    kernels_.surfaceBin(scratch.triangles, exactSumPlanes, items, maps_, scratch.slots.data(), rowBegin, rowEnd,
                        background, fb, *surfaces);
  } else {
    kernels_.shadeBin(scratch.triangles, exactSumPlanes, items, maps_, scratch.slots.data(), rowBegin, rowEnd,
                      background, fb);
  }
  return passed;
}

void FastPipeline::draw(const std::vector<ItemState>& items, vec4 background, Framebuffer& fb, RenderStats& stats,
                        bool depthOnly, GBuffer* surfaces) {
  const std::uint32_t backgroundRgba = backgroundWord(background);
  runVertexStage(items);
  const int binCount = (fb.height + kBinRows - 1) / kBinRows;
  runFrontEnd(items, binCount);
  prepareMaps(items);
  std::vector<std::uint64_t> shaded(static_cast<std::size_t>(binCount), 0);
  pool_.run(binCount, [&](int bin, int thread) {
    shaded[static_cast<std::size_t>(bin)] =
        drawBin(items, bin, backgroundRgba, fb, backEnds_[static_cast<std::size_t>(thread)], depthOnly, surfaces);
  });
  for (const FrontEnd& frontEnd : frontEnds_) {
    stats.trianglesIn += frontEnd.stats.trianglesIn;
    stats.trianglesClipped += frontEnd.stats.trianglesClipped;
    stats.trianglesCulled += frontEnd.stats.trianglesCulled;
    stats.trianglesProduced += frontEnd.stats.trianglesProduced;
  }
  for (const std::uint64_t n : shaded) stats.pixelsShaded += n;
}

void FastPipeline::reflect(const GBuffer& surfaces, SsrUniforms u, const Mat4T<float>& worldFromClip,
                           bool positionStored, Framebuffer& fb) {
  ssrPlanesOf(fb, surfaces, positionStored, u, ssrPlanes_);
  useSsrPlanes(ssrPlanes_, u);
  const int binCount = (fb.height + kBinRows - 1) / kBinRows;
  pool_.run(binCount, [&](int bin, int) {
    kernels_.reflectRows(surfaces, u, worldFromClip, positionStored, bin * kBinRows,
                         std::min(fb.height, (bin + 1) * kBinRows), fb);
  });
}

void FastPipeline::light(const GBuffer& surfaces, const DeferredUniforms& u, Framebuffer& fb) {
  const int binCount = (fb.height + kBinRows - 1) / kBinRows;
  pool_.run(binCount, [&](int bin, int) {
    kernels_.lightRows(surfaces, u, bin * kBinRows, std::min(fb.height, (bin + 1) * kBinRows), fb);
  });
}

}  // namespace twr
