// The bodies of the fuzz targets, shared by the libFuzzer executables (main_*.cpp, clang
// only) and the corpus replay test (test_corpus_replay.cpp, any compiler), so a crasher kept
// under tests/corpus/<target>/ replays through exactly the code that found it.
//
// Each target feeds raw bytes to one public entry point. InputError is the expected answer
// to bad input: it is accepted once its message is checked to name the input. Anything else
// escaping (std::bad_alloc, std::length_error, a JSON exception) and every broken promise of
// the result (InvariantViolation) is a finding: libFuzzer reports the uncaught exception as a
// crash, the replay test as a failure.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <stdexcept>
#include <string>

namespace twr::fuzz {

class InvariantViolation : public std::logic_error {
 public:
  explicit InvariantViolation(const std::string& what) : std::logic_error(what) {}
};

// A folder the targets write their input files into, with helper files the inputs may name:
// "tex.png" (a 2x2 RGBA PNG), "model.obj" (one triangle, mtllib model.mtl) and "model.mtl"
// (material "red" with map_Kd tex.png). The folder is created empty and removed again by the
// destructor.
class Workspace {
 public:
  explicit Workspace(std::filesystem::path dir);
  ~Workspace();
  Workspace(const Workspace&) = delete;
  Workspace& operator=(const Workspace&) = delete;

  const std::filesystem::path& dir() const { return dir_; }

 private:
  std::filesystem::path dir_;
};

// A fresh folder under the system temp directory, named after the process id, so parallel
// fuzzing jobs never share one.
std::filesystem::path processWorkspaceDir(const std::string& target);

// Target "scene_file": the bytes as a scene file (parseScene, paths relative to the
// workspace); an accepted scene is rendered small on the CPU and the output checked.
void fuzzSceneFile(const Workspace& workspace, const std::uint8_t* data, std::size_t size);

// Target "obj_file": the bytes up to a line "~mtl~" become fuzz.obj, the rest fuzz.mtl
// (absent without the line); loadObj must give finite, well-indexed meshes with unit
// normals and tangents, and a small model is rendered on the CPU.
void fuzzObjFile(const Workspace& workspace, const std::uint8_t* data, std::size_t size);

// Target "image_file": the bytes as an image file through loadPng and loadTexture (sizes,
// buffer lengths and the row flip are checked).
void fuzzImageFile(const Workspace& workspace, const std::uint8_t* data, std::size_t size);

// Target "pipeline": the bytes decode into random settings, camera, lights, material, tiny
// textures and triangles (hostile values: w near 0, huge, tiny, denormal) rendered by the CPU
// renderer, plus raw clip-space triangles fed to the clip, setup, raster and interpolation
// stages directly. Checked: no access outside the framebuffer (ASan), no NaN in a shaded
// colour, every depth finite and in [0, 1], spans inside the viewport.
void fuzzPipeline(const std::uint8_t* data, std::size_t size);

// The target names, as used for tests/corpus/<name>/ and the fuzz_<name> executables.
inline constexpr const char* kTargetNames[] = {"scene_file", "obj_file", "image_file", "pipeline"};

}  // namespace twr::fuzz
