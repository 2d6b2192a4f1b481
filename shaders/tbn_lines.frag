// TBN debug lines, core profile: flat colour with alpha 1, written to the colour target
// and, as fixed-function immediate mode does by replicating its colour, to the line mask.
in vec3 colour;

layout(location = 0) out vec4 fragColour;
layout(location = 1) out vec4 lineMaskColour;

void main() {
  fragColour = vec4(colour, 1.0);
  lineMaskColour = fragColour;
}
