// The eye distances the screen-space reflections compare (docs/ssr.md), shared by ssr.frag
// and hiz.frag. C++ twins: distanceOfPoint, distanceOfDepth and ssrPlanesOf
// (softrender/ssr-inl.h, ssr.cpp). GBUFFER_POSITION: the G-buffer holds the world position.

uniform sampler2D gbufferDepth;     // window depth, 1 where nothing was drawn
#ifdef GBUFFER_POSITION
uniform sampler2D gbufferPosition;  // xyz: the world position
#endif
uniform mat4 clipFromWorld;
uniform float distanceNumerator;    // 2 n f
uniform float distanceSum;          // f + n
uniform float distanceDifference;   // f - n

// A world point's eye distance: the clip w (distanceOfPoint).
float distanceOfPoint(vec3 p) {
  mat4 m = clipFromWorld;  // columns summed from the left
  return ((m[0][3] * p.x + m[1][3] * p.y) + m[2][3] * p.z) + m[3][3];
}

// A window depth's eye distance (distanceOfDepth), the far plane at the clear depth.
float distanceOfDepth(float d) {
  float zNdc = 2.0 * d - 1.0;
  return distanceNumerator / (distanceSum - zNdc * distanceDifference);
}

// The eye distance of the surface the frame holds at a pixel (ssrPlanesOf's plane): the stored
// position's own, the same floats on both renderers; else the depth's.
float bufferDistance(ivec2 pixel) {
  float d = texelFetch(gbufferDepth, pixel, 0).r;
  if (!(d < 1.0)) return distanceOfDepth(1.0);
#ifdef GBUFFER_POSITION
  return distanceOfPoint(texelFetch(gbufferPosition, pixel, 0).xyz);
#else
  return distanceOfDepth(d);
#endif
}
