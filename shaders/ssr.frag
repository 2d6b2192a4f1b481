// Screen-space reflections (docs/ssr.md): one fragment per pixel of a full-screen triangle
// (sky.vert's), after the deferred lighting pass. A pixel whose material has ssr_reflect > 0
// (the G-buffer's specular.w) marches its mirror ray through the depth buffer; on a hit it adds
// reflect_strength * ssr_reflect times the lit colour there, every other fragment is discarded.
// C++ twin: softrender/ssr-inl.h, function by function in the same order of operations.
// Included after common.glsl; GBUFFER_POSITION as in deferred_lighting.frag.

uniform sampler2D gbufferDepth;     // window depth, 1 where nothing was drawn
uniform sampler2D gbufferNormal;    // xyz: the lighting normal, world
uniform sampler2D gbufferSpecular;  // w: ssr_reflect
#ifdef GBUFFER_POSITION
uniform sampler2D gbufferPosition;  // xyz: the world position
#else
uniform mat4 worldFromClip;         // the inverse of the camera's clipFromWorld
#endif
uniform sampler2D litColour;        // the frame after the lighting pass (RGBA8)
uniform mat4 clipFromWorld;
uniform vec2 viewportSize;          // pixels
uniform float distanceNumerator;    // 2 n f
uniform float distanceSum;          // f + n
uniform float distanceDifference;   // f - n
uniform vec3 eyePosWorld;
uniform int adaptiveMarch;          // 0: linear_world, 1: adaptive_world
uniform int maxSteps;
uniform float marchStep;            // world units: linear's every step, adaptive's first
uniform float minStep;              // adaptive's smallest
uniform float thickness;            // world units
uniform float reflectStrength;

layout(location = 0) out vec4 fragColour;

const float SSR_HIT = 1.0;  // SsrResult (softrender/ssr.h)
const float SSR_MISS = 2.0;
const float SSR_OFF_SCREEN = 3.0;
const float SSR_BEHIND = 4.0;

#ifndef GBUFFER_POSITION
// deferred_lighting.frag's worldFromWindow.
vec3 worldFromWindow(vec2 fragCoord, float depth) {
  float x = (2.0 * fragCoord.x) / viewportSize.x - 1.0;
  float y = (2.0 * fragCoord.y) / viewportSize.y - 1.0;
  float z = 2.0 * depth - 1.0;
  mat4 m = worldFromClip;
  float wx = ((m[0][0] * x + m[1][0] * y) + m[2][0] * z) + m[3][0];
  float wy = ((m[0][1] * x + m[1][1] * y) + m[2][1] * z) + m[3][1];
  float wz = ((m[0][2] * x + m[1][2] * y) + m[2][2] * z) + m[3][2];
  float w = ((m[0][3] * x + m[1][3] * y) + m[2][3] * z) + m[3][3];
  return vec3(wx / w, wy / w, wz / w);
}
#endif

// Where a world point lands: its clip w, its window position, whether that is on the screen,
// and its pixel (ssrScreenOfLanes).
struct Screen {
  float w;
  vec2 window;
  bool onScreen;
  ivec2 pixel;
};
// A world point's eye distance: the clip w (ssrDistanceOfPointLanes).
float distanceOfPoint(vec3 p) {
  mat4 m = clipFromWorld;  // columns summed from the left
  return ((m[0][3] * p.x + m[1][3] * p.y) + m[2][3] * p.z) + m[3][3];
}

Screen screenOf(vec3 p) {
  mat4 m = clipFromWorld;  // columns summed from the left
  float x = ((m[0][0] * p.x + m[1][0] * p.y) + m[2][0] * p.z) + m[3][0];
  float y = ((m[0][1] * p.x + m[1][1] * p.y) + m[2][1] * p.z) + m[3][1];
  float w = distanceOfPoint(p);
  bool front = w > 0.0;
  float safeW = front ? w : 1.0;
  Screen s;
  s.w = w;
  s.window = vec2(((x / safeW) * 0.5 + 0.5) * viewportSize.x, ((y / safeW) * 0.5 + 0.5) * viewportSize.y);
  s.onScreen = front && s.window.x >= 0.0 && s.window.x < viewportSize.x && s.window.y >= 0.0 &&
               s.window.y < viewportSize.y;
  s.pixel = s.onScreen ? ivec2(floor(s.window)) : ivec2(0, 0);
  return s;
}

// A window depth's eye distance (ssrDistanceOfDepthLanes), the far plane at the clear depth.
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

// The march (ssrMarchLanes): the result, the steps, the hit pixel.
float march(vec3 origin, vec3 dir, out float steps, out ivec2 hitPixel) {
  float result = SSR_MISS;
  steps = 0.0;
  hitPixel = ivec2(0, 0);
  // Distances along the ray in plain adds, each point origin + dir t (ssrMarchLanes: a
  // multiply-add fused here and not in C++ must not drift from step to step).
  float tCur = 0.0;
  float stepLength = marchStep;
  for (int i = 0; i < maxSteps; ++i) {
    float tNext = tCur + stepLength;
    Screen sn = screenOf(origin + dir * tNext);
    steps = steps + 1.0;
    if (!sn.onScreen) return SSR_OFF_SCREEN;
    float surfaceNext = bufferDistance(sn.pixel);
    bool inFront = sn.w < surfaceNext;
    bool decide = !inFront && (adaptiveMarch == 0 || !(stepLength > minStep));
    if (decide) {
      Screen sc = screenOf(origin + dir * tCur);
      float s1 = bufferDistance(sc.pixel) - sc.w;
      float s2 = sn.w - surfaceNext;
      float sum = s1 + s2;
      float t = sum > 0.0 ? s1 / (sum > 0.0 ? sum : 1.0) : 0.0;
      Screen sh = screenOf(origin + dir * (tCur + stepLength * t));
      if (s1 < thickness && s2 < thickness && sh.onScreen) {
        hitPixel = sh.pixel;
        return SSR_HIT;
      }
      return SSR_BEHIND;
    }
    if (inFront) tCur = tNext;
    if (adaptiveMarch != 0 && !inFront) stepLength = stepLength * 0.5;
  }
  return result;
}

void main() {
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  float depth = texelFetch(gbufferDepth, pixel, 0).r;
  float ssrReflect = texelFetch(gbufferSpecular, pixel, 0).w;
  if (!(depth < 1.0) || !(ssrReflect > 0.0)) discard;  // nothing drawn, or no reflection
  vec3 nl = texelFetch(gbufferNormal, pixel, 0).xyz;
#ifdef GBUFFER_POSITION
  vec3 posWorld = texelFetch(gbufferPosition, pixel, 0).xyz;
#else
  vec3 posWorld = worldFromWindow(gl_FragCoord.xy, depth);
#endif
  vec3 wo = safeNormalize(eyePosWorld - posWorld);
  vec3 r = safeNormalize((2.0 * dot(nl, wo)) * nl - wo);
  float steps;
  ivec2 hitPixel;
  float result = march(posWorld, r, steps, hitPixel);
  if (result != SSR_HIT) discard;  // the lit colour stays
  vec3 colour = texelFetch(litColour, pixel, 0).rgb;
  vec3 reflected = texelFetch(litColour, hitPixel, 0).rgb;
  float k = reflectStrength * ssrReflect;
  fragColour = clamp(vec4(colour + reflected * k, 1.0), 0.0, 1.0);
}
