// Included (repeatedly, no guard) by a translation unit that compiles the shared "-inl.h"
// sources once per Highway target (fast_kernels-inl.h, tests/softrender/test_lanes.cpp): from
// here on they go into twr::HWY_NAMESPACE with the target's attributes (softrender/lanes.h).
// softrender/lanes_target_end.h switches back to the plain namespace.
#define TWR_LANES_HIGHWAY
#undef TWR_LANES_BEGIN
#undef TWR_LANES_END
#define TWR_LANES_BEGIN \
  HWY_BEFORE_NAMESPACE(); \
  namespace twr {         \
  namespace HWY_NAMESPACE {
#define TWR_LANES_END \
  }                   \
  }                   \
  HWY_AFTER_NAMESPACE();
// Forced inline only in optimised builds without sanitizers: at -O0 or with AddressSanitizer
// (the sanitizer and fuzzing builds) forcing every shared function into every kernel makes
// this one translation unit take tens of minutes and gigabytes to compile.
#undef TWR_LANE_INLINE
#if defined(__has_feature)
#if __has_feature(address_sanitizer)
#define TWR_LANES_SANITIZED 1
#endif
#endif
#if defined(__SANITIZE_ADDRESS__)
#define TWR_LANES_SANITIZED 1
#endif
#if defined(__OPTIMIZE__) && !defined(TWR_LANES_SANITIZED)
#define TWR_LANE_INLINE HWY_INLINE
#else
#define TWR_LANE_INLINE inline
#endif
// A large shared function called from many kernels (sampling one mip level): one out-of-line
// copy per target, or the kernels' code (and the compile time) grows with every call site.
#undef TWR_LANE_OUTLINE
#define TWR_LANE_OUTLINE HWY_NOINLINE
// A colour read (one mip level of an RGBA map) inlined into the kernels on the SIMD targets:
// out of line, the call spills every live vector and returns its four through memory. The
// default frame on AVX-512 about 4 % faster; each SIMD target's kernel object takes about three
// times as long to compile (AVX-512 24 -> 78 s), so the scalar target keeps one copy.
#undef TWR_LANES_INLINE_COLOUR_READS
#if defined(__OPTIMIZE__) && !defined(TWR_LANES_SANITIZED) && HWY_TARGET != HWY_SCALAR
#define TWR_LANES_INLINE_COLOUR_READS 1
#else
#define TWR_LANES_INLINE_COLOUR_READS 0
#endif
