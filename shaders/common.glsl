// Helpers both phong stages use; C++ twins in scene/conventions.h and softrender/shade.cpp.
// The prelude before this file defines MAX_LIGHTS, MAX_CLIP_PLANES, MIN_LENGTH_SQUARED and
// MIN_ATTENUATION_DENOMINATOR from the C++ constants (glrender/gl_program.cpp).

// normalize() that never returns NaN: no usable direction gives (0, 0, 1).
vec3 safeNormalize(vec3 v) {
  float lengthSquared = dot(v, v);
  if (!(lengthSquared > MIN_LENGTH_SQUARED) || isinf(lengthSquared) || isnan(lengthSquared)) {
    return vec3(0.0, 0.0, 1.0);
  }
  return v / sqrt(lengthSquared);
}

// A direction in [-1, 1]^3 shown as a colour in [0, 1]^3.
vec3 encodeDirection(vec3 v) {
  return (v + 1.0) / 2.0;
}
