// The reference: the CPU pipeline's own stages instantiated in double precision, with N x N
// samples per pixel box-filtered down. It is the ground truth the report and the stability
// suite measure both backends against (docs/reference.md).
//
// How it samples: N x N passes, each with the whole scene shifted by a sub-pixel offset so the
// pixel centre lands on sample (i, j) at (px + (i + 0.5) / N, py + (j + 0.5) / N); each pass
// has its own depth buffer (double), so this is exactly a render at N times the resolution
// followed by a box filter, without the N^2-sized buffers.
//
// What the RenderOutput holds:
//   rgb        mean of the N^2 sample colours, a sample nobody covers counting as the
//              background (the true box-filtered image), rounded to 8 bits once at the end
//   alpha      the same box filter of the samples' alpha: 1 for a covered sample, the
//              background's alpha for the others, so with a transparent background
//              ([r, g, b, 0]) it is round(255 * covered samples / N^2), the coverage fraction.
//              A pixel no sample covers holds the background exactly as the CPU renderer
//              clears it (backgroundWord). compare() counts a pixel as covered by its triangle
//              id, set when any sample is covered, and diffs RGB only, so edge pixels carry
//              their aliasing error in the colour metrics
//   depth, triangleId   those of the covered sample nearest the pixel centre (1 and
//              kNoTriangle where no sample is covered)
//   lineMask   all 0: the reference draws no TBN debug lines (compare skips line pixels of
//              the other side anyway)
//   stats      triangle counts of the first pass; pixelsShaded summed over all samples
// With N = 1 it is the plain double-precision pipeline (one sample at the pixel centre, alpha
// 255 or the background's, as the CPU renderer writes), the "double" side of the report's
// float-versus-double knob.
#pragma once

#include "scene/renderer.h"
#include "softrender/precision.h"

#include <memory>
#include <vector>

namespace twr {

// Largest N (samples per axis) the reference accepts (inclusive): 16 x 16 = 256 passes.
inline constexpr int kMaxReferenceSamplesPerAxis = 16;

struct ReferenceOptions {
  int samplesPerAxis = 4;  // N, in [1, kMaxReferenceSamplesPerAxis]
  int threads = 1;         // row bands per pass, as CpuOptions::threads (values below 1 mean 1)
  // false: the same loop and passes with the float stages. Not a reference then; it exists so
  // that float and double can be timed through identical code (the report's precision knob).
  bool doublePrecision = true;
};

// Throws InputError for samplesPerAxis outside [1, kMaxReferenceSamplesPerAxis].
std::unique_ptr<Renderer> makeReferenceRenderer(const ReferenceOptions& options = {});

// The scene's transforms in double: worldFromModel for every draw item, in flattenScene's
// order (T * Rz * Ry * Rx * S per node, parents first), and the camera's clipFromWorld.
std::vector<glm::dmat4> referenceWorldFromModel(const Scene& scene);
glm::dmat4 referenceClipFromWorld(const Camera& camera, int width, int height);

}  // namespace twr
