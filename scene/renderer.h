// The one interface the app sees: the CPU and the GL renderer both implement it.
#pragma once

#include "scene/scene.h"

#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace twr {

// Triangle id written where no triangle covers a pixel.
inline constexpr std::uint32_t kNoTriangle = std::numeric_limits<std::uint32_t>::max();

struct RenderStats {
  std::uint64_t trianglesIn = 0;        // submitted to the clipper
  std::uint64_t trianglesClipped = 0;   // touched by at least one clip plane
  std::uint64_t trianglesCulled = 0;    // removed by face culling or zero area after snapping
  std::uint64_t trianglesProduced = 0;  // reaching the rasterizer (after fan triangulation)
  std::uint64_t pixelsShaded = 0;       // fragments that passed the depth test and were shaded
  double milliseconds = 0.0;            // wall time of render(), excluding readback to files
  // Of `milliseconds`, the part spent copying finished buffers into the RenderOutput (GL:
  // glReadPixels of the four attachments after glFinish; CPU: 0, it draws into them).
  double readbackMilliseconds = 0.0;
  // Of `milliseconds`, the part spent capturing the environment from the scene (six face
  // renders and building what the materials read from them; 0 when nothing is captured).
  double captureMilliseconds = 0.0;
  // Of `milliseconds`, the part spent drawing the lights' shadow maps (0 without shadows).
  double shadowMilliseconds = 0.0;
  // Of `milliseconds`, the deferred pipeline's G-buffer pass and lighting pass (0 forward).
  double gbufferMilliseconds = 0.0;
  double lightingMilliseconds = 0.0;
  double ssrMilliseconds = 0.0;  // the screen-space reflection pass (0 without settings.ssr)
};

// A deferred frame's G-buffer (docs/deferred.md): one RGBA float target per surface quantity,
// width * height entries, top row first. Its depth is the frame's depth buffer.
struct GBuffer {
  int width = 0, height = 0;
  std::vector<vec4> normal;     // xyz: the normal lighting uses, world space, unit; w: the Phong exponent
  std::vector<vec4> geometric;  // xyz: the interpolated normal (the shadow maps' slope), world, unit; w 1
  std::vector<vec4> albedo;     // xyz: kd albedo, scaled by (1 - the environment's share); w 1
  std::vector<vec4> specular;   // xyz: ks specScale, scaled the same; w: the material's ssr_reflect
  std::vector<vec4> emission;   // xyz: what no light scales (ambient, environment); w 1
  // xyz: the world position the forward shading interpolates; w 1. Empty when the frame
  // rebuilds positions from depth (settings.gbuffer_position depth).
  std::vector<vec4> position;
};

struct CapturedFaces;  // below

// All buffers are top row first (row 0 is the top of the image), width * height entries.
struct RenderOutput {
  int width = 0;
  int height = 0;
  // RGBA8; alpha 255 where geometry was drawn, the background's alpha elsewhere
  // (OutputDesc::background, 1 by default): alpha is not coverage, see coveredAt().
  std::vector<std::uint8_t> rgba;
  std::vector<float> depth;                // window depth in [0, 1], 1 where nothing was drawn
  std::vector<std::uint32_t> triangleId;   // global triangle id (DrawItem::firstTriangleId + i), kNoTriangle where none
  std::vector<std::uint8_t> lineMask;      // 1 where a TBN debug line was drawn (compare skips)
  RenderStats stats;
  // The six faces this renderer captured the environment from (scene/environment_capture.h),
  // null when the scene's environment is not captured.
  std::shared_ptr<const CapturedFaces> capturedFaces;
  // Per light, the shadow map this renderer drew and shaded with (scene/shadow_map.h); empty
  // when no light casts a shadow, null for a light without one. GL's lean frame reads none back.
  ShadowMaps shadowMaps;
  // The G-buffer a deferred frame was lit from; null for a forward frame (and GL's lean frame,
  // which reads none back).
  std::shared_ptr<const GBuffer> gbuffer;
};

// A captured environment's faces as the renderer drew them, in GL order (+X, -X, +Y, -Y, +Z,
// -Z), each laid out as a cube face's texels (row 0 is t = 0: a sky box file's top row).
struct CapturedFaces {
  std::array<RenderOutput, 6> faces;
  vec3 centreWorld{0.0f};     // where the six cameras stood
  double milliseconds = 0.0;  // the six renders and building the maps from them
};

// Whether a triangle covers pixel i (top row first): its triangle id. An output without
// triangle ids (an empty buffer: GL's lean frame, the analytic-sphere reference) can only
// say it in alpha > 0, which holds only where its producer cleared alpha to 0; the CPU and
// GL renderers' full outputs always carry ids.
inline bool coveredAt(const RenderOutput& out, std::size_t i) {
  return out.triangleId.empty() ? out.rgba[i * 4 + 3] != 0 : out.triangleId[i] != kNoTriangle;
}
// Whether a TBN debug line was drawn at pixel i (false for an output without a line mask).
inline bool lineAt(const RenderOutput& out, std::size_t i) { return !out.lineMask.empty() && out.lineMask[i] != 0; }
// Whether anything was drawn at pixel i: a triangle or a TBN debug line.
inline bool drawnAt(const RenderOutput& out, std::size_t i) {
  return coveredAt(out, i) || lineAt(out, i);
}

// The four image buffers (rgba, depth, triangleId, lineMask) moved from one holder to another:
// a RenderOutput, or a renderer's framebuffer that names them alike.
template <typename From, typename To>
void moveImageBuffers(From& from, To& to) {
  to.rgba = std::move(from.rgba);
  to.depth = std::move(from.depth);
  to.triangleId = std::move(from.triangleId);
  to.lineMask = std::move(from.lineMask);
}

// out's four image buffers alone, moved out for a renderer to draw the next frame into
// (Renderer::renderInto); the rest of the output is left behind.
inline RenderOutput imageBuffersOf(RenderOutput&& out) {
  RenderOutput buffers;
  moveImageBuffers(out, buffers);
  return buffers;
}

class Renderer {
 public:
  virtual ~Renderer() = default;
  virtual std::string name() const = 0;  // "cpu" or "gl"
  // Renders `scene` with `settings` (usually scene.settings) at width x height.
  // Throws InputError for inputs it cannot draw.
  virtual RenderOutput render(const Scene& scene, const RenderSettings& settings, int width, int height) = 0;
  // The same into `out`, whose contents it replaces: a renderer may draw into out's buffers
  // where they already have the frame's size, as a GL application keeps its framebuffer from
  // frame to frame, instead of allocating and clearing new ones (a loop over frames calls this).
  // After a throw, `out` is empty.
  virtual void renderInto(const Scene& scene, const RenderSettings& settings, int width, int height,
                          RenderOutput& out) {
    out = RenderOutput{};
    out = render(scene, settings, width, height);
  }
};

}  // namespace twr
