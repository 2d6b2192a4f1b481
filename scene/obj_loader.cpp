#include "scene/obj_loader.h"

#include "scene/errors.h"
#include "scene/tangents.h"

#include <tiny_obj_loader.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <sstream>
#include <tuple>

namespace twr {

namespace {

namespace fs = std::filesystem;

// Counts of the OBJ vertex-data lines, which face indices refer to.
struct AttributeCounts {
  long long positions = 0;  // v
  long long uvs = 0;        // vt
  long long normals = 0;    // vn
};

std::string trimmed(const std::string& text) {
  const std::size_t begin = text.find_first_not_of(" \t\r\n");
  if (begin == std::string::npos) return {};
  const std::size_t end = text.find_last_not_of(" \t\r\n");
  return text.substr(begin, end - begin + 1);
}

// What our own pass over the file learns before tinyobjloader parses it.
struct ObjPrescan {
  fs::path mtlDirectory;  // of the first mtllib: texture paths are relative to the MTL
  bool hasMtllib = false;
};

// Checks the vertex-data lines before tinyobjloader parses the file: tinyobjloader reads
// "nan", "inf" or "abc" as 0 without a word, and we want the line number.
ObjPrescan prescanObj(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw InputError(path + ": cannot open the OBJ file");
  ObjPrescan result;
  result.mtlDirectory = fs::path(path).parent_path();
  std::string line;
  long long lineNumber = 0;
  while (std::getline(in, line)) {
    ++lineNumber;
    std::istringstream tokens(line);
    std::string keyword;
    if (!(tokens >> keyword)) continue;
    std::size_t minimumValues = 0;
    if (keyword == "v") {
      minimumValues = 3;
    } else if (keyword == "vn") {
      minimumValues = 3;
    } else if (keyword == "vt") {
      minimumValues = 1;
    } else if (keyword == "mtllib" && !result.hasMtllib) {
      std::string firstName;  // "mtllib a.mtl b.mtl" may name several; the first decides
      tokens >> firstName;
      result.mtlDirectory = (fs::path(path).parent_path() / fs::path(firstName)).parent_path();
      result.hasMtllib = true;
      continue;
    } else {
      continue;
    }
    std::size_t values = 0;
    std::string token;
    while (tokens >> token) {
      errno = 0;
      char* end = nullptr;
      const double value = std::strtod(token.c_str(), &end);
      if (end == token.c_str() || *end != '\0' || errno == ERANGE || !std::isfinite(value)) {
        throw InputError(path + ":" + std::to_string(lineNumber) + ": '" + keyword +
                         "' expects finite numbers, got '" + token + "'");
      }
      ++values;
    }
    if (values < minimumValues) {
      throw InputError(path + ":" + std::to_string(lineNumber) + ": '" + keyword + "' expects at least " +
                       std::to_string(minimumValues) + " numbers, got " + std::to_string(values));
    }
  }
  return result;
}

// An OBJ index (1-based, or negative = relative to the lines so far) is in range.
bool objIndexInRange(long long index, long long countSoFar, long long countTotal) {
  if (index > 0) return index <= countTotal;
  if (index < 0) return -index <= countSoFar;
  return false;
}

// Finds the first face line with an out-of-range index, for the error message (0 if none
// is found, e.g. when the bad index came from somewhere we do not re-parse).
long long findBadFaceLine(const std::string& path, const AttributeCounts& total) {
  std::ifstream in(path);
  std::string line;
  long long lineNumber = 0;
  AttributeCounts soFar;
  while (std::getline(in, line)) {
    ++lineNumber;
    std::istringstream tokens(line);
    std::string keyword;
    if (!(tokens >> keyword)) continue;
    if (keyword == "v") ++soFar.positions;
    if (keyword == "vt") ++soFar.uvs;
    if (keyword == "vn") ++soFar.normals;
    if (keyword != "f") continue;
    std::string corner;
    while (tokens >> corner) {
      // v, v/vt, v//vn or v/vt/vn
      std::array<std::string, 3> parts;
      std::size_t part = 0;
      for (char character : corner) {
        if (character == '/') {
          if (++part >= parts.size()) break;
        } else {
          parts[part] += character;
        }
      }
      const std::array<long long, 3> soFarCounts{soFar.positions, soFar.uvs, soFar.normals};
      const std::array<long long, 3> totalCounts{total.positions, total.uvs, total.normals};
      for (std::size_t k = 0; k < parts.size(); ++k) {
        if (parts[k].empty()) continue;
        const long long index = std::atoll(parts[k].c_str());
        if (!objIndexInRange(index, soFarCounts[k], totalCounts[k])) return lineNumber;
      }
    }
  }
  return 0;
}

// tinyobjloader ends its messages with newlines; keep them on one line.
std::string oneLine(const std::string& text) {
  std::string result = trimmed(text);
  for (char& character : result) {
    if (character == '\n') character = ' ';
  }
  return result;
}

// The first line of tinyobjloader's warnings that contains `needle`, or "".
std::string warningLine(const std::string& warnings, const std::string& needle) {
  std::istringstream lines(warnings);
  std::string line;
  while (std::getline(lines, line)) {
    if (line.find(needle) != std::string::npos) return trimmed(line);
  }
  return {};
}

vec3 toVec3(const tinyobj::real_t* values) { return vec3(values[0], values[1], values[2]); }

// Loads each texture once per model; paths are relative to the MTL file.
class TextureCache {
 public:
  TextureCache(std::string objPath, fs::path mtlDirectory)
      : objPath_(std::move(objPath)), mtlDirectory_(std::move(mtlDirectory)) {}

  std::shared_ptr<const Texture> get(const std::string& materialName, const char* key, const std::string& name) {
    if (name.empty()) return nullptr;
    const std::string path = (mtlDirectory_ / fs::path(name)).lexically_normal().string();
    if (auto found = cache_.find(path); found != cache_.end()) return found->second;
    std::shared_ptr<const Texture> texture;
    try {
      texture = std::make_shared<const Texture>(loadTexture(path));
    } catch (const InputError& error) {
      throw InputError(objPath_ + ": material '" + materialName + "' " + key + " '" + name +
                       "' cannot be loaded: " + error.what());
    }
    cache_.emplace(path, texture);
    return texture;
  }

 private:
  std::string objPath_;
  fs::path mtlDirectory_;
  std::map<std::string, std::shared_ptr<const Texture>> cache_;
};

Material toMaterial(const tinyobj::material_t& source, TextureCache& textures) {
  Material material;
  material.name = source.name;
  material.ka = toVec3(source.ambient);
  material.kd = toVec3(source.diffuse);
  material.ks = toVec3(source.specular);
  material.shininess = source.shininess;
  material.diffuseMap = textures.get(source.name, "map_Kd", source.diffuse_texname);
  material.specularMap = textures.get(source.name, "map_Ks", source.specular_texname);
  // `norm` is the explicit normal map; many exporters put the normal map in map_Bump/bump.
  const std::string& normalName = source.normal_texname.empty() ? source.bump_texname : source.normal_texname;
  material.normalMap = textures.get(source.name, source.normal_texname.empty() ? "map_Bump" : "norm", normalName);
  return material;
}

void requireFiniteMaterial(const std::string& path, const Material& material) {
  const bool finite = std::isfinite(material.ka.x) && std::isfinite(material.ka.y) && std::isfinite(material.ka.z) &&
                      std::isfinite(material.kd.x) && std::isfinite(material.kd.y) && std::isfinite(material.kd.z) &&
                      std::isfinite(material.ks.x) && std::isfinite(material.ks.y) && std::isfinite(material.ks.z) &&
                      std::isfinite(material.shininess);
  if (!finite) throw InputError(path + ": material '" + material.name + "' has a non-finite Ka, Kd, Ks or Ns");
  if (material.shininess < 0.0f) {
    throw InputError(path + ": material '" + material.name + "' Ns must be >= 0, got " +
                     std::to_string(material.shininess));
  }
}

// One mesh under construction, with its vertices welded by (v, vt, vn) index triple.
struct MeshBuilder {
  Mesh mesh;
  std::map<std::tuple<int, int, int>, std::uint32_t> vertexByIndices;
  std::vector<int> positionIndex;  // parallel to mesh.vertices: the OBJ 'v' it came from
  std::vector<bool> needsNormal;    // parallel to mesh.vertices: the OBJ gave no normal
};

}  // namespace

ObjModel loadObj(const std::string& path) {
  const ObjPrescan prescan = prescanObj(path);

  tinyobj::ObjReaderConfig config;
  config.triangulate = true;
  config.vertex_color = false;
  tinyobj::ObjReader reader;
  if (!reader.ParseFromFile(path, config)) {
    throw InputError(path + ": " + oneLine(reader.Error().empty() ? "cannot parse the OBJ file" : reader.Error()));
  }
  // A missing MTL file, or a usemtl naming a material the MTL lacks, is only a warning to
  // tinyobjloader; the model would silently render white, so both are errors here. (A
  // usemtl in a file without any mtllib is common in exports and just means no material.)
  if (const std::string missingFile = warningLine(reader.Warning(), "Material file ["); !missingFile.empty()) {
    throw InputError(path + ": mtllib: " + missingFile);
  }
  if (const std::string missingMaterial = warningLine(reader.Warning(), "not found in .mtl");
      prescan.hasMtllib && !missingMaterial.empty()) {
    throw InputError(path + ": usemtl: " + missingMaterial);
  }

  const tinyobj::attrib_t& attrib = reader.GetAttrib();
  const AttributeCounts counts{static_cast<long long>(attrib.vertices.size() / 3),
                               static_cast<long long>(attrib.texcoords.size() / 2),
                               static_cast<long long>(attrib.normals.size() / 3)};
  const std::vector<tinyobj::material_t>& sourceMaterials = reader.GetMaterials();

  TextureCache textures(path, prescan.mtlDirectory);
  std::vector<Material> materials;
  materials.reserve(sourceMaterials.size());
  for (const tinyobj::material_t& source : sourceMaterials) {
    materials.push_back(toMaterial(source, textures));
    requireFiniteMaterial(path, materials.back());
  }

  // Material id (-1 = none) -> mesh, in order of first use.
  std::map<int, std::size_t> builderByMaterial;
  std::vector<int> materialOfBuilder;
  std::vector<MeshBuilder> builders;
  std::size_t triangleCount = 0;
  // Area-weighted face normals summed per OBJ position, for corners without a normal:
  // summing per position (not per welded vertex) keeps uv seams smooth.
  std::vector<vec3> normalSumByPosition(static_cast<std::size_t>(counts.positions), vec3(0.0f));

  auto badIndex = [&]() {
    const long long line = findBadFaceLine(path, counts);
    return InputError(path + (line > 0 ? ":" + std::to_string(line) : std::string()) +
                      ": a face references a vertex, uv or normal index outside the file's " +
                      std::to_string(counts.positions) + " v, " + std::to_string(counts.uvs) + " vt and " +
                      std::to_string(counts.normals) + " vn lines");
  };

  for (const tinyobj::shape_t& shape : reader.GetShapes()) {
    std::size_t indexOffset = 0;
    for (std::size_t face = 0; face < shape.mesh.num_face_vertices.size(); ++face) {
      const std::size_t cornerCount = shape.mesh.num_face_vertices[face];
      const std::size_t first = indexOffset;
      indexOffset += cornerCount;
      // Triangulation is on, so anything else is a degenerate face (a point or a line).
      if (cornerCount != 3) continue;
      if (++triangleCount > kMaxSceneTriangles) {
        throw InputError(path + ": more than " + std::to_string(kMaxSceneTriangles) + " triangles");
      }
      int materialId = face < shape.mesh.material_ids.size() ? shape.mesh.material_ids[face] : -1;
      if (materialId < 0 || materialId >= static_cast<int>(materials.size())) materialId = -1;
      auto [found, inserted] = builderByMaterial.try_emplace(materialId, builders.size());
      if (inserted) {
        builders.emplace_back();
        materialOfBuilder.push_back(materialId);
      }
      MeshBuilder& builder = builders[found->second];

      for (std::size_t corner = 0; corner < 3; ++corner) {
        const tinyobj::index_t& index = shape.mesh.indices[first + corner];
        if (index.vertex_index < 0 || index.vertex_index >= counts.positions ||
            index.texcoord_index >= counts.uvs || index.normal_index >= counts.normals) {
          throw badIndex();
        }
      }
      std::array<vec3, 3> cornerPositions;
      for (std::size_t corner = 0; corner < 3; ++corner) {
        const std::size_t at = 3 * static_cast<std::size_t>(shape.mesh.indices[first + corner].vertex_index);
        cornerPositions[corner] = toVec3(&attrib.vertices[at]);
      }
      // |cross| is twice the area: the sum is area-weighted.
      const vec3 areaNormal =
          glm::cross(cornerPositions[1] - cornerPositions[0], cornerPositions[2] - cornerPositions[0]);
      for (std::size_t corner = 0; corner < 3; ++corner) {
        const tinyobj::index_t& index = shape.mesh.indices[first + corner];
        normalSumByPosition[static_cast<std::size_t>(index.vertex_index)] += areaNormal;
        const auto key = std::make_tuple(index.vertex_index, std::max(index.texcoord_index, -1),
                                         std::max(index.normal_index, -1));
        auto [vertexEntry, newVertex] =
            builder.vertexByIndices.try_emplace(key, static_cast<std::uint32_t>(builder.mesh.vertices.size()));
        if (newVertex) {
          Vertex vertex;
          vertex.posModel = toVec3(&attrib.vertices[3 * static_cast<std::size_t>(index.vertex_index)]);
          if (index.texcoord_index >= 0) {
            const std::size_t uvAt = 2 * static_cast<std::size_t>(index.texcoord_index);
            vertex.uv = vec2(attrib.texcoords[uvAt], attrib.texcoords[uvAt + 1]);
          } else {
            vertex.uv = vec2(0.0f);
          }
          const bool hasNormal = index.normal_index >= 0;
          if (hasNormal) {
            vertex.nModel = toVec3(&attrib.normals[3 * static_cast<std::size_t>(index.normal_index)]);
          }
          builder.mesh.vertices.push_back(vertex);
          builder.positionIndex.push_back(index.vertex_index);
          builder.needsNormal.push_back(!hasNormal);
        }
        builder.mesh.indices.push_back(vertexEntry->second);
      }
    }
  }
  if (builders.empty()) throw InputError(path + ": the OBJ file has no triangles (no 'f' lines with 3+ corners)");

  ObjModel model;
  for (std::size_t b = 0; b < builders.size(); ++b) {
    MeshBuilder& builder = builders[b];
    Mesh& mesh = builder.mesh;
    for (std::size_t i = 0; i < mesh.vertices.size(); ++i) {
      vec3& nModel = mesh.vertices[i].nModel;
      if (builder.needsNormal[i]) nModel = normalSumByPosition[static_cast<std::size_t>(builder.positionIndex[i])];
      nModel = safeNormalize(nModel, vec3(0.0f, 1.0f, 0.0f));
    }
    computeTangents(mesh);

    const int materialId = materialOfBuilder[b];
    model.meshes.push_back(std::move(mesh));
    if (materialId >= 0) {
      model.materials.push_back(materials[static_cast<std::size_t>(materialId)]);
      model.hasMaterial.push_back(true);
    } else {
      Material none;
      none.name = "";
      model.materials.push_back(none);
      model.hasMaterial.push_back(false);
    }
  }
  return model;
}

}  // namespace twr
