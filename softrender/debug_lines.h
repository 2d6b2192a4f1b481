// TBN debug lines: at every vertex a short line along N (blue), T (red) and B (green), in
// world space, `length` world units long. Lines go through the same homogeneous clipper as
// triangles (frustum or guard band, w >= kMinClipW, user planes), are depth-tested GL_LESS
// and write depth, and mark lineMask so the compare tools skip them.
//
// Rasterization approximates GL's diamond-exit rule for one-pixel lines with a DDA: along
// the major axis, one fragment per pixel column (or row) whose centre lies in the half-open
// interval [start, end) of the segment, at the minor coordinate floor(y(x_centre)); depth is
// interpolated linearly in window space. It matches GL on most pixels but not on every
// end point, which is why the compare tools exclude line pixels.
#pragma once

#include "softrender/clip.h"
#include "softrender/framebuffer.h"
#include "softrender/setup.h"
#include "softrender/vertex.h"

namespace twr {

inline const vec3 kTbnNormalColour{0.0f, 0.0f, 1.0f};
inline const vec3 kTbnTangentColour{1.0f, 0.0f, 0.0f};
inline const vec3 kTbnBitangentColour{0.0f, 1.0f, 0.0f};

// Rasterizes one segment already in window coordinates; returns the fragments written.
std::uint64_t drawWindowLine(Framebuffer& fb, const WindowVertex& a, const WindowVertex& b, vec3 colour);

// Clips and draws the segment posWorld a -> b.
std::uint64_t drawWorldLine(Framebuffer& fb, vec3 aWorld, vec3 bWorld, vec3 colour, const VertexUniforms& uniforms,
                            const ClipConfig& clipConfig, const Viewport& viewport);

// The three lines of one vertex stage output (directions normalised as the fragment stage does).
std::uint64_t drawTbnLines(Framebuffer& fb, const ClipVertex& vertex, float length, const VertexUniforms& uniforms,
                           const ClipConfig& clipConfig, const Viewport& viewport);

}  // namespace twr
