// TBN debug lines, core profile: world-space segments with a colour per vertex, cut by
// the user clip planes like the surfaces.
layout(location = 0) in vec3 posWorld;
layout(location = 1) in vec3 lineColour;

uniform mat4 clipFromWorld;
uniform vec4 userClipPlanes[MAX_CLIP_PLANES];  // world space, keeps dot(plane, (p, 1)) >= 0
uniform int userClipPlaneCount;                // in [0, MAX_CLIP_PLANES]

out vec3 colour;
out float gl_ClipDistance[MAX_CLIP_PLANES];

void main() {
  gl_Position = clipFromWorld * vec4(posWorld, 1.0);
  colour = lineColour;
  for (int j = 0; j < MAX_CLIP_PLANES; ++j) {
    gl_ClipDistance[j] = j < userClipPlaneCount ? dot(userClipPlanes[j], vec4(posWorld, 1.0)) : 0.0;
  }
}
