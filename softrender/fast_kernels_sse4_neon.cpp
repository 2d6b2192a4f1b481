// The fast path's kernels for SSE4 (x86-64) or NEON (aarch64): fast_kernels.cpp compiled for that target only
// (the file explains the split); on another architecture this object is empty.
#define TWR_FAST_KERNEL_TARGETS (HWY_SSE4 | HWY_NEON)
#include "softrender/fast_kernels.cpp"
