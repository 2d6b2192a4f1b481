#include "softrender/shade.h"

#include <algorithm>

namespace twr {

ShadeUniforms makeShadeUniforms(const Material& material, const Scene& scene, const RenderSettings& settings) {
  ShadeUniforms u;
  u.ka = material.ka;
  u.kd = material.kd;
  u.ks = material.ks;
  u.shininess = std::fmax(material.shininess, 0.0f);
  // A map with no texels cannot be sampled; the feature is then off, as if absent.
  auto usable = [](const std::shared_ptr<const Texture>& t) -> const Texture* {
    return t && t->width > 0 && t->height > 0 && !t->rgba.empty() ? t.get() : nullptr;
  };
  u.diffuseMap = usable(material.diffuseMap);
  u.normalMap = usable(material.normalMap);
  u.specularMap = usable(material.specularMap);
  u.filter = settings.textureFilter;
  u.ambient = scene.ambient;
  u.lightCount = std::min(static_cast<int>(scene.lights.size()), kMaxLights);
  for (int i = 0; i < u.lightCount; ++i) {
    const PointLight& light = scene.lights[static_cast<std::size_t>(i)];
    LightUniform& lu = u.lights[static_cast<std::size_t>(i)];
    lu.posWorld = light.posWorld;
    lu.diffuse = light.diffuse;
    lu.specular = light.specular;
    lu.attenuation = light.attenuation;
  }
  u.eyePosWorld = scene.camera.position;
  return u;
}

float phongPow(float x, float s) {
  if (!(x > 0.0f)) return s > 0.0f ? 0.0f : 1.0f;
  return std::pow(x, s);
}

ShaderKey shaderKeyFor(const ShadeUniforms& uniforms, const RenderSettings& settings) {
  ShaderKey key;
  key.diffuseMap = uniforms.diffuseMap != nullptr;
  key.normalMap = uniforms.normalMap != nullptr;
  key.specularMap = uniforms.specularMap != nullptr;
  key.space = settings.lightingSpace;
  key.view = settings.view;
  return key;
}

vec4 shadeFragmentDynamic(const ShaderKey& key, const Fragment& f, const ShadeUniforms& u, ShadeTerms* terms) {
  vec4 colour(0.0f);
  withShaderFeatures(key, [&]<typename Features>() { colour = shadeFragment<Features>(f, u, terms); });
  return colour;
}

}  // namespace twr
