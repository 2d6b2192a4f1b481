// Frame times per backend as the Stats panel shows them: a moving median that restarts
// whenever the frames stop being comparable (another scene, render size or CPU renderer)
// and skips the first frames after each restart, which are cold (GL compiles its shader
// permutations and uploads textures, the CPU allocates its buffers and warms its caches).
// It says what it covers, so the number never silently mixes two scenes.
#pragma once

#include "gui/moving_median.h"
#include "gui/text_concat.h"

#include <cstddef>
#include <optional>
#include <string>

namespace twr::gui {

// Frames kept for the median (samples) and cold frames skipped after a restart (samples).
inline constexpr std::size_t kTimingWindow = 31;
inline constexpr std::size_t kColdFramesSkipped = 2;

class FrameTimes {
 public:
  explicit FrameTimes(std::size_t window = kTimingWindow, std::size_t coldFrames = kColdFramesSkipped)
      : window_(window), coldFrames_(coldFrames), median_(window) {}

  // Forgets every sample; `reason` says why ("scene loaded", "render size 640 x 480").
  void restart(std::string reason) {
    median_ = MovingMedian(window_);
    seen_ = 0;
    counted_ = 0;
    reason_ = std::move(reason);
  }
  // One frame's wall time, milliseconds; the first coldFrames after a restart are dropped.
  void add(double milliseconds) {
    ++seen_;
    if (seen_ <= coldFrames_) return;
    median_.add(milliseconds);
    if (counted_ < window_) ++counted_;
  }
  // Empty until a frame past the cold ones arrived.
  std::optional<double> median() const { return median_.median(); }
  // Frames the median covers now (at most the window).
  std::size_t counted() const { return counted_; }
  // Frames seen since the restart, the cold ones included.
  std::size_t seen() const { return seen_; }
  std::size_t coldFrames() const { return coldFrames_; }
  const std::string& restartReason() const { return reason_; }
  // What the median covers, e.g. "median of the last 7 frames since scene loaded (first 2
  // skipped)", or "waiting: 1 of 2 cold frames skipped since scene loaded".
  std::string describe() const {
    const std::string since = reason_.empty() ? std::string() : concat(" since ", reason_);
    if (counted_ == 0) {
      return concat("no frame timed yet", since, " (the first ", coldFrames_, " are skipped: ",
                    seen_ < coldFrames_ ? seen_ : coldFrames_, " seen)");
    }
    return concat("median of the last ", counted_, counted_ == 1 ? " frame" : " frames", since, " (first ",
                  coldFrames_, " skipped)");
  }

 private:
  std::size_t window_;
  std::size_t coldFrames_;
  MovingMedian median_;
  std::size_t seen_ = 0;
  std::size_t counted_ = 0;
  std::string reason_;
};

}  // namespace twr::gui
