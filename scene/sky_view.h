// The sky box's view (docs/environment.md): the uniforms both renderers draw it with. The
// direction of pixel (px, py) (GL window coordinates, centre at +0.5) is
//   ndc = (p + 0.5) * (2 / size) - 1,   dir = (forward + right * ndc.x) + up * ndc.y
// with forward, right and up the camera's axes scaled by the projection (right by
// tan(fov / 2) * aspect, up by tan(fov / 2)), computed once in double and rounded to float.
// The CPU draws it in softrender/sky.*, GL in shaders/sky.* (glrender/gl_scene_draw.cpp).
#pragma once

#include "scene/scene.h"

namespace twr {

template <typename T>
struct SkyUniformsT {
  const CubeMap* cube = nullptr;  // null: no sky (no environment, or background false)
  const ParameterizedMap* layers = nullptr;  // not null: read instead of the cube
  T intensity = T(1);
  glm::vec<3, T> forward{T(0), T(0), T(-1)}, right{T(1), T(0), T(0)}, up{T(0), T(1), T(0)};
  glm::vec<2, T> ndcPerPixel{T(1)};  // 2 / width, 2 / height
  // Shaded: the environment's colour; an environment view (isEnvironmentView): what the sky's
  // direction reads, as the surfaces show it (softrender/environment_view-inl.h).
  View view = View::Shaded;
};

// Whether a frame of `scene` with `settings` draws the sky box: an environment with
// "background" true, in the shaded view or an environment view (the other debug views show
// the clear colour behind surfaces).
bool drawsSky(const Scene& scene, const RenderSettings& settings);

// The sky of `scene` for a frame of width x height in `view` (cube null when it draws none:
// no environment, background false, or a view that shows no sky): float for both renderers,
// double for the reference renderer.
template <typename T = float>
SkyUniformsT<T> makeSkyUniforms(const Scene& scene, int width, int height, View view);

}  // namespace twr
