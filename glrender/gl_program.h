// GLSL programs: sources from the embedded copies of shaders/ or from a folder on disk,
// a prelude with #version and the permutation's #defines, compile and link errors mapped
// back to file:line, and a cache so each permutation compiles once per context.
#pragma once

#include "glrender/gl_objects.h"

#include <map>
#include <string>
#include <vector>

namespace twr {

// Where shader text comes from: the copies embedded at build time, or a folder.
class ShaderLibrary {
 public:
  explicit ShaderLibrary(std::string shaderDir) : shaderDir_(std::move(shaderDir)) {}
  // The text of `file` (e.g. "phong.frag"); throws InputError when it does not exist.
  std::string text(const std::string& file) const;
  // How messages name `file`: its path on disk, or "shaders/<file> (embedded)".
  std::string displayName(const std::string& file) const;

 private:
  std::string shaderDir_;
};

struct ProgramDesc {
  std::string name;                       // for messages, e.g. "phong"
  std::vector<std::string> vertexFiles;   // joined in order into one vertex shader
  std::vector<std::string> fragmentFiles;
  std::vector<std::string> defines;       // each becomes "#define X" after #version
};

class ProgramCache {
 public:
  explicit ProgramCache(ShaderLibrary library) : library_(std::move(library)) {}
  // The linked program for `desc`, compiled on first use. Throws InputError with the
  // GLSL log mapped to file:line when compiling or linking fails.
  GLuint get(const ProgramDesc& desc);

 private:
  ShaderLibrary library_;
  std::map<std::string, GlProgram> programs_;  // key: name, files and defines
};

// glGetUniformLocation with a std::string-free call site; -1 when the program does not use it.
inline GLint uniformLocation(GLuint program, const char* name) { return glGetUniformLocation(program, name); }

}  // namespace twr
