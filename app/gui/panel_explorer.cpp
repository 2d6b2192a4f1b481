// The inspector's stage explorer: the pinned pixel's triangle stepped through the CPU pipeline,
// vertex to shade, with the stage's numbers and its overlay on every image. What it shows is
// gui/stage_explorer.h's, from the pixel trace.
#include "app/gui/app.h"
#include "app/gui/ui_widgets.h"
#include "gui/text_concat.h"
#include "softrender/stage_pictures.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdio>
#include <iterator>

namespace twr::gui {
namespace {

// The stage buttons' short names (titleOf heads the numbers).
const char* buttonLabelOf(ExplorerStage stage) {
  return stage == ExplorerStage::Divide ? "Divide" : titleOf(stage);
}

ImU32 colourOf(int r, int g, int b, int a = 255) { return IM_COL32(r, g, b, a); }

}  // namespace

std::shared_ptr<const ExplorerView> GuiApp::explorerView(bool glSide) const {
  if (!pin_.cpu || pin_.cpuRevision != doc_.revision) return nullptr;
  const BackendFrame& backend = glSide ? glFrame_ : cpuFrame_;
  const ExplorerPosition position{explorerStage_, explorerVisit_,
                                  ExplorerChoices{explorerClipPass_, explorerRasterStep_, explorerPerspectiveMap_,
                                                  explorerClipAxes_}};
  return explorerViews_[glSide ? 1 : 0].viewOf(pin_.cpu->trace, doc_.revision, backend.output, backend.revision,
                                               position);
}

void GuiApp::drawStageExplorerSection() {
  explorerOpen_ = ImGui::CollapsingHeader("Stage explorer###explorer", ImGuiTreeNodeFlags_DefaultOpen);
  probe_.item("explorer");
  if (!explorerOpen_) return;
  if (pin_.cpuRevision != doc_.revision) {
    hintText("Waiting for the CPU trace of this edit...");
    return;
  }
  if (!explorerVisitOf(*pin_.cpu->trace, explorerVisit_)) {
    hintText("No triangle reaches this pixel: nothing to step through.");
    return;
  }
  drawVisitChoice();
  if (ImGui::SmallButton("< Previous")) explorerStage_ = previousStage(explorerStage_);
  probe_.item("explorer_previous");
  ImGui::SameLine();
  if (ImGui::SmallButton("Next >")) explorerStage_ = nextStage(explorerStage_);
  probe_.item("explorer_next");
  // One button per stage, wrapped onto the next line where the panel is narrow.
  const ImGuiStyle& style = ImGui::GetStyle();
  const float right = ImGui::GetWindowPos().x + ImGui::GetWindowContentRegionMax().x;
  for (const ExplorerStage stage : kExplorerStages) {
    const char* label = buttonLabelOf(stage);
    const float width = ImGui::CalcTextSize(label).x + 2.0f * style.FramePadding.x;
    if (ImGui::GetItemRectMax().x + style.ItemSpacing.x + width <= right) ImGui::SameLine();
    const bool shown = stage == explorerStage_;
    if (shown) ImGui::PushStyleColor(ImGuiCol_Button, ImGui::GetStyleColorVec4(ImGuiCol_ButtonActive));
    if (ImGui::SmallButton(label)) explorerStage_ = stage;
    if (shown) ImGui::PopStyleColor();
    probe_.item(concat("explorer_stage_", toString(stage)).c_str());
  }
  if (explorerStage_ == ExplorerStage::Clip) drawClipPassButtons();
  if (explorerStage_ == ExplorerStage::Interpolate) drawWeightMapChoice();
  const std::shared_ptr<const ExplorerView> view = explorerView();
  if (!view) return;
  if (view->stage == ExplorerStage::Raster) drawVisitOrderControls(*view);
  if (view->stage == ExplorerStage::Clip) drawClipPlot(*view);
  hintText(stageHintOf(view->stage));
  if (monoFont_) ImGui::PushFont(monoFont_);
  for (const std::string& line : view->lines) ImGui::TextWrapped("%s", line.c_str());
  probe_.item("explorer_last_line");  // where the section ends (the docs' pictures crop to it)
  if (monoFont_) ImGui::PopFont();
  if (probe_.enabled()) {
    nlohmann::json& state = probe_.state()["explorer"];
    state = explorerViewToJson(*view);
    state["visit"] = visitChoiceText(*pin_.cpu->trace, explorerVisit_);
    if (const std::shared_ptr<const ExplorerView> gl = explorerView(true)) state["overlay"]["covered_gl"] = gl->overlay.covered.size();
  }
}

// The Clip stage's pass picker: all passes (the final polygon) or one plane's before and after.
void GuiApp::drawClipPassButtons() {
  const std::shared_ptr<const ExplorerView> view = explorerView();
  if (!view || view->clipPasses == 0) return;
  if (ImGui::SmallButton("< Pass")) explorerClipPass_ = view->clipPass < 0 ? view->clipPasses - 1 : view->clipPass - 1;
  probe_.item("explorer_pass_previous");
  ImGui::SameLine();
  if (ImGui::SmallButton("Pass >")) explorerClipPass_ = view->clipPass + 1 >= view->clipPasses ? -1 : view->clipPass + 1;
  probe_.item("explorer_pass_next");
  ImGui::SameLine();
  if (view->clipPass < 0) {
    ImGui::Text("all %d passes: the polygon the last one left", view->clipPasses);
  } else {
    ImGui::Text("pass %d of %d: grey before the plane, cyan what it left", view->clipPass + 1, view->clipPasses);
    hintText("A side plane cuts at the image's edge, so what it removes lies off the image; the plot below draws "
             "the pass in clip space, where it shows (as `twinraster trace --stages` does).");
  }
}

// The Clip stage's plot of the pass shown: x, y or z against w, where the two planes of that
// axis are the diagonals through the origin and a cut lies where an edge crosses one, or NDC
// with the frustum's square. One unit is as long across as up, so the diagonals stay at 45
// degrees.
void GuiApp::drawClipPlot(const ExplorerView& view) {
  for (const ClipPlotAxes axes : kClipPlotAxes) {
    if (axes != kClipPlotAxes[0]) ImGui::SameLine();
    const char* label = axes == ClipPlotAxes::XW   ? "x against w"
                        : axes == ClipPlotAxes::YW ? "y against w"
                        : axes == ClipPlotAxes::ZW ? "z against w"
                                                   : "NDC";
    if (ImGui::RadioButton(label, explorerClipAxes_ == axes)) explorerClipAxes_ = axes;
    probe_.item(concat("explorer_axes_", toString(axes)).c_str());
  }
  if (!view.clipPlot) return;
  const ClipPlot& plot = *view.clipPlot;
  const float width = ImGui::GetContentRegionAvail().x;
  const ImVec2 size(width, std::min(0.6f * width, 260.0f * uiScale_));
  const ImVec2 corner = ImGui::GetCursorScreenPos();
  ImGui::Dummy(size);
  probe_.item("explorer_clip_plot");
  const ImVec2 end(corner.x + size.x, corner.y + size.y);
  ImDrawList* draw = ImGui::GetWindowDrawList();
  draw->AddRectFilled(corner, end, colourOf(18, 20, 26));
  draw->PushClipRect(corner, end, true);
  const auto& b = plot.bounds;
  const double scale = std::min(size.x / (b[2] - b[0]), size.y / (b[3] - b[1]));
  const double midH = 0.5 * (b[0] + b[2]), midV = 0.5 * (b[1] + b[3]);
  const auto at = [&](const PlotPoint& p) {
    return ImVec2(corner.x + 0.5f * size.x + static_cast<float>((p[0] - midH) * scale),
                  corner.y + 0.5f * size.y - static_cast<float>((p[1] - midV) * scale));
  };
  const ImU32 axisColour = colourOf(110, 110, 120);
  draw->AddLine(at({b[0], 0.0}), at({b[2], 0.0}), axisColour);
  draw->AddLine(at({0.0, b[1]}), at({0.0, b[3]}), axisColour);
  draw->AddText(ImVec2(end.x - 40.0f * uiScale_, at({0.0, 0.0}).y + 2.0f), axisColour, plot.horizontal.c_str());
  draw->AddText(ImVec2(at({0.0, 0.0}).x + 4.0f, corner.y + 2.0f), axisColour, plot.vertical.c_str());
  for (const ClipPlotLine& line : plot.planes) {
    const ImU32 colour = line.cutting ? colourOf(255, 220, 60) : colourOf(200, 120, 60, 170);
    draw->AddLine(at(line.from), at(line.to), colour, (line.cutting ? 2.0f : 1.0f) * uiScale_);
    // The name near the top of a diagonal, at the middle of a side of the NDC square.
    const double along = plot.axes == ClipPlotAxes::Ndc ? 0.5 : 0.85;
    const ImVec2 tip = at({line.from[0] + along * (line.to[0] - line.from[0]), line.from[1] + along * (line.to[1] - line.from[1])});
    // Kept inside the plot (a narrow plot keeps the left and top edges first).
    const ImVec2 label(std::max(corner.x + 2.0f, std::min(tip.x + 4.0f, end.x - 110.0f * uiScale_)),
                       std::max(corner.y + 2.0f, std::min(tip.y, end.y - 16.0f * uiScale_)));
    draw->AddText(label, colour, line.name.c_str());
  }
  const auto polygon = [&](const std::vector<PlotPoint>& points, ImU32 colour) {
    std::vector<ImVec2> screen;
    for (const PlotPoint& p : points) screen.push_back(at(p));
    if (screen.size() >= 2) draw->AddPolyline(screen.data(), static_cast<int>(screen.size()), colour, ImDrawFlags_Closed, 1.5f * uiScale_);
    for (const ImVec2& p : screen) draw->AddCircleFilled(p, 2.5f * uiScale_, colour);
  };
  polygon(plot.before, colourOf(170, 170, 170, 220));
  polygon(plot.after, colourOf(90, 220, 255));
  for (std::size_t k = 0; k < plot.cuts.size(); ++k) {
    const ImVec2 p = at(plot.cuts[k]);
    draw->AddCircle(p, 5.0f * uiScale_, colourOf(255, 255, 255), 0, 1.5f * uiScale_);
    char label[32];
    std::snprintf(label, sizeof label, "t %.3g", plot.cutTs[k]);
    // One line below the other: a pass's two cuts can lie close together on the plot.
    draw->AddText(ImVec2(p.x + 7.0f, p.y + (2.0f + 15.0f * static_cast<float>(k)) * uiScale_), colourOf(255, 255, 255), label);
  }
  draw->PopClipRect();
  if (plot.offPlot > 0) hintText(concat(plot.offPlot, " vertices behind the eye (w <= 0) have no NDC: left out.").c_str());
}

// The Raster stage's visit order: a slider over the pixels in the order the rasterizer visits
// them, and buttons that step a pixel or a span at a time.
void GuiApp::drawVisitOrderControls(const ExplorerView& view) {
  if (view.rasterSteps == 0) return;
  const PixelTrace& trace = *pin_.cpu->trace;
  const TriangleVisit& visit = *explorerVisitOf(trace, explorerVisit_);
  const int shown = view.rasterStep;
  if (ImGui::SmallButton("< Span")) explorerRasterStep_ = spanStepFrom(trace, visit, shown, -1);
  probe_.item("explorer_span_previous");
  ImGui::SameLine();
  if (ImGui::SmallButton("< Pixel")) explorerRasterStep_ = std::max(shown - 1, 0);
  probe_.item("explorer_pixel_previous");
  ImGui::SameLine();
  if (ImGui::SmallButton("Pixel >")) explorerRasterStep_ = std::min(shown + 1, view.rasterSteps - 1);
  probe_.item("explorer_pixel_next");
  ImGui::SameLine();
  if (ImGui::SmallButton("Span >")) explorerRasterStep_ = spanStepFrom(trace, visit, shown, +1);
  probe_.item("explorer_span_next");
  ImGui::SameLine();
  if (ImGui::SmallButton("Traced")) explorerRasterStep_ = visitStepOf(trace, visit);
  probe_.item("explorer_step_traced");
  ImGui::SameLine();
  if (ImGui::SmallButton("Off")) explorerRasterStep_ = -1;
  probe_.item("explorer_step_off");
  int step = std::max(shown, 0);
  ImGui::SetNextItemWidth(-FLT_MIN);
  if (ImGui::SliderInt("##visit", &step, 0, view.rasterSteps - 1, shown < 0 ? "visit order: off" : "step %d")) {
    explorerRasterStep_ = step;
  }
  probe_.item("explorer_visit_slider");
  hintText("Purple: the pixels visited so far, in the rasterizer's order; white: the pixel of this step.");
}

// Which of the triangles reaching the pixel the explorer follows (the one that wrote it first):
// a hidden triangle, culled or behind another, is stepped through the same way.
void GuiApp::drawVisitChoice() {
  const PixelTrace& trace = *pin_.cpu->trace;
  const int count = static_cast<int>(trace.visits.size());
  if (count > 1) {
    const TriangleVisit* shown = explorerVisitOf(trace, explorerVisit_);
    const int index = static_cast<int>(shown - trace.visits.data());
    if (ImGui::SmallButton("< Triangle")) explorerVisit_ = std::max(index - 1, 0);
    probe_.item("explorer_visit_previous");
    ImGui::SameLine();
    if (ImGui::SmallButton("Triangle >")) explorerVisit_ = std::min(index + 1, count - 1);
    probe_.item("explorer_visit_next");
    ImGui::SameLine();
  }
  ImGui::TextWrapped("%s", visitChoiceText(trace, explorerVisit_).c_str());
}

// The Interpolate stage's map: the screen barycentrics or the perspective weights.
void GuiApp::drawWeightMapChoice() {
  if (ImGui::RadioButton("Screen barycentrics", !explorerPerspectiveMap_)) explorerPerspectiveMap_ = false;
  probe_.item("explorer_weights_screen");
  ImGui::SameLine();
  if (ImGui::RadioButton("Perspective weights", explorerPerspectiveMap_)) explorerPerspectiveMap_ = true;
  probe_.item("explorer_weights_perspective");
}

// The weight map's texture is uploaded once per view and drawn on every image.
void GuiApp::drawWeightMap(ImDrawList* draw, const ExplorerView& view, ImVec2 imageMin, ImVec2 imageMax) const {
  const ExplorerWeightMap& map = view.overlay.weightMap;
  if (map.covered.empty()) return;
  const WeightMapKey key{pin_.cpu->trace, explorerVisit_, view.perspectiveMap};
  if (explorerWeightKey_ != key) {
    explorerWeightTexture_.upload(weightMapImage(map));
    explorerWeightKey_ = key;
  }
  const float sx = (imageMax.x - imageMin.x) / static_cast<float>(renderWidth_);
  const float sy = (imageMax.y - imageMin.y) / static_cast<float>(renderHeight_);
  const ImVec2 from(imageMin.x + static_cast<float>(map.x0) * sx, imageMin.y + static_cast<float>(map.y0) * sy);
  const ImVec2 to(from.x + static_cast<float>(map.width) * sx, from.y + static_cast<float>(map.height) * sy);
  draw->AddImage(explorerWeightTexture_.id(), from, to, ImVec2(0, 0), ImVec2(1, 1), IM_COL32(255, 255, 255, 235));
}

void GuiApp::drawExplorerOverlay(ImDrawList* draw, const ExplorerView& view, ImVec2 imageMin, ImVec2 imageMax) const {
  const float sx = (imageMax.x - imageMin.x) / static_cast<float>(renderWidth_);
  const float sy = (imageMax.y - imageMin.y) / static_cast<float>(renderHeight_);
  const auto at = [&](const ImagePoint& p) {
    return ImVec2(imageMin.x + static_cast<float>(p.x) * sx, imageMin.y + static_cast<float>(p.y) * sy);
  };
  const float thick = 1.5f * uiScale_;
  const auto outline = [&](const std::vector<ImagePoint>& points, ImU32 colour, float width) {
    std::vector<ImVec2> screen;
    for (const ImagePoint& p : points) screen.push_back(at(p));
    if (screen.size() >= 2) draw->AddPolyline(screen.data(), static_cast<int>(screen.size()), colour, ImDrawFlags_Closed, width);
    for (const ImVec2& p : screen) draw->AddCircleFilled(p, 2.5f * uiScale_, colour);
  };
  const ExplorerOverlay& o = view.overlay;
  drawWeightMap(draw, view, imageMin, imageMax);
  // The pixels won, one rectangle per run along a row.
  for (std::size_t i = 0; i < o.covered.size();) {
    std::size_t end = i + 1;
    while (end < o.covered.size() && o.covered[end][1] == o.covered[i][1] && o.covered[end][0] == o.covered[end - 1][0] + 1) ++end;
    const ImagePoint from{static_cast<double>(o.covered[i][0]), static_cast<double>(o.covered[i][1])};
    const ImagePoint to{static_cast<double>(o.covered[end - 1][0] + 1), static_cast<double>(o.covered[i][1] + 1)};
    draw->AddRectFilled(at(from), at(to), colourOf(80, 220, 110, 90));
    i = end;
  }
  if (o.boundingBox) {
    const auto& b = *o.boundingBox;
    draw->AddRect(at({static_cast<double>(b[0]), static_cast<double>(b[1])}),
                  at({static_cast<double>(b[2] + 1), static_cast<double>(b[3] + 1)}), colourOf(200, 200, 200, 200), 0.0f, 0,
                  thick);
  }
  for (std::size_t k = 0; k < o.fan.size(); ++k) {
    const auto& t = o.fan[k];
    if (static_cast<int>(k) == o.fanTriangle) draw->AddTriangleFilled(at(t[0]), at(t[1]), at(t[2]), colourOf(90, 200, 255, 70));
    draw->AddTriangle(at(t[0]), at(t[1]), at(t[2]), colourOf(90, 200, 255, 160), 1.0f);
  }
  outline(o.polygonBefore, colourOf(170, 170, 170, 220), thick);
  if (o.triangle.size() == 3) outline(o.triangle, colourOf(255, 220, 60), thick);
  else for (const ImagePoint& p : o.triangle) draw->AddCircleFilled(at(p), 3.0f * uiScale_, colourOf(255, 220, 60));
  outline(o.polygon, colourOf(90, 220, 255), thick);
  for (std::size_t k = 0; k < o.polygon.size(); ++k) {
    const ImVec2 p = at(o.polygon[k]);
    draw->AddText(ImVec2(p.x + 4.0f, p.y - 14.0f * uiScale_), colourOf(90, 220, 255), concat('p', k).c_str());
  }
  outline(o.snapped, colourOf(255, 150, 50), thick);
  // The fill rule along a shared edge: each side's pixels in its own colour, the centres on it outlined.
  if (o.sharedEdge) {
    const ExplorerSharedEdge& e = *o.sharedEdge;
    const auto cells = [&](const std::vector<std::array<int, 2>>& pixels, ImU32 colour, bool filled) {
      for (const auto& p : pixels) {
        const ImVec2 from = at({static_cast<double>(p[0]), static_cast<double>(p[1])});
        const ImVec2 to = at({static_cast<double>(p[0] + 1), static_cast<double>(p[1] + 1)});
        if (filled) draw->AddRectFilled(from, to, colour);
        else draw->AddRect(from, to, colour, 0.0f, 0, thick);
      }
    };
    cells(e.mine, colourOf(70, 140, 255, 150), true);
    cells(e.theirs, colourOf(255, 150, 40, 150), true);
    cells(e.onEdge, colourOf(255, 255, 255), false);
    draw->AddLine(at(e.from), at(e.to), colourOf(255, 255, 255, 200), 1.0f * uiScale_);
  }
  // The visit order so far, and the pixel of the step.
  for (const auto& run : o.visitedRuns) {
    draw->AddRectFilled(at({static_cast<double>(run[0]), static_cast<double>(run[2])}),
                        at({static_cast<double>(run[1]), static_cast<double>(run[2] + 1)}), colourOf(200, 90, 255, 120));
  }
  if (o.visitPixel) {
    const ImagePoint p{static_cast<double>((*o.visitPixel)[0]), static_cast<double>((*o.visitPixel)[1])};
    draw->AddRect(at(p), at({p.x + 1.0, p.y + 1.0}), colourOf(255, 255, 255), 0.0f, 0, thick);
  }
  // The weight map's corners, each in its weight's colour.
  const ImU32 cornerColours[] = {colourOf(255, 70, 70), colourOf(70, 255, 70), colourOf(90, 140, 255)};
  for (std::size_t i = 0; i < o.weightCorners.size() && i < 3; ++i) {
    const ImVec2 p = at(o.weightCorners[i]);
    draw->AddCircleFilled(p, 4.0f * uiScale_, cornerColours[i]);
    draw->AddText(ImVec2(p.x + 5.0f, p.y - 14.0f * uiScale_), cornerColours[i], concat('c', i).c_str());
  }
  // The surface frame at the fragment: T red, B green, N blue (as the TBN debug lines), the lit normal white.
  for (const ExplorerFrameArrow& a : o.frameArrows) {
    const ImU32 colour = a.axis == 'T'   ? colourOf(255, 80, 80)
                         : a.axis == 'B' ? colourOf(80, 255, 80)
                         : a.axis == 'N' ? colourOf(90, 140, 255)
                                         : colourOf(255, 255, 255);
    // Nl thin over the others, its label below the tip: it lies on N where no map bends it.
    const bool lit = a.axis == 'L';
    const ImVec2 from = at(a.from), to = at(a.to);
    draw->AddLine(from, to, colour, (lit ? 1.0f : 2.5f) * uiScale_);
    if (lit) draw->AddCircle(to, 4.0f * uiScale_, colour, 0, 1.0f * uiScale_);
    else draw->AddCircleFilled(to, 3.0f * uiScale_, colour);
    const char axis[2] = {a.axis, '\0'};
    draw->AddText(ImVec2(to.x + 5.0f * uiScale_, to.y + (lit ? 2.0f : -15.0f) * uiScale_), colour, lit ? "Nl" : axis);
  }
}

}  // namespace twr::gui
