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
// NO_TRIANGLE_ID: no triangle-id output, as an OpenGL user's shader has none (the lean
// frame, glrender/gl_renderer.h; llvmpipe pays for gl_PrimitiveID even when no draw buffer
// takes the output).

in vec3 posWorld;
in vec3 nWorld;
in vec3 tWorld;
in vec3 bWorld;
in vec2 uv;
#ifdef LIGHTING_TANGENT
in vec3 lightDirTangent[MAX_LIGHTS];
in vec3 eyeDirTangent;
#endif

struct LightUniform {
  vec3 posWorld;
  vec3 diffuse;      // Id
  vec3 specular;     // Is
  vec3 attenuation;  // A_C, A_L, A_Q
};

uniform vec3 ka;  // material reflectances
uniform vec3 kd;
uniform vec3 ks;
uniform float shininess;  // Phong exponent, >= 0
uniform vec3 ambient;     // Ia
uniform LightUniform lights[MAX_LIGHTS];
uniform int lightCount;   // in [0, MAX_LIGHTS]
uniform vec3 eyePosWorld;
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

layout(location = 0) out vec4 fragColour;
#ifndef NO_TRIANGLE_ID
layout(location = 1) out uint fragTriangleId;
#endif

void main() {
  vec3 n = safeNormalize(nWorld);
  vec3 t = safeNormalize(tWorld);
  vec3 b = safeNormalize(bWorld);

  // Each map's own uv (the map's uv transform, an MTL's -s and -o).
  vec2 uvDiffuse = uv;
#ifdef DIFFUSE_UV_TRANSFORM
  uvDiffuse = uv * diffuseUvScale + diffuseUvOffset;
#endif
  vec2 uvNormal = uv;
#ifdef NORMAL_UV_TRANSFORM
  uvNormal = uv * normalUvScale + normalUvOffset;
#endif
  vec2 uvSpecular = uv;
#ifdef SPECULAR_UV_TRANSFORM
  uvSpecular = uv * specularUvScale + specularUvOffset;
#endif

  vec3 albedo = vec3(1.0);
#ifdef HAS_DIFFUSE_MAP
  albedo = texture(diffuseMap, uvDiffuse).rgb;
#endif
  vec3 specScale = vec3(1.0);
#ifdef HAS_SPECULAR_MAP
  specScale = texture(specularMap, uvSpecular).rgb;
#endif
  vec3 mappedTangent = vec3(0.0, 0.0, 1.0);
#ifdef HAS_NORMAL_MAP
  vec4 normalTexel = texture(normalMap, uvNormal);
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

  vec3 nl = n;
#if defined(LIGHTING_TANGENT)
  nl = mappedTangent;
#elif defined(HAS_NORMAL_MAP)
  nl = safeNormalize(t * mappedTangent.x + b * mappedTangent.y + n * mappedTangent.z);
#endif

  vec4 colour = vec4(0.0);
#if defined(VIEW_SHADED)
  vec3 sum = vec3(0.0);
  for (int i = 0; i < lightCount; ++i) {
#ifdef LIGHTING_TANGENT
    vec3 lVec = lightDirTangent[i];
    vec3 vVec = eyeDirTangent;
#else
    vec3 lVec = lights[i].posWorld - posWorld;
    vec3 vVec = eyePosWorld - posWorld;
#endif
    float d = length(lights[i].posWorld - posWorld);  // always from posWorld, both spaces
    vec3 l = safeNormalize(lVec);
    vec3 v = safeNormalize(vVec);
    float nDotL = dot(nl, l);
    vec3 r = 2.0 * nDotL * nl - l;
    float rDotV = max(dot(r, v), 0.0);
    float attenuation = 1.0 / max(lights[i].attenuation.x + lights[i].attenuation.y * d +
                                      lights[i].attenuation.z * d * d,
                                  MIN_ATTENUATION_DENOMINATOR);
    vec3 diffuse = kd * albedo * max(nDotL, 0.0) * lights[i].diffuse;
    vec3 specular = nDotL > 0.0 ? ks * specScale * phongPow(rDotV, shininess) * lights[i].specular : vec3(0.0);
    sum += (diffuse + specular) * attenuation;
  }
  vec3 ambientTerm = ka * albedo * ambient;
  colour = vec4(ambientTerm + sum, 1.0);
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
    vec3 w = (kLight ? lights[0].posWorld : eyePosWorld) - posWorld;
    dirTangent = safeNormalize(vec3(dot(t, w), dot(b, w), dot(n, w)));
#endif
  }
  colour = vectorAsColour(dirTangent);
#else
#error "phong.frag: no VIEW_<NAME> defined"
#endif

  fragColour = clamp(colour, 0.0, 1.0);
#ifndef NO_TRIANGLE_ID
  fragTriangleId = firstTriangleId + uint(gl_PrimitiveID);
#endif
}
