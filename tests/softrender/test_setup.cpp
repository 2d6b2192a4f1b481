// Setup: divide by w, viewport, snapping, culling and the fill rule's edge functions.
#include "softrender/clip.h"
#include "softrender/raster.h"
#include "softrender/setup.h"

#include <gtest/gtest.h>

#include <cmath>

namespace twr {
namespace {

WindowVertex win(float x, float y) {
  WindowVertex v;
  v.x = x;
  v.y = y;
  v.z = 0.5f;
  v.invW = 1.0f;
  return v;
}

TEST(Setup, ViewportTransformIsGlBottomLeft) {
  const Viewport vp{100, 50};
  // ndc (0.25, -0.25, 0.1): window x = 0.25 * 50 + 50, y = -0.25 * 25 + 25, z = 0.05 + 0.5.
  for (bool fused : {true, false}) {
    const WindowVertex w = windowFromClip(vec4(0.5f, -0.5f, 0.2f, 2.0f), vp, fused);
    EXPECT_FLOAT_EQ(w.x, 62.5f);
    EXPECT_FLOAT_EQ(w.y, 18.75f);
    EXPECT_FLOAT_EQ(w.z, 0.55f);
    EXPECT_FLOAT_EQ(w.invW, 0.5f);
  }
  // NDC (-1, -1) is the bottom-left corner of the window, (1, 1) the top-right.
  EXPECT_FLOAT_EQ(windowFromClip(vec4(-1, -1, 0, 1), vp, true).x, 0.0f);
  EXPECT_FLOAT_EQ(windowFromClip(vec4(1, 1, 0, 1), vp, true).y, 50.0f);
}

TEST(Setup, SnapsToEightSubpixelBitsRoundingHalfToEven) {
  EXPECT_EQ(snapToSubpixel(0.5f), 0);        // a pixel centre is an integer multiple of 256
  EXPECT_EQ(snapToSubpixel(10.5f), 10 * 256);
  EXPECT_EQ(snapToSubpixel(10.5f + 1.0f / 256), 10 * 256 + 1);
  EXPECT_EQ(snapToSubpixel(10.5f + 1.0f / 512), 10 * 256);      // 2560.5 -> 2560 (even)
  EXPECT_EQ(snapToSubpixel(10.5f + 3.0f / 512), 10 * 256 + 2);  // 2561.5 -> 2562 (even)
  EXPECT_EQ(snapToSubpixel(0.0f), -128);
  EXPECT_EQ(snapToSubpixel(1e30f), static_cast<std::int32_t>((kMaxWindowCoord - 0.5f) * 256));
  EXPECT_EQ(snapToSubpixel(std::numeric_limits<float>::quiet_NaN()), static_cast<std::int32_t>((-kMaxWindowCoord - 0.5f) * 256));
}

TEST(Setup, FacingAndCulling) {
  const Viewport vp{16, 16};
  const std::array<WindowVertex, 3> ccw{win(1, 1), win(9, 1), win(1, 9)};
  const std::array<WindowVertex, 3> cw{win(1, 1), win(1, 9), win(9, 1)};
  TriangleSetup s;
  EXPECT_EQ(setupTriangle(ccw, CullMode::Back, FrontFace::Ccw, vp, s), SetupResult::Ready);
  EXPECT_TRUE(s.frontFacing);
  EXPECT_EQ(setupTriangle(cw, CullMode::Back, FrontFace::Ccw, vp, s), SetupResult::CulledBack);
  EXPECT_EQ(setupTriangle(ccw, CullMode::Front, FrontFace::Ccw, vp, s), SetupResult::CulledFront);
  EXPECT_EQ(setupTriangle(cw, CullMode::Back, FrontFace::Cw, vp, s), SetupResult::Ready);
  EXPECT_TRUE(s.frontFacing);
  EXPECT_EQ(setupTriangle(cw, CullMode::None, FrontFace::Ccw, vp, s), SetupResult::Ready);
  EXPECT_FALSE(s.frontFacing);
}

TEST(Setup, SameCoverageWhicheverTheWinding) {
  const Viewport vp{16, 16};
  TriangleSetup a, b;
  ASSERT_EQ(setupTriangle({win(1.3f, 0.7f), win(12.1f, 3.5f), win(4.5f, 14.5f)}, CullMode::None, FrontFace::Ccw, vp, a), SetupResult::Ready);
  ASSERT_EQ(setupTriangle({win(1.3f, 0.7f), win(4.5f, 14.5f), win(12.1f, 3.5f)}, CullMode::None, FrontFace::Ccw, vp, b), SetupResult::Ready);
  for (int y = 0; y < 16; ++y)
    for (int x = 0; x < 16; ++x) EXPECT_EQ(coversPixel(a, x, y), coversPixel(b, x, y)) << x << "," << y;
}

TEST(Setup, ZeroAreaAfterSnappingIsRejected) {
  const Viewport vp{16, 16};
  TriangleSetup s;
  // The third vertex is 1/1024 px off the line through the first two: snapped, it is on it.
  EXPECT_EQ(setupTriangle({win(1, 1), win(9, 9), win(5.0f + 1.0f / 1024, 5)}, CullMode::None, FrontFace::Ccw, vp, s),
            SetupResult::ZeroArea);
  EXPECT_EQ(setupTriangle({win(3, 3), win(3, 3), win(7, 2)}, CullMode::None, FrontFace::Ccw, vp, s), SetupResult::ZeroArea);
}

TEST(Setup, LeftAndBottomEdgesOwnThePixelCentresOnThem) {
  // Two triangles tiling the rectangle [2.5, 5.5] x [1.5, 4.5], whose sides run exactly
  // through pixel centres: the left column (x = 2) and the bottom row (y = 1) are in, the
  // right column (x = 5) and the top row (y = 4) are out (GL on llvmpipe, origin bottom-left).
  const Viewport vp{8, 8};
  TriangleSetup lower, upper;
  ASSERT_EQ(setupTriangle({win(2.5f, 1.5f), win(5.5f, 1.5f), win(5.5f, 4.5f)}, CullMode::None, FrontFace::Ccw, vp, lower), SetupResult::Ready);
  ASSERT_EQ(setupTriangle({win(2.5f, 1.5f), win(5.5f, 4.5f), win(2.5f, 4.5f)}, CullMode::None, FrontFace::Ccw, vp, upper), SetupResult::Ready);
  for (int y = 0; y < 8; ++y) {
    for (int x = 0; x < 8; ++x) {
      const int count = (coversPixel(lower, x, y) ? 1 : 0) + (coversPixel(upper, x, y) ? 1 : 0);
      const bool inside = x >= 2 && x <= 4 && y >= 1 && y <= 3;
      EXPECT_EQ(count, inside ? 1 : 0) << "pixel " << x << "," << y;
    }
  }
}

TEST(Setup, EdgeValuesAreTwiceTheAreaTowardsThePixel) {
  // Corners (0,0), (0,2), (2,0) px after removing the centre offset (clockwise), pixel (0,1):
  // E = (Y_i - Y_j)(X_i - X) - (X_i - X_j)(Y_i - Y), in 1/256 px units, plus the left-edge bias.
  const Viewport vp{4, 4};
  TriangleSetup s;
  ASSERT_EQ(setupTriangle({win(0.5f, 0.5f), win(0.5f, 2.5f), win(2.5f, 0.5f)}, CullMode::None, FrontFace::Ccw, vp, s), SetupResult::Ready);
  EXPECT_EQ(s.doubleAreaFixed, 512LL * 512);
  // Edge 0 from (0,0) to (0,512) is the left edge: E = (0-512)(0-0) - 0 + 1 = 1 at (0, 1).
  EXPECT_EQ(s.edges[0].at(0, 1), 1);
  EXPECT_TRUE(s.edges[0].ownsPixelsOnIt);
  // Edge 2 from (512,0) to (0,0) is the bottom edge (horizontal, going left): also biased.
  EXPECT_TRUE(s.edges[2].ownsPixelsOnIt);
  EXPECT_FALSE(s.edges[1].ownsPixelsOnIt);
  EXPECT_TRUE(coversPixel(s, 0, 0));
  EXPECT_TRUE(coversPixel(s, 1, 0));
  EXPECT_FALSE(coversPixel(s, 1, 1));  // on the hypotenuse: a right edge, not owned
}

// The fast path bins a triangle by the pixels whose centres its corners' extent holds: every
// covered pixel must be among them, and a sliver between centres gives none.
TEST(Setup, PixelCentreBoxHoldsEveryCoveredPixel) {
  const Viewport vp{12, 12};
  std::uint32_t state = 12345u;
  const auto next = [&] {  // a small LCG: the same triangles on every run
    state = state * 1664525u + 1013904223u;
    return static_cast<float>(state >> 8) / static_cast<float>(1u << 24);
  };
  int covering = 0, emptyBoxes = 0;
  for (int n = 0; n < 4000; ++n) {
    // Corners within a 3 px square (sometimes exactly on centres), so most boxes are small.
    const float ox = 1.0f + 8.0f * next(), oy = 1.0f + 8.0f * next();
    std::array<WindowVertex, 3> w{};
    for (WindowVertex& v : w) {
      v = win(ox + 3.0f * next(), oy + 3.0f * next());
      if (n % 5 == 0) v = win(std::floor(v.x) + 0.5f, std::floor(v.y) + 0.5f);
    }
    TriangleSetup s;
    if (setupTriangle(w, CullMode::None, FrontFace::Ccw, vp, s) != SetupResult::Ready) continue;
    const PixelBox box = pixelCentreBox(s);
    EXPECT_GE(box.x0, s.x0);
    EXPECT_LE(box.x1, s.x1);
    EXPECT_GE(box.y0, s.y0);
    EXPECT_LE(box.y1, s.y1);
    bool any = false;
    for (int y = 0; y < vp.height; ++y) {
      for (int x = 0; x < vp.width; ++x) {
        if (!coversPixel(s, x, y)) continue;
        any = true;
        EXPECT_TRUE(x >= box.x0 && x <= box.x1 && y >= box.y0 && y <= box.y1) << "triangle " << n << " pixel " << x << "," << y;
      }
    }
    covering += any ? 1 : 0;
    emptyBoxes += box.empty() ? 1 : 0;
  }
  EXPECT_GT(covering, 1000);   // the property was checked on many covered pixels
  EXPECT_GT(emptyBoxes, 100);  // and the box does reject slivers
  // A triangle inside one pixel, between its centre and its neighbours': nothing to bin.
  TriangleSetup tiny;
  ASSERT_EQ(setupTriangle({win(3.6f, 3.6f), win(4.4f, 3.6f), win(3.6f, 4.4f)}, CullMode::None, FrontFace::Ccw, vp, tiny),
            SetupResult::Ready);
  EXPECT_FALSE(tiny.x0 > tiny.x1 || tiny.y0 > tiny.y1);  // llvmpipe's box holds pixel 3
  EXPECT_TRUE(pixelCentreBox(tiny).empty());
}

TEST(Setup, WindowPositionStaysFiniteNearWZero) {
  const Viewport vp{64, 64};
  // Depth clamp lets z / w grow without bound near w = 0: clamped to kMaxNdcDepth, so window z
  // stays finite (every fragment's depth is clamped to [0, 1] later anyway).
  const WindowVertex deep = windowFromClip(vec4(0.0f, 0.0f, -1e30f, 1e-30f), vp, true);
  EXPECT_TRUE(std::isfinite(deep.z));
  EXPECT_FLOAT_EQ(deep.z, -0.5f * kMaxNdcDepth + 0.5f);
  // A subnormal or zero w (the apex) takes 1 / kMinClipW instead of an infinite reciprocal.
  for (float w : {0.0f, 1e-40f}) {
    const WindowVertex apex = windowFromClip(vec4(0.0f, 0.0f, 1.0f, w), vp, false);
    EXPECT_FLOAT_EQ(apex.invW, 1.0f / kMinClipW) << w;
    EXPECT_FLOAT_EQ(apex.x, 32.0f) << w;
    EXPECT_TRUE(std::isfinite(apex.z)) << w;
  }
  // Ordinary values are untouched: z / w = 2 (behind far with depth clamp) gives 1.5.
  EXPECT_FLOAT_EQ(windowFromClip(vec4(0.0f, 0.0f, 2.0f, 1.0f), vp, true).z, 1.5f);
}

}  // namespace
}  // namespace twr
