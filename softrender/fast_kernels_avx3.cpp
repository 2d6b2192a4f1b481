// The fast path's kernels for AVX-512 (x86-64): fast_kernels.cpp compiled for that target only
// (the file explains the split); on another architecture this object is empty.
#define TWR_FAST_KERNEL_TARGETS HWY_AVX3
#include "softrender/fast_kernels.cpp"
