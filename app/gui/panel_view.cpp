// The view panel: toolbar, the images in the chosen view mode, mouse camera control and
// pixel pinning, and a status line about the frames on screen.
#include "app/gui/app.h"
#include "gui/text_concat.h"
#include "gui/camera_control.h"
#include "gui/view_layout.h"
#include "app/gui/ui_widgets.h"

#include "compare/colours.h"
#include "compare/heatmap.h"
#include "scene/camera.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <nlohmann/json.hpp>

#include <imgui_stdlib.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace twr::gui {
namespace {

// Gap between the two images of the side-by-side view, points.
constexpr float kSideGapPoints = 6.0f;
// Mouse travel below which a press and release is a click, not a drag, points (inclusive).
constexpr float kClickSlopPoints = 3.0f;
// How close to the split divider a press grabs it, points (inclusive).
constexpr float kDividerGrabPoints = 6.0f;
// Smallest side of the pinned-pixel marker, points: a pixel can be smaller than a point.
constexpr float kMinMarkerPoints = 9.0f;
// How long a screenshot message stays under the toolbar, seconds.
constexpr double kMessageSeconds = 8.0;
// Radius of a light marker, and how close a press must be to grab it, points (inclusive).
constexpr float kLightMarkerPoints = 6.0f;
constexpr float kLightGrabPoints = 10.0f;
// Steps of the heat ramp drawn in the legend.
constexpr int kLegendRampSteps = 64;
// Rows of controls above the images (toolbar, resolution, the legend or caption), in
// frame heights; fixed, so no widget or message changes the image area (only a window too
// narrow for the toolbar's two rows adds the rows it wraps into).
constexpr float kViewHeaderRows = 4.0f;
constexpr int kToolbarRows = 2;

const ImU32 kErrorBanner = IM_COL32(89, 20, 20, 255);  // opaque: tests/cli/test_gui_smoke looks for it
const ImU32 kMessageBackground = IM_COL32(0, 0, 0, 200);

const ImU32 kMarkerColour = IM_COL32(255, 230, 40, 255);
const ImU32 kMarkerShadow = IM_COL32(0, 0, 0, 200);
const ImU32 kLabelBackground = IM_COL32(0, 0, 0, 170);

using Rect = ScreenRect;
ImVec2 im(ScreenPoint p) { return ImVec2(p.x, p.y); }
ScreenPoint pt(ImVec2 p) { return ScreenPoint{p.x, p.y}; }
std::vector<Rect> slotsFor(ViewMode mode, ImVec2 regionMin, ImVec2 regionSize) {
  return slotsFor(mode, pt(regionMin), pt(regionSize), kSideGapPoints);
}

void drawTexture(ImDrawList* draw, const ImageTexture& texture, const Rect& rect, float u0 = 0.0f, float u1 = 1.0f) {
  if (texture.empty()) return;
  const ImVec2 min(rect.min.x + u0 * rect.width(), rect.min.y);
  const ImVec2 max(rect.min.x + u1 * rect.width(), rect.max.y);
  draw->AddImage(texture.id(), min, max, ImVec2(u0, 0.0f), ImVec2(u1, 1.0f));
}

// A small tag with a coloured name and grey details at `corner` (top-left).
void drawTag(ImDrawList* draw, ImVec2 corner, const char* name, ImU32 colour, const std::string& details) {
  const ImVec2 padding(6.0f, 3.0f);
  const ImVec2 nameSize = ImGui::CalcTextSize(name);
  const ImVec2 detailSize = ImGui::CalcTextSize(details.c_str());
  const float gap = details.empty() ? 0.0f : 8.0f;
  const ImVec2 max(corner.x + 2.0f * padding.x + nameSize.x + gap + detailSize.x, corner.y + 2.0f * padding.y + nameSize.y);
  draw->AddRectFilled(corner, max, kLabelBackground, 3.0f);
  draw->AddText(ImVec2(corner.x + padding.x, corner.y + padding.y), colour, name);
  if (!details.empty()) {
    draw->AddText(ImVec2(corner.x + padding.x + nameSize.x + gap, corner.y + padding.y), IM_COL32(210, 210, 210, 255),
                  details.c_str());
  }
}

// A line of centred grey text in the middle of a rect (waiting, errors).
void drawCentredMessage(ImDrawList* draw, const Rect& rect, const std::string& text, ImU32 colour) {
  const float wrap = std::max(100.0f, rect.width() - 40.0f);
  const ImVec2 size = ImGui::CalcTextSize(text.c_str(), nullptr, false, wrap);
  const ImVec2 at(rect.min.x + 0.5f * (rect.width() - size.x), rect.min.y + 0.5f * (rect.height() - size.y));
  draw->AddText(ImGui::GetFont(), ImGui::GetFontSize(), at, colour, text.c_str(), nullptr, wrap);
}

}  // namespace

void GuiApp::drawViewPanel() {
  // The rows above the images have a fixed height in every view mode, whatever they hold
  // (the diff legend, heat or class map), and messages and error banners are drawn over the
  // images: the "fit view" render size depends only on what the user sizes (the window,
  // the panels, the scale), so showing a message never re-renders both backends.
  const float headerHeight =
      (kViewHeaderRows + static_cast<float>(std::max(0, toolbarRows_ - kToolbarRows))) * ImGui::GetFrameHeightWithSpacing();
  if (ImGui::BeginChild("##viewHeader", ImVec2(0.0f, headerHeight), false,
                        ImGuiWindowFlags_NoScrollbar | ImGuiWindowFlags_NoScrollWithMouse)) {
    drawViewToolbar();
    if (prefs_.viewMode == ViewMode::Diff) drawDiffLegend();
    else drawViewCaption();
  }
  ImGui::EndChild();
  ImGui::Separator();
  const float statusHeight = ImGui::GetFrameHeightWithSpacing();
  const ImVec2 regionMin = ImGui::GetCursorScreenPos();
  ImVec2 regionSize = ImGui::GetContentRegionAvail();
  regionSize.x = std::max(1.0f, regionSize.x);
  regionSize.y = std::max(1.0f, regionSize.y - statusHeight);

  // The per-image slot in framebuffer pixels decides the "fit view" resolution.
  const ImVec2 framebufferScale = ImGui::GetIO().DisplayFramebufferScale;
  const Rect slot = slotsFor(prefs_.viewMode, regionMin, regionSize).front();
  imagePanelPixels_ = ImVec2(std::floor(slot.width() * framebufferScale.x), std::floor(slot.height() * framebufferScale.y));

  drawImages(regionMin, regionSize);
  drawViewMessages(regionMin, regionSize);
  handleImageMouse(regionMin, regionSize);
  probe_.item("view_images");
  ImGui::SetCursorScreenPos(ImVec2(regionMin.x, regionMin.y + regionSize.y + ImGui::GetStyle().ItemSpacing.y));
  drawStatusLine();
}

void GuiApp::drawViewMessages(ImVec2 regionMin, ImVec2 regionSize) {
  ImDrawList* draw = ImGui::GetWindowDrawList();
  const float padding = 6.0f * uiScale_;
  const float wrap = std::max(50.0f, regionSize.x - 4.0f * padding);
  float y = regionMin.y + padding;
  // One box per message, stacked from the top of the image region, over the images.
  const auto box = [&](const std::string& text, ImU32 background, ImU32 colour, bool fullWidth = false) {
    const ImVec2 size = ImGui::CalcTextSize(text.c_str(), nullptr, false, wrap);
    const ImVec2 min(regionMin.x + padding, y);
    const float width = fullWidth ? regionSize.x - 2.0f * padding : size.x + 2.0f * padding;
    const ImVec2 max(min.x + width, min.y + size.y + 2.0f * padding);
    draw->AddRectFilled(min, max, background, 3.0f);
    draw->AddText(ImGui::GetFont(), ImGui::GetFontSize(), ImVec2(min.x + padding, min.y + padding), colour,
                  text.c_str(), nullptr, wrap);
    y = max.y + padding;
  };
  if (!sceneError_.empty()) box(sceneError_, kErrorBanner, IM_COL32(255, 235, 235, 255), true);
  if (!pinWarning_.empty()) box(pinWarning_, kMessageBackground, IM_COL32(255, 200, 90, 255));
  if (const std::string horizon = horizonStatus(); !horizon.empty()) {
    box(horizon, kMessageBackground, IM_COL32(255, 200, 90, 255));
  }
  if (!screenshotMessage_.empty() && glfwGetTime() - screenshotMessageTime_ < kMessageSeconds) {
    box(screenshotMessage_, kMessageBackground, IM_COL32(220, 220, 220, 255));
    redraw_.redrawAt(screenshotMessageTime_ + kMessageSeconds);  // to take it away
  }
  if (probe_.enabled()) {
    nlohmann::json& state = probe_.state();
    state["lights_hint"] = lightsHint_;
    state["scene_error"] = sceneError_;
    state["screenshot_message"] =
        glfwGetTime() - screenshotMessageTime_ < kMessageSeconds ? screenshotMessage_ : std::string();
  }
}

void GuiApp::drawViewCaption() {
  // Row 3 outside the diff view: what the images are, so every number says what it covers.
  const ShownRevisions shown = shownRevisions();
  std::string text = std::to_string(renderWidth_) + " x " + std::to_string(renderHeight_) + " px per image";
  if (!renderBlocker_.empty()) {
    text += "; nothing renders: " + renderBlocker_;
  } else if (const std::string revisions = revisionCaption(shown); !revisions.empty()) {
    text += "; " + revisions;
  }
  // Lights ticked but off screen: said here, not over the image it would hide (last frame's
  // list: the images are drawn after this caption).
  if (!lightsHint_.empty()) text += ". " + lightsHint_;
  if (doc_.scene.settings.view == View::Depth) {
    char depthText[128];
    if (prefs_.linearDepth && !linearDepthRange_.empty()) {
      std::snprintf(depthText, sizeof depthText, "; depth linearised: eye distance %.3g (black) to %.3g (white) world units",
                    static_cast<double>(linearDepthRange_.nearest), static_cast<double>(linearDepthRange_.farthest));
    } else {
      std::snprintf(depthText, sizeof depthText, "; window depth: 0 black at near, 1 white at far");
    }
    text += depthText;
  }
  hintText(text.c_str());
  if (probe_.enabled()) probe_.state()["caption"] = text;
}

void GuiApp::drawViewToolbar() {
  const float top = ImGui::GetCursorScreenPos().y;
  drawViewToolbarRows();
  // The rows it took (a narrow window wraps row 2): next frame's header makes room for them.
  const float rowHeight = ImGui::GetFrameHeightWithSpacing();
  toolbarRows_ = std::max(kToolbarRows, static_cast<int>(std::lround((ImGui::GetCursorScreenPos().y - top) / rowHeight)));
  if (probe_.enabled()) probe_.state()["toolbar_rows"] = toolbarRows_;
}

void GuiApp::drawViewToolbarRows() {
  // Row 1: the view modes as one segmented control, the screenshot button on the right.
  for (ViewMode mode : kAllViewModes) {
    const bool selected = prefs_.viewMode == mode;
    if (selected) ImGui::PushStyleColor(ImGuiCol_Button, ImGui::GetStyleColorVec4(ImGuiCol_ButtonActive));
    if (ImGui::Button(label(mode))) {
      prefs_.viewMode = mode;
      flickerStart_ = glfwGetTime();
    }
    probe_.item(concat("mode_", toString(mode)).c_str());
    if (selected) ImGui::PopStyleColor();
    ImGui::SameLine(0.0f, 2.0f);
  }
  const char* shotLabel = "Screenshot";
  const float shotWidth = ImGui::CalcTextSize(shotLabel).x + 2.0f * ImGui::GetStyle().FramePadding.x;
  ImGui::SameLine(std::max(ImGui::GetCursorPosX() + 8.0f, ImGui::GetWindowContentRegionMax().x - shotWidth));
  if (ImGui::Button(shotLabel)) saveViewScreenshots();
  probe_.item("screenshot");
  // F12 saves the whole window (app.cpp).
  if (ImGui::BeginPopupContextItem("##shotFolder")) {
    ImGui::TextUnformatted("Screenshot folder");
    ImGui::SetNextItemWidth(260.0f * uiScale_);
    ImGui::InputText("##folder", &prefs_.screenshotDir);
    ImGui::EndPopup();
  }
  const std::string shotHelp = "Saves the current view and both backend images (the scene's background alpha where "
                               "nothing was drawn) as PNGs in '" + prefs_.screenshotDir +
                               "'. Right-click to change the folder.";
  itemTooltip(shotHelp.c_str());

  // Row 2: resolution, then what the current mode needs.
  ImGui::SetNextItemWidth(ImGui::CalcTextSize("Scene output").x + ImGui::GetFrameHeight() * 2.0f);
  const char* sources[] = {"Scene output", "Fit view"};
  int source = prefs_.resolution == ResolutionSource::FitView ? 1 : 0;
  if (ImGui::Combo("##resolution", &source, sources, 2)) {
    prefs_.resolution = source == 1 ? ResolutionSource::FitView : ResolutionSource::SceneOutput;
  }
  itemTooltip("Both backends always render at the same size: the scene's output size or the size of the image "
              "panel on screen, times the scale.");
  // Each item after the first goes on the line while it fits, else starts the next one.
  sameLineIfFits(110.0f * uiScale_);
  ImGui::SetNextItemWidth(110.0f * uiScale_);
  ImGui::SliderFloat("##scale", &prefs_.resolutionScale, kMinResolutionScale, kMaxResolutionScale, "x %.3g",
                     ImGuiSliderFlags_Logarithmic | ImGuiSliderFlags_AlwaysClamp);
  itemTooltip("Resolution scale. Small scales make single pixels (and the fill rule) easy to see.");
  const std::string sizeText = concat(renderWidth_, " x ", renderHeight_, " px");
  sameLineIfFits(ImGui::CalcTextSize(sizeText.c_str()).x);
  ImGui::TextDisabled("%s", sizeText.c_str());
  sameLineIfFits(checkboxWidth("Checker bg"));
  if (ImGui::Checkbox("Checker bg", &prefs_.checkerBackground)) cpuTextureStale_ = glTextureStale_ = true;
  probe_.item("checker_bg");
  itemTooltip("Show pixels no triangle covered as a checker, so coverage is visible against any background colour.");
  sameLineIfFits(checkboxWidth("Lights"));
  ImGui::Checkbox("Lights", &prefs_.showLights);
  probe_.item("show_lights");
  itemTooltip("Mark each point light over the images (L0, L1, ...). Drag a marker to move the light parallel to "
              "the image at its own depth.");

  if (prefs_.viewMode == ViewMode::Flicker) {
    sameLineIfFits(120.0f * uiScale_);
    ImGui::SetNextItemWidth(120.0f * uiScale_);
    ImGui::SliderFloat("##flicker", &prefs_.flickerHz, kMinFlickerHz, kMaxFlickerHz, "%.2g Hz",
                       ImGuiSliderFlags_Logarithmic | ImGuiSliderFlags_AlwaysClamp);
    itemTooltip("Switches per second between the CPU and the GL image: the eye catches what moves.");
  } else if (prefs_.viewMode == ViewMode::Split) {
    sameLineIfFits(120.0f * uiScale_);
    ImGui::SetNextItemWidth(120.0f * uiScale_);
    ImGui::SliderFloat("##split", &prefs_.splitFraction, 0.0f, 1.0f, "divider %.2f", ImGuiSliderFlags_AlwaysClamp);
  } else if (prefs_.viewMode == ViewMode::Diff) {
    sameLineIfFits(checkboxWidth("Heat map"));
    if (ImGui::RadioButton("Heat map", !prefs_.diffShowClasses)) prefs_.diffShowClasses = false;
    probe_.item("diff_heat");
    sameLineIfFits(checkboxWidth("Class map"));
    if (ImGui::RadioButton("Class map", prefs_.diffShowClasses)) prefs_.diffShowClasses = true;
    probe_.item("diff_class");
  }
}

void GuiApp::drawDiffLegend() {
  if (!prefs_.diffShowClasses) {
    // The heat ramp: black for 0, then inferno up to maxLevels.
    ImGui::TextUnformatted("|CPU - GL| per pixel, max over RGB, levels:");
    ImGui::SameLine();
    const ImVec2 corner = ImGui::GetCursorScreenPos();
    const float width = 160.0f * uiScale_, height = ImGui::GetTextLineHeight();
    ImDrawList* draw = ImGui::GetWindowDrawList();
    const HeatRamp ramp{prefs_.heatMaxLevels, prefs_.heatScale};
    for (int i = 0; i < kLegendRampSteps; ++i) {
      const int levels = (i * ramp.maxLevels + kLegendRampSteps / 2) / (kLegendRampSteps - 1);
      const float x0 = corner.x + width * static_cast<float>(i) / kLegendRampSteps;
      const float x1 = corner.x + width * static_cast<float>(i + 1) / kLegendRampSteps;
      draw->AddRectFilled(ImVec2(x0, corner.y), ImVec2(x1, corner.y + height), toImColour(heatColour(levels, ramp)));
    }
    ImGui::Dummy(ImVec2(width, height));
    ImGui::SameLine();
    ImGui::Text("0 .. %d+", ramp.maxLevels);
    ImGui::SameLine();
    bool logScale = prefs_.heatScale == HeatScale::Log;
    if (ImGui::Checkbox("log", &logScale)) {
      prefs_.heatScale = logScale ? HeatScale::Log : HeatScale::Linear;
      diff_.texturesStale = true;
    }
    ImGui::SameLine();
    ImGui::SetNextItemWidth(90.0f * uiScale_);
    if (ImGui::SliderInt("##maxlevels", &prefs_.heatMaxLevels, 1, 255, "top %d", ImGuiSliderFlags_AlwaysClamp)) {
      diff_.texturesStale = true;
    }
    itemTooltip("Differences of this many levels or more get the brightest colour.");
  }
  // Per-class counts, with the class map's colours.
  const CompareMetrics* metrics = diff_.result ? &diff_.result->metrics : nullptr;
  struct Entry {
    const char* name;
    Rgb8 colour;
    std::uint64_t count;
    const char* help;
  };
  std::uint64_t same = 0, empty = 0;
  if (diff_.result) {
    for (PixelClass c : diff_.result->pixels.pixelClass) {
      if (c == PixelClass::Same) ++same;
      if (c == PixelClass::Empty) ++empty;
    }
  }
  const Entry entries[] = {
      {"same", kColourSame, same, "Both covered, no difference."},
      {"shading", kColourShading, metrics ? metrics->classShading : 0,
       "Both covered by the same triangle, other colour: interpolation, texture sampling, lighting."},
      {"depth", kColourDepth, metrics ? metrics->classDepth : 0, "Both covered, but a different surface won the depth test."},
      {"CPU only", kColourCpuOnly, metrics ? metrics->coverageCpuOnly : 0, "Covered by the CPU only: fill rule, clipping."},
      {"GL only", kColourGlOnly, metrics ? metrics->coverageGlOnly : 0, "Covered by GL only: fill rule, clipping."},
      {"TBN line", kColourExcludedLine, metrics ? metrics->excludedLinePixels : 0, "Debug line pixels, not compared."},
      {"empty", kColourCheckerLight, empty, "Neither backend covered it."},
  };
  bool first = true;
  for (const Entry& entry : entries) {
    if (!first) ImGui::SameLine(0.0f, 14.0f);
    first = false;
    // The heat map shows shading and depth differences on its ramp, so they get no swatch there.
    const bool onRamp = !prefs_.diffShowClasses && (entry.colour == kColourShading || entry.colour == kColourDepth);
    if (!onRamp) colourSquare(toImColour(entry.colour));
    ImGui::Text("%s %llu", entry.name, static_cast<unsigned long long>(entry.count));
    itemTooltip(entry.help);
  }
  if (!diff_.error.empty()) warningText(diff_.error);
}

void GuiApp::drawImages(ImVec2 regionMin, ImVec2 regionSize) {
  ImDrawList* draw = ImGui::GetWindowDrawList();
  const std::vector<Rect> slots = slotsFor(prefs_.viewMode, regionMin, regionSize);
  draw->AddRectFilled(regionMin, ImVec2(regionMin.x + regionSize.x, regionMin.y + regionSize.y), IM_COL32(16, 16, 20, 255));
  const Rect image = fitRect(slots.front(), renderWidth_, renderHeight_);

  const auto backendMessage = [this](const BackendFrame& frame, const char* name) -> std::string {
    if (!renderBlocker_.empty()) return renderBlocker_;
    if (!frame.error.empty()) return std::string(name) + " error: " + frame.error;
    if (!frame.output) return std::string(name) + ": rendering the first frame...";
    return "";
  };
  // The frame's age and edit; an older edit says whether a newer one is on its way.
  std::optional<double> youngestAge;  // of the tags drawn, seconds
  const auto details = [this, &youngestAge](const BackendFrame& frame) {
    if (frame.revision == 0) return std::string();
    const double age = std::chrono::duration<double>(Clock::now() - frame.finishedAt).count();
    youngestAge = std::min(age, youngestAge.value_or(age));
    std::string text = frameAgeText(age);
    text += concat(", edit ", frame.revision);
    if (frame.revision != doc_.revision) {
      text += !renderBlocker_.empty() ? " (nothing renders: invalid camera)" : ", rendering the new one...";
    }
    return text;
  };
  const auto cpuDetails = [&] { return details(cpuFrame_); };
  const auto glDetails = [&] { return details(glFrame_); };
  const ImVec2 tagOffset(6.0f, 6.0f);
  const auto tagAt = [&](const Rect& rect) { return ImVec2(rect.min.x + tagOffset.x, rect.min.y + tagOffset.y); };

  switch (prefs_.viewMode) {
    case ViewMode::Cpu:
    case ViewMode::Gl: {
      const bool cpu = prefs_.viewMode == ViewMode::Cpu;
      const BackendFrame& frame = cpu ? cpuFrame_ : glFrame_;
      const ImageTexture& texture = cpu ? cpuTexture_ : glTexture_;
      const std::string message = backendMessage(frame, cpu ? "CPU" : "GL");
      if (frame.output) drawTexture(draw, texture, fitRect(slots.front(), texture.width(), texture.height()));
      if (!message.empty()) drawCentredMessage(draw, slots.front(), message, IM_COL32(230, 200, 120, 255));
      drawTag(draw, tagAt(image), cpu ? "CPU" : "GL", cpu ? kCpuAccent : kGlAccent, cpu ? cpuDetails() : glDetails());
      break;
    }
    case ViewMode::SideBySide: {
      const BackendFrame* frames[2] = {&cpuFrame_, &glFrame_};
      const ImageTexture* textures[2] = {&cpuTexture_, &glTexture_};
      for (std::size_t i = 0; i < 2; ++i) {
        const Rect rect = fitRect(slots[i], renderWidth_, renderHeight_);
        if (frames[i]->output) {
          drawTexture(draw, *textures[i], fitRect(slots[i], textures[i]->width(), textures[i]->height()));
        }
        const std::string message = backendMessage(*frames[i], i == 0 ? "CPU" : "GL");
        if (!message.empty()) drawCentredMessage(draw, slots[i], message, IM_COL32(230, 200, 120, 255));
        drawTag(draw, tagAt(rect), i == 0 ? "CPU" : "GL", i == 0 ? kCpuAccent : kGlAccent,
                i == 0 ? cpuDetails() : glDetails());
      }
      break;
    }
    case ViewMode::Split: {
      const float split = prefs_.splitFraction;
      if (cpuFrame_.output) drawTexture(draw, cpuTexture_, image, 0.0f, split);
      if (glFrame_.output) drawTexture(draw, glTexture_, image, split, 1.0f);
      const float dividerX = image.min.x + split * image.width();
      draw->AddLine(ImVec2(dividerX, image.min.y), ImVec2(dividerX, image.max.y), IM_COL32(255, 255, 255, 230), 2.0f);
      const ImVec2 handle(dividerX, 0.5f * (image.min.y + image.max.y));
      draw->AddCircleFilled(handle, 7.0f * uiScale_, IM_COL32(255, 255, 255, 230));
      draw->AddText(ImVec2(handle.x - 4.0f * uiScale_, handle.y - 0.5f * ImGui::GetFontSize()), IM_COL32(0, 0, 0, 255), "|");
      drawTag(draw, tagAt(image), "CPU", kCpuAccent, cpuDetails());
      const char* glName = "GL";
      const std::string glText = glDetails();
      const float glTagWidth = ImGui::CalcTextSize(glName).x + 8.0f + ImGui::CalcTextSize(glText.c_str()).x + 12.0f;
      drawTag(draw, ImVec2(image.max.x - glTagWidth - tagOffset.x, image.min.y + tagOffset.y + ImGui::GetFrameHeight()),
              glName, kGlAccent, glText);
      const std::string message = !backendMessage(cpuFrame_, "CPU").empty() ? backendMessage(cpuFrame_, "CPU")
                                                                           : backendMessage(glFrame_, "GL");
      if (!message.empty()) drawCentredMessage(draw, slots.front(), message, IM_COL32(230, 200, 120, 255));
      break;
    }
    case ViewMode::Diff: {
      const ImageTexture& texture = prefs_.diffShowClasses ? classTexture_ : heatTexture_;
      if (diff_.result) {
        drawTexture(draw, texture, fitRect(slots.front(), texture.width(), texture.height()));
        std::string details = concat("CPU and GL of edit ", diff_.revision);
        if (diff_.revision != doc_.revision) {
          details += !renderBlocker_.empty() ? " (nothing renders: invalid camera)" : "; the CPU is rendering the new one...";
        }
        drawTag(draw, tagAt(image), prefs_.diffShowClasses ? "Classes" : "|CPU - GL|", IM_COL32(255, 255, 255, 255),
                details);
      } else {
        std::string message = !renderBlocker_.empty() ? renderBlocker_
                              : !diff_.error.empty()  ? diff_.error
                                                      : "Waiting for both backends to finish a frame...";
        drawCentredMessage(draw, slots.front(), message, IM_COL32(230, 200, 120, 255));
      }
      break;
    }
    case ViewMode::Flicker: {
      const double phase = (glfwGetTime() - flickerStart_) * static_cast<double>(prefs_.flickerHz);
      const bool cpu = static_cast<long long>(std::floor(phase)) % 2 == 0;
      const ImageTexture& texture = cpu ? cpuTexture_ : glTexture_;
      if ((cpu ? cpuFrame_ : glFrame_).output) drawTexture(draw, texture, fitRect(slots.front(), texture.width(), texture.height()));
      // Each redraw shows one image, so the eye sees at most one switch per redraw.
      const double redraws = static_cast<double>(ImGui::GetIO().Framerate);
      const double asked = static_cast<double>(prefs_.flickerHz);
      char rate[96];
      if (redraws < asked) {
        std::snprintf(rate, sizeof rate, "asked %.2g Hz; about %.0f switches/s shown (the UI redraws %.0f times/s)",
                      asked, redraws, redraws);
      } else {
        std::snprintf(rate, sizeof rate, "%.2g switches/s", asked);
      }
      drawTag(draw, tagAt(image), cpu ? "CPU" : "GL", cpu ? kCpuAccent : kGlAccent,
              std::string(rate) + "; " + (cpu ? cpuDetails() : glDetails()));
      break;
    }
  }

  // An idle loop redraws when the youngest age's text next changes (it gets coarser as the
  // frame ages); an older tag's age changes at the same redraws, never more often. Its figure
  // is rounded down, so showing it late still tells the truth (the frame is at least that old).
  if (youngestAge) redraw_.redrawAt(glfwGetTime() + frameAgeTextLasts(*youngestAge));

  // Lights ticked but not on screen get a hint (drawViewCaption): a marker nobody sees
  // does not say where the light went.
  lightsHint_.clear();
  if (prefs_.showLights && renderBlocker_.empty() && renderWidth_ > 0 && renderHeight_ > 0) {
    std::string behind, outside;
    for (std::size_t i = 0; i < doc_.scene.lights.size(); ++i) {
      if (doc_.scene.lights[i].type == LightType::Directional) continue;  // no position to mark
      const std::optional<ScreenPoint> at =
          projectToRect(doc_.scene.camera, doc_.scene.lights[i].posWorld, image, renderWidth_, renderHeight_);
      std::string& list = !at ? behind : outside;
      if (at && image.contains(*at)) continue;
      list += concat(list.empty() ? "L" : ", L", i);
    }
    if (!behind.empty()) lightsHint_ += behind + " behind the camera";
    if (!outside.empty()) lightsHint_ += (lightsHint_.empty() ? "" : "; ") + outside + " outside the image";
    if (!lightsHint_.empty()) {
      lightsHint_ = "Lights off screen: " + lightsHint_ + " (orbit or zoom out to see their markers).";
    }
  }
  // The lights, in every image: a disc of the light's diffuse colour, and its index.
  if (prefs_.showLights && renderBlocker_.empty() && renderWidth_ > 0 && renderHeight_ > 0) {
    for (const Rect& slot : slots) {
      const Rect rect = fitRect(slot, renderWidth_, renderHeight_);
      draw->PushClipRect(im(rect.min), im(rect.max), true);
      for (std::size_t i = 0; i < doc_.scene.lights.size(); ++i) {
        const Light& light = doc_.scene.lights[i];
        if (light.type == LightType::Directional) continue;  // no position to mark
        const std::optional<ScreenPoint> at = projectToRect(doc_.scene.camera, light.posWorld, rect, renderWidth_, renderHeight_);
        if (!at) continue;
        const vec3 colour = glm::clamp(light.diffuse, 0.0f, 1.0f) * 255.0f;
        const float radius = kLightMarkerPoints * uiScale_;
        draw->AddCircleFilled(im(*at), radius + 1.5f, IM_COL32(0, 0, 0, 220));
        draw->AddCircleFilled(im(*at), radius, IM_COL32(static_cast<int>(colour.r), static_cast<int>(colour.g),
                                                    static_cast<int>(colour.b), 255));
        const std::string name = concat('L', i);
        draw->AddText(ImVec2(at->x + radius + 3.0f, at->y - radius - 3.0f), IM_COL32(255, 255, 255, 230), name.c_str());
      }
      draw->PopClipRect();
    }
  }

  // The stage explorer's overlay, in every image, under the pinned pixel's marker.
  if (explorerOpen_ && pin_.pixel && renderWidth_ > 0 && renderHeight_ > 0) {
    for (std::size_t k = 0; k < slots.size(); ++k) {
      // Each image marks the pixels its own frame gave the triangle (GL's through its ids):
      // side by side the CPU's then GL's, GL alone GL's, the mixed modes the CPU's.
      const bool glSide = prefs_.viewMode == ViewMode::Gl || (prefs_.viewMode == ViewMode::SideBySide && k == 1);
      const std::shared_ptr<const ExplorerView> view = explorerView(glSide);
      if (!view) continue;
      const Rect rect = fitRect(slots[k], renderWidth_, renderHeight_);
      draw->PushClipRect(im(rect.min), im(rect.max), true);
      drawExplorerOverlay(draw, *view, im(rect.min), im(rect.max));
      draw->PopClipRect();
    }
  }
  // The pinned pixel, in every image.
  if (pin_.pixel && renderWidth_ > 0 && renderHeight_ > 0) {
    for (const Rect& slot : slots) {
      const Rect rect = fitRect(slot, renderWidth_, renderHeight_);
      const float pixelWidth = rect.width() / static_cast<float>(renderWidth_);
      const float pixelHeight = rect.height() / static_cast<float>(renderHeight_);
      const ImVec2 centre(rect.min.x + (static_cast<float>(pin_.pixel->x) + 0.5f) * pixelWidth,
                          rect.min.y + (static_cast<float>(pin_.pixel->yTop) + 0.5f) * pixelHeight);
      const float halfX = 0.5f * std::max(pixelWidth, kMinMarkerPoints * uiScale_);
      const float halfY = 0.5f * std::max(pixelHeight, kMinMarkerPoints * uiScale_);
      const ImVec2 min(centre.x - halfX, centre.y - halfY), max(centre.x + halfX, centre.y + halfY);
      draw->AddRect(ImVec2(min.x - 1.0f, min.y - 1.0f), ImVec2(max.x + 1.0f, max.y + 1.0f), kMarkerShadow, 0.0f, 0, 3.0f);
      draw->AddRect(min, max, kMarkerColour, 0.0f, 0, 1.5f);
    }
  }
}

void GuiApp::handleImageMouse(ImVec2 regionMin, ImVec2 regionSize) {
  ImGuiIO& io = ImGui::GetIO();
  const std::vector<Rect> slots = slotsFor(prefs_.viewMode, regionMin, regionSize);
  const auto pixelUnder = [&](ImVec2 point) { return pixelAt(slots, pt(point), renderWidth_, renderHeight_); };
  const Rect image = fitRect(slots.front(), renderWidth_, renderHeight_);
  const float dividerX = image.min.x + prefs_.splitFraction * image.width();
  // The light whose marker is within grab distance of a point, if any.
  const auto lightAt = [&](ImVec2 point) -> int {
    if (!prefs_.showLights || !renderBlocker_.empty()) return -1;
    for (const Rect& slot : slots) {
      const Rect rect = fitRect(slot, renderWidth_, renderHeight_);
      for (std::size_t i = 0; i < doc_.scene.lights.size(); ++i) {
        if (doc_.scene.lights[i].type == LightType::Directional) continue;
        const std::optional<ScreenPoint> at =
            projectToRect(doc_.scene.camera, doc_.scene.lights[i].posWorld, rect, renderWidth_, renderHeight_);
        if (!at || !rect.contains(*at)) continue;
        const float dx = at->x - point.x, dy = at->y - point.y;
        if (dx * dx + dy * dy <= kLightGrabPoints * kLightGrabPoints * uiScale_ * uiScale_) return static_cast<int>(i);
      }
    }
    return -1;
  };
  const auto nearDivider = [&](ImVec2 point) {
    return prefs_.viewMode == ViewMode::Split && std::fabs(point.x - dividerX) <= kDividerGrabPoints * uiScale_ &&
           point.y >= image.min.y && point.y < image.max.y;
  };

  ImGui::SetCursorScreenPos(regionMin);
  ImGui::InvisibleButton("##image", regionSize,
                         ImGuiButtonFlags_MouseButtonLeft | ImGuiButtonFlags_MouseButtonRight |
                             ImGuiButtonFlags_MouseButtonMiddle);
  const bool hovered = ImGui::IsItemHovered();
  hovered_ = hovered ? pixelUnder(io.MousePos) : std::nullopt;
  if (hovered && (nearDivider(io.MousePos) || dragMode_ == DragMode::Divider)) {
    ImGui::SetMouseCursor(ImGuiMouseCursor_ResizeEW);
  } else if (hovered && (dragMode_ == DragMode::Light || (dragMode_ == DragMode::None && lightAt(io.MousePos) >= 0))) {
    ImGui::SetMouseCursor(ImGuiMouseCursor_Hand);
  }

  if (ImGui::IsItemActivated()) {
    pressPos_ = io.MousePos;
    dragged_ = false;
    if (ImGui::IsMouseClicked(ImGuiMouseButton_Left)) {
      dragLight_ = lightAt(io.MousePos);
      dragMode_ = nearDivider(io.MousePos) ? DragMode::Divider
                  : dragLight_ >= 0        ? DragMode::Light
                  : io.KeyShift            ? DragMode::Pan
                                           : DragMode::Orbit;
    } else {
      dragMode_ = DragMode::Pan;
    }
  }
  if (ImGui::IsItemActive() && dragMode_ != DragMode::None) {
    const float travelX = io.MousePos.x - pressPos_.x, travelY = io.MousePos.y - pressPos_.y;
    if (!dragged_ && travelX * travelX + travelY * travelY > kClickSlopPoints * kClickSlopPoints) {
      dragged_ = true;
    }
    if (dragMode_ == DragMode::Divider) {
      if (image.width() > 0.0f) prefs_.splitFraction = std::clamp((io.MousePos.x - image.min.x) / image.width(), 0.0f, 1.0f);
    } else if (dragged_ && (io.MouseDelta.x != 0.0f || io.MouseDelta.y != 0.0f)) {
      if (dragMode_ == DragMode::Light) {
        if (dragLight_ >= 0 && dragLight_ < static_cast<int>(doc_.scene.lights.size()) &&
            dragPointInViewPlane(doc_.scene.camera, doc_.scene.lights[static_cast<std::size_t>(dragLight_)].posWorld,
                                 io.MouseDelta.x, io.MouseDelta.y, image.height())) {
          doc_.touch();
        }
      } else {
        if (dragMode_ == DragMode::Orbit) orbitCamera(doc_.scene.camera, io.MouseDelta.x, io.MouseDelta.y);
        else panCamera(doc_.scene.camera, io.MouseDelta.x, io.MouseDelta.y, image.height());
        doc_.touch();
      }
    }
  }
  if (ImGui::IsItemDeactivated()) {
    if (!dragged_ && dragMode_ == DragMode::Orbit) pinPixel(pixelUnder(pressPos_));
    dragMode_ = DragMode::None;
  }
  if (hovered && io.MouseWheel != 0.0f) {
    zoomCamera(doc_.scene.camera, io.MouseWheel);
    doc_.touch();
  }
}

void GuiApp::drawStatusLine() {
  if (!hovered_) {
    ImGui::TextDisabled("%d x %d px, edit %llu.  Hover the image to read pixels; click to pin one.", renderWidth_,
                        renderHeight_, static_cast<unsigned long long>(doc_.revision));
    if (probe_.enabled()) probe_.state()["hover"] = nullptr;
    return;
  }
  const PixelPos p = *hovered_;
  const ShownRevisions shown = shownRevisions();
  std::string line = concat('(', p.x, ", ", p.yTop, ')');
  ImGui::Text("(%d, %d)", p.x, p.yTop);
  const auto show = [&](const char* name, ImU32 accent, const std::shared_ptr<const RenderOutput>& output,
                        std::uint64_t revision) {
    ImGui::SameLine(0.0f, 14.0f);
    ImGui::PushStyleColor(ImGuiCol_Text, ImGui::ColorConvertU32ToFloat4(accent));
    ImGui::TextUnformatted(name);
    ImGui::PopStyleColor();
    ImGui::SameLine();
    line += std::string(" ") + name;
    if (!output || output->width != renderWidth_ || output->height != renderHeight_) {
      ImGui::TextDisabled("-");
      line += " -";
      return;
    }
    const std::size_t i = static_cast<std::size_t>(p.yTop) * static_cast<std::size_t>(output->width) +
                          static_cast<std::size_t>(p.x);
    const std::uint8_t* rgba = &output->rgba[i * 4];
    rgbaValue(rgba, false);
    ImGui::SameLine();
    char details[64];
    std::snprintf(details, sizeof details, "z %.5f (edit %llu)", static_cast<double>(output->depth[i]),
                  static_cast<unsigned long long>(revision));
    ImGui::TextDisabled("%s", details);
    line += concat(' ', int{rgba[0]}, ' ', int{rgba[1]}, ' ', int{rgba[2]}, ' ', details);
  };
  show("CPU", kCpuAccent, cpuFrame_.output, shown.cpu);
  show("GL", kGlAccent, glFrame_.output, shown.gl);
  // A diff only between the two images shown, and only when they are from the same edit.
  ImGui::SameLine(0.0f, 14.0f);
  bool diffShown = false;
  if (pairState(shown) == PairState::SameEdit && diff_.result && diff_.result->pixels.width == renderWidth_ &&
      diff_.result->pixels.height == renderHeight_) {
    const std::size_t i = diff_.result->pixels.index(p.x, p.yTop);
    const std::string text =
        concat("diff ", diff_.result->pixels.diffLevels[i], " (", toString(diff_.result->pixels.pixelClass[i]), ')');
    ImGui::TextUnformatted(text.c_str());
    line += " " + text;
    diffShown = true;
  } else {
    const std::string note = pairState(shown) == PairState::SameEdit ? "no diff at this size yet" : pairNote(shown);
    ImGui::TextColored(kWarningColour, "%s", note.c_str());
    line += " " + note;
  }
  if (probe_.enabled()) {
    probe_.state()["hover"] = {{"text", line},
                               {"cpu_edit", shown.cpu},
                               {"gl_edit", shown.gl},
                               {"diff_edit", shown.diff},
                               {"diff_shown", diffShown}};
  }
}

}  // namespace twr::gui
