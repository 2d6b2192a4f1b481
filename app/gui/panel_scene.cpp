// The Scene tab: open a file, the node tree with transforms and live mesh parameters,
// materials, lights, ambient and the output size.
#include "app/gui/app.h"
#include "gui/material_maps.h"
#include "gui/scene_help.h"
#include "gui/scene_picker.h"
#include "gui/text_concat.h"
#include "app/gui/ui_widgets.h"

#include "compare/capture_faces.h"
#include "compare/cube_cross.h"
#include "compare/pass_buffers.h"
#include "scene/environment_light.h"
#include "scene/environment_specular.h"
#include "scene/errors.h"
#include "scene/primitives.h"
#include "scene/scene_file.h"

#include <imgui_stdlib.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <string>

namespace twr::gui {
namespace {

// Drag speeds, units per pixel of mouse travel.
constexpr float kTranslateDragSpeed = 0.01f;  // world units
constexpr float kRotateDragSpeed = 0.5f;      // degrees
constexpr float kScaleDragSpeed = 0.005f;
constexpr float kSizeDragSpeed = 0.005f;      // world units
constexpr float kAttenuationDragSpeed = 0.001f;
// The shadow bias per dragged point: world units (constant), texels (slope); both fields stop
// at kMaxShadowBiasDrag (Ctrl+click types any value >= 0).
constexpr float kShadowBiasDragSpeed = 0.001f;
constexpr float kShadowSlopeDragSpeed = 0.01f;
constexpr float kMaxShadowBiasDrag = 10.0f;
// A directional light's direction components per dragged point (unitless; renormalised after).
constexpr float kDirectionDragSpeed = 0.005f;
// Largest magnitude the transform and size fields accept (inclusive), world units or degrees.
constexpr float kMaxCoordinate = 1000.0f;
constexpr float kMaxShininess = 512.0f;
// Largest output side the Scene tab offers, pixels (inclusive; the renderers go further).
constexpr int kMaxOutputSide = 4096;
// Segment sliders stop here (inclusive); Ctrl+click types any count, and buildMesh says
// when one is out of its range [minimum, kMaxSegments].
constexpr int kSegmentSliderMax = 256;
// Fewest segments buildMesh accepts (inclusive): sphere stacks, and every round count.
constexpr int kMinStacks = 2;
constexpr int kMinRoundSegments = 3;
// Smallest primitive dimension the fields allow, world units (exclusive bound in buildMesh: > 0).
constexpr float kMinDimension = 0.001f;

// A light's shadow map (scene/shadow_map.h): on or off, the map's side, the bias and the PCF
// kernel. A point light's cube map is at most kMaxCubeShadowMapSize; at most
// kMaxShadowedLights lights cast shadows. True when something changed.
bool editShadow(Light& light, const std::vector<Light>& lights) {
  const bool cube = light.type == LightType::Point && !isSpotLight(light);
  const int maxSize = cube ? kMaxCubeShadowMapSize : kMaxShadowMapSize;
  if (light.shadow && light.shadow->size > maxSize) light.shadow->size = maxSize;  // switched to a point light
  const auto others = std::count_if(lights.begin(), lights.end(),
                                    [&](const Light& l) { return &l != &light && l.shadow.has_value(); });
  bool changed = false;
  bool on = light.shadow.has_value();
  ImGui::BeginDisabled(!on && others >= kMaxShadowedLights);
  if (ImGui::Checkbox("shadow map", &on)) {
    if (on) {
      light.shadow = ShadowDesc{};
      if (cube) light.shadow->size = kDefaultCubeShadowMapSize;
    } else {
      light.shadow.reset();
    }
    changed = true;
  }
  ImGui::EndDisabled();
  itemTooltip("A shadow map (shadow): a depth pass from the light before the frame, on both renderers; an "
              "orthographic map for a directional light, a cube of six for a point light, one perspective map "
              "over a spot light's cone (docs/shadows.md). At most 4 lights.");
  if (!light.shadow) return changed;
  ShadowDesc& shadow = *light.shadow;
  const std::string label = std::to_string(shadow.size) + (cube ? " x 6" : "");
  ImGui::SetNextItemWidth(ImGui::GetContentRegionAvail().x * 0.4f);
  if (ImGui::BeginCombo("Map size", label.c_str())) {
    for (int size = 256; size <= maxSize; size *= 2) {
      if (ImGui::Selectable(std::to_string(size).c_str(), size == shadow.size)) {
        shadow.size = size;
        changed = true;
      }
    }
    ImGui::EndCombo();
  }
  itemTooltip("Texels per side of the map (each cube face). Smaller maps show blockier shadow edges.");
  ImGui::SetNextItemWidth(ImGui::GetContentRegionAvail().x * 0.4f);
  changed |= ImGui::DragFloat("Bias constant", &shadow.bias.x, kShadowBiasDragSpeed, 0.0f, kMaxShadowBiasDrag, "%.4f",
                              ImGuiSliderFlags_AlwaysClamp);
  itemTooltip("World units along the light the surface is moved towards it before the test (bias[0]). Too "
              "little shows acne (the surface shadows itself: the shadow view paints it magenta), too much "
              "peter-panning (shadows come loose from their casters).");
  ImGui::SetNextItemWidth(ImGui::GetContentRegionAvail().x * 0.4f);
  changed |= ImGui::DragFloat("Bias slope", &shadow.bias.y, kShadowSlopeDragSpeed, 0.0f, kMaxShadowBiasDrag, "%.2f",
                              ImGuiSliderFlags_AlwaysClamp);
  itemTooltip("Texels of the surface's own rise across the kernel (bias[1]): tan(angle to the light) * one texel's "
              "width * (1 + pcf / 2), added to the constant. 1 covers a surface sloping away from the light at any "
              "map size and kernel (docs/shadows.md).");
  int pcf = shadow.pcf;
  ImGui::TextUnformatted("PCF");
  for (const int side : {1, 3, 5}) {
    ImGui::SameLine();
    if (ImGui::RadioButton((std::to_string(side) + "x" + std::to_string(side)).c_str(), pcf == side)) {
      shadow.pcf = side;
      changed = true;
    }
  }
  return changed;
}

// A point light's spot cone (scene.h's SpotCone): on or off, its axis and half-angles. True
// when something changed.
constexpr float kSpotAngleDragSpeed = 0.2f;  // degrees
bool editSpot(Light& light) {
  bool changed = false;
  bool on = light.spot.has_value();
  if (ImGui::Checkbox("spot", &on)) {
    if (on) {
      light.spot = SpotCone{};
    } else {
      light.spot.reset();
    }
    changed = true;
  }
  itemTooltip("A spot cone (spot): the light shines only within the outer half-angle of its axis, fully "
              "within the inner one, smoothstep between; a shadowed spot light gets one perspective map "
              "over its cone instead of a cube (docs/shadows.md).");
  if (!light.spot) return changed;
  SpotCone& spot = *light.spot;
  ImGui::SetNextItemWidth(ImGui::GetContentRegionAvail().x * 0.6f);
  vec3 axis = spot.directionWorld;
  if (ImGui::DragFloat3("Spot axis", &axis.x, kDirectionDragSpeed, -1.0f, 1.0f, "%.3f")) {
    // Kept unit length, as the scene file leaves it; a zero vector keeps the last one.
    if (glm::length(axis) > 0.0f) spot.directionWorld = glm::normalize(axis);
    changed = true;
  }
  itemTooltip("The cone's axis, the way the light shines, world space (spot.direction; kept unit length).");
  ImGui::SetNextItemWidth(ImGui::GetContentRegionAvail().x * 0.4f);
  if (ImGui::DragFloat("Outer deg", &spot.outerDeg, kSpotAngleDragSpeed, 0.1f, kMaxSpotOuterDeg - 0.1f, "%.1f",
                       ImGuiSliderFlags_AlwaysClamp)) {
    spot.innerDeg = std::min(spot.innerDeg, spot.outerDeg);
    changed = true;
  }
  itemTooltip("Half-angle beyond which the light gives nothing (spot.outer_deg, below 89).");
  ImGui::SetNextItemWidth(ImGui::GetContentRegionAvail().x * 0.4f);
  changed |= ImGui::DragFloat("Inner deg", &spot.innerDeg, kSpotAngleDragSpeed, 0.0f, spot.outerDeg, "%.1f",
                              ImGuiSliderFlags_AlwaysClamp);
  itemTooltip("Half-angle within which the light is at full strength (spot.inner_deg, at most outer_deg).");
  return changed;
}

// Colours as the scene file writes them (floats; light colours may exceed 1).
constexpr ImGuiColorEditFlags kColourFlags = ImGuiColorEditFlags_Float | ImGuiColorEditFlags_HDR;

constexpr TextureWrap kWrapModes[] = {TextureWrap::Repeat, TextureWrap::MirroredRepeat, TextureWrap::ClampToEdge};
constexpr GreenAxis kGreenAxes[] = {GreenAxis::Up, GreenAxis::Down};
// Names of the maps in the test probe's widget keys, in kMapSlots order.
const char* const kMapKeys[] = {"diffuse", "normal", "specular", "height"};
constexpr SelfShadow kSelfShadows[] = {SelfShadow::None, SelfShadow::HeightMarch, SelfShadow::HorizonMap};
// The height_scale slider's range, texture-space units (Ctrl+click types up to kMaxHeightScale):
// real reliefs are a few hundredths of a uv unit deep.
constexpr float kHeightScaleSliderMax = 0.2f;
// Environment controls (docs/environment.md): the intensity slider's top (the scene file allows
// more), the ratio a material starts refracting with (glass from air), the slider's bottom.
constexpr float kEnvironmentIntensitySliderMax = 4.0f;
// The capture size combo's range, texels per face (the scene file allows 1..1024).
constexpr int kMinCaptureSizeInGui = 16;
constexpr int kMaxCaptureSizeInGui = 512;
constexpr float kDefaultRefractionIndex = 0.66f;
constexpr float kMinRefractionIndexSlider = 0.2f;
constexpr EnvironmentSpecular kEnvironmentSpeculars[] = {EnvironmentSpecular::None, EnvironmentSpecular::Mirror,
                                                         EnvironmentSpecular::Prefiltered};
constexpr EnvironmentDiffuse kEnvironmentDiffuses[] = {EnvironmentDiffuse::None, EnvironmentDiffuse::IrradianceMap,
                                                       EnvironmentDiffuse::Sh9};
constexpr Fresnel kFresnels[] = {Fresnel::None, Fresnel::Schlick};

bool segmentsField(const char* label, int& value, int minimum) {
  ImGui::SetNextItemWidth(ImGui::GetContentRegionAvail().x * 0.6f);
  const bool changed = ImGui::SliderInt(label, &value, minimum, kSegmentSliderMax);
  itemTooltip("Subdivisions of the primitive, a count; more follow the round shape more closely. Ctrl+click to "
              "type more than the slider offers.");
  return changed;
}

bool dimensionField(const char* label, float& value) {
  ImGui::SetNextItemWidth(ImGui::GetContentRegionAvail().x * 0.6f);
  const bool changed = ImGui::DragFloat(label, &value, kSizeDragSpeed, kMinDimension, kMaxCoordinate, "%.3f",
                                        ImGuiSliderFlags_AlwaysClamp);
  itemTooltip("World units (uv scale: texture repeats across the plane, no unit), before the node's scale.");
  return changed;
}

}  // namespace

void GuiApp::drawSceneTab() {
  sectionTitle("Scene file");
  const float openWidth = ImGui::CalcTextSize("Open").x + 2.0f * ImGui::GetStyle().FramePadding.x;
  ImGui::SetNextItemWidth(ImGui::GetContentRegionAvail().x - openWidth - ImGui::GetStyle().ItemSpacing.x);
  const bool entered = ImGui::InputTextWithHint("##scenePath", "path/to/scene.json", &scenePathInput_,
                                                ImGuiInputTextFlags_EnterReturnsTrue);
  probe_.item("scene_path");
  ImGui::SameLine();
  if (ImGui::Button("Open") || entered) openScene(scenePathInput_);
  // Pick instead of typing: the scenes shipped in assets/scenes/, then the recent files.
  ImGui::SetNextItemWidth(-FLT_MIN);
  if (ImGui::BeginCombo("##scenePicker", "Pick a scene: assets/scenes/ or a recent file")) {
    std::string picked;
    const std::string defaultScene = findStartupScene("");
    const std::filesystem::path folder =
        defaultScene.empty() ? std::filesystem::path("assets/scenes") : std::filesystem::path(defaultScene).parent_path();
    disabledTextWrapped("%s", folder.string().c_str());
    for (const std::filesystem::path& file : sceneFilesIn(folder)) {
      if (ImGui::Selectable(file.filename().string().c_str(), file.string() == doc_.scene.sourcePath)) picked = file.string();
    }
    if (!prefs_.recentScenes.empty()) {
      ImGui::Separator();
      ImGui::TextDisabled("recent");
      for (std::size_t i = 0; i < prefs_.recentScenes.size(); ++i) {
        ImGui::PushID(static_cast<int>(i));
        if (ImGui::Selectable(prefs_.recentScenes[i].c_str())) picked = prefs_.recentScenes[i];
        ImGui::PopID();
      }
    }
    ImGui::EndCombo();
    if (!picked.empty()) {
      scenePathInput_ = picked;
      openScene(picked);
    }
  }
  itemTooltip("The scene files in assets/scenes/ (each a lesson: docs/scene-format.md) and the last files opened.");
  if (!doc_.scene.sourcePath.empty()) {
    disabledTextWrapped("%s", doc_.scene.sourcePath.c_str());
    ImGui::SameLine();
    if (ImGui::SmallButton("Reload")) openScene(doc_.scene.sourcePath);
    itemTooltip("Read the file again, dropping every edit made here.");
  }
  if (!sceneError_.empty()) errorText(sceneError_);

  bool changed = false;
  sectionTitle("Output");
  int size[2] = {doc_.scene.output.width, doc_.scene.output.height};
  ImGui::SetNextItemWidth(ImGui::GetContentRegionAvail().x * 0.6f);
  if (ImGui::DragInt2("Size (pixels)", size, 1.0f, 1, kMaxOutputSide, "%d", ImGuiSliderFlags_AlwaysClamp)) {
    doc_.scene.output.width = size[0];
    doc_.scene.output.height = size[1];
    changed = true;
  }
  itemTooltip("The render size when the view's resolution is 'scene output' (times the scale).");
  changed |= ImGui::ColorEdit4("Background", &doc_.scene.output.background.x,
                                ImGuiColorEditFlags_Float | ImGuiColorEditFlags_AlphaBar);
  itemTooltip("Linear RGB and alpha, each in [0, 1], where no triangle is drawn. Alpha 1 (default) saves opaque "
              "PNGs, 0 transparent ones; coverage (Checker bg, the diff) comes from the triangle ids, not alpha.");
  changed |= ImGui::ColorEdit3("Ambient Ia", &doc_.scene.ambient.x, kColourFlags);
  itemTooltip("Ambient light intensity, linear RGB (may exceed 1): adds ka * albedo * Ia to every lit pixel.");
  if (doc_.scene.environment) {
    Environment& env = *doc_.scene.environment;
    if (env.capture) {
      changed |= drawEnvironmentCaptureControls(env);
    } else {
      disabledTextWrapped("environment: %s, %dx%d per face, %d levels",
                          env.equirectPath.empty() ? "six cube faces" : "an equirect made into a cube",
                          env.cube ? env.cube->size() : 0, env.cube ? env.cube->size() : 0,
                          env.cube ? env.cube->levelCount() : 0);
    }
    ImGui::SetNextItemWidth(ImGui::GetContentRegionAvail().x * 0.6f);
    changed |= ImGui::SliderFloat("environment intensity", &env.intensity, 0.0f, kEnvironmentIntensitySliderMax, "%.2f",
                                  ImGuiSliderFlags_AlwaysClamp);
    itemTooltip("Scales every environment read: the sky box, reflections and refractions (intensity).");
    probe_.item("environment_intensity");
    changed |= ImGui::Checkbox("sky box", &env.background);
    itemTooltip("Draw the environment where no triangle is, in the shaded view (background).");
    probe_.item("environment_background");
    ImGui::SetNextItemWidth(ImGui::GetContentRegionAvail().x * 0.6f);
    if (ImGui::BeginCombo("parameterization", std::string(toString(env.parameterization)).c_str())) {
      for (const EnvironmentParameterization kind : {EnvironmentParameterization::Cube, EnvironmentParameterization::Sphere,
                                                     EnvironmentParameterization::DualParaboloid}) {
        const bool chosen = kind == env.parameterization;
        const bool picked = ImGui::Selectable(std::string(toString(kind)).c_str(), chosen) && !chosen;
        if (picked && env.capture) {
          // A captured cube is built by each renderer per frame, its map with it.
          env.parameterization = kind;
          if (kind != EnvironmentParameterization::Cube && !env.sizeGiven) {
            env.size = std::clamp(2 * env.capture->size, kDefaultEnvironmentSize, kMaxCubeFaceSize);
          }
          changed = true;
        } else if (picked && env.cube) {
          // Built here from the cube, as the scene file builds it (a 1024-texel map takes
          // well under a second).
          env.parameterization = kind;
          if (kind == EnvironmentParameterization::Cube) {
            env.layers = nullptr;
          } else {
            const int size = env.sizeGiven ? env.size : std::clamp(2 * env.cube->size(), kDefaultEnvironmentSize, kMaxCubeFaceSize);
            env.layers = std::make_shared<const ParameterizedMap>(parameterizedMapFromCube(*env.cube, kind, size));
          }
          prefilterEnvironmentLight(doc_.scene);  // the irradiance map follows the parameterization
          changed = true;
        }
        probe_.item(concat("environment_parameterization_", toString(kind)).c_str());
        if (chosen) ImGui::SetItemDefaultFocus();
      }
      ImGui::EndCombo();
    }
    itemTooltip("How both renderers read the environment: the cube, or a sphere or dual-paraboloid map built from it "
                "(parameterization). Turn the camera to watch where each one distorts: the sphere map's rim is -Z, "
                "the paraboloid's seam the z = 0 circle.");
    probe_.item("environment_parameterization");
    if (env.layers) {
      disabledTextWrapped("read from a %s map: %d x %dx%d, %d levels", std::string(toString(env.parameterization)).c_str(),
                          env.layers->layers, env.layers->size(), env.layers->size(), env.layers->levelCount());
    }
    drawEnvironmentSourceImages(env);
  }

  sectionTitle("Nodes");
  if (doc_.scene.nodes.empty()) hintText("No nodes.");
  for (std::size_t i = 0; i < doc_.scene.nodes.size(); ++i) {
    ImGui::PushID(static_cast<int>(i));
    drawNode(doc_.scene.nodes[i]);
    ImGui::PopID();
  }

  drawMaterialsSection();
  drawLightsSection();
  if (changed) doc_.touch();
}

void GuiApp::drawNode(Node& node) {
  const std::string label = (node.name.empty() ? std::string("(unnamed)") : node.name) + "###node";
  if (!ImGui::TreeNode(label.c_str())) return;
  bool changed = false;
  ImGui::SetNextItemWidth(ImGui::GetContentRegionAvail().x * 0.6f);
  changed |= ImGui::DragFloat3("Translate", &node.translate.x, kTranslateDragSpeed, -kMaxCoordinate, kMaxCoordinate,
                               "%.3f");
  itemTooltip("Offset from the parent node, world units.");
  ImGui::SetNextItemWidth(ImGui::GetContentRegionAvail().x * 0.6f);
  changed |= ImGui::DragFloat3("Rotate (deg)", &node.rotateDeg.x, kRotateDragSpeed, -720.0f, 720.0f, "%.1f");
  itemTooltip("Degrees about the node's X, then Y, then Z axis (right-handed).");
  ImGui::SetNextItemWidth(ImGui::GetContentRegionAvail().x * 0.6f);
  changed |= ImGui::DragFloat3("Scale", &node.scale.x, kScaleDragSpeed, -kMaxCoordinate, kMaxCoordinate, "%.3f");
  itemTooltip("Scale factor per axis, no unit. A negative scale mirrors: the bitangent sign flips (see the "
              "tangent_transform setting).");

  const auto& materials = doc_.scene.materials;
  const std::string current = node.materialIndex >= 0 && node.materialIndex < static_cast<int>(materials.size())
                                  ? materials[static_cast<std::size_t>(node.materialIndex)].name
                                  : std::string("(default white)");
  ImGui::SetNextItemWidth(ImGui::GetContentRegionAvail().x * 0.6f);
  if (ImGui::BeginCombo("Material", current.c_str())) {
    if (ImGui::Selectable("(default white)", node.materialIndex < 0)) {
      node.materialIndex = -1;
      changed = true;
    }
    for (std::size_t m = 0; m < materials.size(); ++m) {
      ImGui::PushID(static_cast<int>(m));
      if (ImGui::Selectable(materials[m].name.c_str(), node.materialIndex == static_cast<int>(m))) {
        node.materialIndex = static_cast<int>(m);
        changed = true;
      }
      ImGui::PopID();
    }
    ImGui::EndCombo();
  }
  if (changed) doc_.touch();
  if (node.meshIndex >= 0 && node.meshIndex < static_cast<int>(doc_.scene.meshes.size())) drawMeshEditor(node.meshIndex);
  for (std::size_t i = 0; i < node.children.size(); ++i) {
    ImGui::PushID(static_cast<int>(i));
    drawNode(node.children[i]);
    ImGui::PopID();
  }
  ImGui::TreePop();
}

void GuiApp::drawMeshEditor(int meshIndex) {
  const std::size_t index = static_cast<std::size_t>(meshIndex);
  MeshDesc& desc = doc_.scene.meshDescs[index];
  const MeshDesc before = desc;
  const int users = countNodesUsingMesh(doc_.scene.nodes, meshIndex);
  disabledTextWrapped("mesh %d: %s, %zu triangles%s", meshIndex, std::string(toString(desc.type)).c_str(),
                      doc_.scene.meshes[index].triangleCount(), users > 1 ? " (shared: edits change every user)" : "");
  bool edited = false;
  switch (desc.type) {
    case MeshType::Cube:
      edited |= dimensionField("Size", desc.size);
      break;
    case MeshType::Sphere:
      edited |= dimensionField("Radius", desc.radius);
      edited |= segmentsField("Stacks", desc.stacks, kMinStacks);
      edited |= segmentsField("Slices", desc.slices, kMinRoundSegments);
      break;
    case MeshType::Plane:
      ImGui::SetNextItemWidth(ImGui::GetContentRegionAvail().x * 0.6f);
      edited |= ImGui::DragFloat2("Size", &desc.planeSize.x, kSizeDragSpeed, kMinDimension, kMaxCoordinate, "%.3f",
                                  ImGuiSliderFlags_AlwaysClamp);
      edited |= dimensionField("uv scale", desc.uvScale);
      break;
    case MeshType::Cylinder:
      edited |= dimensionField("Radius", desc.radius);
      edited |= dimensionField("Height", desc.height);
      edited |= segmentsField("Slices", desc.slices, kMinRoundSegments);
      break;
    case MeshType::Torus:
      edited |= dimensionField("Major radius", desc.major);
      edited |= dimensionField("Minor radius", desc.minor);
      edited |= segmentsField("Rings", desc.rings, kMinRoundSegments);
      edited |= segmentsField("Sides", desc.sides, kMinRoundSegments);
      break;
    case MeshType::Obj:
      disabledTextWrapped("%s", desc.path.c_str());
      break;
    case MeshType::Triangles:
      ImGui::TextDisabled("%zu positions from the scene file", desc.positions.size());
      break;
    case MeshType::Heightfield: {
      // Up to millions of triangles (one vertex per texel): built again when an edit ends, not
      // on every frame of a drag.
      const auto finished = [] { return ImGui::IsItemDeactivatedAfterEdit(); };
      ImGui::SetNextItemWidth(ImGui::GetContentRegionAvail().x * 0.6f);
      ImGui::DragFloat2("Size", &desc.planeSize.x, kSizeDragSpeed, kMinDimension, kMaxCoordinate, "%.3f",
                        ImGuiSliderFlags_AlwaysClamp);
      edited |= finished();
      ImGui::SetNextItemWidth(ImGui::GetContentRegionAvail().x * 0.6f);
      ImGui::DragFloat("uv scale", &desc.uvScale, kSizeDragSpeed, kMinDimension, kMaxCoordinate, "%.3f",
                       ImGuiSliderFlags_AlwaysClamp);
      itemTooltip("How often the height map repeats across the surface, no unit.");
      edited |= finished();
      ImGui::SetNextItemWidth(ImGui::GetContentRegionAvail().x * 0.6f);
      ImGui::SliderFloat("Height scale", &desc.heightScale, 0.0f, kHeightScaleSliderMax, "%.3f");
      desc.heightScale = std::clamp(desc.heightScale, 0.0f, kMaxHeightScale);
      itemTooltip("The mesh's own relief depth, texture-space units (as a material's height_scale; Ctrl+click "
                  "types up to 1): the true displaced surface parallax mapping is measured against. The mesh is "
                  "built again when the edit ends.");
      edited |= finished();
      ImGui::SetNextItemWidth(ImGui::GetContentRegionAvail().x * 0.6f);
      ImGui::DragInt2("Grid", &desc.gridSegments.x, 1.0f, 0, kMaxSegments, "%d", ImGuiSliderFlags_AlwaysClamp);
      itemTooltip("Quads along x (u) and z (v); 0 0: one vertex per height-map texel. Built again when the edit ends.");
      edited |= finished();
      if (desc.gridSegments != ivec2(0)) desc.gridSegments = glm::max(desc.gridSegments, ivec2(1));
      break;
    }
  }
  if (edited) {
    try {
      doc_.scene.meshes[index] = buildMesh(desc);
      if (meshErrorIndex_ == meshIndex) meshError_.clear();
      doc_.touch();
    } catch (const InputError& e) {
      // Keep the last mesh that built; say why this one did not.
      desc = before;
      meshError_ = e.what();
      meshErrorIndex_ = meshIndex;
    }
  }
  if (meshErrorIndex_ == meshIndex && !meshError_.empty()) errorText(meshError_);
}

void GuiApp::drawMaterialsSection() {
  sectionTitle("Materials");
  if (doc_.scene.materials.empty()) hintText("No materials: nodes use the default white one.");
  bool changed = false;
  for (std::size_t m = 0; m < doc_.scene.materials.size(); ++m) {
    Material& material = doc_.scene.materials[m];
    ImGui::PushID(static_cast<int>(m));
    const ImGuiTreeNodeFlags selected = selectedMaterial_ == m ? ImGuiTreeNodeFlags_Selected : 0;
    const bool open = ImGui::TreeNodeEx("##material", selected, "%s", material.name.c_str());
    if (ImGui::IsItemClicked() || ImGui::IsItemToggledOpen()) selectedMaterial_ = m;
    itemTooltip("Open to edit the material. The highlighted one is the material the parallax_steps legend "
                "(Rendering tab) counts layers for.");
    probe_.item(concat("material", m).c_str());
    if (open) {
      changed |= ImGui::ColorEdit3("ka", &material.ka.x, kColourFlags);
      itemTooltip("Ambient reflectance (times the diffuse map).");
      changed |= ImGui::ColorEdit3("kd", &material.kd.x, kColourFlags);
      itemTooltip("Diffuse reflectance (times the diffuse map).");
      changed |= ImGui::ColorEdit3("ks", &material.ks.x, kColourFlags);
      itemTooltip("Specular reflectance (times the specular map).");
      ImGui::SetNextItemWidth(ImGui::GetContentRegionAvail().x * 0.6f);
      changed |= ImGui::SliderFloat("Shininess", &material.shininess, 0.0f, kMaxShininess, "%.1f",
                                    ImGuiSliderFlags_Logarithmic | ImGuiSliderFlags_AlwaysClamp);
      itemTooltip("Phong exponent n in (R.V)^n, no unit: larger is a smaller, sharper highlight.");
      for (const MapSlot slot : kMapSlots) drawMapControls(m, slot);
      drawHeightFieldControls(m);
      changed |= drawEnvironmentControls(m);
      ImGui::TreePop();
    }
    ImGui::PopID();
  }
  if (changed) doc_.touch();
}

// The height-field keys of a material (issue 16): how the height map is drawn and each method's
// knobs, greyed where the method does not read them. Applying an edit, and knowing when the horizon
// map must be built again, is material_maps.h's job.
void GuiApp::drawHeightFieldControls(std::size_t index) {
  const Material& material = doc_.scene.materials[index];
  const std::string key = concat("material", index, '_');
  const bool hasHeightMap = loadedMap(doc_, index, MapSlot::Height) != nullptr || material.heightMap != nullptr;
  HeightFieldSettings s = heightFieldOf(material);
  bool edited = false;
  const float fieldWidth = ImGui::GetContentRegionAvail().x * 0.6f;

  ImGui::PushID("height_field");
  ImGui::TextDisabled("height field");
  ImGui::Indent();
  if (!hasHeightMap) {
    hintText("No height map: bump, parallax and self-shadowing need \"height_map\" in the scene file.");
  } else if (!material.heightMap) {
    hintText("Height map off: drawn as normal_map until it is on again.");
  }

  ImGui::SetNextItemWidth(fieldWidth);
  const std::string current(toString(s.surfaceDetail));
  if (ImGui::BeginCombo("surface detail", current.c_str())) {
    for (const SurfaceDetail method : kAllSurfaceDetails) {
      const bool unavailable = readsHeightMap(method) && !hasHeightMap;
      const bool chosen = method == s.surfaceDetail;
      ImGui::BeginDisabled(unavailable);
      if (ImGui::Selectable(std::string(toString(method)).c_str(), chosen) && !chosen) {
        s.surfaceDetail = method;
        edited = true;
      }
      ImGui::EndDisabled();
      itemTooltip(unavailable ? concat(surfaceDetailHelp(method),
                                       "\n\nUnavailable: it reads a height map, and this material has none.")
                                    .c_str()
                              : surfaceDetailHelp(method));
      probe_.item(concat(key, "surface_detail_", toString(method)).c_str());
      if (chosen) ImGui::SetItemDefaultFocus();
    }
    ImGui::EndCombo();
  }
  itemTooltip(concat("How the surface detail is drawn (surface_detail).\n\n", surfaceDetailHelp(s.surfaceDetail)).c_str());
  probe_.item(concat(key, "surface_detail").c_str());

  const bool heightField = hasHeightMap && readsHeightMap(s.surfaceDetail);
  ImGui::BeginDisabled(!hasHeightMap);
  ImGui::SetNextItemWidth(fieldWidth);
  // No AlwaysClamp: Ctrl+click may type a depth beyond the slider, up to kMaxHeightScale
  // (clampHeightField). Every frame of a drag redraws; the horizon map waits for the release.
  if (ImGui::SliderFloat("height scale", &s.heightScale, 0.0f, kHeightScaleSliderMax, "%.3f")) edited = true;
  itemTooltip("Depth of the relief in texture-space units (height_scale): 1 = one uv unit along the surface; "
              "height 0 lies this far below the polygon. Ctrl+click to type a value up to 1. Bump methods scale "
              "their slopes by it, parallax methods their shift.");
  probe_.item(concat(key, "height_scale").c_str());

  ImGui::BeginDisabled(!readsParallaxLayers(s));
  ImGui::SetNextItemWidth(fieldWidth);
  if (ImGui::DragIntRange2("parallax layers", &s.parallaxLayers.x, &s.parallaxLayers.y, 0.25f, 1, kMaxParallaxLayers,
                           "min %d", "max %d", ImGuiSliderFlags_AlwaysClamp)) {
    edited = true;
  }
  itemTooltip("Layers the march takes (parallax_layers [min, max], each in [1, 256], min <= max): min when the "
              "view (or the light, for height_march) is straight on, up to max at grazing angles. More layers, "
              "fewer steps visible, more texture reads. Read by steep_parallax, relief, parallax_occlusion and "
              "the height_march self-shadow. Ctrl+click to type.");
  probe_.item(concat(key, "parallax_layers").c_str());
  ImGui::EndDisabled();

  ImGui::BeginDisabled(s.surfaceDetail != SurfaceDetail::Relief);
  ImGui::SetNextItemWidth(fieldWidth);
  if (ImGui::SliderInt("refinement steps", &s.reliefRefinementSteps, 0, kMaxReliefRefinementSteps, "%d",
                       ImGuiSliderFlags_AlwaysClamp)) {
    edited = true;
  }
  itemTooltip("relief only (relief_refinement_steps, 0 to 16): halvings of the binary search after the march; "
              "each halves the error of the hit and costs one more read.");
  probe_.item(concat(key, "relief_refinement_steps").c_str());
  ImGui::EndDisabled();

  ImGui::BeginDisabled(!heightField);
  ImGui::SetNextItemWidth(fieldWidth);
  const std::string shadowName(toString(s.selfShadow));
  if (ImGui::BeginCombo("self shadow", shadowName.c_str())) {
    for (const SelfShadow shadow : kSelfShadows) {
      const bool chosen = shadow == s.selfShadow;
      if (ImGui::Selectable(std::string(toString(shadow)).c_str(), chosen) && !chosen) {
        s.selfShadow = shadow;
        edited = true;
      }
      itemTooltip(selfShadowHelp(shadow));
      probe_.item(concat(key, "self_shadow_", toString(shadow)).c_str());
      if (chosen) ImGui::SetItemDefaultFocus();
    }
    ImGui::EndCombo();
  }
  itemTooltip(heightField ? concat("Whether the height field shadows itself (self_shadow).\n\n",
                                   selfShadowHelp(s.selfShadow)).c_str()
                          : "Self-shadowing needs a height map and a height-field method (not normal_map).");
  probe_.item(concat(key, "self_shadow").c_str());
  ImGui::EndDisabled();

  ImGui::BeginDisabled(!heightField || s.selfShadow != SelfShadow::HorizonMap);
  ImGui::AlignTextToFramePadding();
  ImGui::TextUnformatted("horizon directions");
  const char* directionsHelp =
      "horizon_map only (horizon_directions): azimuths the horizon map stores, 4 per RGBA texture; more follow a "
      "light circling the surface more smoothly, each 4 cost a texture read per light and a longer build.";
  itemTooltip(directionsHelp);
  for (const int directions : kHorizonDirectionChoices) {
    ImGui::SameLine();
    if (ImGui::RadioButton(std::to_string(directions).c_str(), s.horizonDirections == directions) &&
        s.horizonDirections != directions) {
      s.horizonDirections = directions;
      edited = true;
    }
    itemTooltip(directionsHelp);
    probe_.item(concat(key, "horizon_directions_", directions).c_str());
  }
  ImGui::EndDisabled();
  ImGui::EndDisabled();  // !hasHeightMap

  if (edited) {
    selectedMaterial_ = index;
    try {
      setHeightField(doc_, index, s);
      heightFieldErrors_.erase(index);
    } catch (const std::exception& e) {
      heightFieldErrors_[index] = e.what();
    }
  }
  if (const auto error = heightFieldErrors_.find(index); error != heightFieldErrors_.end()) errorText(error->second);
  if (horizonMapStale(doc_, index) || (horizonBuilding_ && horizonBuilding_->material == index)) {
    warningText(horizonStatus());
  }
  ImGui::Unindent();
  ImGui::PopID();
}

// A captured environment (scene/environment_capture.h): the node it is captured from and the
// faces' size. Returns whether one changed.
bool GuiApp::drawEnvironmentCaptureControls(Environment& env) {
  bool changed = false;
  EnvironmentCapture& capture = *env.capture;
  disabledTextWrapped("environment: captured from \"%s\", %dx%d per face, by each renderer every frame",
                      capture.node.c_str(), capture.size, capture.size);
  std::vector<std::string> names;
  const std::function<void(const Node&)> collect = [&](const Node& node) {
    names.push_back(node.name);
    for (const Node& child : node.children) collect(child);
  };
  for (const Node& node : doc_.scene.nodes) collect(node);
  ImGui::SetNextItemWidth(ImGui::GetContentRegionAvail().x * 0.6f);
  if (ImGui::BeginCombo("capture node", capture.node.c_str())) {
    for (std::size_t i = 0; i < names.size(); ++i) {
      ImGui::PushID(static_cast<int>(i));
      const bool chosen = names[i] == capture.node;
      if (ImGui::Selectable(names[i].c_str(), chosen) && !chosen) {
        capture.node = names[i];
        changed = true;
      }
      ImGui::PopID();
    }
    ImGui::EndCombo();
  }
  itemTooltip("The node the cube map is rendered from: six 90-degree views from the middle of its mesh, the node "
              "itself hidden (capture.node).");
  probe_.item("environment_capture_node");
  ImGui::SetNextItemWidth(ImGui::GetContentRegionAvail().x * 0.6f);
  const std::string sizeLabel = std::to_string(capture.size);
  if (ImGui::BeginCombo("capture size", sizeLabel.c_str())) {
    for (int size = kMinCaptureSizeInGui; size <= kMaxCaptureSizeInGui; size *= 2) {
      const bool chosen = size == capture.size;
      if (ImGui::Selectable(std::to_string(size).c_str(), chosen) && !chosen) {
        capture.size = size;
        // A built map's default side follows the cube's, as the scene file sets it at load.
        if (env.parameterization != EnvironmentParameterization::Cube && !env.sizeGiven) {
          env.size = std::clamp(2 * size, kDefaultEnvironmentSize, kMaxCubeFaceSize);
        }
        changed = true;
      }
      probe_.item(concat("environment_capture_size_", size).c_str());
    }
    ImGui::EndCombo();
  }
  itemTooltip("Texels per face side (capture.size): six renders of this size every frame, before the frame.");
  probe_.item("environment_capture_size");
  return changed;
}

// `make`'s image in `texture` under `label`, made again only when `source` or `revision` changes
// (`revision` tells apart two frames' buffers that happen to reuse one address); nothing when
// `source` is null.
void GuiApp::showCachedImage(ImageTexture& texture, const void* source, std::uint64_t revision,
                             const std::function<Image()>& make, const char* label, ImVec2 size) {
  if (source == nullptr) return;
  if (texture.empty() || crossSources_[&texture] != std::make_pair(source, revision)) {
    texture.upload(make());
    crossSources_[&texture] = {source, revision};
  }
  ImGui::TextDisabled("%s", label);
  ImGui::Image(texture.id(), size);
}

// The environment's source as a cube cross: the loaded cube's level 0, or the faces each
// renderer captured for the frames shown.
void GuiApp::drawEnvironmentSourceImages(const Environment& env) {
  const float width = ImGui::GetContentRegionAvail().x;
  const auto show = [&](ImageTexture& texture, const void* source, std::uint64_t revision,
                        const std::function<Image()>& make, const char* label) {
    showCachedImage(texture, source, revision, make, label, ImVec2(width, width * 0.75f));
  };
  if (!env.capture) {
    if (!env.cube || !ImGui::TreeNode("source images")) return;
    show(sourceCrossTexture_, env.cube.get(), 0, [&] { return cubeCrossFromCube(*env.cube); },
         "level 0 (linear values above 1 show white)");
    ImGui::TreePop();
    return;
  }
  if (!ImGui::TreeNode("captured faces")) return;
  const auto facesOf = [](const BackendFrame& frame) -> const CapturedFaces* {
    return frame.output && frame.output->capturedFaces ? frame.output->capturedFaces.get() : nullptr;
  };
  const CapturedFaces* cpu = facesOf(cpuFrame_);
  const CapturedFaces* gl = facesOf(glFrame_);
  if (!cpu && !gl) hintText("No frame drawn with a capture yet.");
  show(captureCpuTexture_, cpu, cpuFrame_.revision, [&] { return capturedFacesCross(*cpu); }, "CPU's faces");
  show(captureGlTexture_, gl, glFrame_.revision, [&] { return capturedFacesCross(*gl); }, "GL's faces");
  ImGui::TreePop();
}

// Light `light`'s shadow map as each renderer drew it for the frames shown (compare's pictures:
// the layers side by side, depth stretched over the range drawn) and their difference (the heat
// ramp's top at the depth tolerance compare uses).
void GuiApp::drawShadowMapImages(std::size_t light) {
  if (!ImGui::TreeNode("shadow maps")) return;
  const auto mapOf = [light](const BackendFrame& frame) -> const ShadowMap* {
    if (!frame.output || light >= frame.output->shadowMaps.size()) return nullptr;
    const ShadowMap* map = frame.output->shadowMaps[light].get();
    return map && !map->depth.empty() ? map : nullptr;
  };
  const ShadowMap* cpu = mapOf(cpuFrame_);
  const ShadowMap* gl = mapOf(glFrame_);
  if (!cpu && !gl) hintText("No frame drawn with this light's shadow map yet.");
  const float width = ImGui::GetContentRegionAvail().x;
  const auto show = [&](ImageTexture& texture, const void* source, std::uint64_t revision,
                        const std::function<Image()>& make, const char* label) {
    const int layers = (cpu ? cpu : gl)->projection.layers;
    showCachedImage(texture, source, revision, make, label, ImVec2(width, width / static_cast<float>(layers)));
  };
  const auto layers = [](const ShadowMap& m) {
    return depthLayersImage(m.depth, m.projection.size, m.projection.size, m.projection.layers);
  };
  show(shadowCpuTexture_, cpu, cpuFrame_.revision, [&] { return layers(*cpu); }, "CPU's map");
  show(shadowGlTexture_, gl, glFrame_.revision, [&] { return layers(*gl); }, "GL's map");
  if (cpu && gl && cpu->depth.size() == gl->depth.size()) {
    // Compared once per pair of frames, not on every redraw (a 2048^2 map is 4 M texels).
    const std::tuple<std::size_t, std::uint64_t, std::uint64_t> key{light, cpuFrame_.revision, glFrame_.revision};
    if (shadowDiffKey_ != key) {
      shadowDiffMetrics_ = compareDepthBuffers(cpu->depth, gl->depth, cpu->projection.size, cpu->projection.size,
                                               cpu->projection.layers, kDefaultDepthTolerance);
      shadowDiffKey_ = key;
    }
    const DepthBufferMetrics& d = shadowDiffMetrics_;
    show(shadowDiffTexture_, cpu, cpuFrame_.revision + (glFrame_.revision << 32),
         [&] {
           return depthDiffImage(cpu->depth, gl->depth, cpu->projection.size, cpu->projection.size,
                                 cpu->projection.layers, kDefaultDepthTolerance);
         },
         "|CPU - GL|");
    ImGui::Text("depth max diff %.3g, texels over %.0e: %llu", d.maxAbsDiff, kDefaultDepthTolerance,
                static_cast<unsigned long long>(d.overTolerance));
  }
  char pass[96];
  std::snprintf(pass, sizeof pass, "shadow pass: CPU %.1f ms, GL %.1f ms",
                cpuFrame_.output ? cpuFrame_.output->stats.shadowMilliseconds : 0.0,
                glFrame_.output ? glFrame_.output->stats.shadowMilliseconds : 0.0);
  hintText(pass);
  ImGui::TreePop();
}

// The environment keys of a material (issue 17): how much of the environment it reflects, whether
// it refracts and with which ratio, and how the reflected share is found. Greyed without an
// environment in the scene. Returns whether one changed.
bool GuiApp::drawEnvironmentControls(std::size_t index) {
  Material& material = doc_.scene.materials[index];
  const std::string key = concat("material", index, '_');
  const float fieldWidth = ImGui::GetContentRegionAvail().x * 0.6f;
  bool edited = false;
  // A combo whose entries the test probe sees as <key><name>_<entry>.
  const auto probedCombo = [&](const char* label, const char* name, auto& value, const auto& values) {
    bool changed = false;
    if (ImGui::BeginCombo(label, std::string(toString(value)).c_str())) {
      for (const auto entry : values) {
        const bool chosen = entry == value;
        if (ImGui::Selectable(std::string(toString(entry)).c_str(), chosen) && !chosen) {
          value = entry;
          changed = true;
        }
        probe_.item(concat(key, name, '_', toString(entry)).c_str());
        if (chosen) ImGui::SetItemDefaultFocus();
      }
      ImGui::EndCombo();
    }
    return changed;
  };
  ImGui::SetNextItemWidth(fieldWidth);
  edited |= ImGui::SliderFloat("ssr reflect", &material.ssrReflect, 0.0f, 1.0f, "%.3f", ImGuiSliderFlags_AlwaysClamp);
  itemTooltip("The share of the screen-space reflection this surface adds (ssr_reflect, [0, 1]); drawn with "
              "Reflections (SSR) on, Rendering tab (docs/ssr.md).");
  probe_.item(concat(key, "ssr_reflect").c_str());
  ImGui::PushID("environment");
  ImGui::TextDisabled("environment");
  ImGui::Indent();
  if (!doc_.scene.environment) hintText("No environment: reflections and refractions need \"environment\" in the scene file.");
  ImGui::BeginDisabled(!doc_.scene.environment);
  ImGui::SetNextItemWidth(fieldWidth);
  if (probedCombo("env specular", "environment_specular", material.environmentSpecular, kEnvironmentSpeculars)) {
    prefilterEnvironmentLight(doc_.scene);  // the glossy cube, built once, the first time a material asks
    edited = true;
  }
  itemTooltip("none: no reflection of the environment; mirror: the reflected direction read as texture() reads it; "
              "prefiltered: a cube with a Phong lobe per mip level, read with textureLod at the level the shininess "
              "names, so a rougher material reflects a blurrier sky (environment_specular).");
  if (material.environmentSpecular == EnvironmentSpecular::Prefiltered && doc_.scene.environment &&
      doc_.scene.environment->specular) {
    const CubeMap& glossy = *doc_.scene.environment->specular;
    char lod[32];
    std::snprintf(lod, sizeof lod, "%.2f", specularLodFromShininess(glossy, material.shininess));
    hintText(concat("Shininess ", static_cast<int>(material.shininess), " reads the glossy cube at LOD ",
                    std::string_view(lod), " of ", glossy.levelCount() - 1, " (level 0: exponent ",
                    static_cast<int>(specularExponentOfSide(glossy.size())), ").")
                 .c_str());
  }
  probe_.item(concat(key, "environment_specular").c_str());
  ImGui::SetNextItemWidth(fieldWidth);
  edited |= ImGui::SliderFloat("reflectivity", &material.reflectivity, 0.0f, 1.0f, "%.3f", ImGuiSliderFlags_AlwaysClamp);
  itemTooltip("The reflected share with fresnel none, Schlick's F0 with schlick (reflectivity, [0, 1]).");
  probe_.item(concat(key, "reflectivity").c_str());
  if (material.environmentSpecular == EnvironmentSpecular::None && material.reflectivity > 0.0f) {
    hintText("Reflectivity is read with env specular \"mirror\" (the scene file turns it on for you).");
  }
  ImGui::SetNextItemWidth(fieldWidth);
  edited |= probedCombo("fresnel", "fresnel", material.fresnel, kFresnels);
  itemTooltip("none: the share is the reflectivity; schlick: F0 + (1 - F0)(1 - N.V)^5, more reflection at grazing "
              "angles (fresnel).");
  probe_.item(concat(key, "fresnel").c_str());
  ImGui::SetNextItemWidth(fieldWidth);
  if (probedCombo("env diffuse", "environment_diffuse", material.environmentDiffuse, kEnvironmentDiffuses)) {
    prefilterEnvironmentLight(doc_.scene);  // built once, the first time a material asks
    edited = true;
  }
  itemTooltip("The environment's light on a white Lambertian surface, times kd and the albedo, added to the Phong "
              "colour: none; irradiance_map: a 32-texel cube of the cosine-weighted sum, read at the normal; sh9: nine "
              "spherical-harmonic coefficients per channel (environment_diffuse).");
  probe_.item(concat(key, "environment_diffuse").c_str());
  bool refracts = material.refractionIndex > 0.0f;
  if (ImGui::Checkbox("refracts", &refracts)) {
    material.refractionIndex = refracts ? kDefaultRefractionIndex : 0.0f;
    edited = true;
  }
  itemTooltip("The refracted environment replaces the Phong colour, as glass shows what lies behind it.");
  probe_.item(concat(key, "refracts").c_str());
  if (refracts) {
    ImGui::SameLine();
    ImGui::SetNextItemWidth(fieldWidth * 0.6f);
    edited |= ImGui::SliderFloat("n1 / n2", &material.refractionIndex, kMinRefractionIndexSlider, kMaxRefractionIndex,
                                 "%.3f", ImGuiSliderFlags_AlwaysClamp | ImGuiSliderFlags_Logarithmic);
    itemTooltip("refraction_index: the ratio for Snell's law. 0.66 enters glass from air, 0.75 water; above 1 leaves a "
                "denser medium, where total internal reflection takes over past the critical angle.");
    probe_.item(concat(key, "refraction_index").c_str());
  }
  ImGui::EndDisabled();
  ImGui::Unindent();
  ImGui::PopID();
  if (edited) selectedMaterial_ = index;
  return edited;
}

// One map of a material: on/off, then the options a scene file gives it. Applying an edit is
// material_maps.h's job (a new Texture, so neither backend keeps a stale copy).
void GuiApp::drawMapControls(std::size_t material, MapSlot slot) {
  const std::shared_ptr<const Texture> loaded = loadedMap(doc_, material, slot);
  if (!loaded) return;
  const std::string key = concat("material", material, '_', kMapKeys[static_cast<std::size_t>(slot)]);
  ImGui::PushID(static_cast<int>(slot));
  bool on = mapOn(doc_, material, slot);
  const std::string label = concat(toString(slot), " (", loaded->width, 'x', loaded->height, ", ",
                                   loaded->formatName, ')');
  if (ImGui::Checkbox(label.c_str(), &on)) setMapOn(doc_, material, slot, on);
  itemTooltip(concat(loaded->path, "\nOff: the material is drawn without this map (it stays loaded, so switching "
                                   "back costs nothing).",
                     slot == MapSlot::Height
                         ? "\nThe red channel is the height: 1 = the top of the relief, where the polygon lies, 0 "
                           "= height_scale below it. Off, every surface_detail draws as normal_map."
                         : "")
                  .c_str());
  probe_.item(concat(key, "_on").c_str());

  ImGui::Indent();
  TextureOptions options = loaded->options;
  bool edited = false;
  edited |= ImGui::Checkbox("flip v", &options.flipV);
  itemTooltip("Off: the image file's top row is v = 1, as GL tutorials load images; on: the top row is v = 0. "
              "The file is read again.");
  probe_.item(concat(key, "_flip_v").c_str());
  ImGui::SameLine();
  edited |= ImGui::Checkbox("sRGB", &options.srgb);
  itemTooltip(slot == MapSlot::Normal
                  ? "Decode the texels from sRGB to linear before filtering (GL_SRGB8_ALPHA8). A normal map holds "
                    "directions, not colours: this bends every normal. The file is read again."
              : slot == MapSlot::Height
                  ? "Decode the texels from sRGB to linear before filtering (GL_SRGB8_ALPHA8). A height map holds "
                    "heights, not colours: this bends every slope. The file is read again (and the horizon map "
                    "built again)."
                  : "Decode the colour channels from sRGB to linear before filtering (GL_SRGB8_ALPHA8), as a "
                    "colour image painted on screen needs; mip levels are then averaged as linear light. The file "
                    "is read again.");
  probe_.item(concat(key, "_srgb").c_str());
  ImGui::SetNextItemWidth(ImGui::GetContentRegionAvail().x * 0.6f);
  edited |= enumCombo("wrap", options.wrap, kWrapModes);
  itemTooltip("How u and v outside [0, 1] read the texture (GL_TEXTURE_WRAP_S and _T): repeat tiles it, "
              "mirrored_repeat tiles it mirrored every other time, clamp_to_edge repeats the border texels.");
  probe_.item(concat(key, "_wrap").c_str());
  if (offersGreen(slot)) {
    edited |= enumRadio("green", options.green, kGreenAxes, 0.0f,
                        "Which way the map's green channel points: up (+v: OpenGL and Blender), or down (Direct3D-"
                        "style tools, some LearnOpenGL assets): both renderers then use 1 - g.");
    probe_.item(concat(key, "_green").c_str());
  }
  const auto messageKey = std::make_pair(material, slot);
  if (edited) {
    MapMessage message;
    try {
      for (const std::string& warning : setMapOptions(doc_, material, slot, options)) {
        if (!message.text.empty()) message.text += '\n';
        message.text += warning;
      }
    } catch (const std::exception& e) {
      message = MapMessage{e.what(), true};
    }
    mapMessages_[messageKey] = message;
  }
  if (const auto found = mapMessages_.find(messageKey); found != mapMessages_.end() && !found->second.text.empty()) {
    if (found->second.error) errorText(found->second.text);
    else warningText(found->second.text);
  }
  ImGui::Unindent();
  ImGui::PopID();
}

void GuiApp::drawLightsSection() {
  sectionTitle("Lights");
  std::vector<Light>& lights = doc_.scene.lights;
  bool changed = false;
  int removeIndex = -1;
  for (std::size_t i = 0; i < lights.size(); ++i) {
    Light& light = lights[i];
    ImGui::PushID(static_cast<int>(i));
    const bool open = ImGui::TreeNodeEx("##light", ImGuiTreeNodeFlags_DefaultOpen, "light %zu", i);
    ImGui::SameLine(ImGui::GetContentRegionAvail().x + ImGui::GetCursorPosX() - ImGui::CalcTextSize("Remove").x -
                    2.0f * ImGui::GetStyle().FramePadding.x);
    if (ImGui::SmallButton("Remove")) removeIndex = static_cast<int>(i);
    if (open) {
      bool directional = light.type == LightType::Directional;
      if (ImGui::Checkbox("directional", &directional)) {
        light.type = directional ? LightType::Directional : LightType::Point;
        changed = true;
      }
      itemTooltip("A directional light (type directional) shines along one direction from infinitely far, "
                  "unattenuated, as the sun; a point light from its position, fading with distance.");
      ImGui::SetNextItemWidth(ImGui::GetContentRegionAvail().x * 0.6f);
      if (directional) {
        vec3 direction = light.directionWorld;
        if (ImGui::DragFloat3("Direction", &direction.x, kDirectionDragSpeed, -1.0f, 1.0f, "%.3f")) {
          // Kept unit length, as the scene file leaves it; a zero vector keeps the last one.
          if (glm::length(direction) > 0.0f) light.directionWorld = glm::normalize(direction);
          changed = true;
        }
        itemTooltip("The way the light travels, world space (direction; kept unit length).");
      } else {
        changed |= ImGui::DragFloat3("Position", &light.posWorld.x, kTranslateDragSpeed, -kMaxCoordinate,
                                     kMaxCoordinate, "%.2f");
        itemTooltip("World space. Drag the numbers to move the light.");
      }
      changed |= ImGui::ColorEdit3("Diffuse Id", &light.diffuse.x, kColourFlags);
      itemTooltip("Diffuse intensity of the light, linear RGB (may exceed 1).");
      changed |= ImGui::ColorEdit3("Specular Is", &light.specular.x, kColourFlags);
      itemTooltip("Specular intensity of the light, linear RGB (may exceed 1).");
      ImGui::SetNextItemWidth(ImGui::GetContentRegionAvail().x * 0.6f);
      ImGui::BeginDisabled(directional);
      changed |= ImGui::DragFloat3("A_C A_L A_Q", &light.attenuation.x, kAttenuationDragSpeed, 0.0f, 10.0f,
                                   "%.4f", ImGuiSliderFlags_AlwaysClamp);
      ImGui::EndDisabled();
      itemTooltip("Attenuation If = 1 / (A_C + A_L d + A_Q d^2), d in world units (point lights only).");
      if (!directional) changed |= editSpot(light);
      changed |= editShadow(light, lights);
      if (light.shadow) drawShadowMapImages(i);
      ImGui::TreePop();
    }
    ImGui::PopID();
  }
  if (removeIndex >= 0) {
    lights.erase(lights.begin() + removeIndex);
    changed = true;
  }
  ImGui::BeginDisabled(lights.size() >= static_cast<std::size_t>(kMaxLights));
  if (ImGui::Button("Add light")) {
    lights.push_back(Light{});
    changed = true;
  }
  ImGui::EndDisabled();
  ImGui::SameLine();
  ImGui::TextDisabled("%zu of %d", lights.size(), kMaxLights);
  if (changed) doc_.touch();
}

}  // namespace twr::gui
