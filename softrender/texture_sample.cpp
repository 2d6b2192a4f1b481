// The scalar entry points of texture sampling: texture_sample-inl.h's shared source with
// T = float and double, reading a Texture.
#include "softrender/texture_sample.h"

#include <cstdio>
#include <cstdlib>

namespace twr {

namespace {

constexpr int kMaxByte = 255;  // texels normalised as c / 255

bool hasTexels(const Texture& texture) { return texture.width > 0 && texture.height > 0; }

}  // namespace

template <typename T>
int nearestTexelIndex(T coord, int size) {
  return (lanes::nearestTexel<T>)((lanes::sanitizedCoord<T>)(coord), size, TextureWrap::Repeat);
}

const std::array<double, 256>& srgbDecodeTable() {
  static const std::array<double, 256> table = [] {
    std::array<double, 256> t{};
    for (int c = 0; c < 256; ++c) t[static_cast<std::size_t>(c)] = linearFromSrgb(c / 255.0);
    return t;
  }();
  return table;
}

const std::array<float, kEwaWeightCount>& ewaWeightTable() {
  static const std::array<float, kEwaWeightCount> table = [] {
    std::array<float, kEwaWeightCount> t{};
    const float alpha = 2.0f;  // the Gaussian's falloff: weight e^-2 at the ellipse's edge
    for (int i = 0; i < kEwaWeightCount; ++i) {
      const float r2 = static_cast<float>(i) / static_cast<float>(kEwaWeightCount - 1);
      // The six decimals llvmpipe's table was printed with, then the C compiler's reading:
      // the decimal to double, the double to float.
      char printed[32];
      std::snprintf(printed, sizeof printed, "%f", static_cast<double>(std::exp(-alpha * r2)));
      t[static_cast<std::size_t>(i)] = static_cast<float>(std::strtod(printed, nullptr));
    }
    return t;
  }();
  return table;
}

template <typename T>
Vec4T<T> texelAt(const Texture& texture, int x, int y) {
  const std::uint8_t* t = texture.texel(x, y);
  return Vec4T<T>(t[0], t[1], t[2], t[3]) * (T(1) / T(kMaxByte));
}

template <typename T>
SampleFootprintT<T> sampleFootprint(const Texture& texture, Vec2T<T> uv, TextureFilter filter) {
  const lanes::FootprintL<T> f = lanes::sampleFootprint<T>(texture, uv, filter);
  return SampleFootprintT<T>{f.x0, f.y0, f.x1, f.y1, f.alpha, f.beta};
}

template <typename T>
Vec4T<T> sampleNearest(const Texture& texture, Vec2T<T> uv) {
  if (!hasTexels(texture)) return Vec4T<T>(T(0));
  return lanes::sampleTexture<T>(texture, uv, TextureFilter::Nearest, T(0));
}

template <typename T>
Vec4T<T> sampleBilinear(const Texture& texture, Vec2T<T> uv) {
  if (!hasTexels(texture)) return Vec4T<T>(T(0));
  return lanes::sampleTexture<T>(texture, uv, TextureFilter::Bilinear, T(0));
}

template <typename T>
Vec4T<T> sampleTexture(const Texture& texture, Vec2T<T> uv, TextureFilter filter, T lod) {
  if (!hasTexels(texture)) return Vec4T<T>(T(0));
  return lanes::sampleTexture<T>(texture, uv, filter, lod);
}

template <typename T>
Vec4T<T> sampleTextureAnisotropic(const Texture& texture, Vec2T<T> uv, TextureFilter filter, Vec2T<T> dUvDx,
                                  Vec2T<T> dUvDy) {
  if (!hasTexels(texture)) return Vec4T<T>(T(0));
  return lanes::sampleTextureAnisotropic<T>(texture, uv, filter, dUvDx, dUvDy);
}

// The two scalar pipelines: float (matches GL) and double (the reference).
#define TWR_INSTANTIATE_SAMPLING(T)                                                        \
  template Vec4T<T> sampleTextureAnisotropic<T>(const Texture&, Vec2T<T>, TextureFilter, Vec2T<T>, Vec2T<T>); \
  template int nearestTexelIndex<T>(T, int);                                               \
  template Vec4T<T> texelAt<T>(const Texture&, int, int);                                  \
  template Vec4T<T> sampleNearest<T>(const Texture&, Vec2T<T>);                            \
  template Vec4T<T> sampleBilinear<T>(const Texture&, Vec2T<T>);                           \
  template Vec4T<T> sampleTexture<T>(const Texture&, Vec2T<T>, TextureFilter, T);          \
  template SampleFootprintT<T> sampleFootprint<T>(const Texture&, Vec2T<T>, TextureFilter);
TWR_INSTANTIATE_SAMPLING(float)
TWR_INSTANTIATE_SAMPLING(double)
#undef TWR_INSTANTIATE_SAMPLING

}  // namespace twr
