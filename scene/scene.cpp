#include "scene/scene.h"

#include <glm/gtc/matrix_transform.hpp>

namespace twr {

mat4 localFromNodeTrs(const vec3& translate, const vec3& rotateDeg, const vec3& scale) {
  const mat4 identity(1.0f);
  const mat4 t = glm::translate(identity, translate);
  const mat4 rx = glm::rotate(identity, degreesToRadians(rotateDeg.x), vec3(1, 0, 0));
  const mat4 ry = glm::rotate(identity, degreesToRadians(rotateDeg.y), vec3(0, 1, 0));
  const mat4 rz = glm::rotate(identity, degreesToRadians(rotateDeg.z), vec3(0, 0, 1));
  const mat4 s = glm::scale(identity, scale);
  return t * rz * ry * rx * s;
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
