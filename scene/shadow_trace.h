// One pixel's shadow test, tap by tap (docs/shadows.md, "One pixel's taps"): for a shadowed
// light, what each renderer compared at every PCF tap, so `trace` and the pixel inspector can
// show both side by side and point at the first tap where they part. The fragment's values
// (its compared depth, its texel) are each renderer's own: the CPU's from its shading's test
// (softrender/shadow-inl.h, recorded by the pixel trace), GL's from phong.frag's SHADOW_PROBE
// variant; each tap's stored depth is read from that renderer's own map, as its test reads it.
#pragma once

#include "scene/conventions.h"
#include "scene/shadow_map.h"

#include <nlohmann/json_fwd.hpp>  // declarations only: json.hpp costs 4 s per source that includes it

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace twr {

struct ShadowTap {
  int dx = 0, dy = 0;   // offset from the fragment's own texel, texels
  glm::ivec3 texel{0};       // the texel read: x, y clamped to the map's edges, the layer
  float stored = 1.0f;  // the map's depth there
  bool lit = true;      // reference <= stored: the map's surface is not in front of the fragment
};

struct ShadowTapTrace {
  int light = -1;         // the light's index in the scene
  bool tested = false;    // the pixel shows a surface and the light has a map there
  bool inside = false;    // the fragment lies inside the map (outside: lit, no taps)
  int pcf = 1;            // the kernel's side
  glm::ivec3 texel{0};         // the fragment's own texel (x, y) and layer
  float depth = 0.0f;     // the fragment's depth from the light (window depth of the map's camera)
  float bias = 0.0f;      // depth units
  float reference = 0.0f; // what every tap compares: depth - bias
  float visibility = 1.0f;  // the test's result: the lit taps' share
  float stored = 1.0f;      // the test's own read of the map at its texel (1 outside the map)
  std::vector<ShadowTap> taps;  // row by row (dy outer, dx inner), as the test's loops run
};

// The pcf x pcf taps around `centre` (x, y, layer) of `map`, each compared with `reference`,
// exactly as the shading's test reads and compares them. Throws InputError when the map holds
// no depths (drawn without read-back) or `centre` lies outside it.
std::vector<ShadowTap> shadowTapsOf(const ShadowMap& map, glm::ivec3 centre, float reference);

// Whether the taps read from the map agree with what the test itself reported: the centre tap's
// depth is the test's `stored`, and the lit taps' share its visibility. True without taps.
bool tapsMatchTest(const ShadowTapTrace& trace);

// Where two tests part before any tap ("cpu: not tested, gl: inside the map", ...): one was
// tested or inside the map and the other not. Empty when both read their taps alike.
std::string testsPartBeforeTaps(const std::string& nameA, const ShadowTapTrace& a, const std::string& nameB,
                                const ShadowTapTrace& b);

// The first tap where two traces differ: another texel, stored depth or outcome; also where one
// has a tap the other has not. None: the same taps (see testsPartBeforeTaps for tests that read
// none).
std::optional<std::size_t> firstDifferingTap(const ShadowTapTrace& a, const ShadowTapTrace& b);

// {"light", "tested", "inside", "pcf", "texel": [x, y, layer], "depth", "bias", "reference",
//  "visibility", "stored", "taps_match_test", "taps": [{"dx", "dy", "texel": [x, y, layer],
//  "stored", "lit"}, ...]}
nlohmann::json shadowTapTraceToJson(const ShadowTapTrace& trace);

// Tap by tap, `a` and `b` side by side under their names, the first tap where they part marked
// with '*' and named in the last line; depths to 9 digits (a flip is decided in the last bits).
// `b` may be null (one column).
std::string formatShadowTapTraces(const std::string& nameA, const ShadowTapTrace& a, const std::string& nameB,
                                  const ShadowTapTrace* b);

}  // namespace twr
