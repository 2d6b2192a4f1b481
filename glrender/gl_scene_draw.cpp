#include "glrender/gl_scene_draw.h"

#include "glrender/model_transforms.h"
#include "scene/environment_light.h"
#include "scene/environment_specular.h"
#include "scene/errors.h"
#include "scene/horizon_map.h"
#include "scene/surface_detail.h"
#include "scene/sky_view.h"

#include <algorithm>
#include <map>
#include <mutex>
#include <tuple>
#include <array>
#include <cctype>
#include <cmath>

namespace twr {
namespace {

// Texture units of the material maps.
constexpr GLint kDiffuseUnit = 0;
constexpr GLint kNormalUnit = 1;
constexpr GLint kSpecularUnit = 2;
constexpr GLint kHeightUnit = 3;
constexpr GLint kFirstHorizonUnit = 4;  // 4 to 7: one per 4 horizon azimuths
constexpr GLint kEnvironmentUnit = 8;   // the environment's cube map
constexpr GLint kIrradianceUnit = 9;    // its irradiance map (environment_diffuse irradiance_map)
constexpr GLint kGlossyUnit = 10;       // its prefiltered glossy map (environment_specular prefiltered)
constexpr GLint kLodStandInUnit = 11;   // the env_lod view's stand-in for the environment's map

// The env_lod view's stand-in for the map `environment` is read from (environment_map.glsl's
// environmentReadLod): the same size, layers and levels, level l holding l in every texel, so
// a read returns the LOD the sampler chose, clamped and blended. Built once per shape, kept
// for the process (a 1024-texel cube's is 100 MB; the view is a teaching aid).
void bindLodStandIn(GlUploadCache& uploads, const Environment& environment) {
  static std::mutex mutex;
  static std::map<std::tuple<int, int, int>, std::shared_ptr<const CubeMap>> cubes;
  static std::map<std::tuple<int, int, int>, std::shared_ptr<const ParameterizedMap>> maps;
  const std::lock_guard<std::mutex> lock(mutex);
  const auto filled = [](int size, int faces, int levels) {
    std::vector<CubeMapLevel> chain;
    for (int l = 0; l < levels; ++l) {
      CubeMapLevel level;
      level.size = std::max(1, size >> l);
      const std::size_t texels = static_cast<std::size_t>(faces) * static_cast<std::size_t>(level.size) *
                                 static_cast<std::size_t>(level.size);
      level.r.assign(texels, static_cast<float>(l));
      level.g = level.b = level.r;
      chain.push_back(std::move(level));
    }
    return chain;
  };
  if (environment.layers) {
    const ParameterizedMap& m = *environment.layers;
    auto& standIn = maps[{m.size(), m.layers, m.levelCount()}];
    if (!standIn) {
      auto made = std::make_shared<ParameterizedMap>();
      made->kind = m.kind;
      made->layers = m.layers;
      made->levels = filled(m.size(), m.layers, m.levelCount());
      standIn = std::move(made);
    }
    uploads.environmentLayers(standIn);
    return;
  }
  const CubeMap& c = *environment.cube;
  auto& standIn = cubes[{c.size(), kCubeFaces, c.levelCount()}];
  if (!standIn) {
    auto made = std::make_shared<CubeMap>();
    made->source = "env_lod stand-in";
    made->levels = filled(c.size(), kCubeFaces, c.levelCount());
    standIn = std::move(made);
  }
  uploads.cubeMap(standIn);
}

// The environment's texture on the active unit: the cube, or the sphere or paraboloid map.
void bindEnvironment(GlUploadCache& uploads, const Environment& environment) {
  if (environment.layers) {
    uploads.environmentLayers(environment.layers);
  } else {
    uploads.cubeMap(environment.cube);
  }
}

// An environment, shadow or Phong-term view's defines (environment_map.glsl, shadow.glsl,
// phong.frag), none for other views.
std::vector<std::string> environmentViewDefines(View view) {
  switch (view) {
    case View::ReflectDir: return {"ENVIRONMENT_VIEW", "ENVIRONMENT_VIEW_REFLECT_DIR"};
    case View::EnvFace: return {"ENVIRONMENT_VIEW", "ENVIRONMENT_VIEW_FACE"};
    case View::EnvLod: return {"ENVIRONMENT_VIEW", "ENVIRONMENT_VIEW_LOD"};
    case View::Shadow: return {"SHADOW_VIEW_SHADOW"};
    case View::LightDepth: return {"SHADOW_VIEW_LIGHT_DEPTH"};
    case View::Ambient: return {"PHONG_TERM_VIEW", "PHONG_TERM_VIEW_AMBIENT"};
    case View::Diffuse: return {"PHONG_TERM_VIEW", "PHONG_TERM_VIEW_DIFFUSE"};
    case View::Specular: return {"PHONG_TERM_VIEW", "PHONG_TERM_VIEW_SPECULAR"};
    default: return {};
  }
}

// The sky program's defines: the environment is always read.
std::vector<std::string> skyDefines(const Environment& environment, View view) {
  std::vector<std::string> defines{"HAS_ENVIRONMENT"};
  for (std::string& d : environmentMapDefines(environment)) defines.push_back(std::move(d));
  for (std::string& d : environmentViewDefines(view)) defines.push_back(std::move(d));
  return defines;
}

// A map without texels is treated as absent, as the CPU does (softrender/shade.cpp).
bool usableMap(const std::shared_ptr<const Texture>& map) {
  return map && map->width > 0 && map->height > 0 && !map->rgba.empty();
}

// Whether a usable map is read at a transformed uv (phong.frag's <MAP>_UV_TRANSFORM).
bool hasUvTransform(const std::shared_ptr<const Texture>& map) {
  return usableMap(map) && (map->options.uvScale != vec2(1.0f) || map->options.uvOffset != vec2(0.0f));
}

// GL does not check indices; one past the vertex array would read outside the buffer.
void checkIndices(const Mesh& mesh, const std::string& nodeName) {
  const std::uint32_t vertexCount = static_cast<std::uint32_t>(mesh.vertices.size());
  for (std::uint32_t index : mesh.indices) {
    if (index >= vertexCount) {
      throw InputError("GL: mesh of node '" + nodeName + "' has vertex index " + std::to_string(index) +
                       ", expected below its vertex count " + std::to_string(vertexCount));
    }
  }
  if (mesh.indices.size() % 3 != 0) {
    throw InputError("GL: mesh of node '" + nodeName + "' has " + std::to_string(mesh.indices.size()) +
                     " indices, expected a multiple of 3");
  }
}

std::string viewDefine(View view) {
  // mip_level is drawn as albedo of stand-in textures (scene/mip_level_view.h).
  // The environment, shadow and term views are the shaded program with their defines
  // (environmentViewDefines).
  std::string name(toString(view == View::MipLevel                       ? View::Albedo
                            : isShadedView(view) || isSsrView(view) ? View::Shaded
                                                                     : view));
  std::transform(name.begin(), name.end(), name.begin(),
                 [](unsigned char c) { return static_cast<char>(std::toupper(c)); });
  return "VIEW_" + name;
}

void applyPipelineState(const RenderSettings& settings) {
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glDepthMask(GL_TRUE);
  glDisable(GL_BLEND);
  // The scissor is the caller's: none for a frame, one pixel for renderGlPixel.
  glDisable(GL_STENCIL_TEST);
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
  // Cube maps filter across face edges, as the CPU does (softrender/cube_sample-inl.h); off by
  // default in a core context.
  glEnable(GL_TEXTURE_CUBE_MAP_SEAMLESS);
  applyFaceCulling(settings);
}

}  // namespace

void setLightUniforms(GLuint program, const Scene& scene) {
  glUniform3fv(uniformLocation(program, "eyePosWorld"), 1, &scene.camera.position.x);
  // The vertex stage reads lightVectorWorld[], the fragment stage lights[] (as the C++
  // VertexUniforms and ShadeUniforms do): each light as lightVectorWorld gives it, a point
  // light's position with w 1, a directional light's direction towards it with w 0.
  std::vector<vec4> lightVectors;
  for (const Light& light : scene.lights) lightVectors.push_back(lightVectorWorld(light));
  const GLsizei lightCount = static_cast<GLsizei>(scene.lights.size());
  glUniform1i(uniformLocation(program, "lightCount"), lightCount);
  if (lightCount > 0) glUniform4fv(uniformLocation(program, "lightVectorWorld"), lightCount, &lightVectors[0].x);
  for (std::size_t i = 0; i < scene.lights.size(); ++i) {
    const Light& light = scene.lights[i];
    const std::string prefix = "lights[" + std::to_string(i) + "].";
    const vec3 attenuation = attenuationUsed(light);
    glUniform4fv(uniformLocation(program, (prefix + "vectorWorld").c_str()), 1, &lightVectors[i].x);
    glUniform3fv(uniformLocation(program, (prefix + "diffuse").c_str()), 1, &light.diffuse.x);
    glUniform3fv(uniformLocation(program, (prefix + "specular").c_str()), 1, &light.specular.x);
    glUniform3fv(uniformLocation(program, (prefix + "attenuation").c_str()), 1, &attenuation.x);
    const SpotUniform spot = spotUniformOf(light);
    glUniform4fv(uniformLocation(program, (prefix + "spotAxis").c_str()), 1, &spot.axis.x);
    glUniform2fv(uniformLocation(program, (prefix + "spotCone").c_str()), 1, &spot.cone.x);
  }
}

namespace {

void setUniforms(GLuint program, const Scene& scene, const RenderSettings& settings, const GlClipState& clipState,
                 const DrawItem& item, const mat4& clipFromWorld) {
  const ModelTransforms transforms = makeModelTransforms(item.worldFromModel, settings.tangentTransform);
  glUniformMatrix4fv(uniformLocation(program, "worldFromModel"), 1, GL_FALSE, &transforms.worldFromModel[0][0]);
  glUniformMatrix4fv(uniformLocation(program, "clipFromWorld"), 1, GL_FALSE, &clipFromWorld[0][0]);
  glUniformMatrix3fv(uniformLocation(program, "normalFromModel"), 1, GL_FALSE, &transforms.normalFromModel[0][0]);
  glUniformMatrix3fv(uniformLocation(program, "tangentFromModel"), 1, GL_FALSE,
                     &transforms.tangentFromModel[0][0]);
  glUniform1f(uniformLocation(program, "mirrorSign"), transforms.mirrorSign);
  setLightUniforms(program, scene);
  setGlClipUniforms(program, clipState, settings.userClipPlanes);

  const Material& material = *item.material;
  glUniform3fv(uniformLocation(program, "ka"), 1, &material.ka.x);
  glUniform3fv(uniformLocation(program, "kd"), 1, &material.kd.x);
  glUniform3fv(uniformLocation(program, "ks"), 1, &material.ks.x);
  glUniform1f(uniformLocation(program, "shininess"), std::fmax(material.shininess, 0.0f));
  glUniform1f(uniformLocation(program, "ssrReflect"), material.ssrReflect);
  glUniform3fv(uniformLocation(program, "ambient"), 1, &scene.ambient.x);
  glUniform1ui(uniformLocation(program, "firstTriangleId"), item.firstTriangleId);
  glUniform1i(uniformLocation(program, "diffuseMap"), kDiffuseUnit);
  glUniform1i(uniformLocation(program, "normalMap"), kNormalUnit);
  glUniform1i(uniformLocation(program, "specularMap"), kSpecularUnit);
  // Only the permutation that declares them has these (-1 otherwise, which GL ignores).
  glUniform1f(uniformLocation(program, "normalStrength"), material.normalStrength);
  const auto uvTransform = [&](const std::shared_ptr<const Texture>& map, const char* scale, const char* offset) {
    if (!hasUvTransform(map)) return;
    glUniform2fv(uniformLocation(program, scale), 1, &map->options.uvScale.x);
    glUniform2fv(uniformLocation(program, offset), 1, &map->options.uvOffset.x);
  };
  uvTransform(material.diffuseMap, "diffuseUvScale", "diffuseUvOffset");
  uvTransform(material.normalMap, "normalUvScale", "normalUvOffset");
  uvTransform(material.specularMap, "specularUvScale", "specularUvOffset");

  const SurfaceDetailUse use = surfaceDetailUse(material, settings);
  if (use.heightMap) {
    const Texture& height = *material.heightMap;
    glUniform1i(uniformLocation(program, "heightMap"), kHeightUnit);
    glUniform1f(uniformLocation(program, "heightScale"), material.heightScale);
    // The same float divisions as softrender/shade.cpp's uniforms.
    const vec2 texel(1.0f / static_cast<float>(height.width), 1.0f / static_cast<float>(height.height));
    glUniform2fv(uniformLocation(program, "heightTexel"), 1, &texel.x);
    glUniform1f(uniformLocation(program, "layersMin"), static_cast<float>(material.parallaxLayers.x));
    glUniform1f(uniformLocation(program, "layersMax"), static_cast<float>(material.parallaxLayers.y));
    glUniform1i(uniformLocation(program, "layerCap"), material.parallaxLayers.y);
    glUniform1i(uniformLocation(program, "refinementSteps"),
                use.method == SurfaceDetail::Relief ? material.reliefRefinementSteps : 0);
    for (int k = 0; k < 4; ++k) {
      glUniform1i(uniformLocation(program, ("horizonMap" + std::to_string(k)).c_str()), kFirstHorizonUnit + k);
    }
  }
  if (materialReadsEnvironment(material, scene)) {
    glUniform1i(uniformLocation(program, scene.environment->layers ? "environmentLayers" : "environmentMap"),
                kEnvironmentUnit);
    glUniform1f(uniformLocation(program, "environmentIntensity"), scene.environment->intensity);
    glUniform1f(uniformLocation(program, "reflectivity"), material.reflectivity);
    glUniform1f(uniformLocation(program, "refractionEta"), material.refractionIndex > 0.0f ? material.refractionIndex : 1.0f);
    const Environment& environment = *scene.environment;
    if (settings.view == View::EnvLod) glUniform1i(uniformLocation(program, "environmentLodStandIn"), kLodStandInUnit);
    if (environmentSpecularOf(material, environment) == EnvironmentSpecular::Prefiltered) {
      glUniform1i(uniformLocation(program, environment.specularLayers ? "environmentSpecularLayers" : "environmentSpecular"),
                  kGlossyUnit);
      // The CPU's uniform: the LOD in double, rounded to float once.
      glUniform1f(uniformLocation(program, "environmentSpecularLod"),
                  static_cast<float>(specularLodFromShininess(*environment.specular, material.shininess)));
    }
    const EnvironmentDiffuse diffuse = environmentDiffuseOf(material, environment);
    if (diffuse == EnvironmentDiffuse::IrradianceMap) {
      glUniform1i(uniformLocation(program, environment.irradianceLayers ? "environmentIrradianceLayers"
                                                                         : "environmentIrradiance"),
                  kIrradianceUnit);
    } else if (diffuse == EnvironmentDiffuse::Sh9) {
      std::array<float, 27> sh{};
      for (std::size_t i = 0; i < 9; ++i) {
        const vec3 c(environment.sh9->c[i]);  // rounded to float as the CPU's uniforms are
        sh[3 * i] = c.x;
        sh[3 * i + 1] = c.y;
        sh[3 * i + 2] = c.z;
      }
      glUniform3fv(uniformLocation(program, "environmentSh9"), 9, sh.data());
    }
  }
}

// The sky box (shaders/sky.*): a full-screen triangle at depth 1 with GL_LEQUAL after the
// scene, into the colour attachment alone (a sky pixel keeps "no triangle"), not counted as
// a shaded sample. The CPU twin is softrender/sky.cpp; the same uniforms (makeSkyUniforms).
void drawSky(ProgramCache& programs, GlUploadCache& uploads, const Scene& scene, const SkyUniformsT<float>& sky) {
  // Saved and restored: what the scene's draws set, for the lines and pixel renders after.
  GLint drawBuffer1 = GL_NONE, depthFunc = GL_LESS;
  GLboolean depthMask = GL_TRUE;
  glGetIntegerv(GL_DRAW_BUFFER1, &drawBuffer1);
  glGetIntegerv(GL_DEPTH_FUNC, &depthFunc);
  glGetBooleanv(GL_DEPTH_WRITEMASK, &depthMask);
  const GLboolean cull = glIsEnabled(GL_CULL_FACE);
  const std::array<GLenum, 2> colourOnly = {GL_COLOR_ATTACHMENT0, GL_NONE};
  glDrawBuffers(2, colourOnly.data());
  glDepthFunc(GL_LEQUAL);
  glDepthMask(GL_FALSE);
  glDisable(GL_CULL_FACE);
  const GLuint program = programs.get(ProgramDesc{"sky",
                                                 {"common.glsl", "sky.vert"},
                                                 {"common.glsl", "environment_map.glsl", "sky.frag"},
                                                 skyDefines(*scene.environment, sky.view)});
  glUseProgram(program);
  glUniform1i(uniformLocation(program, scene.environment->layers ? "environmentLayers" : "environmentMap"),
              kEnvironmentUnit);
  glUniform1f(uniformLocation(program, "environmentIntensity"), sky.intensity);
  glUniform3fv(uniformLocation(program, "skyForward"), 1, &sky.forward.x);
  glUniform3fv(uniformLocation(program, "skyRight"), 1, &sky.right.x);
  glUniform3fv(uniformLocation(program, "skyUp"), 1, &sky.up.x);
  glUniform2fv(uniformLocation(program, "ndcPerPixel"), 1, &sky.ndcPerPixel.x);
  glActiveTexture(static_cast<GLenum>(GL_TEXTURE0 + kEnvironmentUnit));
  bindEnvironment(uploads, *scene.environment);
  if (sky.view == View::EnvLod) {
    glUniform1i(uniformLocation(program, "environmentLodStandIn"), kLodStandInUnit);
    glActiveTexture(static_cast<GLenum>(GL_TEXTURE0 + kLodStandInUnit));
    bindLodStandIn(uploads, *scene.environment);
  }
  GlVertexArray empty = makeGlVertexArray();  // core profile: a draw needs a vertex array
  glBindVertexArray(empty.id());
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glBindVertexArray(0);
  glDepthFunc(static_cast<GLenum>(depthFunc));
  glDepthMask(depthMask);
  if (cull) glEnable(GL_CULL_FACE);
  const std::array<GLenum, 2> restored = {GL_COLOR_ATTACHMENT0, static_cast<GLenum>(drawBuffer1)};
  glDrawBuffers(drawBuffer1 == GL_NONE ? 1 : 2, restored.data());
}

}  // namespace

void applyFaceCulling(const RenderSettings& settings) {
  glFrontFace(settings.frontFace == FrontFace::Ccw ? GL_CCW : GL_CW);
  if (settings.cull == CullMode::None) {
    glDisable(GL_CULL_FACE);
  } else {
    glEnable(GL_CULL_FACE);
    glCullFace(settings.cull == CullMode::Back ? GL_BACK : GL_FRONT);
  }
}

std::vector<std::string> environmentMapDefines(const Environment& environment) {
  std::vector<std::string> defines;
  if (environment.layers && environment.layers->kind == EnvironmentParameterization::Sphere) {
    defines.push_back("ENVIRONMENT_SPHERE");
  } else if (environment.layers) {
    defines.push_back("ENVIRONMENT_DUAL_PARABOLOID");
  }
  return defines;
}

std::vector<std::string> phongDefines(const Material& material, const RenderSettings& settings,
                                      const Environment* environment) {
  std::vector<std::string> defines;
  if (usableMap(material.diffuseMap)) defines.push_back("HAS_DIFFUSE_MAP");
  const SurfaceDetailUse use = surfaceDetailUse(material, settings);
  if (use.normalMap) {
    defines.push_back("HAS_NORMAL_MAP");
    if (material.normalMap->options.green == GreenAxis::Down) defines.push_back("NORMAL_MAP_GREEN_DOWN");
    if (material.normalMap->channels == TextureChannels::RedGreen) defines.push_back("NORMAL_MAP_XY");
    if (material.normalStrength != 1.0f) defines.push_back("NORMAL_MAP_STRENGTH");
  }
  if (usableMap(material.specularMap)) defines.push_back("HAS_SPECULAR_MAP");
  if (hasUvTransform(material.diffuseMap)) defines.push_back("DIFFUSE_UV_TRANSFORM");
  if (use.normalMap && hasUvTransform(material.normalMap)) defines.push_back("NORMAL_UV_TRANSFORM");
  if (hasUvTransform(material.specularMap)) defines.push_back("SPECULAR_UV_TRANSFORM");
  if (settings.lightingSpace == LightingSpace::Tangent) defines.push_back("LIGHTING_TANGENT");
  if (settings.interpolation == Interpolation::Affine) defines.push_back("AFFINE_INTERPOLATION");
  if (use.heightMap) {
    defines.push_back("HAS_HEIGHT_MAP");
    if (use.method != SurfaceDetail::NormalMap) {
      std::string method(toString(use.method));
      std::transform(method.begin(), method.end(), method.begin(),
                     [](unsigned char c) { return static_cast<char>(std::toupper(c)); });
      defines.push_back("SURFACE_" + method);
    }
    if (shiftsUv(use.method)) defines.push_back("PARALLAX_UV");
    if (use.selfShadow != SelfShadow::None) {
      defines.push_back("SELF_SHADOW");
      if (use.selfShadow == SelfShadow::HeightMarch) {
        defines.push_back("SELF_SHADOW_HEIGHT_MARCH");
      } else {
        defines.push_back("SELF_SHADOW_HORIZON_MAP");
        defines.push_back("HORIZON_DIRECTIONS " + std::to_string(use.horizonDirections));
      }
    }
  }
  if (environment) {
    defines.push_back("HAS_ENVIRONMENT");
    const EnvironmentSpecular specular = environmentSpecularOf(material, *environment);
    if (specular != EnvironmentSpecular::None) defines.push_back("ENVIRONMENT_REFLECT");
    if (specular == EnvironmentSpecular::Prefiltered) defines.push_back("ENVIRONMENT_PREFILTERED");
    if (material.refractionIndex > 0.0f) defines.push_back("ENVIRONMENT_REFRACTION");
    if (material.fresnel == Fresnel::Schlick) defines.push_back("FRESNEL_SCHLICK");
    const EnvironmentDiffuse diffuse = environmentDiffuseOf(material, *environment);
    if (diffuse != EnvironmentDiffuse::None) {
      defines.push_back("ENVIRONMENT_DIFFUSE");
      defines.push_back(diffuse == EnvironmentDiffuse::IrradianceMap ? "ENVIRONMENT_IRRADIANCE" : "ENVIRONMENT_SH9");
    }
  }
  defines.push_back(viewDefine(settings.view));
  for (std::string& d : environmentViewDefines(settings.view)) defines.push_back(std::move(d));
  return defines;
}

SceneDrawStats drawScene(ProgramCache& programs, GlUploadCache& uploads, const Scene& scene,
                         const RenderSettings& settings, const GlClipState& clipState,
                         const std::vector<DrawItem>& items, const mat4& clipFromWorld, int width, int height,
                         GlFrame frame, const GlShadowMaps* shadows, const std::function<void()>& gbufferLighting) {
  SceneDrawStats stats;
  const bool countSamples = frame == GlFrame::Full;
  applyPipelineState(settings);
  applyGlClipState(clipState);

  uploads.beginFrame();
  const auto bindMap = [&](const std::shared_ptr<const Texture>& map, GLint unit) {
    if (!usableMap(map)) return;
    // Select the unit first: uploading binds the new texture to the active unit.
    glActiveTexture(static_cast<GLenum>(GL_TEXTURE0 + unit));
    uploads.texture(map, settings.textureFilter, settings.anisotropy);
  };

  GlQuery samples;
  if (countSamples) {
    samples = makeGlQuery();
    glBeginQuery(GL_SAMPLES_PASSED, samples.id());
  }
  for (const DrawItem& item : items) {
    if (item.mesh->indices.empty()) continue;
    checkIndices(*item.mesh, item.nodeName);
    stats.trianglesIn += item.mesh->triangleCount();
    const Material& material = *item.material;
    ProgramDesc desc{"phong",
                     {"common.glsl", "phong.vert"},
                     {"common.glsl", "surface_detail.glsl", "environment_map.glsl", "environment.glsl", "shadow.glsl",
                      "lighting.glsl", "phong.frag"},
                     phongDefines(material, settings, materialReadsEnvironment(material, scene) ? &*scene.environment : nullptr)};
    if (materialReadsEnvironment(material, scene)) {
      for (std::string& d : environmentMapDefines(*scene.environment)) desc.defines.push_back(std::move(d));
    }
    if (frame == GlFrame::Lean) desc.defines.push_back("NO_TRIANGLE_ID");
    if (sceneHasShadows(scene)) desc.defines.push_back("HAS_SHADOWS");
    if (shadows && shadows->probing()) desc.defines.push_back("SHADOW_PROBE");
    if (gbufferLighting) desc.defines.push_back("GBUFFER_PASS");
    if (gbufferLighting && storesGBufferPosition(settings)) desc.defines.push_back("GBUFFER_POSITION");
    const GLuint program = programs.get(desc);
    glUseProgram(program);
    setUniforms(program, scene, settings, clipState, item, clipFromWorld);
    if (shadows) shadows->bind(program);
    bindMap(material.diffuseMap, kDiffuseUnit);
    bindMap(material.normalMap, kNormalUnit);
    bindMap(material.specularMap, kSpecularUnit);
    const SurfaceDetailUse use = surfaceDetailUse(material, settings);
    if (use.heightMap) bindMap(material.heightMap, kHeightUnit);
    for (int k = 0; k < use.horizonDirections / 4; ++k) {
      bindMap(material.horizonMap->textures[static_cast<std::size_t>(k)], kFirstHorizonUnit + k);
    }
    if (materialReadsEnvironment(material, scene)) {
      const Environment& environment = *scene.environment;
      glActiveTexture(static_cast<GLenum>(GL_TEXTURE0 + kEnvironmentUnit));
      bindEnvironment(uploads, environment);
      if (settings.view == View::EnvLod) {
        glActiveTexture(static_cast<GLenum>(GL_TEXTURE0 + kLodStandInUnit));
        bindLodStandIn(uploads, environment);
      }
      if (environmentSpecularOf(material, environment) == EnvironmentSpecular::Prefiltered) {
        glActiveTexture(static_cast<GLenum>(GL_TEXTURE0 + kGlossyUnit));
        if (environment.specularLayers) {
          uploads.environmentLayers(environment.specularLayers);
        } else {
          uploads.cubeMap(environment.specular);
        }
      }
      if (environmentDiffuseOf(material, environment) == EnvironmentDiffuse::IrradianceMap) {
        glActiveTexture(static_cast<GLenum>(GL_TEXTURE0 + kIrradianceUnit));
        if (environment.irradianceLayers) {
          uploads.environmentLayers(environment.irradianceLayers);
        } else {
          uploads.cubeMap(environment.irradiance);
        }
      }
    }
    const GlMesh& mesh = uploads.mesh(*item.mesh);
    glBindVertexArray(mesh.vertexArray.id());
    glDrawElements(GL_TRIANGLES, mesh.indexCount, GL_UNSIGNED_INT, nullptr);
    glBindVertexArray(0);
  }
  if (countSamples) {
    glEndQuery(GL_SAMPLES_PASSED);
    GLuint64 passed = 0;
    glGetQueryObjectui64v(samples.id(), GL_QUERY_RESULT, &passed);
    stats.samplesPassed = passed;
  }
  if (gbufferLighting) gbufferLighting();
  const SkyUniformsT<float> sky = makeSkyUniforms(scene, width, height, settings.view);
  if (sky.cube) drawSky(programs, uploads, scene, sky);
  glActiveTexture(GL_TEXTURE0);
  uploads.endFrame();
  return stats;
}

}  // namespace twr
