// The frame's lights (docs/shading.md) and the light loop that lights one surface point:
// shared by the forward shading (phong.frag) and the deferred pipeline's lighting pass
// (deferred_lighting.frag). C++ twin: lightSum in softrender/shade-inl.h, the same order
// of operations. Included after shadow.glsl (and surface_detail.glsl for a height field).

struct LightUniform {
  vec4 vectorWorld;  // (position, 1) for a point light, (towards the light, 0) for a directional one
  vec3 diffuse;      // Id
  vec3 specular;     // Is
  vec3 attenuation;  // A_C, A_L, A_Q
  vec4 spotAxis;     // a spot light: (the cone's axis, 1); any other light: w 0
  vec2 spotCone;     // cos outer, cos inner - cos outer
};

uniform LightUniform lights[MAX_LIGHTS];
uniform int lightCount;   // in [0, MAX_LIGHTS]
uniform vec3 eyePosWorld;

// The vector from p to a light: xyz - w p (w 1 for a point light, 0 for a directional one).
vec3 toLightWorld(LightUniform light, vec3 p) {
  return light.vectorWorld.xyz - light.vectorWorld.w * p;
}

// A spot light's cone at a point: smoothstep(cos outer, cos inner, cos angle), written out (the
// builtin's precision is the driver's), the angle between the cone's axis and the way from the
// light to the point. C++ twin: spotFactor (softrender/shade-inl.h).
float spotFactor(LightUniform light, vec3 toLight) {
  float cosAngle = 0.0 - dot3(light.spotAxis.xyz, safeNormalize(toLight));
  float x = clamp((cosAngle - light.spotCone.x) / light.spotCone.y, 0.0, 1.0);
  return (x * x) * (3.0 - 2.0 * x);
}

struct LightSum {
  vec3 sum;  // sum_i (diffuse + specular) If shadow
#ifdef HAS_SHADOWS
  ShadowTest firstShadowTest;  // the first shadowed light's test, for the shadow views
  float firstShadowCosine;
  bool haveShadowTest;
#endif
#ifdef PHONG_TERM_VIEW
  vec3 diffuseSum;   // sum_i diffuse If shadow, the diffuse view's value
  vec3 specularSum;  // sum_i specular If shadow, the specular view's
#endif
};

// If = 1 / max(A_C + A_L d + A_Q d^2, MIN_ATTENUATION_DENOMINATOR), evaluated left to right as
// (A_C + A_L d) + (A_Q d) d. C++: attenuation.
float attenuation(vec3 a, float d) {
  return 1.0 / max(a.x + a.y * d + a.z * d * d, MIN_ATTENUATION_DENOMINATOR);
}

#ifdef HAS_SHADOWS
// Light i's shadow map at this point (shadow.glsl), at the geometric normal's angle, in world
// space; tested only where it can matter: a point the light lights (diffuse or specular) and
// the shadow views, since elsewhere both terms are 0 and so is their product with it. Keeps the
// first test (the probe: the probed light's) for the shadow views; true when it tested.
// C++: the shadow step of lightSum.
bool shadowMapStep(int i, vec3 posWorld, vec3 n, bool lit, inout LightSum result, inout float shadow) {
#if defined(SHADOW_VIEW_SHADOW) || defined(SHADOW_VIEW_LIGHT_DEPTH) || defined(SHADOW_PROBE)
  const bool shadowTestAlways = true;
#else
  const bool shadowTestAlways = false;
#endif
  int slot = shadowSlotOfLight[i];
  if (!(slot >= 0 && (shadowTestAlways || lit))) return false;
  ShadowTest mapTest = shadowTest(slot, posWorld, n, safeNormalize(toLightWorld(lights[i], posWorld)));
  shadow = shadow * mapTest.visibility;
#ifdef SHADOW_PROBE
  bool keep = i == shadowProbeLight;  // the probed light's test, not the first's
#else
  bool keep = !result.haveShadowTest;
#endif
  if (keep) {
    result.firstShadowTest = mapTest;
    result.firstShadowCosine = dot3(n, safeNormalize(toLightWorld(lights[i], posWorld)));
    result.haveShadowTest = true;
  }
  return true;
}
#endif

// n: the interpolated normal (the shadow maps' slope, world space); nl: the normal lighting
// uses, in the lighting space; kdAlbedo, ksSpec: the diffuse and specular terms' first
// products. Tangent-space lighting reads the vertex stage's light and eye vectors; a height
// field's emboss and self-shadowing read the detail and the fragment's uv.
LightSum lightSum(vec3 posWorld, vec3 n, vec3 t, vec3 b, vec3 nl, vec3 kdAlbedo, vec3 ksSpec, float exponent
#ifdef LIGHTING_TANGENT
                  , vec3 lightDirs[MAX_LIGHTS], vec3 eyeDir
#endif
#ifdef HAS_HEIGHT_MAP
                  , SurfaceDetail detail, vec2 fragmentUv
#endif
) {
  LightSum result;
  result.sum = vec3(0.0);
#ifdef HAS_SHADOWS
  result.firstShadowTest = ShadowTest(1.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, vec2(0.0), 0.0);
  result.firstShadowCosine = 0.0;
  result.haveShadowTest = false;
#endif
#ifdef PHONG_TERM_VIEW
  result.diffuseSum = vec3(0.0);
  result.specularSum = vec3(0.0);
#endif
  if (lightCount == 0) return result;
  // The way to the eye, the same for every light.
#ifdef LIGHTING_TANGENT
  vec3 vVec = eyeDir;
#else
  vec3 vVec = eyePosWorld - posWorld;
#endif
  vec3 v = safeNormalize(vVec);
  for (int i = 0; i < lightCount; ++i) {
#ifdef LIGHTING_TANGENT
    vec3 lVec = lightDirs[i];
#else
    vec3 lVec = toLightWorld(lights[i], posWorld);
#endif
    float d = length3(toLightWorld(lights[i], posWorld));  // always from posWorld, both spaces
    vec3 l = safeNormalize(lVec);
    float nDotL = dot3(nl, l);
    vec3 r = 2.0 * nDotL * nl - l;
    float rDotV = max(dot3(r, v), 0.0);
    float falloff = attenuation(lights[i].attenuation, d);
    if (lights[i].spotAxis.w > 0.0) falloff = falloff * spotFactor(lights[i], toLightWorld(lights[i], posWorld));
    float diffuseFactor = max(nDotL, 0.0);
    float shadow = 1.0;
#if defined(SURFACE_BUMP_EMBOSS) || defined(SELF_SHADOW)
    vec3 lT = tangentFromLighting(lVec, t, b, n);  // the light in tangent space
#endif
#ifdef SURFACE_BUMP_EMBOSS
    // Emboss: N'.L ~ N.L + s (h(uv) - h(uv + lT.xy d)) / d, d = one texel; diffuse only.
    float texel = heightTexel.x;
    float hShifted = heightAt(vec2(fragmentUv.x + lT.x * texel, fragmentUv.y + lT.y * texel));
    diffuseFactor = max(nDotL + heightScale * (detail.height - hShifted) / texel, 0.0);
#endif
#ifdef SELF_SHADOW
    shadow = selfShadow(detail, lT);
#endif
    vec3 diffuse = kdAlbedo * diffuseFactor * lights[i].diffuse;
#ifdef SURFACE_BUMP_EMBOSS
    vec3 specular = vec3(0.0);
#else
    vec3 specular = nDotL > 0.0 ? ksSpec * phongPow(rDotV, exponent) * lights[i].specular : vec3(0.0);
#endif
    bool mapOn = false;
#ifdef HAS_SHADOWS
    mapOn = shadowMapStep(i, posWorld, n, diffuseFactor > 0.0 || nDotL > 0.0, result, shadow);
#endif
#ifdef SELF_SHADOW
    result.sum += ((diffuse + specular) * falloff) * shadow;
#else
    if (mapOn) {
      result.sum += ((diffuse + specular) * falloff) * shadow;
    } else {
      result.sum += (diffuse + specular) * falloff;
    }
#endif
#ifdef PHONG_TERM_VIEW
    result.diffuseSum += (diffuse * falloff) * shadow;
    result.specularSum += (specular * falloff) * shadow;
#endif
  }
  return result;
}
