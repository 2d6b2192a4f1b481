// An environment captured from the scene (docs/environment.md, "Captured from the scene"):
// `"environment": {"capture": {"node": NAME, "size": N}}` makes the cube map out of the scene
// itself, as a game's reflection probe does, by each renderer with its own pipeline:
//   1. the centre: the middle of the node's mesh bounds in world space (its origin when it
//      has no mesh);
//   2. six square renders of side N from there, 90 degrees each, one per face in GL order,
//      with the node and its children removed and no environment (what the probe sees is the
//      rest of the scene under its lights, the output background where nothing is);
//   3. each render's 8-bit colours read as c / 255 into the face's texels, the rows flipped
//      (below), and the cube, its mip chain and whatever the materials read from it (a sphere
//      or paraboloid map, the prefiltered lights) built exactly as for a loaded cube.
// The frame is then drawn with that cube. Every frame captures anew: a scene that changes
// (the GUI's live edits) is reflected as it is now.
//
// Why the rows flip. Face f's texel (s, t) looks along directionFromCubeCoord(f, s, t). A
// camera at the centre looking along the face's middle direction, with up along increasing t,
// has its image's right along increasing s (for each of the six faces; the GL table is made
// so), but its image's top row is t = 1 where a face's row 0 is t = 0. So the render, read
// top row first, is the face upside down: flipping the rows gives the face as a sky box file
// holds it (+X's top row looks up, towards +Y).
#pragma once

#include "scene/renderer.h"
#include "scene/scene.h"

namespace twr {

// Whether the scene's environment is captured and has no cube yet: a renderer then captures
// it (captureEnvironment) before it draws.
bool needsEnvironmentCapture(const Scene& scene);

// The world-space point the faces are rendered from (step 1 above). Throws InputError naming
// the node when no node has that name.
vec3 captureCentre(const Scene& scene, const std::string& nodeName);

// The camera of face `face` (0..5, GL order) at `centre`: 90 degrees, looking along the face's
// middle direction, up along its increasing t; near and far are `like`'s (the scene camera's:
// the scene's own scale).
Camera captureCamera(int face, const vec3& centre, const Camera& like);

// The scene the faces are drawn from (step 2): `scene` without the named node and its
// children, and without an environment.
Scene sceneForCapture(const Scene& scene, const std::string& nodeName);

// A render's rows in reverse order (every buffer it holds): the render of a face camera made
// into the face's texel layout, and back.
RenderOutput flipRows(RenderOutput out);

struct CapturedEnvironment {
  Scene scene;  // the input, its environment's cube (and what its materials read) built from the faces
  std::shared_ptr<const CapturedFaces> faces;
};

// Steps 1 to 3 with `renderer` (settings as given, but the shaded view and no TBN lines).
// Throws InputError when the scene's environment is not captured or a face render fails.
CapturedEnvironment captureEnvironment(const Scene& scene, const RenderSettings& settings, Renderer& renderer);

// Records a capture on the frame drawn with it: its faces, and its time as part of the
// frame's (stats.milliseconds includes it, stats.captureMilliseconds says how much).
void attachCapture(RenderOutput& frame, const CapturedEnvironment& capture);

}  // namespace twr
