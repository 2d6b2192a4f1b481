#include "app/gui/app.h"
#include "app/gui/ui_widgets.h"
#include "gui/scene_picker.h"
#include "gui/view_screenshot.h"

#include "compare/heatmap.h"
#include "compare/side_by_side.h"
#include "glrender/gl_renderer.h"
#include "scene/errors.h"

#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>
#include <glad/gl.h>
#include <nlohmann/json.hpp>
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <imgui_internal.h>

#include <algorithm>
#include <csignal>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <ctime>
#include <filesystem>
#include <iostream>
#include <thread>

namespace twr::gui {
namespace {

// How long the loop sleeps while the window is minimised (zero-size framebuffer), seconds.
constexpr double kMinimisedWaitSeconds = 0.1;
// While frames are needed (redraw_policy.h decides when) at most one frame per this many
// seconds without input (60 Hz): without vsync (Xvfb, some drivers) the loop would spin and
// take a core from the CPU renderer. When none is needed the loop draws nothing.
constexpr double kBusyFrameSeconds = 1.0 / 60.0;
// While --frames waits for the CPU frame, how long each wait for the worker lasts.
constexpr std::chrono::milliseconds kSettlePoll{10};
// Tries to open a window (inclusive) and the pause between tries.
constexpr int kWindowAttempts = 5;
constexpr std::chrono::milliseconds kWindowRetryDelay{200};
// Text sizes at content scale 1, pixels.
constexpr float kBaseFontPixels = 15.0f;
constexpr float kMonoFontPixels = 14.0f;
constexpr float kDefaultFontPixels = 13.0f;  // ImGui's built-in font, when DejaVu is missing
// Largest UI scale honoured (a content scale above this is a misreport), inclusive.
constexpr float kMaxUiScale = 4.0f;
// Window background behind the panels (linear RGB).
constexpr float kClearColour[3] = {0.08f, 0.08f, 0.10f};

const char* const kUiFontPath = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";
const char* const kMonoFontPath = "/usr/share/fonts/truetype/dejavu/DejaVuSansMono.ttf";

// Set by SIGTERM or SIGINT: the loop closes the window as if the user had, so the settings
// are saved (a script or a test ends the app this way).
volatile std::sig_atomic_t gQuitRequested = 0;

extern "C" void requestQuit(int) { gQuitRequested = 1; }

bool fileExists(const char* path) {
  std::error_code code;
  return std::filesystem::is_regular_file(path, code);
}

}  // namespace

GuiApp::GuiApp(GuiOptions options) : options_(std::move(options)) {
  paths_ = prefsPaths();
  if (options_.reset) std::cerr << "twinraster-gui: --reset: " << resetPrefs(paths_) << "\n";
  prefs_ = loadPrefs(paths_.prefs, prefsWarning_);
  if (!prefsWarning_.empty()) std::cerr << "twinraster-gui: warning: " << prefsWarning_ << "\n";
  if (options_.viewMode) prefs_.viewMode = *options_.viewMode;
  if (options_.cpuPath) prefs_.cpuPath = *options_.cpuPath;
  if (options_.cpuIsa) prefs_.cpuIsa = *options_.cpuIsa;
  if (!paths_.dir.empty()) {
    std::error_code code;
    std::filesystem::create_directories(paths_.dir, code);
    iniPath_ = paths_.imguiIni.string();
  }

  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  ImGuiIO& io = ImGui::GetIO();
  io.IniFilename = iniPath_.empty() ? nullptr : iniPath_.c_str();
  io.ConfigWindowsMoveFromTitleBarOnly = true;

  createWindow();
  GlOptions glOptions;
  glOptions.fastSampling = options_.glFastSampling;
  glWorker_ = std::make_unique<GlWorker>(glOptions);

  // HiDPI comes in two kinds. Where window coordinates are pixels (X11, Windows) the
  // content scale says how much bigger everything must be drawn: scale the layout and the
  // fonts. Where the framebuffer has more pixels than the window has coordinates (macOS,
  // Wayland) ImGui already lays out in points: only rasterize the fonts finer.
  float scaleX = 1.0f, scaleY = 1.0f;
  glfwGetWindowContentScale(window_->window(), &scaleX, &scaleY);
  const float contentScale = std::clamp(std::max(scaleX, scaleY), 1.0f, kMaxUiScale);
  int windowWidth = 0, windowHeight = 0, framebufferWidth = 0, framebufferHeight = 0;
  glfwGetWindowSize(window_->window(), &windowWidth, &windowHeight);
  glfwGetFramebufferSize(window_->window(), &framebufferWidth, &framebufferHeight);
  const float framebufferRatio =
      windowWidth > 0 ? std::clamp(static_cast<float>(framebufferWidth) / static_cast<float>(windowWidth), 1.0f, kMaxUiScale)
                      : 1.0f;
  const bool pointsLayout = framebufferRatio > 1.0f;
  uiScale_ = pointsLayout ? 1.0f : contentScale;
  setUpImGuiStyle(uiScale_, pointsLayout ? framebufferRatio : contentScale);

  const std::string startScene = options_.scenePath.empty() ? findStartupScene(prefs_.lastScene) : options_.scenePath;
  if (startScene.empty()) {
    doc_ = emptySceneDoc();
    sceneError_ = "No scene opened: type the path of a scene file (JSON) in the Scene tab and press Open.";
    selectSceneTab_ = true;
  } else {
    openScene(startScene);
  }
  if (options_.pin) {
    pin_.pixel = options_.pin;
  }
  flickerStart_ = glfwGetTime();
  std::signal(SIGTERM, requestQuit);
  std::signal(SIGINT, requestQuit);
}

GuiApp::~GuiApp() {
  std::string error;
  if (!paths_.prefs.empty() && !savePrefs(paths_.prefs, prefs_, error)) {
    std::cerr << "twinraster-gui: warning: " << error << "\n";
  }
  // First: its renders may load glad's entry points, which the window's end loads again.
  glWorker_.reset();
  destroyWindow();
  ImGui::DestroyContext();
}

void GuiApp::createWindow() {
  GlfwWindowDesc desc;
  desc.width = options_.width;
  desc.height = options_.height;
  desc.title = "twinraster";
  // GlfwContext ends GLFW with its window, closing the display connection. A server whose
  // last client left may be resetting (Xvfb does), so a new window right after the old one
  // is tried a few times before the failure counts.
  for (int attempt = 1;; ++attempt) {
    try {
      window_ = std::make_unique<GlfwContext>(desc);
      break;
    } catch (const InputError&) {
      if (attempt >= kWindowAttempts) throw;
      std::this_thread::sleep_for(kWindowRetryDelay);
    }
  }
  // Our callbacks go in first: ImGui's backend chains to the ones it installs too. A tap of
  // F12 shorter than a frame still counts (ImGui 1.86 only sees keys held down at a frame's start).
  GLFWwindow* window = window_->window();
  glfwSetWindowUserPointer(window, this);
  glfwSetKeyCallback(window, [](GLFWwindow* w, int key, int, int action, int) {
    GuiApp& app = *static_cast<GuiApp*>(glfwGetWindowUserPointer(w));
    app.noteEvent();
    if (key == GLFW_KEY_F12 && action == GLFW_PRESS) app.windowShotRequested_ = true;
    // A press and its release between two frames: hold the key for the next frame (holdTappedKeys).
    if (action == GLFW_PRESS) app.keysPressedSinceFrame_.insert(key);
    if (action == GLFW_RELEASE && app.keysPressedSinceFrame_.count(key) != 0) app.keysToHold_.insert(key);
  });
  // Every other input and window event wakes an idle loop for a frame too (redraw_policy.h).
  // The refresh callback is X's expose: the window lost its pixels and must be drawn again.
  glfwSetCharCallback(window, [](GLFWwindow* w, unsigned int) { windowEvent(w); });
  glfwSetMouseButtonCallback(window, [](GLFWwindow* w, int, int, int) { windowEvent(w); });
  glfwSetScrollCallback(window, [](GLFWwindow* w, double, double) { windowEvent(w); });
  glfwSetCursorPosCallback(window, [](GLFWwindow* w, double, double) { windowEvent(w); });
  glfwSetCursorEnterCallback(window, [](GLFWwindow* w, int) { windowEvent(w); });
  glfwSetWindowFocusCallback(window, [](GLFWwindow* w, int) { windowEvent(w); });
  glfwSetWindowRefreshCallback(window, [](GLFWwindow* w) { windowEvent(w); });
  glfwSetWindowSizeCallback(window, [](GLFWwindow* w, int, int) { windowEvent(w); });
  glfwSetFramebufferSizeCallback(window, [](GLFWwindow* w, int, int) { windowEvent(w); });
  glfwSetWindowContentScaleCallback(window, [](GLFWwindow* w, float, float) { windowEvent(w); });
  glfwSetWindowIconifyCallback(window, [](GLFWwindow* w, int) { windowEvent(w); });
  ImGui_ImplGlfw_InitForOpenGL(window, true);
  ImGui_ImplOpenGL3_Init("#version 330");
  // The textures live in the new context: upload them again.
  cpuTextureStale_ = glTextureStale_ = diff_.texturesStale = true;
}

void GuiApp::destroyWindow() {
  if (!window_) return;
  window_->makeCurrent();
  cpuTexture_.reset();
  glTexture_.reset();
  heatTexture_.reset();
  classTexture_.reset();
  ImGui_ImplOpenGL3_Shutdown();
  ImGui_ImplGlfw_Shutdown();
  window_.reset();
}

void GuiApp::setUpImGuiStyle(float uiScale, float fontRasterScale) {
  ImGuiIO& io = ImGui::GetIO();
  io.Fonts->Clear();
  // Glyphs rasterized at fontRasterScale pixels per point, drawn at uiScale.
  io.FontGlobalScale = uiScale / fontRasterScale;
  ImFontConfig config;
  config.OversampleH = 2;
  if (fileExists(kUiFontPath)) {
    io.Fonts->AddFontFromFileTTF(kUiFontPath, std::round(kBaseFontPixels * fontRasterScale), &config);
  } else {
    ImFontConfig fallback;
    fallback.SizePixels = std::round(kDefaultFontPixels * fontRasterScale);
    io.Fonts->AddFontDefault(&fallback);
  }
  monoFont_ = fileExists(kMonoFontPath)
                  ? io.Fonts->AddFontFromFileTTF(kMonoFontPath, std::round(kMonoFontPixels * fontRasterScale), &config)
                  : nullptr;

  ImGui::StyleColorsDark();
  ImGuiStyle& style = ImGui::GetStyle();
  style.WindowRounding = 0.0f;
  style.FrameRounding = 3.0f;
  style.GrabRounding = 3.0f;
  style.TabRounding = 3.0f;
  style.WindowBorderSize = 1.0f;
  style.FramePadding = ImVec2(6.0f, 3.0f);
  style.ItemSpacing = ImVec2(8.0f, 5.0f);
  style.IndentSpacing = 14.0f;
  ImVec4* colours = style.Colors;
  colours[ImGuiCol_WindowBg] = ImVec4(0.11f, 0.11f, 0.13f, 1.0f);
  colours[ImGuiCol_ChildBg] = ImVec4(0.0f, 0.0f, 0.0f, 0.0f);
  colours[ImGuiCol_TitleBg] = ImVec4(0.15f, 0.16f, 0.20f, 1.0f);
  colours[ImGuiCol_TitleBgActive] = ImVec4(0.18f, 0.22f, 0.32f, 1.0f);
  colours[ImGuiCol_Header] = ImVec4(0.22f, 0.28f, 0.40f, 0.75f);
  colours[ImGuiCol_HeaderHovered] = ImVec4(0.28f, 0.36f, 0.52f, 0.85f);
  colours[ImGuiCol_FrameBg] = ImVec4(0.18f, 0.19f, 0.23f, 1.0f);
  colours[ImGuiCol_Tab] = ImVec4(0.16f, 0.18f, 0.24f, 1.0f);
  colours[ImGuiCol_TabActive] = ImVec4(0.26f, 0.34f, 0.52f, 1.0f);
  colours[ImGuiCol_TabHovered] = ImVec4(0.32f, 0.42f, 0.62f, 1.0f);
  style.ScaleAllSizes(uiScale);
}

void GuiApp::openScene(const std::string& path) {
  try {
    SceneDoc loaded = loadSceneDoc(path);
    loaded.revision = doc_.revision + 1;  // revisions only grow, so no old frame matches
    doc_ = std::move(loaded);
    sceneError_.clear();
    meshError_.clear();
    meshErrorIndex_ = -1;
    mapMessages_.clear();
    heightFieldErrors_.clear();
    horizonFailed_.reset();
    horizonError_.clear();
    horizonLastBuild_.clear();
    // The first material with a height map: the one a height-field lesson is about.
    selectedMaterial_ = 0;
    for (std::size_t m = 0; m < doc_.scene.materials.size(); ++m) {
      if (loadedMap(doc_, m, MapSlot::Height)) {
        selectedMaterial_ = m;
        break;
      }
    }
    std::error_code code;
    const std::filesystem::path absolute = std::filesystem::absolute(path, code);
    prefs_.lastScene = code ? path : absolute.lexically_normal().string();
    rememberRecent(prefs_.recentScenes, prefs_.lastScene);
    scenePathInput_ = path;
    pin_ = PinState{};
    // Another scene: the old scene's frame times say nothing about this one.
    cpuMs_.restart("scene loaded");
    glMs_.restart("scene loaded");
    timingsFromRevision_ = doc_.revision;
    if (window_) {
      const std::string title = "twinraster - " + std::filesystem::path(path).filename().string();
      glfwSetWindowTitle(window_->window(), title.c_str());
    }
  } catch (const std::exception& e) {
    sceneError_ = e.what();
    selectSceneTab_ = true;
    if (scenePathInput_.empty()) scenePathInput_ = path;
    std::cerr << "twinraster-gui: could not open the scene: " << e.what() << "\n";
  }
}

bool GuiApp::settled() const {
  if (!renderInputsValid()) return true;
  if (!worker_.idle() || (glWorker_ && !glWorker_->idle())) return false;
  if (horizonMapsPending()) return false;  // its frames are still to come
  const std::uint64_t now = doc_.revision;
  if (cpuFrame_.revision != now || glFrame_.revision != now) return false;
  if (cpuFrame_.output && glFrame_.output && diff_.revision != now) return false;
  if (diff_.cpu && diff_.gl && diff_.buffer != shownBuffer_) return false;  // the diff is of another buffer
  if (pin_.pixel) {
    // A CPU frame that threw has no probe (its error is shown instead).
    const bool cpuProbeDone = (pin_.cpu && pin_.cpuRevision == now) || !cpuFrame_.error.empty();
    if (!cpuProbeDone) return false;
    const bool glProbeDone =
        (pin_.glRevision == now && (!pin_.glError.empty() ||
                                    std::all_of(pin_.gl.begin(), pin_.gl.end(), [](const auto& s) { return s.has_value(); }))) ||
        !glFrame_.error.empty();
    if (!glProbeDone) return false;
  }
  return true;
}

void GuiApp::noteEvent() { redraw_.event(glfwGetTime()); }

void GuiApp::windowEvent(GLFWwindow* window) { static_cast<GuiApp*>(glfwGetWindowUserPointer(window))->noteEvent(); }

bool GuiApp::workRunning() const {
  return !worker_.idle() || (glWorker_ && !glWorker_->idle()) || !horizonWorker_.idle();
}

bool GuiApp::resultsWaiting() const {
  return worker_.hasFinished() || (glWorker_ && glWorker_->hasFinished()) || horizonWorker_.hasFinished();
}

bool GuiApp::keepDrawing() const {
  // The flicker view switches images by the clock; a drag over the image moves with the mouse.
  if (prefs_.viewMode == ViewMode::Flicker || dragMode_ != DragMode::None) return true;
  // A held button or key: ImGui repeats keys and buttons, scrolls while text is selected by
  // dragging, and so on, by its clock and with no event.
  const ImGuiIO& io = ImGui::GetIO();
  if (std::any_of(std::begin(io.MouseDown), std::end(io.MouseDown), [](bool down) { return down; }) ||
      std::any_of(std::begin(io.KeysDown), std::end(io.KeysDown), [](bool down) { return down; })) {
    return true;
  }
  // An active widget, except a text field being typed into: that one only blinks its cursor,
  // and scheduleImGuiTimers asks for each blink.
  const ImGuiContext& context = *GImGui;
  if (ImGui::IsAnyItemActive() && context.ActiveId != context.InputTextState.ID) return true;
  if (redraw_.settling(glfwGetTime())) return true;
  // Not caught up, yet no worker will deliver anything: what is missing waits for a frame (a
  // probe held back while a widget was active, say). Nothing else would wake the loop for it.
  return !settled() && !workRunning() && !resultsWaiting();
}

void GuiApp::scheduleImGuiTimers() {
  const ImGuiContext& context = *GImGui;
  const double now = glfwGetTime();
  if (context.ActiveId != 0 && context.ActiveId == context.InputTextState.ID && context.IO.ConfigInputTextCursorBlink) {
    redraw_.redrawAt(now + cursorBlinkSwitchesIn(context.InputTextState.CursorAnim));
  }
  // ImGui writes imgui.ini a while after a change (io.IniSavingRate), counting down in frames.
  if (context.SettingsDirtyTimer > 0.0f) redraw_.redrawAt(now + context.SettingsDirtyTimer);
}

void GuiApp::holdTappedKeys() {
  // ImGui 1.86 reads keys as "down at the start of a frame": a key pressed and released
  // between two frames (a fast typist, xdotool, a loaded machine) would be lost. Such a key
  // is held down for one frame and released at the next.
  ImGuiIO& io = ImGui::GetIO();
  const auto setDown = [&io](int key, bool down) {
    if (key >= 0 && key < static_cast<int>(IM_ARRAYSIZE(io.KeysDown))) io.KeysDown[key] = down;
  };
  for (int key : keysHeld_) {
    if (keysToHold_.count(key) == 0 && glfwGetKey(window_->window(), key) != GLFW_PRESS) setDown(key, false);
  }
  keysHeld_ = keysToHold_;
  for (int key : keysHeld_) setDown(key, true);
  keysToHold_.clear();
  keysPressedSinceFrame_.clear();
  io.KeyCtrl = io.KeysDown[GLFW_KEY_LEFT_CONTROL] || io.KeysDown[GLFW_KEY_RIGHT_CONTROL];
  io.KeyShift = io.KeysDown[GLFW_KEY_LEFT_SHIFT] || io.KeysDown[GLFW_KEY_RIGHT_SHIFT];
  io.KeyAlt = io.KeysDown[GLFW_KEY_LEFT_ALT] || io.KeysDown[GLFW_KEY_RIGHT_ALT];
  io.KeySuper = io.KeysDown[GLFW_KEY_LEFT_SUPER] || io.KeysDown[GLFW_KEY_RIGHT_SUPER];
}

void GuiApp::frame(bool& finalFrame, bool present) {
  // No exception may end the app: the renders report theirs per backend, the panels theirs
  // per panel (drawGuarded); anything else is shown over the whole window.
  try {
    syncRenders();
  } catch (const std::exception& e) {
    showScreenshotMessage(std::string("Internal error while updating the renders: ") + e.what());
    std::cerr << "twinraster-gui: error: " << e.what() << "\n";
  }
  if (finalFrame) finalFrame = settled();

  ImGui_ImplOpenGL3_NewFrame();
  ImGui_ImplGlfw_NewFrame();
  holdTappedKeys();
  ImGui::NewFrame();
  probe_.beginFrame();
  shownTooltip() = {};
  redraw_.beginFrame();  // the timed elements drawn below ask for their next redraw
  try {
    drawLayout();
  } catch (const std::exception& e) {
    ImGui::ErrorCheckEndFrameRecover(nullptr);
    showScreenshotMessage(std::string("Internal error while drawing the window: ") + e.what());
    std::cerr << "twinraster-gui: error: " << e.what() << "\n";
  }
  if (probe_.enabled()) {
    nlohmann::json& state = probe_.state();
    state["render"] = {renderWidth_, renderHeight_};
    state["edit"] = doc_.revision;
    state["cpu_edit"] = cpuFrame_.revision;
    state["gl_edit"] = glFrame_.revision;
    state["diff_edit"] = diff_.result ? diff_.revision : 0;
    if (diff_.result) {
      const CompareMetrics& m = diff_.result->metrics;
      state["diff"] = {{"max_abs_diff", m.maxAbsDiff},
                       {"covered_cpu", m.coveredCpu},
                       {"covered_gl", m.coveredGl},
                       {"coverage_mismatch", m.coverageMismatch}};
    }
    state["render_blocker"] = renderBlocker_;
    state["projection_warnings"] = projectionWarnings_;
    state["camera"] = {{"near", doc_.scene.camera.near}, {"far", doc_.scene.camera.far}};
    state["frames"] = ImGui::GetFrameCount();
    state["presented"] = presentedFrames_ + (present ? 1 : 0);
    state["clock"] = glfwGetTime();  // seconds: the clock the redraw policy runs on
    state["settled"] = settled();
    // Every loaded map with its options, whether it is drawn, and its Texture object (a new
    // one after each option edit).
    nlohmann::json maps = nlohmann::json::array();
    for (std::size_t m = 0; m < doc_.scene.materials.size(); ++m) {
      for (const MapSlot slot : kMapSlots) {
        const std::shared_ptr<const Texture> map = loadedMap(doc_, m, slot);
        if (!map) continue;
        const auto message = mapMessages_.find({m, slot});
        maps.push_back({{"material", m},
                        {"slot", std::string(toString(slot))},
                        {"on", mapOn(doc_, m, slot)},
                        {"flip_v", map->options.flipV},
                        {"srgb", map->options.srgb},
                        {"wrap", std::string(toString(map->options.wrap))},
                        {"green", std::string(toString(map->options.green))},
                        {"object", reinterpret_cast<std::uintptr_t>(map.get())},
                        {"message", message != mapMessages_.end() ? message->second.text : std::string()}});
      }
    }
    state["maps"] = std::move(maps);
    // Every material's height-field keys, and where its horizon map stands.
    nlohmann::json materials = nlohmann::json::array();
    for (std::size_t m = 0; m < doc_.scene.materials.size(); ++m) {
      const Material& material = doc_.scene.materials[m];
      nlohmann::json horizon = nullptr;
      if (material.horizonMap) {
        horizon = {{"directions", material.horizonMap->directions},
                   {"object", reinterpret_cast<std::uintptr_t>(material.horizonMap.get())}};
      }
      materials.push_back({{"name", material.name},
                           {"height_map", loadedMap(doc_, m, MapSlot::Height) != nullptr},
                           {"height_map_on", material.heightMap != nullptr},
                           {"surface_detail", std::string(toString(material.surfaceDetail))},
                           {"height_scale", material.heightScale},
                           {"parallax_layers", {material.parallaxLayers.x, material.parallaxLayers.y}},
                           {"relief_refinement_steps", material.reliefRefinementSteps},
                           {"self_shadow", std::string(toString(material.selfShadow))},
                           {"horizon_directions", material.horizonDirections},
                           {"horizon_map", horizon},
                           {"horizon_stale", horizonMapStale(doc_, m)},
                           {"error", heightFieldErrors_.count(m) != 0 ? heightFieldErrors_.at(m) : std::string()},
                           {"reflectivity", material.reflectivity},
                           {"ssr_reflect", material.ssrReflect},
                           {"refraction_index", material.refractionIndex},
                           {"fresnel", std::string(toString(material.fresnel))},
                           {"environment_specular", std::string(toString(material.environmentSpecular))},
                           {"environment_diffuse", std::string(toString(material.environmentDiffuse))}});
    }
    state["materials"] = std::move(materials);
    state["selected_material"] = selectedMaterial_;
    state["horizon_building"] = horizonBuilding_ ? nlohmann::json(horizonBuilding_->material) : nlohmann::json(nullptr);
    state["horizon_status"] = horizonStatus();
    state["horizon_last_build"] = horizonLastBuild_;
    state["anisotropy"] = doc_.scene.settings.anisotropy;
    state["pipeline"] = std::string(toString(doc_.scene.settings.pipeline));
    state["interpolation"] = std::string(toString(doc_.scene.settings.interpolation));
    state["gbuffer_position"] = std::string(toString(doc_.scene.settings.gbufferPosition));
    const SsrSettings& ssr = doc_.scene.settings.ssr;
    state["ssr"] = {{"enabled", ssr.enabled},       {"march", std::string(toString(ssr.march))},
                    {"max_steps", ssr.maxSteps},    {"step", ssr.step},
                    {"thickness", ssr.thickness},   {"reflect_strength", ssr.reflectStrength}};
    state["buffer"] = std::string(toString(shownBuffer_));
    state["diff_buffer"] = std::string(toString(diff_.buffer));
    state["cpu_gbuffer"] = cpuFrame_.output && cpuFrame_.output->gbuffer != nullptr;
    state["gl_gbuffer"] = glFrame_.output && glFrame_.output->gbuffer != nullptr;
    state["environment"] = doc_.scene.environment
                               ? nlohmann::json{{"intensity", doc_.scene.environment->intensity},
                                                {"background", doc_.scene.environment->background},
                                                {"parameterization", std::string(toString(doc_.scene.environment->parameterization))},
                                                {"map_size", doc_.scene.environment->layers ? doc_.scene.environment->layers->size() : 0},
                                                {"irradiance_layers", doc_.scene.environment->irradianceLayers != nullptr},
                                                {"sh9", doc_.scene.environment->sh9 != nullptr},
                                                {"specular_levels", doc_.scene.environment->specular ? doc_.scene.environment->specular->levelCount() : 0},
                                                {"specular_layers", doc_.scene.environment->specularLayers != nullptr},
                                                {"capture", doc_.scene.environment->capture
                                                                ? nlohmann::json{{"node", doc_.scene.environment->capture->node},
                                                                                 {"size", doc_.scene.environment->capture->size}}
                                                                : nlohmann::json(nullptr)}}
                               : nlohmann::json(nullptr);
    state["view"] = std::string(toString(doc_.scene.settings.view));
    const ShownTooltip& tip = shownTooltip();
    state["tooltip"] = tip.text.empty() ? nlohmann::json(nullptr)
                                        : nlohmann::json{{"text", tip.text},
                                                         {"rect", {tip.rect[0], tip.rect[1], tip.rect[2], tip.rect[3]}},
                                                         {"alpha", tip.alpha}};
  }
  probe_.endFrame();
  interacting_ = dragMode_ != DragMode::None || ImGui::IsAnyItemActive();
  ImGui::Render();
  scheduleImGuiTimers();
  if (!present) return;

  int width = 0, height = 0;
  glfwGetFramebufferSize(window_->window(), &width, &height);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glViewport(0, 0, width, height);
  glClearColor(kClearColour[0], kClearColour[1], kClearColour[2], 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
}

int GuiApp::run() {
  int framesDrawn = 0;
  std::optional<Clock::time_point> settleStart;
  int exitCode = kExitOk;
  bool idle = false;
  Clock::time_point frameStart = Clock::now();
  double lastFrameTime = glfwGetTime();  // the last frame, presented or not (glfwGetTime(), seconds)
  while (!glfwWindowShouldClose(window_->window())) {
    if (gQuitRequested) break;
    if (options_.frames > 0) {
      glfwPollEvents();  // scripted runs go as fast as they can
    } else if (idle) {
      const double wait = redraw_.sleepSeconds(glfwGetTime(), workRunning());
      if (wait > 0.0) glfwWaitEventsTimeout(wait);
      else glfwPollEvents();  // a timed change is due already
    } else {
      // Busy: wait only for what is left of this frame's 1/60 s, so the wait caps the rate
      // without adding to a frame that already took its time (a fixed wait on top of drawing
      // and presenting kept a 1600x1000 window under 30 redraws/s).
      const double spent = std::chrono::duration<double>(Clock::now() - frameStart).count();
      if (spent < kBusyFrameSeconds) glfwWaitEventsTimeout(kBusyFrameSeconds - spent);
      else glfwPollEvents();
    }
    frameStart = Clock::now();
    int width = 0, height = 0;
    glfwGetFramebufferSize(window_->window(), &width, &height);
    if (width <= 0 || height <= 0) {
      // Minimised: nothing to draw into. Keep taking finished frames so the workers
      // does not hold them, and sleep until something happens.
      takeCpuFrames();
      takeGlFrames();
      glfwWaitEventsTimeout(kMinimisedWaitSeconds);
      continue;
    }
    // A worker's result changes what is shown (images, tags, stats, the horizon status) and
    // the layout with it: drawn, and settled, as after an event (the frame that takes it
    // notes one too, for a result that comes in between).
    if (resultsWaiting()) noteEvent();
    // Idle and nothing happened: no frame (redraw_policy.h). The test probe still gets one
    // laid out now and then, not drawn, so a scripted test waiting for frames sees them come.
    bool present = true;
    if (options_.frames <= 0 && idle && !redraw_.due(glfwGetTime())) {
      if (!probe_.enabled() || glfwGetTime() - lastFrameTime < kProbeFrameSeconds) continue;
      present = false;
    }
    lastFrameTime = glfwGetTime();
    const bool limitReached = options_.frames > 0 && framesDrawn + 1 >= options_.frames;
    bool finalFrame = limitReached;
    if (limitReached && !settleStart) settleStart = Clock::now();
    const bool timedOut =
        settleStart && Clock::now() - *settleStart > std::chrono::milliseconds(kSettleTimeoutMs);
    frame(finalFrame, present);
    if (limitReached && timedOut && !finalFrame) {
      std::cerr << "twinraster-gui: warning: the frames did not settle within " << kSettleTimeoutMs / 1000
                << " s; the last frame shows what had finished\n";
      finalFrame = true;
    }
    if (present && windowShotRequested_) {
      windowShotRequested_ = false;
      const std::string path = screenshotStem(prefs_.screenshotDir, std::time(nullptr)) + "-window.png";
      try {
        saveWindowScreenshot(path);
        showScreenshotMessage("Saved the window as " + path);
      } catch (const std::exception& e) {
        showScreenshotMessage(std::string("Window screenshot failed: ") + e.what());
      }
    }
    if (finalFrame && !options_.screenshotPath.empty()) {
      try {
        saveWindowScreenshot(options_.screenshotPath);
      } catch (const std::exception& e) {
        std::cerr << "twinraster-gui: error: " << e.what() << "\n";
        exitCode = kExitBadInput;
      }
    }
    if (present) {
      glfwSwapBuffers(window_->window());
      ++framesDrawn;
      ++presentedFrames_;
      redraw_.frameDrawn();
    }
    if (finalFrame) break;
    idle = !keepDrawing();
    if (limitReached) {
      worker_.waitIdle(kSettlePoll);
      glWorker_->waitIdle(kSettlePoll);
    }
  }
  return exitCode;
}

void GuiApp::showScreenshotMessage(std::string message) {
  screenshotMessage_ = std::move(message);
  screenshotMessageTime_ = glfwGetTime();
  noteEvent();  // set after a frame was drawn (F12): it needs a frame of its own
}

void GuiApp::saveWindowScreenshot(const std::string& path) {
  int width = 0, height = 0;
  glfwGetFramebufferSize(window_->window(), &width, &height);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
  glReadBuffer(GL_BACK);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  std::vector<std::uint8_t> bottomFirst(static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 4);
  glReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, bottomFirst.data());
  const std::filesystem::path parent = std::filesystem::path(path).parent_path();
  if (!parent.empty()) {
    std::error_code code;
    std::filesystem::create_directories(parent, code);
  }
  savePng(path, imageFromBottomRows(width, height, bottomFirst));
}

void GuiApp::saveViewScreenshots() {
  const std::shared_ptr<const RenderOutput> cpu = cpuFrame_.output, gl = glFrame_.output;
  if (!cpu || !gl) {
    showScreenshotMessage("Nothing to save yet: both backends need a finished frame.");
    return;
  }
  try {
    std::error_code code;
    std::filesystem::create_directories(prefs_.screenshotDir.empty() ? "." : prefs_.screenshotDir, code);
    const std::string stem = screenshotStem(prefs_.screenshotDir, std::time(nullptr));
    const ViewMode shown = shownViewMode(prefs_.viewMode, glfwGetTime() - flickerStart_, prefs_.flickerHz);
    const Image view = viewScreenshotOf(*cpu, *gl, shown, prefs_, diff_.result);
    const std::string viewPath = stem + "-" + std::string(toString(prefs_.viewMode)) + ".png";
    savePng(viewPath, view);
    savePng(stem + "-cpu.png", rawImage(*cpu));
    savePng(stem + "-gl.png", rawImage(*gl));
    showScreenshotMessage("Saved " + viewPath + " and the -cpu.png / -gl.png beside it.");
  } catch (const std::exception& e) {
    showScreenshotMessage(std::string("Screenshot failed: ") + e.what());
  }
}

}  // namespace twr::gui
