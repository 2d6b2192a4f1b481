// Which edit each image on screen comes from, and whether two of them may be compared. The
// GL image follows every edit at once (it renders on the UI thread); the CPU image lags
// while its worker catches up. A per-pixel "diff" next to a CPU and a GL value from
// different edits would compare two different pictures, so it is only claimed when both
// shown images and the diff come from the same edit.
#pragma once

#include "gui/text_concat.h"
#include <cstdint>
#include <string>

namespace twr::gui {

struct ShownRevisions {
  std::uint64_t cpu = 0;   // edit of the CPU image on screen; 0: none
  std::uint64_t gl = 0;    // edit of the GL image on screen; 0: none
  std::uint64_t diff = 0;  // edit both diffed frames were rendered at; 0: no diff
};

enum class PairState {
  Missing,        // one image is not there yet
  DifferentEdits, // both there, from different edits: nothing to compare
  SameEditNoDiff, // same edit, the diff of that edit is not ready (or failed)
  SameEdit,       // same edit, and the diff is that edit's
};

inline PairState pairState(const ShownRevisions& shown) {
  if (shown.cpu == 0 || shown.gl == 0) return PairState::Missing;
  if (shown.cpu != shown.gl) return PairState::DifferentEdits;
  return shown.diff == shown.cpu ? PairState::SameEdit : PairState::SameEditNoDiff;
}

// Which image is behind when the two show different edits: the one with the older edit. The
// CPU usually is (its worker catches up), but GL lags too while the UI thread skips its draws
// (an orbit at the teaching path's pace, a throttled redraw).
inline std::string catchingUpNote(const ShownRevisions& shown) {
  return shown.cpu < shown.gl ? "the CPU is catching up" : "GL is catching up";
}

// The caption's words on which edit each image shows: "both images show edit N", or each
// one's edit and which is catching up; empty while an image is missing.
inline std::string revisionCaption(const ShownRevisions& shown) {
  if (shown.cpu == 0 || shown.gl == 0) return "";
  if (shown.cpu == shown.gl) return concat("both images show edit ", shown.cpu);
  return concat("CPU shows edit ", shown.cpu, ", GL edit ", shown.gl, " (", catchingUpNote(shown), ")");
}

// What the hover line says in place of the diff when it cannot show one; empty for SameEdit.
inline std::string pairNote(const ShownRevisions& shown) {
  switch (pairState(shown)) {
    case PairState::Missing:
      return "no diff: one image is missing";
    case PairState::DifferentEdits:
      return concat("no diff: CPU shows edit ", shown.cpu, ", GL edit ", shown.gl, " (different edits; ",
                    catchingUpNote(shown), ")");
    case PairState::SameEditNoDiff:
      return concat("no diff yet for edit ", shown.cpu);
    case PairState::SameEdit:
      break;
  }
  return "";
}

}  // namespace twr::gui
