// The Camera tab: the course's P/T camera as numbers, and how the mouse moves it.
#include "app/gui/app.h"
#include "app/gui/ui_widgets.h"

#include "scene/camera.h"

namespace twr::gui {
namespace {

constexpr float kPositionDragSpeed = 0.01f;  // world units per pixel of mouse travel
// Field of view slider range, degrees (inclusive; the camera needs (0, 180) exclusive).
constexpr float kMinFovDeg = 1.0f;
constexpr float kMaxFovDeg = 170.0f;

}  // namespace

void GuiApp::drawCameraTab() {
  Camera& camera = doc_.scene.camera;
  bool changed = false;
  sectionTitle("Camera");
  const float fieldWidth = ImGui::GetContentRegionAvail().x * 0.6f;
  ImGui::SetNextItemWidth(fieldWidth);
  changed |= ImGui::DragFloat3("Position P", &camera.position.x, kPositionDragSpeed, 0.0f, 0.0f, "%.3f");
  itemTooltip("The eye, world units. P - T must not be parallel to Up.");
  ImGui::SetNextItemWidth(fieldWidth);
  changed |= ImGui::DragFloat3("Target T", &camera.target.x, kPositionDragSpeed, 0.0f, 0.0f, "%.3f");
  itemTooltip("The point looked at, world units; must differ from P.");
  ImGui::SetNextItemWidth(fieldWidth);
  changed |= ImGui::DragFloat3("Up", &camera.up.x, kPositionDragSpeed, 0.0f, 0.0f, "%.3f");
  itemTooltip("The camera's up vector (up; the world's (0, 1, 0) by default), any length > 0, not parallel to P - T. "
              "Panning moves along the image's axes; orbiting turns about the world's Y axis.");
  ImGui::SetNextItemWidth(fieldWidth);
  changed |= ImGui::SliderFloat("fov (deg)", &camera.fovDeg, kMinFovDeg, kMaxFovDeg, "%.1f");
  itemTooltip("Vertical field of view, degrees, in (0, 180) exclusive.");
  ImGui::SetNextItemWidth(fieldWidth);
  changed |= ImGui::DragFloat("near", &camera.near, 0.001f, 0.0f, 0.0f, "%.4f");
  probe_.item("near");
  itemTooltip("Distance from P to the near clip plane, world units; must be > 0. Ctrl+click to type a value. "
              "While it is invalid nothing renders and the reason shows below in red.");
  ImGui::SetNextItemWidth(fieldWidth);
  changed |= ImGui::DragFloat("far", &camera.far, 0.1f, 0.0f, 0.0f, "%.2f");
  probe_.item("far");
  itemTooltip("Distance from P to the far clip plane, world units; must be > near. Window depth 1 lies on it.");
  if (ImGui::Button("Reset camera")) {
    camera = doc_.fileCamera;
    changed = true;
  }
  itemTooltip("Back to the camera the scene file gave.");
  if (!renderBlocker_.empty()) errorText(renderBlocker_ + " (nothing is rendered until it is fixed)");
  for (const std::string& warning : projectionWarnings_) warningText(warning);
  if (changed) doc_.touch();

  sectionTitle("Mouse, over the image");
  hintText("Left drag: orbit P around T.\nRight or middle drag, or Shift + left drag: pan P and T.\n"
           "Wheel: zoom (move P towards T).\nLeft click without dragging: pin that pixel in the inspector.\n"
           "Drag a light marker (L0, L1, ...): move that light.\nSplit view: drag the divider.");

  sectionTitle("Matrices (as both renderers build them)");
  hintText("D = normalize(P - T), R = normalize(cross(Up, D)), U = cross(D, R);\n"
           "viewFromWorld = [R; U; D] * translate(-P); clipFromView = perspective(fov, aspect, near, far).");
  if (validateCamera(camera).empty() && renderHeight_ > 0) {
    const mat4 view = viewFromWorld(camera);
    const mat4 projection = clipFromView(camera, static_cast<float>(renderWidth_) / static_cast<float>(renderHeight_));
    const auto showMatrix = [this](const char* name, const mat4& m) {
      ImGui::TextUnformatted(name);
      if (monoFont_) ImGui::PushFont(monoFont_);
      for (int row = 0; row < 4; ++row) {
        ImGui::Text("  %8.3f %8.3f %8.3f %8.3f", static_cast<double>(m[0][row]), static_cast<double>(m[1][row]),
                    static_cast<double>(m[2][row]), static_cast<double>(m[3][row]));
      }
      if (monoFont_) ImGui::PopFont();
    };
    showMatrix("viewFromWorld", view);
    showMatrix("clipFromView", projection);
  }
}

}  // namespace twr::gui
