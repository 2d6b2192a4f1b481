// The window's layout: controls on the left (resizable width), the image view top right,
// stats and the pixel inspector bottom right (resizable height). ImGui's ini file keeps
// the two sizes between runs.
#include "app/gui/app.h"

#include <algorithm>

namespace twr::gui {
namespace {

// Panel sizes at UI scale 1, screen points.
constexpr float kLeftPanelDefault = 390.0f;
constexpr float kLeftPanelMin = 280.0f;
constexpr float kBottomPanelDefault = 270.0f;
// ...or this share of the window height when that is more (fraction).
constexpr float kBottomPanelDefaultShare = 0.38f;
constexpr float kBottomPanelMin = 120.0f;
// Largest share of the window either side panel may take (fraction, inclusive), so the
// image keeps most of a small window.
constexpr float kMaxPanelShare = 0.45f;

constexpr ImGuiWindowFlags kDockedFlags = ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoCollapse;

}  // namespace

void GuiApp::drawLayout() {
  const ImGuiViewport* viewport = ImGui::GetMainViewport();
  const ImVec2 origin = viewport->WorkPos;
  const ImVec2 size = viewport->WorkSize;

  const float leftMin = std::min(kLeftPanelMin * uiScale_, size.x);
  const float leftMax = std::max(leftMin, size.x * kMaxPanelShare);
  ImGui::SetNextWindowPos(origin, ImGuiCond_Always);
  ImGui::SetNextWindowSize(ImVec2(kLeftPanelDefault * uiScale_, size.y), ImGuiCond_FirstUseEver);
  ImGui::SetNextWindowSizeConstraints(ImVec2(leftMin, size.y), ImVec2(leftMax, size.y));
  if (ImGui::Begin("Controls", nullptr, kDockedFlags)) drawControlsPanel();
  leftPanelWidth_ = std::clamp(ImGui::GetWindowWidth(), leftMin, leftMax);
  ImGui::End();

  const float rightX = origin.x + leftPanelWidth_;
  const float rightWidth = std::max(1.0f, size.x - leftPanelWidth_);
  const float bottomMin = std::min(kBottomPanelMin * uiScale_, size.y);
  const float bottomMax = std::max(bottomMin, size.y * kMaxPanelShare);
  const float bottomDefault = std::max(kBottomPanelDefault * uiScale_, kBottomPanelDefaultShare * size.y);
  if (bottomPanelHeight_ <= 0.0f) bottomPanelHeight_ = bottomDefault;
  bottomPanelHeight_ = std::clamp(bottomPanelHeight_, bottomMin, bottomMax);
  ImGui::SetNextWindowPos(ImVec2(rightX, origin.y + size.y - bottomPanelHeight_), ImGuiCond_Always);
  ImGui::SetNextWindowSize(ImVec2(rightWidth, bottomDefault), ImGuiCond_FirstUseEver);
  ImGui::SetNextWindowSizeConstraints(ImVec2(rightWidth, bottomMin), ImVec2(rightWidth, bottomMax));
  if (ImGui::Begin("Stats and pixel inspector", nullptr, kDockedFlags)) {
    if (ImGui::BeginTable("##bottom", 2, ImGuiTableFlags_Resizable | ImGuiTableFlags_BordersInnerV)) {
      ImGui::TableSetupColumn("stats", ImGuiTableColumnFlags_WidthStretch, 1.0f);
      ImGui::TableSetupColumn("inspector", ImGuiTableColumnFlags_WidthStretch, 1.15f);
      ImGui::TableNextRow();
      ImGui::TableSetColumnIndex(0);
      if (ImGui::BeginChild("##stats")) drawStatsPanel();
      ImGui::EndChild();
      ImGui::TableSetColumnIndex(1);
      if (ImGui::BeginChild("##inspector")) drawInspectorPanel();
      ImGui::EndChild();
      ImGui::EndTable();
    }
  }
  bottomPanelHeight_ = std::clamp(ImGui::GetWindowHeight(), bottomMin, bottomMax);
  ImGui::End();

  ImGui::SetNextWindowPos(ImVec2(rightX, origin.y), ImGuiCond_Always);
  ImGui::SetNextWindowSize(ImVec2(rightWidth, std::max(1.0f, size.y - bottomPanelHeight_)), ImGuiCond_Always);
  if (ImGui::Begin("View", nullptr,
                   kDockedFlags | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoScrollbar |
                       ImGuiWindowFlags_NoScrollWithMouse | ImGuiWindowFlags_NoBringToFrontOnFocus)) {
    drawViewPanel();
  }
  ImGui::End();
}

void GuiApp::drawControlsPanel() {
  if (!ImGui::BeginTabBar("##controls")) return;
  if (ImGui::BeginTabItem("Rendering")) {
    drawRenderingTab();
    ImGui::EndTabItem();
  }
  const ImGuiTabItemFlags sceneFlags = selectSceneTab_ ? ImGuiTabItemFlags_SetSelected : 0;
  selectSceneTab_ = false;
  if (ImGui::BeginTabItem("Scene", nullptr, sceneFlags)) {
    drawSceneTab();
    ImGui::EndTabItem();
  }
  if (ImGui::BeginTabItem("Camera")) {
    drawCameraTab();
    ImGui::EndTabItem();
  }
  ImGui::EndTabBar();
}

}  // namespace twr::gui
