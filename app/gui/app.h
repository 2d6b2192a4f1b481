// The desktop app: one window (glrender's GlfwContext), Dear ImGui panels around an image
// view, and both renderers on worker threads (the GL one in a headless EGL context of its
// own, gl_worker.h), so the UI keeps redrawing while they work. The member functions are spread over files by concern:
// app.cpp (window, loop, screenshots), app_renders.cpp (frames, diff, probes),
// panel_*.cpp (one per panel).
#pragma once

#include "gui/cpu_worker.h"
#include "gui/debug_views.h"
#include "gui/frame_pairing.h"
#include "gui/frame_timing.h"
#include "gui/gl_worker.h"
#include "gui/gui_options.h"
#include "gui/horizon_worker.h"
#include "app/gui/image_texture.h"
#include "gui/material_maps.h"
#include "gui/panel_sizing.h"
#include "gui/pixel_probe.h"
#include "gui/prefs.h"
#include "gui/redraw_policy.h"
#include "gui/scene_doc.h"
#include "gui/explorer_cache.h"
#include "gui/stage_explorer.h"
#include "app/gui/test_probe.h"
#include "compare/metrics.h"
#include "compare/pass_buffers.h"
#include "glrender/context_glfw.h"

#include <imgui.h>

#include <functional>
#include <map>
#include <tuple>
#include <memory>
#include <optional>
#include <set>
#include <string>

namespace twr::gui {

// A finished frame of one backend as the UI shows it.
struct BackendFrame {
  std::uint64_t revision = 0;                  // 0: none yet
  std::shared_ptr<const RenderOutput> output;  // null when the render threw
  std::string error;
  Clock::time_point finishedAt{};
  std::string cpuPath;  // CPU frames: the path that drew it, "teaching" or "fast (avx2)"
};

struct DiffState {
  std::uint64_t revision = 0;  // the revision both compared frames were rendered at; 0: none
  std::optional<CompareResult> result;
  std::string error;
  bool texturesStale = true;  // heat/class map textures need rebuilding
  // The frames compared and the buffer they were compared as (a new buffer re-diffs them).
  std::shared_ptr<const RenderOutput> cpu, gl;
  PassBuffer buffer = PassBuffer::Final;
};

// The pinned pixel and what each backend says about it.
struct PinState {
  std::optional<PixelPos> pixel;  // at the current render size (rescaled when it changes)
  std::uint64_t cpuRevision = 0;  // revision of `cpu`; 0: not probed yet
  std::optional<CpuProbe> cpu;
  std::uint64_t cpuAskedRevision = 0;  // the last probe job sent to the worker
  std::optional<PixelPos> cpuAskedPixel;
  std::uint64_t glRevision = 0;  // revision of `gl`; 0: not probed yet
  ViewSamples gl;
  std::string glError;
  std::optional<SsrMarchTrace> glMarch;  // the GL probe's march of its job's ray (frames with reflections)
  std::string glMarchError;
  std::vector<ShadowTapTrace> glShadowTaps;  // the GL probe's shadow tests, tap by tap (shadowed lights)
  std::string glShadowTapsError;
  std::uint64_t glAskedRevision = 0;  // the last probe job sent to the GL worker
  std::optional<PixelPos> glAskedPixel;
  int cpuAskedRay = kSsrMirrorRay;  // the ray of the last probe jobs
  int glAskedRay = kSsrMirrorRay;
};

// One copy of the scene at one edit, shared by the GL and the CPU job of that edit (never
// changed once made).
struct SceneSnapshot {
  std::uint64_t revision = 0;  // 0: none yet
  std::shared_ptr<const Scene> scene;
  int width = 0, height = 0;  // the render size, pixels
};

enum class DragMode { None, Orbit, Pan, Divider, Light };

class GuiApp {
 public:
  explicit GuiApp(GuiOptions options);
  ~GuiApp();
  GuiApp(const GuiApp&) = delete;
  GuiApp& operator=(const GuiApp&) = delete;

  // Runs until the window closes or --frames is reached; returns the exit code.
  int run();

 private:
  // ---- app.cpp ----
  void createWindow();
  void destroyWindow();
  void setUpImGuiStyle(float uiScale, float fontRasterScale);
  void openScene(const std::string& path);
  // One frame: the renders brought up to date, the panels laid out and (when `present`)
  // drawn into the back buffer. Unpresented frames only keep the test probe's state current.
  void frame(bool& finalFrame, bool present);
  void holdTappedKeys();
  bool settled() const;
  // Loop pacing (redraw_policy.h): an input or window event arrived (GLFW callbacks).
  void noteEvent();
  static void windowEvent(GLFWwindow* window);
  // A worker has a job queued or running / a finished one the UI has not taken.
  bool workRunning() const;
  bool resultsWaiting() const;
  // After a frame: whether the loop must keep drawing at the busy rate, rather than sleep
  // until something happens.
  bool keepDrawing() const;
  // Asks for the redraws ImGui's own timers need (text cursor blink, imgui.ini save).
  void scheduleImGuiTimers();
  void saveWindowScreenshot(const std::string& path);
  void saveViewScreenshots();
  void showScreenshotMessage(std::string message);

  // ---- app_renders.cpp ----
  void syncRenders();
  void takeCpuFrames();
  void takeGlFrames();
  void submitGl();
  void submitCpu();
  void keepGlTwins();
  void updateDiff();
  // diff_.result of diff_.cpu and diff_.gl as shownBuffer_ shows them.
  void computeDiff();
  // The frame as the buffer picker shows it: the buffer's picture, or the frame itself when it
  // does not hold that buffer (a forward frame's G-buffer targets).
  RenderOutput shownBufferOf(const RenderOutput& frame) const;
  void refreshTextures();
  bool renderInputsValid() const { return renderBlocker_.empty(); }
  // Checks the camera again: a panel drawn after an edit must not use a stale verdict.
  void refreshRenderBlocker();
  ShownRevisions shownRevisions() const;
  void pinPixel(std::optional<PixelPos> pixel);
  // Installs finished horizon maps and starts the next stale one once no widget is being edited.
  void syncHorizonMaps();
  // A horizon map is being built or waits to be (not counting one whose build failed).
  bool horizonMapsPending() const;
  // What the horizon maps are doing, one line for the user; empty when all are current.
  std::string horizonStatus() const;

  // ---- panels ----
  void drawLayout();
  // Draws one panel's contents; an exception thrown while drawing is caught, the panel's
  // ImGui stacks are unwound, and the message is shown in red at the panel's top.
  void drawGuarded(const char* panel, const std::function<void()>& draw);
  void drawPanelFault(const char* panel);
  void drawControlsPanel();
  void drawRenderingTab();
  void drawCpuRendererSection();
  void drawSceneTab();
  void drawNode(Node& node);
  void drawMeshEditor(int meshIndex);
  void drawMaterialsSection();
  void drawMapControls(std::size_t material, MapSlot slot);
  void drawHeightFieldControls(std::size_t material);
  bool drawEnvironmentControls(std::size_t material);
  // The parallax_steps view's heat ramp as a bar, labelled with the selected material's counts.
  void drawParallaxStepsLegend();
  void drawEnvironmentViewLegend(View view);
  bool drawEnvironmentCaptureControls(Environment& env);
  void drawEnvironmentSourceImages(const Environment& env);
  void drawShadowMapImages(std::size_t light);
  void showCachedImage(ImageTexture& texture, const void* source, std::uint64_t revision,
                       const std::function<Image()>& make, const char* label, ImVec2 size);  // the light's map as each renderer drew it, and their difference  // env_face's swatches, env_lod's heat bar
  void drawLightsSection();
  void drawCameraTab();
  void drawViewPanel();
  void drawViewToolbar();
  void drawViewToolbarRows();
  void drawDiffLegend();
  void drawViewCaption();
  void drawViewMessages(ImVec2 regionMin, ImVec2 regionSize);
  void drawImages(ImVec2 regionMin, ImVec2 regionSize);
  void handleImageMouse(ImVec2 regionMin, ImVec2 regionSize);
  void drawStatusLine();
  void drawStatsPanel();
  void drawInspectorPanel();
  void drawTraceSection(const PixelTrace& trace);
  void drawStageExplorerSection();
  void drawClipPassButtons();
  void drawVisitOrderControls(const ExplorerView& view);
  void drawWeightMapChoice();
  void drawVisitChoice();
  void drawClipPlot(const ExplorerView& view);
  // The explorer's view of the pinned pixel's triangle at the shown stage; none while the
  // trace is missing or of an older edit, or when no triangle reaches the pixel. `glSide`:
  // the pixels won are GL's frame's (its triangle ids), else the CPU's.
  std::shared_ptr<const ExplorerView> explorerView(bool glSide = false) const;
  void drawExplorerOverlay(ImDrawList* draw, const ExplorerView& view, ImVec2 imageMin, ImVec2 imageMax) const;
  void drawWeightMap(ImDrawList* draw, const ExplorerView& view, ImVec2 imageMin, ImVec2 imageMax) const;
  void drawViewProbeSection();
  void drawSsrMarchSection();
  void drawShadowTapsSection();

  GuiOptions options_;
  PrefsPaths paths_;
  GuiPrefs prefs_;
  std::string iniPath_;  // ImGui keeps a pointer to it
  std::string prefsWarning_;
  TestProbe probe_;

  std::unique_ptr<GlfwContext> window_;
  float uiScale_ = 1.0f;  // layout sizes in ImGui units per point at scale 1 (see the constructor)
  ImFont* monoFont_ = nullptr;  // the trace report; null: the default font
  CpuWorker worker_;
  HorizonWorker horizonWorker_;
  std::unique_ptr<GlWorker> glWorker_;  // made once the options are known, ended before the window

  SceneDoc doc_;
  std::string scenePathInput_;
  std::string sceneError_;
  std::string meshError_;
  int meshErrorIndex_ = -1;
  // Per (material, map), what the last option edit said: its warnings, or why it failed.
  struct MapMessage {
    std::string text;
    bool error = false;
  };
  std::map<std::pair<std::size_t, MapSlot>, MapMessage> mapMessages_;
  // The material whose tree node in the Scene tab was opened or edited last: the one the
  // parallax_steps legend counts layers for.
  std::size_t selectedMaterial_ = 0;
  // Per material, why the last height-field edit was refused.
  std::map<std::size_t, std::string> heightFieldErrors_;
  // The horizon map the worker is building (nullopt: none), and the last build that threw (not
  // tried again until its inputs change).
  std::optional<HorizonRequest> horizonBuilding_;
  std::optional<HorizonRequest> horizonFailed_;
  std::string horizonError_;
  std::string horizonLastBuild_;  // "'bricks': 8 directions in 0.41 s", for the status
  std::string renderBlocker_;  // why nothing is rendered right now (invalid camera), else empty
  // What float lets this camera show at the render size (scene/projection_checks.h): drawn, but
  // the user should know. Recomputed when the scene or the size changes.
  std::string projectionProblem_;
  std::vector<std::string> projectionWarnings_;
  std::uint64_t projectionCheckedRevision_ = 0;
  int projectionCheckedWidth_ = 0, projectionCheckedHeight_ = 0;

  int renderWidth_ = 0, renderHeight_ = 0;  // the size both backends render at
  ImVec2 imagePanelPixels_{0.0f, 0.0f};       // one image panel on screen, framebuffer pixels
  int toolbarRows_ = 2;  // rows the view toolbar took last frame: more when a narrow window wraps it

  BackendFrame cpuFrame_, glFrame_;
  std::uint64_t cpuSubmitted_ = 0;  // revision of the last full CPU job
  std::set<std::uint64_t> cpuPending_;  // revisions of full CPU jobs not back yet
  // The last snapshot sent to the GL worker. The CPU draws only such snapshots, so every CPU
  // frame has a GL twin of the same edit to diff against.
  SceneSnapshot glSnapshot_;
  // GL frames (null: the render threw) awaiting their CPU twin: of pending CPU jobs, and of
  // glSnapshot_ (the CPU's next job).
  std::map<std::uint64_t, std::shared_ptr<const RenderOutput>> glForCpu_;
  FrameTimes cpuMs_, glMs_;
  // What the timings were taken at; a change restarts them (see frame_timing.h).
  int timedWidth_ = 0, timedHeight_ = 0;
  std::string timedCpuPath_;
  std::uint64_t timingsFromRevision_ = 0;  // CPU frames of older edits (another scene) are not timed
  DiffState diff_;
  PinState pin_;
  // The stage explorer: the stage shown, and whether its section is open (its overlay is drawn
  // over the images only then).
  ExplorerStage explorerStage_ = ExplorerStage::Vertex;
  int explorerClipPass_ = -1;  // the clipper's pass the Clip stage draws, -1: the final polygon
  int explorerVisit_ = -1;  // the trace's visit followed (a triangle under the pixel), -1: the one that wrote it
  int explorerRasterStep_ = -1;  // the Raster stage's step of the visit order, -1: none shown
  bool explorerPerspectiveMap_ = false;  // Interpolate maps the perspective weights, else the screen ones
  ClipPlotAxes explorerClipAxes_ = ClipPlotAxes::XW;  // the Clip stage's plot
  bool explorerOpen_ = false;
  mutable ExplorerViewCache explorerViews_[2];  // CPU's, GL's (gui/explorer_cache.h)
  mutable ImageTexture explorerWeightTexture_;
  using WeightMapKey = std::tuple<std::shared_ptr<const PixelTrace>, int, bool>;  // trace, visit, perspective
  mutable std::optional<WeightMapKey> explorerWeightKey_;  // the map the texture holds
  // The ray the inspector's SSR march follows: the mirror ray or indirect sample k (kept across
  // pinned pixels; the mirror ray while the settings have no sample k, as in an SSR view).
  int ssrTraceRay_ = kSsrMirrorRay;
  static int ssrTraceSamples(const RenderSettings& settings) {
    return isSsrView(settings.view) ? 0 : settings.ssr.indirectSamples;
  }
  int ssrTraceRayOf(const RenderSettings& settings) const {
    return ssrTraceRay_ < ssrTraceSamples(settings) ? ssrTraceRay_ : kSsrMirrorRay;
  }

  ImageTexture cpuTexture_, glTexture_, heatTexture_, classTexture_;
  // The environment's cube cross (Scene tab): a loaded cube's, or each renderer's captured faces,
  // with what each texture was last made from (re-uploaded when that changes).
  ImageTexture sourceCrossTexture_, captureCpuTexture_, captureGlTexture_;
  ImageTexture shadowCpuTexture_, shadowGlTexture_, shadowDiffTexture_;
  // The shadow maps' comparison shown, and the (light, CPU revision, GL revision) it is of.
  DepthBufferMetrics shadowDiffMetrics_;
  std::tuple<std::size_t, std::uint64_t, std::uint64_t> shadowDiffKey_{};
  std::map<const ImageTexture*, std::pair<const void*, std::uint64_t>> crossSources_;
  bool cpuTextureStale_ = true, glTextureStale_ = true;
  // What the images show of each frame (the buffer picker beside the debug views).
  PassBuffer shownBuffer_ = PassBuffer::Final;

  RedrawPolicy redraw_;
  long presentedFrames_ = 0;  // frames drawn on screen (the test probe's "presented")

  DragMode dragMode_ = DragMode::None;
  bool interacting_ = false;  // last frame: a drag over the image or an active widget (the GL probe waits)
  int dragLight_ = -1;  // the light a DragMode::Light moves
  ImVec2 pressPos_{0.0f, 0.0f};
  bool dragged_ = false;
  std::optional<PixelPos> hovered_;
  std::string screenshotMessage_;
  double screenshotMessageTime_ = 0.0;  // glfwGetTime() when it was set
  bool windowShotRequested_ = false;  // F12: save the whole window after this frame is drawn
  bool selectSceneTab_ = false;       // show the Scene tab once (a scene failed to open)
  double flickerStart_ = 0.0;
  float leftPanelWidth_ = 0.0f, bottomPanelHeight_ = 0.0f;  // as shown this frame, ImGui units
  std::string pinWarning_;  // why the --pin pixel could not be pinned
  std::string lightsHint_;
  EyeRange linearDepthRange_;  // the grey ramp of the linearised depth view, world units  // which lights are ticked but off screen, else empty
  bool commandLinePinChecked_ = false;
  // Per panel, the last exception its drawing threw and when (glfwGetTime(), seconds).
  struct PanelFault {
    std::string message;
    double time = 0.0;
  };
  std::map<std::string, PanelFault> panelFaults_;
  // Keys pressed and released between two frames: ImGui 1.86 only sees a key held at a
  // frame's start, so such a tap is held down for one frame (keyLatch in app.cpp).
  std::set<int> keysPressedSinceFrame_, keysToHold_, keysHeld_;
};

}  // namespace twr::gui
