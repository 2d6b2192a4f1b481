// Which parts of a material's height field a frame reads: one decision both renderers follow
// (softrender/shade.cpp's uniforms, glrender/gl_scene_draw.cpp's defines), so a scene pays
// only for what it draws and both draw the same thing.
#pragma once

#include "scene/scene.h"

namespace twr {

struct SurfaceDetailUse {
  bool heightMap = false;  // the height map is read (a method draws it, or a height view shows it)
  bool normalMap = false;  // the normal map is read (the bump methods make their own normal)
  SurfaceDetail method = SurfaceDetail::NormalMap;
  SelfShadow selfShadow = SelfShadow::None;  // None unless a height-field method draws it
  int horizonDirections = 0;                 // > 0 when a horizon map is read
};

// A texture both renderers can sample (texels present).
bool usableTexture(const Texture* texture);

SurfaceDetailUse surfaceDetailUse(const Material& material, const RenderSettings& settings);

}  // namespace twr
