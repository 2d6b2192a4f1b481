// TBN debug lines, core profile: flat colour, alpha 1 like every drawn pixel.
in vec3 colour;

layout(location = 0) out vec4 fragColour;

void main() {
  fragColour = vec4(colour, 1.0);
}
