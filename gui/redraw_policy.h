// When the app's loop draws the window. A frame of the whole window is the dearest thing an
// idle app does (about 25 ms of CPU at 1280 x 800 on llvmpipe under Xvfb, in the UI thread
// and llvmpipe's threads at the UI's priority), and it is taken from the render workers,
// which run at a lower one (worker_priority.h): drawn 8 times a second while idle and up to
// 60 while a worker built a horizon map, it starved that worker. So the loop draws only when
// something happened or is about to change on screen: an input or window event, a worker's
// result, a timed element's next change (the clock is glfwGetTime(), seconds). Pure: no GLFW,
// no ImGui, tested without a window (tests/gui/test_app_logic.cpp).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
#include <string>

namespace twr::gui {

// After an event, ImGui needs a frame or two more to settle: hover follows the mouse a frame
// late, a popup opens or closes on the next frame, an auto-sized window (a tooltip, a combo's
// list) is measured hidden on its first frame. So the loop keeps drawing for at least this
// many frames after the last event (inclusive of the one that shows it)...
inline constexpr int kSettleFrames = 4;
// ...and for at least this long, seconds: ImGui highlights a window's resize border 0.04 s
// after the mouse reaches it, with no event of its own.
inline constexpr double kSettleSeconds = 0.25;
// While idle, how long the loop sleeps at most before it looks at the workers again, seconds:
// while one works, the busy frame interval (its result shows as soon as a busy loop would have
// shown it); while none does, 0.1 s (nothing can finish then; a cheap wake just in case).
inline constexpr double kWorkPollSeconds = 1.0 / 60.0;
inline constexpr double kIdlePollSeconds = 0.1;
// With the test probe on (test_probe.h), while idle a frame is still laid out (not drawn)
// at most this often, seconds, so a scripted test that waits for frames sees them come.
inline constexpr double kProbeFrameSeconds = 0.1;

class RedrawPolicy {
 public:
  // An input or window event arrived at `now`: draw it, then let ImGui settle.
  void event(double now) {
    eventPending_ = true;
    settleFramesLeft_ = kSettleFrames;
    settleUntil_ = now + kSettleSeconds;
  }
  // A frame begins: the timed elements it draws ask for their next change again (redrawAt).
  void beginFrame() { deadline_.reset(); }
  // Something drawn this frame changes on its own at `at` (its text, whether it is shown):
  // the earliest such time wins.
  void redrawAt(double at) {
    if (!deadline_ || at < *deadline_) deadline_ = at;
  }
  // A frame was drawn on screen: it shows every event so far.
  void frameDrawn() {
    eventPending_ = false;
    if (settleFramesLeft_ > 0) --settleFramesLeft_;
  }
  // ImGui is still settling after an event: keep drawing.
  bool settling(double now) const { return settleFramesLeft_ > 0 || now < settleUntil_; }
  // While idle, whether this wake needs a frame on screen: an event not drawn yet (a worker's
  // result counts as one), or a timed change that is due.
  bool due(double now) const { return eventPending_ || (deadline_ && now >= *deadline_); }
  // While idle, how long the loop may sleep, seconds (an event ends the sleep sooner).
  double sleepSeconds(double now, bool workRunning) const {
    double wait = workRunning ? kWorkPollSeconds : kIdlePollSeconds;
    if (deadline_) wait = std::min(wait, std::max(0.0, *deadline_ - now));
    return wait;
  }
  std::optional<double> deadline() const { return deadline_; }

 private:
  bool eventPending_ = false;
  int settleFramesLeft_ = 0;
  double settleUntil_ = 0.0;
  std::optional<double> deadline_;
};

// A frame's age as its tag shows it. Coarser as the frame gets older, so that an idle window
// redraws for it once a second for 10 s, every 10 s up to a minute, then once a minute, then
// once an hour: milliseconds below 1 s, whole seconds below 10 s, tens of seconds below 60 s,
// minutes below an hour, hours. Each figure is rounded down (the frame is at least that old).
inline std::string frameAgeText(double seconds) {
  seconds = std::max(0.0, seconds);
  char text[48];
  if (seconds < 1.0) std::snprintf(text, sizeof text, "%.0f ms old", std::floor(seconds * 1000.0));
  else if (seconds < 10.0) std::snprintf(text, sizeof text, "%.0f s old", std::floor(seconds));
  else if (seconds < 60.0) std::snprintf(text, sizeof text, "%.0f s old", 10.0 * std::floor(seconds / 10.0));
  else if (seconds < 3600.0) std::snprintf(text, sizeof text, "%.0f min old", std::floor(seconds / 60.0));
  else std::snprintf(text, sizeof text, "%.0f h old", std::floor(seconds / 3600.0));
  return text;
}

// How long frameAgeText(seconds) keeps its text, seconds (> 0). Below 1 s the milliseconds
// change on every frame; an idle loop does not redraw for them and shows "1 s old" next.
inline double frameAgeTextLasts(double seconds) {
  seconds = std::max(0.0, seconds);
  const auto untilNext = [seconds](double step) { return (std::floor(seconds / step) + 1.0) * step - seconds; };
  if (seconds < 1.0) return 1.0 - seconds;
  if (seconds < 10.0) return untilNext(1.0);
  if (seconds < 60.0) return untilNext(10.0);
  if (seconds < 3600.0) return untilNext(60.0);
  return untilNext(3600.0);
}

// ImGui 1.86 blinks a text field's cursor (imgui_widgets.cpp, InputTextEx): shown while its
// timer is <= 0 (it is set to -0.3 s at every key, so the cursor stays on while one types) and
// while the timer modulo this period is <= this much, seconds.
inline constexpr double kCursorBlinkPeriodSeconds = 1.2;
inline constexpr double kCursorBlinkOnSeconds = 0.8;
// How far past a switch the redraw is asked for, seconds, so the frame lands after it (the
// timer advances by the frame interval, which the loop's sleep may end a little short of).
inline constexpr double kCursorBlinkSlackSeconds = 0.005;

// How long until the cursor of a text field with blink timer `timer` (seconds) turns on or
// off, seconds: a focused field redraws twice per period, not on every frame.
inline double cursorBlinkSwitchesIn(double timer) {
  if (timer <= 0.0) return kCursorBlinkOnSeconds - timer + kCursorBlinkSlackSeconds;
  const double phase = std::fmod(timer, kCursorBlinkPeriodSeconds);
  const double untilSwitch = phase <= kCursorBlinkOnSeconds ? kCursorBlinkOnSeconds - phase : kCursorBlinkPeriodSeconds - phase;
  return untilSwitch + kCursorBlinkSlackSeconds;
}

}  // namespace twr::gui
