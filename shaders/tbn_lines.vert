// TBN debug lines, core profile: world-space segments with a colour per vertex.
layout(location = 0) in vec3 posWorld;
layout(location = 1) in vec3 lineColour;

uniform mat4 clipFromWorld;

out vec3 colour;

void main() {
  gl_Position = clipFromWorld * vec4(posWorld, 1.0);
  colour = lineColour;
}
