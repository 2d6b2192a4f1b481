// TBN debug lines, core profile: world-space segments with a colour per vertex, cut by
// the user clip planes like the surfaces.
layout(location = 0) in vec3 posWorld;
layout(location = 1) in vec3 lineColour;

uniform mat4 clipFromWorld;
uniform vec4 userClipPlanes[MAX_CLIP_PLANES];  // world space, keeps dot(plane, (p, 1)) >= 0
uniform int userClipPlaneCount;                // in [0, MAX_CLIP_PLANES]
// When one of near/far is off, GL's depth clamp drops both and the other one returns as
// clip distance 0 (glrender/gl_clip_state.h); user plane j then is clip distance j + 1.
uniform vec4 frustumClipPlane;  // clip space: keeps dot(plane, gl_Position) >= 0
uniform int firstUserClipSlot;  // 0, or 1 when slot 0 holds frustumClipPlane

out vec3 colour;
out float gl_ClipDistance[MAX_CLIP_PLANES];

void main() {
  gl_Position = clipFromWorld * vec4(posWorld, 1.0);
  colour = lineColour;
  for (int slot = 0; slot < MAX_CLIP_PLANES; ++slot) {
    int j = slot - firstUserClipSlot;
    float clipDistance = 0.0;
    if (j < 0) {
      clipDistance = dot(frustumClipPlane, gl_Position);
    } else if (j < userClipPlaneCount) {
      clipDistance = dot(userClipPlanes[j], vec4(posWorld, 1.0));
    }
    gl_ClipDistance[slot] = clipDistance;
  }
}
