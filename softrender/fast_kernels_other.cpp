// The fast path's kernels for every target the other fast_kernels_<group>.cpp leave out:
// Highway's portable one (SCALAR, or EMU128) and any target a newer Highway adds.
// fast_kernels.cpp compiled for those only (the file explains the split).
#define TWR_FAST_KERNEL_TARGETS (~(HWY_AVX3 | HWY_AVX2 | HWY_SSE4 | HWY_NEON))
#include "softrender/fast_kernels.cpp"
