#include "fuzz/support.h"

#include "fuzz/targets.h"

#include <array>
#include <cmath>
#include <cstring>
#include <limits>

namespace twr::fuzz {

void require(bool condition, const std::string& what) {
  if (!condition) throw InvariantViolation(what);
}

void requireNamesInput(const InputError& error, const std::string& name) {
  const std::string message = error.what();
  require(message.rfind(name, 0) == 0, "an InputError does not start with the input's name '" + name + "': " + message);
}

bool isFinite(vec2 v) { return std::isfinite(v.x) && std::isfinite(v.y); }
bool isFinite(vec3 v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }
bool isFinite(vec4 v) { return isFinite(vec3(v)) && std::isfinite(v.w); }

void checkRenderOutput(const RenderOutput& output, int width, int height, std::size_t triangleCount,
                       std::uint8_t backgroundAlpha, const std::string& what) {
  const std::size_t pixels = static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
  require(output.width == width && output.height == height, what + ": output size differs from the request");
  require(output.rgba.size() == 4 * pixels, what + ": rgba holds " + std::to_string(output.rgba.size()) + " bytes");
  require(output.depth.size() == pixels, what + ": depth holds " + std::to_string(output.depth.size()) + " values");
  require(output.triangleId.size() == pixels, what + ": triangleId has the wrong size");
  require(output.lineMask.size() == pixels, what + ": lineMask has the wrong size");
  for (std::size_t i = 0; i < pixels; ++i) {
    const float depth = output.depth[i];
    const std::string at = what + ": pixel " + std::to_string(i);
    require(std::isfinite(depth), at + ": depth is not finite");
    require(depth >= 0.0f && depth <= 1.0f, at + ": depth " + std::to_string(depth) + " outside [0, 1]");
    const std::uint32_t id = output.triangleId[i];
    const std::uint8_t alpha = output.rgba[4 * i + 3];
    if (id != kNoTriangle) {
      require(id < triangleCount, at + ": triangle id " + std::to_string(id) + " >= triangle count " +
                                      std::to_string(triangleCount));
      require(alpha == 255, at + ": drawn by a triangle but alpha is " + std::to_string(alpha));
    } else if (output.lineMask[i] == 0) {
      require(alpha == backgroundAlpha, at + ": nothing drawn but alpha is " + std::to_string(alpha) +
                                            ", not the background's " + std::to_string(backgroundAlpha));
      require(depth == 1.0f, at + ": nothing drawn but depth is " + std::to_string(depth));
    }
  }
}

std::uint32_t ByteReader::u32() {
  std::uint32_t value = 0;
  for (int i = 0; i < 4; ++i) value = (value << 8) | byte();
  return value;
}

int ByteReader::intIn(int low, int high) {
  const std::uint64_t range = static_cast<std::uint64_t>(static_cast<std::int64_t>(high) - low) + 1;
  const std::uint64_t raw = range <= 256 ? byte() : u32();
  return static_cast<int>(low + static_cast<std::int64_t>(raw % range));
}

float ByteReader::hostileFloat() {
  constexpr float kMax = std::numeric_limits<float>::max();
  constexpr float kDenormal = std::numeric_limits<float>::denorm_min();
  constexpr float kNormalMin = std::numeric_limits<float>::min();
  static constexpr std::array<float, 32> kSpecial{
      0.0f,  -0.0f, 1.0f,    -1.0f,  0.5f,    -0.5f,   2.0f,     -2.0f,     1e-5f,      -1e-5f,     1.0001e-5f,
      9.999e-6f, 1e-7f, -1e-7f, 1e-30f, -1e-30f, kDenormal, -kDenormal, kNormalMin, -kNormalMin, 1e6f, -1e6f,
      1e20f, -1e20f, 1e30f,   -1e30f, kMax,    -kMax,   16384.0f, -16384.0f, 65536.5f,   0.999999f};
  const std::uint8_t selector = byte();
  if (selector < 128) return kSpecial[selector % kSpecial.size()];
  if (selector < 192) return tameFloat();
  const std::uint32_t bits = u32();
  float value = 0.0f;
  std::memcpy(&value, &bits, sizeof value);
  return std::isfinite(value) ? value : 0.0f;
}

float ByteReader::nonNegativeFloat() { return std::fabs(hostileFloat()); }

float ByteReader::tameFloat() {
  // 256 steps of 1/16 centred on 0: [-8, 7.9375].
  return (static_cast<float>(byte()) - 128.0f) / 16.0f;
}

}  // namespace twr::fuzz
