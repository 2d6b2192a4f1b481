// The draw loop the teaching path and the reference renderer share (docs/pipeline.md): for
// every draw item in submission order, every triangle of its mesh:
//   clip -> fan -> setup (cull) -> raster -> interpolate -> depth test -> shade -> write
// (the depth test is output_merge.h's depthTestLess; the teaching path's write is its
// writeFragment)
// over one band of rows. Templated on the number type T (float: the teaching pipeline;
// double: the reference) and on the Target the fragments go to, which provides
//   T storedDepth(int px, int py) const                   the depth buffer at the pixel
//   DepthFormat depthFormat() const                       how it stores a depth (framebuffer.h)
//   void write(int px, int py, const Vec4T<T>& colour, T depth, std::uint32_t triangleId)
// (GL window coordinates, row 0 at the bottom). The teaching path's target is its RGBA8
// framebuffer; the reference's a double sample buffer. A target with kWritesSurface (the
// deferred pipeline's G-buffer, deferred.h) takes each fragment's surface instead:
//   void writeSurface(int px, int py, const GBufferTexelL<T>& surface, T depth, std::uint32_t triangleId)
// and is drawn with the shaded permutations only. The fast path runs the same stages in
// another traversal (fast_pipeline.h).
#pragma once

#include "scene/mesh.h"
#include "scene/renderer.h"
#include "softrender/clip.h"
#include "softrender/deferred.h"
#include "softrender/interpolate.h"
#include "softrender/output_merge.h"
#include "softrender/raster.h"
#include "softrender/setup.h"
#include "softrender/shade.h"
#include "softrender/vertex.h"

#include <algorithm>
#include <cstdint>
#include <functional>
#include <thread>
#include <vector>

namespace twr {

// One draw item as the loop needs it: the vertex stage's output and the fixed-function state.
template <typename T>
struct LoopItemT {
  const Mesh* mesh = nullptr;
  std::uint32_t firstTriangleId = 0;
  std::vector<ClipVertexT<T>> vertices;  // runVertexStage of each mesh vertex
  ShadeUniformsT<T> shade;
  ShaderKey shaderKey;
  ClipConfig clip;
  CullMode cull = CullMode::Back;
  FrontFace frontFace = FrontFace::Ccw;
  Viewport viewport;
  bool tangentLighting = false;
  Interpolation interpolation = Interpolation::Perspective;  // how varyings spread (interpolate.h)
};

// The rows [rowBegin, rowEnd) one worker draws (exclusive end). Every band sees every triangle
// in submission order, so the image does not depend on the number of bands; only the band
// with countsTriangles counts triangles, so the statistics do not either.
struct RowBand {
  int rowBegin = 0;
  int rowEnd = 0;
  bool countsTriangles = true;
};

// Raster, interpolation, early depth test (GL_LESS), shading and write for one triangle that
// survived clipping (v0, v1, v2 in fan order).
template <typename Features, typename T, typename Target>
void drawClippedTriangle(const LoopItemT<T>& s, const ClipVertexT<T>& v0, const ClipVertexT<T>& v1,
                         const ClipVertexT<T>& v2, std::uint32_t triangleId, const RowBand& band, Target& target,
                         RenderStats& stats) {
  const std::array<WindowVertexT<T>, 3> window{windowFromClip(v0, s.viewport), windowFromClip(v1, s.viewport),
                                               windowFromClip(v2, s.viewport)};
  TriangleSetup setup;
  if (setupTriangle(window, s.cull, s.frontFace, s.viewport, setup) != SetupResult::Ready) {
    if (band.countsTriangles) ++stats.trianglesCulled;
    return;
  }
  if (band.countsTriangles) ++stats.trianglesProduced;
  if (setup.y1 < band.rowBegin || setup.y0 >= band.rowEnd) return;
  const AttributePlaneT<T> depthPlane = makeDepthPlane(window, setup);
  const VaryingPlanesT<T> varyings =
      makeVaryingPlanes(window, v0, v1, v2, s.tangentLighting, s.shade.lightCount, setup, s.interpolation);
  const UvPlanesT<T> uv{varyings.overW[kVaryingUv], varyings.overW[kVaryingUv + 1], varyings.oneOverW};
  const DepthFormat depthFormat = target.depthFormat();
  rasterizeTriangle(setup, band.rowBegin, band.rowEnd, [&](int py, Span span) {
    for (int px = span.xBegin; px < span.xEnd; ++px) {
      const T depth =
          (lanes::depthAsStored<T>)(lanes::planeAt<T>(depthPlane, static_cast<T>(px), static_cast<T>(py)), depthFormat);
      if (!depthTestLess(depth, target.storedDepth(px, py))) continue;  // stage 6, before shading
      FragmentT<T> fragment = interpolateFragment(varyings, px, py, depth);
      if (s.shade.needsQuadDifferences()) {
        // The pixel's 2x2 quad (even column and row): its uv differences give the LOD.
        lanes::setQuadUvDifferences<T>(uv, static_cast<T>(px & ~1), static_cast<T>(py & ~1), fragment);
        if (s.shade.heightMap) {
          lanes::setFineUvDifferences<T>(uv, static_cast<T>(px & ~1), static_cast<T>(py & ~1),
                                         static_cast<T>(px), static_cast<T>(py), fragment);
        }
      }
      setEnvironmentDifferences<Features>(varyings, px, py, s.shade, fragment);  // only when the material reads it
      if constexpr (requires { Target::kWritesSurface; }) {
        target.writeSurface(px, py, gbufferFragment<Features>(fragment, s.shade), depth, triangleId);
      } else {
        target.write(px, py, shadeFragment<Features>(fragment, s.shade, nullptr), depth, triangleId);
      }
      ++stats.pixelsShaded;
    }
  });
}

// Every triangle of one item: clip, then the fan of the convex clipped polygon around its
// first vertex, each fan triangle's corners in llvmpipe's order (fanTriangleCorners).
template <typename Features, typename T, typename Target>
void drawItem(const LoopItemT<T>& s, const RowBand& band, Target& target, RenderStats& stats) {
  const Mesh& mesh = *s.mesh;
  ClipPolygonT<T> polygon, scratch;
  for (std::size_t t = 0; t < mesh.triangleCount(); ++t) {
    if (band.countsTriangles) ++stats.trianglesIn;
    const ClipVertexT<T>& a = s.vertices[mesh.indices[3 * t + 0]];
    const ClipVertexT<T>& b = s.vertices[mesh.indices[3 * t + 1]];
    const ClipVertexT<T>& c = s.vertices[mesh.indices[3 * t + 2]];
    const std::uint32_t planesCut = clipTriangle(a, b, c, s.clip, polygon, scratch);
    if (planesCut != 0 && band.countsTriangles) ++stats.trianglesClipped;
    const std::uint32_t triangleId = s.firstTriangleId + static_cast<std::uint32_t>(t);
    for (int k = 0; k + 3 <= polygon.count; ++k) {
      const std::array<int, 3> c = fanTriangleCorners(k, planesCut != 0);
      const auto at = [&](int i) -> const ClipVertexT<T>& { return polygon.v[static_cast<std::size_t>(c[static_cast<std::size_t>(i)])]; };
      drawClippedTriangle<Features>(s, at(0), at(1), at(2), triangleId, band, target, stats);
    }
  }
}

// Every item, in submission order, into one band: the one runtime dispatch per item picks
// the shader permutation (withShaderFeatures), so nothing per pixel is dispatched.
template <typename T, typename Target>
void drawBand(const std::vector<LoopItemT<T>>& items, const RowBand& band, Target& target, RenderStats& stats) {
  for (const LoopItemT<T>& s : items) {
    withShaderFeatures(s.shaderKey, [&]<typename Features>() { drawItem<Features>(s, band, target, stats); });
  }
}

inline void addTriangleAndPixelStats(RenderStats& into, const RenderStats& from) {
  into.trianglesIn += from.trianglesIn;
  into.trianglesClipped += from.trianglesClipped;
  into.trianglesCulled += from.trianglesCulled;
  into.trianglesProduced += from.trianglesProduced;
  into.pixelsShaded += from.pixelsShaded;
}

// Most worker threads a render uses (inclusive); more would only split rows finer.
inline constexpr int kMaxDrawThreads = 64;

// Calls draw(band, bandStats) for `threads` bands of rows [0, height) at once (the calling
// thread takes the last), then adds every band's statistics to `stats`. Band 0 counts
// triangles when `countTriangles`.
template <typename Draw>
void drawInBands(int threads, int height, bool countTriangles, Draw&& draw, RenderStats& stats) {
  const int bandCount = std::clamp(threads, 1, std::min(height, kMaxDrawThreads));
  std::vector<RenderStats> bandStats(static_cast<std::size_t>(bandCount));
  std::vector<std::thread> workers;
  for (int b = 0; b < bandCount; ++b) {
    const RowBand band{height * b / bandCount, height * (b + 1) / bandCount, countTriangles && b == 0};
    if (b + 1 == bandCount) {
      draw(band, bandStats[static_cast<std::size_t>(b)]);
    } else {
      workers.emplace_back([&draw, band, &bandStats, b] { draw(band, bandStats[static_cast<std::size_t>(b)]); });
    }
  }
  for (std::thread& worker : workers) worker.join();
  for (const RenderStats& b : bandStats) addTriangleAndPixelStats(stats, b);
}

}  // namespace twr
