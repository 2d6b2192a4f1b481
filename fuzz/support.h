// Helpers the fuzz targets share: a reader that turns fuzzer bytes into typed values, and
// the checks of the promises the code makes about its results.
#pragma once

#include "scene/conventions.h"
#include "scene/errors.h"
#include "scene/renderer.h"

#include <cstddef>
#include <cstdint>
#include <string>

namespace twr::fuzz {

// Throws InvariantViolation(what) when `condition` is false.
void require(bool condition, const std::string& what);

// An InputError must name the input it refuses: its message starts with `name`.
void requireNamesInput(const InputError& error, const std::string& name);

// The Renderer contract for an output of width x height drawing `triangleCount` triangles:
// every buffer has width * height entries, every depth is finite and in [0, 1], a pixel with
// a triangle id has id < triangleCount and alpha 255, and a pixel with neither a triangle nor
// a debug line keeps the background's alpha (`backgroundAlpha`, clearByte of
// OutputDesc::background.a) and the cleared depth 1.
void checkRenderOutput(const RenderOutput& output, int width, int height, std::size_t triangleCount,
                       std::uint8_t backgroundAlpha, const std::string& what);

// True when every component is finite.
bool isFinite(vec2 v);
bool isFinite(vec3 v);
bool isFinite(vec4 v);

// Reads typed values front to back. Past the end every read yields zero bytes, so any input,
// the empty one included, decodes to something.
class ByteReader {
 public:
  ByteReader(const std::uint8_t* data, std::size_t size) : data_(data), size_(size) {}

  std::uint8_t byte() { return position_ < size_ ? data_[position_++] : 0; }
  std::uint32_t u32();
  // An integer in [low, high] (inclusive both).
  int intIn(int low, int high);
  bool flag() { return (byte() & 1u) != 0; }
  // A finite float, often one of the values that break pipelines: 0, -0, denormals,
  // 1e-30, values near the clipper's w epsilon, 1e30, FLT_MAX, or raw bits.
  float hostileFloat();
  // hostileFloat() folded to >= 0.
  float nonNegativeFloat();
  // A float in a tame range [-8, 8] in steps of 1/16, for values that only need variety.
  float tameFloat();
  // Braced lists evaluate left to right, so every compiler decodes an input alike.
  vec3 hostileVec3() { return vec3{hostileFloat(), hostileFloat(), hostileFloat()}; }
  vec3 tameVec3() { return vec3{tameFloat(), tameFloat(), tameFloat()}; }
  bool exhausted() const { return position_ >= size_; }

 private:
  const std::uint8_t* data_;
  std::size_t size_;
  std::size_t position_ = 0;
};

}  // namespace twr::fuzz
