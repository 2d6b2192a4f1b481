// Real-world OBJ files: every .obj in Debian's assimp-testmodels (UTF-16 files, files
// without a final newline, point clouds, line-only files, concave polygons, odd number
// formats, empty materials, spaces in material names, Windows texture paths) goes through
// the scene loader, as a scene file naming it, and then through both renderers. Each one
// either renders (finite depth in [0, 1], valid triangle ids, something covered) or is
// refused with an InputError naming the scene file, the key and the OBJ file. Known files
// also have their expected outcome pinned, so a change in behaviour shows up here.
// Skipped, with the reason, when the package is not installed.
#include "fuzz/support.h"
#include "glrender/gl_renderer.h"
#include "scene/errors.h"
#include "scene/scene_file.h"
#include "softrender/cpu_renderer.h"
#include "softrender/framebuffer.h"
#include "tests/missing_dependency.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace twr {
namespace {

namespace fs = std::filesystem;

const fs::path kModelRoot = "/usr/share/assimp/models";
constexpr int kWidth = 48;   // pixels
constexpr int kHeight = 36;  // pixels
// The camera sits this many bounding radii from the model's centre (unitless).
constexpr float kViewDistanceInRadii = 2.5f;

// Expected outcome of the files assimp-testmodels 5.2.5 ships: the empty string means
// "renders", anything else is a fragment the refusal message must contain.
const std::map<std::string, std::string> kExpected{
    {"WusonOBJ.obj", ""},
    {"box.obj", ""},
    {"box_UTF16BE.obj", ""},  // transcoded from UTF-16
    {"box_longline.obj", ""},
    {"box_mat_with_spaces.obj", ""},  // "usemtl" and "newmtl" names with spaces
    {"box_without_lineending.obj", ""},
    {"concave_polygon.obj", ""},
    {"cube_mtllib_after_g.obj", "cube_mtllib_after_g.mat"},  // names an MTL file that is not shipped
    {"cube_usemtl.obj", "'mtl3'"},                           // uses a material its MTL lacks
    {"cube_with_vertexcolors.obj", ""},
    {"cube_with_vertexcolors_uni.obj", ""},
    {"empty_mat.obj", ""},
    {"multiple_spaces.obj", ""},
    {"number_formats.obj", "number_formats.obj:11: 'v' expects finite numbers, got '3.1+e2'"},
    {"point_cloud.obj", "no triangles"},
    {"regr01.obj", ""},
    {"regr_3429812.obj", ""},
    {"space_in_material_name.obj", ""},
    {"spider.obj", ""},  // map_Kd '.\wal67ar_small.jpg': a Windows path to a JPEG
    {"testline.obj", "no triangles"},
    {"testmixed.obj", ""},
    {"testpoints.obj", "no triangles"},
    {"empty.obj", "no triangles"},
    {"malformed.obj", "line 28"},
    {"malformed2.obj", ""},
};

std::vector<fs::path> objFiles() {
  std::vector<fs::path> files;
  std::error_code ec;
  for (auto it = fs::recursive_directory_iterator(kModelRoot, ec); !ec && it != fs::recursive_directory_iterator();
       it.increment(ec)) {
    std::string extension = it->path().extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    if (it->is_regular_file() && extension == ".obj") files.push_back(it->path());
  }
  std::sort(files.begin(), files.end());
  return files;
}

// A scene file naming the OBJ, with a camera on its bounding sphere when `bounds` is given.
std::string sceneJson(const fs::path& obj, const vec3* centre, float radius) {
  std::string camera;
  if (centre) {
    const vec3 eye = *centre + vec3(0.3f, 0.4f, 1.0f) * (kViewDistanceInRadii * radius / 1.16f);
    const auto v = [](vec3 p) {
      return "[" + std::to_string(p.x) + ", " + std::to_string(p.y) + ", " + std::to_string(p.z) + "]";
    };
    camera = R"("camera": {"position": )" + v(eye) + R"(, "target": )" + v(*centre) +
             R"(, "near": )" + std::to_string(radius * 0.05f) + R"(, "far": )" + std::to_string(radius * 10.0f) +
             "},\n";
  }
  return "{\n" + camera + R"("lights": [{"position": [3, 4, 5], "attenuation": [1, 0, 0]}],)" + "\n" +
         R"("settings": {"cull": "none"},)" + "\n" + R"("nodes": [{"name": "model", "mesh": {"type": "obj", "path": )" +
         nlohmann::json(obj.string()).dump() + "}}]\n}\n";
}

void writeText(const fs::path& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out << text;
}

// Centre and radius of the bounding box of every vertex the scene draws.
void boundsOf(const Scene& scene, vec3& centre, float& radius) {
  vec3 low(std::numeric_limits<float>::max()), high(std::numeric_limits<float>::lowest());
  for (const Mesh& mesh : scene.meshes) {
    for (const Vertex& v : mesh.vertices) {
      low = glm::min(low, v.posModel);
      high = glm::max(high, v.posModel);
    }
  }
  centre = 0.5f * (low + high);
  radius = 0.5f * glm::length(high - low);
  if (!(radius > 0.0f)) radius = 1.0f;
}

std::size_t coveredPixels(const RenderOutput& output) {
  return static_cast<std::size_t>(std::count_if(output.triangleId.begin(), output.triangleId.end(),
                                                [](std::uint32_t id) { return id != kNoTriangle; }));
}

TEST(RealWorldModels, EveryAssimpObjRendersOrIsRefusedClearly) {
  if (!fs::is_directory(kModelRoot)) {
    TWR_MISSING_DEPENDENCY("assimp-testmodels") << kModelRoot << " is missing: install Debian's assimp-testmodels (scripts/install-deps.sh does)";
  }
  const std::vector<fs::path> files = objFiles();
  ASSERT_FALSE(files.empty()) << "no .obj files under " << kModelRoot;
  const fs::path dir = fs::path(TWINRASTER_TEST_OUT) / "real-world-models";
  fs::remove_all(dir);
  fs::create_directories(dir);
  const std::unique_ptr<Renderer> cpu = makeCpuRenderer();
  const std::unique_ptr<Renderer> gl = makeGlRenderer();
  int rendered = 0, refused = 0;

  for (const fs::path& obj : files) {
    const std::string name = obj.filename().string();
    SCOPED_TRACE(obj.string());
    const fs::path scenePath = dir / (obj.stem().string() + ".json");
    writeText(scenePath, sceneJson(obj, nullptr, 0.0f));
    Scene scene;
    std::string refusal;
    try {
      scene = loadSceneFile(scenePath.string());
    } catch (const InputError& e) {
      refusal = e.what();
    }
    const auto expected = kExpected.find(name);
    if (!refusal.empty()) {
      ++refused;
      // "<scene>: nodes[0].mesh.path: <obj>...: <what>"
      EXPECT_EQ(refusal.rfind(scenePath.string() + ": nodes[0].mesh.path: " + obj.string(), 0), 0u) << refusal;
      if (expected != kExpected.end()) {
        EXPECT_FALSE(expected->second.empty()) << "expected to render, refused: " << refusal;
        EXPECT_NE(refusal.find(expected->second), std::string::npos) << refusal;
      }
      continue;
    }
    ++rendered;
    if (expected != kExpected.end()) {
      EXPECT_TRUE(expected->second.empty()) << "expected a refusal with " << expected->second;
    }

    vec3 centre;
    float radius = 1.0f;
    boundsOf(scene, centre, radius);
    writeText(scenePath, sceneJson(obj, &centre, radius));
    ASSERT_NO_THROW(scene = loadSceneFile(scenePath.string()));
    const std::size_t triangles = countTriangles(scene);
    for (Renderer* renderer : {cpu.get(), gl.get()}) {
      SCOPED_TRACE(renderer->name());
      RenderOutput output;
      ASSERT_NO_THROW(output = renderer->render(scene, scene.settings, kWidth, kHeight));
      EXPECT_NO_THROW(
          fuzz::checkRenderOutput(output, kWidth, kHeight, triangles, clearByte(scene.output.background.a), name));
      EXPECT_GT(coveredPixels(output), 0u) << "the framed model covers no pixel";
    }
  }
  std::cout << "[ models   ] " << files.size() << " OBJ files: " << rendered << " rendered, " << refused
            << " refused\n";
}

}  // namespace
}  // namespace twr
