#include "softrender/debug_lines.h"

#include "softrender/output_merge.h"

#include <algorithm>
#include <cmath>

namespace twr {

namespace {
constexpr float kPixelCentre = 0.5f;
}  // namespace

std::uint64_t drawWindowLine(Framebuffer& fb, const WindowVertex& a, const WindowVertex& b, vec3 colour) {
  // The clipper bounds window x and y (frustum or guard band); a non-finite end would make
  // the conversions to int below undefined, so such a line draws nothing.
  if (!std::isfinite(a.x) || !std::isfinite(a.y) || !std::isfinite(b.x) || !std::isfinite(b.y)) return 0;
  const float dx = b.x - a.x, dy = b.y - a.y;
  const bool xMajor = std::fabs(dx) >= std::fabs(dy);
  const float major0 = xMajor ? a.x : a.y, major1 = xMajor ? b.x : b.y;
  const float minor0 = xMajor ? a.y : a.x, minor1 = xMajor ? b.y : b.x;
  const float span = major1 - major0;
  if (span == 0.0f) return 0;  // shorter than a pixel centre spacing in both axes: no fragment
  const int majorSize = xMajor ? fb.width : fb.height;
  const int minorSize = xMajor ? fb.height : fb.width;
  // Pixel centres c = p + 0.5 in [start, end) along the direction of travel.
  // Clamped one pixel beyond the framebuffer so the int conversions stay in range; the loop
  // clamps to the framebuffer anyway.
  const float majorLimit = static_cast<float>(majorSize) + 1.0f;
  const float lo = std::clamp(std::min(major0, major1), -1.0f, majorLimit);
  const float hi = std::clamp(std::max(major0, major1), -1.0f, majorLimit);
  const bool forward = span > 0.0f;
  // forward: lo <= c < hi;  backward: lo < c <= hi.
  int pFirst = forward ? static_cast<int>(std::ceil(lo - kPixelCentre)) : static_cast<int>(std::floor(lo - kPixelCentre)) + 1;
  int pLast = forward ? static_cast<int>(std::ceil(hi - kPixelCentre)) - 1 : static_cast<int>(std::floor(hi - kPixelCentre));
  pFirst = std::max(pFirst, 0);
  pLast = std::min(pLast, majorSize - 1);
  std::uint64_t written = 0;
  for (int p = pFirst; p <= pLast; ++p) {
    const float t = (static_cast<float>(p) + kPixelCentre - major0) / span;
    const float minor = minor0 + t * (minor1 - minor0);
    // A minor coordinate off the framebuffer (or NaN) is skipped before it is converted.
    if (!(minor >= 0.0f && minor < static_cast<float>(minorSize))) continue;
    const int q = static_cast<int>(std::floor(minor));
    if (q < 0 || q >= minorSize) continue;
    const float depth = std::fmin(std::fmax(a.z + t * (b.z - a.z), 0.0f), 1.0f);
    const int x = xMajor ? p : q, y = xMajor ? q : p;
    if (!depthTestLess(depth, fb.depth[fb.index(x, y)])) continue;
    writeLineFragment(fb, x, y, colour, depth);
    ++written;
  }
  return written;
}

std::uint64_t drawWorldLine(Framebuffer& fb, vec3 aWorld, vec3 bWorld, vec3 colour, const VertexUniforms& uniforms,
                            const ClipConfig& clipConfig, const Viewport& viewport) {
  ClipVertex a, b;
  a.posWorld = aWorld;
  b.posWorld = bWorld;
  a.posClip = transformPoint(uniforms.clipFromWorld, aWorld);
  b.posClip = transformPoint(uniforms.clipFromWorld, bWorld);
  for (int j = 0; j < uniforms.userClipPlaneCount; ++j) {
    const vec4& plane = uniforms.userClipPlanes[static_cast<std::size_t>(j)];
    a.clipDistance[static_cast<std::size_t>(j)] = clipDistanceFrom(plane, aWorld);
    b.clipDistance[static_cast<std::size_t>(j)] = clipDistanceFrom(plane, bWorld);
  }
  std::uint32_t planesCut = 0;
  if (!clipSegment(a, b, clipConfig, planesCut)) return 0;
  return drawWindowLine(fb, windowFromClip(a, viewport), windowFromClip(b, viewport), colour);
}

std::uint64_t drawTbnLines(Framebuffer& fb, const ClipVertex& vertex, float length, const VertexUniforms& uniforms,
                           const ClipConfig& clipConfig, const Viewport& viewport) {
  const vec3 p = vertex.posWorld;
  std::uint64_t written = 0;
  written += drawWorldLine(fb, p, p + length * safeNormalize(vertex.nWorld), kTbnNormalColour, uniforms, clipConfig, viewport);
  written += drawWorldLine(fb, p, p + length * safeNormalize(vertex.tWorld), kTbnTangentColour, uniforms, clipConfig, viewport);
  written += drawWorldLine(fb, p, p + length * safeNormalize(vertex.bWorld), kTbnBitangentColour, uniforms, clipConfig, viewport);
  return written;
}

}  // namespace twr
