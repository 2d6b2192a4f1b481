// The fast path: the same stages as the teaching path in another traversal, built for speed.
// The image, depth, triangle ids and statistics are the teaching path's bit for bit
// (tests/softrender/test_fast_path.cpp renders every suite scene both ways).
//
//   1. vertex stage, in parallel chunks: runVertexStage once per mesh vertex, plus what
//      every triangle using the vertex would recompute: the window position (divide by w,
//      viewport, fused multiply-add as setup does for stage outputs), its 24.8 snap, and the
//      clipper's outcode (or the non-finite bit);
//   2. front end, one contiguous range of triangles per thread: triangles with no outcode bit
//      go straight to setup on the snapped corners; the others take the teaching clipper and
//      fan; setup culls; the survivors are appended in order to the thread's list and binned
//      by the rows they may cover (kBinRows rows per bin);
//   3. back end, one bin at a time on whichever thread is free: each bin draws its triangles
//      in submission order (thread 0's list, then thread 1's, ...) into its own rows, with
//      the AVX-512 kernel when the CPU has it and the view is shaded, else pixel by pixel
//      with the teaching loop (draw_triangle.h).
// Rows belong to one bin, so threads never write the same pixel and the order of triangles
// per pixel is the submission order: the result does not depend on the thread count.
#pragma once

#include "scene/renderer.h"
#include "softrender/clip.h"
#include "softrender/draw_list.h"
#include "softrender/framebuffer.h"
#include "softrender/worker_pool.h"

#include <array>
#include <cstdint>
#include <deque>
#include <vector>

namespace twr {

// Rows per bin of the back end (a multiple of the SIMD kernel's 4-row blocks).
inline constexpr int kBinRows = 32;

// A vertex after the vertex stage, with what setup and the clipper need of it.
struct FastVertex {
  ClipVertex clip;
  WindowVertex window;
  std::int32_t xFixed = 0, yFixed = 0;  // snapToSubpixel of window x and y (1/256 px)
  std::uint32_t outcode = 0;            // planes it is outside of, or kClipNonFiniteBit
};

class FastPipeline {
 public:
  FastPipeline(int threads, bool simd);

  // makeFramebuffer's result, with the four buffers filled in parallel.
  Framebuffer clearedFramebuffer(int width, int height, vec3 background);

  // Draws every item's triangles into `fb` (already cleared) and adds the counts to `stats`.
  // `items` are in submission order; validateIndices must have passed for each.
  void draw(const std::vector<ItemState>& items, Framebuffer& fb, RenderStats& stats);

 private:
  // A triangle that setup accepted and that may cover a pixel, in submission order.
  struct RasterTriangle {
    std::array<const FastVertex*, 3> v{};  // fan order
    std::uint32_t triangleId = 0;
    std::uint32_t item = 0;  // index into the items of draw()
  };
  // What one front-end thread produces, kept across frames so memory is reused.
  struct FrontEnd {
    std::deque<FastVertex> clipped;  // vertices the clipper made (stable addresses)
    std::vector<RasterTriangle> triangles;
    std::vector<std::vector<std::uint32_t>> bins;  // per bin: indices into triangles
    RenderStats stats;
    ClipPolygon polygon, scratch;
  };

  void runVertexStage(const std::vector<ItemState>& items);
  void runFrontEnd(const std::vector<ItemState>& items, int binCount);
  void frontEndRange(const std::vector<ItemState>& items, std::size_t begin, std::size_t end, FrontEnd& out);
  void emit(const ItemState& s, std::uint32_t item, std::uint32_t triangleId, const FastVertex& a,
            const FastVertex& b, const FastVertex& c, FrontEnd& out);
  std::uint64_t drawBin(const std::vector<ItemState>& items, int bin, Framebuffer& fb);

  WorkerPool pool_;
  bool simd_ = true;
  std::vector<std::vector<FastVertex>> vertices_;  // per item, vertex stage output
  std::vector<FrontEnd> frontEnds_;                // one per thread
};

}  // namespace twr
