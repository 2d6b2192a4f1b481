// Fragment stage of the shading contract (docs/shading.md). Its C++ twin is
// shadeFragment<Features>() in softrender/shade.h: same inputs, names and order of
// operations; main() here is that function's body.
// Permutation defines: HAS_DIFFUSE_MAP, HAS_NORMAL_MAP, HAS_SPECULAR_MAP, LIGHTING_TANGENT
// (else world lighting space), and exactly one VIEW_<NAME> (VIEW_SHADED ... VIEW_EYE_TANGENT).
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
// GBUFFER_PASS (with VIEW_SHADED): the deferred pipeline's G-buffer pass, the surface written
// to five targets instead of the colour (docs/deferred.md); GBUFFER_POSITION: and the world
// position to a sixth. The frame's lights and the light
// loop are shaders/lighting.glsl's, included before this file.

in vec3 posWorld;
in vec3 nWorld;
in vec3 tWorld;
in vec3 bWorld;
in vec2 uv;
#ifdef LIGHTING_TANGENT
in vec3 lightDirTangent[MAX_LIGHTS];
in vec3 eyeDirTangent;
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

void main() {
  vec3 n = safeNormalize(nWorld);
  vec3 t = safeNormalize(tWorld);
  vec3 b = safeNormalize(bWorld);

  // Surface detail from the height map: the parallax methods move the uv every map is read at;
  // bump_blinn makes the normal; the rest read the height at uv.
  vec2 uvMaps = uv;
  float detailHeight = 1.0;
  float detailSteps = 0.0;
#ifdef HAS_HEIGHT_MAP
  uvDx = dFdx(uv);
  uvDy = dFdy(uv);
  SurfaceDetail detail = SurfaceDetail(uv, 1.0, 0.0, vec3(0.0, 0.0, 1.0));
#ifdef PARALLAX_UV
#ifdef LIGHTING_TANGENT
  vec3 eyeVec = eyeDirTangent;
#else
  vec3 eyeVec = eyePosWorld - posWorld;
#endif
  vec3 vT = tangentFromLighting(eyeVec, t, b, n);
  detail = parallax(uv, vT);
#else
#ifdef SURFACE_BUMP_BLINN
  detail.bumpTangent = bumpBlinn(uv);
#endif
  detail.height = heightAt(uv);
#endif
  uvMaps = detail.uv;
  detailHeight = detail.height;
  detailSteps = detail.steps;
#endif

  // Each map's own uv (the map's uv transform, an MTL's -s and -o).
  vec2 uvDiffuse = uvMaps;
  vec2 diffuseScale = vec2(1.0);
#ifdef DIFFUSE_UV_TRANSFORM
  uvDiffuse = uvMaps * diffuseUvScale + diffuseUvOffset;
  diffuseScale = diffuseUvScale;
#endif
  vec2 uvNormal = uvMaps;
  vec2 normalScale = vec2(1.0);
#ifdef NORMAL_UV_TRANSFORM
  uvNormal = uvMaps * normalUvScale + normalUvOffset;
  normalScale = normalUvScale;
#endif
  vec2 uvSpecular = uvMaps;
  vec2 specularScale = vec2(1.0);
#ifdef SPECULAR_UV_TRANSFORM
  uvSpecular = uvMaps * specularUvScale + specularUvOffset;
  specularScale = specularUvScale;
#endif

  vec3 albedo = vec3(1.0);
#ifdef HAS_DIFFUSE_MAP
#ifdef PARALLAX_UV
  albedo = textureGrad(diffuseMap, uvDiffuse, uvDx * diffuseScale, uvDy * diffuseScale).rgb;
#else
  albedo = texture(diffuseMap, uvDiffuse).rgb;
#endif
#endif
  vec3 specScale = vec3(1.0);
#ifdef HAS_SPECULAR_MAP
#ifdef PARALLAX_UV
  specScale = textureGrad(specularMap, uvSpecular, uvDx * specularScale, uvDy * specularScale).rgb;
#else
  specScale = texture(specularMap, uvSpecular).rgb;
#endif
#endif
  vec3 mappedTangent = vec3(0.0, 0.0, 1.0);
#ifdef HAS_NORMAL_MAP
#ifdef PARALLAX_UV
  vec4 normalTexel = textureGrad(normalMap, uvNormal, uvDx * normalScale, uvDy * normalScale);
#else
  vec4 normalTexel = texture(normalMap, uvNormal);
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
  mappedTangent = safeNormalize(tangentNormal);
#endif
#ifdef SURFACE_BUMP_BLINN
  mappedTangent = detail.bumpTangent;
#endif

  vec3 nl = n;
#if defined(LIGHTING_TANGENT)
  nl = mappedTangent;
#elif defined(HAS_NORMAL_MAP) || defined(SURFACE_BUMP_BLINN)
  nl = safeNormalize(t * mappedTangent.x + b * mappedTangent.y + n * mappedTangent.z);
#endif

  vec4 colour = vec4(0.0);
#if defined(VIEW_SHADED)
  vec3 kdAlbedo = kd * albedo;   // diffuse's first product
  vec3 ksSpec = ks * specScale;  // specular's first
  // What no light scales first: the ambient term, then the environment's diffuse light, added
  // as the lights' diffuse terms are (environment.glsl). The G-buffer pass stores this sum.
  vec3 ambientTerm = ka * albedo * ambient;
  vec3 unlit = ambientTerm;
#ifdef ENVIRONMENT_DIFFUSE
  unlit = unlit + kdAlbedo * environmentDiffuse(nl, t, b, n);
#endif
#if !defined(GBUFFER_PASS) || defined(GBUFFER_LIT_HERE)
  LightSum lit = lightSum(posWorld, n, t, b, nl, kdAlbedo, ksSpec, shininess
#ifdef LIGHTING_TANGENT
                          , lightDirTangent, eyeDirTangent
#endif
#ifdef HAS_HEIGHT_MAP
                          , detail, uv
#endif
  );
  colour = vec4(unlit + lit.sum, 1.0);
#if defined(ENVIRONMENT_REFLECT) || defined(ENVIRONMENT_REFRACTION)
  // The environment, mixed into the Phong colour (environment.glsl).
#ifdef LIGHTING_TANGENT
  vec3 eyeVecEnvironment = eyeDirTangent;
#else
  vec3 eyeVecEnvironment = eyePosWorld - posWorld;
#endif
  vec3 reflectWorld;
  float reflectLod;
  vec3 reflected;
  float share;
  colour = vec4(environmentMix(nl, eyeVecEnvironment, t, b, n, colour.rgb, reflectWorld, reflectLod, reflected, share),
                1.0);
#ifdef ENVIRONMENT_VIEW
  colour = environmentViewColour(reflectWorld, reflectLod);
#endif
#elif defined(ENVIRONMENT_VIEW)
  // An environment view on a surface that reads no reflection: dimmed to grey.
  colour = dimmedColour(colour);
#endif
#if defined(SHADOW_VIEW_SHADOW) || defined(SHADOW_VIEW_LIGHT_DEPTH)
  // The shadow views (shadow.glsl): the first shadowed light's test, or dimmed without one.
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
#endif  // the forward lighting
#ifdef GBUFFER_PASS
  // The G-buffer (C++ twin: gbufferFragmentLanes, softrender/deferred-inl.h). The lighting
  // normal in world space: a tangent-space material's mapped normal through its TBN.
  vec3 nlWorld = nl;
#ifdef LIGHTING_TANGENT
#if defined(HAS_NORMAL_MAP) || defined(SURFACE_BUMP_BLINN)
  nlWorld = safeNormalize(t * mappedTangent.x + b * mappedTangent.y + n * mappedTangent.z);
#else
  nlWorld = n;
#endif
#endif
  gbufferNormal = vec4(nlWorld, shininess);
  gbufferGeometric = vec4(n, 1.0);
#ifdef GBUFFER_POSITION
  gbufferPosition = vec4(posWorld, 1.0);
#endif
#ifdef GBUFFER_LIT_HERE
  gbufferAlbedo = vec4(0.0, 0.0, 0.0, 1.0);
  gbufferSpecular = vec4(0.0, 0.0, 0.0, ssrReflect);
  gbufferEmission = vec4(clamp(colour.rgb, 0.0, 1.0), 1.0);
#else
  // The environment's mix, colour = phong + (C - phong) w, folded into the targets: albedo and
  // specular scaled by (1 - w), the emission (1 - w) unlit + w C. Refraction: w = 1.
  float mixShare = 0.0;
  vec3 mixTarget = vec3(0.0);
#if defined(ENVIRONMENT_REFLECT) || defined(ENVIRONMENT_REFRACTION)
#ifdef LIGHTING_TANGENT
  vec3 eyeVecSurface = eyeDirTangent;
#else
  vec3 eyeVecSurface = eyePosWorld - posWorld;
#endif
  vec3 reflectWorldSurface;
  float reflectLodSurface;
  vec3 reflectedSurface;
  float shareSurface;
  vec3 mixedSurface = environmentMix(nl, eyeVecSurface, t, b, n, vec3(0.0), reflectWorldSurface, reflectLodSurface,
                                     reflectedSurface, shareSurface);
#ifdef ENVIRONMENT_REFRACTION
  mixShare = 1.0;
  mixTarget = mixedSurface;
#else
  mixShare = shareSurface;
  mixTarget = reflectedSurface;
#endif
#endif
  float keep = 1.0 - mixShare;
  gbufferAlbedo = vec4(kdAlbedo * keep, 1.0);
  gbufferSpecular = vec4(ksSpec * keep, ssrReflect);
  gbufferEmission = vec4(unlit * keep + mixTarget * mixShare, 1.0);
#endif
#endif
#elif defined(VIEW_ALBEDO)
  colour = vec4(albedo * kd, 1.0);
#elif defined(VIEW_NORMAL)
  colour = vectorAsColour(n);
#elif defined(VIEW_TANGENT)
  colour = vectorAsColour(t);
#elif defined(VIEW_BITANGENT)
  colour = vectorAsColour(b);
#elif defined(VIEW_MAPPED_NORMAL)
  colour = vectorAsColour(nl);
#elif defined(VIEW_UV)
  colour = vec4(uv.x - floor(uv.x), uv.y - floor(uv.y), 0.0, 1.0);
#elif defined(VIEW_DEPTH)
  float depth = clamp(gl_FragCoord.z, 0.0, 1.0);  // window depth, clamped to the depth range
  colour = vec4(depth, depth, depth, 1.0);
#elif defined(VIEW_LIGHT_TANGENT) || defined(VIEW_EYE_TANGENT)
#ifdef VIEW_LIGHT_TANGENT
  const bool kLight = true;
#else
  const bool kLight = false;
#endif
  vec3 dirTangent = vec3(0.0);  // no light: (0, 0, 0), shown as grey 0.5
  if (!kLight || lightCount > 0) {
#ifdef LIGHTING_TANGENT
    dirTangent = safeNormalize(kLight ? lightDirTangent[0] : eyeDirTangent);
#else
    vec3 w = kLight ? toLightWorld(lights[0], posWorld) : eyePosWorld - posWorld;
    dirTangent = safeNormalize(vec3(dot3(t, w), dot3(b, w), dot3(n, w)));
#endif
  }
  colour = vectorAsColour(dirTangent);
#elif defined(VIEW_HEIGHT)
  colour = vec4(detailHeight, detailHeight, detailHeight, 1.0);
#elif defined(VIEW_PARALLAX_OFFSET)
  colour = vec4(0.5 + (uvMaps.x - uv.x) * PARALLAX_OFFSET_VIEW_GAIN, 0.5 + (uvMaps.y - uv.y) * PARALLAX_OFFSET_VIEW_GAIN,
                0.5, 1.0);
#elif defined(VIEW_PARALLAX_STEPS)
#ifdef HAS_HEIGHT_MAP
  colour = heatColour(detailSteps / float(layerCap + refinementSteps));
#else
  colour = heatColour(0.0);
#endif
#elif defined(VIEW_SELF_SHADOW)
  float shadow = 1.0;
#ifdef SELF_SHADOW
  if (lightCount > 0) {
#ifdef LIGHTING_TANGENT
    vec3 lVec0 = lightDirTangent[0];
#else
    vec3 lVec0 = toLightWorld(lights[0], posWorld);
#endif
    shadow = selfShadow(detail, tangentFromLighting(lVec0, t, b, n));
  }
#endif
  colour = vec4(shadow, shadow, shadow, 1.0);
#else
#error "phong.frag: no VIEW_<NAME> defined"
#endif

#ifndef GBUFFER_PASS
  fragColour = clamp(colour, 0.0, 1.0);
#endif
#ifndef NO_TRIANGLE_ID
  fragTriangleId = firstTriangleId + uint(gl_PrimitiveID);
#endif
}
