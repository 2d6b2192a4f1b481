// The sky box: the environment in the pixel's view direction, its LOD from the direction's
// quad differences (texture(), environment_map.glsl's environmentRead). C++ twin:
// skyDirection and skyColour in softrender/sky-inl.h, the same operations in order.
uniform float environmentIntensity;
uniform vec3 skyForward;   // the camera's -Z axis in world space
uniform vec3 skyRight;     // its +X axis times tan(fov / 2) * aspect
uniform vec3 skyUp;        // its +Y axis times tan(fov / 2)
uniform vec2 ndcPerPixel;  // 2 / width, 2 / height

layout(location = 0) out vec4 fragColour;

void main() {
  vec2 ndc = gl_FragCoord.xy * ndcPerPixel - 1.0;  // gl_FragCoord.xy is the pixel centre
  vec3 dir = (skyForward + skyRight * ndc.x) + skyUp * ndc.y;
#ifdef ENVIRONMENT_VIEW
  // An environment view: what the sky's direction reads (environment_map.glsl).
  fragColour = environmentViewColour(dir, environmentReadLod(dir));
#else
  vec3 c = environmentRead(dir) * environmentIntensity;
  fragColour = vec4(clamp(c, 0.0, 1.0), 1.0);
#endif
}
