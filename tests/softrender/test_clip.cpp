// Homogeneous clipping: hand-checked polygons, planes, attributes and vertex bounds.
#include "softrender/clip.h"
#include "softrender/clip_steps.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

namespace twr {
namespace {

constexpr float kEps = 1e-5f;

ClipVertex at(vec4 posClip, vec2 uv = vec2(0.0f)) {
  ClipVertex v;
  v.posClip = posClip;
  v.posWorld = vec3(posClip);
  v.uv = uv;
  return v;
}

ClipConfig allPlanes(int userPlanes = 0) { return makeClipConfig(ClipSwitches{}, userPlanes, 100, 100); }

void expectNear(vec4 a, vec4 b, float eps = kEps) {
  EXPECT_NEAR(a.x, b.x, eps);
  EXPECT_NEAR(a.y, b.y, eps);
  EXPECT_NEAR(a.z, b.z, eps);
  EXPECT_NEAR(a.w, b.w, eps);
}

TEST(Clip, TriangleInsideIsUntouched) {
  ClipPolygon out, scratch;
  const ClipVertex a = at({-0.5f, -0.5f, 0, 1}), b = at({0.5f, -0.5f, 0, 1}), c = at({0, 0.5f, 0, 1});
  EXPECT_EQ(clipTriangle(a, b, c, allPlanes(), out, scratch), 0u);
  ASSERT_EQ(out.count, 3);
  EXPECT_EQ(out.v[0].posClip, a.posClip);
  EXPECT_EQ(out.v[2].posClip, c.posClip);
  EXPECT_FALSE(out.v[1].fromClipper);
}

TEST(Clip, VertexExactlyOnAPlaneIsInside) {
  ClipPolygon out, scratch;
  // x = w (right plane) and z = -w (near plane), distance exactly 0.
  const ClipVertex a = at({1, 0, 0, 1}), b = at({0, 0.5f, -1, 1}), c = at({0, -0.5f, 0, 1});
  EXPECT_EQ(outcode(a, allPlanes()), 0u);
  EXPECT_EQ(outcode(b, allPlanes()), 0u);
  EXPECT_EQ(clipTriangle(a, b, c, allPlanes(), out, scratch), 0u);
  EXPECT_EQ(out.count, 3);
}

TEST(Clip, TriangleEntirelyOutsideOnePlaneIsRemoved) {
  ClipPolygon out, scratch;
  const std::uint32_t cut =
      clipTriangle(at({2, 0, 0, 1}), at({3, 1, 0, 1}), at({2.5f, -1, 0, 1}), allPlanes(), out, scratch);
  EXPECT_EQ(out.count, 0);
  EXPECT_EQ(cut, 1u << kClipPlaneRight);
}

TEST(Clip, TriangleCrossingWZeroBecomesTheRightQuad) {
  // A and B in front of the camera (w = 1), C behind it (w = -1). Only near (w + z >= 0)
  // bounds the visible part: gamma <= 0.2 in barycentric terms, where |x|, |y| <= w holds.
  // The cuts land at B + 0.2 (C - B) = (0.4, 0, -0.6, 0.6) and A + 0.2 (C - A) = (-0.4, 0, -0.6, 0.6).
  const ClipVertex a = at({-0.5f, 0, 0, 1}, {0, 0}), b = at({0.5f, 0, 0, 1}, {1, 0}), c = at({0, 0, -3, -1}, {0, 1});
  ClipPolygon out, scratch;
  const std::uint32_t cut = clipTriangle(a, b, c, allPlanes(), out, scratch);
  EXPECT_NE(cut & (1u << kClipPlaneNear), 0u);
  ASSERT_EQ(out.count, 4);
  expectNear(out.v[0].posClip, a.posClip);
  expectNear(out.v[1].posClip, b.posClip);
  expectNear(out.v[2].posClip, {0.4f, 0, -0.6f, 0.6f});
  expectNear(out.v[3].posClip, {-0.4f, 0, -0.6f, 0.6f});
  // Varyings follow the same parameter: uv = B + 0.2 (C - B) and A + 0.2 (C - A).
  EXPECT_NEAR(out.v[2].uv.x, 0.8f, kEps);
  EXPECT_NEAR(out.v[2].uv.y, 0.2f, kEps);
  EXPECT_NEAR(out.v[3].uv.x, 0.0f, kEps);
  EXPECT_NEAR(out.v[3].uv.y, 0.2f, kEps);
  EXPECT_NEAR(out.v[2].posWorld.z, -0.6f, kEps);
  EXPECT_TRUE(out.v[2].fromClipper);
  for (int i = 0; i < out.count; ++i) EXPECT_GT(out.v[static_cast<std::size_t>(i)].posClip.w, 0.0f);
}

TEST(Clip, TriangleGainsOneVertexFromEachOfTheSixPlanes) {
  // In the plane x + y + z = 0 the cube |x|,|y|,|z| <= 1 is a hexagon; this triangle's edges
  // (at distance 1.3 from the centre, below the hexagon's circumradius sqrt 2) each cut off one
  // corner, so the result has 6 + 3 = 9 = 3 + 6 vertices.
  const float r = 2.6f / std::sqrt(2.0f);
  const ClipVertex a = at({-r, r, 0, 1}), b = at({0, -r, r, 1}), c = at({r, 0, -r, 1});
  ClipPolygon out, scratch;
  const std::uint32_t cut = clipTriangle(a, b, c, allPlanes(), out, scratch);
  EXPECT_EQ(cut, 0x3Fu);  // all six frustum planes
  ASSERT_EQ(out.count, 9);
  EXPECT_LE(out.count, kMaxClipVertices);
  for (int i = 0; i < out.count; ++i) {
    const vec4 p = out.v[static_cast<std::size_t>(i)].posClip;
    EXPECT_LE(std::fabs(p.x), 1.0f + kEps);
    EXPECT_LE(std::fabs(p.y), 1.0f + kEps);
    EXPECT_LE(std::fabs(p.z), 1.0f + kEps);
    EXPECT_NEAR(p.x + p.y + p.z, 0.0f, kEps);
  }
}

TEST(Clip, UserPlanesAddVerticesWithinTheBound) {
  // Eight user planes each cutting a corner of an already hexagon-clipped triangle still fit.
  const float r = 2.6f / std::sqrt(2.0f);
  ClipVertex a = at({-r, r, 0, 1}), b = at({0, -r, r, 1}), c = at({r, 0, -r, 1});
  const ClipConfig config = allPlanes(kMaxUserClipPlanes);
  for (int j = 0; j < kMaxUserClipPlanes; ++j) {
    // Planes 1.25 - dot(dir_j, p) >= 0: an octagon a little wider than the 9-gon (clipDistance is linear in p).
    const float angle = 6.2831853f * static_cast<float>(j) / kMaxUserClipPlanes;
    const vec3 dir = glm::normalize(vec3(std::cos(angle), std::sin(angle), -std::cos(angle) - std::sin(angle)));
    for (ClipVertex* v : {&a, &b, &c}) v->clipDistance[static_cast<std::size_t>(j)] = 1.25f - glm::dot(dir, vec3(v->posClip));
  }
  ClipPolygon out, scratch;
  clipTriangle(a, b, c, config, out, scratch);
  EXPECT_GT(out.count, 9) << "the octagon cuts the 9-gon into more pieces";
  EXPECT_LE(out.count, kMaxClipVertices);
  for (int i = 0; i < out.count; ++i) {
    for (int j = 0; j < kMaxUserClipPlanes; ++j) {
      EXPECT_GE(out.v[static_cast<std::size_t>(i)].clipDistance[static_cast<std::size_t>(j)], -kEps);
    }
  }
}

TEST(Clip, UserPlaneKeepsThePositiveSide) {
  ClipVertex a = at({-0.5f, -0.5f, 0, 1}), b = at({0.5f, -0.5f, 0, 1}), c = at({0.5f, 0.5f, 0, 1});
  for (ClipVertex* v : {&a, &b, &c}) v->clipDistance[0] = v->posWorld.x;  // keep x >= 0
  ClipPolygon out, scratch;
  const std::uint32_t cut = clipTriangle(a, b, c, allPlanes(1), out, scratch);
  EXPECT_EQ(cut, 1u << kClipPlaneUser0);
  ASSERT_EQ(out.count, 4);
  for (int i = 0; i < out.count; ++i) EXPECT_GE(out.v[static_cast<std::size_t>(i)].posWorld.x, -kEps);
}

TEST(Clip, SharedEdgeGetsTheSameNewVertexEitherWay) {
  const ClipVertex p = at({0.3f, -0.7f, 0.1f, 1}), q = at({2.9f, 0.4f, -0.2f, 1.3f});
  const ClipVertex other1 = at({0, 0.5f, 0, 1}), other2 = at({0.2f, -0.9f, 0, 1});
  ClipPolygon one, two, scratch;
  clipTriangle(p, q, other1, allPlanes(), one, scratch);  // walks p -> q
  clipTriangle(q, p, other2, allPlanes(), two, scratch);  // walks q -> p
  bool found = false;
  for (int i = 0; i < one.count; ++i) {
    for (int j = 0; j < two.count; ++j) {
      if (one.v[static_cast<std::size_t>(i)].fromClipper && one.v[static_cast<std::size_t>(i)].posClip == two.v[static_cast<std::size_t>(j)].posClip) found = true;
    }
  }
  EXPECT_TRUE(found) << "the vertex where edge pq meets x = w must be bit-identical";
}

TEST(Clip, NearOffStillNeverLetsWReachZero) {
  ClipSwitches frustum;
  frustum.near = false;
  const ClipConfig config = makeClipConfig(frustum, 0, 100, 100);
  ClipPolygon out, scratch;
  clipTriangle(at({-0.1f, 0, 0.5f, 1}), at({0.1f, 0, 0.5f, 1}), at({0, 0.05f, -3, -1}), config, out, scratch);
  ASSERT_GE(out.count, 3);
  for (int i = 0; i < out.count; ++i) EXPECT_GE(out.v[static_cast<std::size_t>(i)].posClip.w, kMinClipW * 0.999f);
}

TEST(Clip, SidePlaneOffFallsBackToTheGuardBand) {
  ClipSwitches frustum;
  frustum.right = false;
  const ClipConfig config = makeClipConfig(frustum, 0, 100, 100);
  // x_ndc up to 1 + 2 * 16384 / 100 is kept; a vertex at x_ndc = 1000 is cut to that bound.
  ClipPolygon out, scratch;
  const std::uint32_t cut = clipTriangle(at({0, -0.5f, 0, 1}), at({1000, 0, 0, 1}), at({0, 0.5f, 0, 1}), config, out, scratch);
  EXPECT_EQ(cut, 1u << kClipPlaneRight);
  float maxX = 0.0f;
  for (int i = 0; i < out.count; ++i) maxX = std::fmax(maxX, out.v[static_cast<std::size_t>(i)].posClip.x);
  EXPECT_NEAR(maxX, config.guardBandX, 1e-3f);
  EXPECT_GT(maxX, 300.0f);
}

TEST(Clip, NonFiniteVerticesRemoveTheTriangle) {
  ClipPolygon out, scratch;
  const float inf = std::numeric_limits<float>::infinity();
  EXPECT_EQ(clipTriangle(at({inf, 0, 0, 1}), at({0, 0, 0, 1}), at({0, 1, 0, 1}), allPlanes(), out, scratch),
            kClipNonFiniteBit);
  EXPECT_EQ(out.count, 0);
}

TEST(Clip, SegmentIsCutFromBothEnds) {
  ClipVertex a = at({-3, 0, 0, 1}), b = at({3, 0, 0, 1});
  std::uint32_t cut = 0;
  ASSERT_TRUE(clipSegment(a, b, allPlanes(), cut));
  EXPECT_EQ(cut, (1u << kClipPlaneLeft) | (1u << kClipPlaneRight));
  EXPECT_NEAR(a.posClip.x, -1.0f, kEps);
  EXPECT_NEAR(b.posClip.x, 1.0f, kEps);
  ClipVertex c = at({2, 0, 0, 1}), d = at({3, 0, 0, 1});
  EXPECT_FALSE(clipSegment(c, d, allPlanes(), cut));
}

TEST(Clip, CoordinatesBeyondTheRangeRemoveTheTriangle) {
  // A vertex past kMaxClipCoordinate would let g w or an endpoint difference overflow float:
  // the triangle goes, as for a non-finite position, and outcode says why.
  ClipPolygon out, scratch;
  const ClipVertex a = at({-0.5f, -0.5f, 0, 1}), b = at({0.5f, -0.5f, 0, 1});
  const ClipVertex far = at({0, 2e30f, 0, 1});
  EXPECT_EQ(outcode(far, allPlanes()), kClipNonFiniteBit);
  EXPECT_EQ(clipTriangle(a, b, far, allPlanes(), out, scratch), kClipNonFiniteBit);
  EXPECT_EQ(out.count, 0);
  // At the bound it is still clipped normally.
  const ClipVertex edge = at({0, kMaxClipCoordinate, 0, 1});
  EXPECT_EQ(clipTriangle(a, b, edge, allPlanes(), out, scratch), 1u << kClipPlaneTop);
  EXPECT_GE(out.count, 3);
  // A user clip distance counts only while its plane is active.
  ClipVertex hugeDistance = at({0, 0.5f, 0, 1});
  hugeDistance.clipDistance[0] = 1e31f;
  EXPECT_EQ(clipTriangle(a, b, hugeDistance, allPlanes(1), out, scratch), kClipNonFiniteBit);
  EXPECT_EQ(clipTriangle(a, b, hugeDistance, allPlanes(0), out, scratch), 0u);
  ClipVertex lineEnd = far;
  ClipVertex lineStart = a;
  std::uint32_t cut = 0;
  EXPECT_FALSE(clipSegment(lineStart, lineEnd, allPlanes(), cut));
  EXPECT_EQ(cut, kClipNonFiniteBit);
}

TEST(Clip, GuardBandWithHugeWLeavesEveryCutVertexFinite) {
  // Side planes off (guard band g = 1 + 2 * 16384 / 1 on a 1-pixel viewport) and a vertex
  // with w = 1e30: g w is 3.3e34, no overflow, and every cut vertex stays finite with w > 0.
  ClipSwitches switches;
  switches.left = switches.right = switches.top = switches.bottom = switches.near = switches.far = false;
  const ClipConfig config = makeClipConfig(switches, 0, 1, 1);
  ClipPolygon out, scratch;
  const ClipVertex a = at({-1e30f, 0, 0, 1e-5f}), b = at({1e30f, 1e30f, 0, 1e30f}), c = at({0, -1e30f, 0, 2e-5f});
  clipTriangle(a, b, c, config, out, scratch);
  for (int i = 0; i < out.count; ++i) {
    const vec4& p = out.v[static_cast<std::size_t>(i)].posClip;
    EXPECT_TRUE(std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z) && std::isfinite(p.w)) << i;
    EXPECT_GT(p.w, 0.0f) << i;
    EXPECT_LE(std::fabs(p.x), config.guardBandX * p.w * 1.0001f) << i;
  }
}

// clipTriangleSteps replays clipTriangle's passes: one step per plane of the returned mask, in
// plane order, each cutting the polygon the last one left, the last leaving clipTriangle's
// polygon bit for bit; each vertex a plane made lies on the edge it names, at its t.
// Affine (noperspective) varyings stay linear on the screen across the whole original triangle:
// every vertex the clipper makes carries the uv that screen-space barycentrics over the original
// corners give at its NDC position, while the perspective cut carries clip space's uv (the two
// differ here because the corners' w differ by 4x).
TEST(Clip, AffineCutVerticesKeepTheOriginalTrianglesScreenLinearVaryings) {
  const ClipVertex a = at({-3.0f, -0.5f, 0, 1}, {0, 0}), b = at({2.0f, -0.5f, 0, 4}, {1, 0}),
                   c = at({0.0f, 3.5f, 0, 2}, {0, 1});
  const auto ndc = [](const vec4& p) { return vec2(p.x / p.w, p.y / p.w); };
  const vec2 pa = ndc(a.posClip), pb = ndc(b.posClip), pc = ndc(c.posClip);
  const auto screenLinearUv = [&](vec2 p) {
    const float area = (pb.x - pa.x) * (pc.y - pa.y) - (pb.y - pa.y) * (pc.x - pa.x);
    const float lb = ((p.x - pa.x) * (pc.y - pa.y) - (p.y - pa.y) * (pc.x - pa.x)) / area;
    const float lc = ((pb.x - pa.x) * (p.y - pa.y) - (pb.y - pa.y) * (p.x - pa.x)) / area;
    return (1 - lb - lc) * a.uv + lb * b.uv + lc * c.uv;
  };
  ClipPolygon affine, perspective, scratch;
  const ClipConfig affineConfig = makeClipConfig(ClipSwitches{}, 0, 100, 100, Interpolation::Affine);
  ASSERT_NE(clipTriangle(a, b, c, affineConfig, affine, scratch), 0u);
  ASSERT_NE(clipTriangle(a, b, c, allPlanes(), perspective, scratch), 0u);
  ASSERT_EQ(affine.count, perspective.count);
  int cut = 0;
  float largestPerspectiveError = 0.0f;
  for (int i = 0; i < affine.count; ++i) {
    const ClipVertex& v = affine.v[static_cast<std::size_t>(i)];
    EXPECT_EQ(v.posClip, perspective.v[static_cast<std::size_t>(i)].posClip) << "the polygon does not move";
    if (!v.fromClipper) continue;
    ++cut;
    const vec2 expected = screenLinearUv(ndc(v.posClip));
    EXPECT_NEAR(v.uv.x, expected.x, 1e-5f) << i;
    EXPECT_NEAR(v.uv.y, expected.y, 1e-5f) << i;
    const vec2 other = perspective.v[static_cast<std::size_t>(i)].uv;
    const float error = std::fabs(other.x - expected.x) + std::fabs(other.y - expected.y);
    largestPerspectiveError = std::fmax(largestPerspectiveError, error);
  }
  EXPECT_GE(cut, 2);
  EXPECT_GT(largestPerspectiveError, 0.05f) << "the perspective cut takes clip space's t";
}

TEST(Clip, ScreenLinearTFallsBackToYThenToClipSpacesT) {
  const vec4 from{1, 0, 0, 1}, to{1, 4, 0, 2};  // equal x: the parameter comes from y / w
  const vec4 cut = from + 0.5f * (to - from);    // (1, 2, 0, 1.5): NDC y 4/3 between 0 and 2
  EXPECT_FLOAT_EQ(screenLinearT(from, to, cut, 0.5f), (2.0f / 1.5f) / 2.0f);
  EXPECT_FLOAT_EQ(screenLinearT(from, from, from, 0.25f), 0.25f);
  // On the right plane (x = w) both ends have NDC x 1 though their clip x differ: y again,
  // where Mesa's clipper would divide 0 by 0.
  const vec4 onRight{2, 4, 0, 2};
  const vec4 cutOnRight = from + 0.5f * (onRight - from);  // (1.5, 2, 0, 1.5)
  const float t = screenLinearT(from, onRight, cutOnRight, 0.5f);
  EXPECT_TRUE(std::isfinite(t));
  EXPECT_FLOAT_EQ(t, (2.0f / 1.5f) / 2.0f);
}

TEST(ClipSteps, ReplayTheClippersPassesPlaneByPlane) {
  const float r = 2.6f / std::sqrt(2.0f);
  const std::array<std::array<ClipVertex, 3>, 3> triangles = {{
      {at({-r, r, 0, 1}), at({0, -r, r, 1}), at({r, 0, -r, 1})},          // all six frustum planes
      {at({0.2f, 0.1f, 0.5f, 1}), at({3, 0.2f, 0.4f, 1}), at({0.1f, 2, -3, 1})},  // right, top, near
      {at({-0.5f, -0.5f, 0, 1}), at({0.5f, -0.5f, 0, 1}), at({0, 0.5f, 0, 1})},   // inside: no step
  }};
  for (const auto& t : triangles) {
    ClipPolygon out, scratch;
    const std::uint32_t mask = clipTriangle(t[0], t[1], t[2], allPlanes(), out, scratch);
    const std::vector<ClipStep> steps = clipTriangleSteps(t[0], t[1], t[2], allPlanes());
    std::uint32_t planes = 0;
    int previous = -1;
    std::vector<vec4> polygon = {t[0].posClip, t[1].posClip, t[2].posClip};
    for (const ClipStep& step : steps) {
      EXPECT_GT(step.plane, previous);
      previous = step.plane;
      planes |= 1u << step.plane;
      EXPECT_EQ(step.before, polygon) << clipPlaneName(step.plane);
      EXPECT_EQ(step.distances.size(), step.before.size());
      for (const ClipCut& cut : step.cuts) {
        EXPECT_GE(cut.t, 0.0f);
        EXPECT_LE(cut.t, 1.0f);
        const vec4 from = step.before[static_cast<std::size_t>(cut.nearer)];
        const vec4 to = step.before[static_cast<std::size_t>(cut.farther)];
        expectNear(step.after[static_cast<std::size_t>(cut.index)], from + cut.t * (to - from));
        // The nearer endpoint and the farther one lie on either side of the plane.
        EXPECT_NE(step.distances[static_cast<std::size_t>(cut.nearer)] >= 0.0f,
                  step.distances[static_cast<std::size_t>(cut.farther)] >= 0.0f);
      }
      polygon = step.after;
    }
    EXPECT_EQ(planes, mask);
    ASSERT_EQ(polygon.size(), static_cast<std::size_t>(out.count));
    for (int i = 0; i < out.count; ++i) {
      const vec4 expected = out.v[static_cast<std::size_t>(i)].posClip;
      EXPECT_EQ(std::memcmp(&polygon[static_cast<std::size_t>(i)], &expected, sizeof(vec4)), 0) << "vertex " << i;
    }
  }
  EXPECT_TRUE(clipTriangleSteps(triangles[2][0], triangles[2][1], triangles[2][2], allPlanes()).empty());
  EXPECT_EQ(clipTriangleSteps(triangles[0][0], triangles[0][1], triangles[0][2], allPlanes()).size(), 6u);
}

}  // namespace
}  // namespace twr
