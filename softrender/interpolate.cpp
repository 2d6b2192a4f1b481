#include "softrender/interpolate.h"

#include "scene/image.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>

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

// llvmpipe's triangle setup (lp_state_setup.c) for attribute planes: the float window corners
// in setup's corner order (llvmpipe builds its planes from the triangle as its rasterizer orders
// it, and the roundings depend on which corner comes first), 1 / area, and the pixel-centre
// offset folded into the value at the origin. Collinear float corners give non-finite planes.
template <typename T>
struct PlaneSetup {
  PlaneSetup(const std::array<WindowVertexT<T>, 3>& window, const TriangleSetup& setup)
      : w0(window[corner(setup, 0)]) {
    const WindowVertexT<T>& w1 = window[corner(setup, 1)];
    const WindowVertexT<T>& w2 = window[corner(setup, 2)];
    const T dx01 = w0.x - w1.x, dy01 = w0.y - w1.y;
    const T dx20 = w2.x - w0.x, dy20 = w2.y - w0.y;
    const T oneOverArea = T(1) / (dx01 * dy20 - dy01 * dx20);
    dx20a = dx20 * oneOverArea;
    dy20a = dy20 * oneOverArea;
    dx01a = dx01 * oneOverArea;
    dy01a = dy01 * oneOverArea;
  }
  static std::size_t corner(const TriangleSetup& setup, std::size_t c) { return static_cast<std::size_t>(setup.corner[c]); }
  // The plane through a0, a1, a2, the values at setup's corners 0, 1, 2.
  AttributePlaneT<T> planeOf(T a0, T a1, T a2) const {
    const T half(0.5);  // pixel centres at + 0.5 px
    const T da01 = a0 - a1, da20 = a2 - a0;
    AttributePlaneT<T> p;
    p.dx = da01 * dy20a - da20 * dy01a;
    p.dy = da20 * dx01a - da01 * dx20a;
    p.atOrigin = a0 - (p.dx * (w0.x - half) + p.dy * (w0.y - half));
    return p;
  }
  WindowVertexT<T> w0;
  T dx20a = T(0), dy20a = T(0), dx01a = T(0), dy01a = T(0);
};

}  // namespace

template <typename T>
VaryingPlanesT<T> makeVaryingPlanes(const std::array<WindowVertexT<T>, 3>& window,
                                    const std::array<const T*, 3>& varyings, int count, const TriangleSetup& setup,
                                    Interpolation mode) {
  const PlaneSetup<T> planes(window, setup);
  const std::size_t c0 = PlaneSetup<T>::corner(setup, 0), c1 = PlaneSetup<T>::corner(setup, 1),
                    c2 = PlaneSetup<T>::corner(setup, 2);
  VaryingPlanesT<T> out;
  out.count = count;
  // The planes of a/w and of 1/w, divided per pixel (affine: w is 1 at every corner).
  const auto invW = [&](std::size_t c) { return attributeInvW(window[c], mode); };
  out.oneOverW = planes.planeOf(invW(c0), invW(c1), invW(c2));
  bool finite = true;
  const auto isFinitePlane = [](const AttributePlaneT<T>& p) {
    return std::isfinite(p.atOrigin) && std::isfinite(p.dx) && std::isfinite(p.dy);
  };
  finite = isFinitePlane(out.oneOverW);
  for (int k = 0; k < count; ++k) {
    const auto overW = [&](std::size_t c) { return varyings[c][k] * invW(c); };
    AttributePlaneT<T>& plane = out.overW[static_cast<std::size_t>(k)];
    plane = planes.planeOf(overW(c0), overW(c1), overW(c2));
    finite = finite && isFinitePlane(plane);
  }
  if (!finite) {
    out.oneOverW = AttributePlaneT<T>{T(1), T(0), T(0)};
    for (int k = 0; k < count; ++k) out.overW[static_cast<std::size_t>(k)] = AttributePlaneT<T>{varyings[0][k], T(0), T(0)};
  }
  return out;
}

template <typename T>
UvPlanesT<T> makeUvPlanes(const std::array<WindowVertexT<T>, 3>& window, const std::array<Vec2T<T>, 3>& uv,
                          const TriangleSetup& setup, Interpolation mode) {
  const std::array<std::array<T, 2>, 3> floats{{{uv[0].x, uv[0].y}, {uv[1].x, uv[1].y}, {uv[2].x, uv[2].y}}};
  const VaryingPlanesT<T> planes =
      makeVaryingPlanes<T>(window, {floats[0].data(), floats[1].data(), floats[2].data()}, 2, setup, mode);
  return UvPlanesT<T>{planes.overW[0], planes.overW[1], planes.oneOverW};
}

template <typename T>
AttributePlaneT<T> makeDepthPlane(const std::array<WindowVertexT<T>, 3>& window, const TriangleSetup& setup) {
  const auto cornerZ = [&](std::size_t c) { return window[PlaneSetup<T>::corner(setup, c)].z; };
  return PlaneSetup<T>(window, setup).planeOf(cornerZ(0), cornerZ(1), cornerZ(2));
}

template <typename T>
InterpolationSetupT<T> makeInterpolationSetup(const std::array<WindowVertexT<T>, 3>& window,
                                              const std::array<Vec2T<T>, 3>& uv, const TriangleSetup& setup,
                                              Interpolation mode) {
  InterpolationSetupT<T> out;
  out.uv = makeUvPlanes(window, uv, setup, mode);
  out.depth = makeDepthPlane(window, setup);
  std::array<double, 3> x{}, y{};
  for (std::size_t i = 0; i < 3; ++i) {
    x[i] = window[i].x;
    y[i] = window[i].y;
    out.zWindow[i] = window[i].z;
    out.invW[i] = attributeInvW(window[i], mode);
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

bool planeSumsExactInDouble(const AttributePlaneT<float>& p) {
  constexpr int kPixelIndexBits = 15;  // px, py <= 2^15
  // Pixel indices, a vector's lanes past a row's end and a quad's neighbours included, stay
  // below twice the largest image side.
  static_assert(2 * kMaxImageSide <= 1 << kPixelIndexBits);
  constexpr int kFloatFractionBits = 23;  // ulp(c) = 2^(e(c) - 23)
  constexpr int kFloatExponentBias = 127;
  constexpr std::uint32_t kExponentField = 0xFFu, kMagnitudeBits = 0x7FFFFFFFu;
  constexpr int kDoubleSignificandBits = 53;
  constexpr int kSumHeadroomBits = 3;  // a + dx px + dy py below 2^(M + 3)
  int highest = std::numeric_limits<int>::min(), lowestUlp = std::numeric_limits<int>::max();
  // e(c) from the exponent field (it runs per triangle: no libm call); a subnormal's ulp is
  // 2^-149, as the smallest normal's.
  const auto take = [&](float c, int indexBits) {
    const std::uint32_t bits = std::bit_cast<std::uint32_t>(c);
    if ((bits & kMagnitudeBits) == 0) return true;  // +-0
    const int field = static_cast<int>((bits >> kFloatFractionBits) & kExponentField);
    if (field == static_cast<int>(kExponentField)) return false;  // infinity, NaN
    const int e = std::max(field, 1) - kFloatExponentBias;
    highest = std::max(highest, e + indexBits);
    lowestUlp = std::min(lowestUlp, e - kFloatFractionBits);
    return true;
  };
  if (!take(p.atOrigin, 0) || !take(p.dx, kPixelIndexBits) || !take(p.dy, kPixelIndexBits)) return false;
  if (lowestUlp == std::numeric_limits<int>::max()) return true;  // the zero plane
  return highest + kSumHeadroomBits - lowestUlp <= kDoubleSignificandBits;
}

// The two pipelines: float (matches GL) and double (the reference).
template InterpolationSetupT<float> makeInterpolationSetup<float>(const std::array<WindowVertexT<float>, 3>&,
                                                                  const std::array<Vec2T<float>, 3>&,
                                                                  const TriangleSetup&, Interpolation);
template InterpolationSetupT<double> makeInterpolationSetup<double>(const std::array<WindowVertexT<double>, 3>&,
                                                                    const std::array<Vec2T<double>, 3>&,
                                                                    const TriangleSetup&, Interpolation);
template UvPlanesT<float> makeUvPlanes<float>(const std::array<WindowVertexT<float>, 3>&,
                                              const std::array<Vec2T<float>, 3>&, const TriangleSetup&,
                                              Interpolation);
template UvPlanesT<double> makeUvPlanes<double>(const std::array<WindowVertexT<double>, 3>&,
                                                const std::array<Vec2T<double>, 3>&, const TriangleSetup&,
                                                Interpolation);
template VaryingPlanesT<float> makeVaryingPlanes<float>(const std::array<WindowVertexT<float>, 3>&,
                                                        const std::array<const float*, 3>&, int, const TriangleSetup&,
                                                        Interpolation);
template VaryingPlanesT<double> makeVaryingPlanes<double>(const std::array<WindowVertexT<double>, 3>&,
                                                          const std::array<const double*, 3>&, int,
                                                          const TriangleSetup&, Interpolation);
template AttributePlaneT<float> makeDepthPlane<float>(const std::array<WindowVertexT<float>, 3>&, const TriangleSetup&);
template AttributePlaneT<double> makeDepthPlane<double>(const std::array<WindowVertexT<double>, 3>&,
                                                        const TriangleSetup&);
}  // namespace twr
