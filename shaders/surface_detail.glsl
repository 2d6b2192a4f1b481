// Height fields: Blinn and emboss bump mapping, the parallax family and self-shadowing. The
// GLSL twin of softrender/surface_detail-inl.h, function by function in the same order of
// operations; docs/parallax.md derives each one. Included between common.glsl and phong.frag.
// Defines (glrender/gl_scene_draw.cpp): HAS_HEIGHT_MAP, and at most one method of
// SURFACE_BUMP_BLINN, SURFACE_BUMP_EMBOSS, SURFACE_PARALLAX, SURFACE_PARALLAX_OFFSET_LIMITED,
// SURFACE_STEEP_PARALLAX, SURFACE_RELIEF, SURFACE_PARALLAX_OCCLUSION (none: the height is only
// shown by a height view); PARALLAX_UV when the method moves uv; SELF_SHADOW with
// SELF_SHADOW_HEIGHT_MARCH or SELF_SHADOW_HORIZON_MAP and HORIZON_DIRECTIONS (4 per texture).
// Heights: red channel, 1 = top; the polygon lies at the top, depth = 1 - h in units of
// heightScale (texture-space units).

// The detail a height field gives one fragment (C++: SurfaceDetailL): the uv every map is read
// at, the height there, the parallax march's steps and bump_blinn's normal. Declared for every
// material: without a height map it holds the fragment's own uv, height 1 and no steps.
struct SurfaceDetail {
  vec2 uv;
  float height;
  float steps;
  vec3 bumpTangent;
};

#ifdef HAS_HEIGHT_MAP
uniform sampler2D heightMap;
uniform float heightScale;  // texture-space units
uniform vec2 heightTexel;   // one level-0 texel, in uv
uniform float layersMin;    // parallaxLayers, as floats
uniform float layersMax;
uniform int layerCap;         // the most iterations of any march (the max layer count)
uniform int refinementSteps;  // relief's binary search
#ifdef SELF_SHADOW_HORIZON_MAP
uniform sampler2D horizonMap0;
uniform sampler2D horizonMap1;
uniform sampler2D horizonMap2;
uniform sampler2D horizonMap3;
#endif

// The fragment's uv differences, set once in main(): every height and map read after a uv
// shift uses them (textureGrad), as the C++ side reads with the fragment's own differences.
vec2 uvDx;
vec2 uvDy;

float heightAt(vec2 uvAt) {
  return textureGrad(heightMap, uvAt, uvDx, uvDy).r;
}

vec3 tangentFromLighting(vec3 w, vec3 t, vec3 b, vec3 n) {
#ifdef LIGHTING_TANGENT
  return safeNormalize(w);
#else
  return safeNormalize(vec3(dot3(t, w), dot3(b, w), dot3(n, w)));
#endif
}

float layerCount(vec3 dir) {
  return layersMin + (layersMax - layersMin) * (1.0 - abs(dir.z));
}

vec3 bumpBlinn(vec2 uv0) {
  float du = heightTexel.x;
  float dv = heightTexel.y;
  float hL = heightAt(vec2(uv0.x - du, uv0.y));
  float hR = heightAt(vec2(uv0.x + du, uv0.y));
  float hD = heightAt(vec2(uv0.x, uv0.y - dv));
  float hU = heightAt(vec2(uv0.x, uv0.y + dv));
  float dhDu = (hR - hL) / (2.0 * du);
  float dhDv = (hU - hD) / (2.0 * dv);
  return safeNormalize(vec3(0.0 - heightScale * dhDu, 0.0 - heightScale * dhDv, 1.0));
}

SurfaceDetail parallax(vec2 uv0, vec3 vT) {
  SurfaceDetail r = SurfaceDetail(uv0, 1.0, 0.0, vec3(0.0, 0.0, 1.0));
  float vz = max(vT.z, MIN_PARALLAX_VIEW_Z);
  float h0 = heightAt(uv0);
#if defined(SURFACE_PARALLAX)
  float depth = (1.0 - h0) * heightScale;
  r.uv = vec2(uv0.x - vT.x / vz * depth, uv0.y - vT.y / vz * depth);
  r.height = h0;
#elif defined(SURFACE_PARALLAX_OFFSET_LIMITED)
  float depth = (1.0 - h0) * heightScale;
  r.uv = vec2(uv0.x - vT.x * depth, uv0.y - vT.y * depth);
  r.height = h0;
#else
  float layers = layerCount(vT);
  float layerDepth = 1.0 / layers;
  float shiftPerLayer = heightScale / layers;
  vec2 deltaUv = vec2(vT.x / vz * shiftPerLayer, vT.y / vz * shiftPerLayer);
  vec2 uvC = uv0;
  float depthC = 0.0;
  float surfaceDepth = 1.0 - h0;
  float steps = 0.0;
  vec2 prevUv = uvC;
  float prevSurfaceDepth = surfaceDepth;
  for (int i = 0; i < layerCap; ++i) {
    if (!(depthC < surfaceDepth)) break;
    prevUv = uvC;
    prevSurfaceDepth = surfaceDepth;
    uvC = vec2(uvC.x - deltaUv.x, uvC.y - deltaUv.y);
    depthC = depthC + layerDepth;
    surfaceDepth = 1.0 - heightAt(uvC);
    steps = steps + 1.0;
  }
#if defined(SURFACE_RELIEF)
  vec2 du = deltaUv;
  float dd = layerDepth;
  for (int k = 0; k < refinementSteps; ++k) {
    du = vec2(du.x * 0.5, du.y * 0.5);
    dd = dd * 0.5;
    bool below = depthC >= surfaceDepth;
    uvC = below ? vec2(uvC.x + du.x, uvC.y + du.y) : vec2(uvC.x - du.x, uvC.y - du.y);
    depthC = below ? depthC - dd : depthC + dd;
    surfaceDepth = 1.0 - heightAt(uvC);
  }
  steps = steps + float(refinementSteps);
#elif defined(SURFACE_PARALLAX_OCCLUSION)
  float after = surfaceDepth - depthC;
  float before = prevSurfaceDepth - depthC + layerDepth;
  float denominator = after - before;
  float weight = abs(denominator) > 0.0 ? after / denominator : 0.0;
  uvC = vec2(prevUv.x * weight + uvC.x * (1.0 - weight), prevUv.y * weight + uvC.y * (1.0 - weight));
#endif
  r.uv = uvC;
  r.steps = steps;
  r.height = heightAt(r.uv);
#endif
  return r;
}

#ifdef SELF_SHADOW_HEIGHT_MARCH
float heightMarchShadow(vec2 uvP, float hP, vec3 lT) {
  float lz = max(lT.z, MIN_PARALLAX_VIEW_Z);
  float layers = layerCount(lT);
  float startDepth = 1.0 - hP;
  float layerDepth = startDepth / layers;
  float shiftPerLayer = heightScale * startDepth / layers;
  vec2 deltaUv = vec2(lT.x / lz * shiftPerLayer, lT.y / lz * shiftPerLayer);
  float occlusion = 0.0;
  vec2 uvC = uvP;
  float depthC = startDepth;
  for (int i = 1; i <= layerCap; ++i) {
    float index = float(i);
    if (!(index < layers && depthC > 0.0)) break;
    uvC = vec2(uvC.x + deltaUv.x, uvC.y + deltaUv.y);
    depthC = depthC - layerDepth;
    float surfaceDepth = 1.0 - heightAt(uvC);
    float above = (depthC - surfaceDepth) * (1.0 - index / layers);
    occlusion = occlusion > above ? occlusion : above;
  }
  float lit = 1.0 - min(occlusion * SELF_SHADOW_SHARPNESS, 1.0);
  return lT.z > 0.0 ? lit : 0.0;
}
#endif

#ifdef SELF_SHADOW_HORIZON_MAP
float horizonShadow(vec2 uvP, vec3 lT) {
  float horizon[HORIZON_DIRECTIONS];
  vec4 texel = textureGrad(horizonMap0, uvP, uvDx, uvDy);
  horizon[0] = texel.x; horizon[1] = texel.y; horizon[2] = texel.z; horizon[3] = texel.w;
#if HORIZON_DIRECTIONS > 4
  texel = textureGrad(horizonMap1, uvP, uvDx, uvDy);
  horizon[4] = texel.x; horizon[5] = texel.y; horizon[6] = texel.z; horizon[7] = texel.w;
#endif
#if HORIZON_DIRECTIONS > 8
  texel = textureGrad(horizonMap2, uvP, uvDx, uvDy);
  horizon[8] = texel.x; horizon[9] = texel.y; horizon[10] = texel.z; horizon[11] = texel.w;
#endif
#if HORIZON_DIRECTIONS > 12
  texel = textureGrad(horizonMap3, uvP, uvDx, uvDy);
  horizon[12] = texel.x; horizon[13] = texel.y; horizon[14] = texel.z; horizon[15] = texel.w;
#endif
  float ax = abs(lT.x);
  float ay = abs(lT.y);
  float sum = max(ax + ay, MIN_LENGTH_SQUARED);
  float q = ay / sum;
  float diamond = lT.x >= 0.0 ? (lT.y >= 0.0 ? q : 4.0 - q) : (lT.y >= 0.0 ? 2.0 - q : 2.0 + q);
  diamond = diamond >= 4.0 ? diamond - 4.0 : diamond;
  float position = diamond * float(HORIZON_DIRECTIONS) / 4.0;
  float k0f = min(floor(position), float(HORIZON_DIRECTIONS - 1));
  float weight = position - k0f;
  int k0 = int(k0f);
  float h0 = horizon[k0];
  float h1 = horizon[(k0 + 1) % HORIZON_DIRECTIONS];
  float horizonSine = h0 + (h1 - h0) * weight;
  float lit = min(max(0.5 + (lT.z - horizonSine) * HORIZON_SHARPNESS, 0.0), 1.0);
  return lT.z > 0.0 ? lit : 0.0;
}
#endif

#ifdef SELF_SHADOW
float selfShadow(SurfaceDetail detail, vec3 lT) {
#if defined(SELF_SHADOW_HEIGHT_MARCH)
  return heightMarchShadow(detail.uv, detail.height, lT);
#else
  return horizonShadow(detail.uv, lT);
#endif
}
#endif

#endif  // HAS_HEIGHT_MAP
