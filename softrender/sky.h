// The sky box on the CPU: where no triangle was drawn, the environment in the pixel's view
// direction (scene/sky_view.h has the direction), the C++ twin of shaders/sky.frag. The cube
// is read as texture() reads it: trilinear and seamless, the LOD from the direction's quad
// differences (cube_sample-inl.h).
#pragma once

#include "scene/scene.h"
#include "scene/sky_view.h"
#include "softrender/framebuffer.h"
#include "softrender/precision.h"

namespace twr {

// The sky's colour at pixel (px, py), in [0, 1] (clamped as every fragment is).
vec3 skyColour(const SkyUniformsT<float>& sky, int px, int py);

// Writes the sky into every pixel of rows [rowBegin, rowEnd) with no triangle (window rows).
void drawSkyRows(const SkyUniformsT<float>& sky, Framebuffer& fb, int rowBegin, int rowEnd);

// The same over the whole frame, split into bands over `threads` threads.
void drawSky(const SkyUniformsT<float>& sky, Framebuffer& fb, int threads);

}  // namespace twr
