// Shadow maps (docs/shadows.md): a light's `"shadow"` turns on a depth pass from the light,
// which each renderer draws with its own stages before the frame, and a test in the shading:
// a fragment is in shadow where the map holds a nearer surface than the fragment's own depth
// from the light, less a bias.
//
//   directional  one orthographic map, square, `extent` world units either side of the
//                scene's middle (0: the scene's bounding radius), deep enough for the whole
//                scene;
//   point        a cube shadow map: six 90-degree perspective maps from the light, one per
//                cube face in GL order, reaching `extent` world units (0: the farthest corner
//                of the scene's bounds);
//   spot         (a point light with a "spot" cone) one square perspective map from the light
//                along the cone's axis, its field of view twice the cone's outer half-angle
//                (the cone's circle inscribed in the square), reaching as a cube map does.
//
// What a map holds: the light camera's window depth (0.5 z_ndc + 0.5, as the renderers' depth
// buffers do), layer by layer, each row by row with row 0 at the bottom (GL window and
// texture order: texel (x, y) is window pixel (x, y) of that layer's render).
//
// The test (written once over lanes in softrender/shadow-inl.h, and in shaders/shadow.glsl):
//   (s, t, z) = the fragment's position in the map (layer: the cube face of P - light, by
//               the largest axis, as a cube map picks its face; a spot map's point behind
//               the light lies outside it);
//   texel     = one texel's width in world units at the fragment (orthographic: 2 extent /
//               size; cube: 2 m / size, m the distance along the face's axis; spot:
//               2 m tan(outer) / size, m the distance along the cone's axis);
//   bias      = (constant + slope * min(tan(theta), kMaxShadowSlopeTangent) * texel *
//               (1 + pcf / 2)) * the map's depth units per world unit at the fragment;
//               theta the angle between the surface's normal and the light: the constant in
//               world units along the light, the slope in texels of the surface's own rise
//               over the kernel's reach, so one setting holds at every map side and kernel;
//   visibility = mean over the pcf x pcf texels around floor((s, t) size), clamped to the
//               map's edges, of [z - bias <= stored depth];
// a fragment outside the map (s or t outside [0, 1), z > 1) is lit.
#pragma once

#include "scene/conventions.h"

#include <array>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace twr {

struct Scene;
struct Light;

// Shadow-map side bounds, texels (inclusive). 4096^2 texel indices stay exact in a float lane.
inline constexpr int kMinShadowMapSize = 16;
inline constexpr int kMaxShadowMapSize = 4096;
inline constexpr int kDefaultShadowMapSize = 2048;
// A point light's cube map: six layers, so 1024^2 x 6 texel indices stay exact in a float lane.
inline constexpr int kMaxCubeShadowMapSize = 1024;
inline constexpr int kDefaultCubeShadowMapSize = 512;
// Most lights with a shadow map (GL: one sampler each, texture units 12 to 15; inclusive).
inline constexpr int kMaxShadowedLights = 4;
// PCF kernel sides allowed: 1 (one texel, hard), 3 or 5.
inline constexpr int kMaxShadowPcf = 5;
// The slope term's tangent is clamped here (unitless): a surface edge-on to the light would
// otherwise get an unbounded bias.
inline constexpr float kMaxShadowSlopeTangent = 10.0f;
// The cosine the tangent divides by is at least this (unitless), so tan stays finite.
inline constexpr float kMinShadowCosine = 1e-4f;
// A point light's cube map: near plane = far * this (unitless), the depth buffer's
// precision spread over the three decades nearest the light.
inline constexpr float kCubeShadowNearRatio = 1e-3f;
// The `shadow` view calls a shadowed fragment acne when the map's surface lies less than this
// many of the surface's own texel rises (tan(theta) texel, at least one texel) in front of its
// biased depth: the surface shadowing itself, not another one (unitless).
inline constexpr float kShadowAcneTexels = 2.0f;

// The `shadow` view's colours (linear RGB): lit, in shadow, acne (a surface shadowing itself:
// the map's surface within kShadowAcneTexels of the fragment's biased depth), turned
// away from the light. A fractional PCF visibility blends the first two.
inline constexpr float kShadowViewLit[3] = {1.0f, 0.92f, 0.6f};
inline constexpr float kShadowViewShadowed[3] = {0.1f, 0.15f, 0.45f};
inline constexpr float kShadowViewAcne[3] = {1.0f, 0.0f, 1.0f};
inline constexpr float kShadowViewAway[3] = {0.3f, 0.3f, 0.3f};
// The light_depth view outside the map (linear RGB): dark red.
inline constexpr float kLightDepthOutside[3] = {0.3f, 0.0f, 0.0f};

// The scene file's "shadow" on a light (all optional).
struct ShadowDesc {
  int size = kDefaultShadowMapSize;  // texels per side, [kMinShadowMapSize, kMaxShadowMapSize]
  // [constant, slope]: world units along the light, and texels of the surface's rise (above).
  vec2 bias{0.005f, 1.0f};
  int pcf = 1;          // 1, 3 or 5: the kernel's side in texels
  float extent = 0.0f;  // world units, >= 0; 0 picks it from the scene's bounds (above)
};

// Its values are the shaders' ShadowUniform.kind (shaders/shadow.glsl).
enum class ShadowKind { Orthographic = 0, Cube = 1, Perspective = 2 };
inline constexpr int kCubeShadowLayers = 6;

// Where a light's map lies in the world: what each layer's render is drawn with.
struct ShadowProjection {
  ShadowKind kind = ShadowKind::Orthographic;
  int size = kDefaultShadowMapSize;
  int layers = 1;  // 1 (orthographic) or kCubeShadowLayers
  // The render of each layer: clip from world (layers entries used).
  std::array<mat4, kCubeShadowLayers> clipFromWorld{};
  // Cube and spot: the light's position, the faces' near and far planes (world units), and their
  // projection's depth terms as the face renders use them (clipFromView's m[2][2] and m[3][2],
  // floats): a point m world units along a face's axis has z_clip = depthA (-m) + depthB and
  // w = m, so its window depth is 0.5 (depthB - depthA m) / m + 0.5 (cubeShadowDepth).
  vec3 lightPosWorld{0.0f};
  float near = 0.0f, far = 0.0f;
  float depthA = 0.0f, depthB = 0.0f;
  // The bias's scales (see the test above). Orthographic: one texel's width in world units and
  // the map's depth units per world unit, both constant. Cube: 2 / size (times m: the texel's
  // width) and 0.5 |depthB| (over m^2: the depth units per world unit along the axis). Spot:
  // 2 tan(outer) / size and 0.5 |depthB|, the same way.
  float texelWorld = 0.0f, depthPerWorld = 0.0f;
  vec2 bias{0.0f};
  int pcf = 1;
};

// One light's map as a renderer drew it.
struct ShadowMap {
  ShadowProjection projection;
  std::vector<float> depth;  // layers * size * size window depths, layer by layer, rows bottom first
  double milliseconds = 0.0;  // the renders of its layers
  float at(int layer, int x, int y) const {
    const std::size_t size = static_cast<std::size_t>(projection.size);
    return depth[(static_cast<std::size_t>(layer) * size + static_cast<std::size_t>(y)) * size +
                 static_cast<std::size_t>(x)];
  }
};

// Per light index, the map drawn for it (null where a light has none); what a frame's shading
// reads and what RenderOutput hands on to compare.
using ShadowMaps = std::vector<std::shared_ptr<const ShadowMap>>;

// The scene's world-space bounds over every mesh vertex (lo > hi when there is none).
struct WorldBounds {
  vec3 lo{1.0f}, hi{-1.0f};
  bool empty() const { return lo.x > hi.x; }
};
WorldBounds worldBoundsOf(const Scene& scene);

// Whether any light of the scene has a shadow map.
bool sceneHasShadows(const Scene& scene);

// The projection of `light`'s map (light.shadow set) over a scene of bounds `bounds`.
ShadowProjection shadowProjectionFor(const Light& light, const WorldBounds& bounds);

// A cube face's window depth of a point m world units along the face's axis from the light,
// in float as the shading computes it: 0.5 ((depthB - depthA m) / m) + 0.5.
float cubeShadowDepth(const ShadowProjection& projection, float m);

// The cube face (GL order +X, -X, +Y, -Y, +Z, -Z) a direction d selects: its largest
// component by magnitude, ties to z, then y (llvmpipe's rule, softrender/cube_sample-inl.h).
int cubeFaceOf(const vec3& d);

// "orthographic", "cube", "perspective".
std::string_view toString(ShadowKind kind);
// "orthographic 2048^2, bias 0.005 + 1 texel slope, pcf 3" for info and the GUI.
std::string describeShadow(const ShadowProjection& projection);

}  // namespace twr
