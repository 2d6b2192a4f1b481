// Stages 6 and 8, depth test and output merge: GL_LESS against a float depth buffer cleared
// to 1, then the colour (RGBA8, alpha 255 where geometry was drawn), the depth and the
// triangle id are written. The test runs before shading (early z): the shader never writes
// depth, so the result is the same as GL's late test, and hidden fragments cost nothing.
#pragma once

#include "softrender/framebuffer.h"

namespace twr {

// GL_LESS: the fragment passes when strictly nearer than what is stored (float on the
// teaching path, double in the reference; a NaN depth never passes).
template <typename T>
inline bool depthTestLess(T fragmentDepth, T storedDepth) {
  return fragmentDepth < storedDepth;
}

// Writes a shaded triangle fragment at (x, y) (GL window coordinates, row 0 at the bottom).
inline void writeFragment(Framebuffer& fb, int x, int y, vec4 colour, float depth, std::uint32_t triangleId) {
  const std::size_t i = fb.index(x, y);
  std::uint8_t* px = &fb.rgba[i * 4];
  px[0] = unitToByte(colour.r);
  px[1] = unitToByte(colour.g);
  px[2] = unitToByte(colour.b);
  px[3] = 255;  // surfaces are opaque (the background has the scene's alpha)
  fb.depth[i] = depth;
  fb.triangleId[i] = triangleId;
}

// Writes a debug-line fragment: colour and depth, and marks the pixel for the compare tools.
inline void writeLineFragment(Framebuffer& fb, int x, int y, vec3 colour, float depth) {
  const std::size_t i = fb.index(x, y);
  std::uint8_t* px = &fb.rgba[i * 4];
  px[0] = unitToByte(colour.r);
  px[1] = unitToByte(colour.g);
  px[2] = unitToByte(colour.b);
  px[3] = 255;
  fb.depth[i] = depth;
  fb.lineMask[i] = 1;
}

}  // namespace twr
