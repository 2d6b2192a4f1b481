// A frame that shows nothing: a comparison of two empty frames agrees perfectly and proves
// nothing, so every command that draws a frame says so, and `compare --targets` fails on it
// unless the scene expects it (output.expect_empty, for tests of clipping and culling).
#pragma once

#include "scene/renderer.h"
#include "scene/scene.h"

#include <string>

namespace twr {

// Empty when `frame` covers a pixel (coveredAt). Else why nothing was drawn, in a user's terms,
// from the frame's statistics: no triangles at all; every triangle culled (or of zero area);
// every triangle outside the view; or triangles drawn that cover no pixel centre. Only the CPU
// renderer counts what its clipper and culler removed: for another's frame (`clipStats` false)
// the reason says so instead of guessing. Then the scene's bounds and the camera, so the reader
// can see where the model is and where the camera looks.
std::string emptyFrameReason(const Scene& scene, const RenderOutput& frame, bool clipStats = true);

}  // namespace twr
