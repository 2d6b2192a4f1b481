#include "softrender/clip.h"

#include <cmath>
#include <utility>

namespace twr {

ClipConfig makeClipConfig(const ClipSwitches& frustum, int userPlaneCount, int viewportWidth, int viewportHeight) {
  ClipConfig config;
  config.frustum = frustum;
  // Window x = (x_ndc + 1) W / 2 stays in [-G, W + G] when |x_ndc| <= 1 + 2 G / W.
  config.guardBandX = 1.0f + 2.0f * kGuardBandPixels / static_cast<float>(viewportWidth > 0 ? viewportWidth : 1);
  config.guardBandY = 1.0f + 2.0f * kGuardBandPixels / static_cast<float>(viewportHeight > 0 ? viewportHeight : 1);
  config.userPlaneCount = userPlaneCount < 0 ? 0 : (userPlaneCount > kMaxUserClipPlanes ? kMaxUserClipPlanes : userPlaneCount);
  return config;
}

float clipDistanceTo(const ClipVertex& vertex, int plane, const ClipConfig& config) {
  const vec4& p = vertex.posClip;
  switch (plane) {
    case kClipPlaneLeft: return (config.frustum.left ? p.w : config.guardBandX * p.w) + p.x;
    case kClipPlaneRight: return (config.frustum.right ? p.w : config.guardBandX * p.w) - p.x;
    case kClipPlaneBottom: return (config.frustum.bottom ? p.w : config.guardBandY * p.w) + p.y;
    case kClipPlaneTop: return (config.frustum.top ? p.w : config.guardBandY * p.w) - p.y;
    case kClipPlaneNear: return p.w + p.z;
    case kClipPlaneFar: return p.w - p.z;
    case kClipPlaneMinW: return p.w - kMinClipW;
    default: return vertex.clipDistance[static_cast<std::size_t>(plane - kClipPlaneUser0)];
  }
}

namespace {

bool planeActive(int plane, const ClipConfig& config) {
  if (plane == kClipPlaneNear) return config.frustum.near;
  if (plane == kClipPlaneFar) return config.frustum.far;
  if (plane >= kClipPlaneUser0) return plane - kClipPlaneUser0 < config.userPlaneCount;
  return true;  // side planes fall back to the guard band; w >= kMinClipW is always on
}

bool finitePosition(const ClipVertex& v) {
  return std::isfinite(v.posClip.x) && std::isfinite(v.posClip.y) && std::isfinite(v.posClip.z) &&
         std::isfinite(v.posClip.w);
}

// Cuts `in` by one plane into `out` (Sutherland-Hodgman: keep inside vertices, add a vertex
// where an edge crosses the plane).
void clipPolygonByPlane(const ClipPolygon& in, int plane, const ClipConfig& config, ClipPolygon& out) {
  std::array<float, kMaxClipVertices> distance{};
  for (int i = 0; i < in.count; ++i) distance[static_cast<std::size_t>(i)] = clipDistanceTo(in.v[static_cast<std::size_t>(i)], plane, config);
  out.count = 0;
  for (int i = 0; i < in.count; ++i) {
    const int next = (i + 1) % in.count;
    const ClipVertex& current = in.v[static_cast<std::size_t>(i)];
    const ClipVertex& following = in.v[static_cast<std::size_t>(next)];
    const float dCurrent = distance[static_cast<std::size_t>(i)];
    const float dNext = distance[static_cast<std::size_t>(next)];
    const bool currentInside = dCurrent >= 0.0f;
    const bool nextInside = dNext >= 0.0f;
    if (currentInside) out.v[static_cast<std::size_t>(out.count++)] = current;
    if (currentInside != nextInside) {
      // Signs differ, so dOutside - dInside is strictly negative: no division by zero.
      if (currentInside) {
        out.v[static_cast<std::size_t>(out.count++)] = interpolateClipVertex(following, current, dNext / (dNext - dCurrent));
      } else {
        out.v[static_cast<std::size_t>(out.count++)] = interpolateClipVertex(current, following, dCurrent / (dCurrent - dNext));
      }
    }
  }
  if (out.count < 3) out.count = 0;
}

}  // namespace

std::uint32_t outcode(const ClipVertex& vertex, const ClipConfig& config) {
  std::uint32_t code = 0;
  for (int plane = 0; plane < kClipPlaneUser0 + config.userPlaneCount; ++plane) {
    if (planeActive(plane, config) && clipDistanceTo(vertex, plane, config) < 0.0f) code |= 1u << plane;
  }
  return code;
}

ClipVertex interpolateClipVertex(const ClipVertex& outside, const ClipVertex& inside, float t) {
  ClipVertex r;
  r.posClip = outside.posClip + t * (inside.posClip - outside.posClip);
  r.posWorld = outside.posWorld + t * (inside.posWorld - outside.posWorld);
  r.nWorld = outside.nWorld + t * (inside.nWorld - outside.nWorld);
  r.tWorld = outside.tWorld + t * (inside.tWorld - outside.tWorld);
  r.bWorld = outside.bWorld + t * (inside.bWorld - outside.bWorld);
  r.uv = outside.uv + t * (inside.uv - outside.uv);
  for (std::size_t i = 0; i < r.lightDirTangent.size(); ++i) {
    r.lightDirTangent[i] = outside.lightDirTangent[i] + t * (inside.lightDirTangent[i] - outside.lightDirTangent[i]);
  }
  r.eyeDirTangent = outside.eyeDirTangent + t * (inside.eyeDirTangent - outside.eyeDirTangent);
  for (std::size_t j = 0; j < r.clipDistance.size(); ++j) {
    r.clipDistance[j] = outside.clipDistance[j] + t * (inside.clipDistance[j] - outside.clipDistance[j]);
  }
  return r;
}

std::uint32_t clipTriangle(const ClipVertex& a, const ClipVertex& b, const ClipVertex& c, const ClipConfig& config,
                           ClipPolygon& out, ClipPolygon& scratch) {
  if (!finitePosition(a) || !finitePosition(b) || !finitePosition(c)) {
    out.count = 0;
    return kClipNonFiniteBit;
  }
  const std::uint32_t codeA = outcode(a, config), codeB = outcode(b, config), codeC = outcode(c, config);
  out.v[0] = a;
  out.v[1] = b;
  out.v[2] = c;
  out.count = 3;
  if ((codeA | codeB | codeC) == 0) return 0;  // trivially inside
  if ((codeA & codeB & codeC) != 0) {          // all three outside one plane
    out.count = 0;
    return codeA & codeB & codeC;
  }
  std::uint32_t cut = 0;
  const std::uint32_t straddled = codeA | codeB | codeC;
  ClipPolygon* current = &out;
  ClipPolygon* next = &scratch;
  for (int plane = 0; plane < kClipPlaneCount; ++plane) {
    if ((straddled & (1u << plane)) == 0) continue;
    clipPolygonByPlane(*current, plane, config, *next);
    cut |= 1u << plane;
    std::swap(current, next);
    if (current->count == 0) break;
  }
  if (current != &out) {
    out.count = current->count;
    for (int i = 0; i < current->count; ++i) out.v[static_cast<std::size_t>(i)] = current->v[static_cast<std::size_t>(i)];
  }
  return cut;
}

bool clipSegment(ClipVertex& a, ClipVertex& b, const ClipConfig& config, std::uint32_t& planesCut) {
  planesCut = 0;
  if (!finitePosition(a) || !finitePosition(b)) {
    planesCut = kClipNonFiniteBit;
    return false;
  }
  for (int plane = 0; plane < kClipPlaneUser0 + config.userPlaneCount; ++plane) {
    if (!planeActive(plane, config)) continue;
    const float dA = clipDistanceTo(a, plane, config);
    const float dB = clipDistanceTo(b, plane, config);
    const bool insideA = dA >= 0.0f, insideB = dB >= 0.0f;
    if (insideA && insideB) continue;
    planesCut |= 1u << plane;
    if (!insideA && !insideB) return false;
    if (insideA) {
      b = interpolateClipVertex(b, a, dB / (dB - dA));
    } else {
      a = interpolateClipVertex(a, b, dA / (dA - dB));
    }
  }
  return true;
}

const char* clipPlaneName(int plane) {
  static_assert(kClipPlaneCount == 15, "one name per plane");
  static const char* const kNames[kClipPlaneCount] = {"left",  "right", "bottom", "top",   "near",
                                                      "far",   "w>=eps", "user0", "user1", "user2",
                                                      "user3", "user4",  "user5", "user6", "user7"};
  return plane >= 0 && plane < kClipPlaneCount ? kNames[plane] : "?";
}

}  // namespace twr
