#include "softrender/vertex.h"

#include "scene/camera.h"

#include <algorithm>
#include <cmath>

namespace twr {

template <typename T>
Mat3T<T> normalMatrixFrom(const Mat4T<T>& worldFromModel) {
  const Mat3T<T> upper(worldFromModel);
  // Cofactor matrix: column i is the cross product of the other two columns. It equals
  // det * inverse transpose, so it is the answer up to scale even when det is 0.
  const Mat3T<T> cofactor(glm::cross(upper[1], upper[2]), glm::cross(upper[2], upper[0]),
                          glm::cross(upper[0], upper[1]));
  const T det = glm::determinant(upper);
  if (det != T(0) && std::isfinite(det)) {
    const Mat3T<T> inverseTranspose = glm::transpose(glm::inverse(upper));
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

template <typename T>
VertexUniformsT<T> makeVertexUniforms(const Mat4T<T>& worldFromModel, const Mat4T<T>& clipFromWorld,
                                      const Scene& scene, const RenderSettings& settings) {
  VertexUniformsT<T> u;
  u.worldFromModel = worldFromModel;
  u.clipFromWorld = clipFromWorld;
  u.normalFromModel = normalMatrixFrom(worldFromModel);
  u.tangentFromModel =
      settings.tangentTransform == TangentTransform::Model ? Mat3T<T>(worldFromModel) : u.normalFromModel;
  u.mirrorSign = glm::determinant(Mat3T<T>(worldFromModel)) < T(0) ? T(-1) : T(1);
  u.eyePosWorld = Vec3T<T>(scene.camera.position);
  u.lightCount = std::min(static_cast<int>(scene.lights.size()), kMaxLights);
  for (int i = 0; i < u.lightCount; ++i)
    u.lightVectorWorld[static_cast<std::size_t>(i)] = Vec4T<T>(lightVectorWorld(scene.lights[static_cast<std::size_t>(i)]));
  u.tangentLighting = settings.lightingSpace == LightingSpace::Tangent;
  u.userClipPlaneCount = std::min(static_cast<int>(settings.userClipPlanes.size()), kMaxUserClipPlanes);
  for (int j = 0; j < u.userClipPlaneCount; ++j)
    u.userClipPlanes[static_cast<std::size_t>(j)] = Vec4T<T>(settings.userClipPlanes[static_cast<std::size_t>(j)]);
  return u;
}

template <typename T>
ClipVertexT<T> runVertexStage(const Vertex& vertex, const VertexUniformsT<T>& u) {
  const lanes::VertexInL<T> in{Vec3T<T>(vertex.posModel), Vec3T<T>(vertex.nModel), Vec4T<T>(vertex.tangentModel),
                               Vec2T<T>(vertex.uv)};
  const lanes::VertexOutL<T> stage = lanes::vertexStage<T>(in, u);
  ClipVertexT<T> out;
  out.posClip = stage.posClip;
  out.posWorld = stage.posWorld;
  out.nWorld = stage.nWorld;
  out.tWorld = stage.tWorld;
  out.bWorld = stage.bWorld;
  out.uv = stage.uv;
  if (u.tangentLighting) {
    out.lightDirTangent = stage.lightDirTangent;
    out.eyeDirTangent = stage.eyeDirTangent;
  }
  for (int j = 0; j < u.userClipPlaneCount; ++j) {
    out.clipDistance[static_cast<std::size_t>(j)] = stage.clipDistance[static_cast<std::size_t>(j)];
  }
  return out;
}

// The two pipelines: float (matches GL) and double (the reference).
template mat3 normalMatrixFrom<float>(const mat4&);
template glm::dmat3 normalMatrixFrom<double>(const glm::dmat4&);
template VertexUniformsT<float> makeVertexUniforms<float>(const mat4&, const mat4&, const Scene&,
                                                          const RenderSettings&);
template VertexUniformsT<double> makeVertexUniforms<double>(const glm::dmat4&, const glm::dmat4&, const Scene&,
                                                            const RenderSettings&);
template ClipVertexT<float> runVertexStage<float>(const Vertex&, const VertexUniformsT<float>&);
template ClipVertexT<double> runVertexStage<double>(const Vertex&, const VertexUniformsT<double>&);

}  // namespace twr
