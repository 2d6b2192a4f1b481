// The fast path: the same stages as the teaching path in another traversal, built for speed.
// The image, depth, triangle ids and statistics are the teaching path's bit for bit
// (tests/softrender/test_fast_path.cpp renders every suite scene both ways).
//
//   1. vertex stage, in parallel chunks: runVertexStage once per mesh vertex, kept compactly
//      (the varyings the fragment stage reads, interpolate.h's layout) beside what every
//      triangle would recompute: the window position (setup's fused multiply-add), its 24.8
//      snap, and the clipper's outcode (or the non-finite bit);
//   2. front end, one contiguous range of triangles per thread: a triangle with no outcode bit
//      goes straight to setup's area and culling test on the snapped corners; the others are
//      rebuilt as ClipVertex and take the teaching clipper and fan; survivors are appended in
//      order to the thread's list and binned by the rows they may cover (kBinRows per bin);
//      The SIMD kernels read textures from tiled copies (4 x 4 texels per cache line), made
//      once per texture and kept while frames use it;
//   3. back end, one bin at a time on whichever thread is free, triangles in submission order
//      (thread 0's list, then thread 1's, ...): the chosen Highway target's kernels
//      (fast_kernels.h), a visibility pass then one shading pass per visible pixel.
// A bin's rows belong to it alone, so threads never write the same pixel and each pixel sees
// its triangles in submission order: the result does not depend on the thread count.
#pragma once

#include "scene/renderer.h"
#include "softrender/cpu_renderer.h"
#include "softrender/clip.h"
#include "softrender/deferred.h"
#include "softrender/draw_list.h"
#include "softrender/fast_kernels.h"
#include "softrender/framebuffer.h"
#include "softrender/worker_pool.h"

#include <array>
#include <cstdint>
#include <deque>
#include <map>
#include <memory>
#include <vector>

namespace twr {

// Rows per bin of the back end (a multiple of the SIMD kernel's 4-row blocks).
inline constexpr int kBinRows = 32;
// Pixels a triangle must pass the depth test at in a bin before a target without fused
// multiply-adds checks its planes for planeAt's short way (exactSumPlaneBits): an estimate,
// not tuned, of where the check's integer work meets what the pixels save; a million small
// triangles would pay for checks they gain little from (docs/performance.md).
inline constexpr std::uint64_t kExactSumMinPixels = 8;

class FastPipeline {
 public:
  // Throws InputError for a target this CPU cannot run.
  FastPipeline(int threads, CpuIsa isa);

  // The target whose kernels draw.
  CpuIsa isa() const { return kernels_.isa; }

  // A frame's draws are coming: the workers wake now, while the caller prepares them, and wait
  // for them spinning (WorkerPool::wake). frameEnds(): they sleep again.
  void frameBegins() { pool_.wake(); }
  void frameEnds() { pool_.rest(); }

  // A framebuffer of that size whose buffers are allocated in parallel: draw() clears each
  // bin's rows itself, just before drawing them (while they are in cache). `reuse`'s buffers
  // are kept where they have the frame's size (a frame drawn into the last one's memory
  // neither allocates nor zeroes 12 MB at 1280 x 720); the others are allocated, zeroed.
  Framebuffer allocateFramebuffer(int width, int height, Framebuffer reuse = {});
  // The same for a depth-only pass (draw's depthOnly: a shadow map): the depth buffer alone,
  // 32-bit float as makeShadowFramebuffer stores it. Colour, ids and line mask stay empty, as
  // that pass never touches them (at 2048 x 2048 they were 36 MB allocated and cleared for
  // nothing).
  Framebuffer allocateDepthTarget(int width, int height);

  // Clears `fb` to `background` (as makeFramebuffer) and draws every item's triangles into it,
  // adding the counts to `stats`. `items` are in submission order; an index at or past its
  // mesh's vertex count throws validateIndices's InputError (checked as the front end reads
  // the indices, before any is used). depthOnly: the visibility pass alone (a shadow pass): depth is written,
  // colour and triangle ids are left as they were, nothing is shaded. `surfaces` (the deferred
  // pipeline's G-buffer pass, sized as fb): each pixel's surface is written there instead of
  // its colour (kernels' surfaceBin); colour gets the background.
  void draw(const std::vector<ItemState>& items, vec4 background, Framebuffer& fb, RenderStats& stats,
            bool depthOnly = false, GBuffer* surfaces = nullptr);

  // The deferred lighting pass: fb's pixels with a surface (depth below the clear depth) lit
  // from `surfaces`, bins of rows on the pool's threads.
  void light(const GBuffer& surfaces, const DeferredUniforms& u, Framebuffer& fb);

  // Screen-space reflections (ssr.h): fb's reflecting pixels marched, bins of rows on the
  // pool's threads; the lit colour they read is copied first.
  void reflect(const GBuffer& surfaces, SsrUniforms u, const Mat4T<float>& worldFromClip, bool positionStored,
               Framebuffer& fb);

 private:
  // One item's vertex stage output, one entry per mesh vertex (capacity kept across frames).
  struct ItemVertices {
    std::vector<FastVertex> vertices;
    std::vector<SnappedCorner> corners;  // the same vertices' snapped position and outcode
    std::vector<float> varyings;         // varyingCount floats per vertex
  };
  // A vertex the clipper made (or copied into a clipped polygon).
  struct ClippedVertex {
    FastVertex vertex;
    std::array<float, kMaxVaryings> varyings{};
  };
  // A triangle that setup accepted and that may cover a pixel, in submission order.
  struct RasterTriangle {
    std::array<const FastVertex*, 3> v{};      // fan order
    std::array<const float*, 3> varyings{};
    std::uint32_t triangleId = 0;
    std::uint32_t item = 0;  // index into the items of draw()
  };
  // What one front-end thread produces, kept across frames so memory is reused.
  struct FrontEnd {
    std::deque<ClippedVertex> clipped;  // stable addresses
    std::vector<RasterTriangle> triangles;
    std::vector<std::vector<std::uint32_t>> bins;  // per bin: indices into triangles
    RenderStats stats;
    ClipPolygon polygon, scratch;
    // The first index in this front end's range at or past its vertex count: the item and the
    // index's position (badItem kNoBadIndex when every index is in range).
    std::size_t badItem = kNoBadIndex, badIndex = 0;
  };
  static constexpr std::size_t kNoBadIndex = static_cast<std::size_t>(-1);
  // One back-end thread's scratch space for the bin it is drawing.
  struct BackEnd {
    std::vector<BinTriangle> triangles;
    std::vector<std::uint64_t> exactSumPlanes;  // exactSumPlaneBits per triangle, without fused multiply-adds only
    std::vector<std::uint32_t> slots;  // kBinRows x width, kNoSlot where nothing passed
    std::vector<float> clearDepthRow;  // a row of kClearDepth, copied over each row a bin clears
  };

  // A texture's tiled copy, kept while frames use it and for kUnusedFramesKept frames after
  // (a texture that sits out a frame or two, as when two scenes are drawn in turn or a GUI
  // toggles a method that reads it, is not tiled again). The entry holds the texture, so its
  // address cannot be reused by another one meanwhile, and texels are const.
  static constexpr std::uint64_t kUnusedFramesKept = 4;  // frames
  struct TiledEntry {
    std::shared_ptr<const Texture> texture;
    TiledTexture tiled;
    std::uint64_t lastFrame = 0;
    bool readAsHeight = false;  // some item reads it as a height map: it needs red footprints
    bool queued = false;        // in this frame's list of copies to make
  };

  void prepareMaps(const std::vector<ItemState>& items);
  void runVertexStage(const std::vector<ItemState>& items);
  void runFrontEnd(const std::vector<ItemState>& items, int binCount);
  void frontEndRange(const std::vector<ItemState>& items, std::size_t begin, std::size_t end, FrontEnd& out);
  void clipAndEmit(const ItemState& s, std::uint32_t item, std::uint32_t triangleId,
                   const std::array<std::uint32_t, 3>& indices, FrontEnd& out);
  void emit(const ItemState& s, std::uint32_t item, std::uint32_t triangleId, const std::array<std::int32_t, 3>& xFixed,
            const std::array<std::int32_t, 3>& yFixed, std::array<const FastVertex*, 3> v,
            std::array<const float*, 3> varyings, FrontEnd& out);
  std::uint64_t drawBin(const std::vector<ItemState>& items, int bin, std::uint32_t background, Framebuffer& fb,
                        BackEnd& scratch, bool depthOnly, GBuffer* surfaces);

  WorkerPool pool_;
  SsrPlanes ssrPlanes_;  // what the reflections read of the lit frame (capacity kept across frames)
  FastKernels kernels_;  // the chosen Highway target's
  std::vector<ItemVertices> vertices_;  // per item
  std::vector<FrontEnd> frontEnds_;     // one per thread
  std::vector<BackEnd> backEnds_;       // one per thread
  std::map<const Texture*, TiledEntry> tiled_;
  std::vector<ItemMaps> maps_;  // per item of the current frame
  std::uint64_t frame_ = 0;
};

}  // namespace twr
