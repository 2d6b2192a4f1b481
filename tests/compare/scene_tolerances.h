// Tolerances for the scene suite, CPU versus llvmpipe in precise sampling mode: one place,
// one row per scene. None may be looser than the project's targets (issue 5):
//   coverage_mismatch = 0 where no triangle is clipped, <= 1 per 10,000 covered pixels where
//   clipping happens; over_1 <= 0.1 % of pixels both covered; max_abs_diff <= 3; no NaN.
// Measured on 2026-11-21 (Mesa 22.3.6 llvmpipe): every scene and view at coverage mismatch 0
// and max_abs_diff 1 with over_1 = 0. The defaults below keep one level (and 0.01 %) of
// headroom over that measurement for code-generation differences between x86 machines
// (llvmpipe fuses multiply-adds where the CPU has FMA); coverage stays exact.
#pragma once

#include <string_view>

namespace twr::suite {

struct SceneTolerance {
  std::string_view scene;              // file name in assets/scenes/
  int maxAbsDiff = 2;                  // levels, inclusive (target: 3)
  double maxOver1Pct = 0.01;           // % of pixels both covered, inclusive (target: 0.1)
  double maxCoverageMismatchPer10k = 0.0;  // per 10,000 covered pixels, inclusive (target: 0 / 1)
  // A measured exception to the targets, held to its own limits instead (said in the row's
  // comment and in the docs; an open issue owns each one).
  bool knownException = false;
};

inline constexpr SceneTolerance kSceneTolerances[] = {
    {"default.json"},
    {"cylinder_tutorial.json"},
    {"cube_faces.json"},
    {"sphere_coarse.json"},
    {"sphere_fine.json"},
    {"culling.json"},
    {"inside_near.json"},
    {"fill_rule.json"},
    {"user_clip.json"},
    {"nonuniform_scale.json"},
    {"mirrored_uvs.json"},
    {"uv_wrap.json"},
    {"many_lights.json"},
    {"light_touching.json"},
    {"filter_nearest.json"},
    {"tangent_space.json"},
    {"tbn_lines.json"},
    {"obj_model.json"},
    {"stability_poles.json"},
    {"stability_scales.json"},
    {"stability_w_zero.json"},
    // Height fields (issue 16): every method, at the scene's filter, agrees to 1 level at
    // 640x480 and 1280x720 since every varying is interpolated on llvmpipe's planes.
    {"height_bump_blinn.json"},
    {"height_bump_emboss.json"},
    {"height_parallax.json"},
    {"height_parallax_offset_limited.json"},
    {"height_steep_parallax.json"},
    {"height_relief.json"},
    {"height_parallax_occlusion.json"},
    {"height_grazing_mirrored.json"},
    // Environment mapping (issue 17): a sky box from six faces, a mirror sphere and a
    // Fresnel-reflective normal-mapped slab; glass and water (refraction, total internal
    // reflection, Schlick) under an equirect made into a cube.
    {"env_sky_box.json"},  // a cube corner and two edges filling the frame: seamless filtering
    {"env_mirror_sphere.json"},
    {"env_glass_sphere.json"},
    {"env_sphere_map.json"},        // the mirror sphere and sky read from a sphere map (rim at -Z, ahead)
    {"env_dual_paraboloid.json"},  // from a dual paraboloid, the seam between its halves in view
    {"env_diffuse_light.json"},                    // lit by the environment alone: irradiance cube and SH9
    {"env_diffuse_light_sphere.json"},             // the same, the irradiance read from a sphere map
    {"env_diffuse_light_dual_paraboloid.json"},    // and from a dual paraboloid
    {"env_glass_sphere_map.json"},                 // glass and water through a sphere map (its rim ahead)
    {"env_glass_dual_paraboloid.json"},            // and through a dual paraboloid
    {"env_glossy.json"},                           // prefiltered glossy reflection: shininess 8, 60, 700
    {"env_glossy_sphere.json"},                    // the same read from a sphere map
    {"env_glossy_dual_paraboloid.json"},           // and from a dual paraboloid, across its seam
    {"env_capture.json"},          // a mirror sphere's cube captured from the scene by each renderer
    {"env_capture_glossy.json"},   // the same, prefiltered and irradiance light, through a dual paraboloid
    {"light_directional.json"},    // a cube on a floor under two directional lights (the GAMES202 write-up's light)
    {"light_directional_tangent.json"},  // the same lit in tangent space (the vertex stage's light vectors)
    {"shadow_directional.json"},   // a cube and a ball on a floor, a directional light's 2048^2 map, PCF 3
    {"shadow_point_cube.json"},    // a point light's cube shadow map (6 x 512^2) over boxes, a ball and a wall
    {"shadow_peter_panning.json"},  // a thin card under a too-large bias: its shadow lost (peter-panning)
    {"shadow_spot.json"},  // a spot light's cone and its perspective shadow map (1024^2) over a box and a ball
    {"ssr_mirror_floor.json"},  // a cube and a ball on a floor that reflects them (SSR, linear_world), shadowed
    {"ssr_cave.json"},  // a room lit through a hole in its roof: SSR hiz with 4 cosine-weighted indirect samples
};

}  // namespace twr::suite
