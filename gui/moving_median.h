// Median of the last few samples: frame times jump (page faults, the other thread), and a
// median ignores single spikes where a mean would not.
#pragma once

#include "scene/statistics.h"

#include <cstddef>
#include <deque>
#include <optional>
#include <vector>

namespace twr::gui {

class MovingMedian {
 public:
  explicit MovingMedian(std::size_t window) : window_(window < 1 ? 1 : window) {}

  void add(double sample) {
    samples_.push_back(sample);
    while (samples_.size() > window_) samples_.pop_front();
  }
  // The middle sample (the mean of the two middle ones for an even count); empty before any.
  std::optional<double> median() const {
    if (samples_.empty()) return std::nullopt;
    return medianOf(std::vector<double>(samples_.begin(), samples_.end()));
  }

 private:
  std::size_t window_;
  std::deque<double> samples_;
};

}  // namespace twr::gui
