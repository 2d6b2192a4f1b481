#include "glrender/gl_upload_cache.h"

#include "scene/errors.h"

#include <cstddef>
#include <cstring>
#include <string>

namespace twr {
namespace {

// layout(location) of the inputs in shaders/phong.vert.
constexpr GLuint kPosModelLocation = 0;
constexpr GLuint kNormalModelLocation = 1;
constexpr GLuint kTangentModelLocation = 2;
constexpr GLuint kUvLocation = 3;

// Vertex is four float vectors with no padding, so comparing bytes compares values (a NaN
// compares equal to the same NaN, which is what "unchanged" means here).
static_assert(sizeof(Vertex) == (3 + 3 + 4 + 2) * sizeof(float), "Vertex must have no padding bytes");

template <typename T>
bool sameBytes(const std::vector<T>& a, const std::vector<T>& b) {
  return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0);
}

// Fills `out`'s buffers from `mesh` (the vertex array's layout is set once, at creation).
void uploadMeshData(const Mesh& mesh, GlMesh& out) {
  glBindVertexArray(out.vertexArray.id());
  glBindBuffer(GL_ARRAY_BUFFER, out.vertices.id());
  glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(mesh.vertices.size() * sizeof(Vertex)),
               mesh.vertices.data(), GL_STATIC_DRAW);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, out.indices.id());
  glBufferData(GL_ELEMENT_ARRAY_BUFFER, static_cast<GLsizeiptr>(mesh.indices.size() * sizeof(std::uint32_t)),
               mesh.indices.data(), GL_STATIC_DRAW);
  glBindVertexArray(0);
  out.indexCount = static_cast<GLsizei>(mesh.indices.size());
}

GlMesh makeMesh() {
  GlMesh out{makeGlVertexArray(), makeGlBuffer(), makeGlBuffer(), 0};
  glBindVertexArray(out.vertexArray.id());
  glBindBuffer(GL_ARRAY_BUFFER, out.vertices.id());
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, out.indices.id());
  constexpr GLsizei kStride = sizeof(Vertex);
  const auto attribute = [&](GLuint location, GLint components, std::size_t offset) {
    glEnableVertexAttribArray(location);
    glVertexAttribPointer(location, components, GL_FLOAT, GL_FALSE, kStride, reinterpret_cast<const void*>(offset));
  };
  attribute(kPosModelLocation, 3, offsetof(Vertex, posModel));
  attribute(kNormalModelLocation, 3, offsetof(Vertex, nModel));
  attribute(kTangentModelLocation, 4, offsetof(Vertex, tangentModel));
  attribute(kUvLocation, 2, offsetof(Vertex, uv));
  glBindVertexArray(0);
  return out;
}

void setFilter(TextureFilter filter) {
  const GLint glFilter = filter == TextureFilter::Nearest ? GL_NEAREST : GL_LINEAR;
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, glFilter);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, glFilter);
}

// RGBA8, rows bottom first as stored, GL_REPEAT, no mipmaps, no sRGB. Binds the new texture
// to the active unit.
GlTexture uploadTexture(const Texture& texture, TextureFilter filter) {
  const std::size_t expectedBytes =
      static_cast<std::size_t>(texture.width) * static_cast<std::size_t>(texture.height) * 4;
  if (texture.width <= 0 || texture.height <= 0 || texture.rgba.size() != expectedBytes) {
    throw InputError("GL: texture '" + texture.path + "' has " + std::to_string(texture.rgba.size()) +
                     " bytes for " + std::to_string(texture.width) + " x " + std::to_string(texture.height) +
                     " RGBA8 texels (expected width * height * 4, both sides > 0)");
  }
  GlTexture out = makeGlTexture();
  glBindTexture(GL_TEXTURE_2D, out.id());
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, texture.width, texture.height, 0, GL_RGBA, GL_UNSIGNED_BYTE,
               texture.rgba.data());
  setFilter(filter);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_REPEAT);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_BASE_LEVEL, 0);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, 0);
  return out;
}

}  // namespace

void GlUploadCache::beginFrame() { ++frame_; }

const GlMesh& GlUploadCache::mesh(const Mesh& mesh) {
  auto found = meshes_.find(&mesh);
  if (found == meshes_.end()) found = meshes_.emplace(&mesh, MeshEntry{makeMesh(), {}, {}, 0}).first;
  MeshEntry& entry = found->second;
  // A new entry has empty copies, so a non-empty mesh always uploads the first time.
  const bool unchanged = sameBytes(entry.vertices, mesh.vertices) && sameBytes(entry.indices, mesh.indices);
  if (entry.gl.indexCount == 0 || !unchanged) {
    uploadMeshData(mesh, entry.gl);
    entry.vertices = mesh.vertices;
    entry.indices = mesh.indices;
    ++meshUploads_;
  }
  entry.lastFrame = frame_;
  return entry.gl;
}

GLuint GlUploadCache::texture(const std::shared_ptr<const Texture>& texture, TextureFilter filter) {
  auto found = textures_.find(texture.get());
  if (found == textures_.end()) {
    TextureEntry entry{texture, uploadTexture(*texture, filter), filter, frame_};
    ++textureUploads_;
    return textures_.emplace(texture.get(), std::move(entry)).first->second.gl.id();
  }
  TextureEntry& entry = found->second;
  glBindTexture(GL_TEXTURE_2D, entry.gl.id());
  if (entry.filter != filter) {
    setFilter(filter);
    entry.filter = filter;
  }
  entry.lastFrame = frame_;
  return entry.gl.id();
}

void GlUploadCache::endFrame() {
  std::erase_if(meshes_, [this](const auto& item) { return item.second.lastFrame != frame_; });
  std::erase_if(textures_, [this](const auto& item) { return item.second.lastFrame != frame_; });
}

}  // namespace twr
