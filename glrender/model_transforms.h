// Per-draw matrices of the vertex stage (docs/shading.md), computed on the CPU once per
// draw item and handed to GLSL as uniforms. softrender/vertex.cpp computes the same.
#pragma once

#include "scene/conventions.h"
#include "scene/settings.h"

namespace twr {

struct ModelTransforms {
  mat4 worldFromModel{1.0f};
  mat3 normalFromModel{1.0f};   // inverse transpose of the upper 3x3 of worldFromModel
  mat3 tangentFromModel{1.0f};  // upper 3x3 (tangent_transform = model) or normalFromModel
  float mirrorSign = 1.0f;      // -1 when det(upper 3x3 of worldFromModel) < 0, else +1
};

// For a singular upper 3x3 (a zero scale) normalFromModel is the cofactor matrix: the same
// directions up to scale, never Inf or NaN.
ModelTransforms makeModelTransforms(const mat4& worldFromModel, TangentTransform tangentTransform);

}  // namespace twr
