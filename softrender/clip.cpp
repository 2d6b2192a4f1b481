#include "softrender/clip.h"
#include "softrender/clip_steps.h"

#include <cmath>
#include <utility>

namespace twr {

ClipConfig makeClipConfig(const ClipSwitches& frustum, int userPlaneCount, int viewportWidth, int viewportHeight,
                          Interpolation varyings) {
  ClipConfig config;
  config.frustum = frustum;
  config.varyings = varyings;
  // Window x = (x_ndc + 1) W / 2 stays in [-G, W + G] when |x_ndc| <= 1 + 2 G / W.
  config.guardBandX = 1.0f + 2.0f * kGuardBandPixels / static_cast<float>(viewportWidth > 0 ? viewportWidth : 1);
  config.guardBandY = 1.0f + 2.0f * kGuardBandPixels / static_cast<float>(viewportHeight > 0 ? viewportHeight : 1);
  config.userPlaneCount = userPlaneCount < 0 ? 0 : (userPlaneCount > kMaxUserClipPlanes ? kMaxUserClipPlanes : userPlaneCount);
  return config;
}

template <typename T>
T clipDistanceTo(const ClipVertexT<T>& vertex, int plane, const ClipConfig& config) {
  const Vec4T<T>& p = vertex.posClip;
  const T guardBandX = static_cast<T>(config.guardBandX), guardBandY = static_cast<T>(config.guardBandY);
  switch (plane) {
    case kClipPlaneRight: return (config.frustum.right ? p.w : guardBandX * p.w) - p.x;
    case kClipPlaneLeft: return (config.frustum.left ? p.w : guardBandX * p.w) + p.x;
    case kClipPlaneTop: return (config.frustum.top ? p.w : guardBandY * p.w) - p.y;
    case kClipPlaneBottom: return (config.frustum.bottom ? p.w : guardBandY * p.w) + p.y;
    case kClipPlaneNear: return p.w + p.z;
    case kClipPlaneFar: return p.w - p.z;
    case kClipPlaneMinW: return p.w - static_cast<T>(kMinClipW);
    default: return vertex.clipDistance[static_cast<std::size_t>(plane - kClipPlaneUser0)];
  }
}

namespace {

bool planeActive(int plane, const ClipConfig& config) {
  if (plane == kClipPlaneNear) return config.frustum.near;
  if (plane == kClipPlaneFar) return config.frustum.far;
  // With near on, near and the side planes already give w >= 0 (w > 0 but at the apex of
  // the frustum); clipping at kMinClipW as well would cut triangles GL draws.
  if (plane == kClipPlaneMinW) return !config.frustum.near;
  if (plane >= kClipPlaneUser0) return plane - kClipPlaneUser0 < config.userPlaneCount;
  return true;  // side planes fall back to the guard band
}


// Where along the edge from `from` to `to` the cut vertex, t along it in clip space, takes its
// varyings: at t itself, or for affine varyings at its place on the screen.
template <typename T>
T varyingsT(const ClipVertexT<T>& from, const ClipVertexT<T>& to, T t, const ClipConfig& config) {
  if (config.varyings == Interpolation::Perspective) return t;
  return screenLinearT(from.posClip, to.posClip, from.posClip + t * (to.posClip - from.posClip), t);
}

// Cuts `in` by one plane into `out` (Sutherland-Hodgman: keep inside vertices, add a vertex
// where an edge crosses the plane).
// `step`, when given, records the distances and every vertex the plane makes (clip_steps.h).
template <typename T>
void clipPolygonByPlane(const ClipPolygonT<T>& in, int plane, const ClipConfig& config, ClipPolygonT<T>& out,
                        ClipStep* step = nullptr) {
  std::array<T, kMaxClipVertices> distance{};
  for (int i = 0; i < in.count; ++i) distance[static_cast<std::size_t>(i)] = clipDistanceTo(in.v[static_cast<std::size_t>(i)], plane, config);
  out.count = 0;
  for (int i = 0; i < in.count; ++i) {
    const int next = (i + 1) % in.count;
    const ClipVertexT<T>& current = in.v[static_cast<std::size_t>(i)];
    const ClipVertexT<T>& following = in.v[static_cast<std::size_t>(next)];
    const T dCurrent = distance[static_cast<std::size_t>(i)];
    const T dNext = distance[static_cast<std::size_t>(next)];
    const bool currentInside = dCurrent >= T(0);
    const bool nextInside = dNext >= T(0);
    if (currentInside) out.v[static_cast<std::size_t>(out.count++)] = current;
    if (currentInside != nextInside) {
      // Start from the endpoint nearer to the plane (the smaller |d|), as Mesa does: the new
      // vertex is then the same whichever way round a shared edge is walked. The signs
      // differ, so dNear - dFar is never zero.
      const bool currentNearer = std::fabs(dCurrent) < std::fabs(dNext) ||
                                 (std::fabs(dCurrent) == std::fabs(dNext) && currentInside);
      const ClipVertexT<T>& nearer = currentNearer ? current : following;
      const ClipVertexT<T>& farther = currentNearer ? following : current;
      const T dNearer = currentNearer ? dCurrent : dNext;
      const T dFarther = currentNearer ? dNext : dCurrent;
      const T t = dNearer / (dNearer - dFarther);
      const T tVaryings = varyingsT(nearer, farther, t, config);
      out.v[static_cast<std::size_t>(out.count++)] = interpolateClipVertex(nearer, farther, t, tVaryings);
      if (step) {
        step->cuts.push_back({currentNearer ? i : next, currentNearer ? next : i, static_cast<float>(t), out.count - 1,
                              static_cast<float>(tVaryings)});
      }
    }
  }
  if (out.count < 3) out.count = 0;
  if (step) {
    for (int i = 0; i < in.count; ++i) {
      step->before.push_back(vec4(in.v[static_cast<std::size_t>(i)].posClip));
      step->distances.push_back(static_cast<float>(distance[static_cast<std::size_t>(i)]));
    }
    for (int i = 0; i < out.count; ++i) step->after.push_back(vec4(out.v[static_cast<std::size_t>(i)].posClip));
  }
}

template <typename T>
bool withinClipRange(T value) {
  // Also false for NaN and infinities.
  return std::fabs(value) <= static_cast<T>(kMaxClipCoordinate);
}

}  // namespace

template <typename T>
bool clipVertexUsable(const ClipVertexT<T>& vertex, const ClipConfig& config) {
  const Vec4T<T>& p = vertex.posClip;
  if (!withinClipRange(p.x) || !withinClipRange(p.y) || !withinClipRange(p.z) || !withinClipRange(p.w)) return false;
  for (int j = 0; j < config.userPlaneCount; ++j) {
    if (!withinClipRange(vertex.clipDistance[static_cast<std::size_t>(j)])) return false;
  }
  return true;
}

template <typename T>
std::uint32_t outcode(const ClipVertexT<T>& vertex, const ClipConfig& config) {
  if (!clipVertexUsable(vertex, config)) return kClipNonFiniteBit;
  std::uint32_t code = 0;
  for (int plane = 0; plane < kClipPlaneCount; ++plane) {
    if (planeActive(plane, config) && clipDistanceTo(vertex, plane, config) < T(0)) code |= 1u << plane;
  }
  return code;
}

template <typename T>
T screenLinearT(const Vec4T<T>& from, const Vec4T<T>& to, const Vec4T<T>& cut, std::type_identity_t<T> t) {
  // Mesa tries x where the clip x differ, else y. An edge an earlier side plane made lies on
  // x = w, so both ends have NDC x 1 and Mesa divides 0 by 0 (llvmpipe then draws the fan
  // black, docs/pipeline.md); here an axis whose NDC ends are equal is passed over instead.
  const auto alongAxis = [&](T fromC, T toC, T cutC, T& out) {
    if (fromC == toC) return false;
    const T fromNdc = fromC / from.w, toNdc = toC / to.w, cutNdc = cutC / cut.w;
    if (toNdc == fromNdc) return false;
    out = (cutNdc - fromNdc) / (toNdc - fromNdc);
    return true;
  };
  T onScreen = t;
  if (alongAxis(from.x, to.x, cut.x, onScreen) || alongAxis(from.y, to.y, cut.y, onScreen)) return onScreen;
  return t;
}

template <typename T>
ClipVertexT<T> interpolateClipVertex(const ClipVertexT<T>& from, const ClipVertexT<T>& to, std::type_identity_t<T> t) {
  return interpolateClipVertex(from, to, t, t);
}

template <typename T>
ClipVertexT<T> interpolateClipVertex(const ClipVertexT<T>& from, const ClipVertexT<T>& to, std::type_identity_t<T> t,
                                     std::type_identity_t<T> tVaryings) {
  ClipVertexT<T> r;
  r.fromClipper = true;
  r.posClip = from.posClip + t * (to.posClip - from.posClip);
  for (std::size_t j = 0; j < r.clipDistance.size(); ++j) {
    r.clipDistance[j] = from.clipDistance[j] + t * (to.clipDistance[j] - from.clipDistance[j]);
  }
  t = tVaryings;
  r.posWorld = from.posWorld + t * (to.posWorld - from.posWorld);
  r.nWorld = from.nWorld + t * (to.nWorld - from.nWorld);
  r.tWorld = from.tWorld + t * (to.tWorld - from.tWorld);
  r.bWorld = from.bWorld + t * (to.bWorld - from.bWorld);
  r.uv = from.uv + t * (to.uv - from.uv);
  for (std::size_t i = 0; i < r.lightDirTangent.size(); ++i) {
    r.lightDirTangent[i] = from.lightDirTangent[i] + t * (to.lightDirTangent[i] - from.lightDirTangent[i]);
  }
  r.eyeDirTangent = from.eyeDirTangent + t * (to.eyeDirTangent - from.eyeDirTangent);
  return r;
}

namespace {

// clipTriangle, and with `steps` each plane's pass recorded (clipTriangleSteps).
template <typename T>
std::uint32_t clipTriangleRecorded(const ClipVertexT<T>& a, const ClipVertexT<T>& b, const ClipVertexT<T>& c,
                                   const ClipConfig& config, ClipPolygonT<T>& out, ClipPolygonT<T>& scratch,
                                   std::vector<ClipStep>* steps) {
  if (!clipVertexUsable(a, config) || !clipVertexUsable(b, config) || !clipVertexUsable(c, config)) {
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
  ClipPolygonT<T>* current = &out;
  ClipPolygonT<T>* next = &scratch;
  for (int plane = 0; plane < kClipPlaneCount; ++plane) {
    if ((straddled & (1u << plane)) == 0) continue;
    ClipStep* step = nullptr;
    if (steps) {
      steps->push_back(ClipStep{});
      steps->back().plane = plane;
      step = &steps->back();
    }
    clipPolygonByPlane(*current, plane, config, *next, step);
    cut |= 1u << plane;
    std::swap(current, next);
    if (current->count == 0) break;
  }
  // A cut vertex may land a rounding beyond a plane its polygon was not clipped against:
  // with the near plane on and the polygon reaching the eye (w = 0), at w <= 0, where 1 / w
  // flips sign or overflows (found by fuzzing; a perspective camera's near plane keeps every
  // real vertex far from it). Such a polygon is removed like one with an unusable vertex.
  for (int i = 0; i < current->count; ++i) {
    if (!(current->v[static_cast<std::size_t>(i)].posClip.w > T(0))) {
      out.count = 0;
      return cut | kClipNonFiniteBit;
    }
  }
  if (current != &out) {
    out.count = current->count;
    for (int i = 0; i < current->count; ++i) out.v[static_cast<std::size_t>(i)] = current->v[static_cast<std::size_t>(i)];
  }
  return cut;
}

}  // namespace

template <typename T>
std::uint32_t clipTriangle(const ClipVertexT<T>& a, const ClipVertexT<T>& b, const ClipVertexT<T>& c,
                           const ClipConfig& config, ClipPolygonT<T>& out, ClipPolygonT<T>& scratch) {
  return clipTriangleRecorded(a, b, c, config, out, scratch, static_cast<std::vector<ClipStep>*>(nullptr));
}

std::vector<ClipStep> clipTriangleSteps(const ClipVertex& a, const ClipVertex& b, const ClipVertex& c,
                                        const ClipConfig& config) {
  std::vector<ClipStep> steps;
  ClipPolygon out, scratch;
  clipTriangleRecorded(a, b, c, config, out, scratch, &steps);
  // A removed polygon (a cut vertex at w <= 0) leaves nothing, whatever the last plane left.
  if (out.count == 0 && !steps.empty()) steps.back().after.clear();
  return steps;
}

template <typename T>
bool clipSegment(ClipVertexT<T>& a, ClipVertexT<T>& b, const ClipConfig& config, std::uint32_t& planesCut) {
  planesCut = 0;
  if (!clipVertexUsable(a, config) || !clipVertexUsable(b, config)) {
    planesCut = kClipNonFiniteBit;
    return false;
  }
  // tA, tB: how much of the segment each plane cuts off from that end; keep the largest.
  T tA = T(0), tB = T(0);
  for (int plane = 0; plane < kClipPlaneCount; ++plane) {
    if (!planeActive(plane, config)) continue;
    const T dA = clipDistanceTo(a, plane, config);
    const T dB = clipDistanceTo(b, plane, config);
    if (dA >= T(0) && dB >= T(0)) continue;
    planesCut |= 1u << plane;
    if (dA < T(0) && dB < T(0)) return false;
    if (dB < T(0)) tB = std::fmax(tB, dB / (dB - dA));
    if (dA < T(0)) tA = std::fmax(tA, dA / (dA - dB));
    if (tA + tB >= T(1)) return false;
  }
  const ClipVertexT<T> originalA = a, originalB = b;
  if (tA > T(0)) a = interpolateClipVertex(originalA, originalB, tA);
  if (tB > T(0)) b = interpolateClipVertex(originalB, originalA, tB);
  return true;
}

// The two pipelines: float (matches GL) and double (the reference).
#define TWR_INSTANTIATE_CLIP(T)                                                                               \
  template bool clipVertexUsable<T>(const ClipVertexT<T>&, const ClipConfig&);                                \
  template T clipDistanceTo<T>(const ClipVertexT<T>&, int, const ClipConfig&);                                \
  template std::uint32_t outcode<T>(const ClipVertexT<T>&, const ClipConfig&);                                \
  template ClipVertexT<T> interpolateClipVertex<T>(const ClipVertexT<T>&, const ClipVertexT<T>&, T);          \
  template ClipVertexT<T> interpolateClipVertex<T>(const ClipVertexT<T>&, const ClipVertexT<T>&, T, T);       \
  template T screenLinearT<T>(const Vec4T<T>&, const Vec4T<T>&, const Vec4T<T>&, T);                          \
  template std::uint32_t clipTriangle<T>(const ClipVertexT<T>&, const ClipVertexT<T>&, const ClipVertexT<T>&, \
                                         const ClipConfig&, ClipPolygonT<T>&, ClipPolygonT<T>&);              \
  template bool clipSegment<T>(ClipVertexT<T>&, ClipVertexT<T>&, const ClipConfig&, std::uint32_t&);
TWR_INSTANTIATE_CLIP(float)
TWR_INSTANTIATE_CLIP(double)
#undef TWR_INSTANTIATE_CLIP

const char* clipPlaneName(int plane) {
  static_assert(kClipPlaneCount == 15, "one name per plane");
  static const char* const kNames[kClipPlaneCount] = {"right", "left",  "top",   "bottom", "near",
                                                      "far",   "user0", "user1", "user2",  "user3",
                                                      "user4", "user5", "user6", "user7",  "w>=eps"};
  return plane >= 0 && plane < kClipPlaneCount ? kNames[plane] : "?";
}

}  // namespace twr
