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

// The two pipelines: float (matches GL) and double (the reference).
template InterpolationSetupT<float> makeInterpolationSetup<float>(const std::array<WindowVertexT<float>, 3>&,
                                                                  const TriangleSetup&);
template InterpolationSetupT<double> makeInterpolationSetup<double>(const std::array<WindowVertexT<double>, 3>&,
                                                                    const TriangleSetup&);
}  // namespace twr
