// Pixel trace: the story of one pixel, told by re-running each pipeline stage for the
// triangles that reach it. For every triangle (in draw order) whose projection covers the
// pixel it records the clip planes that cut it, the clipped polygon, the fan triangle that
// covers the pixel, its window and snapped positions and edge values, the barycentrics and
// perspective weights, the interpolated varyings, every shading term, the depth, and what
// happened: shaded, failed the depth test, culled, or clipped away. The replay follows the
// same code as the renderer, so the last shaded visit is the pixel's final colour (unless a
// TBN debug line was drawn over it, which the trace reports too).
#pragma once

#include "scene/renderer.h"
#include "scene/scene.h"
#include "scene/shadow_trace.h"
#include "softrender/clip.h"
#include "softrender/clip_steps.h"
#include "softrender/interpolate.h"
#include "softrender/setup.h"
#include "softrender/shade.h"

#include <nlohmann/json_fwd.hpp>  // declarations only: json.hpp costs 4 s per source that includes it

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace twr {

enum class TraceOutcome {
  Shaded,            // passed the depth test and was shaded
  FailedDepthTest,   // covered the pixel, but something nearer was already there
  CulledBack,        // would cover the pixel, removed by back-face culling
  CulledFront,       // would cover the pixel, removed by front-face culling
  ClippedAway,       // the unclipped triangle covers the pixel, the clipped one does not
};
const char* toString(TraceOutcome outcome);

// A triangle of the same mesh that shares an edge with a traced one: two of its corners lie
// at the model positions of two of the traced triangle's (the fill rule's picture shows who
// owns the pixels along that edge).
struct EdgeNeighbour {
  std::uint32_t triangleId = 0;
  std::array<vec4, 3> posClip{};      // its vertex stage output
  std::array<int, 2> sharedCorners{};  // the traced triangle's corners the edge joins
};

struct TriangleVisit {
  std::uint32_t triangleId = 0;  // global id (as in RenderOutput::triangleId)
  std::string nodeName;
  std::size_t triangleInMesh = 0;
  std::array<vec3, 3> posModel{};
  std::array<vec4, 3> posClip{};       // vertex stage output
  std::vector<EdgeNeighbour> neighbours;  // up to one per edge
  std::uint32_t planesCut = 0;         // mask, see clip.h
  std::vector<vec4> clippedPolygon;    // posClip of each vertex after clipping
  std::vector<ClipStep> clipSteps;     // the clipper's passes, one per plane that cut it (clip_steps.h)
  int fanTriangle = -1;                // i: fan triangle (0, i, i+1) that covers the pixel
  std::array<int, 3> fanCorners{};     // ... its polygon vertices in llvmpipe's setup order
  std::array<WindowVertex, 3> window{};
  std::array<std::int32_t, 3> xFixed{}, yFixed{};  // after setup's corner ordering
  std::array<std::int64_t, 3> edgeValue{};         // E_i at the pixel (> 0 inside)
  bool frontFacing = true;
  PixelWeights weights;      // barycentrics, perspective weights, depth
  Fragment fragment;         // interpolated varyings
  VaryingPlanes varyings;    // the triangle's planes (the quad's other pixels are found from them)
  float depthBefore = 1.0f;  // depth buffer value when this triangle arrived
  TraceOutcome outcome = TraceOutcome::Shaded;
  ShadeTerms terms;          // filled when shaded
  // The material reads a height map: its method, and terms' uvShifted, height and
  // parallaxSteps are the surface detail's (where the maps were read, the height there, the
  // layers marched).
  bool heightMap = false;
  SurfaceDetail surfaceDetail = SurfaceDetail::NormalMap;
  EnvironmentDiffuse environmentDiffuse = EnvironmentDiffuse::None;  // the diffuse light it read
};

struct PixelTrace {
  int x = 0, yTop = 0;  // the pixel, top-left image coordinates (as in the PNG files)
  int yGl = 0;          // the same row in GL window coordinates (origin bottom-left)
  int width = 0, height = 0;
  View view = View::Shaded;
  LightingSpace lightingSpace = LightingSpace::World;
  Interpolation interpolation = Interpolation::Perspective;
  mat4 clipFromWorld{1.0f};  // the camera's projection times view (the vertex stage's)
  ClipConfig clip;           // the frustum planes on, and the guard bands of those off (no user planes)
  std::vector<TriangleVisit> visits;
  // What the renderer wrote to the pixel.
  std::array<std::uint8_t, 4> rgba{};
  float depth = 1.0f;
  std::uint32_t triangleId = kNoTriangle;
  bool debugLine = false;
  // No triangle, and the scene draws its sky box there: what the sky read (docs/environment.md).
  bool sky = false;
  vec3 skyDirection{0.0f};  // world space, unnormalised
  // What was read: a cube's face (GL order: +X, -X, +Y, -Y, +Z, -Z) and s, t on it, or a
  // sphere or paraboloid map's layer and u, v.
  EnvironmentParameterization skyParameterization = EnvironmentParameterization::Cube;
  int skyFace = 0;
  vec2 skyFaceCoord{0.0f};
  float skyLod = 0.0f;      // texture()'s LOD, from the direction's quad differences
  // The shadow maps the replay shaded with (per light; empty without shadows).
  ShadowMaps shadowMaps;
};

// Throws InputError when the pixel is outside the image or the size is invalid.
// Renders the frame once (fast path, one thread) for the final pixel, then replays.
PixelTrace tracePixel(const Scene& scene, const RenderSettings& settings, int width, int height, int x, int yTop);

// The replay alone, for a caller that already has the frame (the GUI's inspector): the
// visits and the pixel's coordinates, with rgba, depth, triangleId and debugLine left at
// their defaults. Throws InputError for what the renderer would refuse (size, pixel, clip
// slots, mesh indices). `shadows`: the frame's shadow maps; null draws them anew with the
// teaching traversal (shadow_pass.h).
PixelTrace tracePixelVisits(const Scene& scene, const RenderSettings& settings, int width, int height, int x,
                            int yTop, const ShadowMaps* shadows = nullptr);

// The pixel's shadow test tap by tap (scene/shadow_trace.h), one entry per light of `scene`
// with a map, from the last shaded visit's test (the pixel's surface) and the trace's maps.
// Empty without shadowed lights; an entry is not `tested` where no triangle was shaded.
std::vector<ShadowTapTrace> shadowTapTracesOf(const PixelTrace& trace, const Scene& scene);

// A readable multi-line report.
std::string formatPixelTrace(const PixelTrace& trace);
nlohmann::json pixelTraceToJson(const PixelTrace& trace);

}  // namespace twr
