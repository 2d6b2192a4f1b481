// The scene graph both renderers draw: nodes with TRS transforms, meshes, materials,
// point lights, one camera, render settings.
#pragma once

#include "scene/camera.h"
#include "scene/conventions.h"
#include "scene/environment.h"
#include "scene/mesh.h"
#include "scene/settings.h"
#include "scene/shadow_map.h"
#include "scene/texture.h"

#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace twr {

// Largest colour component a scene may give (inclusive; ambient, ka, kd, ks, light diffuse and
// specular; unitless, 1 = full intensity). Bounds every shading product, so no sum of terms
// overflows to Inf and no Inf * 0 makes a NaN.
inline constexpr float kMaxColourValue = 1e4f;

// Height-field defaults and bounds (docs/parallax.md). Depth in texture-space units (uv units);
// layer and step counts inclusive.
inline constexpr float kDefaultHeightScale = 0.05f;
inline constexpr float kMaxHeightScale = 1.0f;
inline constexpr int kMaxParallaxLayers = 256;
inline constexpr int kMaxReliefRefinementSteps = 16;
inline constexpr int kMinHorizonDirections = 4;
inline constexpr int kMaxHorizonDirections = 16;

// Largest refraction_index (n1 / n2, unitless, inclusive): diamond to air is 2.42.
inline constexpr float kMaxRefractionIndex = 4.0f;

struct HorizonMap;  // scene/horizon_map.h

struct Material {
  std::string name;
  vec3 ka{1.0f};  // ambient reflectance (scaled by the diffuse map, see docs/shading.md)
  vec3 kd{1.0f};  // diffuse reflectance (scaled by the diffuse map)
  vec3 ks{0.0f};  // specular reflectance (scaled by the specular map)
  float shininess = 32.0f;  // Phong exponent, >= 0
  // Optional maps; null when the material does not use the feature, so both renderers
  // compile that path out.
  std::shared_ptr<const Texture> diffuseMap;
  std::shared_ptr<const Texture> normalMap;
  std::shared_ptr<const Texture> specularMap;
  // A height map (grey, or the red channel; 1 = top) and how it is drawn (docs/parallax.md).
  // heightScale: depth of the relief in texture-space units (1 = the length of one uv unit
  // along the surface); the polygon lies at the top (height 1), height 0 lies heightScale below.
  std::shared_ptr<const Texture> heightMap;
  float heightScale = kDefaultHeightScale;
  // Default: normal_map when a normal map is given, else bump_blinn when a height map is.
  SurfaceDetail surfaceDetail = SurfaceDetail::NormalMap;
  // Layer counts of the marching methods, [min, max], interpolated by view angle (max at
  // grazing views); both in [1, kMaxParallaxLayers].
  ivec2 parallaxLayers{8, 32};
  int reliefRefinementSteps = 5;  // binary-search steps of relief, in [0, kMaxReliefRefinementSteps]
  SelfShadow selfShadow = SelfShadow::None;
  int horizonDirections = 8;  // horizon_map: azimuths, in [kMinHorizonDirections, kMaxHorizonDirections]
  // Built at load from heightMap when selfShadow is HorizonMap (scene/horizon_map.h).
  std::shared_ptr<const HorizonMap> horizonMap;
  // Tangent-space normal strength: the mapped normal's x and y are scaled by this before
  // normalising (the MTL's -bm on a normal map; 1 leaves the map as it is).
  float normalStrength = 1.0f;
  // The environment on this surface (docs/environment.md); drawn only when the scene has one.
  // reflectivity: the reflected share with fresnel none, Schlick's F0 with fresnel schlick
  // (unitless, [0, 1]). refractionIndex: n1 / n2 for Snell's law (1 / 1.33 enters water from
  // air), 0 = no refraction. With refraction the refracted environment stands where the Phong
  // colour stood (glass shows what is behind it).
  float reflectivity = 0.0f;
  float refractionIndex = 0.0f;
  // The share of the screen-space reflection this surface adds (docs/ssr.md), [0, 1]; drawn
  // only with settings.ssr on.
  float ssrReflect = 0.0f;
  Fresnel fresnel = Fresnel::None;
  EnvironmentSpecular environmentSpecular = EnvironmentSpecular::None;
  EnvironmentDiffuse environmentDiffuse = EnvironmentDiffuse::None;
};

// A point light shines from posWorld and fades with distance; a directional light (the sun,
// the GAMES202 write-up's light) shines along directionWorld from infinitely far, unattenuated.
enum class LightType { Point, Directional };

// A point light's spot cone (the scene file's "spot"): the light shines only within outerDeg
// of the cone's axis, at full strength within innerDeg, and between the two its strength
// falls with smoothstep(cos outer, cos inner, cos angle). Half-angles in degrees,
// 0 <= innerDeg <= outerDeg, kMinSpotOuterDeg <= outerDeg < kMaxSpotOuterDeg; a shadowed spot light gets one perspective map
// covering the cone (scene/shadow_map.h) instead of a cube map.
inline constexpr float kMaxSpotOuterDeg = 89.0f;
// The narrowest outer half-angle (degrees): below about 0.02 its cosine rounds to 1 in float
// and the cone would light nothing.
inline constexpr float kMinSpotOuterDeg = 0.1f;
struct SpotCone {
  vec3 directionWorld{0.0f, -1.0f, 0.0f};  // the cone's axis, the way the light shines, unit length
  float innerDeg = 20.0f;
  float outerDeg = 30.0f;
};

struct Light {
  vec3 posWorld{2.0f, 3.0f, 4.0f};  // point: where it is, world units
  vec3 diffuse{1.0f};               // Id
  vec3 specular{1.0f};              // Is
  // If = 1 / (A_C + A_L d + A_Q d^2), d in world units (point lights; a directional one's is 1).
  vec3 attenuation{1.0f, 0.09f, 0.032f};
  LightType type = LightType::Point;       // last, so {position, Id, Is, attenuation} still makes a point light
  vec3 directionWorld{0.0f, -1.0f, 0.0f};  // directional: the way its light travels, unit length
  // Its shadow map (scene/shadow_map.h): none unless the scene file gives "shadow".
  std::optional<ShadowDesc> shadow;
  // A point light's cone; none: it shines every way.
  std::optional<SpotCone> spot;
};

// Whether a light is a spot light (a point light with a cone).
inline bool isSpotLight(const Light& light) { return light.type == LightType::Point && light.spot.has_value(); }
// A spot cone's cosines: (cos outerDeg, cos innerDeg), computed in double and rounded once.
vec2 spotCosines(const SpotCone& spot);
// The smallest cos inner - cos outer the falloff divides by (unitless): inner == outer is a
// hard-edged cone.
inline constexpr float kMinSpotCosineRange = 1e-6f;
// A light's cone as both renderers' shaders take it (shaders/lighting.glsl's LightUniform):
// axis (the cone's axis, 1) for a spot light, w 0 for any other (then nothing else is read);
// cone (cos outer, max(cos inner - cos outer, kMinSpotCosineRange)).
struct SpotUniform {
  vec4 axis{0.0f};
  vec2 cone{-1.0f, 1.0f};
};
SpotUniform spotUniformOf(const Light& light);

// The light as both renderers' shaders take it, one vec4 for either type:
//   point:        (posWorld, 1)
//   directional:  (-directionWorld, 0)
// so that the vector from a point P to the light is xyz - w P for both (1 P and 0 P are exact:
// a point light's vector has the bits it had before directional lights existed).
vec4 lightVectorWorld(const Light& light);
// The attenuation both renderers use: the light's, or (1, 0, 0) for a directional light, which
// makes 1 / (1 + 0 d + 0 d^2) exactly 1 (its d, the length of a unit vector, is finite).
vec3 attenuationUsed(const Light& light);

struct OutputDesc {
  int width = 640;   // pixels
  int height = 480;  // pixels
  // Written where no triangle is drawn: linear RGB and alpha, each in [0, 1]. Alpha 1 gives
  // opaque images, 0 transparent ones; either way coverage comes from the triangle ids
  // (RenderOutput), never from alpha.
  vec4 background{0.05f, 0.05f, 0.08f, 1.0f};
  // The scene is meant to draw nothing (a test of clipping or culling): no warning for an empty
  // frame, and `compare --targets` passes it (compare/empty_frame.h).
  bool expectEmpty = false;
};

struct Node {
  std::string name;
  vec3 translate{0.0f};
  vec3 rotateDeg{0.0f};  // applied X, then Y, then Z (right-handed), degrees
  vec3 scale{1.0f};
  int meshIndex = -1;      // into Scene::meshes, -1 for none
  int materialIndex = -1;  // into Scene::materials, -1 for the default material
  std::vector<Node> children;
};

struct Scene {
  std::string sourcePath;  // the scene file, empty when built in code
  OutputDesc output;
  Camera camera;
  vec3 ambient{0.1f};  // Ia
  std::vector<Light> lights;
  std::vector<Material> materials;
  std::vector<MeshDesc> meshDescs;  // parallel to meshes
  std::vector<Mesh> meshes;
  std::vector<Node> nodes;  // roots
  RenderSettings settings;
  // What surrounds the scene (the scene file's "environment"); none when absent, and then no
  // renderer reads or pays for anything of it.
  std::optional<Environment> environment;
  // What was read and ignored, or read another way than asked: one line each, naming the
  // file (and line or key). The CLI prints each as "warning: ..." on stderr; the GUI lists them.
  std::vector<std::string> warnings;
};

// parentFromNode = T * Rz * Ry * Rx * S (so X rotates first, then Y, then Z).
mat4 localFromNodeTrs(const vec3& translate, const vec3& rotateDeg, const vec3& scale);

// One mesh instance ready to draw: the flattened scene graph.
struct DrawItem {
  const Mesh* mesh = nullptr;
  const Material* material = nullptr;  // never null (default material when unset)
  mat4 worldFromModel{1.0f};
  std::string nodeName;
  std::uint32_t firstTriangleId = 0;  // triangle ids are global across the draw list, from 0
};

// Depth-first, parents before children, in file order. worldFromModel = parent * child.
std::vector<DrawItem> flattenScene(const Scene& scene);

// The material used when a node names none: white diffuse, no maps.
const Material& defaultMaterial();

std::size_t countTriangles(const Scene& scene);
std::size_t countVertices(const Scene& scene);

}  // namespace twr
