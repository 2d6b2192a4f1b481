// The stage explorer's kept views (gui/explorer_cache.h).
#include "gui/explorer_cache.h"

namespace twr::gui {

std::shared_ptr<const ExplorerView> ExplorerViewCache::viewOf(const std::shared_ptr<const PixelTrace>& trace,
                                                              std::uint64_t revision,
                                                              const std::shared_ptr<const RenderOutput>& frame,
                                                              std::uint64_t frameRevision,
                                                              const ExplorerPosition& position) {
  if (!trace) return nullptr;
  const TriangleVisit* visit = explorerVisitOf(*trace, position.visit);
  if (!visit) return nullptr;
  // The ids mark this trace's triangles only in a frame of the same edit and size.
  const bool idsUsable = frame && frameRevision == revision && frame->width == trace->width &&
                         frame->height == trace->height && frame->triangleId.size() == frame->rgba.size() / 4;
  const ExplorerChoices& c = position.choices;
  const Key key{trace,          idsUsable ? frame : nullptr, revision,     frameRevision, position.stage,
                position.visit, c.clipPass,                  c.rasterStep, c.perspectiveMap, c.clipAxes};
  if (!kept_ || !(kept_->first == key)) {
    ++viewsMade_;
    kept_.emplace(key, std::make_shared<const ExplorerView>(explorerViewOf(
                           *trace, *visit, position.stage, idsUsable ? &frame->triangleId : nullptr, c)));
  }
  return kept_->second;
}

}  // namespace twr::gui
