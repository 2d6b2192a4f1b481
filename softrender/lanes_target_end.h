// Back to the plain namespace after softrender/lanes_target_begin.h (no guard: included once
// per Highway target), for whatever follows (the next target's pass, or HWY_ONCE).
#undef TWR_LANES_HIGHWAY
#undef TWR_LANES_BEGIN
#undef TWR_LANES_END
#define TWR_LANES_BEGIN \
  namespace twr {        \
  namespace lanes {
#define TWR_LANES_END \
  }                   \
  }
#undef TWR_LANE_INLINE
#define TWR_LANE_INLINE inline
#undef TWR_LANE_OUTLINE
#define TWR_LANE_OUTLINE inline
#undef TWR_LANES_INLINE_COLOUR_READS
#define TWR_LANES_INLINE_COLOUR_READS 0
