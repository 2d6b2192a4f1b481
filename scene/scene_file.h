// JSON scene files (docs/scene-format.md). Unknown keys are errors; every key but "nodes"
// has a default. Paths are relative to the scene file.
#pragma once

#include "scene/scene.h"

#include <string>
#include <string_view>

namespace twr {

// Throws InputError: "<file>: <json path>: <what was expected>" (or the JSON line/column).
Scene loadSceneFile(const std::string& path);
// Parses from a string; `nameForMessages` stands in for the file name, `baseDir` for
// resolving relative paths.
Scene parseScene(const std::string& json, const std::string& nameForMessages, const std::string& baseDir);

// Mesh type names as written in scene files ("cube", "sphere", ..., "triangles").
std::string_view toString(MeshType type);

}  // namespace twr
