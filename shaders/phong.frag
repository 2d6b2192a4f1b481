// Fragment stage of the shading contract (docs/shading.md). Its C++ twin is
// shadeFragment() in softrender/shade-inl.h: same inputs, steps and order of operations.
// main() is the tutorial's list of named steps (surface frame, material texels, unlit terms,
// lights, environment, shadow views, output), each a function here and one there; the table of
// twins is docs/shading.md's.
// Permutation defines: HAS_DIFFUSE_MAP, HAS_NORMAL_MAP, HAS_SPECULAR_MAP, LIGHTING_TANGENT
// (else world lighting space), AFFINE_INTERPOLATION (common.glsl's VARYING), and exactly one
// VIEW_<NAME> (VIEW_SHADED ... VIEW_EYE_TANGENT).
// Texture conventions, each set only for a material that needs it (so every other scene
// compiles the program it always did): NORMAL_MAP_GREEN_DOWN (a Direct3D-style normal map:
// green flipped), NORMAL_MAP_XY (a two-channel normal map, BC5: z rebuilt from x and y),
// NORMAL_MAP_STRENGTH (x and y scaled by normalStrength), and DIFFUSE_UV_TRANSFORM,
// NORMAL_UV_TRANSFORM, SPECULAR_UV_TRANSFORM (that map read at uv * <map>UvScale +
// <map>UvOffset). The debug views keep the untransformed uv.
// Height fields (shaders/surface_detail.glsl, included before this file): HAS_HEIGHT_MAP, the
// method's SURFACE_<NAME>, PARALLAX_UV (every map is then read at the shifted uv with the
// fragment's own uv differences, textureGrad), SELF_SHADOW_*; the views VIEW_HEIGHT,
// VIEW_PARALLAX_OFFSET, VIEW_PARALLAX_STEPS, VIEW_SELF_SHADOW.
// Environment (shaders/environment.glsl, included before this file): HAS_ENVIRONMENT,
// ENVIRONMENT_REFLECT (with ENVIRONMENT_PREFILTERED), ENVIRONMENT_REFRACTION, FRESNEL_SCHLICK, ENVIRONMENT_DIFFUSE (with
// ENVIRONMENT_IRRADIANCE or ENVIRONMENT_SH9).
// Shadow maps (shaders/shadow.glsl, included before this file): HAS_SHADOWS; the views
// SHADOW_VIEW_SHADOW and SHADOW_VIEW_LIGHT_DEPTH (with VIEW_SHADED); SHADOW_PROBE (with
// VIEW_SHADED): the pixel inspector's probe of one light's test (shadow.glsl).
// NO_TRIANGLE_ID: no triangle-id output, as an OpenGL user's shader has none (the lean
// frame, glrender/gl_renderer.h; llvmpipe pays for gl_PrimitiveID even when no draw buffer
// takes the output).
// Phong's terms alone (with VIEW_SHADED): PHONG_TERM_VIEW and one of PHONG_TERM_VIEW_AMBIENT,
// PHONG_TERM_VIEW_DIFFUSE, PHONG_TERM_VIEW_SPECULAR.
// GBUFFER_PASS (with VIEW_SHADED): the deferred pipeline's G-buffer pass, the surface written
// to five targets instead of the colour (docs/deferred.md); GBUFFER_POSITION: and the world
// position to a sixth. The frame's lights and the light
// loop are shaders/lighting.glsl's, included before this file.

VARYING in vec3 posWorld;
VARYING in vec3 nWorld;
VARYING in vec3 tWorld;
VARYING in vec3 bWorld;
VARYING in vec2 uv;
#ifdef LIGHTING_TANGENT
VARYING in vec3 lightDirTangent[MAX_LIGHTS];
VARYING in vec3 eyeDirTangent;
#endif

uniform vec3 ka;  // material reflectances
uniform vec3 kd;
uniform vec3 ks;
uniform float shininess;  // Phong exponent, >= 0
#ifdef GBUFFER_PASS
uniform float ssrReflect;  // the material's share of the screen-space reflection (specular.w)
#endif
uniform vec3 ambient;     // Ia
uniform uint firstTriangleId;
uniform sampler2D diffuseMap;
uniform sampler2D normalMap;
uniform sampler2D specularMap;
#ifdef NORMAL_MAP_STRENGTH
uniform float normalStrength;  // scales the mapped normal's x and y (an MTL's -bm)
#endif
#ifdef DIFFUSE_UV_TRANSFORM
uniform vec2 diffuseUvScale;
uniform vec2 diffuseUvOffset;
#endif
#ifdef NORMAL_UV_TRANSFORM
uniform vec2 normalUvScale;
uniform vec2 normalUvOffset;
#endif
#ifdef SPECULAR_UV_TRANSFORM
uniform vec2 specularUvScale;
uniform vec2 specularUvOffset;
#endif

#ifdef GBUFFER_PASS
// The deferred pipeline's G-buffer (scene/renderer.h's GBuffer, target by target); the
// triangle id after them. A material whose light terms read its height field is lit here.
layout(location = 0) out vec4 gbufferNormal;
layout(location = 1) out vec4 gbufferGeometric;
layout(location = 2) out vec4 gbufferAlbedo;
layout(location = 3) out vec4 gbufferSpecular;
layout(location = 4) out vec4 gbufferEmission;
#ifdef GBUFFER_POSITION
layout(location = 5) out vec4 gbufferPosition;
#endif
#ifndef NO_TRIANGLE_ID
layout(location = 6) out uint fragTriangleId;
#endif
#if defined(SURFACE_BUMP_EMBOSS) || defined(SELF_SHADOW)
#define GBUFFER_LIT_HERE
#endif
#else
layout(location = 0) out vec4 fragColour;
#ifndef NO_TRIANGLE_ID
layout(location = 1) out uint fragTriangleId;
#endif
#endif

// A material map's texel at uvAt. After a uv shift the map is read with the fragment's own uv
// differences, scaled by the map's uv transform (textureGrad). C++: sampleMap.
vec4 sampleMap(sampler2D map, vec2 uvAt, vec2 uvScale) {
#ifdef PARALLAX_UV
  return textureGrad(map, uvAt, uvDx * uvScale, uvDy * uvScale);
#else
  return texture(map, uvAt);
#endif
}

// The fragment's view vector in the lighting space: the vertex stage's in tangent space.
vec3 eyeVector() {
#ifdef LIGHTING_TANGENT
  return eyeDirTangent;
#else
  return eyePosWorld - posWorld;
#endif
}

// What lighting reads of the surface at this fragment (C++: surfaceFrame): the normalised
// frame; the surface detail (the parallax methods move the uv every map is read at, bump_blinn
// makes the normal, the rest read the height at uv); the normal map's decoded normal; and nl,
// the normal lighting uses, in the lighting space.
struct SurfaceFrame {
  vec3 n;
  vec3 t;
  vec3 b;
  SurfaceDetail detail;
  vec3 mappedTangent;
  vec3 nl;
};

SurfaceFrame surfaceFrame() {
  SurfaceFrame s;
  s.n = safeNormalize(nWorld);
  s.t = safeNormalize(tWorld);
  s.b = safeNormalize(bWorld);
  s.detail = SurfaceDetail(uv, 1.0, 0.0, vec3(0.0, 0.0, 1.0));
#ifdef HAS_HEIGHT_MAP
  uvDx = dFdx(uv);
  uvDy = dFdy(uv);
#ifdef PARALLAX_UV
  vec3 vT = tangentFromLighting(eyeVector(), s.t, s.b, s.n);
  s.detail = parallax(uv, vT);
#else
#ifdef SURFACE_BUMP_BLINN
  s.detail.bumpTangent = bumpBlinn(uv);
#endif
  s.detail.height = heightAt(uv);
#endif
#endif
  s.mappedTangent = vec3(0.0, 0.0, 1.0);
#ifdef HAS_NORMAL_MAP
#ifdef NORMAL_UV_TRANSFORM
  vec4 normalTexel = sampleMap(normalMap, s.detail.uv * normalUvScale + normalUvOffset, normalUvScale);
#else
  vec4 normalTexel = sampleMap(normalMap, s.detail.uv, vec2(1.0));
#endif
  vec3 encoded = normalTexel.rgb;
#ifdef NORMAL_MAP_GREEN_DOWN
  encoded.g = 1.0 - encoded.g;  // green pointing down: flip it to +v
#endif
  vec3 tangentNormal = 2.0 * encoded - 1.0;
#ifdef NORMAL_MAP_XY
  // Two channels (BC5 samples as (r, g, 0, 1)): z from unit length, never sqrt of < 0.
  tangentNormal.z = sqrt(max(1.0 - (tangentNormal.x * tangentNormal.x + tangentNormal.y * tangentNormal.y), 0.0));
#endif
#ifdef NORMAL_MAP_STRENGTH
  tangentNormal.xy = tangentNormal.xy * normalStrength;
#endif
  s.mappedTangent = safeNormalize(tangentNormal);
#endif
#ifdef SURFACE_BUMP_BLINN
  s.mappedTangent = s.detail.bumpTangent;
#endif
  s.nl = s.n;
#if defined(LIGHTING_TANGENT)
  s.nl = s.mappedTangent;
#elif defined(HAS_NORMAL_MAP) || defined(SURFACE_BUMP_BLINN)
  s.nl = safeNormalize(s.t * s.mappedTangent.x + s.b * s.mappedTangent.y + s.n * s.mappedTangent.z);
#endif
  return s;
}

// The material's own texels at the surface detail's uv (C++: materialTexels): the diffuse
// map's albedo and the specular map's scale, 1 without the map, each map read at its own uv
// (its uv transform, an MTL's -s and -o).
struct MaterialTexels {
  vec3 albedo;
  vec3 specScale;
};

MaterialTexels materialTexels(vec2 uvMaps) {
  MaterialTexels m = MaterialTexels(vec3(1.0), vec3(1.0));
#ifdef HAS_DIFFUSE_MAP
#ifdef DIFFUSE_UV_TRANSFORM
  m.albedo = sampleMap(diffuseMap, uvMaps * diffuseUvScale + diffuseUvOffset, diffuseUvScale).rgb;
#else
  m.albedo = sampleMap(diffuseMap, uvMaps, vec2(1.0)).rgb;
#endif
#endif
#ifdef HAS_SPECULAR_MAP
#ifdef SPECULAR_UV_TRANSFORM
  m.specScale = sampleMap(specularMap, uvMaps * specularUvScale + specularUvOffset, specularUvScale).rgb;
#else
  m.specScale = sampleMap(specularMap, uvMaps, vec2(1.0)).rgb;
#endif
#endif
  return m;
}

// What no light scales, summed first (C++: unlitTerms): the ambient term, then the
// environment's diffuse light, added as the lights' diffuse terms are (environment.glsl). The
// forward shading adds the lights to it; the G-buffer pass stores it.
vec3 unlitTerms(SurfaceFrame s, vec3 albedo, vec3 kdAlbedo) {
  vec3 ambientTerm = ka * albedo * ambient;
  vec3 unlit = ambientTerm;
#ifdef ENVIRONMENT_DIFFUSE
  unlit = unlit + kdAlbedo * environmentDiffuse(s.nl, s.t, s.b, s.n);
#endif
  return unlit;
}

// The frame's lights at this fragment (lighting.glsl's lightSum, C++: lightSum).
LightSum lightsAt(SurfaceFrame s, vec3 kdAlbedo, vec3 ksSpec) {
  return lightSum(posWorld, s.n, s.t, s.b, s.nl, kdAlbedo, ksSpec, shininess
#ifdef LIGHTING_TANGENT
                  , lightDirTangent, eyeDirTangent
#endif
#ifdef HAS_HEIGHT_MAP
                  , s.detail, uv
#endif
  );
}

// The environment mixed into the Phong colour (environment.glsl), or one of its views; an
// environment view on a surface that reads no reflection is dimmed to grey. C++: the
// environment step of shadeFragment.
vec4 environmentStep(SurfaceFrame s, vec4 colour) {
#if defined(ENVIRONMENT_REFLECT) || defined(ENVIRONMENT_REFRACTION)
  vec3 reflectWorld;
  float reflectLod;
  vec3 reflected;
  float share;
  colour = vec4(environmentMix(s.nl, eyeVector(), s.t, s.b, s.n, colour.rgb, reflectWorld, reflectLod, reflected, share),
                1.0);
#ifdef ENVIRONMENT_VIEW
  colour = environmentViewColour(reflectWorld, reflectLod);
#endif
#elif defined(ENVIRONMENT_VIEW)
  colour = dimmedColour(colour);
#endif
  return colour;
}

// The shadow views (shadow.glsl): the first shadowed light's test, or dimmed without one; the
// pixel inspector's probe of its bits. C++: the shadow-view step of shadeFragment.
vec4 shadowViewStep(LightSum lit, vec4 colour) {
#if defined(SHADOW_VIEW_SHADOW) || defined(SHADOW_VIEW_LIGHT_DEPTH)
#ifdef HAS_SHADOWS
  if (!lit.haveShadowTest) {
    colour = dimmedColour(colour);
  } else {
#ifdef SHADOW_VIEW_SHADOW
    colour = shadowViewColour(lit.firstShadowTest, lit.firstShadowCosine);
#else
    colour = lightDepthColour(lit.firstShadowTest);
#endif
  }
#else
  colour = dimmedColour(colour);
#endif
#endif
#ifdef SHADOW_PROBE
  colour = shadowProbeColour(lit.firstShadowTest, lit.haveShadowTest);  // shadow.glsl: one field's bits
#endif
  return colour;
}

#ifdef GBUFFER_PASS
// The G-buffer's targets for this fragment (C++: gbufferFragment, softrender/deferred-inl.h).
// The lighting normal in world space: a tangent-space material's mapped normal through its TBN.
// A material lit here stores its colour as emission; any other folds the environment's mix,
// colour = phong + (C - phong) w, into the targets: albedo and specular scaled by (1 - w), the
// emission (1 - w) unlit + w C. Refraction: w = 1.
void gbufferFragment(SurfaceFrame s, vec3 kdAlbedo, vec3 ksSpec, vec3 unlit, vec4 colour) {
  vec3 nlWorld = s.nl;
#ifdef LIGHTING_TANGENT
#if defined(HAS_NORMAL_MAP) || defined(SURFACE_BUMP_BLINN)
  nlWorld = safeNormalize(s.t * s.mappedTangent.x + s.b * s.mappedTangent.y + s.n * s.mappedTangent.z);
#else
  nlWorld = s.n;
#endif
#endif
  gbufferNormal = vec4(nlWorld, shininess);
  gbufferGeometric = vec4(s.n, 1.0);
#ifdef GBUFFER_POSITION
  gbufferPosition = vec4(posWorld, 1.0);
#endif
#ifdef GBUFFER_LIT_HERE
  gbufferAlbedo = vec4(0.0, 0.0, 0.0, 1.0);
  gbufferSpecular = vec4(0.0, 0.0, 0.0, ssrReflect);
  gbufferEmission = vec4(clamp(colour.rgb, 0.0, 1.0), 1.0);
#else
  float mixShare = 0.0;
  vec3 mixTarget = vec3(0.0);
#if defined(ENVIRONMENT_REFLECT) || defined(ENVIRONMENT_REFRACTION)
  vec3 reflectWorld;
  float reflectLod;
  vec3 reflected;
  float share;
  vec3 mixed = environmentMix(s.nl, eyeVector(), s.t, s.b, s.n, vec3(0.0), reflectWorld, reflectLod, reflected, share);
#ifdef ENVIRONMENT_REFRACTION
  mixShare = 1.0;
  mixTarget = mixed;
#else
  mixShare = share;
  mixTarget = reflected;
#endif
#endif
  float keep = 1.0 - mixShare;
  gbufferAlbedo = vec4(kdAlbedo * keep, 1.0);
  gbufferSpecular = vec4(ksSpec * keep, ssrReflect);
  gbufferEmission = vec4(unlit * keep + mixTarget * mixShare, 1.0);
#endif
}
#endif

#ifdef PHONG_TERM_VIEW
// A Phong-term view's colour (C++: phongTermColour): the ambient term, or the lights'
// diffuse or specular terms summed (lighting.glsl), alpha 1.
vec4 phongTermColour(vec3 ambientTerm, LightSum lit) {
#if defined(PHONG_TERM_VIEW_AMBIENT)
  return vec4(ambientTerm, 1.0);
#elif defined(PHONG_TERM_VIEW_DIFFUSE)
  return vec4(lit.diffuseSum, 1.0);
#else
  return vec4(lit.specularSum, 1.0);
#endif
}
#endif

// The shaded view (C++: shadeFragment' View::Shaded branch): unlit terms, the lights, the
// environment and the shadow views; the G-buffer pass writes its targets instead.
vec4 shadedColour(SurfaceFrame s, MaterialTexels m) {
  vec3 kdAlbedo = kd * m.albedo;     // diffuse's first product
  vec3 ksSpec = ks * m.specScale;    // specular's first
  vec3 unlit = unlitTerms(s, m.albedo, kdAlbedo);
  vec4 colour = vec4(0.0);
#if !defined(GBUFFER_PASS) || defined(GBUFFER_LIT_HERE)
  LightSum lit = lightsAt(s, kdAlbedo, ksSpec);
  colour = vec4(unlit + lit.sum, 1.0);
  colour = environmentStep(s, colour);
  colour = shadowViewStep(lit, colour);
#ifdef PHONG_TERM_VIEW
  colour = phongTermColour(ka * m.albedo * ambient, lit);  // unlitTerms' ambient term
#endif
#endif
#ifdef GBUFFER_PASS
  gbufferFragment(s, kdAlbedo, ksSpec, unlit, colour);
#endif
  return colour;
}

// A tangent-space direction view: the first light's or the eye's direction in the fragment's
// tangent frame; no light gives (0, 0, 0), shown as grey 0.5. C++: shadeFragment'
// LightTangent and EyeTangent branch.
vec4 tangentDirectionColour(SurfaceFrame s, bool toLight) {
  vec3 dirTangent = vec3(0.0);
  if (!toLight || lightCount > 0) {
#ifdef LIGHTING_TANGENT
    dirTangent = safeNormalize(toLight ? lightDirTangent[0] : eyeDirTangent);
#else
    vec3 w = toLight ? toLightWorld(lights[0], posWorld) : eyePosWorld - posWorld;
    dirTangent = safeNormalize(vec3(dot3(s.t, w), dot3(s.b, w), dot3(s.n, w)));
#endif
  }
  return vectorAsColour(dirTangent);
}

// The first light's self-shadowing factor as grey (1 without self-shadowing or lights).
// C++: shadeFragment' SelfShadow branch.
vec4 selfShadowColour(SurfaceFrame s) {
  float shadow = 1.0;
#ifdef SELF_SHADOW
  if (lightCount > 0) {
#ifdef LIGHTING_TANGENT
    vec3 lVec0 = lightDirTangent[0];
#else
    vec3 lVec0 = toLightWorld(lights[0], posWorld);
#endif
    shadow = selfShadow(s.detail, tangentFromLighting(lVec0, s.t, s.b, s.n));
  }
#endif
  return vec4(shadow, shadow, shadow, 1.0);
}

#ifndef VIEW_SHADED
// The debug views (C++: shadeFragment' other branches, in the same order).
vec4 debugViewColour(SurfaceFrame s, MaterialTexels m) {
#if defined(VIEW_ALBEDO)
  return vec4(m.albedo * kd, 1.0);
#elif defined(VIEW_NORMAL)
  return vectorAsColour(s.n);
#elif defined(VIEW_TANGENT)
  return vectorAsColour(s.t);
#elif defined(VIEW_BITANGENT)
  return vectorAsColour(s.b);
#elif defined(VIEW_MAPPED_NORMAL)
  return vectorAsColour(s.nl);
#elif defined(VIEW_UV)
  return vec4(uv.x - floor(uv.x), uv.y - floor(uv.y), 0.0, 1.0);
#elif defined(VIEW_DEPTH)
  float depth = clamp(gl_FragCoord.z, 0.0, 1.0);  // window depth, clamped to the depth range
  return vec4(depth, depth, depth, 1.0);
#elif defined(VIEW_LIGHT_TANGENT)
  return tangentDirectionColour(s, true);
#elif defined(VIEW_EYE_TANGENT)
  return tangentDirectionColour(s, false);
#elif defined(VIEW_HEIGHT)
  return vec4(s.detail.height, s.detail.height, s.detail.height, 1.0);
#elif defined(VIEW_PARALLAX_OFFSET)
  return vec4(0.5 + (s.detail.uv.x - uv.x) * PARALLAX_OFFSET_VIEW_GAIN,
              0.5 + (s.detail.uv.y - uv.y) * PARALLAX_OFFSET_VIEW_GAIN, 0.5, 1.0);
#elif defined(VIEW_PARALLAX_STEPS)
#ifdef HAS_HEIGHT_MAP
  return heatColour(s.detail.steps / float(layerCap + refinementSteps));
#else
  return heatColour(0.0);
#endif
#elif defined(VIEW_SELF_SHADOW)
  return selfShadowColour(s);
#else
#error "phong.frag: no VIEW_<NAME> defined"
#endif
}
#endif

void main() {
  SurfaceFrame s = surfaceFrame();
  MaterialTexels m = materialTexels(s.detail.uv);
#ifdef VIEW_SHADED
  vec4 colour = shadedColour(s, m);
#else
  vec4 colour = debugViewColour(s, m);
#endif
#ifndef GBUFFER_PASS
  fragColour = clamp(colour, 0.0, 1.0);
#endif
#ifndef NO_TRIANGLE_ID
  fragTriangleId = firstTriangleId + uint(gl_PrimitiveID);
#endif
}
