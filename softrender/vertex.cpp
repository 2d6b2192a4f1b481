#include "softrender/vertex.h"

#include "scene/camera.h"

#include <algorithm>
#include <cmath>

namespace twr {

vec4 transformPoint(const mat4& m, vec3 p) { return m[0] * p.x + m[1] * p.y + m[2] * p.z + m[3]; }

vec3 transformVector(const mat3& m, vec3 v) { return m[0] * v.x + m[1] * v.y + m[2] * v.z; }

mat3 normalMatrixFrom(const mat4& worldFromModel) {
  const mat3 upper(worldFromModel);
  // Cofactor matrix: column i is the cross product of the other two columns. It equals
  // det * inverse transpose, so it is the answer up to scale even when det is 0.
  const mat3 cofactor(glm::cross(upper[1], upper[2]), glm::cross(upper[2], upper[0]),
                      glm::cross(upper[0], upper[1]));
  const float det = glm::determinant(upper);
  if (det != 0.0f && std::isfinite(det)) {
    const mat3 inverseTranspose = glm::transpose(glm::inverse(upper));
    bool finite = true;
    for (int c = 0; c < 3; ++c)
      for (int r = 0; r < 3; ++r) finite = finite && std::isfinite(inverseTranspose[c][r]);
    if (finite) return inverseTranspose;
  }
  return cofactor;
}

mat4 clipFromWorldFor(const Camera& camera, int width, int height) {
  const float aspect = static_cast<float>(width) / static_cast<float>(height);
  return clipFromView(camera, aspect) * viewFromWorld(camera);
}

VertexUniforms makeVertexUniforms(const mat4& worldFromModel, const mat4& clipFromWorld, const Scene& scene,
                                  const RenderSettings& settings) {
  VertexUniforms u;
  u.worldFromModel = worldFromModel;
  u.clipFromWorld = clipFromWorld;
  u.normalFromModel = normalMatrixFrom(worldFromModel);
  u.tangentFromModel =
      settings.tangentTransform == TangentTransform::Model ? mat3(worldFromModel) : u.normalFromModel;
  u.mirrorSign = glm::determinant(mat3(worldFromModel)) < 0.0f ? -1.0f : 1.0f;
  u.eyePosWorld = scene.camera.position;
  u.lightCount = std::min(static_cast<int>(scene.lights.size()), kMaxLights);
  for (int i = 0; i < u.lightCount; ++i) u.lightPosWorld[static_cast<std::size_t>(i)] = scene.lights[static_cast<std::size_t>(i)].posWorld;
  u.tangentLighting = settings.lightingSpace == LightingSpace::Tangent;
  u.userClipPlaneCount = std::min(static_cast<int>(settings.userClipPlanes.size()), kMaxUserClipPlanes);
  for (int j = 0; j < u.userClipPlaneCount; ++j)
    u.userClipPlanes[static_cast<std::size_t>(j)] = settings.userClipPlanes[static_cast<std::size_t>(j)];
  return u;
}

ClipVertex runVertexStage(const Vertex& vertex, const VertexUniforms& u) {
  ClipVertex out;
  out.posWorld = vec3(transformPoint(u.worldFromModel, vertex.posModel));
  out.posClip = transformPoint(u.clipFromWorld, out.posWorld);
  out.nWorld = transformVector(u.normalFromModel, vertex.nModel);
  out.tWorld = transformVector(u.tangentFromModel, vec3(vertex.tangentModel));
  // A mirroring transform reverses the handedness of the (T, B, N) frame, so the sign that
  // rebuilds B from N and T flips with it.
  const float sign = vertex.tangentModel.w * u.mirrorSign;
  out.bWorld = sign * glm::cross(out.nWorld, out.tWorld);
  out.uv = vertex.uv;

  if (u.tangentLighting) {
    // The tutorial's vertex shader: light and eye directions in the vertex's tangent frame,
    // left unnormalised so that linear interpolation is the tutorial's behaviour.
    const vec3 t = safeNormalize(out.tWorld);
    const vec3 b = safeNormalize(out.bWorld);
    const vec3 n = safeNormalize(out.nWorld);
    for (int i = 0; i < u.lightCount; ++i) {
      const vec3 lw = u.lightPosWorld[static_cast<std::size_t>(i)] - out.posWorld;
      out.lightDirTangent[static_cast<std::size_t>(i)] = vec3(glm::dot(t, lw), glm::dot(b, lw), glm::dot(n, lw));
    }
    const vec3 ew = u.eyePosWorld - out.posWorld;
    out.eyeDirTangent = vec3(glm::dot(t, ew), glm::dot(b, ew), glm::dot(n, ew));
  }

  for (int j = 0; j < u.userClipPlaneCount; ++j) {
    out.clipDistance[static_cast<std::size_t>(j)] = glm::dot(u.userClipPlanes[static_cast<std::size_t>(j)], vec4(out.posWorld, 1.0f));
  }
  return out;
}

}  // namespace twr
