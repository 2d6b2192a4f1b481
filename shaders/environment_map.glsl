// How the environment is read in a direction: the GLSL twin of softrender/layer_sample-inl.h
// (environmentCoord, sampleEnvironment), the same operations in the same order
// (docs/environment.md). The cube is read as is; a sphere or dual-paraboloid map, built from
// it at load, is a 2D array texture read at the direction's coordinate (scene/environment.h):
//   sphere:           m = 2 sqrt(rx^2 + ry^2 + (rz + 1)^2),   (u, v) = (rx, ry) / m + 1/2
//   dual paraboloid:  (u, v) = (rx, ry) / (1 + |rz|) / 2 + 1/2,   layer 1 where rz < 0
// texture() takes a cube's LOD from the direction's differences, a 2D map's from its
// coordinate's (the quad's, computed here per pixel as any varying). Defines: HAS_ENVIRONMENT,
// ENVIRONMENT_SPHERE or ENVIRONMENT_DUAL_PARABOLOID.
#ifdef HAS_ENVIRONMENT
#if defined(ENVIRONMENT_SPHERE) || defined(ENVIRONMENT_DUAL_PARABOLOID)
uniform sampler2DArray environmentLayers;

// Where direction rIn (any length) is read: (u, v, layer).
vec3 environmentCoord(vec3 rIn) {
  vec3 r = safeNormalize(rIn);
#ifdef ENVIRONMENT_SPHERE
  float z1 = r.z + 1.0;
  float m = 2.0 * sqrt((r.x * r.x + r.y * r.y) + z1 * z1);
  return vec3(r.x / m + 0.5, r.y / m + 0.5, 0.0);
#else
  float d = 1.0 + abs(r.z);
  return vec3((r.x / d) * 0.5 + 0.5, (r.y / d) * 0.5 + 0.5, r.z < 0.0 ? 1.0 : 0.0);
#endif
}

vec3 environmentRead(vec3 r) {
  return texture(environmentLayers, environmentCoord(r)).rgb;
}
#ifdef ENVIRONMENT_PREFILTERED
uniform sampler2DArray environmentSpecularLayers;
uniform float environmentSpecularLod;  // from the shininess (scene/environment_specular.h)

// The prefiltered glossy map of the same kind, a Phong lobe per level (environment_specular
// prefiltered).
vec3 environmentSpecularRead(vec3 r) {
  return textureLod(environmentSpecularLayers, environmentCoord(r), environmentSpecularLod).rgb;
}
#endif
#ifdef ENVIRONMENT_IRRADIANCE
uniform sampler2DArray environmentIrradianceLayers;

// The irradiance map of the same kind, one level (environment_diffuse irradiance_map).
vec3 environmentIrradianceRead(vec3 r) {
  return textureLod(environmentIrradianceLayers, environmentCoord(r), 0.0).rgb;
}
#endif
#else
uniform samplerCube environmentMap;

vec3 environmentRead(vec3 r) {
  return texture(environmentMap, r).rgb;
}
#ifdef ENVIRONMENT_PREFILTERED
uniform samplerCube environmentSpecular;
uniform float environmentSpecularLod;  // from the shininess (scene/environment_specular.h)

// The prefiltered glossy cube, a Phong lobe per level (environment_specular prefiltered).
vec3 environmentSpecularRead(vec3 r) {
  return textureLod(environmentSpecular, r, environmentSpecularLod).rgb;
}
#endif
#ifdef ENVIRONMENT_IRRADIANCE
uniform samplerCube environmentIrradiance;

// The irradiance cube, one level (environment_diffuse irradiance_map).
vec3 environmentIrradianceRead(vec3 r) {
  return textureLod(environmentIrradiance, r, 0.0).rgb;
}
#endif
#endif
#endif

#ifdef ENVIRONMENT_VIEW
// The environment's debug views: the GLSL twin of softrender/environment_view-inl.h, the same
// operations in the same order. ENVIRONMENT_VIEW_REFLECT_DIR, ENVIRONMENT_VIEW_FACE or
// ENVIRONMENT_VIEW_LOD says which.
#ifdef HAS_ENVIRONMENT
// The LOD texture() reads direction r at, clamped to the chain: the environment's stand-in, a
// texture of the same size and levels whose level l holds l everywhere, read as the
// environment is, so the sampler's own LOD and blend come back (llvmpipe's textureQueryLOD
// for a cube takes other derivatives than its sampling). The C++ twin clamps the LOD it
// computed for the read (environment_view-inl.h).
#ifdef ENVIRONMENT_VIEW_LOD
#if defined(ENVIRONMENT_SPHERE) || defined(ENVIRONMENT_DUAL_PARABOLOID)
uniform sampler2DArray environmentLodStandIn;
float environmentReadLod(vec3 r) {
  return texture(environmentLodStandIn, environmentCoord(r)).r;
}
#else
uniform samplerCube environmentLodStandIn;
float environmentReadLod(vec3 r) {
  return texture(environmentLodStandIn, r).r;
}
#endif
#else
float environmentReadLod(vec3 r) {
  return 0.0;
}
#endif

// Face f's colour (scene/environment.h's kCubeFaceViewColours).
vec3 faceColour(int f) {
  const float b = 80.0 / 255.0, d = 128.0 / 255.0;
  const vec3 colours[6] = vec3[6](vec3(1.0, b, b), vec3(d, 0.0, 0.0), vec3(b, 1.0, b), vec3(0.0, d, 0.0),
                                  vec3(b, b, 1.0), vec3(0.0, 0.0, d));
  return colours[f];
}

// The face a cube read takes (GL's table with llvmpipe's ties: z wins, then y; -0 in z is -Z),
// or the hemisphere of a sphere or paraboloid map (+Z as face 4, -Z as face 5).
int environmentFace(vec3 r) {
#if defined(ENVIRONMENT_SPHERE) || defined(ENVIRONMENT_DUAL_PARABOLOID)
  return r.z < 0.0 ? 5 : 4;
#else
  vec3 a = abs(r);
  if (a.z >= max(a.x, a.y)) return (floatBitsToUint(r.z) >> 31u) != 0u ? 5 : 4;
  if (a.x > a.y) return r.x < 0.0 ? 1 : 0;
  return r.y < 0.0 ? 3 : 2;
#endif
}

// The view's colour for direction r read at `lod`.
vec4 environmentViewColour(vec3 r, float lod) {
#if defined(ENVIRONMENT_VIEW_REFLECT_DIR)
  return vectorAsColour(safeNormalize(r));
#elif defined(ENVIRONMENT_VIEW_LOD)
  return heatColour(lod * (1.0 / ENVIRONMENT_LOD_VIEW_MAX));
#else
  return vec4(faceColour(environmentFace(r)), 1.0);
#endif
}
#endif

#endif
