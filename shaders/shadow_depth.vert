// The shadow pass's vertex stage (glrender/gl_shadow_pass.h): phong.vert's position alone, the
// same two products in the same order, so a surface lands at the depth the frame's vertex
// stage would give it from the light. C++ twin: softrender/vertex.cpp (the shadow pass runs the
// whole vertex stage there; only its position is read).

layout(location = 0) in vec3 posModel;

uniform mat4 worldFromModel;
uniform mat4 clipFromWorld;

void main() {
  vec3 posWorld = (worldFromModel * vec4(posModel, 1.0)).xyz;
  gl_Position = clipFromWorld * vec4(posWorld, 1.0);
}
