#include "glrender/tbn_lines.h"

#include "glrender/model_transforms.h"

namespace twr {

std::vector<TbnLineVertex> buildTbnLines(const std::vector<DrawItem>& items, const RenderSettings& settings) {
  constexpr std::size_t kVerticesPerMeshVertex = 6;  // three segments, two ends each
  std::vector<TbnLineVertex> lines;
  std::size_t total = 0;
  for (const DrawItem& item : items) total += item.mesh->vertices.size() * kVerticesPerMeshVertex;
  lines.reserve(total);
  const float lengthWorld = settings.tbnLines.length;
  for (const DrawItem& item : items) {
    const ModelTransforms transforms = makeModelTransforms(item.worldFromModel, settings.tangentTransform);
    for (const Vertex& vertex : item.mesh->vertices) {
      const vec3 posWorld = vec3(transforms.worldFromModel * vec4(vertex.posModel, 1.0f));
      const vec3 nWorld = transforms.normalFromModel * vertex.nModel;
      const vec3 tWorld = transforms.tangentFromModel * vec3(vertex.tangentModel);
      const vec3 bWorld = (vertex.tangentModel.w * transforms.mirrorSign) * glm::cross(nWorld, tWorld);
      const auto addSegment = [&](const vec3& direction, const vec3& colour) {
        lines.push_back({posWorld, colour});
        lines.push_back({posWorld + lengthWorld * safeNormalize(direction), colour});
      };
      addSegment(nWorld, kNormalLineColour);
      addSegment(tWorld, kTangentLineColour);
      addSegment(bWorld, kBitangentLineColour);
    }
  }
  return lines;
}

}  // namespace twr
