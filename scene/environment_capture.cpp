#include "scene/environment_capture.h"

#include "scene/environment_light.h"
#include "scene/errors.h"

#include <algorithm>
#include <chrono>
#include <functional>
#include <limits>
#include <utility>

namespace twr {

namespace {

// The capture's field of view: a cube face spans 90 degrees.
constexpr float kFaceFovDeg = 90.0f;

// The first node named `name`, depth first, with its world transform; null when none is.
const Node* findNode(const std::vector<Node>& nodes, const std::string& name, const mat4& worldFromParent,
                     mat4& worldFromNode) {
  for (const Node& node : nodes) {
    const mat4 world = worldFromParent * localFromNodeTrs(node.translate, node.rotateDeg, node.scale);
    if (node.name == name) {
      worldFromNode = world;
      return &node;
    }
    if (const Node* found = findNode(node.children, name, world, worldFromNode)) return found;
  }
  return nullptr;
}

// Removes the first node named `name` (depth first) with its children; true when one was.
bool removeNode(std::vector<Node>& nodes, const std::string& name) {
  for (auto it = nodes.begin(); it != nodes.end(); ++it) {
    if (it->name == name) {
      nodes.erase(it);
      return true;
    }
    if (removeNode(it->children, name)) return true;
  }
  return false;
}

}  // namespace

bool needsEnvironmentCapture(const Scene& scene) {
  return scene.environment && scene.environment->capture && !scene.environment->cube;
}

vec3 captureCentre(const Scene& scene, const std::string& nodeName) {
  mat4 worldFromNode(1.0f);
  const Node* node = findNode(scene.nodes, nodeName, mat4(1.0f), worldFromNode);
  if (!node) throw InputError("environment.capture.node: no node is named \"" + nodeName + "\"");
  const bool hasMesh = node->meshIndex >= 0 && node->meshIndex < static_cast<int>(scene.meshes.size()) &&
                       !scene.meshes[static_cast<std::size_t>(node->meshIndex)].vertices.empty();
  if (!hasMesh) return vec3(worldFromNode * vec4(0.0f, 0.0f, 0.0f, 1.0f));
  // The model-space bounds' middle, moved to world space (a sphere's centre, wherever its
  // vertices were modelled around).
  vec3 lo(std::numeric_limits<float>::max()), hi(std::numeric_limits<float>::lowest());
  for (const Vertex& v : scene.meshes[static_cast<std::size_t>(node->meshIndex)].vertices) {
    lo = glm::min(lo, v.posModel);
    hi = glm::max(hi, v.posModel);
  }
  return vec3(worldFromNode * vec4(0.5f * (lo + hi), 1.0f));
}

Camera captureCamera(int face, const vec3& centre, const Camera& like) {
  // The face's middle direction and its increasing-t direction, from the GL table itself
  // (exact: each is a unit axis).
  const glm::dvec3 forward = directionFromCubeCoord(face, 0.5, 0.5);
  const glm::dvec3 towardsT = directionFromCubeCoord(face, 0.5, 1.0) - forward;
  Camera camera = like;
  camera.position = centre;
  camera.target = centre + vec3(forward);
  camera.up = vec3(towardsT);
  camera.fovDeg = kFaceFovDeg;
  return camera;
}

Scene sceneForCapture(const Scene& scene, const std::string& nodeName) {
  Scene out = scene;
  out.environment.reset();
  if (!removeNode(out.nodes, nodeName)) {
    throw InputError("environment.capture.node: no node is named \"" + nodeName + "\"");
  }
  return out;
}

RenderOutput flipRows(RenderOutput out) {
  const auto flip = [&](auto& buffer, std::size_t perPixel) {
    if (buffer.empty()) return;
    const std::size_t row = static_cast<std::size_t>(out.width) * perPixel;
    for (int y = 0; y < out.height / 2; ++y) {
      auto top = buffer.begin() + static_cast<std::ptrdiff_t>(static_cast<std::size_t>(y) * row);
      auto bottom = buffer.begin() + static_cast<std::ptrdiff_t>(static_cast<std::size_t>(out.height - 1 - y) * row);
      std::swap_ranges(top, top + static_cast<std::ptrdiff_t>(row), bottom);
    }
  };
  flip(out.rgba, 4);
  flip(out.depth, 1);
  flip(out.triangleId, 1);
  flip(out.lineMask, 1);
  return out;
}

CapturedEnvironment captureEnvironment(const Scene& scene, const RenderSettings& settings, Renderer& renderer) {
  if (!scene.environment || !scene.environment->capture) {
    throw InputError("captureEnvironment: the scene's environment is not captured");
  }
  const auto start = std::chrono::steady_clock::now();
  const EnvironmentCapture& capture = *scene.environment->capture;
  const vec3 centre = captureCentre(scene, capture.node);
  Scene probe = sceneForCapture(scene, capture.node);
  RenderSettings faceSettings = settings;
  faceSettings.view = View::Shaded;
  faceSettings.tbnLines.enabled = false;

  auto faces = std::make_shared<CapturedFaces>();
  faces->centreWorld = centre;
  std::array<FaceImage, kCubeFaces> images;
  std::array<std::string, kCubeFaces> names;
  for (int f = 0; f < kCubeFaces; ++f) {
    probe.camera = captureCamera(f, centre, scene.camera);
    RenderOutput face;
    try {
      face = flipRows(renderer.render(probe, faceSettings, capture.size, capture.size));
    } catch (const InputError& e) {
      throw InputError(std::string("environment.capture: face ") + kCubeFaceNames[f] + ": " + e.what());
    }
    FaceImage& image = images[static_cast<std::size_t>(f)];
    image.width = image.height = capture.size;
    image.rgb.resize(static_cast<std::size_t>(capture.size) * static_cast<std::size_t>(capture.size) * 3);
    for (std::size_t i = 0; i < image.rgb.size() / 3; ++i) {
      for (std::size_t c = 0; c < 3; ++c) image.rgb[i * 3 + c] = static_cast<float>(face.rgba[i * 4 + c]) / 255.0f;
    }
    names[static_cast<std::size_t>(f)] = "the capture from \"" + capture.node + "\"";
    faces->faces[static_cast<std::size_t>(f)] = std::move(face);
  }

  CapturedEnvironment out{scene, nullptr};
  Environment& env = *out.scene.environment;
  std::vector<std::string> ignored;  // the size is a power of two within the limit: no warning
  CubeMap cube = cubeMapFromFaces(std::move(images), names, ignored);
  cube.source = "captured from \"" + capture.node + "\" by " + renderer.name();
  env.cube = std::make_shared<const CubeMap>(std::move(cube));
  if (env.parameterization != EnvironmentParameterization::Cube) {
    env.layers = std::make_shared<const ParameterizedMap>(parameterizedMapFromCube(*env.cube, env.parameterization, env.size));
  }
  prefilterEnvironmentLight(out.scene);
  faces->milliseconds = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  out.faces = std::move(faces);
  return out;
}

void attachCapture(RenderOutput& frame, const CapturedEnvironment& capture) {
  frame.capturedFaces = capture.faces;
  frame.stats.captureMilliseconds = capture.faces->milliseconds;
  frame.stats.milliseconds += capture.faces->milliseconds;
}

}  // namespace twr
