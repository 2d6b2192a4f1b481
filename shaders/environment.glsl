// The environment on a surface: the GLSL twin of softrender/environment-inl.h, function by
// function, the same operations in the same order (docs/environment.md). Included between
// surface_detail.glsl and phong.frag; empty unless the material mixes in an environment.
// environmentRead (environment_map.glsl) reads the cube or the map built from it.
// Permutation defines: HAS_ENVIRONMENT, ENVIRONMENT_REFLECT (environment_specular mirror or
// prefiltered) with ENVIRONMENT_PREFILTERED (prefiltered: textureLod of the glossy map),
// ENVIRONMENT_REFRACTION (refraction_index given), FRESNEL_SCHLICK, ENVIRONMENT_DIFFUSE with
// ENVIRONMENT_IRRADIANCE or ENVIRONMENT_SH9 (environment_diffuse). Each read is texture():
// its LOD from the direction's quad differences, which the C++ twin computes from the quad's
// other pixels (setEnvironmentDifferences).
#ifdef HAS_ENVIRONMENT
uniform float environmentIntensity;  // scales every read
uniform float reflectivity;          // [0, 1]
uniform float refractionEta;         // n1 / n2

// A lighting-space direction in world space (the fragment's frame in tangent space).
vec3 worldFromLighting(vec3 d, vec3 t, vec3 b, vec3 n) {
#ifdef LIGHTING_TANGENT
  return (t * d.x + b * d.y) + n * d.z;
#else
  return d;
#endif
}

// Schlick: F0 + (1 - F0) m^5 with m = 1 - max(cos, 0), m^5 as (m^2)^2 m.
float schlick(float f0, float cosTheta) {
  float m = 1.0 - max(cosTheta, 0.0);
  float m2 = m * m;
  return f0 + (1.0 - f0) * ((m2 * m2) * m);
}

// The environment mixed into `base` (the Phong colour): nl the lighting normal, vVec the
// unnormalised eye direction, both in the lighting space; t, b, n the fragment's frame.
// reflectWorldOut and reflectLodOut: the reflection's direction and the LOD it was read at,
// for the environment views; reflectedOut and shareOut: the reflection and its share w of the
// mix (the deferred G-buffer folds the mix into its targets).
vec3 environmentMix(vec3 nl, vec3 vVec, vec3 t, vec3 b, vec3 n, vec3 base, out vec3 reflectWorldOut,
                    out float reflectLodOut, out vec3 reflectedOut, out float shareOut) {
  vec3 v = safeNormalize(vVec);
  float nDotV = dot3(nl, v);
  vec3 r = (2.0 * nDotV) * nl - v;  // reflect(-v, nl)
  vec3 reflectWorld = worldFromLighting(r, t, b, n);
  reflectWorldOut = reflectWorld;
#ifdef ENVIRONMENT_PREFILTERED
  vec3 reflected = environmentSpecularRead(reflectWorld) * environmentIntensity;
  reflectLodOut = environmentSpecularLod;
#else
  vec3 reflected = environmentRead(reflectWorld) * environmentIntensity;
#ifdef ENVIRONMENT_VIEW
  reflectLodOut = environmentReadLod(reflectWorld);
#else
  reflectLodOut = 0.0;
#endif
#endif
  vec3 transmitted = base;
  float f0 = reflectivity;
#ifdef ENVIRONMENT_REFRACTION
  // refract(-v, nl, eta), written out; k < 0 is total internal reflection.
  float eta = refractionEta;
  float k = 1.0 - (eta * eta) * (1.0 - nDotV * nDotV);
  float root = sqrt(max(k, 0.0));
  vec3 refracted = (0.0 - eta) * v - (root - eta * nDotV) * nl;
  vec3 through = environmentRead(worldFromLighting(refracted, t, b, n)) * environmentIntensity;
  transmitted = k < 0.0 ? reflected : through;
  float ratio = (1.0 - eta) / (1.0 + eta);
  f0 = ratio * ratio;
#endif
  float share = 0.0;
#ifdef ENVIRONMENT_REFLECT
#ifdef FRESNEL_SCHLICK
  share = schlick(f0, nDotV);
#else
  share = reflectivity;
#endif
#endif
  reflectedOut = reflected;
  shareOut = share;
  return transmitted + (reflected - transmitted) * share;
}

#ifdef ENVIRONMENT_DIFFUSE
#ifdef ENVIRONMENT_SH9
uniform vec3 environmentSh9[9];  // scene/environment_light.h's coefficients, band factors folded in
#endif

// The diffuse light at the lighting normal nl (scene/environment_light.h): nl in world space,
// normalised, then the irradiance map read there at level 0, or the nine SH coefficients
// evaluated left to right and clamped at 0; times the intensity.
vec3 environmentDiffuse(vec3 nl, vec3 t, vec3 b, vec3 n) {
  vec3 w = safeNormalize(worldFromLighting(nl, t, b, n));
#ifdef ENVIRONMENT_IRRADIANCE
  return environmentIrradianceRead(w) * environmentIntensity;
#else
  vec3 d = environmentSh9[0] + environmentSh9[1] * w.y;
  d = d + environmentSh9[2] * w.z;
  d = d + environmentSh9[3] * w.x;
  d = d + environmentSh9[4] * (w.x * w.y);
  d = d + environmentSh9[5] * (w.y * w.z);
  d = d + environmentSh9[6] * ((3.0 * (w.z * w.z)) - 1.0);
  d = d + environmentSh9[7] * (w.x * w.z);
  d = d + environmentSh9[8] * ((w.x * w.x) - (w.y * w.y));
  return max(d, vec3(0.0)) * environmentIntensity;
#endif
}
#endif
#endif
