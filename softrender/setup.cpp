#include "softrender/setup.h"

#include "softrender/clip.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

namespace twr {

namespace {

// Floor division of 24.8 fixed point by 256 (an arithmetic shift rounds towards -infinity).
int pixelFloor(std::int32_t fixed) { return static_cast<int>(fixed >> kSubpixelBits); }

// fmin(fmax(v, -bound), bound), NaN to -bound as fmax does, written as compares so that it
// compiles to a few instructions instead of two libm calls (it runs twice per vertex).
template <typename T>
T clampedTo(T v, T bound) {
  if (!(v >= -bound)) return -bound;
  return v > bound ? bound : v;
}

}  // namespace

template <typename T>
WindowVertexT<T> windowFromClip(const Vec4T<T>& posClip, const Viewport& viewport, bool fusedMultiplyAdd) {
  const T halfWidth = T(0.5) * static_cast<T>(viewport.width);
  const T halfHeight = T(0.5) * static_cast<T>(viewport.height);
  constexpr T kHalfDepthRange = T(0.5);  // glDepthRange(0, 1): scale and offset 0.5
  WindowVertexT<T> out;
  // The clipper leaves w > 0 everywhere except the frustum's apex (x = y = 0, w = 0, a
  // degenerate triangle); keep that case finite instead of dividing by zero, and a subnormal
  // w too, whose reciprocal overflows.
  out.invW = posClip.w >= std::numeric_limits<T>::min() ? T(1) / posClip.w : T(1) / static_cast<T>(kMinClipW);
  const T xNdc = posClip.x * out.invW, yNdc = posClip.y * out.invW;
  // The clipper bounds x / w and y / w (frustum or guard band), but with depth clamp (near or
  // far off) z / w is unbounded near w = 0; a finite bound keeps window z finite. Setup clamps
  // each fragment's depth to [0, 1], so no pixel can tell.
  const T zNdc = clampedTo(posClip.z * out.invW, static_cast<T>(kMaxNdcDepth));
  if (fusedMultiplyAdd) {
    out.x = std::fma(xNdc, halfWidth, halfWidth);
    out.y = std::fma(yNdc, halfHeight, halfHeight);
    out.z = std::fma(zNdc, kHalfDepthRange, kHalfDepthRange);
  } else {
    out.x = xNdc * halfWidth + halfWidth;
    out.y = yNdc * halfHeight + halfHeight;
    out.z = zNdc * kHalfDepthRange + kHalfDepthRange;
  }
  return out;
}

template <typename T>
std::int32_t snapToSubpixel(T windowCoord) {
  // NaN goes to the bound too, so nothing undefined reaches the conversion.
  const T bounded = clampedTo(windowCoord, static_cast<T>(kMaxWindowCoord));
  return static_cast<std::int32_t>(
      std::lrint((bounded - static_cast<T>(kPixelCentreOffset)) * static_cast<T>(kSubpixelScale)));
}

template <typename T>
SetupResult setupTriangle(const std::array<WindowVertexT<T>, 3>& window, CullMode cull, FrontFace frontFace,
                          const Viewport& viewport, TriangleSetup& out) {
  std::array<std::int32_t, 3> xFixed{}, yFixed{};
  for (std::size_t i = 0; i < 3; ++i) {
    xFixed[i] = snapToSubpixel(window[i].x);
    yFixed[i] = snapToSubpixel(window[i].y);
  }
  return setupSnappedTriangle(xFixed, yFixed, cull, frontFace, viewport, out);
}

SetupResult setupSnappedTriangle(const std::array<std::int32_t, 3>& xFixed, const std::array<std::int32_t, 3>& yFixed,
                                 CullMode cull, FrontFace frontFace, const Viewport& viewport, TriangleSetup& out) {
  return setupSnappedCorners(xFixed[0], yFixed[0], xFixed[1], yFixed[1], xFixed[2], yFixed[2], cull, frontFace, viewport,
                             out);
}

SetupResult setupSnappedCorners(std::int32_t xa, std::int32_t ya, std::int32_t xb, std::int32_t yb, std::int32_t xc,
                                std::int32_t yc, CullMode cull, FrontFace frontFace, const Viewport& viewport,
                                TriangleSetup& out) {
  // Every field is assigned below, none through a whole-struct temporary: on a million small
  // triangles a frame, zeroing and copying TriangleSetup cost more than the setup itself.
  out.xFixed = {xa, xb, xc};
  out.yFixed = {ya, yb, yc};
  out.corner = {0, 1, 2};
  const std::int64_t x0 = xa, x1 = xb, x2 = xc;
  const std::int64_t y0 = ya, y1 = yb, y2 = yc;
  // Twice the signed area, positive for counter-clockwise in GL window coordinates (y up).
  const std::int64_t doubleAreaCcw = (x1 - x0) * (y2 - y0) - (x2 - x0) * (y1 - y0);
  const bool counterClockwise = doubleAreaCcw > 0;
  out.frontFacing = doubleAreaCcw == 0 || (frontFace == FrontFace::Ccw) == counterClockwise;
  out.doubleAreaFixed = 0;
  out.x0 = 0, out.x1 = -1, out.y0 = 0, out.y1 = -1;  // empty until accepted
  if (doubleAreaCcw == 0) return SetupResult::ZeroArea;
  if (cull == CullMode::Back && !out.frontFacing) return SetupResult::CulledBack;
  if (cull == CullMode::Front && out.frontFacing) return SetupResult::CulledFront;

  // Order the corners clockwise (llvmpipe swaps the first two), so the inside of every edge
  // is where E > 0.
  if (counterClockwise) {
    std::swap(out.xFixed[0], out.xFixed[1]);
    std::swap(out.yFixed[0], out.yFixed[1]);
    std::swap(out.corner[0], out.corner[1]);
  }
  out.doubleAreaFixed = counterClockwise ? doubleAreaCcw : -doubleAreaCcw;

  for (int i = 0; i < 3; ++i) {
    const int j = (i + 1) % 3;
    const std::int64_t xi = out.xFixed[static_cast<std::size_t>(i)], yi = out.yFixed[static_cast<std::size_t>(i)];
    const std::int64_t xj = out.xFixed[static_cast<std::size_t>(j)], yj = out.yFixed[static_cast<std::size_t>(j)];
    const std::int64_t dcdx = yi - yj;
    const std::int64_t dcdy = xi - xj;
    EdgeFunction& edge = out.edges[static_cast<std::size_t>(i)];
    // Left edges (going up in a clockwise triangle) and bottom edges (horizontal, going
    // left) own the pixel centres exactly on them.
    edge.ownsPixelsOnIt = dcdx < 0 || (dcdx == 0 && dcdy > 0);
    edge.c = dcdx * xi - dcdy * yi + (edge.ownsPixelsOnIt ? 1 : 0);
    edge.stepX = -dcdx * kSubpixelScale;
    edge.stepY = dcdy * kSubpixelScale;
  }

  // Bounding box as llvmpipe computes it: x from min X (inclusive) to max X (exclusive); the
  // same for y.
  const std::int32_t minX = std::min({out.xFixed[0], out.xFixed[1], out.xFixed[2]});
  const std::int32_t maxX = std::max({out.xFixed[0], out.xFixed[1], out.xFixed[2]});
  const std::int32_t minY = std::min({out.yFixed[0], out.yFixed[1], out.yFixed[2]});
  const std::int32_t maxY = std::max({out.yFixed[0], out.yFixed[1], out.yFixed[2]});
  out.x0 = std::max(pixelFloor(minX), 0);
  out.x1 = std::min(pixelFloor(maxX - 1), viewport.width - 1);
  out.y0 = std::max(pixelFloor(minY), 0);
  out.y1 = std::min(pixelFloor(maxY - 1), viewport.height - 1);
  return SetupResult::Ready;
}

// The two pipelines: float (matches GL) and double (the reference).
template WindowVertexT<float> windowFromClip<float>(const vec4&, const Viewport&, bool);
template WindowVertexT<double> windowFromClip<double>(const glm::dvec4&, const Viewport&, bool);
template std::int32_t snapToSubpixel<float>(float);
template std::int32_t snapToSubpixel<double>(double);
template SetupResult setupTriangle<float>(const std::array<WindowVertexT<float>, 3>&, CullMode, FrontFace,
                                          const Viewport&, TriangleSetup&);
template SetupResult setupTriangle<double>(const std::array<WindowVertexT<double>, 3>&, CullMode, FrontFace,
                                           const Viewport&, TriangleSetup&);

PixelBox pixelCentreBox(const TriangleSetup& setup) {
  // Centre px sits at 256 px: the first at or after min X, the last at or before max X.
  const auto firstCentre = [](std::int32_t fixed) { return pixelFloor(fixed + (kSubpixelScale - 1)); };
  const std::int32_t minX = std::min({setup.xFixed[0], setup.xFixed[1], setup.xFixed[2]});
  const std::int32_t maxX = std::max({setup.xFixed[0], setup.xFixed[1], setup.xFixed[2]});
  const std::int32_t minY = std::min({setup.yFixed[0], setup.yFixed[1], setup.yFixed[2]});
  const std::int32_t maxY = std::max({setup.yFixed[0], setup.yFixed[1], setup.yFixed[2]});
  return PixelBox{std::max(setup.x0, firstCentre(minX)), std::min(setup.x1, pixelFloor(maxX)),
                  std::max(setup.y0, firstCentre(minY)), std::min(setup.y1, pixelFloor(maxY))};
}

const char* toString(SetupResult result) {
  switch (result) {
    case SetupResult::Ready: return "ready";
    case SetupResult::ZeroArea: return "zero area after snapping";
    case SetupResult::CulledBack: return "culled (back face)";
    case SetupResult::CulledFront: return "culled (front face)";
  }
  return "?";
}

}  // namespace twr
