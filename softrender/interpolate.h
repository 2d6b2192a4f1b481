// Stage 5, interpolation: per pixel, the window depth, and every varying interpolated
// perspective-correctly, each exactly as llvmpipe interpolates it, because a texel, a layer of
// a parallax march or a shading boundary can flip on one ULP of a varying (docs/textures.md,
// "Which texel"). Each varying a, and 1/w, is a plane set up in float from the float window
// positions, in the corner order setup uses (a counter-clockwise triangle has its first two
// corners swapped), from a_i / w_i at the corners (a_i alone for the window depth):
//   da01 = a0 - a1, da20 = a2 - a0, 1/area = 1 / (dx01 dy20 - dy01 dx20)
//   dadx = da01 (dy20 / area) - da20 (dy01 / area),  dady = da20 (dx01 / area) - da01 (dx20 / area)
//   a(px, py) = fma(dady, py, fma(dadx, px, A0)),     A0 = a0 - (dadx (x0 - 0.5) + dady (y0 - 0.5))
//   varying   = (a/w)(px, py) * (1 / (1/w)(px, py))    (a product with the reciprocal, not a quotient)
//   z_win     = the window z plane (no 1/w), stored as llvmpipe's 24-bit depth buffer holds it
// with one rounding per operation and the two fused multiply-adds llvmpipe's JIT code emits on
// a CPU with FMA (every x86-64 CPU since 2013, every AArch64 one).
// Affine interpolation (settings.interpolation, GLSL's noperspective) weighs every corner with
// 1 in place of 1/w: the plane of a/w is then a's own plane and 1/w the constant 1, so the
// divide changes nothing and the varying is linear on the screen, as llvmpipe draws it (the
// clipper gives a cut vertex its varyings at the edge's screen-space t to match, clip.h).
//
// The screen-space barycentrics of the pixel centre and the perspective weights
//   lambda_i  = screen-space barycentric of the pixel centre (px + 0.5, py + 0.5)
//   p_i       = (lambda_i / w_i) / sum_k (lambda_k / w_k)
// are what the textbook interpolates with (sum p_i a_i); they are kept, in double, for the
// pixel trace and the GUI's inspector, which show them, but no varying is computed from them:
// a sum of three products rounds differently from the planes above, and steep parallax sent
// pixels down another layer on that difference. Barycentrics come from the unsnapped window
// positions (as llvmpipe's attribute setup); the snapped positions stand in when those have
// no area.
//
// The per-pixel part (weights and varyings) is written once over the lane type in
// interpolate-inl.h; the functions below are its scalar entry points, templated on T (float:
// the pipeline, double: the reference).
#pragma once

#include "softrender/setup.h"
#include "softrender/vertex.h"

#include <array>

namespace twr {

// The 1/w a corner's varyings are weighted by: its own 1/w_clip (perspective-correct) or 1 at
// every corner (affine).
template <typename T>
T attributeInvW(const WindowVertexT<T>& corner, Interpolation mode) {
  return mode == Interpolation::Affine ? T(1) : corner.invW;
}

// One attribute as a plane over pixel indices: a(px, py) = fma(dy, py, fma(dx, px, atOrigin))
// (the pixel-centre offset folded into atOrigin).
template <typename T>
struct AttributePlaneT {
  T atOrigin = T(0), dx = T(0), dy = T(0);
};
// Whether a target without fused multiply-add instructions may evaluate the float plane as two
// double sums, each rounded once to float: true when a + dx px, and that sum rounded to float
// plus dy py, are exact in double for every pixel index px, py in [0, 2^15] (an image is at most
// 2^14 wide), so each rounding is the fused multiply-add's only one. A finite nonzero
// coefficient c is a multiple of its ulp 2^(e(c) - 23) below 2^(e(c) + 1): both sums are
// multiples of the smallest ulp, 2^G, below 2^(M + 3) with M = max(e(a), e(dx) + 15,
// e(dy) + 15), which is M + 3 - G bits, exact when at most 53. False for a non-finite
// coefficient.
bool planeSumsExactInDouble(const AttributePlaneT<float>& p);

// The texture coordinate's three planes (see above).
template <typename T>
struct UvPlanesT {
  AttributePlaneT<T> uOverW, vOverW, oneOverW;
};

// The varyings the fragment stage reads, as floats in this order (offsets in floats): the
// layout of VaryingPlanesT and of the fast path's stored vertices.
inline constexpr int kVaryingPosWorld = 0;
inline constexpr int kVaryingNormal = 3;
inline constexpr int kVaryingTangent = 6;
inline constexpr int kVaryingBitangent = 9;
inline constexpr int kVaryingUv = 12;
inline constexpr int kVaryingEyeDirTangent = 14;    // tangent lighting space only
inline constexpr int kVaryingLightDirTangent = 17;  // light i at 17 + 3 i, tangent lighting only
inline constexpr int kMaxVaryings = kVaryingLightDirTangent + 3 * kMaxLights;  // 41
// Floats per vertex: 14 in world lighting space, 17 + 3 lightCount in tangent space.
inline int varyingCount(bool tangentLighting, int lightCount) {
  return tangentLighting ? kVaryingLightDirTangent + 3 * lightCount : kVaryingEyeDirTangent;
}

// The varyings of `v` in that layout (the first varyingCount floats of `out`).
template <typename T>
void storeVaryings(const ClipVertexT<T>& v, bool tangentLighting, int lightCount, T* out) {
  const auto put = [&](int at, const Vec3T<T>& value) {
    out[at] = value.x;
    out[at + 1] = value.y;
    out[at + 2] = value.z;
  };
  put(kVaryingPosWorld, v.posWorld);
  put(kVaryingNormal, v.nWorld);
  put(kVaryingTangent, v.tWorld);
  put(kVaryingBitangent, v.bWorld);
  out[kVaryingUv] = v.uv.x;
  out[kVaryingUv + 1] = v.uv.y;
  if (!tangentLighting) return;
  put(kVaryingEyeDirTangent, v.eyeDirTangent);
  for (int i = 0; i < lightCount; ++i) put(kVaryingLightDirTangent + 3 * i, v.lightDirTangent[static_cast<std::size_t>(i)]);
}

// Every varying's plane of a / w, and the plane of 1 / w they are divided by (see above).
// Where the float corners are collinear (setup accepted their snapped positions) the planes
// would divide by zero; they then hold the first vertex's values everywhere, and 1/w is 1.
template <typename T>
struct VaryingPlanesT {
  AttributePlaneT<T> oneOverW;
  std::array<AttributePlaneT<T>, kMaxVaryings> overW{};  // varying k at overW[k], the layout above
  int count = 0;                                          // planes set (varyingCount)
};
using VaryingPlanes = VaryingPlanesT<float>;

// lambda_i(px, py) = atOrigin[i] + dx[i] * px + dy[i] * py (pixel indices; the centre offset
// is folded into atOrigin).
template <typename T>
struct InterpolationSetupT {
  std::array<double, 3> atOrigin{}, dx{}, dy{};
  std::array<T, 3> zWindow{};  // window depth of each corner
  std::array<T, 3> invW{};     // each corner's attributeInvW (1 / w_clip, or 1 when affine)
  UvPlanesT<T> uv;             // the texture coordinate, as llvmpipe interpolates it
  // Window depth as llvmpipe interpolates it: its position.z plane, set up like uv's (no 1/w),
  // left non-finite where the float corners are collinear (llvmpipe's fragments then fail the
  // depth test; storedDepth).
  AttributePlaneT<T> depth;
};
using InterpolationSetup = InterpolationSetupT<float>;

// Corner i of `window` and of `uv` is vertex i of the triangle (before setup's reordering).
template <typename T = float>
InterpolationSetupT<T> makeInterpolationSetup(const std::array<WindowVertexT<T>, 3>& window,
                                              const std::array<Vec2T<T>, 3>& uv, const TriangleSetup& setup,
                                              Interpolation mode = Interpolation::Perspective);

// The uv planes alone (part of makeInterpolationSetup), made as makeVaryingPlanes makes them.
template <typename T>
UvPlanesT<T> makeUvPlanes(const std::array<WindowVertexT<T>, 3>& window, const std::array<Vec2T<T>, 3>& uv,
                          const TriangleSetup& setup, Interpolation mode = Interpolation::Perspective);

// The planes of the first `count` varyings (the layout above) of vertices 0, 1, 2, whose floats
// start at varyings[0], [1], [2] (corner i of `window` is vertex i, before setup's reordering).
template <typename T>
VaryingPlanesT<T> makeVaryingPlanes(const std::array<WindowVertexT<T>, 3>& window,
                                    const std::array<const T*, 3>& varyings, int count, const TriangleSetup& setup,
                                    Interpolation mode = Interpolation::Perspective);
// The same from the clip vertices (storeVaryings of each).
template <typename T>
VaryingPlanesT<T> makeVaryingPlanes(const std::array<WindowVertexT<T>, 3>& window, const ClipVertexT<T>& v0,
                                    const ClipVertexT<T>& v1, const ClipVertexT<T>& v2, bool tangentLighting,
                                    int lightCount, const TriangleSetup& setup,
                                    Interpolation mode = Interpolation::Perspective) {
  std::array<std::array<T, kMaxVaryings>, 3> floats{};
  const int count = varyingCount(tangentLighting, lightCount);
  storeVaryings(v0, tangentLighting, lightCount, floats[0].data());
  storeVaryings(v1, tangentLighting, lightCount, floats[1].data());
  storeVaryings(v2, tangentLighting, lightCount, floats[2].data());
  return makeVaryingPlanes<T>(window, {floats[0].data(), floats[1].data(), floats[2].data()}, count, setup, mode);
}

// The window depth plane alone (part of makeInterpolationSetup): all the visibility pass needs.
template <typename T>
AttributePlaneT<T> makeDepthPlane(const std::array<WindowVertexT<T>, 3>& window, const TriangleSetup& setup);

template <typename T>
struct PixelWeightsT {
  std::array<T, 3> screen{};       // lambda_i, sum 1
  std::array<T, 3> perspective{};  // p_i, sum 1
  T depth = T(0);                  // the depth the test compares and stores (storedDepth)
  Vec2T<T> uv{T(0)};               // the texture coordinate, from the uv planes
};
using PixelWeights = PixelWeightsT<float>;


// The interpolated varyings a fragment is shaded from (names as in phong.frag).
template <typename T>
struct FragmentT {
  Vec3T<T> posWorld{T(0)};
  Vec3T<T> nWorld{T(0)};
  Vec3T<T> tWorld{T(0)};
  Vec3T<T> bWorld{T(0)};
  Vec2T<T> uv{T(0)};
  // The 2x2 quad's uv differences, top-left pixel to its right and upper neighbours (helper
  // pixels included, as a GPU takes them): set for mipmapped filters only, else 0.
  Vec2T<T> uvDx{T(0)}, uvDy{T(0)};
  Vec2T<T> uvDxFine{T(0)}, uvDyFine{T(0)};  // GLSL's dFdx / dFdy (fine, per row and column)
  // GLSL's dFdx / dFdy of the environment's reflected and refracted directions (world space),
  // which texture(samplerCube, ...) takes its LOD from: set only for a material that reads the
  // environment (setEnvironmentDifferences, shade-inl.h), else 0.
  Vec3T<T> reflectDx{T(0)}, reflectDy{T(0)}, refractDx{T(0)}, refractDy{T(0)};
  std::array<Vec3T<T>, kMaxLights> lightDirTangent{};
  Vec3T<T> eyeDirTangent{T(0)};
  T depth = T(0);  // window depth
};
using Fragment = FragmentT<float>;

}  // namespace twr

#include "softrender/interpolate-inl.h"

namespace twr {

template <typename T>
PixelWeightsT<T> pixelWeights(const InterpolationSetupT<T>& setup, int px, int py) {
  return lanes::pixelWeights<T>(setup, static_cast<double>(px), static_cast<double>(py));
}

// The varyings at pixel (px, py), from their planes; `depth` is the pixel's window depth
// (PixelWeightsT::depth). Tangent-space light and eye directions are interpolated only when
// the planes hold them (tangent lighting space), else left zero.
template <typename T>
FragmentT<T> interpolateFragment(const VaryingPlanesT<T>& planes, int px, int py, T depth) {
  return lanes::interpolateFragment<T>(planes, static_cast<T>(px), static_cast<T>(py), depth);
}

}  // namespace twr
