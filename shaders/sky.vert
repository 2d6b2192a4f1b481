// The sky box's full-screen triangle at the far plane (window depth 1), drawn after the scene
// with GL_LEQUAL: it covers exactly the pixels no triangle wrote. C++ twin: softrender/sky.cpp
// (which writes the pixels with no triangle id directly).
out float gl_ClipDistance[MAX_CLIP_PLANES];

void main() {
  // (-1, -1), (3, -1), (-1, 3): one triangle over the whole viewport.
  vec2 corner = vec2(float((gl_VertexID & 1) * 4 - 1), float((gl_VertexID >> 1) * 4 - 1));
  gl_Position = vec4(corner, 1.0, 1.0);
  for (int slot = 0; slot < MAX_CLIP_PLANES; ++slot) gl_ClipDistance[slot] = 1.0;  // never clipped
}
