// JSON scene files (docs/scene-format.md). Unknown keys are errors; every key but "nodes"
// has a default. Paths are relative to the scene file.
#pragma once

#include "scene/scene.h"

#include <cstdint>
#include <string>
#include <string_view>

namespace twr {

// Largest scene file (inclusive, bytes): the parsed JSON takes up to about 20 times its text.
inline constexpr std::uintmax_t kMaxSceneFileBytes = 32ull * 1024 * 1024;
// Deepest JSON nesting accepted (inclusive; the top-level object is level 1). Nodes may nest
// 64 deep, and each node level is two JSON levels (node object, "children" array).
inline constexpr int kMaxJsonDepth = 160;
// Most nodes (all levels together) and materials a scene may hold (inclusive). Far beyond any
// scene drawn here (the triangle cap is 20 million); each takes about 200 bytes once read, and
// a file at the size cap could otherwise list 10 million empty ones (2 GB, 4 s).
inline constexpr std::size_t kMaxSceneNodes = 1'000'000;
inline constexpr std::size_t kMaxSceneMaterials = 1'000'000;

// Throws InputError: "<file>: <json path>: <what was expected>" (or the JSON line/column).
Scene loadSceneFile(const std::string& path);
// Parses from a string; `nameForMessages` stands in for the file name, `baseDir` for
// resolving relative paths.
Scene parseScene(const std::string& json, const std::string& nameForMessages, const std::string& baseDir);

// Mesh type names as written in scene files ("cube", "sphere", ..., "triangles").
std::string_view toString(MeshType type);

}  // namespace twr
