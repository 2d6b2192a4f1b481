// Every pass's buffers, diffed between the renderers (docs/compare.md, "Buffers"): which
// buffer of which pass the two first part in. `compare --buffer NAME` diffs one,
// `--all-buffers` writes one row per buffer, in pass order, to metrics.json's "buffers".
//   shadow_map      each shadowed light's map (every layer), window depth: the shadow pass;
//   gbuffer_depth   the frame's window depth;
//   gbuffer_normal  the lighting normal each pixel's surface writes (world space);
//   gbuffer_albedo  its albedo times kd;
//   gbuffer_specular, gbuffer_emission  its ks specScale and what no light scales;
//   gbuffer_position  its world position (settings.gbuffer_position stored);
//   lighting        the lit surfaces (the frame without its sky box);
//   final           the frame as written.
// A deferred frame (settings.pipeline deferred) diffs its G-buffer's float targets, channel by
// channel within kGBufferTolerance. A forward frame has no G-buffer: its normal and albedo rows
// are the forward pipeline's `normal` and `albedo` views, its specular and emission rows are
// not available.
#pragma once

#include "compare/metrics.h"
#include "scene/image.h"
#include "scene/renderer.h"

#include <nlohmann/json_fwd.hpp>  // declarations only: json.hpp costs 4 s per source that includes it

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace twr {

enum class PassBuffer {
  ShadowMap,
  GbufferDepth,
  GbufferNormal,
  GbufferAlbedo,
  GbufferSpecular,
  GbufferEmission,
  GbufferPosition,
  Lighting,
  Final
};
inline constexpr PassBuffer kAllPassBuffers[] = {
    PassBuffer::ShadowMap,       PassBuffer::GbufferDepth,    PassBuffer::GbufferNormal, PassBuffer::GbufferAlbedo,
    PassBuffer::GbufferSpecular, PassBuffer::GbufferEmission, PassBuffer::GbufferPosition, PassBuffer::Lighting,
    PassBuffer::Final};
std::string_view toString(PassBuffer buffer);
bool parse(std::string_view name, PassBuffer& out);  // false for an unknown name
std::string allPassBufferNames();                   // "shadow_map|gbuffer_depth|..."
// Whether the buffer holds window depths (else 8-bit colours).
constexpr bool isDepthBuffer(PassBuffer b) { return b == PassBuffer::ShadowMap || b == PassBuffer::GbufferDepth; }
// The view a colour buffer is drawn in (final and lighting: the scene's own).
View viewOfBuffer(PassBuffer buffer, View sceneView);

// A G-buffer target's channels, as the colour they end up in: one 8-bit level (the position's:
// world units, where the renderers' interpolation differs by about 1e-6).
inline constexpr double kGBufferTolerance = 1.0 / 255.0;
// The G-buffer target a row reads (null for a buffer that is no G-buffer colour target, and for
// a position the frame did not store).
const std::vector<vec4>* gbufferTargetOf(const GBuffer& g, PassBuffer buffer);
// A target's x, y and z as three layers of compareDepthBuffers' layout (rows bottom first).
std::vector<float> gbufferPlanes(const std::vector<vec4>& target, int width, int height);
// A target as a picture, top row first: a normal as the normal view shows it (0.5 + 0.5 n), a
// position as a triangle wave of period 2 world units (1 at even units, 0 at odd ones:
// continuous, so a floor lying at y = 0 does not speckle; black where nothing was drawn), the
// other targets clamped to [0, 1].
Image gbufferImage(const std::vector<vec4>& target, int width, int height, PassBuffer buffer);

// The buffers a frame can be shown as (the GUI's buffer picker), in pass order: the frame, its
// depth, the G-buffer's colour targets.
inline constexpr PassBuffer kShowableBuffers[] = {
    PassBuffer::Final,           PassBuffer::GbufferDepth,    PassBuffer::GbufferNormal,  PassBuffer::GbufferAlbedo,
    PassBuffer::GbufferSpecular, PassBuffer::GbufferEmission, PassBuffer::GbufferPosition};
// `frame` with its colour replaced by the buffer as a picture, depth, triangle ids and line
// mask kept (so it diffs and reads back as a frame does): a G-buffer target as gbufferImage
// draws it, the depth as grey (window depth, black 0, white 1), Final the frame itself. Empty
// when the frame does not hold the buffer (a forward frame's G-buffer targets; shadow_map and
// lighting are no picture of the frame).
std::optional<RenderOutput> bufferAsOutput(const RenderOutput& frame, PassBuffer buffer);

// Two depth buffers of the same shape, texel by texel (layers * height * width floats).
struct DepthBufferMetrics {
  int width = 0, height = 0, layers = 0;
  std::uint64_t compared = 0;       // texels finite on both sides
  std::uint64_t nonFinite = 0;      // texels non-finite on either side
  double maxAbsDiff = 0.0;          // window depth units
  double meanAbsDiff = 0.0;
  std::uint64_t overTolerance = 0;  // |a - b| > tolerance (exclusive)
  double tolerance = 0.0;
  int maxX = 0, maxY = 0, maxLayer = 0;  // where maxAbsDiff is (rows bottom first)
};
DepthBufferMetrics compareDepthBuffers(const std::vector<float>& a, const std::vector<float>& b, int width, int height,
                                       int layers, double tolerance);

// A depth buffer's layers side by side as grey (the nearest depth drawn black, the farthest
// below 1 near white, the clear value 1 white), top row first; and the
// difference's heat map on the same layout (black 0, the heat ramp up to `tolerance` and
// beyond; magenta where either side is not finite).
Image depthLayersImage(const std::vector<float>& depth, int width, int height, int layers);
Image depthDiffImage(const std::vector<float>& a, const std::vector<float>& b, int width, int height, int layers,
                     double tolerance);

// One row of `--all-buffers`: the buffer, the pass that writes it, whether both renderers
// produced it, its metrics and whether it meets the targets.
struct BufferRow {
  PassBuffer buffer = PassBuffer::Final;
  int light = -1;             // shadow_map: the light's index
  bool available = false;     // both renderers produced it
  std::string note;           // why not, when not
  bool depth = false;         // depth metrics (else colour metrics)
  bool floats = false;        // with depth: a G-buffer target's channels, not window depths
  DepthBufferMetrics depthMetrics;
  CompareMetrics colourMetrics;
  bool passes = true;         // within the targets (depth: overTolerance 0)
};
nlohmann::json bufferRowToJson(const BufferRow& row);
// The pass that writes the buffer: "shadow", "gbuffer", "lighting", "final".
std::string_view passOfBuffer(PassBuffer buffer);

}  // namespace twr
