// Stats: per-backend frame times (moving median) and pipeline counts, the GL context, and
// the live diff metrics of the last frame pair both backends rendered from the same edit.
#include "app/gui/app.h"
#include "gui/text_concat.h"
#include "app/gui/ui_widgets.h"
#include "glrender/gl_renderer.h"

#include <cstdio>
#include <string>

namespace twr::gui {
namespace {

std::string count(std::uint64_t value) { return std::to_string(value); }

std::string milliseconds(const std::optional<double>& value) {
  if (!value) return "-";
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.1f ms", *value);
  return buffer;
}

void row(const char* name, const std::string& cpu, const std::string& gl, const char* help = nullptr) {
  ImGui::TableNextRow();
  ImGui::TableSetColumnIndex(0);
  ImGui::TextUnformatted(name);
  if (help) itemTooltip(help);
  ImGui::TableSetColumnIndex(1);
  ImGui::TextUnformatted(cpu.c_str());
  ImGui::TableSetColumnIndex(2);
  if (gl == "n/a") ImGui::TextDisabled("n/a");
  else ImGui::TextUnformatted(gl.c_str());
}

void metricRow(const char* name, const std::string& value, const char* help) {
  ImGui::TableNextRow();
  ImGui::TableSetColumnIndex(0);
  ImGui::TextUnformatted(name);
  itemTooltip(help);
  ImGui::TableSetColumnIndex(1);
  ImGui::TextUnformatted(value.c_str());
}

std::string number(double value, const char* format) {
  char buffer[48];
  std::snprintf(buffer, sizeof buffer, format, value);
  return buffer;
}

}  // namespace

void GuiApp::drawStatsPanel() {
  const RenderStats* cpu = cpuFrame_.output ? &cpuFrame_.output->stats : nullptr;
  const RenderStats* gl = glFrame_.output ? &glFrame_.output->stats : nullptr;
  const auto cpuCount = [cpu](std::uint64_t RenderStats::*field) { return cpu ? count(cpu->*field) : "-"; };
  const auto glCount = [gl](std::uint64_t RenderStats::*field) { return gl ? count(gl->*field) : "-"; };

  if (ImGui::BeginTable("##backends", 3, ImGuiTableFlags_RowBg | ImGuiTableFlags_SizingStretchProp)) {
    ImGui::TableSetupColumn("", ImGuiTableColumnFlags_WidthStretch, 1.4f);
    ImGui::TableSetupColumn("CPU", ImGuiTableColumnFlags_WidthStretch, 1.0f);
    ImGui::TableSetupColumn("GL", ImGuiTableColumnFlags_WidthStretch, 1.0f);
    ImGui::TableNextRow(ImGuiTableRowFlags_Headers);
    ImGui::TableSetColumnIndex(0);
    ImGui::TextUnformatted("per backend");
    ImGui::TableSetColumnIndex(1);
    ImGui::TextColored(ImGui::ColorConvertU32ToFloat4(kCpuAccent), "CPU");
    ImGui::TableSetColumnIndex(2);
    ImGui::TextColored(ImGui::ColorConvertU32ToFloat4(kGlAccent), "GL");
    const std::string timingHelp = concat(
        "Wall time of render(): CPU on its worker thread, GL including the read-back of every buffer. The median "
        "of the last ", kTimingWindow, " frames at most; it starts again when a scene is loaded, the render size "
        "changes or the CPU path changes, and skips the first ", kColdFramesSkipped,
        " frames after that (cold: shader compilation, uploads, allocation).\nCPU: ", cpuMs_.describe(),
        ".\nGL: ", glMs_.describe(), '.');
    row("frame, median", milliseconds(cpuMs_.median()), milliseconds(glMs_.median()), timingHelp.c_str());
    row("  frames in it", std::to_string(cpuMs_.counted()), std::to_string(glMs_.counted()), timingHelp.c_str());
    row("last frame", cpu ? milliseconds(cpu->milliseconds) : "-", gl ? milliseconds(gl->milliseconds) : "-",
        "The frame on screen, cold or not.");
    row("path (SIMD target)", cpuFrame_.cpuPath.empty() ? "-" : cpuFrame_.cpuPath, "n/a",
        "The CPU traversal that drew the frame shown, and for the fast path the Highway target it ran on (auto "
        "resolved). Switch both in the Rendering tab.");
    row("triangles in", cpuCount(&RenderStats::trianglesIn), glCount(&RenderStats::trianglesIn),
        "Submitted to the clipper (GL: submitted to glDrawElements).");
    row("  clipped", cpuCount(&RenderStats::trianglesClipped), "n/a",
        "Touched by at least one clip plane. GL clips inside the driver and does not say.");
    row("  culled or zero-area", cpuCount(&RenderStats::trianglesCulled), "n/a",
        "Removed by face culling, or of zero area after snapping to 1/256 pixel (edge-on or tiny triangles). "
        "With Cull = none only the zero-area ones are counted, so this is rarely 0.");
    row("  drawn", cpuCount(&RenderStats::trianglesProduced), "n/a",
        "Reaching the rasterizer after clipping (a clipped triangle becomes a fan of several).");
    row("depth-test passes", cpuCount(&RenderStats::pixelsShaded), glCount(&RenderStats::pixelsShaded),
        "Fragments that passed the depth test when they were drawn (GL: GL_SAMPLES_PASSED), overdraw included: a "
        "surface drawn first and hidden later counts too. So it is not the covered pixel count, and the two "
        "backends may differ while their images match: where two surfaces lie at nearly the same depth (back "
        "and front faces at a silhouette with Cull = none, touching objects) GL compares 24-bit depth and the "
        "CPU 32-bit float, so a later fragment passes on one and fails on the other. The visible result is the "
        "same; the diff below is what compares images.");
    ImGui::EndTable();
  }
  disabledTextWrapped("Timings since %s; the first %zu frames after that are skipped.", cpuMs_.restartReason().c_str(),
                      cpuMs_.coldFrames());
  // The last context made is the GL worker's once it has drawn (the window's comes first).
  disabledTextWrapped("UI %.0f redraws/s (ImGui's average over the last 60 redraws; fewer when idle). GL frames: "
                      "%s, %s, %s",
                      static_cast<double>(ImGui::GetIO().Framerate), glContextString().c_str(),
                      glVersionString().c_str(), glRendererString().c_str());
  probe_.item("stats_gl_line");

  sectionTitle(diff_.result ? concat("Diff (CPU vs GL, both of edit ", diff_.revision, ')').c_str()
                            : "Diff (CPU vs GL, same edit)");
  if (!diff_.result) {
    hintText(diff_.error.empty() ? "Waiting for both backends to finish a frame of the same edit." : diff_.error.c_str());
    return;
  }
  const CompareMetrics& m = diff_.result->metrics;
  if (diff_.revision != doc_.revision) {
    warningText(!renderBlocker_.empty()
                    ? concat("These numbers are for edit ", diff_.revision, "; nothing renders until this is fixed: ",
                             renderBlocker_)
                    : concat("These numbers are for edit ", diff_.revision, "; the CPU is rendering edit ",
                             doc_.revision, '.'));
  }
  if (ImGui::BeginTable("##metrics", 2, ImGuiTableFlags_RowBg | ImGuiTableFlags_SizingStretchProp)) {
    const std::string maxAt = m.hasMaxAbsDiffAt()
                                  ? " at (" + std::to_string(m.maxAbsDiffX) + ", " + std::to_string(m.maxAbsDiffY) + ")"
                                  : "";
    metricRow("max |diff|", std::to_string(m.maxAbsDiff) + " levels" + maxAt,
              "Largest per-pixel difference (max over RGB) where both covered, 0..255. Click 'inspect' to pin "
              "that pixel.");
    if (m.hasMaxAbsDiffAt()) {
      sameLineIfFits(ImGui::CalcTextSize("inspect").x + 2.0f * ImGui::GetStyle().FramePadding.x);  // else under the value
      if (ImGui::SmallButton("inspect")) pinPixel(PixelPos{m.maxAbsDiffX, m.maxAbsDiffY});
      probe_.item("inspect_max_diff");
      itemTooltip("Pin the first pixel (top-left scan) with the largest difference in the inspector.");
    }
    metricRow("mean |diff|, RMSE", number(m.meanAbsDiff, "%.4f") + ", " + number(m.rmse, "%.4f") + " levels",
              "Over pixels both covered x 3 channels.");
    metricRow("PSNR", number(m.psnr, "%.2f dB"), "20 log10(255 / RMSE), capped at 100 dB.");
    metricRow("pixels > 1 / 3 / 12", count(m.over1) + " / " + count(m.over3) + " / " + count(m.over12),
              "Both-covered pixels differing by more than 1, 3, 12 levels.");
    metricRow("> 1 level", number(m.over1Pct(), "%.3f %% of both covered"), "The issue's main target: <= 0.1 %.");
    metricRow("coverage CPU / GL only", count(m.coverageCpuOnly) + " / " + count(m.coverageGlOnly),
              "Pixels one backend covered and the other did not: the fill rule, clipping, snapping.");
    metricRow("coverage mismatch", number(m.coverageMismatchPer10k(), "%.2f per 10k covered"),
              "Per 10,000 pixels covered by either backend.");
    metricRow("classes depth / shading", count(m.classDepth) + " / " + count(m.classShading),
              "Differing pixels where another surface won (depth) or the same one shaded differently.");
    metricRow("depth max diff", m.depthAvailable ? number(m.depthMaxDiff, "%.3g") : "n/a", "Window depth units.");
    metricRow("NaN pixels", count(m.nanPixels), "CPU depth NaN or Inf: must stay 0.");
    metricRow("TBN line pixels", count(m.excludedLinePixels), "Left out of every other number.");
    ImGui::EndTable();
  }
}

}  // namespace twr::gui
