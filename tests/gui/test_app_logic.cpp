// The desktop app's pure logic, no window: frame-time medians that restart and skip cold
// frames (issue 20, defect 2), panel sizes that recover after the window shrinks and grows
// (defect 4), and the hover line's rule for comparing two images (defect 5).
#include "app/gui/frame_pairing.h"
#include "app/gui/frame_timing.h"
#include "app/gui/panel_sizing.h"

#include <gtest/gtest.h>

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

}  // namespace
}  // namespace twr::gui
