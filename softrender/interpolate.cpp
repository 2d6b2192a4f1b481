#include "softrender/interpolate.h"

#include <cmath>

namespace twr {

namespace {

constexpr double kPixelCentre = 0.5;  // pixel centres at +0.5

// Plane equations of the barycentrics of triangle (x_i, y_i); false when it has no area.
template <typename T>
bool barycentricPlanes(const std::array<double, 3>& x, const std::array<double, 3>& y, InterpolationSetupT<T>& out) {
  const double doubleArea = (x[1] - x[0]) * (y[2] - y[0]) - (x[2] - x[0]) * (y[1] - y[0]);
  if (doubleArea == 0.0 || !std::isfinite(doubleArea)) return false;
  for (int i = 0; i < 3; ++i) {
    // lambda_i is the area of the sub-triangle opposite corner i: edge (j, k) with the point.
    const int j = (i + 1) % 3, k = (i + 2) % 3;
    const double a = (y[static_cast<std::size_t>(j)] - y[static_cast<std::size_t>(k)]) / doubleArea;   // d lambda / dx
    const double b = (x[static_cast<std::size_t>(k)] - x[static_cast<std::size_t>(j)]) / doubleArea;   // d lambda / dy
    const double c = (x[static_cast<std::size_t>(j)] * y[static_cast<std::size_t>(k)] - x[static_cast<std::size_t>(k)] * y[static_cast<std::size_t>(j)]) / doubleArea;
    out.dx[static_cast<std::size_t>(i)] = a;
    out.dy[static_cast<std::size_t>(i)] = b;
    out.atOrigin[static_cast<std::size_t>(i)] = c + a * kPixelCentre + b * kPixelCentre;
  }
  return true;
}

}  // namespace

template <typename T>
InterpolationSetupT<T> makeInterpolationSetup(const std::array<WindowVertexT<T>, 3>& window,
                                              const TriangleSetup& setup) {
  InterpolationSetupT<T> out;
  std::array<double, 3> x{}, y{};
  for (std::size_t i = 0; i < 3; ++i) {
    x[i] = window[i].x;
    y[i] = window[i].y;
    out.zWindow[i] = window[i].z;
    out.invW[i] = window[i].invW;
  }
  if (!barycentricPlanes(x, y, out)) {
    // A triangle can keep a snapped area while its float positions are collinear; the snapped
    // positions (corner order undone, pixel-centre offset put back) then define the weights.
    for (std::size_t c = 0; c < 3; ++c) {
      const std::size_t vertex = static_cast<std::size_t>(setup.corner[c]);
      x[vertex] = static_cast<double>(setup.xFixed[c]) / kSubpixelScale + kPixelCentre;
      y[vertex] = static_cast<double>(setup.yFixed[c]) / kSubpixelScale + kPixelCentre;
    }
    if (!barycentricPlanes(x, y, out)) {
      out.atOrigin = {1.0, 0.0, 0.0};  // unreachable for a triangle setup accepted; stay finite
      out.dx = {0.0, 0.0, 0.0};
      out.dy = {0.0, 0.0, 0.0};
    }
  }
  return out;
}

template <typename T>
PixelWeightsT<T> pixelWeights(const InterpolationSetupT<T>& setup, int px, int py) {
  PixelWeightsT<T> w;
  double perspectiveSum = 0.0;
  std::array<double, 3> perspective{};
  double depth = 0.0;
  for (std::size_t i = 0; i < 3; ++i) {
    const double lambda = setup.atOrigin[i] + setup.dx[i] * px + setup.dy[i] * py;
    w.screen[i] = static_cast<T>(lambda);
    depth += lambda * setup.zWindow[i];
    perspective[i] = lambda * setup.invW[i];
    perspectiveSum += perspective[i];
  }
  // 1/w is positive at every corner, so the sum is positive inside the triangle; a pixel
  // centre a hair outside the float triangle could still push it to zero.
  for (std::size_t i = 0; i < 3; ++i) {
    w.perspective[i] = perspectiveSum > 0.0 ? static_cast<T>(perspective[i] / perspectiveSum) : w.screen[i];
  }
  const T clamped = static_cast<T>(depth);
  w.depth = std::isfinite(clamped) ? std::fmin(std::fmax(clamped, T(0)), T(1)) : T(1);
  return w;
}

template <typename T>
FragmentT<T> interpolateFragment(const ClipVertexT<T>& v0, const ClipVertexT<T>& v1, const ClipVertexT<T>& v2,
                                 const PixelWeightsT<T>& weights, bool tangentLighting, int tangentLightCount) {
  const T p0 = weights.perspective[0], p1 = weights.perspective[1], p2 = weights.perspective[2];
  FragmentT<T> f;
  f.posWorld = v0.posWorld * p0 + v1.posWorld * p1 + v2.posWorld * p2;
  f.nWorld = v0.nWorld * p0 + v1.nWorld * p1 + v2.nWorld * p2;
  f.tWorld = v0.tWorld * p0 + v1.tWorld * p1 + v2.tWorld * p2;
  f.bWorld = v0.bWorld * p0 + v1.bWorld * p1 + v2.bWorld * p2;
  f.uv = v0.uv * p0 + v1.uv * p1 + v2.uv * p2;
  if (tangentLighting) {
    for (int i = 0; i < tangentLightCount; ++i) {
      const std::size_t k = static_cast<std::size_t>(i);
      f.lightDirTangent[k] = v0.lightDirTangent[k] * p0 + v1.lightDirTangent[k] * p1 + v2.lightDirTangent[k] * p2;
    }
    f.eyeDirTangent = v0.eyeDirTangent * p0 + v1.eyeDirTangent * p1 + v2.eyeDirTangent * p2;
  }
  f.depth = weights.depth;
  return f;
}

// The two pipelines: float (matches GL) and double (the reference).
template InterpolationSetupT<float> makeInterpolationSetup<float>(const std::array<WindowVertexT<float>, 3>&,
                                                                  const TriangleSetup&);
template InterpolationSetupT<double> makeInterpolationSetup<double>(const std::array<WindowVertexT<double>, 3>&,
                                                                    const TriangleSetup&);
template PixelWeightsT<float> pixelWeights<float>(const InterpolationSetupT<float>&, int, int);
template PixelWeightsT<double> pixelWeights<double>(const InterpolationSetupT<double>&, int, int);
template FragmentT<float> interpolateFragment<float>(const ClipVertexT<float>&, const ClipVertexT<float>&,
                                                     const ClipVertexT<float>&, const PixelWeightsT<float>&, bool,
                                                     int);
template FragmentT<double> interpolateFragment<double>(const ClipVertexT<double>&, const ClipVertexT<double>&,
                                                       const ClipVertexT<double>&, const PixelWeightsT<double>&,
                                                       bool, int);

}  // namespace twr
