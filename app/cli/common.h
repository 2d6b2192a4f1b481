// Options shared by the subcommands that render: scene loading and setting overrides.
#pragma once

#include "scene/scene.h"

#include <CLI/CLI.hpp>

#include <optional>
#include <string>

namespace twr::cli {

struct RenderRequest {
  std::string scenePath;
  std::optional<int> width, height;  // default: the scene's output size
  std::string view;                   // default: the scene's settings.view
  std::string cull, frontFace, lightingSpace, tangentTransform, textureFilter;  // optional overrides
  bool verbose = false;
};

// Adds SCENE, --width/--height, --view and the setting overrides to `cmd`.
void addRenderOptions(CLI::App& cmd, RenderRequest& request);

// Loads the scene and applies the overrides; throws InputError (exit 2) on bad input.
Scene loadRequestedScene(const RenderRequest& request);
int requestedWidth(const RenderRequest& request, const Scene& scene);
int requestedHeight(const RenderRequest& request, const Scene& scene);


}  // namespace twr::cli
