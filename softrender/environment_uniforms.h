// The environment's uniforms (environment-inl.h reads them; shade.h's ShadeUniformsT holds
// one): the cube, what every read is scaled by, and how the material mixes it in. Plain types,
// outside the per-target namespaces, so every lane type's shading reads the same struct.
#pragma once

#include "scene/environment.h"
#include "scene/settings.h"
#include "softrender/precision.h"

#include <array>

namespace twr {

template <typename S>
struct EnvironmentUniformsT {
  // Null: the scene has no environment or the material does not use it; nothing is read.
  const CubeMap* cube = nullptr;
  // Not null: the environment is read from this sphere or dual-paraboloid map instead of the
  // cube (layer_sample-inl.h).
  const ParameterizedMap* layers = nullptr;
  S intensity = S(1);
  bool reflects = false;    // environment_specular mirror or prefiltered: the reflection is mixed in
  // environment_specular prefiltered: the reflection is read from the prefiltered cube (or its
  // sphere or paraboloid map when not null) at the explicit LOD the shininess gives
  // (scene/environment_specular.h), instead of the environment with texture().
  bool prefiltered = false;
  const CubeMap* specularCube = nullptr;
  const ParameterizedMap* specularLayers = nullptr;
  S specularLod = S(0);
  bool refraction = false;  // refraction_index given: the refracted environment replaces the Phong colour
  bool schlick = false;     // fresnel schlick
  S reflectivity = S(0);    // [0, 1]
  S eta = S(1);             // refraction_index, n1 / n2
  // environment_diffuse: the light a white Lambertian surface reflects (scene/environment_light.h),
  // read at the normal from the irradiance cube (or its sphere or paraboloid map when not null),
  // or evaluated from the nine SH coefficients (the band factors folded in).
  EnvironmentDiffuse diffuse = EnvironmentDiffuse::None;
  const CubeMap* irradiance = nullptr;
  const ParameterizedMap* irradianceLayers = nullptr;
  std::array<Vec3T<S>, 9> sh9{};
  // A reflection or a refraction: the directions are needed.
  bool readsDirections() const { return reflects || refraction; }
  // A read with texture() (a mirror reflection, a refraction or its total internal
  // reflection): the directions' quad differences are needed too.
  bool readsDifferences() const { return (reflects && !prefiltered) || refraction; }
};

}  // namespace twr
