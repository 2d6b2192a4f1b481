#include "scene/scene.h"

#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

namespace twr {

mat4 localFromNodeTrs(const vec3& translate, const vec3& rotateDeg, const vec3& scale) {
  // Left to right, skipping the factors that are the identity (a rotation by 0 is exactly
  // the identity, and so is multiplying by it, up to the sign of a zero): most nodes of big
  // scenes rotate about one axis or none, and a scene may hold millions of them.
  const mat4 identity(1.0f);
  mat4 m = glm::translate(identity, translate);
  if (rotateDeg.z != 0.0f) m = m * glm::rotate(identity, degreesToRadians(rotateDeg.z), vec3(0, 0, 1));
  if (rotateDeg.y != 0.0f) m = m * glm::rotate(identity, degreesToRadians(rotateDeg.y), vec3(0, 1, 0));
  if (rotateDeg.x != 0.0f) m = m * glm::rotate(identity, degreesToRadians(rotateDeg.x), vec3(1, 0, 0));
  if (scale != vec3(1.0f)) m = m * glm::scale(identity, scale);
  return m;
}

const Material& defaultMaterial() {
  static const Material material = [] {
    Material m;
    m.name = "default";
    m.ka = vec3(1.0f);
    m.kd = vec3(0.8f);
    m.ks = vec3(0.2f);
    m.shininess = 32.0f;
    return m;
  }();
  return material;
}

namespace {

void flattenNode(const Scene& scene, const Node& node, const mat4& worldFromParent,
                 std::vector<DrawItem>& out, std::uint32_t& nextTriangleId) {
  if (node.meshIndex < 0 && node.children.empty()) return;  // draws nothing, passes nothing on
  const mat4 worldFromNode = worldFromParent * localFromNodeTrs(node.translate, node.rotateDeg, node.scale);
  if (node.meshIndex >= 0 && node.meshIndex < static_cast<int>(scene.meshes.size())) {
    DrawItem item;
    item.mesh = &scene.meshes[node.meshIndex];
    item.material = (node.materialIndex >= 0 && node.materialIndex < static_cast<int>(scene.materials.size()))
                        ? &scene.materials[node.materialIndex]
                        : &defaultMaterial();
    item.worldFromModel = worldFromNode;
    item.nodeName = node.name;
    item.firstTriangleId = nextTriangleId;
    nextTriangleId += static_cast<std::uint32_t>(item.mesh->triangleCount());
    out.push_back(std::move(item));
  }
  for (const Node& child : node.children) flattenNode(scene, child, worldFromNode, out, nextTriangleId);
}

}  // namespace

vec4 lightVectorWorld(const Light& light) {
  return light.type == LightType::Directional ? vec4(-light.directionWorld, 0.0f) : vec4(light.posWorld, 1.0f);
}

vec2 spotCosines(const SpotCone& spot) {
  constexpr double kRadiansPerDegree = 3.14159265358979323846 / 180.0;
  return vec2(static_cast<float>(std::cos(static_cast<double>(spot.outerDeg) * kRadiansPerDegree)),
              static_cast<float>(std::cos(static_cast<double>(spot.innerDeg) * kRadiansPerDegree)));
}

SpotUniform spotUniformOf(const Light& light) {
  SpotUniform u;
  if (!isSpotLight(light)) return u;
  const vec2 c = spotCosines(*light.spot);
  u.axis = vec4(light.spot->directionWorld, 1.0f);
  u.cone = vec2(c.x, std::max(c.y - c.x, kMinSpotCosineRange));
  return u;
}

vec3 attenuationUsed(const Light& light) {
  return light.type == LightType::Directional ? vec3(1.0f, 0.0f, 0.0f) : light.attenuation;
}

std::vector<DrawItem> flattenScene(const Scene& scene) {
  std::vector<DrawItem> items;
  std::uint32_t nextTriangleId = 0;
  for (const Node& node : scene.nodes) flattenNode(scene, node, mat4(1.0f), items, nextTriangleId);
  return items;
}

std::size_t countTriangles(const Scene& scene) {
  std::size_t n = 0;
  for (const DrawItem& item : flattenScene(scene)) n += item.mesh->triangleCount();
  return n;
}

std::size_t countVertices(const Scene& scene) {
  std::size_t n = 0;
  for (const DrawItem& item : flattenScene(scene)) n += item.mesh->vertices.size();
  return n;
}

}  // namespace twr
