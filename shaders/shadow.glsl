// Shadow maps (docs/shadows.md, scene/shadow_map.h): the test of a fragment against a light's
// map. C++ twin: softrender/shadow-inl.h, function by function in the same order of
// operations. Compiled in only with HAS_SHADOWS (a scene with a shadowed light), so every
// other scene keeps the program it had. The prelude defines MAX_SHADOWED_LIGHTS,
// MAX_SHADOW_SLOPE_TANGENT, MIN_SHADOW_COSINE, SHADOW_ACNE_TEXELS and the views' colours.

#ifdef HAS_SHADOWS
struct ShadowUniform {
  int kind;             // 0: orthographic (one layer), 1: cube (six layers, GL face order), 2: spot (one perspective layer)
  mat4 clipFromWorld;   // orthographic and spot: the map's clip from world
  vec3 lightPosWorld;   // cube: the light
  float depthA;         // cube and spot: the faces' depth terms, z_clip = depthA (-m) + depthB, w = m
  float depthB;
  float size;           // texels per side
  float biasConstant;   // world units along the light
  float biasSlope;      // texels of the surface's rise
  float texelWorld;     // orthographic: a texel's width, world units; cube: 2 / size, spot: 2 tan(outer) / size (times m)
  float depthPerWorld;  // orthographic: depth units per world unit; cube and spot: 0.5 |depthB| (over m^2)
  int pcf;              // 1, 3 or 5
};
uniform ShadowUniform shadows[MAX_SHADOWED_LIGHTS];
uniform int shadowSlotOfLight[MAX_LIGHTS];  // the light's slot in shadows[], -1: none
// One array texture per slot (GLSL 330 indexes sampler arrays by constants only): each layer
// holds window depths, texel (x, y) = the layer's window pixel (x, y).
uniform sampler2DArray shadowMap0;
uniform sampler2DArray shadowMap1;
uniform sampler2DArray shadowMap2;
uniform sampler2DArray shadowMap3;

float shadowTexel(int slot, ivec3 texel) {
  if (slot == 0) return texelFetch(shadowMap0, texel, 0).r;
  if (slot == 1) return texelFetch(shadowMap1, texel, 0).r;
  if (slot == 2) return texelFetch(shadowMap2, texel, 0).r;
  return texelFetch(shadowMap3, texel, 0).r;
}

struct ShadowTest {
  float visibility;  // [0, 1], 1 outside the map
  float depth;       // the fragment's depth from the light
  float bias;
  float stored;      // the map's depth at the fragment's texel, 1 outside
  float inside;      // 1 inside the map, else 0
  float acneWindow;  // depth units: SHADOW_ACNE_TEXELS of the surface's own rise (at least a texel's)
  float reference;   // what each tap compares with the map: depth - bias
  vec2 texel;        // the fragment's own texel (the kernel's centre), 0 outside the map
  float layer;       // its layer (a cube's face), 0 outside the map
};

// GL's cube face table with llvmpipe's tie rule (cubeCoord in softrender/cube_sample-inl.h).
void shadowCubeCoord(vec3 r, out float face, out float s, out float t) {
  float ax = abs(r.x), ay = abs(r.y), az = abs(r.z);
  bool onZ = az >= max(ax, ay);
  bool onX = !onZ && ax > ay;
  bool onY = !(onZ || onX);
  bool xNegative = r.x < 0.0, yNegative = r.y < 0.0;
  bool zNegative = r.z < 0.0 || (r.z == 0.0 && 1.0 / r.z < 0.0);
  float negZ = 0.0 - r.z, negY = 0.0 - r.y, negX = 0.0 - r.x;
  face = onZ ? (zNegative ? 5.0 : 4.0) : (onX ? (xNegative ? 1.0 : 0.0) : (yNegative ? 3.0 : 2.0));
  float sc = onZ ? (zNegative ? negX : r.x) : (onX ? (xNegative ? r.z : negZ) : r.x);
  float tc = onY ? (yNegative ? negZ : r.z) : negY;
  float ma = onZ ? az : (onX ? ax : ay);
  bool usable = ma > 0.0;
  float k = usable ? 0.5 / (usable ? ma : 1.0) : 0.0;
  s = sc * k + 0.5;
  t = tc * k + 0.5;
}

// The test at posWorld; n the surface's unit normal, l the unit vector to the light (world).
ShadowTest shadowTest(int slot, vec3 posWorld, vec3 n, vec3 l) {
  ShadowUniform u = shadows[slot];
  float cosTheta = max(dot3(n, l), MIN_SHADOW_COSINE);
  float sinTheta = sqrt(max(1.0 - cosTheta * cosTheta, 0.0));
  float tanTheta = min(sinTheta / cosTheta, MAX_SHADOW_SLOPE_TANGENT);

  float s, t, z, layer, texelWorld, depthPerWorld;
  bool inFront = true;  // a spot map's points behind the light are outside it
  if (u.kind == 0 || u.kind == 2) {
    mat4 m = u.clipFromWorld;  // columns summed from the left (orthographic: w = 1)
    float x = ((m[0][0] * posWorld.x + m[1][0] * posWorld.y) + m[2][0] * posWorld.z) + m[3][0];
    float y = ((m[0][1] * posWorld.x + m[1][1] * posWorld.y) + m[2][1] * posWorld.z) + m[3][1];
    if (u.kind == 0) {
      float zc = ((m[0][2] * posWorld.x + m[1][2] * posWorld.y) + m[2][2] * posWorld.z) + m[3][2];
      s = x * 0.5 + 0.5;
      t = y * 0.5 + 0.5;
      z = zc * 0.5 + 0.5;
      texelWorld = u.texelWorld;
      depthPerWorld = u.depthPerWorld;
    } else {
      // Spot: w is the distance along the cone's axis, m; the depth as a cube face's at m.
      float w = ((m[0][3] * posWorld.x + m[1][3] * posWorld.y) + m[2][3] * posWorld.z) + m[3][3];
      inFront = w > 0.0;
      float safeW = inFront ? w : 1.0;
      s = (x / safeW) * 0.5 + 0.5;
      t = (y / safeW) * 0.5 + 0.5;
      z = 0.5 * ((u.depthB - u.depthA * safeW) / safeW) + 0.5;
      texelWorld = u.texelWorld * safeW;
      depthPerWorld = u.depthPerWorld / (safeW * safeW);
    }
    layer = 0.0;
  } else {
    vec3 d = posWorld - u.lightPosWorld;
    shadowCubeCoord(d, layer, s, t);
    float ma = max(abs(d.z), max(abs(d.x), abs(d.y)));
    z = 0.5 * ((u.depthB - u.depthA * ma) / ma) + 0.5;
    texelWorld = u.texelWorld * ma;
    depthPerWorld = u.depthPerWorld / (ma * ma);
  }
  // bias = (constant + slope tan(theta) texel (1 + pcf / 2)) depth units per world unit
  float reach = float(1 + u.pcf / 2);
  float rise = tanTheta * texelWorld;
  float bias = (u.biasConstant + (u.biasSlope * rise) * reach) * depthPerWorld;
  bool inside = inFront && s >= 0.0 && s < 1.0 && t >= 0.0 && t < 1.0 && z <= 1.0 && !isinf(z) && !isnan(z);
  float size = u.size, last = size - 1.0;
  float x0 = inside ? floor(s * size) : 0.0;
  float y0 = inside ? floor(t * size) : 0.0;
  int layerRead = inside ? int(layer) : 0;
  float reference = z - bias;
  int radius = u.pcf / 2;
  float lit = 0.0, stored = 1.0;
  for (int dy = -radius; dy <= radius; ++dy) {
    float ty = min(max(y0 + float(dy), 0.0), last);
    for (int dx = -radius; dx <= radius; ++dx) {
      float tx = min(max(x0 + float(dx), 0.0), last);
      float texel = shadowTexel(slot, ivec3(int(tx), int(ty), layerRead));
      lit += reference <= texel ? 1.0 : 0.0;
      if (dx == 0 && dy == 0) stored = texel;
    }
  }
  ShadowTest r;
  r.visibility = inside ? lit / float(u.pcf * u.pcf) : 1.0;
  r.depth = z;
  r.bias = bias;
  r.stored = inside ? stored : 1.0;
  r.inside = inside ? 1.0 : 0.0;
  r.acneWindow = (SHADOW_ACNE_TEXELS * max(rise, texelWorld)) * depthPerWorld;
  r.reference = reference;
  r.texel = vec2(x0, y0);
  r.layer = float(layerRead);
  return r;
}

// The shadow view's colour: lit and in shadow blended by the visibility, acne, turned away.
vec4 shadowViewColour(ShadowTest test, float nDotL) {
  vec3 lit = SHADOW_VIEW_LIT, shadowed = SHADOW_VIEW_SHADOWED;
  vec3 c = shadowed + (lit - shadowed) * test.visibility;
  float reference = test.depth - test.bias;
  bool acne = test.inside > 0.0 && test.stored < reference && reference - test.stored < test.acneWindow;
  c = acne ? SHADOW_VIEW_ACNE : c;
  c = nDotL > 0.0 ? c : SHADOW_VIEW_AWAY;
  return vec4(c, 1.0);
}

// The light_depth view: the map's depth at the fragment's texel as grey, dark red outside.
vec4 lightDepthColour(ShadowTest test) {
  return vec4(test.inside > 0.0 ? vec3(test.stored) : LIGHT_DEPTH_OUTSIDE, 1.0);
}

#ifdef SHADOW_PROBE
// The pixel inspector's probe (scene/shadow_trace.h): the test of light shadowProbeLight at the
// one pixel drawn, one field per draw, its 32 bits as the colour's four bytes (lowest first),
// which RGBA8 keeps exactly. Field 0 the compared depth, 1 the depth, 2 the bias, 3 the
// visibility, 4 the stored depth, 5 the texel: x | y << 12 | layer << 24 | inside << 27.
// C++ reader: traceGlShadowTaps (glrender/gl_renderer.cpp).
uniform int shadowProbeLight;
uniform int shadowProbeField;

vec4 shadowProbeColour(ShadowTest test, bool tested) {
  uint bits = 0u;
  if (shadowProbeField == 0) bits = floatBitsToUint(test.reference);
  if (shadowProbeField == 1) bits = floatBitsToUint(test.depth);
  if (shadowProbeField == 2) bits = floatBitsToUint(test.bias);
  if (shadowProbeField == 3) bits = floatBitsToUint(test.visibility);
  if (shadowProbeField == 4) bits = floatBitsToUint(test.stored);
  if (shadowProbeField == 5) {
    bits = uint(test.texel.x) | (uint(test.texel.y) << 12) | (uint(test.layer) << 24) | (test.inside > 0.0 ? 1u << 27 : 0u);
  }
  if (!tested) bits = 0xffffffffu;  // the light was not tested here (no map)
  uvec4 bytes = uvec4(bits & 255u, (bits >> 8) & 255u, (bits >> 16) & 255u, bits >> 24);
  return vec4(bytes) / 255.0;
}
#endif
#endif
