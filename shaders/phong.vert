// Vertex stage of the shading contract (docs/shading.md); C++ twin: softrender/vertex.cpp.
// Permutation defines: LIGHTING_TANGENT (else world lighting space).

layout(location = 0) in vec3 posModel;
layout(location = 1) in vec3 nModel;
layout(location = 2) in vec4 tangentModel;  // w: handedness sign
layout(location = 3) in vec2 uvModel;

uniform mat4 worldFromModel;
uniform mat4 clipFromWorld;
uniform mat3 normalFromModel;   // inverse transpose of the upper 3x3 of worldFromModel
uniform mat3 tangentFromModel;  // upper 3x3 of worldFromModel, or normalFromModel
uniform float mirrorSign;       // -1 when det(upper 3x3 of worldFromModel) < 0, else +1
uniform vec3 eyePosWorld;
// Each light as (position, 1) or, directional, (towards the light, 0): to it is xyz - w P.
uniform vec4 lightVectorWorld[MAX_LIGHTS];
uniform int lightCount;                       // in [0, MAX_LIGHTS]
uniform vec4 userClipPlanes[MAX_CLIP_PLANES];  // world space, keeps dot(plane, (p, 1)) >= 0
uniform int userClipPlaneCount;                // in [0, MAX_CLIP_PLANES]
// When one of near/far is off, GL's depth clamp drops both and the other one returns as
// clip distance 0 (glrender/gl_clip_state.h); user plane j then is clip distance j + 1.
uniform vec4 frustumClipPlane;  // clip space: keeps dot(plane, gl_Position) >= 0
uniform int firstUserClipSlot;  // 0, or 1 when slot 0 holds frustumClipPlane

VARYING out vec3 posWorld;
VARYING out vec3 nWorld;
VARYING out vec3 tWorld;
VARYING out vec3 bWorld;
VARYING out vec2 uv;
#ifdef LIGHTING_TANGENT
VARYING out vec3 lightDirTangent[MAX_LIGHTS];
VARYING out vec3 eyeDirTangent;
#endif

out float gl_ClipDistance[MAX_CLIP_PLANES];

void main() {
  posWorld = (worldFromModel * vec4(posModel, 1.0)).xyz;
  gl_Position = clipFromWorld * vec4(posWorld, 1.0);
  nWorld = normalFromModel * nModel;
  tWorld = tangentFromModel * tangentModel.xyz;
  // A mirroring transform reverses the (T, B, N) frame, so the sign flips with it.
  float handedness = tangentModel.w * mirrorSign;
  bWorld = handedness * cross(nWorld, tWorld);
  uv = uvModel;

#ifdef LIGHTING_TANGENT
  // The tutorial's vertex shader: light and eye directions in the vertex's tangent frame,
  // unnormalised so that interpolating them is the tutorial's behaviour.
  vec3 T = safeNormalize(tWorld);
  vec3 B = safeNormalize(bWorld);
  vec3 N = safeNormalize(nWorld);
  for (int i = 0; i < MAX_LIGHTS; ++i) {
    vec3 Lw = lightVectorWorld[i].xyz - lightVectorWorld[i].w * posWorld;
    lightDirTangent[i] = i < lightCount ? vec3(dot3(T, Lw), dot3(B, Lw), dot3(N, Lw)) : vec3(0.0);
  }
  vec3 Ew = eyePosWorld - posWorld;
  eyeDirTangent = vec3(dot3(T, Ew), dot3(B, Ew), dot3(N, Ew));
#endif

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
