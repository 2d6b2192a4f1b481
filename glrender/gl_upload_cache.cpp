#include "glrender/gl_upload_cache.h"

#include "scene/errors.h"

#include <algorithm>
#include <cstddef>
#include <cstring>
#include <string>
#include <vector>

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

// GL's name of each filter (scene/settings.h). Magnification has no mip levels: it takes the
// texel filter alone, GL_NEAREST for the nearest* filters, GL_LINEAR for the others.
GLint minFilterOf(TextureFilter filter) {
  switch (filter) {
    case TextureFilter::Nearest: return GL_NEAREST;
    case TextureFilter::Bilinear: return GL_LINEAR;
    case TextureFilter::Trilinear: return GL_LINEAR_MIPMAP_LINEAR;
    case TextureFilter::NearestMipmapNearest: return GL_NEAREST_MIPMAP_NEAREST;
    case TextureFilter::LinearMipmapNearest: return GL_LINEAR_MIPMAP_NEAREST;
    case TextureFilter::NearestMipmapLinear: return GL_NEAREST_MIPMAP_LINEAR;
  }
  return GL_LINEAR;
}

void setFilter(TextureFilter filter) {
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, minFilterOf(filter));
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, texelsLinear(filter) ? GL_LINEAR : GL_NEAREST);
}

GLint wrapOf(TextureWrap wrap) {
  switch (wrap) {
    case TextureWrap::Repeat: return GL_REPEAT;
    case TextureWrap::MirroredRepeat: return GL_MIRRORED_REPEAT;
    case TextureWrap::ClampToEdge: return GL_CLAMP_TO_EDGE;
  }
  return GL_REPEAT;
}

void setWrap(TextureWrap wrap) {
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, wrapOf(wrap));
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, wrapOf(wrap));
}

// The compressed internal format of `format` (EXT_texture_compression_s3tc, EXT_texture_sRGB,
// RGTC, all in the glad header). BC4 and BC5 hold data, never colour: the loader turns srgb
// off for them (scene/texture.cpp), so there is no sRGB RGTC format to pick.
GLenum compressedFormatOf(BlockFormat format, bool srgb) {
  switch (format) {
    case BlockFormat::Bc1: return srgb ? GL_COMPRESSED_SRGB_ALPHA_S3TC_DXT1_EXT : GL_COMPRESSED_RGBA_S3TC_DXT1_EXT;
    case BlockFormat::Bc2: return srgb ? GL_COMPRESSED_SRGB_ALPHA_S3TC_DXT3_EXT : GL_COMPRESSED_RGBA_S3TC_DXT3_EXT;
    case BlockFormat::Bc3: return srgb ? GL_COMPRESSED_SRGB_ALPHA_S3TC_DXT5_EXT : GL_COMPRESSED_RGBA_S3TC_DXT5_EXT;
    case BlockFormat::Bc4: return GL_COMPRESSED_RED_RGTC1;
    case BlockFormat::Bc5: return GL_COMPRESSED_RG_RGTC2;
  }
  return GL_COMPRESSED_RGBA_S3TC_DXT1_EXT;
}

[[noreturn]] void throwBadLevel(const Texture& texture, int level, const std::string& what) {
  throw InputError("GL: texture '" + texture.path + "' level " + std::to_string(level) + ": " + what);
}

// Every level must have the size GL expects after the one before (floor(previous / 2), at
// least 1) and its bytes: otherwise GL would silently sample an incomplete texture as black.
void checkLevels(const Texture& texture) {
  for (int level = 0; level < texture.levelCount(); ++level) {
    const int width = texture.levelWidth(level), height = texture.levelHeight(level);
    const std::size_t bytes = texture.levelTexels(level).size();
    const std::size_t expectedBytes = static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 4;
    if (width <= 0 || height <= 0 || bytes != expectedBytes) {
      throwBadLevel(texture, level, std::to_string(bytes) + " bytes for " + std::to_string(width) + " x " +
                                        std::to_string(height) +
                                        " RGBA8 texels (expected width * height * 4, both sides > 0)");
    }
    if (level > 0) {
      const int expectedWidth = std::max(texture.levelWidth(level - 1) / 2, 1);
      const int expectedHeight = std::max(texture.levelHeight(level - 1) / 2, 1);
      if (width != expectedWidth || height != expectedHeight) {
        throwBadLevel(texture, level, std::to_string(width) + " x " + std::to_string(height) + ", expected " +
                                          std::to_string(expectedWidth) + " x " + std::to_string(expectedHeight) +
                                          " (each side half the previous level's, at least 1)");
      }
    }
  }
  if (texture.blockFormat) {
    if (texture.blockLevels.size() != static_cast<std::size_t>(texture.levelCount())) {
      throw InputError("GL: texture '" + texture.path + "' has " + std::to_string(texture.blockLevels.size()) +
                       " compressed levels for " + std::to_string(texture.levelCount()) +
                       " levels (expected one per level)");
    }
    for (int level = 0; level < texture.levelCount(); ++level) {
      const std::size_t expected =
          blockLevelBytes(*texture.blockFormat, texture.levelWidth(level), texture.levelHeight(level));
      const std::size_t bytes = texture.blockLevels[static_cast<std::size_t>(level)].size();
      if (bytes != expected) {
        throwBadLevel(texture, level, std::to_string(bytes) + " bytes of " +
                                          std::string(toString(*texture.blockFormat)) + " blocks, expected " +
                                          std::to_string(expected));
      }
    }
  }
}

// Every level the texture holds, as they are: GL receives the chain both renderers sample
// (never glGenerateMipmap, whose filter is the driver's), compressed when the texture keeps
// its file's blocks, else RGBA8 (sRGB8_ALPHA8 with options.srgb). Rows bottom first as stored.
// Binds the new texture to the active unit.
GlTexture uploadTexture(const Texture& texture, TextureFilter filter) {
  checkLevels(texture);
  GlTexture out = makeGlTexture();
  glBindTexture(GL_TEXTURE_2D, out.id());
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  for (int level = 0; level < texture.levelCount(); ++level) {
    const GLsizei width = texture.levelWidth(level), height = texture.levelHeight(level);
    if (texture.blockFormat) {
      const std::vector<std::uint8_t>& blocks = texture.blockLevels[static_cast<std::size_t>(level)];
      glCompressedTexImage2D(GL_TEXTURE_2D, level, compressedFormatOf(*texture.blockFormat, texture.options.srgb),
                             width, height, 0, static_cast<GLsizei>(blocks.size()), blocks.data());
    } else {
      const GLint internalFormat = texture.options.srgb ? GL_SRGB8_ALPHA8 : GL_RGBA8;
      glTexImage2D(GL_TEXTURE_2D, level, internalFormat, width, height, 0, GL_RGBA, GL_UNSIGNED_BYTE,
                   texture.levelTexels(level).data());
    }
  }
  setFilter(filter);
  setWrap(texture.options.wrap);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_BASE_LEVEL, 0);
  // The chain may stop before 1 x 1 (a DDS file's own): the last level held is the last one.
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, texture.levelCount() - 1);
  return out;
}

}  // namespace

bool setGlTextureAnisotropy(float anisotropy) {
  // Core in GL 4.6; in 3.3 only through one of the two extensions (llvmpipe offers them).
  if (!GLAD_GL_EXT_texture_filter_anisotropic && !GLAD_GL_ARB_texture_filter_anisotropic) return false;
  GLfloat most = 1.0f;
  glGetFloatv(GL_MAX_TEXTURE_MAX_ANISOTROPY, &most);
  glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_MAX_ANISOTROPY, std::clamp(anisotropy, 1.0f, most));
  return true;
}

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

GLuint GlUploadCache::texture(const std::shared_ptr<const Texture>& texture, TextureFilter filter, float anisotropy) {
  auto found = textures_.find(texture.get());
  if (found == textures_.end()) {
    TextureEntry entry{texture, uploadTexture(*texture, filter), filter, texture->options.wrap,
                       texture->options.srgb, 1.0f, frame_};
    if (anisotropy != 1.0f && setGlTextureAnisotropy(anisotropy)) entry.anisotropy = anisotropy;
    ++textureUploads_;
    return textures_.emplace(texture.get(), std::move(entry)).first->second.gl.id();
  }
  TextureEntry& entry = found->second;
  glBindTexture(GL_TEXTURE_2D, entry.gl.id());
  if (entry.filter != filter) {
    setFilter(filter);
    entry.filter = filter;
  }
  if (entry.anisotropy != anisotropy && setGlTextureAnisotropy(anisotropy)) entry.anisotropy = anisotropy;
  // The options are plain fields an owner may change between renders on the same object:
  // the wrap costs a parameter, sRGB a new upload (another internal format).
  if (entry.srgb != texture->options.srgb) {
    entry.gl = uploadTexture(*texture, filter);
    entry.anisotropy = 1.0f;
    if (anisotropy != 1.0f && setGlTextureAnisotropy(anisotropy)) entry.anisotropy = anisotropy;
    entry.srgb = texture->options.srgb;
    entry.wrap = texture->options.wrap;
    ++textureUploads_;
  } else if (entry.wrap != texture->options.wrap) {
    setWrap(texture->options.wrap);
    entry.wrap = texture->options.wrap;
  }
  entry.lastFrame = frame_;
  return entry.gl.id();
}

GLuint GlUploadCache::cubeMap(const std::shared_ptr<const CubeMap>& cube) {
  auto found = cubes_.find(cube.get());
  if (found != cubes_.end()) {
    found->second.lastFrame = frame_;
    glBindTexture(GL_TEXTURE_CUBE_MAP, found->second.gl.id());
    return found->second.gl.id();
  }
  CubeEntry entry;
  entry.cube = cube;
  entry.gl = makeGlTexture();
  entry.lastFrame = frame_;
  glBindTexture(GL_TEXTURE_CUBE_MAP, entry.gl.id());
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  std::vector<float> rgb;
  for (int level = 0; level < cube->levelCount(); ++level) {
    const CubeMapLevel& lv = cube->levels[static_cast<std::size_t>(level)];
    const std::size_t texels = static_cast<std::size_t>(lv.size) * static_cast<std::size_t>(lv.size);
    rgb.resize(texels * 3);
    for (int face = 0; face < kCubeFaces; ++face) {
      // Interleaved RGB from the planar channels; row 0 of the upload is the face's t = 0.
      const std::size_t first = lv.index(face, 0, 0);
      for (std::size_t i = 0; i < texels; ++i) {
        rgb[i * 3] = lv.r[first + i];
        rgb[i * 3 + 1] = lv.g[first + i];
        rgb[i * 3 + 2] = lv.b[first + i];
      }
      glTexImage2D(static_cast<GLenum>(GL_TEXTURE_CUBE_MAP_POSITIVE_X + face), level, GL_RGB32F, lv.size, lv.size, 0,
                   GL_RGB, GL_FLOAT, rgb.data());
    }
  }
  glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_BASE_LEVEL, 0);
  glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MAX_LEVEL, cube->levelCount() - 1);
  glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
  glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  // llvmpipe ignores the wrap of a seamless cube; set to what the CPU models all the same.
  glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_WRAP_R, GL_CLAMP_TO_EDGE);
  const GLuint id = entry.gl.id();
  cubes_.emplace(cube.get(), std::move(entry));
  ++textureUploads_;
  return id;
}

GLuint GlUploadCache::environmentLayers(const std::shared_ptr<const ParameterizedMap>& map) {
  auto found = layers_.find(map.get());
  if (found != layers_.end()) {
    found->second.lastFrame = frame_;
    glBindTexture(GL_TEXTURE_2D_ARRAY, found->second.gl.id());
    return found->second.gl.id();
  }
  LayersEntry entry;
  entry.map = map;
  entry.gl = makeGlTexture();
  entry.lastFrame = frame_;
  glBindTexture(GL_TEXTURE_2D_ARRAY, entry.gl.id());
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  std::vector<float> rgb;
  for (int level = 0; level < map->levelCount(); ++level) {
    const CubeMapLevel& lv = map->levels[static_cast<std::size_t>(level)];
    // Interleaved RGB from the planar channels, layer after layer; row 0 is v = 0.
    rgb.resize(lv.r.size() * 3);
    for (std::size_t i = 0; i < lv.r.size(); ++i) {
      rgb[i * 3] = lv.r[i];
      rgb[i * 3 + 1] = lv.g[i];
      rgb[i * 3 + 2] = lv.b[i];
    }
    glTexImage3D(GL_TEXTURE_2D_ARRAY, level, GL_RGB32F, lv.size, lv.size, map->layers, 0, GL_RGB, GL_FLOAT, rgb.data());
  }
  glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_BASE_LEVEL, 0);
  glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MAX_LEVEL, map->levelCount() - 1);
  glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
  glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  const GLuint id = entry.gl.id();
  layers_.emplace(map.get(), std::move(entry));
  ++textureUploads_;
  return id;
}

void GlUploadCache::endFrame() {
  std::erase_if(meshes_, [this](const auto& item) { return item.second.lastFrame != frame_; });
  std::erase_if(textures_, [this](const auto& item) { return item.second.lastFrame != frame_; });
  std::erase_if(cubes_, [this](const auto& item) { return item.second.lastFrame != frame_; });
  std::erase_if(layers_, [this](const auto& item) { return item.second.lastFrame != frame_; });
}

}  // namespace twr
