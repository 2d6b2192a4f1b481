// The pixel inspector: the pinned pixel in both backends (colour, depth, triangle), every
// debug view read back from both at that pixel, and the CPU pixel trace (which triangles
// reach it, clipping, barycentrics, uv, T/B/N, the normal-map texel, each lighting term).
#include "app/gui/app.h"
#include "gui/text_concat.h"
#include "gui/debug_views.h"
#include "app/gui/ui_widgets.h"
#include "scene/shadow_map.h"
#include "scene/shadow_trace.h"
#include "softrender/stage_pictures.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <string>

namespace twr::gui {
namespace {

int maxChannelDifference(const std::array<std::uint8_t, 4>& a, const std::array<std::uint8_t, 4>& b) {
  int largest = 0;
  for (std::size_t c = 0; c < 3; ++c) largest = std::max(largest, std::abs(int(a[c]) - int(b[c])));
  return largest;
}

void sampleCell(const std::optional<PixelSample>& sample, View view) {
  if (!sample) {
    ImGui::TextDisabled("...");
    return;
  }
  rgbaValue(sample->rgba.data(), false);
  // Only what was drawn is decoded: an empty pixel's background colour is not a vector.
  if (view != View::Shaded && view != View::Albedo) {
    disabledTextWrapped("(%s)", describeViewSample(view, *sample).c_str());  // its own line: the column is narrow
  } else if (!sample->drawn) {
    ImGui::SameLine();
    ImGui::TextDisabled("(empty)");
  }
  itemTooltip(viewLegend(view));
}

// The planes that cut a triangle, by name, and what was left.
std::string clipText(const TriangleVisit& visit) {
  if (visit.planesCut == 0) return "none";
  if (visit.planesCut & kClipNonFiniteBit) return clipPlaneNames(visit.planesCut);
  return clipPlaneNames(visit.planesCut) + " (" + std::to_string(visit.clippedPolygon.size()) + " vertices after)";
}

std::string triangleText(std::uint32_t id) { return id == kNoTriangle ? "none" : std::to_string(id); }

}  // namespace

void GuiApp::drawInspectorPanel() {
  if (!pin_.pixel) {
    sectionTitle("Pixel inspector");
    hintText("Click a pixel in the view (without dragging) to pin it. The inspector then shows what both backends "
             "wrote there, every debug view at that pixel from both, and the CPU pipeline's trace of it: the "
             "triangles that reach it, clipping, barycentrics, uv, T/B/N, the normal-map texel and each "
             "lighting term.");
    return;
  }
  const PixelPos p = *pin_.pixel;
  ImGui::Text("Pixel (%d, %d) of %d x %d", p.x, p.yTop, renderWidth_, renderHeight_);
  helpMarker("x from the left, y from the top, as in the PNG files. GL's window row is height - 1 - y.");
  ImGui::SameLine();
  if (ImGui::SmallButton("Unpin")) {
    pinPixel(std::nullopt);
    return;
  }

  // What each backend wrote in the frame on screen.
  if (ImGui::BeginTable("##written", 3, ImGuiTableFlags_RowBg | ImGuiTableFlags_SizingStretchProp)) {
    ImGui::TableSetupColumn("", ImGuiTableColumnFlags_WidthStretch, 0.8f);
    ImGui::TableSetupColumn("CPU", ImGuiTableColumnFlags_WidthStretch, 1.0f);
    ImGui::TableSetupColumn("GL", ImGuiTableColumnFlags_WidthStretch, 1.0f);
    ImGui::TableHeadersRow();
    const std::shared_ptr<const RenderOutput> outputs[2] = {cpuFrame_.output, glFrame_.output};
    const auto usable = [this](const std::shared_ptr<const RenderOutput>& output) {
      return output && output->width == renderWidth_ && output->height == renderHeight_;
    };
    const std::size_t i = static_cast<std::size_t>(p.yTop) * static_cast<std::size_t>(renderWidth_) +
                          static_cast<std::size_t>(p.x);
    // A deferred frame's G-buffer (docs/deferred.md) at the pixel too, target by target.
    const auto hasGBuffer = [&](const std::shared_ptr<const RenderOutput>& output) {
      return usable(output) && output->gbuffer && output->gbuffer->normal.size() > i;
    };
    const bool gbufferRows = hasGBuffer(outputs[0]) || hasGBuffer(outputs[1]);
    const char* rows[] = {"colour",   "depth",      "triangle",   "G normal",  "G geometric",
                          "G albedo", "G specular", "G emission", "G position"};
    const int rowCount = gbufferRows ? 9 : 3;
    for (int r = 0; r < rowCount; ++r) {
      ImGui::TableNextRow();
      ImGui::TableSetColumnIndex(0);
      ImGui::TextUnformatted(rows[r]);
      if (r >= 3) {
        itemTooltip("The G-buffer a deferred frame was lit from: the world lighting normal (w: the Phong "
                    "exponent), the interpolated normal, kd albedo, ks specScale, what no light scales and "
                    "the world position (docs/deferred.md). A forward frame has none; a frame that rebuilds "
                    "the position from depth stores none.");
      }
      for (int b = 0; b < 2; ++b) {
        ImGui::TableSetColumnIndex(b + 1);
        const std::shared_ptr<const RenderOutput>& output = outputs[b];
        if (!usable(output)) {
          ImGui::TextDisabled("-");
          continue;
        }
        if (r == 0) rgbaValue(&output->rgba[i * 4], true);
        if (r == 1) ImGui::Text("%.7f", static_cast<double>(output->depth[i]));
        if (r == 2) ImGui::TextUnformatted(triangleText(output->triangleId[i]).c_str());
        if (r >= 3) {
          if (!hasGBuffer(output)) {
            ImGui::TextDisabled("forward");
            continue;
          }
          const GBuffer& g = *output->gbuffer;
          const std::vector<vec4>* targets[] = {&g.normal,   &g.geometric, &g.albedo,
                                                &g.specular, &g.emission,  &g.position};
          if (targets[r - 3]->size() <= i) {
            ImGui::TextDisabled("from depth");
            continue;
          }
          const vec4 v = (*targets[r - 3])[i];
          ImGui::Text("%.4f %.4f %.4f %.4g", static_cast<double>(v.x), static_cast<double>(v.y),
                      static_cast<double>(v.z), static_cast<double>(v.w));
        }
      }

    }
    ImGui::EndTable();
  }
  const ShownRevisions shown = shownRevisions();
  if (pairState(shown) == PairState::SameEdit && diff_.result && diff_.result->pixels.width == renderWidth_ &&
      diff_.result->pixels.height == renderHeight_) {
    const std::size_t i = diff_.result->pixels.index(p.x, p.yTop);
    ImGui::Text("diff %d levels, class %s (both of edit %llu)", diff_.result->pixels.diffLevels[i],
                std::string(toString(diff_.result->pixels.pixelClass[i])).c_str(),
                static_cast<unsigned long long>(diff_.revision));
  } else if (pairState(shown) != PairState::SameEdit) {
    warningText(pairNote(shown));
  }

  if (drawsDeferred(doc_.scene.settings)) {
    hintText("This frame was lit deferred (the G rows above). The trace and the views below shade the pixel "
             "forward, on both backends: the lighting terms are the forward pipeline's.");
  }
  if (!pin_.cpu) {
    hintText("CPU trace: waiting for the worker...");
  } else if (!pin_.cpu->traceError.empty()) {
    errorText("CPU trace: " + pin_.cpu->traceError);
  } else if (pin_.cpu->trace) {
    drawStageExplorerSection();
    drawTraceSection(*pin_.cpu->trace);
  }
  drawViewProbeSection();
  if (drawsSsr(doc_.scene.settings)) drawSsrMarchSection();
  if (sceneHasShadows(doc_.scene)) drawShadowTapsSection();
}

namespace {

// One backend's step of the march as table cells: what it did, where, the two distances.
void marchStepCells(const SsrMarchStep* step) {
  if (!step) {
    ImGui::TableNextColumn();
    ImGui::TextDisabled("-");
    ImGui::TableNextColumn();
    ImGui::TableNextColumn();
    return;
  }
  ImGui::TableNextColumn();
  if (step->level > 0) {
    ImGui::Text("%s L%d", toString(step->kind), step->level);
  } else {
    ImGui::TextUnformatted(toString(step->kind));
  }
  ImGui::TableNextColumn();
  ImGui::Text("%.0f, %.0f", static_cast<double>(step->pixel.x), static_cast<double>(step->pixel.y));
  ImGui::TableNextColumn();
  ImGui::Text("%.4f / %.4f", static_cast<double>(step->rayDistance), static_cast<double>(step->surfaceDistance));
}

}  // namespace

// The pinned pixel's march of its mirror ray or an indirect sample, step by step, on both
// backends (docs/ssr.md, "One pixel's march"), the first step where they part marked.
void GuiApp::drawSsrMarchSection() {
  const bool cpuCurrent = pin_.cpu && pin_.cpuRevision == doc_.revision;
  std::string title = "SSR march at this pixel";
  if (!cpuCurrent) title += " (CPU updating...)";
  title += "###ssrmarch";
  if (!ImGui::CollapsingHeader(title.c_str(), ImGuiTreeNodeFlags_DefaultOpen)) return;
  // Which ray: the mirror ray, or one of indirect light's samples (a new probe on a change).
  const int samples = ssrTraceSamples(doc_.scene.settings);
  const int ray = ssrTraceRayOf(doc_.scene.settings);
  ImGui::SetNextItemWidth(ImGui::GetFontSize() * 12.0f);
  if (ImGui::BeginCombo("Ray##ssrray", ssrRayName(ray).c_str())) {
    for (int k = kSsrMirrorRay; k < samples; ++k) {
      if (ImGui::Selectable(ssrRayName(k).c_str(), k == ray) && k != ray) {
        ssrTraceRay_ = k;
        // The last ray's errors go with it; the new ray's probes come with their own.
        pin_.glMarchError.clear();
        if (pin_.cpu) pin_.cpu->ssrMarchError.clear();
      }
    }
    ImGui::EndCombo();
  }
  if (samples == 0 && ImGui::IsItemHovered()) {
    ImGui::SetTooltip("No indirect light is drawn (indirect_samples 0, or an SSR view): the mirror ray only");
  }
  if (!pin_.cpu || !pin_.cpu->ssrMarchError.empty()) {
    if (pin_.cpu) errorText("CPU: " + pin_.cpu->ssrMarchError);
    else hintText("CPU: waiting for the worker...");
  }
  if (!pin_.glMarchError.empty()) errorText("GL: " + pin_.glMarchError);
  // A trace of another ray (just picked) waits for its own.
  const SsrMarchTrace* cpu =
      cpuCurrent && pin_.cpu->ssrMarch && pin_.cpu->ssrMarch->ray == ray ? &*pin_.cpu->ssrMarch : nullptr;
  const SsrMarchTrace* gl =
      pin_.glMarch && pin_.glRevision == doc_.revision && pin_.glMarch->ray == ray ? &*pin_.glMarch : nullptr;
  if (!gl && pin_.glMarchError.empty()) hintText("GL: waiting for the worker...");
  const SsrMarchTrace* any = cpu ? cpu : gl;
  if (!any) return;
  if (!any->marched) {
    hintText("Nothing is drawn here: no ray to march.");
    return;
  }
  hintText("The mirror ray of the lighting normal (or an indirect sample's ray over its hemisphere) from the "
           "G-buffer's point, marched as settings.ssr says; each step: what the march decided, the pixel it "
           "sampled (window, from the bottom), the ray's eye distance against the surface's (a hiz cell: its farthest sample against the cell's nearest surface). The two "
           "backends record the same numbers from their own march (GL: ssr.frag's probe).");
  if (monoFont_) ImGui::PushFont(monoFont_);
  ImGui::Text("origin %s  direction %s", formatVec(any->origin).c_str(), formatVec(any->direction).c_str());
  if (any->ray != kSsrMirrorRay) ImGui::Text("sample weight %.5f", static_cast<double>(any->weight));
  if (monoFont_) ImGui::PopFont();
  if (cpu && gl && cpu->direction != gl->direction) {
    warningText(concat("The backends' directions differ: CPU ", formatVec(cpu->direction, 9), ", GL ",
                       formatVec(gl->direction, 9), "."));
  }
  const std::size_t rows = std::max(cpu ? cpu->steps.size() : 0, gl ? gl->steps.size() : 0);
  std::size_t parted = rows;  // a plain index (rows = none): see formatSsrMarchTraces
  if (cpu && gl) {
    const std::optional<std::size_t> first = firstDifferingStep(*cpu, *gl);
    if (first) {
      parted = *first;
      warningText(concat("The backends part at step ", parted + 1, "."));
    } else {
      ImGui::TextDisabled("Both backends take the same %zu steps.", cpu->steps.size());
    }
  }
  if (ImGui::BeginTable("##ssrmarch", 7, ImGuiTableFlags_RowBg | ImGuiTableFlags_SizingStretchProp |
                                              ImGuiTableFlags_ScrollY,
                        ImVec2(0.0f, ImGui::GetTextLineHeightWithSpacing() * 14.0f))) {
    ImGui::TableSetupScrollFreeze(0, 1);
    ImGui::TableSetupColumn("step", ImGuiTableColumnFlags_WidthStretch, 0.3f);
    ImGui::TableSetupColumn("CPU", ImGuiTableColumnFlags_WidthStretch, 0.8f);
    ImGui::TableSetupColumn("pixel", ImGuiTableColumnFlags_WidthStretch, 0.6f);
    ImGui::TableSetupColumn("ray / surface", ImGuiTableColumnFlags_WidthStretch, 1.1f);
    ImGui::TableSetupColumn("GL", ImGuiTableColumnFlags_WidthStretch, 0.8f);
    ImGui::TableSetupColumn("pixel", ImGuiTableColumnFlags_WidthStretch, 0.6f);
    ImGui::TableSetupColumn("ray / surface", ImGuiTableColumnFlags_WidthStretch, 1.1f);
    ImGui::TableHeadersRow();
    if (monoFont_) ImGui::PushFont(monoFont_);
    for (std::size_t k = 0; k < rows; ++k) {
      ImGui::TableNextRow();
      ImGui::TableNextColumn();
      if (parted == k) ImGui::TextColored(kWarningColour, "%zu", k + 1);
      else ImGui::Text("%zu", k + 1);
      marchStepCells(cpu && k < cpu->steps.size() ? &cpu->steps[k] : nullptr);
      marchStepCells(gl && k < gl->steps.size() ? &gl->steps[k] : nullptr);
    }
    if (monoFont_) ImGui::PopFont();
    ImGui::EndTable();
  }
}

namespace {

// One backend's tap as table cells: the texel read, the map's depth there, the outcome.
void shadowTapCells(const ShadowTap* tap) {
  ImGui::TableNextColumn();
  if (!tap) {
    ImGui::TextDisabled("-");
    ImGui::TableNextColumn();
    ImGui::TableNextColumn();
    return;
  }
  ImGui::Text("%d,%d,%d", tap->texel.x, tap->texel.y, tap->texel.z);
  ImGui::TableNextColumn();
  ImGui::Text("%.9f", static_cast<double>(tap->stored));
  ImGui::TableNextColumn();
  ImGui::TextUnformatted(tap->lit ? "lit" : "shadow");
}

const ShadowTapTrace* tapsOfLight(const std::vector<ShadowTapTrace>& traces, int light) {
  for (const ShadowTapTrace& t : traces) {
    if (t.light == light) return &t;
  }
  return nullptr;
}

}  // namespace

// Each shadowed light's test at the pinned pixel, tap by tap, on both backends (docs/shadows.md,
// "One pixel's taps"), the first tap where they part marked.
void GuiApp::drawShadowTapsSection() {
  const bool cpuCurrent = pin_.cpu && pin_.cpuRevision == doc_.revision;
  const bool glCurrent = pin_.glRevision == doc_.revision;
  std::string title = "Shadow taps at this pixel";
  if (!cpuCurrent) title += " (CPU updating...)";
  title += "###shadowtaps";
  if (!ImGui::CollapsingHeader(title.c_str(), ImGuiTreeNodeFlags_DefaultOpen)) return;
  hintText("Each PCF tap of the light's test: the map texel read (x, y, layer), the map's depth there and whether "
           "the fragment's compared depth (depth - bias) lies at or in front of it. Both backends record their own "
           "numbers (GL: phong.frag's probe) and read their own maps.");
  if (glCurrent && !pin_.glShadowTapsError.empty()) errorText("GL: " + pin_.glShadowTapsError);
  // A GL probe cut short by an error in its views never reaches the taps.
  const bool glStopped = glCurrent && !pin_.glError.empty() && pin_.glShadowTaps.empty();
  if (glStopped) errorText("GL: not traced: " + pin_.glError);
  if (!cpuCurrent) return;
  for (const ShadowTapTrace& cpu : pin_.cpu->shadowTaps) {
    const ShadowTapTrace* gl = glCurrent ? tapsOfLight(pin_.glShadowTaps, cpu.light) : nullptr;
    ImGui::PushID(cpu.light);
    ImGui::Text("Light %d (PCF %d)", cpu.light, cpu.pcf);
    if (!cpu.tested) {
      hintText("Not tested: nothing is drawn here.");
      ImGui::PopID();
      continue;
    }
    if (monoFont_) ImGui::PushFont(monoFont_);
    const auto fragment = [](const char* who, const ShadowTapTrace& t) {
      ImGui::TextWrapped("%s: depth %.9f - bias %.9f = %.9f, texel %d, %d, %d, visibility %.4f", who,
                         static_cast<double>(t.depth), static_cast<double>(t.bias), static_cast<double>(t.reference),
                         t.texel.x, t.texel.y, t.texel.z, static_cast<double>(t.visibility));
    };
    fragment("CPU", cpu);
    if (gl && gl->tested) fragment("GL ", *gl);
    if (monoFont_) ImGui::PopFont();
    if (!gl && pin_.glShadowTapsError.empty() && !glStopped) hintText("GL: waiting for the worker...");
    if (gl) {
      const std::string parted = testsPartBeforeTaps("CPU", cpu, "GL", *gl);
      if (!parted.empty()) warningText("The tests part before any tap: " + parted + ".");
    }
    if (!cpu.inside) {
      hintText("Outside the map: lit, no tap read.");
      ImGui::PopID();
      continue;
    }
    const std::size_t rows = std::max(cpu.taps.size(), gl ? gl->taps.size() : 0);
    std::size_t parted = rows;  // a plain index (rows = none): see formatSsrMarchTraces
    if (gl && testsPartBeforeTaps("CPU", cpu, "GL", *gl).empty()) {
      const std::optional<std::size_t> first = firstDifferingTap(cpu, *gl);
      if (first) {
        parted = *first;
        warningText(concat("The backends part at tap ", parted + 1, "."));
      } else {
        ImGui::TextDisabled("Every tap alike on both backends.");
      }
    }
    if (ImGui::BeginTable("##taps", 8, ImGuiTableFlags_RowBg | ImGuiTableFlags_SizingStretchProp | ImGuiTableFlags_ScrollY,
                          ImVec2(0.0f, ImGui::GetTextLineHeightWithSpacing() * std::min<float>(10.0f, float(rows) + 1.5f)))) {
      ImGui::TableSetupScrollFreeze(0, 1);
      ImGui::TableSetupColumn("tap", ImGuiTableColumnFlags_WidthStretch, 0.3f);
      ImGui::TableSetupColumn("CPU texel", ImGuiTableColumnFlags_WidthStretch, 1.0f);
      ImGui::TableSetupColumn("stored", ImGuiTableColumnFlags_WidthStretch, 1.0f);
      ImGui::TableSetupColumn("", ImGuiTableColumnFlags_WidthStretch, 0.55f);
      ImGui::TableSetupColumn("GL texel", ImGuiTableColumnFlags_WidthStretch, 1.0f);
      ImGui::TableSetupColumn("stored", ImGuiTableColumnFlags_WidthStretch, 1.0f);
      ImGui::TableSetupColumn("", ImGuiTableColumnFlags_WidthStretch, 0.55f);
      ImGui::TableSetupColumn("dx,dy", ImGuiTableColumnFlags_WidthStretch, 0.4f);
      ImGui::TableHeadersRow();
      if (monoFont_) ImGui::PushFont(monoFont_);
      for (std::size_t k = 0; k < rows; ++k) {
        const ShadowTap* a = k < cpu.taps.size() ? &cpu.taps[k] : nullptr;
        const ShadowTap* b = gl && k < gl->taps.size() ? &gl->taps[k] : nullptr;
        ImGui::TableNextRow();
        ImGui::TableNextColumn();
        if (parted == k) ImGui::TextColored(kWarningColour, "%zu", k + 1);
        else ImGui::Text("%zu", k + 1);
        shadowTapCells(a);
        shadowTapCells(b);
        ImGui::TableNextColumn();
        const ShadowTap* any = a ? a : b;
        if (any) ImGui::Text("%d,%d", any->dx, any->dy);
      }
      if (monoFont_) ImGui::PopFont();
      ImGui::EndTable();
    }
    ImGui::PopID();
  }
}

// Every debug view at the pinned pixel, from both backends.
void GuiApp::drawViewProbeSection() {
  const bool cpuCurrent = pin_.cpu && pin_.cpuRevision == doc_.revision;
  const std::size_t glRead =
      static_cast<std::size_t>(std::count_if(pin_.gl.begin(), pin_.gl.end(), [](const auto& s) { return s.has_value(); }));
  std::string title = "Debug views at this pixel";
  if (glRead < kViewCount && pin_.glError.empty()) title += " (GL " + std::to_string(glRead) + "/" + std::to_string(kViewCount) + ")";
  if (!cpuCurrent) title += " (CPU updating...)";
  title += "###views";
  if (ImGui::CollapsingHeader(title.c_str(), ImGuiTreeNodeFlags_DefaultOpen)) {
    hintText("Each view rendered by both backends with TBN lines off; vectors decoded as c / 255 * 2 - 1 where "
             "something was drawn (a triangle id). Hover a value for what its colours mean.");
    if (!pin_.glError.empty()) errorText("GL: " + pin_.glError);
    if (ImGui::BeginTable("##views", 4, ImGuiTableFlags_RowBg | ImGuiTableFlags_SizingStretchProp)) {
      ImGui::TableSetupColumn("view", ImGuiTableColumnFlags_WidthStretch, 0.7f);
      ImGui::TableSetupColumn("CPU", ImGuiTableColumnFlags_WidthStretch, 1.3f);
      ImGui::TableSetupColumn("GL", ImGuiTableColumnFlags_WidthStretch, 1.3f);
      ImGui::TableSetupColumn("diff", ImGuiTableColumnFlags_WidthStretch, 0.3f);
      ImGui::TableHeadersRow();
      for (std::size_t v = 0; v < kViewCount; ++v) {
        const View view = kAllViews[v];
        ImGui::TableNextRow();
        ImGui::TableSetColumnIndex(0);
        const std::string name(toString(view));
        if (view == doc_.scene.settings.view) ImGui::TextColored(ImVec4(0.55f, 0.72f, 1.0f, 1.0f), "%s", name.c_str());
        else ImGui::TextUnformatted(name.c_str());
        const std::optional<PixelSample> cpuSample = cpuCurrent ? pin_.cpu->views[v] : std::nullopt;
        ImGui::TableSetColumnIndex(1);
        sampleCell(cpuSample, view);
        ImGui::TableSetColumnIndex(2);
        sampleCell(pin_.gl[v], view);
        ImGui::TableSetColumnIndex(3);
        if (cpuSample && pin_.gl[v]) {
          const int difference = maxChannelDifference(cpuSample->rgba, pin_.gl[v]->rgba);
          if (difference > 0) ImGui::TextColored(kWarningColour, "%d", difference);
          else ImGui::TextDisabled("0");
        }
      }
      ImGui::EndTable();
    }
  }

}

void GuiApp::drawTraceSection(const PixelTrace& trace) {
  std::string title = "CPU pixel trace: " + std::to_string(trace.visits.size()) + " triangle(s) reach it";
  if (pin_.cpuRevision != doc_.revision) title += " (updating...)";
  title += "###trace";
  if (!ImGui::CollapsingHeader(title.c_str(), ImGuiTreeNodeFlags_DefaultOpen)) return;
  if (trace.debugLine) warningText("A TBN debug line was drawn over this pixel after shading.");

  // The visit that wrote the pixel: the last shaded one.
  const TriangleVisit* winner = nullptr;
  for (const TriangleVisit& visit : trace.visits) {
    if (visit.outcome == TraceOutcome::Shaded) winner = &visit;
  }
  for (std::size_t n = 0; n < trace.visits.size(); ++n) {
    const TriangleVisit& visit = trace.visits[n];
    ImGui::PushID(static_cast<int>(n));
    const bool isWinner = &visit == winner;
    const std::string label = concat('#', n + 1, " triangle ", visit.triangleId, " ('", visit.nodeName, "' ",
                                     visit.triangleInMesh, "): ", toString(visit.outcome),
                                     isWinner ? "  <- wrote the pixel" : "");
    if (isWinner) ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(0.6f, 1.0f, 0.6f, 1.0f));
    const bool open = ImGui::TreeNodeEx("##visit", isWinner ? ImGuiTreeNodeFlags_DefaultOpen : 0, "%s", label.c_str());
    if (isWinner) ImGui::PopStyleColor();
    if (open) {
      if (monoFont_) ImGui::PushFont(monoFont_);
      ImGui::Text("faces %s; clip planes cutting it: %s", visit.frontFacing ? "front" : "back", clipText(visit).c_str());
      ImGui::Text("edges %lld %lld %lld (inside when all > 0)", static_cast<long long>(visit.edgeValue[0]),
                  static_cast<long long>(visit.edgeValue[1]), static_cast<long long>(visit.edgeValue[2]));
      if (visit.outcome != TraceOutcome::ClippedAway) {
        const PixelWeights& w = visit.weights;
        ImGui::Text("barycentric  %.4f %.4f %.4f", static_cast<double>(w.screen[0]), static_cast<double>(w.screen[1]),
                    static_cast<double>(w.screen[2]));
        ImGui::Text("perspective  %.4f %.4f %.4f", static_cast<double>(w.perspective[0]),
                    static_cast<double>(w.perspective[1]), static_cast<double>(w.perspective[2]));
        ImGui::Text("depth %.7f vs stored %.7f", static_cast<double>(w.depth), static_cast<double>(visit.depthBefore));
        const Fragment& f = visit.fragment;
        ImGui::Text("posWorld %s", formatVec(f.posWorld).c_str());
        ImGui::Text("uv       %s", formatVec(f.uv, 4).c_str());
      }
      if (visit.outcome == TraceOutcome::Shaded) {
        const ShadeTerms& s = visit.terms;
        ImGui::Text("T %s", formatVec(s.t).c_str());
        ImGui::Text("B %s", formatVec(s.b).c_str());
        ImGui::Text("N %s", formatVec(s.n).c_str());
        ImGui::Text("normal texel %s -> tangent %s", formatVec(vec3(s.normalTexel)).c_str(),
                    formatVec(s.mappedTangent).c_str());
        ImGui::Text("Nl (lighting) %s", formatVec(s.nl).c_str());
        ImGui::Text("albedo %s  spec scale %s", formatVec(s.albedo).c_str(), formatVec(s.specScale).c_str());
        if (isShadedView(trace.view)) {
          ImGui::Text("ambient ka*albedo*Ia %s", formatVec(s.ambient).c_str());
          for (int l = 0; l < s.lightCount; ++l) {
            const LightTerms& t = s.lights[static_cast<std::size_t>(l)];
            ImGui::Text("light %d: d %.3f  N.L %.4f  R.V %.4f  If %.4f", l, static_cast<double>(t.distance),
                        static_cast<double>(t.nDotL), static_cast<double>(t.rDotV), static_cast<double>(t.attenuation));
            ImGui::Text("  diffuse %s  specular %s", formatVec(t.diffuse).c_str(), formatVec(t.specular).c_str());
          }
          if (isPhongTermView(trace.view)) {
            ImGui::Text("summed with If and shadow: diffuse %s  specular %s", formatVec(s.diffuseSum).c_str(),
                        formatVec(s.specularSum).c_str());
          }
        }
        ImGui::Text("colour %s", formatVec(s.colour).c_str());
      }
      if (monoFont_) ImGui::PopFont();
      ImGui::TreePop();
    }
    ImGui::PopID();
  }
  if (ImGui::TreeNode("Full report")) {
    const std::string report = formatPixelTrace(trace);
    if (ImGui::SmallButton("Copy to clipboard")) ImGui::SetClipboardText(report.c_str());
    if (monoFont_) ImGui::PushFont(monoFont_);
    ImGui::TextUnformatted(report.c_str());
    if (monoFont_) ImGui::PopFont();
    ImGui::TreePop();
  }
}

}  // namespace twr::gui
