// The fast path's SIMD kernel: raster, interpolation, early depth test, shading and output
// merge of one set-up triangle, 4 x 4 pixels at a time in AVX-512 lanes. Every lane performs
// the same IEEE operations in the same order as the scalar stages (pixelWeights,
// interpolateFragment, shadeFragment, writeFragment), so the image is the teaching path's bit
// for bit; coverage is the edge-function test E > 0 that the span rasterizer is equivalent to.
//
// Only the shaded view has a kernel (the debug views take the scalar path); the kernel is
// compiled for AVX-512 (F, DQ, BW, VL) with contraction off and picked at run time.
#pragma once

#include "softrender/framebuffer.h"
#include "softrender/interpolate.h"
#include "softrender/setup.h"
#include "softrender/shade.h"
#include "softrender/vertex.h"

#include <cstddef>
#include <cstdint>

namespace twr {

// Draws the covered pixels of rows [rowBegin, rowEnd) (exclusive end) that pass GL_LESS;
// returns how many were shaded. v0, v1, v2 in submission (fan) order.
using TriangleKernel = std::uint64_t (*)(const TriangleSetup& setup, const InterpolationSetup& interpolation,
                                         const ClipVertex& v0, const ClipVertex& v1, const ClipVertex& v2,
                                         const ShadeUniforms& shade, std::uint32_t triangleId, int rowBegin,
                                         int rowEnd, Framebuffer& fb);

// True when this CPU runs the AVX-512 kernel.
bool cpuHasAvx512();

// The kernel for `key`'s permutation, or null when the CPU lacks AVX-512 or the view is not
// View::Shaded.
TriangleKernel avx512KernelFor(const ShaderKey& key);

// powPositive (phong_pow.h) of x[0, count) with the kernel's SIMD code, into out; exposed so
// the tests can compare it bit for bit with the scalar function. Requires cpuHasAvx512().
void powPositiveAvx512(const float* x, float s, float* out, std::size_t count);

}  // namespace twr
