// GLSL sources embedded at build time (cmake/EmbedShadersScript.cmake writes the table).
#pragma once

#include <string>
#include <vector>

namespace twr {

struct EmbeddedShader {
  const char* name;    // file name in shaders/, e.g. "phong.frag"
  const char* source;  // the file's text
};

const std::vector<EmbeddedShader>& embeddedShaders();

}  // namespace twr
