#include "scene/surface_detail.h"

#include "scene/horizon_map.h"

namespace twr {

bool usableTexture(const Texture* texture) {
  return texture && texture->width > 0 && texture->height > 0 && !texture->rgba.empty();
}

SurfaceDetailUse surfaceDetailUse(const Material& material, const RenderSettings& settings) {
  SurfaceDetailUse use;
  use.normalMap = usableTexture(material.normalMap.get());
  if (!usableTexture(material.heightMap.get())) return use;
  if (material.surfaceDetail == SurfaceDetail::NormalMap && !isHeightView(settings.view)) return use;
  use.heightMap = true;
  use.method = material.surfaceDetail;
  if (use.method == SurfaceDetail::BumpBlinn || use.method == SurfaceDetail::BumpEmboss) use.normalMap = false;
  if (use.method != SurfaceDetail::NormalMap) use.selfShadow = material.selfShadow;
  if (use.selfShadow == SelfShadow::HorizonMap) {
    // A material made in code without its horizon map is drawn unshadowed (scene files build it).
    const HorizonMap* horizon = material.horizonMap.get();
    if (horizon && horizon->directions > 0 &&
        static_cast<int>(horizon->textures.size()) * 4 == horizon->directions) {
      use.horizonDirections = horizon->directions;
    } else {
      use.selfShadow = SelfShadow::None;
    }
  }
  return use;
}

}  // namespace twr
