// OBJ loading: a good file with materials and maps (paths relative to the MTL), generated
// normals, missing uvs, and every class of bad input as an InputError naming the file.
#include "scene/errors.h"
#include "scene/obj_loader.h"
#include "scene/primitives.h"
#include "scene/tangents.h"
#include "tests/missing_dependency.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>

namespace twr {
namespace {

namespace fs = std::filesystem;

constexpr float kTolerance = 1e-5f;

const std::string kDataDir = std::string(TWINRASTER_SOURCE_DIR) + "/tests/scene/data";

void expectVecNear(vec3 actual, vec3 expected) {
  EXPECT_NEAR(glm::length(actual - expected), 0.0f, kTolerance)
      << "(" << actual.x << ", " << actual.y << ", " << actual.z << ") vs (" << expected.x << ", " << expected.y
      << ", " << expected.z << ")";
}

// Writes small files for one bad-input case under the test output folder and returns the
// path of the first one.
std::string writeCase(const std::string& caseName, const std::vector<std::pair<std::string, std::string>>& files) {
  const fs::path dir = fs::path(TWINRASTER_TEST_OUT) / "test_obj" / caseName;
  fs::create_directories(dir);
  for (const auto& [name, text] : files) {
    std::ofstream out(dir / name);
    out << text;
  }
  return (dir / files.front().first).string();
}

// The load must throw InputError whose message contains the path and each of `words`.
void expectLoadError(const std::string& path, const std::vector<std::string>& words) {
  try {
    loadObj(path);
    ADD_FAILURE() << "expected InputError for " << path;
  } catch (const InputError& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find(path), std::string::npos) << "message does not name the file: " << message;
    for (const std::string& word : words) {
      EXPECT_NE(message.find(word), std::string::npos) << "message lacks '" << word << "': " << message;
    }
  }
}

const char* const kThreeVertices = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";

TEST(ObjLoad, TexturedFileGivesOneMeshPerMaterial) {
  const ObjModel model = loadObj(kDataDir + "/textured.obj");
  ASSERT_EQ(model.meshes.size(), 2u);
  ASSERT_EQ(model.materials.size(), 2u);
  ASSERT_EQ(model.hasMaterial.size(), 2u);
  EXPECT_TRUE(model.hasMaterial[0]);
  EXPECT_TRUE(model.hasMaterial[1]);

  // MTL values.
  const Material& bricks = model.materials[0];
  EXPECT_EQ(bricks.name, "bricks");
  expectVecNear(bricks.ka, {0.1f, 0.2f, 0.3f});
  expectVecNear(bricks.kd, {0.4f, 0.5f, 0.6f});
  expectVecNear(bricks.ks, {0.7f, 0.8f, 0.9f});
  EXPECT_FLOAT_EQ(bricks.shininess, 50.0f);
  // Maps, told apart by their sizes: diffuse 2x1, specular 1x2, normal 1x1.
  ASSERT_TRUE(bricks.diffuseMap);
  ASSERT_TRUE(bricks.specularMap);
  ASSERT_TRUE(bricks.normalMap);
  EXPECT_EQ(bricks.diffuseMap->width, 2);
  EXPECT_EQ(bricks.diffuseMap->height, 1);
  EXPECT_EQ(bricks.specularMap->width, 1);
  EXPECT_EQ(bricks.specularMap->height, 2);
  EXPECT_EQ(bricks.normalMap->width, 1);
  // The diffuse texel (0,0) is red, (1,0) green.
  EXPECT_EQ(bricks.diffuseMap->texel(0, 0)[0], 255);
  EXPECT_EQ(bricks.diffuseMap->texel(1, 0)[1], 255);

  const Material& plain = model.materials[1];
  EXPECT_EQ(plain.name, "plain");
  expectVecNear(plain.kd, {1, 0, 0});
  EXPECT_FALSE(plain.diffuseMap);
  EXPECT_FALSE(plain.specularMap);
  // map_Bump serves as the normal map when there is no `norm`; the file is loaded once.
  ASSERT_TRUE(plain.normalMap);
  EXPECT_EQ(plain.normalMap.get(), bricks.normalMap.get());

  // Each quad: 4 welded vertices, triangulated into 2 triangles, counter-clockwise from +Z.
  for (const Mesh& mesh : model.meshes) {
    EXPECT_EQ(mesh.vertices.size(), 4u);
    EXPECT_EQ(mesh.triangleCount(), 2u);
    for (std::size_t first = 0; first < mesh.indices.size(); first += 3) {
      const vec3 p0 = mesh.vertices[mesh.indices[first]].posModel;
      const vec3 faceNormal = glm::cross(mesh.vertices[mesh.indices[first + 1]].posModel - p0,
                                         mesh.vertices[mesh.indices[first + 2]].posModel - p0);
      EXPECT_GT(faceNormal.z, 0.0f);
    }
    for (const Vertex& v : mesh.vertices) expectVecNear(v.nModel, {0, 0, 1});
  }
  // Tangents: +X with w = +1 on the normal quad; on the mirrored quad T = -X and w = -1,
  // so B = w cross(N, T) still points along +v = +Y.
  for (const Vertex& v : model.meshes[0].vertices) {
    expectVecNear(vec3(v.tangentModel), {1, 0, 0});
    EXPECT_EQ(v.tangentModel.w, 1.0f);
  }
  for (const Vertex& v : model.meshes[1].vertices) {
    expectVecNear(vec3(v.tangentModel), {-1, 0, 0});
    EXPECT_EQ(v.tangentModel.w, -1.0f);
    expectVecNear(v.tangentModel.w * glm::cross(v.nModel, vec3(v.tangentModel)), {0, 1, 0});
  }
  // The mirrored quad's first corner: position (2,0,0), uv (1,0).
  bool foundCorner = false;
  for (const Vertex& v : model.meshes[1].vertices) {
    if (v.posModel == vec3(2, 0, 0)) {
      EXPECT_EQ(v.uv, vec2(1, 0));
      foundCorner = true;
    }
  }
  EXPECT_TRUE(foundCorner);
}

TEST(ObjLoad, MissingNormalsAreAreaWeightedPerPosition) {
  const ObjModel model = loadObj(kDataDir + "/no_normals.obj");
  ASSERT_EQ(model.meshes.size(), 1u);
  EXPECT_FALSE(model.hasMaterial[0]);
  const Mesh& mesh = model.meshes[0];
  // (v1, vt1), (v2, vt2), (v3, vt3), (v1, vt5), (v4, vt4).
  EXPECT_EQ(mesh.vertices.size(), 5u);
  EXPECT_EQ(mesh.triangleCount(), 2u);
  // Face normals times twice the area: (0,0,1) and (0,-2,0). On the shared edge v1-v2 the
  // sum is (0,-2,1)/sqrt5, for both uv copies of v1.
  const vec3 shared = glm::normalize(vec3(0, -2, 1));
  int copiesOfV1 = 0;
  for (const Vertex& v : mesh.vertices) {
    if (v.posModel == vec3(0, 0, 0)) {
      ++copiesOfV1;
      expectVecNear(v.nModel, shared);
    } else if (v.posModel == vec3(1, 0, 0)) {
      expectVecNear(v.nModel, shared);
    } else if (v.posModel == vec3(0, 1, 0)) {
      expectVecNear(v.nModel, {0, 0, 1});
    } else {
      expectVecNear(v.nModel, {0, -1, 0});
    }
    EXPECT_NEAR(glm::dot(vec3(v.tangentModel), v.nModel), 0.0f, kTolerance);
    EXPECT_NEAR(glm::length(vec3(v.tangentModel)), 1.0f, kTolerance);
  }
  EXPECT_EQ(copiesOfV1, 2);
}

TEST(ObjLoad, MissingUvsGiveZeroUvAndABasisFromTheNormal) {
  const ObjModel model = loadObj(kDataDir + "/no_uvs.obj");
  ASSERT_EQ(model.meshes.size(), 1u);
  const Mesh& mesh = model.meshes[0];
  EXPECT_EQ(mesh.vertices.size(), 4u);
  EXPECT_EQ(mesh.triangleCount(), 2u);
  for (const Vertex& v : mesh.vertices) {
    EXPECT_EQ(v.uv, vec2(0.0f));
    expectVecNear(v.nModel, {0, 1, 0});
    expectVecNear(vec3(v.tangentModel), anyPerpendicular({0, 1, 0}));
  }
}

TEST(ObjLoad, NegativeIndicesCountBackwards) {
  const std::string path = writeCase("relative", {{"relative.obj", std::string(kThreeVertices) + "f -3 -2 -1\n"}});
  const ObjModel model = loadObj(path);
  ASSERT_EQ(model.meshes.size(), 1u);
  EXPECT_EQ(model.meshes[0].triangleCount(), 1u);
  // No normals: the face normal, +Z for this counter-clockwise triangle.
  for (const Vertex& v : model.meshes[0].vertices) expectVecNear(v.nModel, {0, 0, 1});
}

TEST(ObjLoad, BuildMeshMergesAllParts) {
  MeshDesc desc;
  desc.type = MeshType::Obj;
  desc.path = kDataDir + "/textured.obj";
  const Mesh merged = buildMesh(desc);
  EXPECT_EQ(merged.vertices.size(), 8u);
  EXPECT_EQ(merged.triangleCount(), 4u);
  // Indices of the second part are offset past the first part's vertices.
  for (std::size_t i = 6; i < 12; ++i) EXPECT_GE(merged.indices[i], 4u);
}

TEST(ObjLoad, BuildMeshBuildsOnePartWhenAsked) {
  MeshDesc desc;
  desc.type = MeshType::Obj;
  desc.path = kDataDir + "/textured.obj";
  desc.objPart = 1;
  const Mesh part = buildMesh(desc);
  EXPECT_EQ(part.vertices.size(), 4u);
  EXPECT_EQ(part.triangleCount(), 2u);
  for (std::uint32_t index : part.indices) EXPECT_LT(index, 4u);
  desc.objPart = 2;  // the file has two parts
  EXPECT_THROW(buildMesh(desc), InputError);
}

TEST(ObjErrors, MissingFile) {
  expectLoadError(kDataDir + "/does_not_exist.obj", {"cannot open"});
}

TEST(ObjErrors, OutOfRangeIndexNamesTheLine) {
  // Line 4 references vertex 9 of 3.
  expectLoadError(writeCase("bad_index", {{"bad_index.obj", std::string(kThreeVertices) + "f 1 2 9\n"}}),
                  {":4", "index"});
  // A uv index out of range as well.
  expectLoadError(writeCase("bad_uv_index", {{"bad_uv_index.obj", std::string(kThreeVertices) + "vt 0 0\nf 1/1 2/1 3/2\n"}}),
                  {":5", "index"});
  // A relative index reaching before the first vertex.
  expectLoadError(writeCase("bad_relative", {{"bad_relative.obj", std::string(kThreeVertices) + "f -1 -2 -4\n"}}),
                  {":4"});
}

TEST(ObjErrors, ZeroIndexIsAParseError) {
  expectLoadError(writeCase("zero_index", {{"zero_index.obj", std::string(kThreeVertices) + "f 0 1 2\n"}}), {"line 4"});
}

TEST(ObjErrors, NonFiniteOrMalformedNumbers) {
  expectLoadError(writeCase("nan", {{"nan.obj", "v 0 0 0\nv nan 0 0\nv 0 1 0\nf 1 2 3\n"}}), {":2", "nan"});
  expectLoadError(writeCase("inf", {{"inf.obj", "v 0 0 0\nv 1 0 0\nv 0 inf 0\nf 1 2 3\n"}}), {":3", "inf"});
  expectLoadError(writeCase("overflow", {{"overflow.obj", "v 0 0 0\nv 1e999 0 0\nv 0 1 0\nf 1 2 3\n"}}), {":2"});
  // strtod reads 0 here, tinyobjloader 0 * 10^39126 = NaN (found by fuzzing).
  expectLoadError(writeCase("zero_exponent", {{"z.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0.0E39126 1\nf 1 2 3\n"}}),
                  {":4", "'v'", "infinite or NaN"});
  // Finite as a double but infinite as the float tinyobjloader stores (found by fuzzing).
  expectLoadError(writeCase("float_overflow", {{"f.obj", "v 0 0 0\nv 1 0 0\nvt 0 -7e79\nv 0 1 0\nf 1 2 4\n"}}),
                  {":3", "-7e79", "3.4e38"});
  expectLoadError(writeCase("garbage", {{"garbage.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 abc 1\nf 1 2 3\n"}}),
                  {":4", "abc"});
  expectLoadError(writeCase("short", {{"short.obj", "v 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"}}), {":1", "at least 3"});
}

// tinyobjloader's skin-weight extension casts each joint to int unchecked (a joint of 5e9
// was undefined behaviour, found by fuzzing). The lines are skipped with one warning that
// names the first; the rest of the file loads as if they were not there.
TEST(ObjLoad, SkinWeightLinesAreIgnoredWithAWarning) {
  const std::string path = writeCase(
      "skin_weights", {{"skin_weights.obj", std::string(kThreeVertices) + "vw 0 4294967296 1\n \tvw\t1 0 0.5 7e30 0.5\n" +
                                                "vwx 2 0 1\nf 1 2 3\n"}});
  const ObjModel model = loadObj(path);
  ASSERT_EQ(model.meshes.size(), 1u);
  EXPECT_EQ(model.meshes[0].indices.size(), 3u);
  std::size_t mentions = 0;
  for (const std::string& warning : model.warnings) {
    if (warning.find("'vw'") == std::string::npos) continue;
    ++mentions;
    EXPECT_NE(warning.find(path + ":4:"), std::string::npos) << warning;
    EXPECT_NE(warning.find("2 lines"), std::string::npos) << warning;
  }
  EXPECT_EQ(mentions, 1u);
}

TEST(ObjErrors, NoTriangles) {
  expectLoadError(writeCase("empty", {{"empty.obj", "# nothing here\n"}}), {"no triangles"});
  expectLoadError(writeCase("points_only", {{"points_only.obj", std::string(kThreeVertices) + "l 1 2\n"}}),
                  {"no triangles"});
}

TEST(ObjErrors, MissingMtlFile) {
  expectLoadError(writeCase("missing_mtl", {{"missing_mtl.obj", std::string("mtllib nowhere.mtl\n") + kThreeVertices +
                                                                       "usemtl a\nf 1 2 3\n"}}),
                  {"mtllib", "nowhere.mtl"});
}

TEST(ObjErrors, UnknownMaterialName) {
  expectLoadError(writeCase("unknown_material", {{"unknown_material.obj", std::string("mtllib unknown_material.mtl\n") +
                                                                              kThreeVertices + "usemtl stone\nf 1 2 3\n"},
                                                 {"unknown_material.mtl", "newmtl marble\nKd 1 1 1\n"}}),
                  {"usemtl", "stone"});
  // Without any mtllib, usemtl just names a group: no material, no error.
  const ObjModel model =
      loadObj(writeCase("usemtl_without_mtllib", {{"usemtl_without_mtllib.obj", std::string(kThreeVertices) +
                                                                                    "usemtl stone\nf 1 2 3\n"}}));
  ASSERT_EQ(model.meshes.size(), 1u);
  EXPECT_FALSE(model.hasMaterial[0]);
}

TEST(ObjErrors, MissingTextureNamesMaterialAndTexture) {
  expectLoadError(writeCase("missing_texture",
                            {{"missing_texture.obj", std::string("mtllib missing_texture.mtl\n") + kThreeVertices +
                                                         "usemtl stone\nf 1 2 3\n"},
                             {"missing_texture.mtl", "newmtl stone\nKd 1 1 1\nmap_Kd no_such_texture.png\n"}}),
                  {"stone", "map_Kd", "no_such_texture.png"});
}

TEST(ObjErrors, NegativeShininess) {
  expectLoadError(writeCase("negative_ns", {{"negative_ns.obj", std::string("mtllib negative_ns.mtl\n") + kThreeVertices +
                                                                    "usemtl m\nf 1 2 3\n"},
                                            {"negative_ns.mtl", "newmtl m\nNs -5\n"}}),
                  {"Ns"});
}


// ---- assets/models/house.obj ----

const std::string kHouseObj = std::string(TWINRASTER_SOURCE_DIR) + "/assets/models/house.obj";

// The house's geometry, whatever its textures: every triangle counter-clockwise around its
// (flat) vertex normal, normals pointing away from the house's inside, T along +u and
// B = w cross(N, T) along +v, and w = -1 exactly on the back wall (mirrored uvs).
void expectHouseGeometry(const ObjModel& model) {
  ASSERT_EQ(model.meshes.size(), 2u);
  EXPECT_EQ(model.materials[0].name, "bricks");
  EXPECT_EQ(model.materials[1].name, "roof");
  // Walls: front 2, back 2, two pentagonal gables 3 each; roof: two quads.
  EXPECT_EQ(model.meshes[0].triangleCount(), 10u);
  EXPECT_EQ(model.meshes[1].triangleCount(), 4u);
  const vec3 insidePoint(0.0f, 0.9f, 0.0f);
  int mirrored = 0;
  for (const Mesh& mesh : model.meshes) {
    for (std::size_t first = 0; first < mesh.indices.size(); first += 3) {
      const Vertex& v0 = mesh.vertices[mesh.indices[first]];
      const Vertex& v1 = mesh.vertices[mesh.indices[first + 1]];
      const Vertex& v2 = mesh.vertices[mesh.indices[first + 2]];
      const vec3 e1 = v1.posModel - v0.posModel, e2 = v2.posModel - v0.posModel;
      const vec2 d1 = v1.uv - v0.uv, d2 = v2.uv - v0.uv;
      const float det = d1.x * d2.y - d1.y * d2.x;
      ASSERT_NE(det, 0.0f) << "triangle " << first / 3;
      const vec3 dPdu = glm::normalize((e1 * d2.y - e2 * d1.y) / det);
      const vec3 dPdv = glm::normalize((e2 * d1.x - e1 * d2.x) / det);
      for (const Vertex* v : {&v0, &v1, &v2}) {
        EXPECT_GT(glm::dot(glm::cross(e1, e2), v->nModel), 0.0f) << "triangle " << first / 3;
        EXPECT_GT(glm::dot(v->nModel, v->posModel - insidePoint), 0.0f) << "triangle " << first / 3;
        expectVecNear(vec3(v->tangentModel), dPdu);
        expectVecNear(v->tangentModel.w * glm::cross(v->nModel, vec3(v->tangentModel)), dPdv);
        const bool onBackWall = v->nModel == vec3(0, 0, -1);
        EXPECT_EQ(v->tangentModel.w, onBackWall ? -1.0f : 1.0f) << "triangle " << first / 3;
        if (onBackWall) ++mirrored;
      }
    }
  }
  EXPECT_EQ(mirrored, 6);  // the back wall's two triangles
}

TEST(HouseModel, GeometryWithTestTextures) {
  // The house with its MTL swapped for one naming this folder's tiny PNGs (absolute
  // paths), so the geometry is checked before the generated brick textures exist.
  std::ifstream objIn(kHouseObj);
  ASSERT_TRUE(objIn) << kHouseObj;
  const std::string objText((std::istreambuf_iterator<char>(objIn)), std::istreambuf_iterator<char>());
  const std::string tex = kDataDir + "/tex/";
  const std::string path = writeCase(
      "house", {{"house.obj", objText},
                {"house.mtl", "newmtl bricks\nKd 1 1 1\nmap_Kd " + tex + "diffuse.png\nmap_Ks " + tex +
                                  "specular.png\nnorm " + tex + "normal.png\nnewmtl roof\nKd 0.6 0.25 0.2\nnorm " +
                                  tex + "normal.png\n"}});
  expectHouseGeometry(loadObj(path));
}

TEST(HouseModel, LoadsWithTheGeneratedBrickTextures) {
  const std::string textures = std::string(TWINRASTER_SOURCE_DIR) + "/assets/textures/";
  for (const char* name : {"bricks_diffuse.png", "bricks_normal.png", "bricks_specular.png"}) {
    if (!fs::exists(textures + name)) TWR_MISSING_DEPENDENCY(textures + name) << "not generated yet (make assets)";
  }
  const ObjModel model = loadObj(kHouseObj);
  expectHouseGeometry(model);
  const Material& bricks = model.materials[0];
  EXPECT_TRUE(bricks.diffuseMap && bricks.normalMap && bricks.specularMap);
  const Material& roof = model.materials[1];
  EXPECT_TRUE(roof.normalMap && !roof.diffuseMap && !roof.specularMap);
  EXPECT_EQ(roof.normalMap.get(), bricks.normalMap.get());
}

}  // namespace
}  // namespace twr
