// What a loaded scene holds, for `twinraster info`: as text (the node tree, totals, materials,
// lights, environment, camera, output, settings) or as one JSON object with the same content.
#pragma once

#include "scene/scene.h"

#include <nlohmann/json_fwd.hpp>  // declarations only: json.hpp costs 4 s per source that includes it

#include <ostream>

namespace twr {

// The keys: scene, nodes, triangles, vertices, materials, lights, ambient, environment, camera,
// settings, output (docs/cli.md); floats as their shortest decimal (0.05, not 0.0500000007).
nlohmann::ordered_json sceneDescriptionJson(const Scene& scene);

void printSceneDescription(std::ostream& out, const Scene& scene);

}  // namespace twr
