// Fragment stage of the shading contract (docs/shading.md); C++ twin: softrender/shade.cpp.
// Permutation defines: HAS_DIFFUSE_MAP, HAS_NORMAL_MAP, HAS_SPECULAR_MAP, LIGHTING_TANGENT,
// and exactly one VIEW_<NAME> (VIEW_SHADED, VIEW_ALBEDO, ..., VIEW_EYE_TANGENT).

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
uniform vec3 ambient;     // Ia
uniform vec3 eyePosWorld;
uniform vec3 lightPosWorld[MAX_LIGHTS];
uniform vec3 lightDiffuse[MAX_LIGHTS];      // Id
uniform vec3 lightSpecular[MAX_LIGHTS];     // Is
uniform vec3 lightAttenuation[MAX_LIGHTS];  // (A_C, A_L, A_Q)
uniform int lightCount;                     // in [0, MAX_LIGHTS]
uniform uint firstTriangleId;
uniform sampler2D diffuseMap;
uniform sampler2D normalMap;
uniform sampler2D specularMap;

layout(location = 0) out vec4 fragColour;
layout(location = 1) out uint fragTriangleId;

// If = 1 / (A_C + A_L d + A_Q d^2), the denominator kept away from 0.
float attenuationFactor(vec3 attenuation, float d) {
  return 1.0 / max(attenuation.x + attenuation.y * d + attenuation.z * d * d, MIN_ATTENUATION_DENOMINATOR);
}

// pow(x, s) for x >= 0 with pow(0, 0) = 1 and pow(0, s > 0) = 0 (GLSL leaves both undefined).
float specularPower(float x, float s) {
  if (s == 0.0) return 1.0;
  if (x == 0.0) return 0.0;
  return pow(x, s);
}

// One light's diffuse + specular, attenuated. Nl, Lvec, Vvec in the lighting space;
// d is the world-space distance to the light.
vec3 shadeLight(vec3 Nl, vec3 Lvec, vec3 Vvec, float d, vec3 albedo, vec3 specScale, int i) {
  vec3 L = safeNormalize(Lvec);
  vec3 V = safeNormalize(Vvec);
  float NdotL = dot(Nl, L);
  vec3 R = 2.0 * NdotL * Nl - L;
  float RdotV = max(dot(R, V), 0.0);
  float If = attenuationFactor(lightAttenuation[i], d);
  vec3 diffuse = kd * albedo * max(NdotL, 0.0) * lightDiffuse[i];
  vec3 specular = NdotL > 0.0 ? ks * specScale * specularPower(RdotV, shininess) * lightSpecular[i] : vec3(0.0);
  return (diffuse + specular) * If;
}

// The light-0 and eye directions of the light_tangent / eye_tangent views, in tangent space.
vec3 lightTangentView(vec3 T, vec3 B, vec3 N) {
  if (lightCount == 0) return vec3(0.0);
#ifdef LIGHTING_TANGENT
  return safeNormalize(lightDirTangent[0]);
#else
  vec3 Lw = lightPosWorld[0] - posWorld;
  return safeNormalize(vec3(dot(T, Lw), dot(B, Lw), dot(N, Lw)));
#endif
}

vec3 eyeTangentView(vec3 T, vec3 B, vec3 N) {
#ifdef LIGHTING_TANGENT
  return safeNormalize(eyeDirTangent);
#else
  vec3 Ew = eyePosWorld - posWorld;
  return safeNormalize(vec3(dot(T, Ew), dot(B, Ew), dot(N, Ew)));
#endif
}

void main() {
  vec3 N = safeNormalize(nWorld);
  vec3 T = safeNormalize(tWorld);
  vec3 B = safeNormalize(bWorld);

  vec3 albedo = vec3(1.0);
#ifdef HAS_DIFFUSE_MAP
  albedo = texture(diffuseMap, uv).rgb;
#endif
  vec3 specScale = vec3(1.0);
#ifdef HAS_SPECULAR_MAP
  specScale = texture(specularMap, uv).rgb;
#endif
  vec3 mappedTangent = vec3(0.0, 0.0, 1.0);
#ifdef HAS_NORMAL_MAP
  mappedTangent = safeNormalize(2.0 * texture(normalMap, uv).rgb - 1.0);
#endif

#ifdef LIGHTING_TANGENT
  vec3 Nl = mappedTangent;
#elif defined(HAS_NORMAL_MAP)
  vec3 m = mappedTangent;
  vec3 Nl = safeNormalize(T * m.x + B * m.y + N * m.z);
#else
  vec3 Nl = N;
#endif

  vec3 colour = vec3(0.0);
#if defined(VIEW_SHADED)
  vec3 lightSum = vec3(0.0);
  for (int i = 0; i < lightCount; ++i) {
    float d = length(lightPosWorld[i] - posWorld);  // always from posWorld, both spaces
#ifdef LIGHTING_TANGENT
    vec3 Lvec = lightDirTangent[i];
    vec3 Vvec = eyeDirTangent;
#else
    vec3 Lvec = lightPosWorld[i] - posWorld;
    vec3 Vvec = eyePosWorld - posWorld;
#endif
    lightSum += shadeLight(Nl, Lvec, Vvec, d, albedo, specScale, i);
  }
  colour = ka * albedo * ambient + lightSum;
#elif defined(VIEW_ALBEDO)
  colour = albedo * kd;
#elif defined(VIEW_NORMAL)
  colour = encodeDirection(N);
#elif defined(VIEW_TANGENT)
  colour = encodeDirection(T);
#elif defined(VIEW_BITANGENT)
  colour = encodeDirection(B);
#elif defined(VIEW_MAPPED_NORMAL)
  colour = encodeDirection(Nl);
#elif defined(VIEW_UV)
  colour = vec3(fract(uv.x), fract(uv.y), 0.0);
#elif defined(VIEW_DEPTH)
  colour = vec3(gl_FragCoord.z);
#elif defined(VIEW_LIGHT_TANGENT)
  colour = encodeDirection(lightTangentView(T, B, N));
#elif defined(VIEW_EYE_TANGENT)
  colour = encodeDirection(eyeTangentView(T, B, N));
#else
#error "phong.frag: no VIEW_<NAME> defined"
#endif

  fragColour = vec4(clamp(colour, 0.0, 1.0), 1.0);
  fragTriangleId = firstTriangleId + uint(gl_PrimitiveID);
}
