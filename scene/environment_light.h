// The environment's diffuse light (docs/environment.md, "Diffuse light"), prefiltered once at
// load, in double, for both renderers: what a white Lambertian surface with normal n reflects
// of the whole environment,
//   D(n) = E(n) / pi = (1 / pi) * integral over the sphere of L(w) max(n.w, 0) dw
// (a constant environment L gives D = L). Two forms, as the slides teach:
//   irradiance map  D at each texel centre of a small cube, the integral summed over every
//                   texel of a small level of the source, each weighted by max(n.w, 0) and its
//                   exact solid angle, divided by the weights' sum (pi, but for the texels the
//                   horizon cuts)
//   SH9             L projected on the nine real spherical harmonics of bands 0..2, and D from
//                   them with the cosine lobe's band factors A0 = pi, A1 = 2 pi / 3, A2 = pi / 4
//                   (Ramamoorthi and Hanrahan 2001): nine numbers per channel, no texture
// Both are measured against a Monte Carlo estimate of the integral over the source itself
// (irradianceMonteCarlo), and SH9 against the irradiance map.
#pragma once

#include "scene/environment.h"
#include "scene/monte_carlo.h"
#include "scene/settings.h"

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace twr {

struct Material;
struct Scene;

// Side of the irradiance cube (texels): D varies slowly (the cosine lobe is 180 degrees wide),
// and bilinear over 32 texels per 90-degree face is within 1/255 of the exact sum on the
// sky tests use (tests/scene/test_environment_light.cpp).
inline constexpr int kIrradianceCubeSize = 32;
// The source level the sums read: the first whose side is at most this (texels). The cosine
// lobe and the bands up to 2 carry no detail finer than a few degrees, so a 32-texel face
// (2.8 degrees per texel) loses nothing the measurement can see.
inline constexpr int kIrradianceSourceSize = 32;

// The unit direction through the centre of texel (x, y) of `face` on a cube of side `size`.
glm::dvec3 cubeTexelDirection(int face, int x, int y, int size);
// The solid angle of texel (x, y) of any face of a cube of side `size` (steradians, exact:
// the projected area of the texel's square on the unit sphere; the six faces sum to 4 pi).
double cubeTexelSolidAngle(int x, int y, int size);

// Every texel of a cube level in face order ((face * side + y) * side + x): its direction,
// its exact solid angle and its radiance, in double (what the sums over the sphere read: the
// irradiance here, the prefiltered reflection in environment_specular.h).
struct CubeLevelTexels {
  int side = 0;
  std::vector<glm::dvec3> direction, radiance;
  std::vector<double> solidAngle;
};
CubeLevelTexels cubeLevelTexels(const CubeMapLevel& level);

// The irradiance cube of side `size` (one level): each texel D at its centre's direction.
CubeMap irradianceCubeFromCube(const CubeMap& cube, int size = kIrradianceCubeSize);

// D as nine coefficients per channel with the band factors and the harmonics' constants
// folded in, so both renderers evaluate, for a unit normal n = (x, y, z),
//   D = c0 + c1 y + c2 z + c3 x + c4 (x y) + c5 (y z) + c6 (3 z^2 - 1) + c7 (x z) + c8 (x^2 - y^2)
// left to right, and clamp it at 0 (band 2's ringing can go below 0 opposite a bright sun).
struct Sh9Irradiance {
  std::array<glm::dvec3, 9> c{};
};
Sh9Irradiance sh9IrradianceFromCube(const CubeMap& cube);
// The evaluation above in double, clamped at 0.
glm::dvec3 irradianceFromSh9(const Sh9Irradiance& sh, const glm::dvec3& n);

// D(n) by Monte Carlo over the source itself: `samples` cosine-weighted directions around n
// (the Duff et al. basis, a fixed seed), each the cube's level 0 read exactly (cubeBilinear);
// D is their mean, as cos(w) / pi is the samples' density.
glm::dvec3 irradianceMonteCarlo(const CubeMap& cube, const glm::dvec3& n, std::size_t samples, std::uint64_t seed);
// The same estimate with its standard error (the samples' standard deviation over sqrt(samples)).
using MonteCarloIrradiance = MonteCarloEstimate;
MonteCarloIrradiance irradianceMonteCarloWithError(const CubeMap& cube, const glm::dvec3& n, std::size_t samples,
                                                   std::uint64_t seed);

// Direction i of `count` spread evenly over the sphere (a Fibonacci sphere: deterministic,
// the same set for every measurement of a given count).
glm::dvec3 fibonacciSphereDirection(std::size_t i, std::size_t count);

// Whether a material reads the scene's environment at all (both renderers decide with this):
// a mirror reflection, a refraction or a diffuse light, and the scene has a cube.
bool materialReadsEnvironment(const Material& material, const Scene& scene);
// Whether it reads the reflected or refracted direction (a mirror or prefiltered reflection, a
// refraction).
bool materialReadsEnvironmentDirections(const Material& material);

// The diffuse light a material reads: its environment_diffuse when the environment holds it
// (prefilterEnvironmentLight built it), else None. Both renderers decide with this.
EnvironmentDiffuse environmentDiffuseOf(const Material& material, const Environment& environment);

// The reflection a material mixes in: its environment_specular, but None for prefiltered when
// the environment holds no prefiltered cube (prefilterEnvironmentLight builds it). Both
// renderers decide with this.
EnvironmentSpecular environmentSpecularOf(const Material& material, const Environment& environment);

// Builds what the scene's materials ask for (the irradiance cube and its sphere or paraboloid
// map, the SH9 coefficients, the prefiltered specular cube and its map) on scene.environment,
// once; nothing when no material asks.
void prefilterEnvironmentLight(Scene& scene);

}  // namespace twr
