// What float arithmetic lets the camera's projection show of a scene, checked before
// drawing (docs/robustness.md, classes 7-9). Both renderers compute positions and depths in
// float, as OpenGL does, so a camera or a scene beyond float's reach draws nothing, or a
// picture of rounding, on both. Such inputs are refused when no faithful picture can be
// drawn, and drawn with a warning when the picture is OpenGL's but not what the user meant.
#pragma once

#include "scene/scene.h"

#include <string>
#include <vector>

namespace twr {

// One float step of the coordinates around the camera and target (2^-23 of their magnitude),
// measured in pixels of an image `height` pixels high at the target's distance. Above 1,
// vertices snap to a grid coarser than a pixel.
double floatStepInPixels(const Camera& camera, int height);

// Empty when both renderers can draw the scene at this size, else why not (refused with
// exit 2): the whole view narrower than one float step, projection terms or a node's
// transform beyond float's range. Names the key or node to change.
std::string projectionProblem(const Scene& scene, int width, int height);

// Drawn as OpenGL draws it, but the user should know (one line each, printed as "warning:"):
// vertices snapped coarser than a pixel, nodes whose depth rounds to the cleared 1.0 (never
// pass the depth test), a depth step coarse enough for surfaces to fight, clip coordinates
// past float's range, distances the shaders' squares overflow. For a scene projectionProblem
// accepts.
std::vector<std::string> projectionWarnings(const Scene& scene, int width, int height);

}  // namespace twr
