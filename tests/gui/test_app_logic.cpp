// The desktop app's pure logic, no window: frame-time medians that restart and skip cold
// frames (issue 20, defect 2), panel sizes that recover after the window shrinks and grows
// (defect 4), the hover line's rule for comparing two images (defect 5), and when an idle
// loop draws the window (redraw_policy.h).
#include "gui/frame_pairing.h"
#include "gui/frame_timing.h"
#include "gui/panel_sizing.h"
#include "gui/redraw_policy.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace twr::gui {
namespace {

TEST(FrameTimes, SkipsTheColdFramesAfterEachRestart) {
  FrameTimes times(5, 2);
  times.restart("scene loaded");
  times.add(900.0);  // the first GL frame: shader compilation
  times.add(400.0);
  EXPECT_FALSE(times.median().has_value());
  EXPECT_EQ(times.seen(), 2u);
  EXPECT_EQ(times.counted(), 0u);
  times.add(10.0);
  ASSERT_TRUE(times.median().has_value());
  EXPECT_DOUBLE_EQ(*times.median(), 10.0);
  EXPECT_EQ(times.counted(), 1u);
}

TEST(FrameTimes, ARestartForgetsTheOldScene) {
  FrameTimes times(31, 2);
  times.restart("scene loaded");
  for (int i = 0; i < 40; ++i) times.add(300.0);  // a heavy scene
  EXPECT_DOUBLE_EQ(*times.median(), 300.0);
  EXPECT_EQ(times.counted(), 31u);
  times.restart("scene loaded");
  EXPECT_FALSE(times.median().has_value());
  for (int i = 0; i < 2; ++i) times.add(120.0);  // cold frames of the light scene
  for (int i = 0; i < 3; ++i) times.add(5.0);
  EXPECT_DOUBLE_EQ(*times.median(), 5.0) << "no frame of the heavy scene may remain";
  EXPECT_EQ(times.counted(), 3u);
}

TEST(FrameTimes, SaysWhatItCovers) {
  FrameTimes times(31, 2);
  times.restart("scene loaded");
  times.add(1.0);
  EXPECT_NE(times.describe().find("no frame timed yet since scene loaded"), std::string::npos) << times.describe();
  times.add(1.0);
  times.add(2.0);
  times.add(3.0);
  EXPECT_EQ(times.describe(), "median of the last 2 frames since scene loaded (first 2 skipped)");
  EXPECT_EQ(times.restartReason(), "scene loaded");
}

TEST(FrameTimes, TheWindowKeepsTheNewestFrames) {
  FrameTimes times(3, 0);
  for (double ms : {100.0, 100.0, 100.0, 1.0, 2.0, 3.0}) times.add(ms);
  EXPECT_DOUBLE_EQ(*times.median(), 2.0);
  EXPECT_EQ(times.counted(), 3u);
}

constexpr PanelLimits kControls{300.0f, 0.45f, 390.0f};

TEST(PanelSizing, ShrinkingAndGrowingTheWindowRestoresThePanel) {
  float preferred = 0.0f;  // never dragged: the default
  const float atStart = shownPanelSize(preferred, 1280.0f, kControls);
  EXPECT_FLOAT_EQ(atStart, 390.0f);
  // The window shrinks to 300 wide: the panel is squeezed, the preference is not touched.
  const float squeezed = shownPanelSize(preferred, 300.0f, kControls);
  EXPECT_LE(squeezed, 300.0f);
  preferred = preferredAfterFrame(preferred, squeezed, squeezed, kControls);
  // ...and grows back: the panel is as wide as before.
  EXPECT_FLOAT_EQ(shownPanelSize(preferred, 1280.0f, kControls), atStart);
}

TEST(PanelSizing, AUserDragBecomesThePreference) {
  float preferred = 0.0f;
  const float asked = shownPanelSize(preferred, 1280.0f, kControls);
  preferred = preferredAfterFrame(preferred, asked, 500.0f, kControls);
  EXPECT_FLOAT_EQ(preferred, 500.0f);
  EXPECT_FLOAT_EQ(shownPanelSize(preferred, 1280.0f, kControls), 500.0f);
  // A smaller window caps it at its share, and gives it back when it grows.
  EXPECT_FLOAT_EQ(shownPanelSize(preferred, 1000.0f, kControls), 450.0f);
  EXPECT_FLOAT_EQ(shownPanelSize(preferred, 1280.0f, kControls), 500.0f);
}

TEST(PanelSizing, ATooNarrowSavedSizeIsRaisedToTheMinimum) {
  EXPECT_FLOAT_EQ(sanitisePreferred(120.0f, kControls), 300.0f);
  EXPECT_FLOAT_EQ(shownPanelSize(120.0f, 1280.0f, kControls), 300.0f);
  EXPECT_FLOAT_EQ(sanitisePreferred(-1.0f, kControls), 390.0f);
  EXPECT_FLOAT_EQ(sanitisePreferred(std::numeric_limits<float>::quiet_NaN(), kControls), 390.0f);
}

TEST(PanelSizing, NeverWiderThanTheWindow) {
  EXPECT_FLOAT_EQ(shownPanelSize(390.0f, 200.0f, kControls), 200.0f);
  EXPECT_FLOAT_EQ(shownPanelSize(390.0f, 0.0f, kControls), 0.0f);
}

TEST(PanelSizing, RoundingIsNotADrag) {
  EXPECT_FLOAT_EQ(preferredAfterFrame(0.0f, 390.0f, 390.4f, kControls), 390.0f);
}

TEST(FramePairing, OnlyImagesOfTheSameEditAreCompared) {
  EXPECT_EQ(pairState({7, 7, 7}), PairState::SameEdit);
  EXPECT_EQ(pairState({5, 9, 5}), PairState::DifferentEdits);
  EXPECT_EQ(pairState({9, 9, 5}), PairState::SameEditNoDiff);
  EXPECT_EQ(pairState({0, 9, 0}), PairState::Missing);
  EXPECT_EQ(pairNote({7, 7, 7}), "");
  const std::string note = pairNote({5, 9, 5});
  EXPECT_NE(note.find("different edits"), std::string::npos) << note;
  EXPECT_NE(note.find("edit 5"), std::string::npos) << note;
  EXPECT_NE(note.find("edit 9"), std::string::npos) << note;
}

// The caption named the CPU as the one catching up even when its image was the newer.
TEST(FramePairing, TheCaptionNamesTheImageThatIsBehind) {
  EXPECT_EQ(revisionCaption({100, 98, 0}), "CPU shows edit 100, GL edit 98 (GL is catching up)");
  EXPECT_EQ(revisionCaption({98, 100, 0}), "CPU shows edit 98, GL edit 100 (the CPU is catching up)");
  EXPECT_EQ(revisionCaption({7, 7, 7}), "both images show edit 7");
  EXPECT_EQ(revisionCaption({0, 7, 0}), "");
  EXPECT_NE(pairNote({100, 98, 0}).find("GL is catching up"), std::string::npos) << pairNote({100, 98, 0});
}

// An idle window is drawn only for an event, a worker's result or a timed change; after an
// event it keeps drawing until ImGui has settled, by frames and by time.
TEST(RedrawPolicy, DrawsOnlyWhenSomethingHappened) {
  RedrawPolicy policy;
  EXPECT_FALSE(policy.due(10.0));
  EXPECT_FALSE(policy.settling(10.0));

  policy.event(10.0);
  EXPECT_TRUE(policy.due(10.0));
  for (int frame = 0; frame < kSettleFrames; ++frame) {
    EXPECT_TRUE(policy.settling(10.01)) << "frame " << frame;
    policy.frameDrawn();
    EXPECT_FALSE(policy.due(10.01)) << "the event is drawn";
  }
  EXPECT_TRUE(policy.settling(10.0 + 0.5 * kSettleSeconds)) << "frames drawn, but not for long enough";
  EXPECT_FALSE(policy.settling(10.0 + kSettleSeconds));
}

TEST(RedrawPolicy, TheEarliestTimedChangeWinsAndEachFrameAsksAgain) {
  RedrawPolicy policy;
  policy.beginFrame();
  policy.redrawAt(18.0);
  policy.redrawAt(11.0);
  policy.redrawAt(15.0);
  EXPECT_EQ(policy.deadline(), 11.0);
  EXPECT_FALSE(policy.due(10.9));
  EXPECT_TRUE(policy.due(11.0));
  // Sleeps until the change, never longer than a poll of the workers.
  EXPECT_NEAR(policy.sleepSeconds(10.95, false), 0.05, 1e-9);
  EXPECT_DOUBLE_EQ(policy.sleepSeconds(5.0, false), kIdlePollSeconds);
  EXPECT_DOUBLE_EQ(policy.sleepSeconds(5.0, true), kWorkPollSeconds);
  EXPECT_DOUBLE_EQ(policy.sleepSeconds(12.0, false), 0.0) << "already late";
  policy.beginFrame();
  EXPECT_FALSE(policy.deadline()) << "what is no longer drawn asks for nothing";
  EXPECT_FALSE(policy.due(100.0));
}

TEST(FrameAge, CoarserAsTheFrameAgesAndRoundedDown) {
  EXPECT_EQ(frameAgeText(0.0), "0 ms old");
  EXPECT_EQ(frameAgeText(0.2379), "237 ms old");
  EXPECT_EQ(frameAgeText(-0.01), "0 ms old") << "a clock step back is not a negative age";
  EXPECT_EQ(frameAgeText(1.0), "1 s old");
  EXPECT_EQ(frameAgeText(9.99), "9 s old");
  EXPECT_EQ(frameAgeText(10.0), "10 s old");
  EXPECT_EQ(frameAgeText(59.9), "50 s old");
  EXPECT_EQ(frameAgeText(60.0), "1 min old");
  EXPECT_EQ(frameAgeText(3599.0), "59 min old");
  EXPECT_EQ(frameAgeText(7300.0), "2 h old");
}

TEST(FrameAge, LastsUntilItsTextChanges) {
  // Below 1 s the milliseconds change every frame; the next text an idle loop shows is 1 s.
  EXPECT_DOUBLE_EQ(frameAgeTextLasts(0.25), 0.75);
  EXPECT_DOUBLE_EQ(frameAgeTextLasts(1.0), 1.0);
  EXPECT_DOUBLE_EQ(frameAgeTextLasts(4.5), 0.5);
  EXPECT_DOUBLE_EQ(frameAgeTextLasts(12.0), 8.0);
  EXPECT_DOUBLE_EQ(frameAgeTextLasts(59.0), 1.0);
  EXPECT_DOUBLE_EQ(frameAgeTextLasts(90.0), 30.0);
  EXPECT_DOUBLE_EQ(frameAgeTextLasts(3600.0), 3600.0);
  // At the time it gives, the text is another one; just before, it is the same.
  for (const double age : {0.3, 1.0, 4.5, 9.5, 12.0, 59.0, 61.0, 3599.5, 5000.0}) {
    const double lasts = frameAgeTextLasts(age);
    EXPECT_GT(lasts, 0.0) << age;
    EXPECT_NE(frameAgeText(age + lasts), frameAgeText(age)) << age;
    if (age >= 1.0) {
      EXPECT_EQ(frameAgeText(age + 0.999 * lasts), frameAgeText(age)) << age;
    }
  }
  // An idle window redraws for the age at 1, 2, ..., 10 s, 20, ..., 50 s and 1 min: 15 times
  // in the first minute, then once a minute.
  int redraws = 0;
  for (double age = 0.3; age < 60.0; age += frameAgeTextLasts(age)) ++redraws;
  EXPECT_EQ(redraws, 15);
}

TEST(CursorBlink, SwitchesAsImGuiDrawsIt) {
  const auto visible = [](double timer) {
    return timer <= 0.0 || std::fmod(timer, kCursorBlinkPeriodSeconds) <= kCursorBlinkOnSeconds;
  };
  EXPECT_NEAR(cursorBlinkSwitchesIn(-0.3), 1.1 + kCursorBlinkSlackSeconds, 1e-12) << "just typed: on for 1.1 s";
  EXPECT_NEAR(cursorBlinkSwitchesIn(0.5), 0.3 + kCursorBlinkSlackSeconds, 1e-12);
  EXPECT_NEAR(cursorBlinkSwitchesIn(1.0), 0.2 + kCursorBlinkSlackSeconds, 1e-12);
  for (double timer = -0.3; timer < 5.0; timer += 0.037) {
    const double wait = cursorBlinkSwitchesIn(timer);
    EXPECT_GT(wait, 0.0) << timer;
    EXPECT_NE(visible(timer + wait), visible(timer)) << "no switch at " << timer;
    EXPECT_EQ(visible(timer + wait - 2.0 * kCursorBlinkSlackSeconds), visible(timer)) << "a switch missed at " << timer;
  }
}

}  // namespace
}  // namespace twr::gui
