// Render settings: plain structs the scene file fills, the UI edits, both renderers read.
#pragma once

#include "scene/conventions.h"

#include <string>
#include <string_view>
#include <vector>

namespace twr {

enum class CullMode { None, Back, Front };
enum class FrontFace { Ccw, Cw };
enum class View { Shaded, Albedo, Normal, Tangent, Bitangent, MappedNormal, Uv, Depth, LightTangent, EyeTangent };
enum class LightingSpace { World, Tangent };
enum class TangentTransform { Model, InverseTranspose };
enum class TextureFilter { Nearest, Bilinear };
enum class LineMode { Core, Immediate };

// Each frustum plane of the homogeneous clipper, on (true) or off.
struct ClipSwitches {
  bool left = true, right = true, bottom = true, top = true, near = true, far = true;
};

struct TbnLines {
  bool enabled = false;
  float length = 0.1f;             // world units
  LineMode mode = LineMode::Core;  // immediate needs a compatibility context (GL only)
};

struct RenderSettings {
  CullMode cull = CullMode::Back;
  FrontFace frontFace = FrontFace::Ccw;
  ClipSwitches clip;
  std::vector<vec4> userClipPlanes;  // world space, keeps a*x + b*y + c*z + d >= 0
  View view = View::Shaded;
  LightingSpace lightingSpace = LightingSpace::World;
  TangentTransform tangentTransform = TangentTransform::Model;
  TextureFilter textureFilter = TextureFilter::Bilinear;
  TbnLines tbnLines;
};

// Names as written in scene files and on the command line.
std::string_view toString(CullMode v);
std::string_view toString(FrontFace v);
std::string_view toString(View v);
std::string_view toString(LightingSpace v);
std::string_view toString(TangentTransform v);
std::string_view toString(TextureFilter v);
std::string_view toString(LineMode v);

// Parsers return false for an unknown name.
bool parse(std::string_view s, CullMode& out);
bool parse(std::string_view s, FrontFace& out);
bool parse(std::string_view s, View& out);
bool parse(std::string_view s, LightingSpace& out);
bool parse(std::string_view s, TangentTransform& out);
bool parse(std::string_view s, TextureFilter& out);
bool parse(std::string_view s, LineMode& out);

// "shaded|albedo|..." for help texts and error messages.
std::string allViewNames();
inline constexpr View kAllViews[] = {View::Shaded, View::Albedo, View::Normal, View::Tangent, View::Bitangent,
                                     View::MappedNormal, View::Uv, View::Depth, View::LightTangent,
                                     View::EyeTangent};

}  // namespace twr
