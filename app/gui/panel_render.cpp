// The Rendering tab: the CPU renderer's own choices (path and SIMD target), then every field
// of RenderSettings, applied to both backends.
#include "app/gui/app.h"
#include "gui/debug_views.h"
#include "app/gui/ui_widgets.h"
#include "gui/text_concat.h"
#include "scene/environment.h"
#include "softrender/cpu_renderer.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace twr::gui {
namespace {

constexpr CullMode kCullModes[] = {CullMode::None, CullMode::Back, CullMode::Front};
constexpr FrontFace kFrontFaces[] = {FrontFace::Ccw, FrontFace::Cw};
constexpr LightingSpace kLightingSpaces[] = {LightingSpace::World, LightingSpace::Tangent};
constexpr Pipeline kPipelines[] = {Pipeline::Forward, Pipeline::Deferred};
constexpr GBufferPosition kGBufferPositions[] = {GBufferPosition::Stored, GBufferPosition::Depth};
// The marches drawn so far (dda_screen and hiz are named by the format, not drawn yet).
constexpr SsrMarch kSsrMarches[] = {SsrMarch::LinearWorld, SsrMarch::AdaptiveWorld, SsrMarch::DdaScreen, SsrMarch::Hiz};
constexpr float kSsrStepDragSpeed = 0.005f;  // world units per dragged point
constexpr Interpolation kInterpolations[] = {Interpolation::Perspective, Interpolation::Affine};
constexpr TangentTransform kTangentTransforms[] = {TangentTransform::Model, TangentTransform::InverseTranspose};
constexpr const TextureFilter (&kTextureFilters)[6] = kAllTextureFilters;
constexpr LineMode kLineModes[] = {LineMode::Core, LineMode::Immediate};

// TBN line length range offered by the slider, world units (inclusive).
constexpr float kMinLineLength = 0.005f;
constexpr float kMaxLineLength = 1.0f;
// Drag speed of the clip plane coefficients, units per pixel of mouse travel.
constexpr float kPlaneDragSpeed = 0.01f;

// Colour steps of the parallax_steps legend bar, and how many of its step counts are labelled
// (0, 1/4, ..., the most: where the ramp is blue, cyan, green, yellow, red).
constexpr int kStepsBarSlices = 64;
constexpr int kStepsBarTicks = 5;

// A new user plane keeps the half space y >= 0 (a horizontal cut at the floor).
const vec4 kNewUserPlane{0.0f, 1.0f, 0.0f, 0.0f};

}  // namespace

void GuiApp::drawCpuRendererSection() {
  bool changed = false;
  const float labelWidth = ImGui::CalcTextSize("Tangent transform").x + 2.0f * ImGui::GetStyle().ItemSpacing.x;
  sectionTitle("CPU renderer");
  ImGui::AlignTextToFramePadding();
  ImGui::TextUnformatted("Path");
  ImGui::SameLine(labelWidth);
  if (ImGui::RadioButton("fast", prefs_.cpuPath == CpuPath::Fast) && prefs_.cpuPath != CpuPath::Fast) {
    prefs_.cpuPath = CpuPath::Fast;
    changed = true;
  }
  itemTooltip("Binned triangles, a visibility pass, then the shading source on SIMD vectors (Google Highway) "
              "for the target below.");
  ImGui::SameLine();
  if (ImGui::RadioButton("teaching", prefs_.cpuPath == CpuPath::Teaching) && prefs_.cpuPath != CpuPath::Teaching) {
    prefs_.cpuPath = CpuPath::Teaching;
    changed = true;
  }
  itemTooltip("One stage after the other, one pixel at a time, as docs/pipeline.md draws it: slower, the same "
              "image bit for bit.");

  ImGui::BeginDisabled(prefs_.cpuPath == CpuPath::Teaching);
  ImGui::AlignTextToFramePadding();
  ImGui::TextUnformatted("SIMD target");
  ImGui::SameLine(labelWidth);
  ImGui::SetNextItemWidth(-FLT_MIN);
  const std::string autoLabel = "auto (" + std::string(toString(resolveCpuIsa(CpuIsa::Auto))) + ")";
  const auto label = [&autoLabel](CpuIsa isa) {
    return isa == CpuIsa::Auto ? autoLabel : std::string(toString(isa));
  };
  if (ImGui::BeginCombo("##cpu_isa", label(prefs_.cpuIsa).c_str())) {
    std::vector<CpuIsa> choices = {CpuIsa::Auto};
    for (const CpuIsa isa : supportedCpuIsas()) choices.push_back(isa);
    for (const CpuIsa isa : choices) {
      const bool selected = prefs_.cpuIsa == isa;
      if (ImGui::Selectable(label(isa).c_str(), selected) && !selected) {
        prefs_.cpuIsa = isa;
        changed = true;
      }
      if (selected) ImGui::SetItemDefaultFocus();
    }
    ImGui::EndCombo();
  }
  ImGui::EndDisabled();
  itemTooltip("The fast path's Highway target: auto takes the best this CPU runs; the list holds every target "
              "this binary and this CPU can run. Every target draws the same image; only the time changes.");

  // The CPU image is redrawn with the new renderer (GL too: one edit, one frame pair to diff).
  if (changed) doc_.touch();
}

void GuiApp::drawRenderingTab() {
  drawCpuRendererSection();

  RenderSettings& settings = doc_.scene.settings;
  bool changed = false;
  const float labelWidth = ImGui::CalcTextSize("Tangent transform").x + 2.0f * ImGui::GetStyle().ItemSpacing.x;

  sectionTitle("Debug view");
  ImGui::SetNextItemWidth(-FLT_MIN);
  // kAllViews and kSsrViews, each entry named for the scripted tests (height, parallax_offset, ... included).
  // Tall enough for every view: a scrolled list hid the height views at its end.
  if (ImGui::BeginCombo("##view", std::string(toString(settings.view)).c_str(), ImGuiComboFlags_HeightLargest)) {
    std::vector<View> views(std::begin(kAllViews), std::end(kAllViews));
    views.insert(views.end(), std::begin(kSsrViews), std::end(kSsrViews));  // the reflection pass's
    for (const View view : views) {
      const bool chosen = settings.view == view;
      if (ImGui::Selectable(std::string(toString(view)).c_str(), chosen) && !chosen) {
        settings.view = view;
        changed = true;
      }
      probe_.item(concat("view_", toString(view)).c_str());
      if (chosen) ImGui::SetItemDefaultFocus();
    }
    ImGui::EndCombo();
  }
  probe_.item("view");
  itemTooltip("What both backends write per pixel: the shaded colour, or one shading input as a colour "
              "(vectors as (v + 1) / 2, see docs/shading.md).");
  hintText(viewLegend(settings.view));
  // The buffer picker: what the images, the diff and the inspector's colour row show of each
  // frame (compare --buffer's buffers; docs/deferred.md).
  ImGui::SetNextItemWidth(-FLT_MIN);
  if (ImGui::BeginCombo("##buffer", concat("buffer: ", toString(shownBuffer_)).c_str())) {
    for (const PassBuffer buffer : kShowableBuffers) {
      const bool chosen = shownBuffer_ == buffer;
      if (ImGui::Selectable(std::string(toString(buffer)).c_str(), chosen) && !chosen) {
        shownBuffer_ = buffer;
        cpuTextureStale_ = glTextureStale_ = true;
      }
      probe_.item(concat("buffer_", toString(buffer)).c_str());
      if (chosen) ImGui::SetItemDefaultFocus();
    }
    ImGui::EndCombo();
  }
  probe_.item("buffer");
  itemTooltip("Which buffer of each frame the images and the diff show: the frame (final), its depth, or a "
              "deferred frame's G-buffer targets (normal as (n + 1) / 2, kd albedo, ks specScale, emission, "
              "the world position as a triangle wave of period 2 units).");
  const bool gbufferTarget = shownBuffer_ != PassBuffer::Final && shownBuffer_ != PassBuffer::GbufferDepth;
  if (gbufferTarget && !drawsDeferred(settings)) {
    warningText("A forward frame has no G-buffer: set Pipeline to deferred (Shading, below) in the shaded view. "
                "The frame is shown meanwhile.");
  }
  if (settings.view == View::ParallaxSteps) drawParallaxStepsLegend();
  if (settings.view == View::EnvFace || settings.view == View::EnvLod) drawEnvironmentViewLegend(settings.view);
  if (settings.view == View::Depth) {
    if (ImGui::Checkbox("linearised (eye distance)", &prefs_.linearDepth)) {
      cpuTextureStale_ = glTextureStale_ = true;
    }
    itemTooltip("Shows the eye distance z_eye = 2 n f / ((f + n) - z_ndc (f - n)) instead of window depth, from the "
                "nearest drawn pixel (black) to the farthest (white) of both images; the row above the images gives "
                "the two distances in world units. Display only: the diff, the hover line and the inspector keep "
                "window depth.");
  }

  sectionTitle("Rasterizer");
  changed |= enumRadio("Cull", settings.cull, kCullModes, labelWidth,
                       "Which triangles setup removes: none, the back-facing or the front-facing ones (GL_CULL_FACE). "
                       "Facing comes from the winding on screen and Front face.");
  changed |= enumRadio("Front face", settings.frontFace, kFrontFaces, labelWidth,
                       "Which winding on screen counts as front-facing: counter-clockwise (GL's default) or "
                       "clockwise (glFrontFace).");
  changed |= enumRadio("Interpolation", settings.interpolation, kInterpolations, labelWidth,
                       "How every varying spreads over a triangle. perspective: a/w and 1/w are linear on the "
                       "screen and divided per pixel, so a texture stays put. affine: the varying itself is linear "
                       "on the screen (GLSL's noperspective), and textures swim and bend on a receding floor "
                       "(docs/pipeline.md).");
  probe_.item("interpolation_affine");  // enumRadio's last button

  sectionTitle("Clipping");
  ImGui::TextUnformatted("Frustum planes");
  helpMarker("A switched-off side plane leaves the guard band to the rasterizer. A switched-off near or far "
             "plane becomes depth clamping (GL_DEPTH_CLAMP): geometry beyond it is no longer cut, its window "
             "depth is clamped to [0, 1]. Beyond the far plane that depth is 1.0, the value the depth buffer is "
             "cleared to, and the depth test is GL_LESS (1.0 < 1.0 fails): so those fragments are still not drawn, "
             "on both backends. Near clamping does show: geometry in front of the near plane gets depth 0.");
  if (!settings.clip.far) {
    hintText("Far plane off: depth beyond it clamps to 1.0, which fails GL_LESS against the cleared 1.0, so "
             "nothing beyond far appears (see the (?) above). Raise the camera's far instead to see it.");
  }
  if (ImGui::BeginTable("##frustum", 3)) {
    const std::pair<const char*, bool*> planes[] = {
        {"left", &settings.clip.left}, {"bottom", &settings.clip.bottom}, {"near", &settings.clip.near},
        {"right", &settings.clip.right}, {"top", &settings.clip.top}, {"far", &settings.clip.far}};
    for (const auto& [name, value] : planes) {
      ImGui::TableNextColumn();
      changed |= ImGui::Checkbox(name, value);
      itemTooltip("Clip against this frustum plane (on), or not (off: see the (?) above).");
    }
    ImGui::EndTable();
  }
  ImGui::Text("User clip planes (%zu of %d)", settings.userClipPlanes.size(), kMaxUserClipPlanes);
  helpMarker("World space. Each keeps the points with a*x + b*y + c*z + d >= 0 (GL: gl_ClipDistance).");
  int removeIndex = -1;
  for (std::size_t i = 0; i < settings.userClipPlanes.size(); ++i) {
    ImGui::PushID(static_cast<int>(i));
    ImGui::SetNextItemWidth(ImGui::GetContentRegionAvail().x - ImGui::GetFrameHeight() - ImGui::GetStyle().ItemSpacing.x);
    changed |= ImGui::DragFloat4("##plane", &settings.userClipPlanes[i].x, kPlaneDragSpeed, -100.0f, 100.0f, "%.2f");
    itemTooltip("a b c d: keeps world points with a*x + b*y + c*z + d >= 0; (a, b, c) is the normal (need not be "
                "unit length), d in world units times its length.");
    ImGui::SameLine();
    if (ImGui::Button("x", ImVec2(ImGui::GetFrameHeight(), 0.0f))) removeIndex = static_cast<int>(i);
    itemTooltip("Remove this plane");
    ImGui::PopID();
  }
  if (removeIndex >= 0) {
    settings.userClipPlanes.erase(settings.userClipPlanes.begin() + removeIndex);
    changed = true;
  }
  // GL's clip distances are shared with a lone near or far plane (scene/settings.h).
  RenderSettings withOneMore = settings;
  withOneMore.userClipPlanes.push_back(kNewUserPlane);
  ImGui::BeginDisabled(!clipSlotProblem(withOneMore).empty());
  if (ImGui::Button("Add plane")) {
    settings.userClipPlanes.push_back(kNewUserPlane);
    changed = true;
  }
  ImGui::EndDisabled();
  if (const std::string problem = clipSlotProblem(settings); !problem.empty()) {
    hintText(("Neither backend draws this: " + problem + ".").c_str());
  }

  sectionTitle("Shading");
  changed |= enumRadio("Pipeline", settings.pipeline, kPipelines, labelWidth,
                       "forward: each fragment lit as it is drawn. deferred: a G-buffer pass writes each pixel's "
                       "surface, then a lighting pass lights every pixel once (docs/deferred.md). The debug views "
                       "draw forward.");
  ImGui::BeginDisabled(settings.pipeline != Pipeline::Deferred && !settings.ssr.enabled);  // reflections draw deferred too
  changed |= enumRadio("G position", settings.gbufferPosition, kGBufferPositions, labelWidth,
                       "Where the deferred lighting pass finds each pixel's world position. stored: a G-buffer "
                       "target holds the position forward lights (deferred matches forward). depth: rebuilt from "
                       "the window depth through the inverse camera matrix, one target less, but the depth's "
                       "rounding moves the point along its ray and a shadow-map texel edge can flip a pixel.");
  ImGui::EndDisabled();
  changed |= enumRadio("Lighting space", settings.lightingSpace, kLightingSpaces, labelWidth,
                       "world: N from the normal map is rotated to world space per pixel. tangent: L and V are "
                       "rotated into tangent space per vertex and interpolated (the tutorial's way).");
  changed |= enumRadio("Tangent transform", settings.tangentTransform, kTangentTransforms, labelWidth,
                       "model: tangents transform with the model matrix (they lie in the surface). "
                       "inverse_transpose: like normals (wrong under non-uniform scale: compare the two).");
  changed |= enumRadio("Texture filter", settings.textureFilter, kTextureFilters, labelWidth,
                       "How every map is sampled (GL's filters): nearest texel or bilinear between the four "
                       "nearest (texel centres at +0.5) on level 0; trilinear blends bilinear samples of the two "
                       "mip levels around the LOD; *_mipmap_nearest picks the nearest level, nearest_mipmap_linear "
                       "blends nearest texels of two levels. The LOD is one per 2x2 pixel quad, "
                       "log2 of the texels one pixel step covers (docs/textures.md).");
  // Beside the filter it shapes: the most samples along a footprint, GL_TEXTURE_MAX_ANISOTROPY.
  const char* const anisotropyHelp =
      "GL_TEXTURE_MAX_ANISOTROPY, 1 to 16 (no unit): the largest ratio of a pixel's footprint in the texture, "
      "longer side over shorter, that the filter follows. 1 is isotropic: the mip level follows the longer side, "
      "so a floor seen at a grazing angle blurs; above 1 the filter may take up to that many samples along the "
      "longer side at a sharper level. How each renderer draws it: docs/textures.md, Anisotropy.";
  ImGui::AlignTextToFramePadding();
  ImGui::TextUnformatted("Anisotropy");
  itemTooltip(anisotropyHelp);
  ImGui::SameLine(labelWidth);
  ImGui::SetNextItemWidth(-FLT_MIN);
  changed |= ImGui::SliderFloat("##anisotropy", &settings.anisotropy, 1.0f, kMaxTextureAnisotropy, "%.1f",
                                ImGuiSliderFlags_Logarithmic | ImGuiSliderFlags_AlwaysClamp);
  itemTooltip(anisotropyHelp);
  probe_.item("anisotropy");

  sectionTitle("Reflections (SSR)");
  SsrSettings& ssr = settings.ssr;
  changed |= ImGui::Checkbox("Screen-space reflections", &ssr.enabled);
  probe_.item("ssr_enabled");
  itemTooltip("After the lighting pass, each pixel whose material has ssr reflect > 0 marches its mirror ray "
              "through the depth buffer and adds the lit colour where it hits (docs/ssr.md). The frame draws "
              "deferred: the march reads the G-buffer.");
  ImGui::BeginDisabled(!ssr.enabled && !isSsrView(settings.view));  // the reflection views march too
  changed |= enumRadio("March", ssr.march, kSsrMarches, labelWidth,
                       "linear_world: fixed world-space steps (the GAMES202 write-up's). adaptive_world: the first "
                       "step is Step, halved at every overshoot down to Step / 16. dda_screen: one pixel per step "
                       "along the ray's line on the screen. hiz: dda_screen's answer, skipping the cells of a "
                       "min-depth mip chain the ray passes wholly in front of.");
  probe_.item("ssr_march");  // its last choice
  if (probe_.enabled()) probe_.state()["ssr_march_disabled"] = !ssr.enabled && !isSsrView(settings.view);
  ImGui::SetNextItemWidth(ImGui::GetContentRegionAvail().x * 0.5f);
  changed |= ImGui::SliderInt("Max steps", &ssr.maxSteps, 1, kMaxSsrSteps, "%d", ImGuiSliderFlags_Logarithmic |
                                                                                      ImGuiSliderFlags_AlwaysClamp);
  itemTooltip("The most steps a ray takes before it counts as a miss (max_steps).");
  ImGui::SetNextItemWidth(ImGui::GetContentRegionAvail().x * 0.5f);
  const bool screenMarch = ssr.march == SsrMarch::DdaScreen || ssr.march == SsrMarch::Hiz;
  ImGui::BeginDisabled(screenMarch);  // one pixel per step
  changed |= ImGui::DragFloat("Step", &ssr.step, kSsrStepDragSpeed, 0.001f, 10.0f, "%.3f", ImGuiSliderFlags_AlwaysClamp);
  ImGui::EndDisabled();
  itemTooltip("World units: linear_world's every step, adaptive_world's first (step). The screen marches step one "
              "pixel at a time.");
  ImGui::SetNextItemWidth(ImGui::GetContentRegionAvail().x * 0.5f);
  changed |= ImGui::DragFloat("Thickness", &ssr.thickness, kSsrStepDragSpeed, 0.001f, 10.0f, "%.3f",
                              ImGuiSliderFlags_AlwaysClamp);
  itemTooltip("World units: how far behind the depth buffer's surface a ray may be and still hit it (thickness): "
              "the world marches test both sides of the crossing, the screen marches the ray's nearer end of the "
              "last step. Below the depth a step covers, rays pass through.");
  ImGui::SetNextItemWidth(ImGui::GetContentRegionAvail().x * 0.5f);
  changed |= ImGui::SliderFloat("Strength", &ssr.reflectStrength, 0.0f, kMaxSsrReflectStrength, "%.2f",
                                ImGuiSliderFlags_AlwaysClamp);
  itemTooltip("Scales every reflection (reflect_strength), times each material's ssr reflect.");
  ImGui::EndDisabled();

  sectionTitle("TBN lines");
  changed |= ImGui::Checkbox("Draw T (red), B (green), N (blue) at every vertex", &settings.tbnLines.enabled);
  itemTooltip("Debug lines from every vertex along its tangent frame, drawn by both backends after shading.");
  ImGui::BeginDisabled(!settings.tbnLines.enabled);
  ImGui::SetNextItemWidth(ImGui::GetContentRegionAvail().x * 0.6f);
  changed |= ImGui::SliderFloat("Length (world units)", &settings.tbnLines.length, kMinLineLength, kMaxLineLength,
                                "%.3f", ImGuiSliderFlags_Logarithmic);
  itemTooltip("Length of each T, B, N line, world units.");
  changed |= enumRadio("GL drawing", settings.tbnLines.mode, kLineModes, labelWidth);
  itemTooltip("core: a VBO and a tiny shader. immediate: glBegin(GL_LINES) as the tutorial does, which needs a "
              "compatibility-profile context: the GL renderer (on its worker thread, in EGL contexts of its own) "
              "makes one; where the driver has none, the GL image shows why.");
  ImGui::EndDisabled();
  hintText("Line pixels are left out of the diff metrics (grey in the diff views).");

  if (changed) doc_.touch();
}

}  // namespace twr::gui

namespace twr::gui {

void GuiApp::drawEnvironmentViewLegend(View view) {
  const float width = ImGui::GetContentRegionAvail().x;
  const float barHeight = ImGui::GetTextLineHeight();
  const ImVec2 corner = ImGui::GetCursorScreenPos();
  ImDrawList* draw = ImGui::GetWindowDrawList();
  const ImU32 labelColour = ImGui::GetColorU32(ImGuiCol_Text);
  if (view == View::EnvFace) {
    // Six swatches, each named: the colours both renderers draw (kCubeFaceViewColours).
    for (int f = 0; f < kCubeFaces; ++f) {
      const float x0 = corner.x + width * static_cast<float>(f) / kCubeFaces;
      const float x1 = corner.x + width * static_cast<float>(f + 1) / kCubeFaces;
      const float* c = kCubeFaceViewColours[f];
      draw->AddRectFilled(ImVec2(x0, corner.y), ImVec2(x1, corner.y + barHeight),
                          ImGui::ColorConvertFloat4ToU32(ImVec4(c[0], c[1], c[2], 1.0f)));
      const float luminance = 0.2126f * c[0] + 0.7152f * c[1] + 0.0722f * c[2];
      draw->AddText(ImVec2(x0 + 3.0f, corner.y), luminance > 0.5f ? IM_COL32(0, 0, 0, 255) : IM_COL32(255, 255, 255, 255),
                    kCubeFaceNames[f]);
    }
    ImGui::Dummy(ImVec2(width, barHeight));
    probe_.item("env_face_legend");
    return;
  }
  // env_lod: the heat ramp from LOD 0 to kEnvironmentLodViewMax, with a tick label per 2 levels.
  for (int i = 0; i < kStepsBarSlices; ++i) {
    const float t = (static_cast<float>(i) + 0.5f) / kStepsBarSlices;
    const vec3 c = parallaxStepsColour(t);
    const float x0 = corner.x + width * static_cast<float>(i) / kStepsBarSlices;
    const float x1 = corner.x + width * static_cast<float>(i + 1) / kStepsBarSlices;
    draw->AddRectFilled(ImVec2(x0, corner.y), ImVec2(x1, corner.y + barHeight),
                        ImGui::ColorConvertFloat4ToU32(ImVec4(c.r, c.g, c.b, 1.0f)));
  }
  draw->AddRect(corner, ImVec2(corner.x + width, corner.y + barHeight), IM_COL32(140, 140, 140, 255));
  ImGui::Dummy(ImVec2(width, barHeight));
  const float labelTop = ImGui::GetCursorScreenPos().y;
  constexpr int kLodTicks = 6;  // LOD 0, 2, ..., 10
  for (int k = 0; k < kLodTicks; ++k) {
    const float fraction = static_cast<float>(k) / (kLodTicks - 1);
    const std::string label = std::to_string(static_cast<int>(fraction * kEnvironmentLodViewMax));
    const float labelWidth = ImGui::CalcTextSize(label.c_str()).x;
    const float x = std::clamp(corner.x + fraction * width - 0.5f * labelWidth, corner.x, corner.x + width - labelWidth);
    draw->AddText(ImVec2(x, labelTop), labelColour, label.c_str());
  }
  ImGui::Dummy(ImVec2(width, ImGui::GetTextLineHeight()));
  probe_.item("env_lod_legend");
}

void GuiApp::drawParallaxStepsLegend() {
  const std::vector<Material>& materials = doc_.scene.materials;
  if (materials.empty()) {
    hintText("No materials: nothing marches layers.");
    return;
  }
  const std::size_t index = std::min(selectedMaterial_, materials.size() - 1);
  const Material& material = materials[index];
  const int most = parallaxStepsMost(material);

  // The ramp, as both renderers draw it (parallaxStepsColour), left 0 to right `most`.
  const float width = ImGui::GetContentRegionAvail().x;
  const float barHeight = ImGui::GetTextLineHeight();
  const ImVec2 corner = ImGui::GetCursorScreenPos();
  ImDrawList* draw = ImGui::GetWindowDrawList();
  for (int i = 0; i < kStepsBarSlices; ++i) {
    const float t = (static_cast<float>(i) + 0.5f) / kStepsBarSlices;
    const vec3 c = parallaxStepsColour(t);
    const float x0 = corner.x + width * static_cast<float>(i) / kStepsBarSlices;
    const float x1 = corner.x + width * static_cast<float>(i + 1) / kStepsBarSlices;
    draw->AddRectFilled(ImVec2(x0, corner.y), ImVec2(x1, corner.y + barHeight),
                        ImGui::ColorConvertFloat4ToU32(ImVec4(c.r, c.g, c.b, 1.0f)));
  }
  draw->AddRect(corner, ImVec2(corner.x + width, corner.y + barHeight), IM_COL32(140, 140, 140, 255));
  ImGui::Dummy(ImVec2(width, barHeight));
  probe_.item("parallax_steps_bar");

  // Step counts under the ticks: the layers (and refinement steps) each colour stands for.
  const float labelTop = ImGui::GetCursorScreenPos().y;
  const ImU32 labelColour = ImGui::GetColorU32(ImGuiCol_Text);
  nlohmann::json ticks = nlohmann::json::array();
  for (int k = 0; k < kStepsBarTicks; ++k) {
    const float fraction = static_cast<float>(k) / (kStepsBarTicks - 1);
    const float steps = fraction * static_cast<float>(most);
    char text[16];
    std::snprintf(text, sizeof text, "%g", static_cast<double>(std::round(steps * 10.0f) / 10.0f));
    ticks.push_back(text);
    const float tickX = corner.x + fraction * width;
    draw->AddLine(ImVec2(tickX, corner.y + barHeight), ImVec2(tickX, labelTop + 2.0f), labelColour);
    const float textWidth = ImGui::CalcTextSize(text).x;
    const float x = std::clamp(tickX - 0.5f * textWidth, corner.x, corner.x + width - textWidth);
    draw->AddText(ImVec2(x, labelTop + 2.0f), labelColour, text);
  }
  ImGui::Dummy(ImVec2(width, ImGui::GetTextLineHeight() + 2.0f));

  std::string caption;
  if (!marchesLayers(material.surfaceDetail)) {
    caption = concat("Steps of '", material.name, "' (selected in the Scene tab): ", toString(material.surfaceDetail),
                     " marches no layers, so its pixels are dark blue (0). steep_parallax, relief and "
                     "parallax_occlusion march; red would be its parallax_layers max, ", material.parallaxLayers.y, '.');
  } else {
    caption = concat("Steps of '", material.name, "' (selected in the Scene tab): ", material.parallaxLayers.x,
                     " layers facing the camera, up to ", material.parallaxLayers.y, " at grazing views");
    if (material.surfaceDetail == SurfaceDetail::Relief) {
      caption += concat(", plus ", material.reliefRefinementSteps, " refinement steps: red = ", most);
    } else {
      caption += concat(": red = ", most);
    }
    caption += '.';
  }
  const auto othersMarch = std::any_of(materials.begin(), materials.end(), [&](const Material& other) {
    return &other != &material && other.heightMap && marchesLayers(other.surfaceDetail);
  });
  if (othersMarch) caption += " Each material is red at its own most; select another to read its counts.";
  hintText(caption.c_str());
  if (probe_.enabled()) {
    probe_.state()["parallax_steps_legend"] = {{"material", index}, {"most", most}, {"ticks", ticks}};
  }
}

}  // namespace twr::gui
