// What a loaded scene holds, as `twinraster info` prints it: the node tree with each mesh's type,
// triangle and vertex counts and material, the totals, the materials and their maps, the
// lights, the environment, the camera, the output and the render settings; as text or as one
// JSON object (the keys docs/cli.md lists).
#include "scene/scene_description.h"

#include "scene/environment_light.h"
#include "scene/environment_specular.h"
#include "scene/json_text.h"
#include "scene/scene.h"
#include "scene/scene_file.h"

#include <charconv>
#include <cstdlib>
#include <memory>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

namespace twr {

using Json = nlohmann::ordered_json;

namespace {

// Spaces per level of the node tree in the text output.
constexpr int kTreeIndent = 2;

// The double nearest the float's shortest round-trip decimal, so 0.05f prints as 0.05 and
// not as 0.05000000074505806 (nlohmann stores numbers as double).
double clean(float v) {
  char buffer[32];
  const auto [end, error] = std::to_chars(buffer, buffer + sizeof(buffer), v);
  if (error != std::errc()) return v;
  return std::strtod(std::string(buffer, end).c_str(), nullptr);
}

Json toJson(vec2 v) { return Json::array({clean(v.x), clean(v.y)}); }
Json toJson(vec3 v) { return Json::array({clean(v.x), clean(v.y), clean(v.z)}); }
Json toJson(vec4 v) { return Json::array({clean(v.x), clean(v.y), clean(v.z), clean(v.w)}); }

// Six significant digits, as %g: short and readable for the text listing.
std::string num(float v) {
  std::ostringstream out;
  out << v;
  return out.str();
}
std::string text(vec3 v) { return "(" + num(v.x) + ", " + num(v.y) + ", " + num(v.z) + ")"; }

// The mesh as a scene file would write it; triangles lists are summarised, not repeated.
Json meshJson(const MeshDesc& d) {
  Json j;
  j["type"] = std::string(toString(d.type));
  switch (d.type) {
    case MeshType::Cube: j["size"] = clean(d.size); break;
    case MeshType::Sphere:
      j["radius"] = clean(d.radius);
      j["stacks"] = d.stacks;
      j["slices"] = d.slices;
      break;
    case MeshType::Plane:
      j["size"] = toJson(d.planeSize);
      j["uv_scale"] = clean(d.uvScale);
      break;
    case MeshType::Cylinder:
      j["radius"] = clean(d.radius);
      j["height"] = clean(d.height);
      j["slices"] = d.slices;
      break;
    case MeshType::Torus:
      j["major"] = clean(d.major);
      j["minor"] = clean(d.minor);
      j["rings"] = d.rings;
      j["sides"] = d.sides;
      break;
    case MeshType::Obj: j["path"] = d.path; break;
    case MeshType::Heightfield:
      j["size"] = toJson(d.planeSize);
      j["uv_scale"] = clean(d.uvScale);
      j["height_map"] = d.heightMap ? d.heightMap->path : std::string();
      j["height_scale"] = clean(d.heightScale);
      j["resolution"] = {d.gridSegments.x, d.gridSegments.y};
      break;
    case MeshType::Triangles:
      j["position_count"] = d.positions.size();
      j["has_uvs"] = !d.uvs.empty();
      j["has_normals"] = !d.normals.empty();
      break;
  }
  return j;
}

std::string meshText(const MeshDesc& d) {
  switch (d.type) {
    case MeshType::Cube: return "cube size " + num(d.size);
    case MeshType::Sphere:
      return "sphere radius " + num(d.radius) + ", " + std::to_string(d.stacks) + " stacks x " +
             std::to_string(d.slices) + " slices";
    case MeshType::Plane:
      return "plane " + num(d.planeSize.x) + " x " + num(d.planeSize.y) + ", uv_scale " + num(d.uvScale);
    case MeshType::Cylinder:
      return "cylinder radius " + num(d.radius) + ", height " + num(d.height) + ", " + std::to_string(d.slices) +
             " slices";
    case MeshType::Torus:
      return "torus major " + num(d.major) + ", minor " + num(d.minor) + ", " + std::to_string(d.rings) +
             " rings x " + std::to_string(d.sides) + " sides";
    case MeshType::Obj: return "obj part of " + d.path;
    case MeshType::Heightfield:
      return "heightfield " + num(d.planeSize.x) + " x " + num(d.planeSize.y) + ", uv_scale " + num(d.uvScale) +
             ", height_scale " + num(d.heightScale) + (d.heightMap ? ", height map " + d.heightMap->path : "");
    case MeshType::Triangles: return "triangles";
  }
  return "?";
}

std::string materialName(const Scene& scene, int index) {
  if (index < 0 || index >= static_cast<int>(scene.materials.size())) return "(" + defaultMaterial().name + ")";
  return scene.materials[static_cast<std::size_t>(index)].name;
}

const Mesh* meshOf(const Scene& scene, const Node& node) {
  if (node.meshIndex < 0 || node.meshIndex >= static_cast<int>(scene.meshes.size())) return nullptr;
  return &scene.meshes[static_cast<std::size_t>(node.meshIndex)];
}

Json nodeJson(const Scene& scene, const Node& node) {
  Json j;
  j["name"] = node.name;
  j["translate"] = toJson(node.translate);
  j["rotate_deg"] = toJson(node.rotateDeg);
  j["scale"] = toJson(node.scale);
  if (const Mesh* mesh = meshOf(scene, node)) {
    j["mesh"] = meshJson(scene.meshDescs[static_cast<std::size_t>(node.meshIndex)]);
    j["triangles"] = mesh->triangleCount();
    j["vertices"] = mesh->vertices.size();
    j["material"] = node.materialIndex >= 0 ? Json(materialName(scene, node.materialIndex)) : Json(nullptr);
  } else {
    j["mesh"] = nullptr;
    j["triangles"] = 0;
    j["vertices"] = 0;
    j["material"] = nullptr;
  }
  Json children = Json::array();
  for (const Node& child : node.children) children.push_back(nodeJson(scene, child));
  j["children"] = std::move(children);
  return j;
}

void printNode(std::ostream& out, const Scene& scene, const Node& node, int depth) {
  out << std::string(static_cast<std::size_t>(kTreeIndent * (depth + 1)), ' ') << node.name;
  if (const Mesh* mesh = meshOf(scene, node)) {
    out << ": " << meshText(scene.meshDescs[static_cast<std::size_t>(node.meshIndex)]) << "; "
        << mesh->triangleCount() << " triangles, " << mesh->vertices.size() << " vertices; material "
        << materialName(scene, node.materialIndex);
  } else {
    out << ": (no mesh)";
  }
  if (node.translate != vec3(0.0f)) out << "; translate " << text(node.translate);
  if (node.rotateDeg != vec3(0.0f)) out << "; rotate_deg " << text(node.rotateDeg);
  if (node.scale != vec3(1.0f)) out << "; scale " << text(node.scale);
  out << "\n";
  for (const Node& child : node.children) printNode(out, scene, child, depth + 1);
}

std::string_view mipSourceName(MipSource source) {
  switch (source) {
    case MipSource::File: return "file";
    case MipSource::Built: return "built";
    case MipSource::None: break;
  }
  return "none";
}

Json mapJson(const std::shared_ptr<const Texture>& map) {
  if (!map) return nullptr;
  return Json{{"path", map->path},
              {"width", map->width},
              {"height", map->height},
              {"format", map->formatName},
              {"levels", map->levelCount()},
              {"levels_from", std::string(mipSourceName(map->mipSource))},
              {"gl_upload", map->blockFormat ? "compressed" : "rgba8"},
              {"wrap", std::string(toString(map->options.wrap))},
              {"srgb", map->options.srgb},
              {"flip_v", map->options.flipV},
              {"green", std::string(toString(map->options.green))}};
}

Json settingsJson(const RenderSettings& s) {
  Json j;
  j["cull"] = std::string(toString(s.cull));
  j["front_face"] = std::string(toString(s.frontFace));
  j["clip"] = Json{{"left", s.clip.left}, {"right", s.clip.right}, {"bottom", s.clip.bottom},
                   {"top", s.clip.top},   {"near", s.clip.near},   {"far", s.clip.far}};
  Json planes = Json::array();
  for (const vec4& plane : s.userClipPlanes) planes.push_back(toJson(plane));
  j["user_clip_planes"] = std::move(planes);
  j["view"] = std::string(toString(s.view));
  j["lighting_space"] = std::string(toString(s.lightingSpace));
  j["pipeline"] = std::string(toString(s.pipeline));
  j["gbuffer_position"] = std::string(toString(s.gbufferPosition));
  j["ssr"] = Json{{"enabled", s.ssr.enabled},
                  {"march", std::string(toString(s.ssr.march))},
                  {"max_steps", s.ssr.maxSteps},
                  {"step", clean(s.ssr.step)},
                  {"thickness", clean(s.ssr.thickness)},
                  {"indirect_samples", s.ssr.indirectSamples},
                  {"sample_distribution", std::string(toString(s.ssr.sampleDistribution))},
                  {"reflect_strength", clean(s.ssr.reflectStrength)}};
  j["tangent_transform"] = std::string(toString(s.tangentTransform));
  j["interpolation"] = std::string(toString(s.interpolation));
  j["texture_filter"] = std::string(toString(s.textureFilter));
  j["tbn_lines"] = Json{{"enabled", s.tbnLines.enabled}, {"length", clean(s.tbnLines.length)},
                        {"mode", std::string(toString(s.tbnLines.mode))}};
  return j;
}

// 1 + log2(side): the levels of a full mip chain down to 1 texel (0 for no side).
int levelCountOfSide(int side) {
  int levels = 0;
  for (; side > 0; side /= 2) ++levels;
  return levels;
}

// Whether a material reads the environment: as the renderers decide, or, for a captured
// environment before any renderer has drawn it, as they will once they have.
bool readsEnvironment(const Material& m, const Scene& scene) {
  if (scene.environment && scene.environment->capture && !scene.environment->cube) {
    return materialReadsEnvironmentDirections(m) || m.environmentDiffuse != EnvironmentDiffuse::None;
  }
  return materialReadsEnvironment(m, scene);
}

// The environment as loaded (null without one), and each material's use of it.
Json environmentJson(const Scene& scene) {
  if (!scene.environment) return nullptr;
  const Environment& e = *scene.environment;
  // A captured cube is drawn by each renderer per frame: its size and chain are the capture's.
  const int faceSize = e.cube ? e.cube->size() : e.capture ? e.capture->size : 0;
  Json j{{"source", e.capture ? "capture" : e.equirectPath.empty() ? "cube" : "equirect"},
         {"parameterization", std::string(toString(e.parameterization))},
         {"intensity", clean(e.intensity)},
         {"background", e.background},
         {"face_size", faceSize},
         {"levels", e.cube ? e.cube->levelCount() : levelCountOfSide(faceSize)}};
  if (e.layers) {
    j["map_size"] = e.layers->size();
    j["map_layers"] = e.layers->layers;
    j["map_levels"] = e.layers->levelCount();
  }
  if (e.capture) {
    j["capture"] = Json{{"node", e.capture->node}, {"size", e.capture->size}};
    if (e.parameterization != EnvironmentParameterization::Cube) j["map_size"] = e.size;
  } else if (e.equirectPath.empty()) {
    j["cube"] = Json(e.facePaths);
  } else {
    j["equirect"] = e.equirectPath;
  }
  if (e.irradiance) j["irradiance_size"] = e.irradiance->size();
  j["sh9"] = e.sh9 != nullptr;
  if (e.specular) {
    j["specular_size"] = e.specular->size();
    j["specular_levels"] = e.specular->levelCount();
  }
  Json uses = Json::object();
  for (const Material& m : scene.materials) {
    if (!readsEnvironment(m, scene)) continue;
    Json use{{"reflectivity", clean(m.reflectivity)},
             {"fresnel", std::string(toString(m.fresnel))},
             {"environment_specular", std::string(toString(m.environmentSpecular))},
             {"environment_diffuse", std::string(toString(m.environmentDiffuse))}};
    if (m.refractionIndex > 0.0f) use["refraction_index"] = clean(m.refractionIndex);
    uses[m.name] = use;
  }
  j["materials"] = uses;
  return j;
}

}  // namespace

Json sceneDescriptionJson(const Scene& scene) {
  Json j;
  j["scene"] = scene.sourcePath;
  Json nodes = Json::array();
  for (const Node& node : scene.nodes) nodes.push_back(nodeJson(scene, node));
  j["nodes"] = std::move(nodes);
  j["triangles"] = countTriangles(scene);
  j["vertices"] = countVertices(scene);
  Json materials = Json::array();
  for (const Material& m : scene.materials) {
    materials.push_back(Json{{"name", m.name},
                             {"ka", toJson(m.ka)},
                             {"kd", toJson(m.kd)},
                             {"ks", toJson(m.ks)},
                             {"shininess", clean(m.shininess)},
                             {"diffuse_map", mapJson(m.diffuseMap)},
                             {"normal_map", mapJson(m.normalMap)},
                             {"specular_map", mapJson(m.specularMap)}});
  }
  j["materials"] = std::move(materials);
  Json lights = Json::array();
  for (const Light& l : scene.lights) {
    const bool directional = l.type == LightType::Directional;
    lights.push_back(Json{{"type", directional ? "directional" : "point"},
                          {"position", directional ? Json(nullptr) : toJson(l.posWorld)},
                          {"direction", directional ? toJson(l.directionWorld) : Json(nullptr)},
                          {"diffuse", toJson(l.diffuse)},
                          {"specular", toJson(l.specular)},
                          {"attenuation", toJson(attenuationUsed(l))}});
    lights.back()["spot"] = isSpotLight(l) ? Json{{"direction", toJson(l.spot->directionWorld)},
                                                  {"inner_deg", clean(l.spot->innerDeg)},
                                                  {"outer_deg", clean(l.spot->outerDeg)}}
                                           : Json(nullptr);
    if (l.shadow) {
      const ShadowDesc& d = *l.shadow;
      const ShadowKind kind = directional ? ShadowKind::Orthographic
                              : isSpotLight(l) ? ShadowKind::Perspective
                                               : ShadowKind::Cube;
      lights.back()["shadow"] = Json{{"kind", std::string(toString(kind))},
                                     {"size", d.size},
                                     {"layers", kind == ShadowKind::Cube ? kCubeShadowLayers : 1},
                                     {"bias", {d.bias.x, d.bias.y}},
                                     {"pcf", d.pcf},
                                     {"extent", d.extent}};
    } else {
      lights.back()["shadow"] = nullptr;
    }
  }
  j["lights"] = std::move(lights);
  j["ambient"] = toJson(scene.ambient);
  j["camera"] = Json{{"position", toJson(scene.camera.position)},
                     {"target", toJson(scene.camera.target)},
                     {"up", toJson(scene.camera.up)},
                     {"fov_deg", clean(scene.camera.fovDeg)},
                     {"near", clean(scene.camera.near)},
                     {"far", clean(scene.camera.far)}};
  j["settings"] = settingsJson(scene.settings);
  j["output"] = Json{{"width", scene.output.width},
                     {"height", scene.output.height},
                     {"background", toJson(scene.output.background)}};
  j["environment"] = environmentJson(scene);
  return j;
}

namespace {

std::string mapsText(const Material& m) {
  std::string maps;
  const std::pair<const char*, const std::shared_ptr<const Texture>*> entries[] = {
      {"diffuse", &m.diffuseMap}, {"normal", &m.normalMap}, {"specular", &m.specularMap}};
  for (const auto& [name, map] : entries) {
    if (!*map) continue;
    const Texture& t = **map;
    std::string options;
    if (t.options.wrap != TextureWrap::Repeat) options += ", " + std::string(toString(t.options.wrap));
    if (t.options.srgb) options += ", srgb";
    if (t.options.flipV) options += ", flip_v";
    if (t.options.green == GreenAxis::Down) options += ", green down";
    maps += std::string(maps.empty() ? "" : ", ") + name + " " + t.path + " (" + std::to_string(t.width) + "x" +
            std::to_string(t.height) + " " + (t.formatName.empty() ? std::string("RGBA8") : t.formatName) + ", " +
            std::to_string(t.levelCount()) + " levels" +
            (t.mipSource == MipSource::File ? " from the file" : t.mipSource == MipSource::Built ? " built" : "") +
            (t.blockFormat ? ", uploaded compressed" : "") + options + ")";
  }
  return maps.empty() ? "none" : maps;
}

}  // namespace

void printSceneDescription(std::ostream& out, const Scene& scene) {
  const RenderSettings& s = scene.settings;
  out << "scene: " << scene.sourcePath << "\n";
  out << "output: " << scene.output.width << "x" << scene.output.height << ", background "
      << text(vec3(scene.output.background)) << " alpha " << num(scene.output.background.a) << "\n";
  out << "camera: position " << text(scene.camera.position) << ", target " << text(scene.camera.target)
      << (scene.camera.up != vec3(0.0f, 1.0f, 0.0f) ? ", up " + text(scene.camera.up) : std::string()) << ", fov_deg " << num(scene.camera.fovDeg) << ", near " << num(scene.camera.near) << ", far "
      << num(scene.camera.far) << "\n";

  out << "\nnodes:\n";
  if (scene.nodes.empty()) out << "  (none)\n";
  for (const Node& node : scene.nodes) printNode(out, scene, node, 0);
  const std::vector<DrawItem> items = flattenScene(scene);
  out << "total: " << countTriangles(scene) << " triangles, " << countVertices(scene) << " vertices in "
      << items.size() << " drawn meshes\n";

  out << "\nmaterials (" << scene.materials.size() << "):\n";
  if (scene.materials.empty()) out << "  (none: every mesh uses the default material)\n";
  for (const Material& m : scene.materials) {
    out << "  " << m.name << ": ka " << text(m.ka) << ", kd " << text(m.kd) << ", ks " << text(m.ks)
        << ", shininess " << num(m.shininess) << "; maps: " << mapsText(m) << "\n";
  }

  if (scene.environment) {
    const Environment& e = *scene.environment;
    if (e.capture) {
      out << "\nenvironment: captured from node \"" << e.capture->node << "\" by each renderer before each frame, "
          << e.capture->size << "x" << e.capture->size << " per face, " << levelCountOfSide(e.capture->size)
          << " levels, intensity " << num(e.intensity) << (e.background ? ", drawn as the sky box" : ", no sky box")
          << "\n";
      if (e.parameterization != EnvironmentParameterization::Cube) {
        out << "  read as a " << toString(e.parameterization) << " map built from each capture at " << e.size << "x"
            << e.size << "\n";
      }
    } else {
      out << "\nenvironment: " << (e.equirectPath.empty() ? "cube faces from " + e.facePaths[0] + " ..." : "equirect " + e.equirectPath)
          << ", " << (e.cube ? e.cube->size() : 0) << "x" << (e.cube ? e.cube->size() : 0) << " per face, "
          << (e.cube ? e.cube->levelCount() : 0) << " levels, intensity " << num(e.intensity)
          << (e.background ? ", drawn as the sky box" : ", no sky box") << "\n";
    }
    if (e.layers) {
      out << "  read as a " << toString(e.parameterization) << " map built from the cube: " << e.layers->layers << " x "
          << e.layers->size() << "x" << e.layers->size() << ", " << e.layers->levelCount() << " levels\n";
    }
    if (e.irradiance) {
      out << "  diffuse light: irradiance cube " << e.irradiance->size() << "x" << e.irradiance->size() << " per face"
          << (e.irradianceLayers ? ", read from its " + std::string(toString(e.parameterization)) + " map" : std::string())
          << "\n";
    }
    if (e.sh9) out << "  diffuse light: nine SH coefficients per channel\n";
    if (e.specular) {
      out << "  glossy reflection: prefiltered cube " << e.specular->size() << "x" << e.specular->size() << " per face, "
          << e.specular->levelCount() << " levels, a Phong lobe each (level 0: exponent "
          << num(static_cast<float>(specularExponentOfSide(e.specular->size()))) << ")"
          << (e.specularLayers ? ", read from its " + std::string(toString(e.parameterization)) + " map" : std::string())
          << "\n";
    }
    for (const Material& m : scene.materials) {
      if (!readsEnvironment(m, scene)) continue;
      out << "  " << m.name << ": " << toString(m.environmentSpecular) << ", reflectivity " << num(m.reflectivity)
          << ", fresnel " << toString(m.fresnel)
          << (m.refractionIndex > 0.0f ? ", refraction_index " + num(m.refractionIndex) : std::string())
          << (m.environmentDiffuse != EnvironmentDiffuse::None ? ", diffuse " + std::string(toString(m.environmentDiffuse))
                                                               : std::string())
          << (m.environmentSpecular == EnvironmentSpecular::Prefiltered && e.specular
                  ? ", shininess " + num(m.shininess) + " reads LOD " +
                        num(static_cast<float>(specularLodFromShininess(*e.specular, m.shininess)))
                  : std::string())
          << "\n";
    }
  }

  out << "\nlights (" << scene.lights.size() << "), ambient " << text(scene.ambient) << ":\n";
  if (scene.lights.empty()) out << "  (none: only ambient light)\n";
  for (std::size_t i = 0; i < scene.lights.size(); ++i) {
    const Light& l = scene.lights[i];
    if (l.type == LightType::Directional) {
      out << "  [" << i << "] directional, direction " << text(l.directionWorld) << ", diffuse " << text(l.diffuse)
          << ", specular " << text(l.specular) << ", unattenuated\n";
    } else {
      out << "  [" << i << "] position " << text(l.posWorld) << ", diffuse " << text(l.diffuse) << ", specular "
          << text(l.specular) << ", attenuation " << text(l.attenuation) << "\n";
      if (isSpotLight(l)) {
        out << "      spot: axis " << text(l.spot->directionWorld) << ", full within " << l.spot->innerDeg
            << " deg, none beyond " << l.spot->outerDeg << " deg\n";
      }
    }
    if (l.shadow) {
      const ShadowDesc& d = *l.shadow;
      const bool cube = l.type == LightType::Point && !isSpotLight(l);
      out << "      shadow map: "
          << (l.type == LightType::Directional ? "orthographic " : cube ? "cube " : "perspective (the spot's cone) ")
          << d.size << "^2" << (cube ? " x 6" : "") << ", bias " << d.bias.x << " world units + "
          << d.bias.y << " texels of slope, pcf " << d.pcf << "x" << d.pcf << ", extent "
          << (d.extent > 0.0f ? std::to_string(d.extent) + " world units" : std::string("from the scene's bounds"))
          << "\n";
    }
  }

  std::string clipOff;
  const std::pair<const char*, bool> planes[] = {{"left", s.clip.left}, {"right", s.clip.right},
                                                 {"bottom", s.clip.bottom}, {"top", s.clip.top},
                                                 {"near", s.clip.near}, {"far", s.clip.far}};
  for (const auto& [name, on] : planes) {
    if (!on) clipOff += std::string(clipOff.empty() ? "" : " ") + name;
  }
  out << "\nsettings:\n"
      << "  cull " << toString(s.cull) << ", front_face " << toString(s.frontFace) << "\n"
      << "  clip: " << (clipOff.empty() ? "all six frustum planes on" : "off: " + clipOff) << "; "
      << s.userClipPlanes.size() << " user clip planes\n";
  for (const vec4& p : s.userClipPlanes) {
    out << "    " << num(p.x) << " x + " << num(p.y) << " y + " << num(p.z) << " z + " << num(p.w) << " >= 0\n";
  }
  out << "  view " << toString(s.view) << ", pipeline " << toString(s.pipeline)
      << (drawsDeferred(s) ? " (drawn deferred, position " + std::string(toString(s.gbufferPosition)) + ")" : "")
      << ", lighting_space "
      << toString(s.lightingSpace) << ", tangent_transform "
      << toString(s.tangentTransform) << ", texture_filter " << toString(s.textureFilter) << ", interpolation "
      << toString(s.interpolation) << "\n"
      << "  ssr " << (s.ssr.enabled ? "on, " + std::string(toString(s.ssr.march)) + ", max_steps " +
                                          std::to_string(s.ssr.maxSteps) + ", step " + num(s.ssr.step) +
                                          ", thickness " + num(s.ssr.thickness) + ", reflect_strength " +
                                          num(s.ssr.reflectStrength) +
                                          (s.ssr.indirectSamples > 0
                                               ? ", indirect_samples " + std::to_string(s.ssr.indirectSamples) +
                                                     " (" + std::string(toString(s.ssr.sampleDistribution)) + ")"
                                               : std::string(", no indirect light"))
                                    : std::string("off"))
      << "\n"
      << "  tbn_lines " << (s.tbnLines.enabled ? "on" : "off") << ", length " << num(s.tbnLines.length) << ", mode "
      << toString(s.tbnLines.mode) << "\n";
}

}  // namespace twr
