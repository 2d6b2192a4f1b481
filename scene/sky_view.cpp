#include "scene/sky_view.h"

#include "scene/camera.h"

#include <cmath>

namespace twr {

bool drawsSky(const Scene& scene, const RenderSettings& settings) {
  return scene.environment && scene.environment->background && scene.environment->cube && viewDrawsSky(settings.view);
}

template <typename T>
SkyUniformsT<T> makeSkyUniforms(const Scene& scene, int width, int height, View view) {
  SkyUniformsT<T> sky;
  if (!scene.environment || !scene.environment->background || !scene.environment->cube || !viewDrawsSky(view)) return sky;
  sky.view = view;
  sky.cube = scene.environment->cube.get();
  sky.layers = scene.environment->layers.get();
  // The view's axes in world space are the rows of viewFromWorld's rotation (lookAt).
  const glm::dmat4 viewFromWorldD(viewFromWorld(scene.camera));
  const glm::dvec3 rightAxis(viewFromWorldD[0][0], viewFromWorldD[1][0], viewFromWorldD[2][0]);
  const glm::dvec3 upAxis(viewFromWorldD[0][1], viewFromWorldD[1][1], viewFromWorldD[2][1]);
  const glm::dvec3 backAxis(viewFromWorldD[0][2], viewFromWorldD[1][2], viewFromWorldD[2][2]);
  const double tanHalfFov = std::tan(glm::radians(static_cast<double>(scene.camera.fovDeg)) * 0.5);
  const double aspect = static_cast<double>(width) / static_cast<double>(height);
  using V3 = glm::vec<3, T>;
  sky.intensity = static_cast<T>(scene.environment->intensity);
  sky.forward = V3(-backAxis);
  sky.right = V3(rightAxis * (tanHalfFov * aspect));
  sky.up = V3(upAxis * tanHalfFov);
  sky.ndcPerPixel = glm::vec<2, T>(static_cast<T>(2.0 / width), static_cast<T>(2.0 / height));
  return sky;
}

template SkyUniformsT<float> makeSkyUniforms<float>(const Scene&, int, int, View);
template SkyUniformsT<double> makeSkyUniforms<double>(const Scene&, int, int, View);

}  // namespace twr
