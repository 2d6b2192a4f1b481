// Interpolation: screen-space barycentrics, linear depth, perspective-correct varyings.
#include "softrender/interpolate.h"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>

namespace twr {
namespace {

constexpr float kEps = 1e-6f;

WindowVertex win(float x, float y, float z, float invW) {
  WindowVertex v;
  v.x = x;
  v.y = y;
  v.z = z;
  v.invW = invW;
  return v;
}

TriangleSetup triangleSetupFor(const std::array<WindowVertex, 3>& w) {
  TriangleSetup s;
  EXPECT_EQ(setupTriangle(w, CullMode::None, FrontFace::Ccw, Viewport{64, 64}, s), SetupResult::Ready);
  return s;
}

InterpolationSetup setupFor(const std::array<WindowVertex, 3>& w, const std::array<vec2, 3>& uv = {}) {
  return makeInterpolationSetup(w, uv, triangleSetupFor(w));
}

// The fragment at (px, py) of the triangle w with vertices v0, v1, v2.
Fragment fragmentAt(const std::array<WindowVertex, 3>& w, const ClipVertex& v0, const ClipVertex& v1,
                    const ClipVertex& v2, bool tangentLighting, int lightCount, int px, int py) {
  const TriangleSetup s = triangleSetupFor(w);
  const VaryingPlanes planes = makeVaryingPlanes(w, v0, v1, v2, tangentLighting, lightCount, s);
  return interpolateFragment(planes, px, py, pixelWeights(makeInterpolationSetup(w, {v0.uv, v1.uv, v2.uv}, s), px, py).depth);
}

TEST(Interpolate, BarycentricsAtTheCornersArePure) {
  // Corners on pixel centres (0.5, 0.5), (10.5, 0.5), (0.5, 10.5).
  const InterpolationSetup s = setupFor({win(0.5f, 0.5f, 0.1f, 1), win(10.5f, 0.5f, 0.2f, 1), win(0.5f, 10.5f, 0.3f, 1)});
  const PixelWeights a = pixelWeights(s, 0, 0), b = pixelWeights(s, 10, 0), c = pixelWeights(s, 0, 10);
  EXPECT_NEAR(a.screen[0], 1.0f, kEps);
  EXPECT_NEAR(b.screen[1], 1.0f, kEps);
  EXPECT_NEAR(c.screen[2], 1.0f, kEps);
  EXPECT_NEAR(b.depth, 0.2f, kEps);
  // Pixel (5, 0): halfway along the bottom edge.
  const PixelWeights m = pixelWeights(s, 5, 0);
  EXPECT_NEAR(m.screen[0], 0.5f, kEps);
  EXPECT_NEAR(m.screen[1], 0.5f, kEps);
  EXPECT_NEAR(m.screen[2], 0.0f, kEps);
  EXPECT_NEAR(m.depth, 0.15f, kEps);  // depth is linear in screen space
}

TEST(Interpolate, VaryingsArePerspectiveCorrect) {
  // w = 1 at corner 0, w = 2 at corner 1: halfway in screen space the weights are
  // (0.5 / 1, 0.5 / 2) / (0.5 + 0.25) = (2/3, 1/3), not (1/2, 1/2).
  const std::array<WindowVertex, 3> window{win(0.5f, 0.5f, 0.0f, 1.0f), win(10.5f, 0.5f, 1.0f, 0.5f),
                                           win(0.5f, 10.5f, 0.0f, 1.0f)};
  const InterpolationSetup s = setupFor(window, {vec2(0, 0), vec2(3, 0), vec2(0, 3)});
  const PixelWeights w = pixelWeights(s, 5, 0);
  EXPECT_NEAR(w.perspective[0], 2.0f / 3.0f, 1e-6f);
  EXPECT_NEAR(w.perspective[1], 1.0f / 3.0f, 1e-6f);
  ClipVertex v0, v1, v2;
  v0.uv = vec2(0, 0);
  v1.uv = vec2(3, 0);
  v2.uv = vec2(0, 3);
  v0.nWorld = vec3(0, 0, 1);
  v1.nWorld = vec3(0, 0, 1);
  v2.nWorld = vec3(0, 0, 1);
  v1.posWorld = vec3(3, 0, 0);
  const Fragment f = fragmentAt(window, v0, v1, v2, false, 0, 5, 0);
  EXPECT_NEAR(f.uv.x, 1.0f, 1e-5f);  // 3 * 1/3
  EXPECT_NEAR(f.posWorld.x, 1.0f, 1e-5f);
  EXPECT_NEAR(f.depth, 0.5f, 1e-6f);
}

// The same triangle with affine interpolation: the varying is linear on the screen (halfway
// between the corners reads halfway between their values), the 1/w plane is exactly 1, so the
// divide changes no bit, and the depth is the same z plane as perspective's.
TEST(Interpolate, AffineVaryingsAreLinearOnTheScreen) {
  const std::array<WindowVertex, 3> window{win(0.5f, 0.5f, 0.0f, 1.0f), win(10.5f, 0.5f, 1.0f, 0.5f),
                                           win(0.5f, 10.5f, 0.0f, 1.0f)};
  const TriangleSetup setup = triangleSetupFor(window);
  const std::array<vec2, 3> uvs{vec2(0, 0), vec2(3, 0), vec2(0, 3)};
  const InterpolationSetup perspective = makeInterpolationSetup(window, uvs, setup);
  const InterpolationSetup affine = makeInterpolationSetup(window, uvs, setup, Interpolation::Affine);
  const PixelWeights w = pixelWeights(affine, 5, 0);
  EXPECT_NEAR(w.perspective[0], 0.5f, 1e-6f);  // the weights applied are the screen's
  EXPECT_NEAR(w.perspective[1], 0.5f, 1e-6f);
  EXPECT_EQ(w.depth, pixelWeights(perspective, 5, 0).depth);
  ClipVertex v0, v1, v2;
  v0.uv = uvs[0];
  v1.uv = uvs[1];
  v2.uv = uvs[2];
  v1.posWorld = vec3(3, 0, 0);
  const VaryingPlanes planes = makeVaryingPlanes(window, v0, v1, v2, false, 0, setup, Interpolation::Affine);
  EXPECT_EQ(planes.oneOverW.atOrigin, 1.0f);
  EXPECT_EQ(planes.oneOverW.dx, 0.0f);
  EXPECT_EQ(planes.oneOverW.dy, 0.0f);
  const Fragment f = interpolateFragment(planes, 5, 0, w.depth);
  EXPECT_NEAR(f.uv.x, 1.5f, 1e-5f);  // 3 * 1/2, where perspective reads 1
  EXPECT_NEAR(f.posWorld.x, 1.5f, 1e-5f);
  // Bit for bit the plane's own value: no multiply by a w that is not 1.
  const AttributePlaneT<float>& u = planes.overW[kVaryingUv];
  EXPECT_EQ(f.uv.x, std::fma(u.dy, 0.0f, std::fma(u.dx, 5.0f, u.atOrigin)));
  // And the uv the sampler's LOD is taken from comes from the same affine planes.
  EXPECT_EQ(affine.uv.oneOverW.atOrigin, 1.0f);
  EXPECT_NEAR(w.uv.x, 1.5f, 1e-5f);
}

TEST(Interpolate, DepthIsClampedToTheDepthRange) {
  // Window depths outside [0, 1] (near/far planes off, GL depth clamp) clamp per pixel.
  const InterpolationSetup s = setupFor({win(0.5f, 0.5f, -0.5f, 1), win(10.5f, 0.5f, 1.5f, 1), win(0.5f, 10.5f, -0.5f, 1)});
  EXPECT_EQ(pixelWeights(s, 0, 0).depth, 0.0f);
  EXPECT_EQ(pixelWeights(s, 10, 0).depth, 1.0f);
  EXPECT_NEAR(pixelWeights(s, 5, 0).depth, 0.5f, kEps);
}

TEST(Interpolate, DegenerateUvsStayConstantAndFinite) {
  const vec2 uv(0.25f, 0.75f);
  const std::array<WindowVertex, 3> window{win(0.5f, 0.5f, 0.5f, 1), win(30.5f, 2.5f, 0.5f, 0.25f),
                                           win(3.5f, 40.5f, 0.5f, 2)};
  ClipVertex v0, v1, v2;
  v0.uv = v1.uv = v2.uv = uv;
  for (int py = 0; py < 40; py += 7) {
    for (int px = 0; px < 30; px += 5) {
      const Fragment f = fragmentAt(window, v0, v1, v2, false, 0, px, py);
      EXPECT_NEAR(f.uv.x, 0.25f, 1e-5f);
      EXPECT_NEAR(f.uv.y, 0.75f, 1e-5f);
    }
  }
}

TEST(Interpolate, TangentSpaceVaryingsOnlyWhenAsked) {
  const std::array<WindowVertex, 3> window{win(0.5f, 0.5f, 0, 1), win(10.5f, 0.5f, 0, 1), win(0.5f, 10.5f, 0, 1)};
  ClipVertex v0, v1, v2;
  v0.lightDirTangent[0] = v1.lightDirTangent[0] = v2.lightDirTangent[0] = vec3(1, 2, 3);
  v0.lightDirTangent[1] = v1.lightDirTangent[1] = v2.lightDirTangent[1] = vec3(7, 8, 9);
  v0.eyeDirTangent = v1.eyeDirTangent = v2.eyeDirTangent = vec3(4, 5, 6);
  const Fragment tangent = fragmentAt(window, v0, v1, v2, true, 1, 2, 2);
  EXPECT_NEAR(tangent.lightDirTangent[0].z, 3.0f, 1e-5f);
  EXPECT_EQ(tangent.lightDirTangent[1], vec3(0.0f));  // only the first lightCount lights
  EXPECT_NEAR(tangent.eyeDirTangent.y, 5.0f, 1e-5f);
  const Fragment world = fragmentAt(window, v0, v1, v2, false, 0, 2, 2);
  EXPECT_EQ(world.eyeDirTangent, vec3(0.0f));
  EXPECT_EQ(world.lightDirTangent[0], vec3(0.0f));
}

// Every varying is interpolated as the uv is (llvmpipe's planes): a varying holding the same
// corner values as u has the same bits as u at every pixel, however the triangle is oriented.
TEST(Interpolate, EveryVaryingHasTheUvsBits) {
  const std::array<std::array<WindowVertex, 3>, 2> triangles{{
      {win(0.5f, 0.5f, 0.1f, 1.0f), win(37.3f, 5.1f, 0.2f, 0.31f), win(7.7f, 41.9f, 0.3f, 1.7f)},  // ccw
      {win(0.5f, 0.5f, 0.1f, 1.0f), win(7.7f, 41.9f, 0.3f, 1.7f), win(37.3f, 5.1f, 0.2f, 0.31f)},  // cw
  }};
  const std::array<float, 3> values{0.1f, 2.7f, -1.3f};
  std::array<ClipVertex, 3> v;
  for (std::size_t i = 0; i < 3; ++i) {
    v[i].uv = vec2(values[i], 0.0f);
    v[i].posWorld = vec3(values[i]);
    v[i].tWorld = vec3(values[i]);
    v[i].eyeDirTangent = vec3(values[i]);
    v[i].lightDirTangent[2] = vec3(values[i]);
  }
  int compared = 0;
  for (const std::array<WindowVertex, 3>& window : triangles) {
    for (int py = 0; py < 42; py += 3) {
      for (int px = 0; px < 38; px += 3) {
        const Fragment f = fragmentAt(window, v[0], v[1], v[2], true, 3, px, py);
        EXPECT_EQ(f.posWorld.y, f.uv.x);
        EXPECT_EQ(f.tWorld.z, f.uv.x);
        EXPECT_EQ(f.eyeDirTangent.x, f.uv.x);
        EXPECT_EQ(f.lightDirTangent[2].y, f.uv.x);
        ++compared;
      }
    }
  }
  EXPECT_GT(compared, 300);
}

TEST(Interpolate, CollinearFloatPositionsFallBackToTheSnappedOnes) {
  // Float positions on one line (no area), but they snap to a triangle with area.
  const std::array<WindowVertex, 3> w{win(1.0f, 1.0f, 0.2f, 1), win(9.0f, 9.0f, 0.4f, 1), win(5.0f, 5.0f, 0.6f, 1)};
  TriangleSetup snapped;
  snapped.xFixed = {128, 2176, 1152};  // (1, 1), (9, 9), (5.0039, 5) px minus the centre offset
  snapped.yFixed = {128, 2176, 1151};
  const InterpolationSetup s = makeInterpolationSetup(w, {vec2(0.25f, 0.5f), vec2(0.25f, 0.5f), vec2(0.25f, 0.5f)}, snapped);
  const PixelWeights p = pixelWeights(s, 4, 4);
  EXPECT_TRUE(std::isfinite(p.screen[0]) && std::isfinite(p.screen[1]) && std::isfinite(p.screen[2]));
  EXPECT_NEAR(p.screen[0] + p.screen[1] + p.screen[2], 1.0f, 1e-5f);
  EXPECT_TRUE(std::isfinite(p.depth));
  // The uv planes would divide by the zero float area: they hold the first corner's uv.
  EXPECT_EQ(p.uv, vec2(0.25f, 0.5f));
  // So do the other varyings' planes: the first vertex's values, finite.
  ClipVertex v0, v1, v2;
  v0.posWorld = vec3(1, 2, 3);
  v1.posWorld = vec3(4, 5, 6);
  v2.posWorld = vec3(7, 8, 9);
  const Fragment f = interpolateFragment(makeVaryingPlanes(w, v0, v1, v2, false, 0, snapped), 4, 4, p.depth);
  EXPECT_EQ(f.posWorld, vec3(1, 2, 3));
}

// planeSumsExactInDouble, which lets targets without fused multiply-adds evaluate a plane as
// two double sums rounded once each: where it holds, both sums are exact (Knuth's two-sum
// error is 0) and the result is std::fma's, at pixel indices up to 2^15 and on random planes
// whose coefficients lie from 2^-40 apart to 2^40 apart; where it fails, some sum is inexact
// (the check rejects what it should), and a non-finite coefficient fails it.
TEST(Interpolate, PlaneSumsExactInDoubleHoldsOnlyWhereBothSumsAreExact) {
  std::mt19937 rng(42);
  std::uniform_int_distribution<std::uint32_t> mantissa(1u << 23, (1u << 24) - 1);
  std::uniform_int_distribution<int> exponent(-20, 20), spread(-20, 40), coin(0, 7);
  std::uniform_int_distribution<int> pixel(0, 1 << 15);
  const auto coefficient = [&](int e) {
    if (coin(rng) == 0) return 0.0f;
    const float sign = coin(rng) % 2 == 0 ? 1.0f : -1.0f;
    return sign * std::ldexp(static_cast<float>(mantissa(rng)), e - 23);
  };
  const auto exactSum = [](double p, double c) {
    const double s = p + c, cPart = s - p, pPart = s - cPart;
    return (p - pPart) + (c - cPart) == 0.0;
  };
  int accepted = 0, rejected = 0, rejectedInexact = 0, wrongBits = 0, acceptedInexact = 0;
  for (int plane = 0; plane < 20000; ++plane) {
    const int e = exponent(rng);
    const AttributePlaneT<float> p{coefficient(e), coefficient(e - spread(rng)), coefficient(e - spread(rng))};
    const bool exact = planeSumsExactInDouble(p);
    bool allSumsExact = true;
    for (int k = 0; k < 16; ++k) {
      const int px = k == 0 ? 0 : k == 1 ? 1 << 15 : pixel(rng), py = k == 2 ? 1 << 15 : k == 3 ? 0 : pixel(rng);
      const double inner = static_cast<double>(p.dx) * px + static_cast<double>(p.atOrigin);
      const float innerFloat = static_cast<float>(inner);
      const double outer = static_cast<double>(p.dy) * py + static_cast<double>(innerFloat);
      allSumsExact = allSumsExact && exactSum(static_cast<double>(p.dx) * px, p.atOrigin) &&
                     exactSum(static_cast<double>(p.dy) * py, innerFloat);
      const float expected = std::fma(p.dy, static_cast<float>(py), std::fma(p.dx, static_cast<float>(px), p.atOrigin));
      if (exact && std::bit_cast<std::uint32_t>(static_cast<float>(outer)) != std::bit_cast<std::uint32_t>(expected)) {
        ++wrongBits;
      }
    }
    if (exact) {
      ++accepted;
      if (!allSumsExact) ++acceptedInexact;
    } else {
      ++rejected;
      if (!allSumsExact) ++rejectedInexact;
    }
  }
  EXPECT_EQ(wrongBits, 0);
  EXPECT_EQ(acceptedInexact, 0);
  EXPECT_GT(accepted, 5000);
  EXPECT_GT(rejected, 1000);
  EXPECT_GT(rejectedInexact, rejected / 2) << "the check rejects planes whose sums are exact";

  const float inf = std::numeric_limits<float>::infinity();
  EXPECT_TRUE(planeSumsExactInDouble({0.0f, 0.0f, 0.0f}));
  EXPECT_TRUE(planeSumsExactInDouble({0.5f, 1e-3f, -2e-3f}));
  EXPECT_FALSE(planeSumsExactInDouble({1.0f, 1e-12f, 0.0f}));  // a gradient far below the value
  EXPECT_FALSE(planeSumsExactInDouble({inf, 0.0f, 0.0f}));
  EXPECT_FALSE(planeSumsExactInDouble({0.0f, std::numeric_limits<float>::quiet_NaN(), 0.0f}));
}

}  // namespace
}  // namespace twr
