// The environment's glossy reflection (docs/environment.md, "Glossy reflection"), prefiltered
// once at load, in double, for both renderers: what a Phong lobe of exponent e around the
// reflected direction r gathers of the whole environment,
//   G_e(r) = integral of L(w) max(r.w, 0)^e dw / integral of max(r.w, 0)^e dw
// (a constant environment L gives G = L). One cube holds a lobe per mip level, as the slides
// teach: level l, of side N_l, is the source convolved with the lobe of exponent
//   e_l = (N_l / 2)^2
// whose angular spread 1 / sqrt(e_l) is one texel of that level at a face's centre (2 / N_l
// radians), so each level is as sharp as its texels can show and no sharper. A material of
// shininess s reads it with textureLod at
//   lod = log4(e_0 / s) = 0.5 log2(e_0 / s)        (clamped to the chain)
// which lands on level l exactly where s = e_l; between two levels the read blends two lobes,
// an approximation the report measures against a Monte Carlo estimate over the source itself.
#pragma once

#include "scene/environment.h"
#include "scene/monte_carlo.h"

#include <cstddef>
#include <cstdint>

namespace twr {

// Largest side of the prefiltered cube (texels): level 0's lobe is then e_0 = 32^2 = 1024, a
// spread of 1.8 degrees; a larger shininess reads level 0 (the report measures what that
// costs; environment_specular mirror reads the sharp reflection). A smaller source keeps its
// own side. At 64 the build takes under a tenth of a second; at 128 it took a second.
inline constexpr int kSpecularCubeMaxSize = 64;
// A lobe is summed out to where its weight max(r.w, 0)^e falls below this share of its peak
// (unitless): the Gaussian-like tail beyond holds about that share of the lobe's integral.
inline constexpr double kSpecularLobeCutoff = 1e-4;
// Smallest source side a level is summed from (texels): wide lobes over a source of a few
// texels would lose the sun's shape in its texels' means.
inline constexpr int kSpecularMinSourceSize = 32;

// The Phong exponent of the level of side `side` (texels): (side / 2)^2.
double specularExponentOfSide(int side);
// The prefiltered cube: levels from min(source side, kSpecularCubeMaxSize) down to 1, each the
// source convolved with its level's lobe (above), summed over the texels of the source level of
// side min(source side, max(2 N_l, kSpecularMinSourceSize)) with their exact solid angles and
// divided by the weights' sum. Built on every core.
CubeMap specularCubeFromCube(const CubeMap& cube);
// The LOD a material of shininess `shininess` reads `specular` at: 0.5 log2(e_0 / shininess),
// in double, clamped to [0, levels - 1] (the last level for shininess <= 0). Both renderers
// receive it rounded to float, as a uniform.
double specularLodFromShininess(const CubeMap& specular, double shininess);

// G_e(r) by Monte Carlo over the source itself: `samples` directions drawn from the normalised
// lobe around r ((e + 1) / (2 pi) cos^e, in Duff et al.'s basis, a fixed seed), each the cube's
// level 0 read exactly (cubeBilinear); G is their mean. With its standard error.
MonteCarloEstimate specularMonteCarlo(const CubeMap& cube, const glm::dvec3& r, double exponent, std::size_t samples,
                                      std::uint64_t seed);
// The prefiltered cube read as textureLod does (GL_LINEAR_MIPMAP_LINEAR), in double: the two
// levels around `lod` (clamped to the chain), each bilinear and seamless, blended linearly.
glm::dvec3 cubeTrilinear(const CubeMap& cube, const glm::dvec3& r, double lod);

}  // namespace twr
