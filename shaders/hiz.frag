// The Hi-Z chain of the screen-space reflections' hiz march (docs/ssr.md): one R32F texture,
// level k the least surface eye distance over 2^k x 2^k pixels. HIZ_FROM_GBUFFER draws level 0,
// each pixel's own distance (ssr_distance.glsl's bufferDistance); without it, a level from the
// one below, each texel the least of its 2x2 texels there, with the odd last column or row the
// halving drops folded into the last texel. C++ twin: hizChainOf (softrender/ssr.cpp).
// Included after common.glsl and, with HIZ_FROM_GBUFFER, ssr_distance.glsl.

#ifndef HIZ_FROM_GBUFFER
uniform sampler2D levelBelow;  // the chain with its base and top level set to the level below
#endif

layout(location = 0) out vec4 fragColour;

void main() {
  ivec2 texel = ivec2(gl_FragCoord.xy);
#ifdef HIZ_FROM_GBUFFER
  fragColour = vec4(bufferDistance(texel), 0.0, 0.0, 1.0);
#else
  ivec2 below = textureSize(levelBelow, 0);
  ivec2 here = max(below / 2, ivec2(1));
  ivec2 first = 2 * texel;
  // The last column (row) also covers the one an odd size leaves over.
  ivec2 end = ivec2(texel.x == here.x - 1 ? below.x : first.x + 2, texel.y == here.y - 1 ? below.y : first.y + 2);
  float least = texelFetch(levelBelow, first, 0).r;
  for (int y = first.y; y < end.y; ++y) {
    for (int x = first.x; x < end.x; ++x) least = min(least, texelFetch(levelBelow, ivec2(x, y), 0).r);
  }
  fragColour = vec4(least, 0.0, 0.0, 1.0);
#endif
}
