#include "softrender/draw_list.h"

#include "scene/errors.h"
#include "scene/image.h"

#include <string>

namespace twr {

ItemState makeItemState(const DrawItem& item, const mat4& clipFromWorld, const Scene& scene,
                        const RenderSettings& settings, int width, int height) {
  ItemState s;
  s.item = &item;
  s.vertexUniforms = makeVertexUniforms(item.worldFromModel, clipFromWorld, scene, settings);
  s.shade = makeShadeUniforms(*item.material, scene, settings);
  s.shaderKey = shaderKeyFor(s.shade, settings);
  s.clip = makeClipConfig(settings.clip, s.vertexUniforms.userClipPlaneCount, width, height, settings.interpolation);
  s.cull = settings.cull;
  s.frontFace = settings.frontFace;
  s.viewport = Viewport{width, height};
  s.tangentLighting = s.vertexUniforms.tangentLighting;
  s.interpolation = settings.interpolation;
  return s;
}

void validateImageSize(int width, int height, const char* renderer) {
  if (const std::string problem = renderSizeProblem(width, height); !problem.empty()) {
    throw InputError(std::string(renderer) + ": " + problem);
  }
}

void throwIndexError(const DrawItem& item, std::size_t i) {
  throw InputError("node '" + item.nodeName + "': mesh index " + std::to_string(i) + " is " +
                   std::to_string(item.mesh->indices[i]) + ", expected < vertex count " +
                   std::to_string(item.mesh->vertices.size()));
}

namespace {

// The indices from position `first` on.
void validateIndicesFrom(const DrawItem& item, std::size_t first) {
  const std::size_t vertexCount = item.mesh->vertices.size();
  for (std::size_t i = first; i < item.mesh->indices.size(); ++i) {
    if (item.mesh->indices[i] >= vertexCount) throwIndexError(item, i);
  }
}

}  // namespace

void validateIndices(const DrawItem& item) { validateIndicesFrom(item, 0); }

void validateTrailingIndices(const DrawItem& item) { validateIndicesFrom(item, 3 * item.mesh->triangleCount()); }

}  // namespace twr
