#include "softrender/shade.h"

#include "scene/environment_light.h"
#include "scene/environment_specular.h"
#include "scene/horizon_map.h"
#include "scene/surface_detail.h"

#include <algorithm>

namespace twr {

// One light as the shading reads it: its vector (w 1 for a point light, 0 for a directional
// one), colours, attenuation and spot cone.
template <typename T>
LightUniformT<T> lightUniformOf(const Light& light) {
  LightUniformT<T> lu{};
  lu.vectorWorld = Vec4T<T>(lightVectorWorld(light));
  lu.diffuse = Vec3T<T>(light.diffuse);
  lu.specular = Vec3T<T>(light.specular);
  lu.attenuation = Vec3T<T>(attenuationUsed(light));
  const SpotUniform spot = spotUniformOf(light);
  lu.spot = spot.axis.w > 0.0f;
  lu.spotAxis = Vec3T<T>(vec3(spot.axis));
  lu.spotCosOuter = static_cast<T>(spot.cone.x);
  lu.spotCosRange = static_cast<T>(spot.cone.y);
  return lu;
}

// The environment as a material that reads it sees it: its maps, what it reflects or
// refracts, and its diffuse light.
template <typename T>
EnvironmentUniformsT<T> environmentUniformsOf(const Material& material, const Environment& env) {
  EnvironmentUniformsT<T> e{};
  e.cube = env.cube.get();
  e.layers = env.layers.get();
  e.intensity = static_cast<T>(env.intensity);
  const EnvironmentSpecular specular = environmentSpecularOf(material, env);
  e.reflects = specular != EnvironmentSpecular::None;
  if (specular == EnvironmentSpecular::Prefiltered) {
    // The LOD from the shininess, in double, rounded once: GL receives the same float.
    e.prefiltered = true;
    e.specularCube = env.specular.get();
    e.specularLayers = env.specularLayers.get();
    e.specularLod = static_cast<T>(static_cast<float>(specularLodFromShininess(*env.specular, material.shininess)));
  }
  e.refraction = material.refractionIndex > 0.0f;
  e.schlick = material.fresnel == Fresnel::Schlick;
  e.reflectivity = static_cast<T>(material.reflectivity);
  e.eta = static_cast<T>(e.refraction ? material.refractionIndex : 1.0f);
  // The diffuse light as prefiltered at load (prefilterEnvironmentLight).
  e.diffuse = environmentDiffuseOf(material, env);
  if (e.diffuse == EnvironmentDiffuse::IrradianceMap) {
    e.irradiance = env.irradiance.get();
    e.irradianceLayers = env.irradianceLayers.get();
  } else if (e.diffuse == EnvironmentDiffuse::Sh9) {
    for (std::size_t i = 0; i < 9; ++i) e.sh9[i] = Vec3T<T>(env.sh9->c[i]);
  }
  return e;
}

template <typename T>
ShadeUniformsT<T> makeShadeUniforms(const Material& material, const Scene& scene, const RenderSettings& settings) {
  ShadeUniformsT<T> u;
  u.ka = Vec3T<T>(material.ka);
  u.kd = Vec3T<T>(material.kd);
  u.ks = Vec3T<T>(material.ks);
  u.shininess = static_cast<T>(std::fmax(material.shininess, 0.0f));
  u.ssrReflect = static_cast<T>(material.ssrReflect);
  // A map with no texels cannot be sampled; the feature is then off, as if absent.
  auto usable = [](const std::shared_ptr<const Texture>& t) -> const Texture* {
    return t && t->width > 0 && t->height > 0 && !t->rgba.empty() ? t.get() : nullptr;
  };
  u.diffuseMap = usable(material.diffuseMap);
  u.normalMap = usable(material.normalMap);
  u.specularMap = usable(material.specularMap);
  // Height field: read when the method draws it, or when a height view shows it
  // (scene/surface_detail.h decides for both renderers).
  const SurfaceDetailUse use = surfaceDetailUse(material, settings);
  if (!use.normalMap) u.normalMap = nullptr;
  if (use.heightMap) {
    const Texture* height = material.heightMap.get();
    u.heightMap = height;
    u.surfaceDetail = use.method;
    u.heightScale = static_cast<T>(material.heightScale);
    u.heightTexel = Vec2T<T>(T(1.0f / static_cast<float>(height->width)), T(1.0f / static_cast<float>(height->height)));
    u.layersMin = static_cast<T>(material.parallaxLayers.x);
    u.layersMax = static_cast<T>(material.parallaxLayers.y);
    u.layerCap = material.parallaxLayers.y;
    u.refinementSteps = use.method == SurfaceDetail::Relief ? material.reliefRefinementSteps : 0;
    u.selfShadow = use.selfShadow;
    u.horizonDirections = use.horizonDirections;
    for (int k = 0; k < use.horizonDirections / 4; ++k) {
      u.horizonMaps[static_cast<std::size_t>(k)] = material.horizonMap->textures[static_cast<std::size_t>(k)].get();
    }
  }
  u.filter = settings.textureFilter;
  u.anisotropic = settings.anisotropy > 1.0f;
  if (u.normalMap) {
    u.normalGreenDown = u.normalMap->options.green == GreenAxis::Down;
    u.normalXy = u.normalMap->channels == TextureChannels::RedGreen;
    u.normalStrengthOn = material.normalStrength != 1.0f;
    u.normalStrength = static_cast<T>(material.normalStrength);
  }
  const Texture* maps[3] = {u.diffuseMap, u.normalMap, u.specularMap};
  for (std::size_t i = 0; i < 3; ++i) {
    if (!maps[i]) continue;
    const TextureOptions& o = maps[i]->options;
    u.uvTransform[i] = o.uvScale != vec2(1.0f) || o.uvOffset != vec2(0.0f);
    u.uvScale[i] = Vec2T<T>(o.uvScale);
    u.uvOffset[i] = Vec2T<T>(o.uvOffset);
  }
  u.ambient = Vec3T<T>(scene.ambient);
  u.lightCount = std::min(static_cast<int>(scene.lights.size()), kMaxLights);
  for (int i = 0; i < u.lightCount; ++i) {
    u.lights[static_cast<std::size_t>(i)] = lightUniformOf<T>(scene.lights[static_cast<std::size_t>(i)]);
  }
  u.eyePosWorld = Vec3T<T>(scene.camera.position);
  u.view = fragmentViewOf(settings.view);
  // The environment: read only when the scene has one and the material mixes it in.
  if (materialReadsEnvironment(material, scene)) u.environment = environmentUniformsOf<T>(material, *scene.environment);
  return u;
}

// The two pipelines: float (matches GL) and double (the reference).
template ShadeUniformsT<float> makeShadeUniforms<float>(const Material&, const Scene&, const RenderSettings&);
template ShadeUniformsT<double> makeShadeUniforms<double>(const Material&, const Scene&, const RenderSettings&);

vec4 shadeFragmentDynamic(const ShaderKey& key, const Fragment& f, const ShadeUniforms& u, ShadeTerms* terms) {
  vec4 colour(0.0f);
  withShaderFeatures(key, [&]<typename Features>() { colour = shadeFragment<Features>(f, u, terms); });
  return colour;
}

void setEnvironmentDifferencesDynamic(const ShaderKey& key, const VaryingPlanes& planes, int px, int py,
                                      const ShadeUniforms& u, Fragment& f) {
  withShaderFeatures(key, [&]<typename Features>() { setEnvironmentDifferences<Features>(planes, px, py, u, f); });
}

}  // namespace twr
