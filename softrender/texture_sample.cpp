#include "softrender/texture_sample.h"

#include <cmath>

namespace twr {

namespace {

constexpr double kTexelCentre = 0.5;  // texel centres at +0.5
constexpr int kMaxByte = 255;         // texels normalised as c / 255

// floor(s) reduced modulo `size`, exact in double for any finite float s (|s| < 2^128 fits a
// double's exponent; fmod is exact).
int wrappedFloor(double s, int size) {
  if (!std::isfinite(s) || size <= 0) return 0;
  double wrapped = std::fmod(std::floor(s), static_cast<double>(size));
  if (wrapped < 0.0) wrapped += size;
  const int i = static_cast<int>(wrapped);
  return i >= size ? 0 : i;
}

}  // namespace

template <typename T>
int nearestTexelIndex(T coord, int size) {
  // The product is rounded to T (float as GL computes it), then floored and wrapped exactly.
  return wrappedFloor(static_cast<double>(coord * static_cast<T>(size)), size);
}

template <typename T>
Vec4T<T> texelAt(const Texture& texture, int x, int y) {
  const std::uint8_t* t = texture.texel(x, y);
  return Vec4T<T>(t[0], t[1], t[2], t[3]) * (T(1) / T(kMaxByte));
}

template <typename T>
SampleFootprintT<T> sampleFootprint(const Texture& texture, Vec2T<T> uv, TextureFilter filter) {
  SampleFootprintT<T> f;
  if (filter == TextureFilter::Nearest) {
    f.x0 = nearestTexelIndex(uv.x, texture.width);
    f.y0 = nearestTexelIndex(uv.y, texture.height);
    return f;
  }
  const T u = uv.x * static_cast<T>(texture.width) - static_cast<T>(kTexelCentre);
  const T v = uv.y * static_cast<T>(texture.height) - static_cast<T>(kTexelCentre);
  if (std::isfinite(u)) {
    const T fu = std::floor(u);
    f.alpha = u - fu;
    f.x0 = wrappedFloor(fu, texture.width);
  }
  if (std::isfinite(v)) {
    const T fv = std::floor(v);
    f.beta = v - fv;
    f.y0 = wrappedFloor(fv, texture.height);
  }
  f.x1 = f.x0 + 1 == texture.width ? 0 : f.x0 + 1;
  f.y1 = f.y0 + 1 == texture.height ? 0 : f.y0 + 1;
  return f;
}

template <typename T>
Vec4T<T> sampleNearest(const Texture& texture, Vec2T<T> uv) {
  if (texture.width <= 0 || texture.height <= 0) return Vec4T<T>(T(0));
  const SampleFootprintT<T> f = sampleFootprint(texture, uv, TextureFilter::Nearest);
  return texelAt<T>(texture, f.x0, f.y0);
}

template <typename T>
Vec4T<T> sampleBilinear(const Texture& texture, Vec2T<T> uv) {
  if (texture.width <= 0 || texture.height <= 0) return Vec4T<T>(T(0));
  const SampleFootprintT<T> f = sampleFootprint(texture, uv, TextureFilter::Bilinear);
  const T a = f.alpha, b = f.beta;
  return (T(1) - a) * (T(1) - b) * texelAt<T>(texture, f.x0, f.y0) + a * (T(1) - b) * texelAt<T>(texture, f.x1, f.y0) +
         (T(1) - a) * b * texelAt<T>(texture, f.x0, f.y1) + a * b * texelAt<T>(texture, f.x1, f.y1);
}

template <typename T>
Vec4T<T> sampleTexture(const Texture& texture, Vec2T<T> uv, TextureFilter filter) {
  return filter == TextureFilter::Nearest ? sampleNearest(texture, uv) : sampleBilinear(texture, uv);
}

// The two pipelines: float (matches GL) and double (the reference).
#define TWR_INSTANTIATE_SAMPLING(T)                                                        \
  template int nearestTexelIndex<T>(T, int);                                               \
  template Vec4T<T> texelAt<T>(const Texture&, int, int);                                  \
  template Vec4T<T> sampleNearest<T>(const Texture&, Vec2T<T>);                            \
  template Vec4T<T> sampleBilinear<T>(const Texture&, Vec2T<T>);                           \
  template Vec4T<T> sampleTexture<T>(const Texture&, Vec2T<T>, TextureFilter);             \
  template SampleFootprintT<T> sampleFootprint<T>(const Texture&, Vec2T<T>, TextureFilter);
TWR_INSTANTIATE_SAMPLING(float)
TWR_INSTANTIATE_SAMPLING(double)
#undef TWR_INSTANTIATE_SAMPLING

}  // namespace twr
