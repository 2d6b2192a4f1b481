#include "glrender/model_transforms.h"

#include <cmath>

namespace twr {
namespace {

bool allFinite(const mat3& m) {
  for (int column = 0; column < 3; ++column) {
    for (int row = 0; row < 3; ++row) {
      if (!std::isfinite(m[column][row])) return false;
    }
  }
  return true;
}

mat3 normalMatrix(const mat3& upper) {
  const float det = glm::determinant(upper);
  if (det != 0.0f && std::isfinite(det)) {
    const mat3 inverseTranspose = glm::transpose(glm::inverse(upper));
    if (allFinite(inverseTranspose)) return inverseTranspose;
  }
  // Cofactor matrix, det * inverse transpose: column i is the cross of the other two.
  return mat3(glm::cross(upper[1], upper[2]), glm::cross(upper[2], upper[0]), glm::cross(upper[0], upper[1]));
}

}  // namespace

ModelTransforms makeModelTransforms(const mat4& worldFromModel, TangentTransform tangentTransform) {
  ModelTransforms transforms;
  const mat3 upper(worldFromModel);
  transforms.worldFromModel = worldFromModel;
  transforms.normalFromModel = normalMatrix(upper);
  transforms.tangentFromModel = tangentTransform == TangentTransform::Model ? upper : transforms.normalFromModel;
  transforms.mirrorSign = glm::determinant(upper) < 0.0f ? -1.0f : 1.0f;
  return transforms;
}

}  // namespace twr
