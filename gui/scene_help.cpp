// The Scene tab's tooltips and mesh counts (gui/scene_help.h).
#include "gui/scene_help.h"

namespace twr::gui {

const char* surfaceDetailHelp(SurfaceDetail method) {
  switch (method) {
    case SurfaceDetail::NormalMap:
      return "normal_map: the normal map alone (without one, the interpolated normal). The height map is not read "
             "(except by the height views): the surface is lit as bumpy but stays flat to the eye.";
    case SurfaceDetail::BumpBlinn:
      return "bump_blinn (Blinn 1978): a normal made from the height map's slopes (central differences, times "
             "height_scale) replaces the normal map. Only the lighting changes: uv is not shifted, so the texture "
             "and the silhouette stay flat.";
    case SurfaceDetail::BumpEmboss:
      return "bump_emboss: the fixed-function trick. The height is read again one texel towards the light and the "
             "difference, times height_scale, is added to N.L: diffuse only, no specular, no new normal.";
    case SurfaceDetail::Parallax:
      return "parallax (Kaneko 2001): uv moves by V.xy / V.z times the depth (1 - h) height_scale read at the "
             "pixel. The division by V.z makes the shift grow without bound towards grazing views, where the "
             "texture swims and tears.";
    case SurfaceDetail::ParallaxOffsetLimited:
      return "parallax_offset_limited (Welsh 2004): plain parallax without the division by V.z, so the shift never "
             "exceeds height_scale: stable at grazing views, at the price of less apparent depth there.";
    case SurfaceDetail::SteepParallax:
      return "steep_parallax (McGuire 2005): marches the view ray down through the relief in parallax_layers "
             "layers (min facing the camera, max at grazing views) and stops at the first layer below the height "
             "field: correct occlusion, but the layers show as steps.";
    case SurfaceDetail::Relief:
      return "relief (Policarpo 2005): steep parallax's march, then a binary search between the last two layers "
             "(relief_refinement_steps halvings) for where the ray meets the height field.";
    case SurfaceDetail::ParallaxOcclusion:
      return "parallax_occlusion (Tatarchuk 2006): steep parallax's march, then the hit interpolated linearly "
             "between the last two layers: smooth, with no reads beyond the march.";
  }
  return "";
}

const char* selfShadowHelp(SelfShadow shadow) {
  switch (shadow) {
    case SelfShadow::None:
      return "none: the height field casts no shadow on itself.";
    case SelfShadow::HeightMarch:
      return "height_march: from the shaded point, march towards each light through the height field in "
             "parallax_layers layers; the more the field rises above that ray, the darker. Costs a march per "
             "light per pixel.";
    case SelfShadow::HorizonMap:
      return "horizon_map (Max 1988; Sloan and Cohen 2000): per texel and horizon_directions azimuths, the "
             "elevation of the horizon is computed once; a light below it is shadowed. One or a few texture reads "
             "per light, but the map must be built again when the height map, height_scale or the directions "
             "change.";
  }
  return "";
}

int countNodesUsingMesh(const std::vector<Node>& nodes, int meshIndex) {
  int count = 0;
  for (const Node& node : nodes) {
    if (node.meshIndex == meshIndex) ++count;
    count += countNodesUsingMesh(node.children, meshIndex);
  }
  return count;
}

}  // namespace twr::gui
