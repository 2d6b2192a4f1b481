// Target "obj_file": loadObj on the bytes (and an MTL after a "~mtl~" line), then a small
// CPU render of the model.
#include "fuzz/support.h"
#include "fuzz/targets.h"

#include "scene/obj_loader.h"
#include "softrender/cpu_renderer.h"
#include "softrender/framebuffer.h"

#include <cmath>
#include <fstream>
#include <string_view>

namespace twr::fuzz {

namespace {

// Separates the OBJ part of an input from its MTL part.
constexpr std::string_view kMtlSeparator = "\n~mtl~\n";
// Tolerance on |n| = 1 and |t| = 1 (unitless): float normalisation is exact to a few ulps.
constexpr float kUnitLengthTolerance = 1e-4f;
constexpr int kRenderWidth = 12;   // pixels
constexpr int kRenderHeight = 9;   // pixels
// Models up to this many triangles (inclusive) are also rendered.
constexpr std::size_t kMaxRenderedTriangles = 20'000;

void writeBytes(const std::filesystem::path& path, std::string_view bytes) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  require(static_cast<bool>(out), "cannot write " + path.string());
}

bool isUnit(vec3 v) { return std::fabs(glm::length(v) - 1.0f) <= kUnitLengthTolerance; }

void checkModel(const ObjModel& model) {
  require(!model.meshes.empty(), "loadObj returned no meshes without an error");
  require(model.materials.size() == model.meshes.size() && model.hasMaterial.size() == model.meshes.size(),
          "materials and hasMaterial are not parallel to meshes");
  for (const Mesh& mesh : model.meshes) {
    require(!mesh.indices.empty() && mesh.indices.size() % 3 == 0, "a mesh without whole triangles");
    for (std::uint32_t index : mesh.indices) require(index < mesh.vertices.size(), "mesh index out of range");
    for (const Vertex& v : mesh.vertices) {
      require(isFinite(v.posModel) && isFinite(v.uv), "a non-finite position or uv");
      require(isFinite(v.nModel) && isUnit(v.nModel), "a normal that is not unit length");
      require(isFinite(v.tangentModel) && isUnit(vec3(v.tangentModel)), "a tangent that is not unit length");
      require(v.tangentModel.w == 1.0f || v.tangentModel.w == -1.0f, "a tangent handedness other than +-1");
    }
  }
  for (const Material& m : model.materials) {
    require(isFinite(m.ka) && isFinite(m.kd) && isFinite(m.ks) && std::isfinite(m.shininess) && m.shininess >= 0.0f,
            "material '" + m.name + "' has a non-finite or negative parameter");
  }
}

}  // namespace

void fuzzObjFile(const Workspace& workspace, const std::uint8_t* data, std::size_t size) {
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  const std::size_t separator = bytes.find(kMtlSeparator);
  const std::filesystem::path objPath = workspace.dir() / "fuzz.obj";
  const std::filesystem::path mtlPath = workspace.dir() / "fuzz.mtl";
  writeBytes(objPath, bytes.substr(0, separator));
  std::error_code ec;
  std::filesystem::remove(mtlPath, ec);
  if (separator != std::string_view::npos) writeBytes(mtlPath, bytes.substr(separator + kMtlSeparator.size()));

  ObjModel model;
  try {
    model = loadObj(objPath.string());
  } catch (const InputError& error) {
    requireNamesInput(error, objPath.string());
    return;
  }
  checkModel(model);

  Scene scene;
  std::size_t triangles = 0;
  for (std::size_t i = 0; i < model.meshes.size(); ++i) {
    triangles += model.meshes[i].triangleCount();
    scene.meshes.push_back(std::move(model.meshes[i]));
    scene.materials.push_back(std::move(model.materials[i]));
    Node node;
    node.name = "part" + std::to_string(i);
    node.meshIndex = static_cast<int>(i);
    node.materialIndex = static_cast<int>(i);
    scene.nodes.push_back(std::move(node));
  }
  if (triangles > kMaxRenderedTriangles) return;
  scene.lights.emplace_back();
  scene.settings.cull = CullMode::None;
  const RenderOutput output = makeCpuRenderer()->render(scene, scene.settings, kRenderWidth, kRenderHeight);
  checkRenderOutput(output, kRenderWidth, kRenderHeight, triangles, clearByte(scene.output.background.a),
                    "obj render");
}

}  // namespace twr::fuzz
