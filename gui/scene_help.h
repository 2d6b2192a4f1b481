// The Scene tab's words and counts: what each surface-detail and self-shadowing method does (its
// tooltip) and how many nodes share a mesh. No ImGui here, so tests/gui reads them without a
// window.
#pragma once

#include "scene/scene.h"
#include "scene/settings.h"

#include <vector>

namespace twr::gui {

// What a method does, for its tooltip, starting with its scene-file name
// (docs/parallax.md derives them). Never null; "" for a value outside the enum.
const char* surfaceDetailHelp(SurfaceDetail method);
const char* selfShadowHelp(SelfShadow shadow);

// How many nodes, at any depth below `nodes`, draw mesh `meshIndex`.
int countNodesUsingMesh(const std::vector<Node>& nodes, int meshIndex);

}  // namespace twr::gui
