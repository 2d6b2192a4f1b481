// Order statistics of a sample: the one quantile and median in the tree (frame times in bench,
// compare, the report and the GUI; error percentiles in the environment maps' measurements).
#pragma once

#include <vector>

namespace twr {

// The q-quantile (q in [0, 1]) by linear interpolation between order statistics, the usual
// "type 7" (R's default, NumPy's "linear"): position q * (n - 1) in the sorted sample. The
// median of an even count is the mean of the two middle values. 0 for an empty sample.
double quantileOf(std::vector<double> values, double q);

// quantileOf(values, 0.5).
double medianOf(std::vector<double> values);

// quantileOf over values already sorted ascending, for several quantiles of one sample.
double quantileOfSorted(const std::vector<double>& sorted, double q);

}  // namespace twr
