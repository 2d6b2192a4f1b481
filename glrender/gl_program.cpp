#include "glrender/gl_program.h"

#include "glrender/embedded_shaders.h"
#include "scene/conventions.h"
#include "scene/environment.h"
#include "scene/errors.h"
#include "scene/shadow_map.h"

#include <cstdio>
#include <fstream>
#include <cctype>
#include <optional>
#include <sstream>

namespace twr {
namespace {

// Constants the GLSL shares with the C++ side, so neither writes a second copy.
std::string sharedConstants() {
  char buffer[640];
  std::snprintf(buffer, sizeof buffer,
                "#define MAX_LIGHTS %d\n"
                "#define MAX_CLIP_PLANES %d\n"
                "#define MIN_LENGTH_SQUARED %.9e\n"
                "#define MIN_ATTENUATION_DENOMINATOR %.9e\n"
                "#define MIN_PARALLAX_VIEW_Z %.9e\n"
                "#define SELF_SHADOW_SHARPNESS %.9e\n"
                "#define HORIZON_SHARPNESS %.9e\n"
                "#define PARALLAX_OFFSET_VIEW_GAIN %.9e\n"
                "#define ENVIRONMENT_LOD_VIEW_MAX %.9e\n",
                kMaxLights, kMaxUserClipPlanes, static_cast<double>(kMinLengthSquared),
                static_cast<double>(kMinAttenuationDenominator), static_cast<double>(kMinParallaxViewZ),
                static_cast<double>(kSelfShadowSharpness), static_cast<double>(kHorizonSharpness),
                static_cast<double>(kParallaxOffsetViewGain), static_cast<double>(kEnvironmentLodViewMax));
  const auto colour = [](const char* name, const float (&c)[3]) {
    char line[160];
    std::snprintf(line, sizeof line, "#define %s vec3(%.9e, %.9e, %.9e)\n", name, static_cast<double>(c[0]),
                  static_cast<double>(c[1]), static_cast<double>(c[2]));
    return std::string(line);
  };
  char shadow[320];
  std::snprintf(shadow, sizeof shadow,
                "#define MAX_SHADOWED_LIGHTS %d\n"
                "#define MAX_SHADOW_SLOPE_TANGENT %.9e\n"
                "#define MIN_SHADOW_COSINE %.9e\n"
                "#define SHADOW_ACNE_TEXELS %.9e\n",
                kMaxShadowedLights, static_cast<double>(kMaxShadowSlopeTangent), static_cast<double>(kMinShadowCosine),
                static_cast<double>(kShadowAcneTexels));
  return std::string(buffer) + shadow + colour("SHADOW_VIEW_LIT", kShadowViewLit) +
         colour("SHADOW_VIEW_SHADOWED", kShadowViewShadowed) + colour("SHADOW_VIEW_ACNE", kShadowViewAcne) +
         colour("SHADOW_VIEW_AWAY", kShadowViewAway) + colour("LIGHT_DEPTH_OUTSIDE", kLightDepthOutside);
}

std::string describeDefines(const std::vector<std::string>& defines) {
  if (defines.empty()) return "no defines";
  std::string text = "defines:";
  for (const std::string& define : defines) text += " " + define;
  return text;
}

// Source string 0 is the prelude, file k of the stage is source string k + 1, so the
// log's "S:L(C)" locations name the file (Mesa writes "0:12(7): error: ...").
std::string assembleStage(const ShaderLibrary& library, const std::vector<std::string>& files,
                          const std::vector<std::string>& defines) {
  std::string source = "#version 330 core\n" + sharedConstants();
  for (const std::string& define : defines) source += "#define " + define + "\n";
  for (std::size_t i = 0; i < files.size(); ++i) {
    source += "#line 1 " + std::to_string(i + 1) + "\n";
    source += library.text(files[i]);
    if (!source.empty() && source.back() != '\n') source += '\n';
  }
  return source;
}

// A log line's location "S:L(C): " (source string, line, column), as Mesa writes it.
struct LogLocation {
  std::size_t source = 0;
  std::string line, column, message;
};

// Reads digits from text[pos], advancing pos; empty when there are none.
std::string readDigits(const std::string& text, std::size_t& pos) {
  const std::size_t start = pos;
  while (pos < text.size() && std::isdigit(static_cast<unsigned char>(text[pos]))) ++pos;
  return text.substr(start, pos - start);
}

std::optional<LogLocation> parseLocation(const std::string& text) {
  std::size_t pos = 0;
  const std::string source = readDigits(text, pos);
  if (source.empty() || pos >= text.size() || text[pos++] != ':') return std::nullopt;
  LogLocation location;
  location.line = readDigits(text, pos);
  if (location.line.empty() || pos >= text.size() || text[pos++] != '(') return std::nullopt;
  location.column = readDigits(text, pos);
  if (location.column.empty() || text.compare(pos, 2, "):") != 0) return std::nullopt;
  pos += 2;
  while (pos < text.size() && text[pos] == ' ') ++pos;
  location.source = std::stoul(source);
  location.message = text.substr(pos);
  return location;
}

std::string mapLog(const ShaderLibrary& library, const std::vector<std::string>& files, const std::string& log) {
  std::stringstream in(log);
  std::string line;
  std::string mapped;
  while (std::getline(in, line)) {
    if (line.empty()) continue;
    const std::optional<LogLocation> location = parseLocation(line);
    if (!location) {
      mapped += line + "\n";
      continue;
    }
    const std::size_t source = location->source;
    const std::string file = source == 0             ? "<prelude>"
                             : source <= files.size() ? library.displayName(files[source - 1])
                                                      : "<source " + std::to_string(source) + ">";
    mapped += file + ":" + location->line + ":" + location->column + ": " + location->message + "\n";
  }
  return mapped;
}

std::string infoLog(GLuint object, bool isProgram) {
  GLint length = 0;
  if (isProgram) {
    glGetProgramiv(object, GL_INFO_LOG_LENGTH, &length);
  } else {
    glGetShaderiv(object, GL_INFO_LOG_LENGTH, &length);
  }
  if (length <= 0) return "";
  std::string log(static_cast<std::size_t>(length), '\0');
  if (isProgram) {
    glGetProgramInfoLog(object, length, nullptr, log.data());
  } else {
    glGetShaderInfoLog(object, length, nullptr, log.data());
  }
  while (!log.empty() && (log.back() == '\0' || log.back() == '\n')) log.pop_back();
  return log;
}

GlShader compileStage(const ShaderLibrary& library, const ProgramDesc& desc, GLenum stage,
                      const std::vector<std::string>& files) {
  const std::string source = assembleStage(library, files, desc.defines);
  GlShader shader(glCreateShader(stage));
  const char* text = source.c_str();
  glShaderSource(shader.id(), 1, &text, nullptr);
  glCompileShader(shader.id());
  GLint ok = GL_FALSE;
  glGetShaderiv(shader.id(), GL_COMPILE_STATUS, &ok);
  if (ok != GL_TRUE) {
    const std::string stageName = stage == GL_VERTEX_SHADER ? "vertex" : "fragment";
    throw InputError("GL: GLSL " + stageName + " shader of program '" + desc.name + "' (" +
                     describeDefines(desc.defines) + ") failed to compile:\n" +
                     mapLog(library, files, infoLog(shader.id(), false)));
  }
  return shader;
}

std::string joinFiles(const ShaderLibrary& library, const std::vector<std::string>& files) {
  std::string text;
  for (const std::string& file : files) text += (text.empty() ? "" : ", ") + library.displayName(file);
  return text;
}

}  // namespace

std::string ShaderLibrary::text(const std::string& file) const {
  if (shaderDir_.empty()) {
    for (const EmbeddedShader& shader : embeddedShaders()) {
      if (file == shader.name) return shader.source;
    }
    throw InputError("GL: no embedded shader named '" + file + "' (is it in shaders/?)");
  }
  const std::string path = displayName(file);
  std::ifstream stream(path, std::ios::binary);
  if (!stream) throw InputError("GL: cannot read shader file '" + path + "'");
  std::stringstream text;
  text << stream.rdbuf();
  return text.str();
}

std::string ShaderLibrary::displayName(const std::string& file) const {
  if (shaderDir_.empty()) return "shaders/" + file + " (embedded)";
  return shaderDir_ + "/" + file;
}

GLuint ProgramCache::get(const ProgramDesc& desc) {
  std::string key = desc.name;
  for (const auto& list : {desc.vertexFiles, desc.fragmentFiles, desc.defines}) {
    key += "|";
    for (const std::string& item : list) key += item + ";";
  }
  if (auto found = programs_.find(key); found != programs_.end()) return found->second.id();

  const GlShader vertex = compileStage(library_, desc, GL_VERTEX_SHADER, desc.vertexFiles);
  const GlShader fragment = compileStage(library_, desc, GL_FRAGMENT_SHADER, desc.fragmentFiles);
  GlProgram program(glCreateProgram());
  glAttachShader(program.id(), vertex.id());
  glAttachShader(program.id(), fragment.id());
  glLinkProgram(program.id());
  GLint ok = GL_FALSE;
  glGetProgramiv(program.id(), GL_LINK_STATUS, &ok);
  if (ok != GL_TRUE) {
    throw InputError("GL: GLSL program '" + desc.name + "' (" + describeDefines(desc.defines) +
                     ") failed to link (vertex: " + joinFiles(library_, desc.vertexFiles) +
                     "; fragment: " + joinFiles(library_, desc.fragmentFiles) + "):\n" +
                     infoLog(program.id(), true));
  }
  glDetachShader(program.id(), vertex.id());
  glDetachShader(program.id(), fragment.id());
  const GLuint id = program.id();
  programs_.emplace(std::move(key), std::move(program));
  return id;
}

}  // namespace twr
