// Included (repeatedly, no guard) by a translation unit that compiles the shared "-inl.h"
// sources once per Highway target (fast_kernels.cpp, tests/softrender/test_lanes.cpp): from
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
#undef TWR_LANE_INLINE
#define TWR_LANE_INLINE HWY_INLINE
