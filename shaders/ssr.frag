// Screen-space reflections (docs/ssr.md): one fragment per pixel of a full-screen triangle
// (sky.vert's), after the deferred lighting pass. A pixel whose material has ssr_reflect > 0
// (the G-buffer's specular.w) marches its mirror ray through the depth buffer; on a hit it adds
// reflect_strength * ssr_reflect times the lit colour there. With indirect samples every drawn
// pixel also marches rays over its hemisphere and adds its albedo times the light they find.
// A fragment neither changes is discarded.
// C++ twin: softrender/ssr-inl.h, function by function in the same order of operations.
// Included after common.glsl and ssr_distance.glsl (the surface distances; GBUFFER_POSITION as
// there).

uniform sampler2D gbufferNormal;    // xyz: the lighting normal, world
uniform sampler2D gbufferSpecular;  // w: ssr_reflect
#ifndef GBUFFER_POSITION
uniform mat4 worldFromClip;         // the inverse of the camera's clipFromWorld
#endif
uniform sampler2D litColour;        // the frame after the lighting pass (RGBA8)
uniform vec2 viewportSize;          // pixels
uniform vec3 eyePosWorld;
uniform int marchKind;              // 0: linear_world, 1: adaptive_world, 2: dda_screen or hiz
uniform int maxSteps;
uniform float marchStep;            // world units: linear's every step, adaptive's first
uniform float minStep;              // adaptive's smallest
uniform float thickness;            // world units
uniform float reflectStrength;
uniform float nearDistance;         // the camera's near and far, world units: a screen ray's ends
uniform float farDistance;
uniform int hizLevels;              // hiz: the chain's levels above the frame; 0 for dda_screen
uniform sampler2D hizDistance;      // level k: the least surface distance of 2^k x 2^k pixels
uniform int indirectSamples;        // indirect light's rays per pixel (0: none)
uniform int cosineSamples;          // 1: cosine-weighted, 0: uniform over the hemisphere
uniform float indirectScale;        // 1 / indirectSamples, rounded once on the CPU
uniform sampler2D gbufferAlbedo;    // xyz: the diffuse albedo
uniform int debugView;              // 0: none; 1 ssr_hit, 2 ssr_steps, 3 ssr_uv, 4 hiz_level

layout(location = 0) out vec4 fragColour;

const float SSR_HIT = 1.0;  // SsrResult (softrender/ssr.h)
const float SSR_MISS = 2.0;
const float SSR_OFF_SCREEN = 3.0;
const float SSR_BEHIND = 4.0;

// The pixel inspector's probe (scene/ssr_trace.h): with SSR_PROBE the program marches one
// pixel's ray (its mirror ray or an indirect sample's) per fragment of a strip, fragment k
// keeping what step k did; record() is called where ssrRecordStep is in softrender/ssr-inl.h,
// once per step. Without, it does nothing.
#ifdef SSR_PROBE
int probeStep = -1;
int stepIndex = 0;
vec4 probeSample = vec4(0.0);    // pixel x, y, ray distance, surface distance
vec4 probeDecision = vec4(0.0);  // level, kind (SsrStepKind), along, 1 once recorded
void record(float kind, vec2 pixel, float rayDistance, float surfaceDistance, float level, float along) {
  if (stepIndex == probeStep) {
    probeSample = vec4(pixel, rayDistance, surfaceDistance);
    probeDecision = vec4(level, kind, along, 1.0);
  }
  stepIndex = stepIndex + 1;
}
#else
void record(float kind, vec2 pixel, float rayDistance, float surfaceDistance, float level, float along) {}
#endif

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
// and its pixel (screenOf).
struct Screen {
  float w;
  vec2 window;
  bool onScreen;
  ivec2 pixel;
};
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

// The march (march): the result, the steps, the hit pixel.
float march(vec3 origin, vec3 dir, out float steps, out ivec2 hitPixel) {
  float result = SSR_MISS;
  steps = 0.0;
  hitPixel = ivec2(0, 0);
  // Distances along the ray in plain adds, each point origin + dir t (march: a
  // multiply-add fused here and not in C++ must not drift from step to step).
  float tCur = 0.0;
  float stepLength = marchStep;
  for (int i = 0; i < maxSteps; ++i) {
    float tNext = tCur + stepLength;
    Screen sn = screenOf(origin + dir * tNext);
    steps = steps + 1.0;
    if (!sn.onScreen) {
      record(3.0, vec2(0.0), sn.w, 0.0, 0.0, tNext);
      return SSR_OFF_SCREEN;
    }
    float surfaceNext = bufferDistance(sn.pixel);
    bool inFront = sn.w < surfaceNext;
    bool decide = !inFront && (marchKind == 0 || !(stepLength > minStep));
    if (decide) {
      Screen sc = screenOf(origin + dir * tCur);
      float s1 = bufferDistance(sc.pixel) - sc.w;
      float s2 = sn.w - surfaceNext;
      float sum = s1 + s2;
      float t = sum > 0.0 ? s1 / (sum > 0.0 ? sum : 1.0) : 0.0;
      Screen sh = screenOf(origin + dir * (tCur + stepLength * t));
      if (s1 < thickness && s2 < thickness && sh.onScreen) {
        hitPixel = sh.pixel;
        record(1.0, vec2(sn.pixel), sn.w, surfaceNext, 0.0, tNext);
        return SSR_HIT;
      }
      record(2.0, vec2(sn.pixel), sn.w, surfaceNext, 0.0, tNext);
      return SSR_BEHIND;
    }
    record(inFront ? 0.0 : 5.0, vec2(sn.pixel), sn.w, surfaceNext, 0.0, tNext);
    if (inFront) tCur = tNext;
    if (marchKind == 1 && !inFront) stepLength = stepLength * 0.5;
  }
  return result;
}

// The screen marches' ray as a line on the screen (screenRay): sample j at
// (x0, y0) + step j, one pixel a step along the major axis, its eye distance 1 / (k0 + stepK j).
struct ScreenRay {
  vec2 origin;      // window position, pixels
  vec2 step;        // pixels per sample
  float k0, stepK;  // 1 / eye distance at the origin and its change per sample
  float lastSample;
};
ScreenRay screenRay(vec3 origin, vec3 dir) {
  mat4 m = clipFromWorld;
  Screen s0 = screenOf(origin);
  float wPerT = (m[0][3] * dir.x + m[1][3] * dir.y) + m[2][3] * dir.z;
  bool away = wPerT > 0.0;
  bool toward = wPerT < 0.0;
  float tAway = (farDistance - s0.w) / (away ? wPerT : 1.0);
  float tToward = (nearDistance - s0.w) / (toward ? wPerT : -1.0);
  float tEnd = min(max(away ? tAway : (toward ? tToward : farDistance), 0.0), farDistance);
  Screen s1 = screenOf(origin + dir * tEnd);
  float dx = s1.window.x - s0.window.x;
  float dy = s1.window.y - s0.window.y;
  float len = max(abs(dx), abs(dy));
  bool long1 = len >= 1.0;
  float safeLength = long1 ? len : 1.0;
  float safeW0 = s0.w > 0.0 ? s0.w : 1.0;
  float safeW1 = s1.w > 0.0 ? s1.w : 1.0;
  ScreenRay r;
  r.origin = s0.window;
  r.step = vec2(dx / safeLength, dy / safeLength);
  r.k0 = 1.0 / safeW0;
  r.stepK = (1.0 / safeW1 - r.k0) / safeLength;
  r.lastSample = long1 && s0.w > 0.0 ? floor(len) : 0.0;
  return r;
}

// Sample j of a screen ray (sampleAt).
struct Sample {
  float w;
  vec2 pixel;  // 0 off the screen
  bool onScreen;
};
Sample sampleAt(ScreenRay r, float j) {
  float x = r.origin.x + r.step.x * j;
  float y = r.origin.y + r.step.y * j;
  Sample s;
  s.w = 1.0 / (r.k0 + r.stepK * j);
  s.onScreen = x >= 0.0 && x < viewportSize.x && y >= 0.0 && y < viewportSize.y;
  s.pixel = vec2(floor(s.onScreen ? x : 0.0), floor(s.onScreen ? y : 0.0));
  return s;
}

// The hiz cell a pixel falls in at a level of cellSize pixels (the last row and column reach
// the viewport's edge: the level's size rounds down), its bounds in pixels, and the last
// sample of the ray inside it. C++: the cell step of screenMarch.
struct Cell {
  float x;
  float y;
  float left;
  float bottom;
  float right;
  float top;
  float last;
};

Cell cellOf(ScreenRay ray, vec2 pixel, float cellSize) {
  Cell c;
  float levelWidth = floor(viewportSize.x / cellSize);
  float levelHeight = floor(viewportSize.y / cellSize);
  c.x = min(floor(pixel.x / cellSize), levelWidth - 1.0);
  c.y = min(floor(pixel.y / cellSize), levelHeight - 1.0);
  c.left = c.x * cellSize;
  c.bottom = c.y * cellSize;
  c.right = c.x == levelWidth - 1.0 ? viewportSize.x : c.left + cellSize;
  c.top = c.y == levelHeight - 1.0 ? viewportSize.y : c.bottom + cellSize;
  bool rightward = ray.step.x > 0.0;
  bool leftward = ray.step.x < 0.0;
  bool upward = ray.step.y > 0.0;
  bool downward = ray.step.y < 0.0;
  float safeStepX = rightward || leftward ? ray.step.x : 1.0;
  float safeStepY = upward || downward ? ray.step.y : 1.0;
  float lastX = rightward ? (0.0 - floor((ray.origin.x - c.right) / safeStepX)) - 1.0
                          : (leftward ? floor((c.left - ray.origin.x) / safeStepX) : ray.lastSample);
  float lastY = upward ? (0.0 - floor((ray.origin.y - c.top) / safeStepY)) - 1.0
                       : (downward ? floor((c.bottom - ray.origin.y) / safeStepY) : ray.lastSample);
  c.last = min(min(lastX, lastY), ray.lastSample);
  return c;
}

// hiz: the highest level the last march skipped a cell at (SsrMarchL::level).
float levelReached = 0.0;

// dda_screen (hizLevels 0) and hiz (screenMarch): the result, the steps, the hit pixel.
float screenMarch(vec3 origin, vec3 dir, out float steps, out ivec2 hitPixel) {
  steps = 0.0;
  hitPixel = ivec2(0, 0);
  ScreenRay ray = screenRay(origin, dir);
  float skyDistance = distanceOfDepth(1.0);  // where nothing was drawn (ssrUniforms's skyDistance)
  float topLevel = float(hizLevels);
  float j = 0.0;         // the last sample marched: it and every one before lie in front
  float level = 0.0;     // the level the next sample is tried at
  float cellSize = 1.0;  // 2^level pixels
  float blockedUntil = 0.0;  // the last level-1 cell not skipped ends here: single pixels till then
  for (int i = 0; i < maxSteps; ++i) {
    float n = j + 1.0;
    steps = steps + 1.0;
    if (n > ray.lastSample) {
      record(4.0, vec2(0.0), 0.0, 0.0, 0.0, n);
      return SSR_MISS;
    }
    Sample sn = sampleAt(ray, n);
    if (!sn.onScreen) {
      record(3.0, vec2(0.0), sn.w, 0.0, 0.0, n);
      return SSR_OFF_SCREEN;
    }
    if (level == 0.0) {
      float surfaceN = bufferDistance(ivec2(sn.pixel));
      bool inFront = sn.w < surfaceN || !(surfaceN < skyDistance);  // in front, or nothing there
      if (!inFront) {
        // The ray's nearer end of the last step, against this pixel's surface.
        float behindBy = min(sampleAt(ray, j).w, sn.w) - surfaceN;
        if (behindBy < thickness) {
          hitPixel = ivec2(sn.pixel);
          record(1.0, sn.pixel, sn.w, surfaceN, 0.0, n);
          return SSR_HIT;
        }
        record(2.0, sn.pixel, sn.w, surfaceN, 0.0, n);
        return SSR_BEHIND;
      }
      record(0.0, sn.pixel, sn.w, surfaceN, 0.0, n);
      j = n;
      if (topLevel > 0.0 && !(n < blockedUntil)) {
        level = 1.0;
        cellSize = 2.0;
      }
    } else {
      Cell c = cellOf(ray, sn.pixel, cellSize);
      float last = c.last;
      Sample sl = sampleAt(ray, last);
      bool fits = last >= n && sl.onScreen && sl.pixel.x >= c.left && sl.pixel.x < c.right && sl.pixel.y >= c.bottom &&
                  sl.pixel.y < c.top;
      float cellLeast = fits ? texelFetch(hizDistance, ivec2(int(c.x), int(c.y)), int(level)).r : 0.0;
      bool skip = fits && max(sn.w, sl.w) < cellLeast;
      record(skip ? 6.0 : 7.0, sn.pixel, max(sn.w, sl.w), fits ? cellLeast : 0.0, level, skip ? last : n);
      if (skip) {
        j = last;
        levelReached = max(levelReached, level);
        if (level < topLevel) {
          level = level + 1.0;
          cellSize = cellSize * 2.0;
        }
      } else {
        if (fits && level == 1.0) blockedUntil = last;
        level = level - 1.0;
        cellSize = cellSize * 0.5;
      }
    }
  }
  return SSR_MISS;
}

// Indirect light's random pair for sample k of a pixel (ssrRandomPairOf): PCG hashes
// (Jarzynski and Olano 2020), 24 bits each, exact in a float.
uint pcgHash(uint v) {
  uint state = v * 747796405u + 2891336453u;
  uint word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
  return (word >> 22u) ^ word;
}
vec2 randomPair(uvec2 pixel, uint k) {
  uint seed = pcgHash(pixel.x ^ pcgHash(pixel.y ^ pcgHash(k)));
  uint second = pcgHash(seed);
  const float unit = 1.0 / 16777216.0;  // 2^-24
  return vec2(float(seed >> 8u) * unit, float(second >> 8u) * unit);
}

// The cosine and sine of a turn in [0, 1) (circle): the quadrant, then Taylor series.
vec2 circle(float turn) {
  float q4 = turn * 4.0;
  float quadrant = floor(q4);
  float a = (q4 - quadrant) * 1.57079637;
  float a2 = a * a;
  float sinA = a * (1.0 + a2 * (-0.166666672 + a2 * (0.00833333377 + a2 * (-0.000198412701 + a2 * (2.75573188e-06 + a2 * -2.50521079e-08)))));
  float cosA = 1.0 + a2 * (-0.5 + a2 * (0.0416666679 + a2 * (-0.00138888892 + a2 * (2.48015876e-05 + a2 * (-2.755732e-07 + a2 * 2.08767559e-09)))));
  float c = quadrant == 0.0 ? cosA : (quadrant == 1.0 ? 0.0 - sinA : (quadrant == 2.0 ? 0.0 - cosA : sinA));
  float s = quadrant == 0.0 ? sinA : (quadrant == 1.0 ? cosA : (quadrant == 2.0 ? 0.0 - sinA : 0.0 - cosA));
  return vec2(c, s);
}

// A direction over the hemisphere of n in Duff et al.'s basis, and its weight (hemisphere).
vec3 hemisphere(vec3 n, vec2 xi, out float weight) {
  float sign_ = n.z >= 0.0 ? 1.0 : -1.0;
  float a = -1.0 / (sign_ + n.z);
  float b = n.x * n.y * a;
  vec3 b1 = vec3(1.0 + sign_ * n.x * n.x * a, sign_ * b, 0.0 - sign_ * n.x);
  vec3 b2 = vec3(b, sign_ + n.y * n.y * a, 0.0 - n.y);
  vec2 turn = circle(xi.y);
  float z;
  float r;
  if (cosineSamples != 0) {
    r = sqrt(xi.x);
    z = sqrt(max(0.0, 1.0 - xi.x));
    weight = 1.0;
  } else {
    z = xi.x;
    r = sqrt(max(0.0, 1.0 - z * z));
    weight = 2.0 * z;
  }
  return safeNormalize(b1 * (r * turn.x) + b2 * (r * turn.y) + n * z);
}

// The march the settings name (marchOf).
float marchOf(vec3 origin, vec3 dir, out float steps, out ivec2 hitPixel) {
  levelReached = 0.0;
  return marchKind == 2 ? screenMarch(origin, dir, steps, hitPixel) : march(origin, dir, steps, hitPixel);
}

// Indirect diffuse light (indirect): (1 / N) sum weight lit(hit), and the samples that hit.
vec3 indirect(vec3 nl, vec3 posWorld, uvec2 pixel, out float hits) {
  vec3 sum = vec3(0.0);
  hits = 0.0;
  for (int k = 0; k < indirectSamples; ++k) {
    float weight;
    vec3 dir = hemisphere(nl, randomPair(pixel, uint(k)), weight);
    float steps;
    ivec2 hitPixel;
    if (marchOf(posWorld, dir, steps, hitPixel) != SSR_HIT) continue;
    sum = sum + texelFetch(litColour, hitPixel, 0).rgb * weight;
    hits = hits + 1.0;
  }
  return sum * indirectScale;
}

// A debug view's colour for a march (viewColour): debugView 1 ssr_hit, 2 ssr_steps,
// 3 ssr_uv, 4 hiz_level.
vec3 viewColour(float result, float steps, ivec2 hitPixel) {
  bool hit = result == SSR_HIT;
  if (debugView == 1) {
    return hit ? vec3(0.2, 0.85, 0.2)
               : (result == SSR_MISS ? vec3(0.15, 0.3, 0.9)
                                     : (result == SSR_OFF_SCREEN ? vec3(0.95, 0.85, 0.1)
                                                                 : (result == SSR_BEHIND ? vec3(0.9, 0.15, 0.15) : vec3(0.0))));
  }
  if (debugView == 2) return heatColour(steps / float(maxSteps)).rgb;
  if (debugView == 3) {
    float x = (float(hitPixel.x) + 0.5) / viewportSize.x;
    float y = (float(hitPixel.y) + 0.5) / viewportSize.y;
    return hit ? vec3(x, y, 0.0) : vec3(0.0);
  }
  if (hizLevels == 0) return vec3(0.0);
  return heatColour(levelReached / float(hizLevels)).rgb;
}

#ifdef SSR_PROBE
uniform ivec2 probePixel;  // window column and row from the bottom
uniform int probeRay;      // -1: the mirror ray; k >= 0: indirect sample k (traceSsrMarch's ray)

// Fragment (k, 0) of the strip: step k's sample; (k, 1): its decision (zeros past the march's
// end); (0, 2): the ray's direction and weight, (1, 2) its origin.
void main() {
  probeStep = int(gl_FragCoord.x);
  ivec2 pixel = probePixel;
  float depth = texelFetch(gbufferDepth, pixel, 0).r;
  vec3 nl = texelFetch(gbufferNormal, pixel, 0).xyz;
#ifdef GBUFFER_POSITION
  vec3 posWorld = texelFetch(gbufferPosition, pixel, 0).xyz;
#else
  vec3 posWorld = worldFromWindow(vec2(pixel) + 0.5, depth);
#endif
  vec3 wo = safeNormalize(eyePosWorld - posWorld);
  vec3 r = safeNormalize((2.0 * dot3(nl, wo)) * nl - wo);
  float weight = 1.0;
  if (probeRay >= 0) r = hemisphere(nl, randomPair(uvec2(pixel), uint(probeRay)), weight);
  if (gl_FragCoord.y >= 2.0) {  // the ray's row: no march
    fragColour = gl_FragCoord.x < 1.0 ? vec4(r, weight) : vec4(posWorld, 1.0);
    return;
  }
  float steps;
  ivec2 hitPixel;
  marchOf(posWorld, r, steps, hitPixel);
  fragColour = gl_FragCoord.y < 1.0 ? probeSample : probeDecision;
}
#else
void main() {
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  float depth = texelFetch(gbufferDepth, pixel, 0).r;
  float ssrReflect = texelFetch(gbufferSpecular, pixel, 0).w;
  // Nothing drawn, or neither a mirror ray, indirect light nor a debug view: the lit colour stays.
  if (!(depth < 1.0) || !(ssrReflect > 0.0 || indirectSamples > 0 || debugView != 0)) discard;
  vec3 nl = texelFetch(gbufferNormal, pixel, 0).xyz;
#ifdef GBUFFER_POSITION
  vec3 posWorld = texelFetch(gbufferPosition, pixel, 0).xyz;
#else
  vec3 posWorld = worldFromWindow(gl_FragCoord.xy, depth);
#endif
  vec3 wo = safeNormalize(eyePosWorld - posWorld);
  vec3 r = safeNormalize((2.0 * dot3(nl, wo)) * nl - wo);
  if (debugView != 0) {
    float steps;
    ivec2 hitPixel;
    float result = marchOf(posWorld, r, steps, hitPixel);
    fragColour = vec4(viewColour(result, steps, hitPixel), 1.0);
    return;
  }
  vec3 colour = texelFetch(litColour, pixel, 0).rgb;
  vec3 total = colour;
  bool changed = false;
  if (ssrReflect > 0.0) {
    float steps;
    ivec2 hitPixel;
    if (marchOf(posWorld, r, steps, hitPixel) == SSR_HIT) {
      vec3 reflected = texelFetch(litColour, hitPixel, 0).rgb;
      float k = reflectStrength * ssrReflect;
      total = total + reflected * k;
      changed = true;
    }
  }
  if (indirectSamples > 0) {
    float hits;
    vec3 light = indirect(nl, posWorld, uvec2(pixel), hits);
    total = total + texelFetch(gbufferAlbedo, pixel, 0).rgb * light;
    changed = changed || hits > 0.0;
  }
  if (!changed) discard;  // the lit colour stays
  fragColour = clamp(vec4(total, 1.0), 0.0, 1.0);
}
#endif
