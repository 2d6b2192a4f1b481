// Small ImGui helpers shared by the panels: enum pickers from the settings' own names,
// hover help, colour swatches matching compare/colours.h.
#pragma once

#include "compare/colours.h"
#include "scene/conventions.h"

#include <imgui.h>

#include <string>
#include <string_view>

namespace twr::gui {

// A titled separator between groups of controls.
void sectionTitle(const char* title);
// A "(?)" after the previous item that shows `text` on hover.
void helpMarker(const char* text);
// ImGui::SameLine() when an item `width` pixels wide still fits on this line; else nothing, so
// the item starts the next line instead of being cut off at the window's edge.
void sameLineIfFits(float width);
// The width of a checkbox with `label`, box included.
float checkboxWidth(const char* label);

// ImGui::TextDisabled's colour, wrapped at the window's or table cell's edge instead of cut
// off there (paths, the statistics line, decoded values in a narrow column).
void disabledTextWrapped(const char* format, ...) IM_FMTARGS(1);

// Tooltip on the previous item, opaque even over a disabled item (BeginDisabled dims the style's
// alpha, and a tooltip drawn under it was see-through and unreadable).
void itemTooltip(const char* text);

// The tooltip itemTooltip drew this frame, for the test probe: its text, its window's
// rectangle [x0, y0, x1, y1] and the style alpha its text was drawn with; text empty when none.
struct ShownTooltip {
  std::string text;
  float rect[4] = {0, 0, 0, 0};
  float alpha = 0.0f;
};
ShownTooltip& shownTooltip();

// One radio button per value, on one line after the label (the first button at labelWidth
// from the line start when it is > 0, so rows line up); values are named with toString().
// Returns true when the value changed.
// `help`, when given, is the tooltip of the label and of every button.
template <typename Enum, std::size_t N>
bool enumRadio(const char* label, Enum& value, const Enum (&values)[N], float labelWidth = 0.0f,
               const char* help = nullptr) {
  bool changed = false;
  ImGui::PushID(label);
  ImGui::AlignTextToFramePadding();
  ImGui::TextUnformatted(label);
  if (help) itemTooltip(help);
  for (std::size_t i = 0; i < N; ++i) {
    const std::string name(toString(values[i]));
    // A button that would not fit on the line starts a new one at labelWidth, so a narrow
    // panel wraps the choices instead of cutting them off.
    const float buttonWidth = ImGui::GetFrameHeight() + ImGui::GetStyle().ItemInnerSpacing.x +
                              ImGui::CalcTextSize(name.c_str()).x;
    const float lineEnd = ImGui::GetItemRectMax().x + ImGui::GetStyle().ItemSpacing.x + buttonWidth;
    const float right = ImGui::GetWindowPos().x + ImGui::GetWindowContentRegionMax().x;
    if (i > 0 && lineEnd > right) {
      if (labelWidth > 0.0f) ImGui::SetCursorPosX(labelWidth);
    } else if (i == 0 && labelWidth > 0.0f) {
      ImGui::SameLine(labelWidth);
    } else {
      ImGui::SameLine();
    }
    if (ImGui::RadioButton(name.c_str(), value == values[i]) && value != values[i]) {
      value = values[i];
      changed = true;
    }
    if (help) itemTooltip(help);
  }
  ImGui::PopID();
  return changed;
}

// A combo box over `values`, named with toString().
template <typename Enum, std::size_t N>
bool enumCombo(const char* label, Enum& value, const Enum (&values)[N]) {
  bool changed = false;
  const std::string current(toString(value));
  if (ImGui::BeginCombo(label, current.c_str())) {
    for (std::size_t i = 0; i < N; ++i) {
      const std::string name(toString(values[i]));
      const bool selected = value == values[i];
      if (ImGui::Selectable(name.c_str(), selected) && !selected) {
        value = values[i];
        changed = true;
      }
      if (selected) ImGui::SetItemDefaultFocus();
    }
    ImGui::EndCombo();
  }
  return changed;
}

ImU32 toImColour(Rgb8 colour, std::uint8_t alpha = 255);
// A filled square the height of a text line, then SameLine.
void colourSquare(ImU32 colour);
// A square of an 8-bit RGB value with its numbers, e.g. "[] 255 128 0".
void rgbaValue(const std::uint8_t* rgba, bool withAlpha);
// Text in the warning colour, wrapped.
void warningText(const std::string& text);
void errorText(const std::string& text);
// Grey explanatory text, wrapped.
void hintText(const char* text);

// "x y z" with a fixed number of decimals.
std::string formatVec(const vec3& v, int decimals = 3);
std::string formatVec(const vec4& v, int decimals = 3);
std::string formatVec(const vec2& v, int decimals = 3);

// The UI's colours for the two backends (labels, plot lines).
inline constexpr ImU32 kCpuAccent = IM_COL32(255, 170, 60, 255);
inline constexpr ImU32 kGlAccent = IM_COL32(90, 180, 255, 255);
inline const ImVec4 kWarningColour{1.0f, 0.75f, 0.25f, 1.0f};
inline const ImVec4 kErrorColour{1.0f, 0.38f, 0.35f, 1.0f};
inline const ImVec4 kHintColour{0.62f, 0.64f, 0.70f, 1.0f};

}  // namespace twr::gui
