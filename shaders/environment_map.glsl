// How the environment is read in a direction: the GLSL twin of softrender/layer_sample-inl.h
// (mapCoordLanes, sampleEnvironmentLanes), the same operations in the same order
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
#ifdef ENVIRONMENT_IRRADIANCE
uniform samplerCube environmentIrradiance;

// The irradiance cube, one level (environment_diffuse irradiance_map).
vec3 environmentIrradianceRead(vec3 r) {
  return textureLod(environmentIrradiance, r, 0.0).rgb;
}
#endif
#endif
#endif
