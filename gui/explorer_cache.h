// The stage explorer's views kept between frames. The Interpolate stage maps every pixel of its
// triangle and the Raster stage walks the rasterizer: too much to redo for each image each frame,
// so a view is kept until what it was made from changes (the trace, the frame whose triangle ids
// it marks, the edits behind either, the stage, the visit or a choice).
#pragma once

#include "gui/stage_explorer.h"
#include "scene/renderer.h"
#include "softrender/pixel_trace.h"

#include <cstdint>
#include <memory>
#include <optional>
#include <utility>

namespace twr::gui {

// Where the explorer stands: the stage, the visit (-1: the one that wrote the pixel) and the
// reader's other choices.
struct ExplorerPosition {
  ExplorerStage stage = ExplorerStage::Vertex;
  int visit = -1;
  ExplorerChoices choices;
};

// One image's kept view (the app keeps one for the CPU image and one for GL's).
class ExplorerViewCache {
 public:
  // The view of `trace` (made at doc revision `revision`) at `position`, or null when the trace
  // has no such visit. `frame` (at `frameRevision`): the image's frame, whose triangle ids the
  // view marks when they belong to this trace's edit and size; null for none.
  std::shared_ptr<const ExplorerView> viewOf(const std::shared_ptr<const PixelTrace>& trace, std::uint64_t revision,
                                             const std::shared_ptr<const RenderOutput>& frame,
                                             std::uint64_t frameRevision, const ExplorerPosition& position);
  // How many views were made, not taken from the cache (the tests' count of rebuilds).
  int viewsMade() const { return viewsMade_; }

 private:
  struct Key {
    std::shared_ptr<const PixelTrace> trace;  // held, so no later trace can take its address
    std::shared_ptr<const RenderOutput> frame;
    std::uint64_t revision = 0, frameRevision = 0;
    ExplorerStage stage = ExplorerStage::Vertex;
    int visit = -1, clipPass = -1, rasterStep = -1;
    bool perspectiveMap = false;
    ClipPlotAxes clipAxes = ClipPlotAxes::XW;
    bool operator==(const Key&) const = default;
  };
  std::optional<std::pair<Key, std::shared_ptr<const ExplorerView>>> kept_;
  int viewsMade_ = 0;
};

}  // namespace twr::gui
