// Meshes and textures uploaded once and kept across renders, as an application keeps its
// buffers: a frame of an unchanged scene then costs its draw calls, not a re-upload of every
// vertex and texel (which the CPU pipeline does not pay either, so `twinraster bench` is fair).
//
// When an entry may be reused:
//   mesh     found by the Mesh's address, reused only while its vertex and index bytes equal
//            the copy taken at upload; the GUI rebuilds meshes in place and a freed Mesh's
//            address can come back for another one, so the address alone proves nothing.
//   texture  found by the shared_ptr's object; the cache holds a reference, so that address
//            cannot be reused by another texture while the entry lives, and texels are const.
//            Every level is uploaded as the Texture holds it (compressed blocks when it keeps
//            them), never glGenerateMipmap: both renderers must sample the same chain bytes.
//            A changed filter or wrap re-sets the parameter; a changed srgb re-uploads.
// Entries one render does not use are dropped when it ends (endFrame), so memory follows the
// scene. GL objects belong to the context that was current when they were made: one cache
// per context.
#pragma once

#include "glrender/gl_objects.h"
#include "scene/environment.h"
#include "scene/mesh.h"
#include "scene/settings.h"
#include "scene/texture.h"

#include <cstdint>
#include <map>
#include <memory>
#include <vector>

namespace twr {

// One interleaved VBO of twr::Vertex (position, normal, tangent with sign, uv) + an IBO.
struct GlMesh {
  GlVertexArray vertexArray;
  GlBuffer vertices;
  GlBuffer indices;
  GLsizei indexCount = 0;
};

class GlUploadCache {
 public:
  // Starts a render: entries used from now on are kept by the next endFrame().
  void beginFrame();
  // The uploaded mesh for `mesh`, uploading (or re-uploading changed bytes) when needed.
  const GlMesh& mesh(const Mesh& mesh);
  // Binds the texture object for `texture`, with `filter`, `anisotropy` (1: isotropic) and the
  // texture's wrap set, to the
  // active unit and returns it; throws InputError when the texture cannot be uploaded (wrong
  // byte count, a side of 0, a level not half the previous one, a compressed level's size).
  GLuint texture(const std::shared_ptr<const Texture>& texture, TextureFilter filter, float anisotropy = 1.0f);
  // Binds the GL_TEXTURE_CUBE_MAP for `cube` to the active unit and returns it: every level
  // of the six faces as GL_RGB32F, the floats the CPU samples (scene/environment.h), filtered
  // GL_LINEAR_MIPMAP_LINEAR / GL_LINEAR. Seamless filtering is the context's
  // (GL_TEXTURE_CUBE_MAP_SEAMLESS, enabled by the caller). Held like a texture (see above).
  GLuint cubeMap(const std::shared_ptr<const CubeMap>& cube);
  // Binds the GL_TEXTURE_2D_ARRAY for a sphere or dual-paraboloid map (one layer or two) to
  // the active unit and returns it: every level as GL_RGB32F, GL_LINEAR_MIPMAP_LINEAR /
  // GL_LINEAR, GL_CLAMP_TO_EDGE (layer_sample-inl.h models the same). Held like a texture.
  GLuint environmentLayers(const std::shared_ptr<const ParameterizedMap>& map);
  // Drops what the render since beginFrame() did not use.
  void endFrame();

  std::size_t meshUploads() const { return meshUploads_; }        // since construction
  std::size_t textureUploads() const { return textureUploads_; }  // since construction

 private:
  struct MeshEntry {
    GlMesh gl;
    std::vector<Vertex> vertices;       // the bytes uploaded, to detect a changed mesh
    std::vector<std::uint32_t> indices;
    std::uint64_t lastFrame = 0;
  };
  struct TextureEntry {
    std::shared_ptr<const Texture> texture;  // held: keeps the address unique
    GlTexture gl;
    TextureFilter filter = TextureFilter::Bilinear;
    TextureWrap wrap = TextureWrap::Repeat;  // as set on the GL object
    bool srgb = false;                        // as uploaded
    float anisotropy = 1.0f;                  // GL_TEXTURE_MAX_ANISOTROPY as set
    std::uint64_t lastFrame = 0;
  };

  std::map<const Mesh*, MeshEntry> meshes_;
  struct CubeEntry {
    std::shared_ptr<const CubeMap> cube;  // held: keeps the address unique
    GlTexture gl;
    std::uint64_t lastFrame = 0;
  };
  std::map<const Texture*, TextureEntry> textures_;
  std::map<const CubeMap*, CubeEntry> cubes_;
  struct LayersEntry {
    std::shared_ptr<const ParameterizedMap> map;  // held: keeps the address unique
    GlTexture gl;
    std::uint64_t lastFrame = 0;
  };
  std::map<const ParameterizedMap*, LayersEntry> layers_;
  std::uint64_t frame_ = 0;
  std::size_t meshUploads_ = 0;
  std::size_t textureUploads_ = 0;
};

// Sets GL_TEXTURE_MAX_ANISOTROPY of the texture bound to the active unit to `anisotropy`
// clamped to [1, GL_MAX_TEXTURE_MAX_ANISOTROPY]; false (nothing set) when the context offers
// neither EXT_ nor ARB_texture_filter_anisotropic.
bool setGlTextureAnisotropy(float anisotropy);

}  // namespace twr
