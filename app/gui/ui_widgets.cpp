#include "app/gui/ui_widgets.h"

#include <cstdarg>
#include <cstdio>

namespace twr::gui {

void sectionTitle(const char* title) {
  ImGui::Spacing();
  ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(0.55f, 0.72f, 1.0f, 1.0f));
  ImGui::TextUnformatted(title);
  ImGui::PopStyleColor();
  ImGui::Separator();
}

void helpMarker(const char* text) {
  ImGui::SameLine();
  ImGui::TextDisabled("(?)");
  itemTooltip(text);
}

void sameLineIfFits(float width) {
  const float lineEnd = ImGui::GetItemRectMax().x + ImGui::GetStyle().ItemSpacing.x + width;
  const float right = ImGui::GetCursorScreenPos().x + ImGui::GetContentRegionAvail().x;  // the window's or the table cell's edge
  if (lineEnd <= right) ImGui::SameLine();
}

float checkboxWidth(const char* label) {
  return ImGui::GetFrameHeight() + ImGui::GetStyle().ItemInnerSpacing.x + ImGui::CalcTextSize(label).x;
}

void disabledTextWrapped(const char* format, ...) {
  ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyle().Colors[ImGuiCol_TextDisabled]);
  va_list args;
  va_start(args, format);
  ImGui::TextWrappedV(format, args);
  va_end(args);
  ImGui::PopStyleColor();
}

void itemTooltip(const char* text) {
  // Disabled items too: their tooltip says why they are greyed.
  if (!ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled)) return;
  ImGui::PushStyleVar(ImGuiStyleVar_Alpha, 1.0f);  // undoes BeginDisabled's dimming for the tooltip
  ImGui::BeginTooltip();
  ImGui::PushTextWrapPos(ImGui::GetFontSize() * 32.0f);
  ImGui::TextUnformatted(text);
  ImGui::PopTextWrapPos();
  ShownTooltip& shown = shownTooltip();
  shown.text = text;
  const ImVec2 at = ImGui::GetWindowPos(), size = ImGui::GetWindowSize();
  shown.rect[0] = at.x;
  shown.rect[1] = at.y;
  shown.rect[2] = at.x + size.x;
  shown.rect[3] = at.y + size.y;
  shown.alpha = ImGui::GetStyle().Alpha;
  ImGui::EndTooltip();
  ImGui::PopStyleVar();
}

ShownTooltip& shownTooltip() {
  static ShownTooltip shown;
  return shown;
}

ImU32 toImColour(Rgb8 colour, std::uint8_t alpha) { return IM_COL32(colour.r, colour.g, colour.b, alpha); }

void colourSquare(ImU32 colour) {
  const float side = ImGui::GetTextLineHeight();
  const ImVec2 corner = ImGui::GetCursorScreenPos();
  ImDrawList* draw = ImGui::GetWindowDrawList();
  draw->AddRectFilled(corner, ImVec2(corner.x + side, corner.y + side), colour);
  draw->AddRect(corner, ImVec2(corner.x + side, corner.y + side), IM_COL32(140, 140, 140, 255));
  ImGui::Dummy(ImVec2(side, side));
  ImGui::SameLine();
}

void rgbaValue(const std::uint8_t* rgba, bool withAlpha) {
  colourSquare(IM_COL32(rgba[0], rgba[1], rgba[2], 255));
  if (withAlpha) {
    ImGui::Text("%3d %3d %3d  a %3d", rgba[0], rgba[1], rgba[2], rgba[3]);
  } else {
    ImGui::Text("%3d %3d %3d", rgba[0], rgba[1], rgba[2]);
  }
}

void warningText(const std::string& text) {
  ImGui::PushStyleColor(ImGuiCol_Text, kWarningColour);
  ImGui::TextWrapped("%s", text.c_str());
  ImGui::PopStyleColor();
}

void errorText(const std::string& text) {
  ImGui::PushStyleColor(ImGuiCol_Text, kErrorColour);
  ImGui::TextWrapped("%s", text.c_str());
  ImGui::PopStyleColor();
}

void hintText(const char* text) {
  ImGui::PushStyleColor(ImGuiCol_Text, kHintColour);
  ImGui::TextWrapped("%s", text);
  ImGui::PopStyleColor();
}

namespace {
template <int N>
std::string formatComponents(const glm::vec<N, float>& v, int decimals) {
  std::string text;
  char buffer[32];
  for (int i = 0; i < N; ++i) {
    std::snprintf(buffer, sizeof buffer, "%.*f", decimals, static_cast<double>(v[i]));
    if (i) text += ' ';
    text += buffer;
  }
  return text;
}
}  // namespace

std::string formatVec(const vec3& v, int decimals) { return formatComponents(v, decimals); }
std::string formatVec(const vec4& v, int decimals) { return formatComponents(v, decimals); }
std::string formatVec(const vec2& v, int decimals) { return formatComponents(v, decimals); }

}  // namespace twr::gui
