// The inspector's stage explorer: the pinned pixel's triangle stepped through the CPU pipeline,
// vertex to shade, with the stage's numbers and its overlay on every image. What it shows is
// gui/stage_explorer.h's, from the pixel trace.
#include "app/gui/app.h"
#include "app/gui/ui_widgets.h"
#include "gui/text_concat.h"
#include "softrender/stage_pictures.h"

#include <nlohmann/json.hpp>

#include <iterator>

namespace twr::gui {
namespace {

// What each stage does, for the student reading the numbers under it.
const char* stageHint(ExplorerStage stage) {
  switch (stage) {
    case ExplorerStage::Vertex:
      return "The vertex stage (shaders/phong.vert, softrender/vertex.cpp) takes each corner from model space to "
             "clip space, clip = P V M p. Dots: the corners in front of the eye (w > 0) on the image.";
    case ExplorerStage::Clip:
      return "Sutherland-Hodgman (softrender/clip.cpp), one plane after another: each keeps the part of the polygon "
             "inside it and makes a vertex where an edge crosses it, at t along that edge. Yellow: the triangle; "
             "cyan: the polygon the last plane left.";
    case ExplorerStage::Divide:
      return "The divide (x/w, y/w, z/w: NDC) and the viewport, window = (ndc + 1) / 2 * size (softrender/setup.cpp). "
             "The polygon goes on as a fan from its first vertex; the fan triangle that covers the pixel is filled.";
    case ExplorerStage::Setup:
      return "Setup snaps the corners to 1/256 pixel (orange), orders them clockwise and makes three edge functions "
             "E = c + stepX x + stepY y, positive inside; the box (grey) bounds the pixels to test.";
    case ExplorerStage::Raster:
      return "Every pixel centre in the box is tested: inside when all three E > 0. A pixel exactly on an edge two "
             "triangles share goes to the one for which it is a left or bottom edge (the fill rule), so it is drawn "
             "once. Green: the pixels this triangle won in the frame.";
    case ExplorerStage::Interpolate:
      return "Screen barycentrics are each E over twice the area; the perspective weights divide each by its "
             "corner's w and sum to 1 again (softrender/interpolate.h), so textures do not swim.";
    case ExplorerStage::Shade:
      return "Phong at the pixel (shaders/phong.frag, softrender/shade-inl.h): ambient plus each light's diffuse "
             "and specular, with its attenuation If.";
  }
  return "";
}

// The stage buttons' short names (titleOf heads the numbers).
const char* buttonLabelOf(ExplorerStage stage) {
  return stage == ExplorerStage::Divide ? "Divide" : titleOf(stage);
}

ImU32 colourOf(int r, int g, int b, int a = 255) { return IM_COL32(r, g, b, a); }

}  // namespace

std::optional<ExplorerView> GuiApp::explorerView(bool glSide) const {
  if (!pin_.cpu || !pin_.cpu->trace || pin_.cpuRevision != doc_.revision) return std::nullopt;
  const PixelTrace& trace = *pin_.cpu->trace;
  const TriangleVisit* visit = stageVisitOf(trace);
  if (!visit) return std::nullopt;
  const BackendFrame& backend = glSide ? glFrame_ : cpuFrame_;
  const RenderOutput* frame = backend.output.get();
  const bool idsUsable = frame && backend.revision == doc_.revision && frame->width == trace.width &&
                         frame->height == trace.height && frame->triangleId.size() == frame->rgba.size() / 4;
  return explorerViewOf(trace, *visit, explorerStage_, idsUsable ? &frame->triangleId : nullptr, explorerClipPass_);
}

void GuiApp::drawStageExplorerSection() {
  explorerOpen_ = ImGui::CollapsingHeader("Stage explorer###explorer", ImGuiTreeNodeFlags_DefaultOpen);
  probe_.item("explorer");
  if (!explorerOpen_) return;
  if (pin_.cpuRevision != doc_.revision) {
    hintText("Waiting for the CPU trace of this edit...");
    return;
  }
  if (!stageVisitOf(*pin_.cpu->trace)) {
    hintText("No triangle reaches this pixel: nothing to step through.");
    return;
  }
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
  const std::optional<ExplorerView> view = explorerView();
  if (!view) return;
  hintText(stageHint(view->stage));
  if (monoFont_) ImGui::PushFont(monoFont_);
  for (const std::string& line : view->lines) ImGui::TextWrapped("%s", line.c_str());
  probe_.item("explorer_last_line");  // where the section ends (the docs' pictures crop to it)
  if (monoFont_) ImGui::PopFont();
  if (probe_.enabled()) {
    nlohmann::json& state = probe_.state()["explorer"];
    state = explorerViewToJson(*view);
    if (const std::optional<ExplorerView> gl = explorerView(true)) state["overlay"]["covered_gl"] = gl->overlay.covered.size();
  }
}

// The Clip stage's pass picker: all passes (the final polygon) or one plane's before and after.
void GuiApp::drawClipPassButtons() {
  const std::optional<ExplorerView> view = explorerView();
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
    hintText("A side plane cuts at the image's edge, so what it removes lies off the image; `twinraster trace "
             "--stages` draws each pass in clip space, where it shows.");
  }
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
}

}  // namespace twr::gui
