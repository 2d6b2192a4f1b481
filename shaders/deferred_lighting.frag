// The deferred pipeline's lighting pass (docs/deferred.md): one fragment per pixel of a
// full-screen triangle (sky.vert's), the G-buffer read with texelFetch, the world position read
// from its target (GBUFFER_POSITION) or rebuilt from the depth, lit by the frame's lights with lighting.glsl's loop. C++ twin:
// deferredLighting and worldFromWindow in softrender/deferred-inl.h, in the same
// order of operations. Included after common.glsl, shadow.glsl and lighting.glsl.

uniform sampler2D gbufferDepth;      // window depth, 1 where nothing was drawn
uniform sampler2D gbufferNormal;     // xyz: the lighting normal, world; w: the Phong exponent
uniform sampler2D gbufferGeometric;  // xyz: the interpolated normal, world
uniform sampler2D gbufferAlbedo;     // xyz: kd albedo (1 - the environment's share)
uniform sampler2D gbufferSpecular;   // xyz: ks specScale, scaled the same
uniform sampler2D gbufferEmission;   // xyz: what no light scales
#ifdef GBUFFER_POSITION
uniform sampler2D gbufferPosition;   // xyz: the world position forward interpolates
#endif
uniform mat4 worldFromClip;          // the inverse of the camera's clipFromWorld
uniform vec2 viewportSize;           // pixels

layout(location = 0) out vec4 fragColour;

// The pixel centre and depth to NDC, through worldFromClip (columns summed from the left),
// divided by w.
vec3 worldFromWindow(vec2 fragCoord, float depth) {
  float x = (2.0 * fragCoord.x) / viewportSize.x - 1.0;
  float y = (2.0 * fragCoord.y) / viewportSize.y - 1.0;
  float z = 2.0 * depth - 1.0;
  mat4 m = worldFromClip;
  float wx = ((m[0][0] * x + m[1][0] * y) + m[2][0] * z) + m[3][0];
  float wy = ((m[0][1] * x + m[1][1] * y) + m[2][1] * z) + m[3][1];
  float wz = ((m[0][2] * x + m[1][2] * y) + m[2][2] * z) + m[3][2];
  float w = ((m[0][3] * x + m[1][3] * y) + m[2][3] * z) + m[3][3];
  return vec3(wx / w, wy / w, wz / w);
}

void main() {
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  float depth = texelFetch(gbufferDepth, pixel, 0).r;
  if (!(depth < 1.0)) discard;  // nothing drawn: the background stays
  vec4 normal = texelFetch(gbufferNormal, pixel, 0);
  vec3 geometric = texelFetch(gbufferGeometric, pixel, 0).xyz;
  vec3 kdAlbedo = texelFetch(gbufferAlbedo, pixel, 0).xyz;
  vec3 ksSpec = texelFetch(gbufferSpecular, pixel, 0).xyz;
  vec3 emission = texelFetch(gbufferEmission, pixel, 0).xyz;
#ifdef GBUFFER_POSITION
  vec3 posWorld = texelFetch(gbufferPosition, pixel, 0).xyz;
#else
  vec3 posWorld = worldFromWindow(gl_FragCoord.xy, depth);
#endif
  LightSum lit = lightSum(posWorld, geometric, vec3(0.0), vec3(0.0), normal.xyz, kdAlbedo, ksSpec, normal.w);
  fragColour = clamp(vec4(emission + lit.sum, 1.0), 0.0, 1.0);
}
