#include "report/height_fields.h"

#include "scene/height_field.h"
#include "scene/primitives.h"
#include "scene/texture.h"

#include <cmath>
#include <cstdio>

namespace twr::report {

namespace {

constexpr float kPlaneSide = 2.0f;       // world units
constexpr float kPlaneUvScale = 1.0f;    // one copy of the texture across the plane
constexpr float kSpinDeg = 30.0f;        // about the plane's normal, before the tilt
constexpr float kCameraDistance = 2.4f;  // world units from the plane's centre
constexpr float kFovDeg = 45.0f;         // vertical
constexpr float kNear = 0.05f, kFar = 10.0f;  // world units
// The light in the plane's own frame (normal +Y), world units: 42 degrees from the normal.
const glm::vec3 kLightInPlane{0.6f, 1.2f, 0.9f};
constexpr float kAmbient = 0.12f;  // ambient light, linear RGB (grey)
// Transparent background: the supersampled reference then holds its coverage in alpha, which
// compareInterior uses to leave its edge pixels out (compare/interior.h).
const glm::vec4 kBackground{0.05f, 0.05f, 0.08f, 0.0f};

// Everything but the surface: camera, light, settings, and the two nodes (a parent that tilts,
// a child that spins and holds the mesh).
Scene viewScene(int angleDeg) {
  Scene scene;
  scene.camera.position = vec3(0.0f, 0.0f, kCameraDistance);
  scene.camera.target = vec3(0.0f);
  scene.camera.fovDeg = kFovDeg;
  scene.camera.near = kNear;
  scene.camera.far = kFar;
  scene.ambient = vec3(kAmbient);
  scene.output.background = kBackground;
  scene.settings.textureFilter = TextureFilter::Trilinear;
  // The plane's normal +Y, tilted about X by 90 - angle, becomes (0, sin a, cos a): `angle`
  // from the direction to the camera (+Z).
  const float tiltDeg = 90.0f - static_cast<float>(angleDeg);
  Node tilt;
  tilt.name = "tilt";
  tilt.rotateDeg = vec3(tiltDeg, 0.0f, 0.0f);
  Node surface;
  surface.name = "surface";
  surface.rotateDeg = vec3(0.0f, kSpinDeg, 0.0f);
  surface.meshIndex = 0;
  surface.materialIndex = 0;
  tilt.children.push_back(surface);
  scene.nodes.push_back(tilt);
  const mat4 worldFromPlane = localFromNodeTrs(vec3(0.0f), tilt.rotateDeg, vec3(1.0f)) *
                              localFromNodeTrs(vec3(0.0f), surface.rotateDeg, vec3(1.0f));
  Light light;
  light.posWorld = vec3(worldFromPlane * glm::vec4(kLightInPlane, 1.0f));
  light.attenuation = vec3(1.0f, 0.0f, 0.0f);  // no fall-off: the same light at every angle
  scene.lights.push_back(light);
  return scene;
}

Material surfaceMaterial(const HeightFieldAsset& asset) {
  Material m;
  m.name = asset.name;
  m.ka = vec3(1.0f);
  m.kd = vec3(1.0f);
  m.ks = vec3(0.0f);
  m.diffuseMap = asset.diffuse;
  return m;
}

}  // namespace

HeightFieldAsset loadHeightFieldAsset(const std::string& assetsDir, const std::string& name) {
  HeightFieldAsset a;
  a.name = name;
  const std::string stem = assetsDir + "/textures/" + name;
  a.diffuse = std::make_shared<const Texture>(loadTexture(stem + "_diffuse.png"));
  auto height = std::make_shared<const Texture>(loadTexture(stem + "_height.png"));
  a.normal = std::make_shared<const Texture>(normalMapFromHeight(*height, kHeightFieldScale));
  a.height = std::move(height);
  return a;
}

std::string heightFieldViewText() {
  const auto number = [](double v) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%g", v);
    return std::string(buffer);
  };
  const double lightFromNormalDeg = glm::degrees(std::acos(glm::normalize(kLightInPlane).y));
  return "a " + number(kPlaneSide) + " x " + number(kPlaneSide) + " plane, uv from 0 to " + number(kPlaneUvScale) +
         " across, turned " + number(kSpinDeg) + " degrees about its normal, seen from " +
         number(kCameraDistance) + " units (vertical field of view " + number(kFovDeg) +
         " degrees); one point light fixed to the plane, " + number(std::round(lightFromNormalDeg)) +
         " degrees from its normal, no fall-off; diffuse only";
}

std::string methodSetting(const HeightFieldMethod& m) {
  std::string s(toString(m.method));
  if (marchesLayers(m.method)) {
    s += ' ';
    s += std::to_string(m.layers.x);
    s += '-';
    s += std::to_string(m.layers.y);
  }
  return s;
}

Scene heightFieldPlaneScene(const HeightFieldAsset& asset, int angleDeg, const HeightFieldMethod& method) {
  Scene scene = viewScene(angleDeg);
  Material m = surfaceMaterial(asset);
  m.heightMap = asset.height;
  m.normalMap = asset.normal;
  m.heightScale = kHeightFieldScale;
  m.surfaceDetail = method.method;
  m.parallaxLayers = method.layers;
  m.selfShadow = SelfShadow::None;
  scene.materials.push_back(m);
  MeshDesc desc;
  desc.type = MeshType::Plane;
  desc.planeSize = vec2(kPlaneSide);
  desc.uvScale = kPlaneUvScale;
  scene.meshDescs.push_back(desc);
  scene.meshes.push_back(makePlane(desc.planeSize, desc.uvScale));
  return scene;
}

Mesh heightFieldMesh(const HeightFieldAsset& asset) {
  return makeHeightfield(vec2(kPlaneSide), kPlaneUvScale, *asset.height, kHeightFieldScale,
                         defaultHeightfieldSegments(*asset.height, kPlaneUvScale));
}

Scene heightFieldMeshScene(const HeightFieldAsset& asset, const Mesh& mesh, int angleDeg) {
  Scene scene = viewScene(angleDeg);
  scene.materials.push_back(surfaceMaterial(asset));
  MeshDesc desc;
  desc.type = MeshType::Heightfield;
  desc.planeSize = vec2(kPlaneSide);
  desc.uvScale = kPlaneUvScale;
  desc.heightMap = asset.height;
  desc.heightScale = kHeightFieldScale;
  scene.meshDescs.push_back(desc);
  scene.meshes.push_back(mesh);
  return scene;
}

}  // namespace twr::report
