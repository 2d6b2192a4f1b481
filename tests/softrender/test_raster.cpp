// Scanline rasterizer: spans equal the per-pixel edge test, shared edges are covered exactly
// once, slivers cover nothing, huge triangles fill the screen without overflow.
#include "softrender/clip.h"
#include "softrender/raster.h"
#include "softrender/setup.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

namespace twr {
namespace {

WindowVertex win(float x, float y) {
  WindowVertex v;
  v.x = x;
  v.y = y;
  v.invW = 1.0f;
  return v;
}

// Adds the coverage of one window-space triangle to `count` (width * height, bottom row first).
void accumulate(const std::array<WindowVertex, 3>& w, const Viewport& vp, std::vector<int>& count) {
  TriangleSetup s;
  if (setupTriangle(w, CullMode::None, FrontFace::Ccw, vp, s) != SetupResult::Ready) return;
  rasterizeTriangle(s, 0, vp.height, [&](int py, Span span) {
    for (int px = span.xBegin; px < span.xEnd; ++px) ++count[static_cast<std::size_t>(py * vp.width + px)];
  });
}

// The full path from clip space: clip, fan, window, setup, raster.
void accumulateClipped(vec4 a, vec4 b, vec4 c, const ClipConfig& config, const Viewport& vp, std::vector<int>& count) {
  ClipVertex va, vb, vc;
  va.posClip = a;
  vb.posClip = b;
  vc.posClip = c;
  ClipPolygon polygon, scratch;
  clipTriangle(va, vb, vc, config, polygon, scratch);
  for (int i = 1; i + 1 < polygon.count; ++i) {
    accumulate({windowFromClip(polygon.v[0], vp), windowFromClip(polygon.v[static_cast<std::size_t>(i)], vp),
                windowFromClip(polygon.v[static_cast<std::size_t>(i + 1)], vp)},
               vp, count);
  }
}

TEST(Raster, SpansEqualThePerPixelEdgeTest) {
  const Viewport vp{40, 30};
  std::mt19937 rng(1);
  std::uniform_real_distribution<float> x(-5.0f, 45.0f), y(-5.0f, 35.0f);
  for (int t = 0; t < 500; ++t) {
    TriangleSetup s;
    if (setupTriangle({win(x(rng), y(rng)), win(x(rng), y(rng)), win(x(rng), y(rng))}, CullMode::None, FrontFace::Ccw, vp, s) !=
        SetupResult::Ready)
      continue;
    std::vector<int> fromSpans(40 * 30, 0);
    rasterizeTriangle(s, 0, vp.height, [&](int py, Span span) {
      for (int px = span.xBegin; px < span.xEnd; ++px) ++fromSpans[static_cast<std::size_t>(py * 40 + px)];
    });
    for (int py = 0; py < 30; ++py) {
      for (int px = 0; px < 40; ++px) {
        // The edge functions evaluated directly, without the bounding box.
        bool inside = true;
        for (const EdgeFunction& e : s.edges) inside = inside && e.at(px, py) > 0;
        ASSERT_EQ(fromSpans[static_cast<std::size_t>(py * 40 + px)], inside ? 1 : 0) << "triangle " << t << " pixel " << px << "," << py;
      }
    }
  }
}

// Small triangles, whose narrow boxes coveredSpan scans pixel by pixel (the wider ones divide):
// the same pixels as the edge functions evaluated directly, on boxes from one pixel to nine wide.
TEST(Raster, SpansOfSmallTrianglesEqualThePerPixelEdgeTest) {
  const Viewport vp{40, 30};
  std::mt19937 rng(3);
  std::uniform_real_distribution<float> centreX(2.0f, 38.0f), centreY(2.0f, 28.0f), size(0.3f, 8.0f), unit(-0.5f, 0.5f);
  int narrow = 0, wide = 0;
  for (int t = 0; t < 4000; ++t) {
    const float cx = centreX(rng), cy = centreY(rng), r = size(rng);
    TriangleSetup s;
    if (setupTriangle({win(cx + r * unit(rng), cy + r * unit(rng)), win(cx + r * unit(rng), cy + r * unit(rng)),
                       win(cx + r * unit(rng), cy + r * unit(rng))},
                      CullMode::None, FrontFace::Ccw, vp, s) != SetupResult::Ready)
      continue;
    ++(s.x1 - s.x0 < 4 ? narrow : wide);
    for (int py = s.y0; py <= s.y1; ++py) {
      const Span span = coveredSpan(s, py);
      for (int px = s.x0 - 1; px <= s.x1 + 1; ++px) {
        bool inside = px >= 0 && px < vp.width;
        for (const EdgeFunction& e : s.edges) inside = inside && e.at(px, py) > 0;
        ASSERT_EQ(px >= span.xBegin && px < span.xEnd, inside) << "triangle " << t << " pixel " << px << "," << py;
      }
    }
  }
  EXPECT_GT(narrow, 500);
  EXPECT_GT(wide, 500);
}

TEST(Raster, RowRangeLimitsTheRows) {
  const Viewport vp{10, 10};
  TriangleSetup s;
  ASSERT_EQ(setupTriangle({win(0, 0), win(10, 0), win(0, 10)}, CullMode::None, FrontFace::Ccw, vp, s), SetupResult::Ready);
  int minRow = 100, maxRow = -1;
  rasterizeTriangle(s, 3, 6, [&](int py, Span) {
    minRow = std::min(minRow, py);
    maxRow = std::max(maxRow, py);
  });
  EXPECT_EQ(minRow, 3);
  EXPECT_EQ(maxRow, 5);  // end row exclusive
}

void expectFanCoversDiskOnce(vec2 centre, int triangles, float radius) {
  const Viewport vp{100, 100};
  std::vector<int> count(100 * 100, 0);
  constexpr float kTwoPi = 6.28318530718f;
  for (int i = 0; i < triangles; ++i) {
    const float a0 = kTwoPi * static_cast<float>(i) / static_cast<float>(triangles);
    const float a1 = kTwoPi * static_cast<float>(i + 1) / static_cast<float>(triangles);
    accumulate({win(centre.x, centre.y), win(centre.x + radius * std::cos(a0), centre.y + radius * std::sin(a0)),
                win(centre.x + radius * std::cos(a1), centre.y + radius * std::sin(a1))},
               vp, count);
  }
  int covered = 0;
  for (int py = 0; py < 100; ++py) {
    for (int px = 0; px < 100; ++px) {
      const int c = count[static_cast<std::size_t>(py * 100 + px)];
      ASSERT_LE(c, 1) << "pixel " << px << "," << py << " covered twice";
      // Well inside the fan's polygon (inradius radius * cos(pi / n)) every pixel is covered.
      const float d = glm::length(vec2(px + 0.5f, py + 0.5f) - centre);
      if (d < radius * std::cos(3.14159265f / static_cast<float>(triangles)) - 1.0f) {
        ASSERT_EQ(c, 1) << "crack at pixel " << px << "," << py;
      }
      covered += c;
    }
  }
  EXPECT_GT(covered, 0);
}

TEST(Raster, FanAroundAPixelCentreCoversEveryPixelExactlyOnce) { expectFanCoversDiskOnce({50.5f, 50.5f}, 64, 40.0f); }

TEST(Raster, FanAroundAPixelCornerCoversEveryPixelExactlyOnce) { expectFanCoversDiskOnce({50.0f, 50.0f}, 37, 45.0f); }

TEST(Raster, FanAroundAnArbitraryPointCoversEveryPixelExactlyOnce) {
  expectFanCoversDiskOnce({49.2371f, 51.8113f}, 200, 44.0f);
}

TEST(Raster, SliverBetweenPixelCentresCoversNothing) {
  const Viewport vp{20, 20};
  std::vector<int> count(20 * 20, 0);
  // A long thin triangle between the pixel-centre rows y = 5.5 and y = 6.5.
  accumulate({win(0.2f, 5.7f), win(19.8f, 5.9f), win(0.2f, 6.1f)}, vp, count);
  for (int c : count) EXPECT_EQ(c, 0);
}

TEST(Raster, TriangleFarLargerThanTheScreenFillsItExactly) {
  const Viewport vp{64, 48};
  const ClipConfig config = makeClipConfig(ClipSwitches{}, 0, vp.width, vp.height);
  std::vector<int> count(64 * 48, 0);
  accumulateClipped({-1e4f, -1e4f, 0, 1}, {3e4f, -1e4f, 0, 1}, {-1e4f, 3e4f, 0, 1}, config, vp, count);
  for (int c : count) ASSERT_EQ(c, 1);
}

TEST(Raster, HugeTriangleWithSidePlanesOffStaysWithinTheGuardBand) {
  const Viewport vp{64, 48};
  ClipSwitches frustum;
  frustum.left = frustum.right = frustum.bottom = frustum.top = false;
  const ClipConfig config = makeClipConfig(frustum, 0, vp.width, vp.height);
  std::vector<int> count(64 * 48, 0);
  accumulateClipped({-1e9f, -1e9f, 0, 1}, {3e9f, -1e9f, 0, 1}, {-1e9f, 3e9f, 0, 1}, config, vp, count);
  for (int c : count) ASSERT_EQ(c, 1);
}

TEST(Raster, TwoTrianglesSharingADiagonalCoverTheSquareOnce) {
  const Viewport vp{32, 32};
  std::vector<int> count(32 * 32, 0);
  accumulate({win(3.3f, 2.7f), win(29.1f, 4.2f), win(27.6f, 30.9f)}, vp, count);
  accumulate({win(3.3f, 2.7f), win(27.6f, 30.9f), win(1.9f, 28.4f)}, vp, count);
  int covered = 0;
  for (int c : count) {
    ASSERT_LE(c, 1);
    covered += c;
  }
  EXPECT_GT(covered, 600);
}

}  // namespace
}  // namespace twr
