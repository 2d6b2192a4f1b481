#include "scene/statistics.h"

#include <algorithm>
#include <cstddef>
#include <utility>

namespace twr {

double quantileOfSorted(const std::vector<double>& sorted, double q) {
  if (sorted.empty()) return 0.0;
  const double position = std::clamp(q, 0.0, 1.0) * static_cast<double>(sorted.size() - 1);
  const std::size_t below = static_cast<std::size_t>(position);
  const std::size_t above = std::min(below + 1, sorted.size() - 1);
  const double fraction = position - static_cast<double>(below);
  return sorted[below] + (sorted[above] - sorted[below]) * fraction;
}

double quantileOf(std::vector<double> values, double q) {
  std::sort(values.begin(), values.end());
  return quantileOfSorted(values, q);
}

double medianOf(std::vector<double> values) { return quantileOf(std::move(values), 0.5); }

}  // namespace twr
