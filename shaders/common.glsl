// Helpers both phong stages use, each with a C++ twin of the same name and body:
// safeNormalize in scene/conventions.h (glm::dot's order, as dot3), phongPow in
// softrender/shade.*, dot3, length3 (lengthOf), vectorAsColour and heatColour in
// softrender/lane_math-inl.h, dimmedColour in softrender/environment_view-inl.h.
// The prelude before this file defines MAX_LIGHTS, MAX_CLIP_PLANES, MIN_LENGTH_SQUARED and
// MIN_ATTENUATION_DENOMINATOR from the C++ constants (glrender/gl_program.cpp).

// How a triangle's varyings are interpolated (settings.interpolation, docs/pipeline.md):
// AFFINE_INTERPOLATION spreads them linearly on the screen (noperspective, the C++ side's 1/w
// taken as 1 at every corner), else perspective-correctly. Both stages qualify alike.
#ifdef AFFINE_INTERPOLATION
#define VARYING noperspective
#else
#define VARYING smooth
#endif

// The dot product summed in the C++ twins' order, (x x' + y y') + z z' (glm::dot, dot3 in
// softrender/lane_math-inl.h). GLSL's dot() leaves the order to the compiler, and llvmpipe's
// sums it another way: directions one ulp apart that part a screen-space march now and then.
float dot3(vec3 a, vec3 b) {
  return (a.x * b.x + a.y * b.y) + a.z * b.z;
}

// length() in the same order (lengthOf in softrender/lane_math-inl.h).
float length3(vec3 v) {
  return sqrt(dot3(v, v));
}

// normalize() that never returns NaN: no usable direction gives (0, 0, 1).
vec3 safeNormalize(vec3 v) {
  float lengthSquared = dot3(v, v);
  if (!(lengthSquared > MIN_LENGTH_SQUARED) || isinf(lengthSquared) || isnan(lengthSquared)) {
    return vec3(0.0, 0.0, 1.0);
  }
  return v / sqrt(lengthSquared);
}

// pow(x, s) for x >= 0 with 0^s = 0 for s > 0 and 0^0 = 1 (GLSL leaves both undefined).
float phongPow(float x, float s) {
  if (!(x > 0.0)) return s > 0.0 ? 0.0 : 1.0;
  return pow(x, s);
}

// (v + 1) / 2 with alpha 1: how the debug views show a vector.
vec4 vectorAsColour(vec3 v) {
  return vec4((v + 1.0) * 0.5, 1.0);
}

// The heat views' ramp (parallax_steps, env_lod) (blue, cyan, green, yellow, red over t in [0, 1]).
float heatChannel(float t, float centre) {
  return min(max(1.5 - abs(4.0 * t - centre), 0.0), 1.0);
}
vec4 heatColour(float tIn) {
  float t = min(max(tIn, 0.0), 1.0);
  return vec4(heatChannel(t, 3.0), heatChannel(t, 2.0), heatChannel(t, 1.0), 1.0);
}

// A surface a debug view has nothing to show on (an environment view where no reflection is
// read, a shadow view without a shadowed light): clamped, then a quarter of its luminance
// (Rec. 709 weights) as grey.
vec4 dimmedColour(vec4 colour) {
  vec4 c = clamp(colour, 0.0, 1.0);
  float grey = 0.25 * ((0.2126 * c.r + 0.7152 * c.g) + 0.0722 * c.b);
  return vec4(grey, grey, grey, 1.0);
}
