// The window's layout: controls on the left (resizable width), the image view top right,
// stats and the pixel inspector bottom right (resizable height). gui.json keeps the two
// sizes the user dragged to between runs (not ImGui's ini file: see panel_sizing.h).
#include "app/gui/app.h"
#include "app/gui/ui_widgets.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui_internal.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <iostream>

namespace twr::gui {
namespace {

// Panel sizes at UI scale 1, screen points. Below the minimum width the Rendering tab's
// radio rows wrap (enumRadio) but labels no longer fit beside their fields.
constexpr float kLeftPanelDefault = 390.0f;
constexpr float kLeftPanelMin = 300.0f;
constexpr float kBottomPanelDefault = 270.0f;
// ...or this share of the window height when that is more (fraction).
constexpr float kBottomPanelDefaultShare = 0.38f;
constexpr float kBottomPanelMin = 120.0f;
// Largest share of the window either side panel may take (fraction, inclusive), so the
// image keeps most of a small window.
constexpr float kMaxPanelShare = 0.45f;

// A panel size that differs from the one asked by more than this was dragged by the user,
// ImGui units (ImGui floors sizes, so anything below 1 is rounding).
constexpr float kResizeTolerance = 1.5f;
// How long a panel's error stays on screen after its last occurrence, seconds.
constexpr double kFaultSeconds = 5.0;

// The side panels are sized by the app every frame (prefs_), so ImGui's ini keeps nothing
// of theirs: no squeezed size survives a restart.
constexpr ImGuiWindowFlags kDockedFlags =
    ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoSavedSettings;

}  // namespace

void GuiApp::drawLayout() {
  const ImGuiViewport* viewport = ImGui::GetMainViewport();
  const ImVec2 origin = viewport->WorkPos;
  const ImVec2 size = viewport->WorkSize;

  // The Controls width: the user's (prefs_), squeezed by a small window but never replaced
  // by the squeezed size (panel_sizing.h). ImGui's ini file does not keep it.
  const PanelLimits leftLimits{kLeftPanelMin * uiScale_, kMaxPanelShare, kLeftPanelDefault * uiScale_};
  if (prefs_.controlsWidth > 0.0f && prefs_.controlsWidth < kLeftPanelMin) prefs_.controlsWidth = 0.0f;
  const float leftAsked = std::floor(shownPanelSize(prefs_.controlsWidth * uiScale_, size.x, leftLimits));
  const float leftMax = std::max(leftAsked, std::min(size.x, std::max(leftLimits.minimum, size.x * kMaxPanelShare)));
  ImGui::SetNextWindowPos(origin, ImGuiCond_Always);
  ImGui::SetNextWindowSize(ImVec2(leftAsked, size.y), ImGuiCond_Always);
  ImGui::SetNextWindowSizeConstraints(ImVec2(std::min(leftAsked, leftLimits.minimum), size.y), ImVec2(leftMax, size.y));
  if (ImGui::Begin("Controls", nullptr, kDockedFlags)) {
    drawGuarded("Controls", [this] { drawControlsPanel(); });
  }
  leftPanelWidth_ = ImGui::GetWindowWidth();
  ImGui::End();
  if (std::fabs(leftPanelWidth_ - leftAsked) > kResizeTolerance) {
    prefs_.controlsWidth = sanitisePreferred(leftPanelWidth_, leftLimits) / uiScale_;
  }
  // A camera edit in the Controls panel is judged before the view draws with it.
  refreshRenderBlocker();

  const float rightX = origin.x + leftPanelWidth_;
  const float rightWidth = std::max(1.0f, size.x - leftPanelWidth_);
  const float bottomDefault = std::max(kBottomPanelDefault * uiScale_, kBottomPanelDefaultShare * size.y);
  const PanelLimits bottomLimits{kBottomPanelMin * uiScale_, kMaxPanelShare, bottomDefault};
  if (prefs_.statsHeight > 0.0f && prefs_.statsHeight < kBottomPanelMin) prefs_.statsHeight = 0.0f;
  const float bottomAsked = std::floor(shownPanelSize(prefs_.statsHeight * uiScale_, size.y, bottomLimits));
  const float bottomMax =
      std::max(bottomAsked, std::min(size.y, std::max(bottomLimits.minimum, size.y * kMaxPanelShare)));
  ImGui::SetNextWindowPos(ImVec2(rightX, origin.y + size.y - bottomAsked), ImGuiCond_Always);
  ImGui::SetNextWindowSize(ImVec2(rightWidth, bottomAsked), ImGuiCond_Always);
  ImGui::SetNextWindowSizeConstraints(ImVec2(rightWidth, std::min(bottomAsked, bottomLimits.minimum)),
                                      ImVec2(rightWidth, bottomMax));
  if (ImGui::Begin("Stats and pixel inspector", nullptr, kDockedFlags)) {
    if (ImGui::BeginTable("##bottom", 2, ImGuiTableFlags_Resizable | ImGuiTableFlags_BordersInnerV)) {
      ImGui::TableSetupColumn("stats", ImGuiTableColumnFlags_WidthStretch, 1.0f);
      ImGui::TableSetupColumn("inspector", ImGuiTableColumnFlags_WidthStretch, 1.15f);
      ImGui::TableNextRow();
      ImGui::TableSetColumnIndex(0);
      if (ImGui::BeginChild("##stats")) drawGuarded("Stats", [this] { drawStatsPanel(); });
      ImGui::EndChild();
      probe_.item("stats_panel");
      ImGui::TableSetColumnIndex(1);
      if (ImGui::BeginChild("##inspector")) drawGuarded("Inspector", [this] { drawInspectorPanel(); });
      ImGui::EndChild();
      ImGui::EndTable();
    }
  }
  bottomPanelHeight_ = ImGui::GetWindowHeight();
  ImGui::End();
  if (std::fabs(bottomPanelHeight_ - bottomAsked) > kResizeTolerance) {
    prefs_.statsHeight = sanitisePreferred(bottomPanelHeight_, bottomLimits) / uiScale_;
  }

  ImGui::SetNextWindowPos(ImVec2(rightX, origin.y), ImGuiCond_Always);
  ImGui::SetNextWindowSize(ImVec2(rightWidth, std::max(1.0f, size.y - bottomPanelHeight_)), ImGuiCond_Always);
  if (ImGui::Begin("View", nullptr,
                   kDockedFlags | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoScrollbar |
                       ImGuiWindowFlags_NoScrollWithMouse | ImGuiWindowFlags_NoBringToFrontOnFocus)) {
    drawGuarded("View", [this] { drawViewPanel(); });
  }
  ImGui::End();

  if (probe_.enabled()) {
    nlohmann::json& state = probe_.state();
    state["window"] = {size.x, size.y};
    state["controls_width"] = leftPanelWidth_;
    state["stats_height"] = bottomPanelHeight_;
  }
}

void GuiApp::drawGuarded(const char* panel, const std::function<void()>& draw) {
  ImGuiContext& context = *ImGui::GetCurrentContext();
  ImGuiWindow* const window = context.CurrentWindow;
  drawPanelFault(panel);
  try {
    draw();
  } catch (const std::exception& e) {
    // Unwind whatever the panel had open (child windows, popups, tables, tree nodes, IDs,
    // styles) back to its own window, so the frame still ends cleanly.
    while (context.CurrentWindow && context.CurrentWindow != window) {
      ImGui::ErrorCheckEndWindowRecover(nullptr);
      if (context.CurrentWindow->Flags & ImGuiWindowFlags_ChildWindow) ImGui::EndChild();
      else ImGui::End();
    }
    ImGui::ErrorCheckEndWindowRecover(nullptr);
    PanelFault& fault = panelFaults_[panel];
    if (fault.message != e.what()) std::cerr << "twinraster-gui: " << panel << " panel: " << e.what() << "\n";
    fault.message = e.what();
    fault.time = ImGui::GetTime();
  }
}

void GuiApp::drawPanelFault(const char* panel) {
  const auto fault = panelFaults_.find(panel);
  if (fault == panelFaults_.end()) return;
  if (ImGui::GetTime() - fault->second.time > kFaultSeconds) {
    panelFaults_.erase(fault);
    return;
  }
  redraw_.redrawAt(glfwGetTime() + (fault->second.time + kFaultSeconds - ImGui::GetTime()));  // to take it away
  errorText(std::string(panel) + " panel: " + fault->second.message +
            " (the rest of this panel was skipped; the app keeps running)");
  if (probe_.enabled()) probe_.state()["panel_faults"][panel] = fault->second.message;
}

void GuiApp::drawControlsPanel() {
  if (!ImGui::BeginTabBar("##controls")) return;
  const bool rendering = ImGui::BeginTabItem("Rendering");
  probe_.item("tab_rendering");
  if (rendering) {
    drawRenderingTab();
    ImGui::EndTabItem();
  }
  const ImGuiTabItemFlags sceneFlags = selectSceneTab_ ? ImGuiTabItemFlags_SetSelected : 0;
  selectSceneTab_ = false;
  const bool scene = ImGui::BeginTabItem("Scene", nullptr, sceneFlags);
  probe_.item("tab_scene");
  if (scene) {
    drawSceneTab();
    ImGui::EndTabItem();
  }
  const bool camera = ImGui::BeginTabItem("Camera");
  probe_.item("tab_camera");
  if (camera) {
    drawCameraTab();
    ImGui::EndTabItem();
  }
  ImGui::EndTabBar();
}

}  // namespace twr::gui
