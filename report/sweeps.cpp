#include "report/sweeps.h"

#include "report/analytic_sphere.h"
#include "report/height_fields.h"
#include "report/reading.h"
#include "compare/colours.h"
#include "compare/draw.h"
#include "compare/interior.h"
#include "compare/metrics.h"
#include "compare/montage.h"
#include "compare/side_by_side.h"
#include "compare/timing.h"
#include "glrender/gl_renderer.h"
#include "raytrace/ssr_reference_report.h"
#include "scene/environment_error.h"
#include "scene/environment_light.h"
#include "scene/environment_specular.h"
#include "scene/errors.h"
#include "scene/primitives.h"
#include "scene/scene_file.h"
#include "scene/statistics.h"
#include "scene/texture.h"
#include "softrender/cpu_renderer.h"
#include "softrender/reference_renderer.h"
#include "softrender/shadow_reference.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <optional>
#include <memory>
#include <sstream>
#include <thread>

namespace twr::report {

namespace {

// N of the N x N reference (16 samples per pixel): enough that edge coverage is known to
// 1/16 and the texture is averaged over the pixel footprint.
constexpr int kReferenceSamplesPerAxis = 4;
constexpr int kWarmupFrames = 1;        // renders before timing (caches, JIT, first context)
constexpr int kFramesDefault = 9;       // timed frames per point
constexpr int kFramesQuick = 2;
constexpr int kWidthDefault = 320, kHeightDefault = 240;  // pixels, most knobs
constexpr int kWidthQuick = 160, kHeightQuick = 120;
// Settings of the precision knob timed through the reference renderer's loop.
constexpr const char* kFloatLoop = "float, same loop";
constexpr const char* kDoubleLoop = "double, same loop";
// Timing runs per basis construction; the fastest counts.
constexpr int kBasisTimingRepetitions = 5;
// Height-field section (docs/report.md, "Height fields"). The view angles the issue names,
// degrees from the plane's normal; the layer counts ([min, max] parallax_layers) each marching
// method runs at (quick: two of them); the angle the pictures show; the 720p cost line.
constexpr int kHeightFieldAngles[] = {0, 45, 70, 85};
constexpr int kHeightFieldPictureAngle = 70;
constexpr int kCostWidth = 1280, kCostHeight = 720;  // pixels
constexpr int kCostAngle = 45;                       // degrees, bricks
constexpr int kCostFrames = 9;                       // frames of each, at least (in turn)
// N of the N x N samples of the displaced-mesh reference in quick runs: one, the plain double
// pipeline (16 passes over a 524,288-triangle mesh take about 8 s a view here).
constexpr int kHeightReferenceSamplesQuick = 1;
constexpr int kLegendMarginPx = 6;       // text inset in a legend tile
constexpr int kLegendLineWidthPx = 160;  // a legend tile this wide or wider (twice) draws at scale 2
// Magic at the start of a child's output file, and the file layout version.
constexpr char kChildMagic[8] = {'T', 'W', 'R', 'G', 'L', 'C', 'H', '1'};

struct Timing {
  double msMedian = 0.0, msMin = 0.0;
  int frames = 0;
};

// One warm-up render, then `frames` timed ones; `out` keeps the last image.
Timing timeRenderer(Renderer& renderer, const Scene& scene, const RenderSettings& settings, int width, int height,
                    int frames, RenderOutput& out) {
  for (int i = 0; i < kWarmupFrames; ++i) out = renderer.render(scene, settings, width, height);
  std::vector<double> ms;
  for (int i = 0; i < frames; ++i) {
    const auto start = std::chrono::steady_clock::now();
    out = renderer.render(scene, settings, width, height);
    ms.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
  }
  Timing t;
  t.msMedian = medianOf(ms);
  t.msMin = *std::min_element(ms.begin(), ms.end());
  t.frames = frames;
  return t;
}

// Two scenes on one renderer, frame by frame in turn (a, b, a, b, ...): a slower spell of the
// machine weighs on both alike, which is what a cost stated as a multiple of another needs.
std::pair<Timing, Timing> timeScenesInTurn(Renderer& renderer, const Scene& a, const Scene& b, int width, int height,
                                           int frames) {
  RenderOutput out;
  for (int i = 0; i < kWarmupFrames; ++i) {
    out = renderer.render(a, a.settings, width, height);
    out = renderer.render(b, b.settings, width, height);
  }
  std::vector<double> msA, msB;
  for (int i = 0; i < frames; ++i) {
    for (const Scene* scene : {&a, &b}) {
      const auto start = std::chrono::steady_clock::now();
      out = renderer.render(*scene, scene->settings, width, height);
      (scene == &a ? msA : msB).push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
    }
  }
  const auto timing = [frames](const std::vector<double>& ms) {
    Timing t;
    t.msMedian = medianOf(ms);
    t.msMin = *std::min_element(ms.begin(), ms.end());
    t.frames = frames;
    return t;
  };
  return {timing(msA), timing(msB)};
}

ReportPoint makePoint(const std::string& setting, const std::string& backend, const Timing& timing,
                      const CompareMetrics& vsReference) {
  ReportPoint p;
  p.setting = setting;
  p.backend = backend;
  p.msMedian = timing.msMedian;
  p.msMin = timing.msMin;
  p.frames = timing.frames;
  p.vsReference = vsReference;
  return p;
}

std::string sizeText(int width, int height) { return std::to_string(width) + "x" + std::to_string(height); }

std::string fmtFixed(double value, int decimals) {
  std::ostringstream s;
  s << std::fixed << std::setprecision(decimals) << value;
  return s.str();
}

// A tile of one colour with a few lines of text: the key under a montage's reference column.
Image legendTile(int width, int height, const std::vector<std::string>& lines) {
  Image tile = makeImage(width, height);
  fillRect(tile, 0, 0, width, height, kColourPanel);
  const int scale = width >= 2 * kLegendLineWidthPx ? 2 : 1;
  int y = kLegendMarginPx;
  for (const std::string& line : lines) {
    drawText(tile, kLegendMarginPx, y, line, kColourWhite, scale);
    y += kFontLineHeightUnits * scale;
  }
  return tile;
}

// Shared state of one report run.
class Sweeper {
 public:
  Sweeper(const ReportOptions& options, std::ostream& progress)
      : options_(options), progress_(progress), start_(std::chrono::steady_clock::now()) {
    frames_ = options.quick ? kFramesQuick : kFramesDefault;
    width_ = options.quick ? kWidthQuick : kWidthDefault;
    height_ = options.quick ? kHeightQuick : kHeightDefault;
  }

  ReportData run();

 private:
  void say(const std::string& what) {
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    progress_ << "[report " << std::fixed << std::setprecision(1) << std::setw(6) << seconds << " s] " << what
              << std::endl;
  }
  std::string scenePath(const std::string& name) const { return options_.assetsDir + "/scenes/" + name; }
  Renderer& gl() {
    if (!gl_) gl_ = makeGlRenderer(options_.gl);
    return *gl_;
  }
  RenderOutput reference(const Scene& scene, const RenderSettings& settings, int width, int height,
                         const std::string& what);

  // Both backends at one setting, against `reference`; the GL row also carries CPU vs GL.
  void measureBoth(KnobResult& knob, const std::string& setting, const Scene& scene, const RenderSettings& settings,
                   int width, int height, const RenderOutput& reference, RenderOutput* cpuCopy = nullptr,
                   RenderOutput* glCopy = nullptr);
  ReportPoint measureOne(const std::string& knobId, const std::string& setting, const std::string& backend,
                         Renderer& renderer, const Scene& scene, const RenderSettings& settings, int width,
                         int height, const RenderOutput& reference, RenderOutput* outputCopy = nullptr);

  // GL in a child process: a new llvmpipe with its own GALLIVM_PERF and LP_NUM_THREADS.
  bool measureGlChild(KnobResult& knob, const std::string& setting, const std::string& sceneFile, int width,
                      int height, bool fastSampling, int llvmpipeThreads, const RenderOutput& reference,
                      const RenderOutput* cpuOutput, RenderOutput* glCopy = nullptr);

  KnobResult tessellation();
  KnobResult minification();
  KnobResult twoSettings(const std::string& id);
  KnobResult glSampling();
  KnobResult resolution();
  KnobResult threads();
  KnobResult precision();
  void heightFields(HeightFieldSection& section, const std::string& outDir);
  ReportPoint measureHeightPoint(const std::string& viewId, const HeightFieldPointInfo& info,
                                 const std::string& setting, const std::string& backend, Renderer& renderer,
                                 const Scene& scene, int width, int height, const RenderOutput& reference,
                                 RenderOutput* outputCopy);
  void bases(ReportData& data);
  void parameterizations(ParameterizationSection& section, const std::string& outDir);
  void diffuseLight(DiffuseLightSection& section, const std::string& outDir);
  void glossy(GlossySection& section, const std::string& outDir);
  void shadows(ShadowSection& section, const std::string& outDir);
  void ssr(SsrSection& section, const std::string& outDir);
  // The asset tool's sky as a cube, or nothing with `skipped` saying why.
  std::optional<CubeMap> loadSky(std::string& skipped) const;

  const ReportOptions& options_;
  std::ostream& progress_;
  std::chrono::steady_clock::time_point start_;
  int frames_ = kFramesDefault;
  int width_ = kWidthDefault, height_ = kHeightDefault;
  std::unique_ptr<Renderer> gl_;  // in-process llvmpipe, precise sampling
  int childCount_ = 0;
};

RenderOutput Sweeper::reference(const Scene& scene, const RenderSettings& settings, int width, int height,
                                const std::string& what) {
  say(what + ": reference (double, " + std::to_string(kReferenceSamplesPerAxis) + "x" +
      std::to_string(kReferenceSamplesPerAxis) + " samples) at " + sizeText(width, height));
  ReferenceOptions options;
  options.samplesPerAxis = kReferenceSamplesPerAxis;
  options.threads = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  return makeReferenceRenderer(options)->render(scene, settings, width, height);
}

ReportPoint Sweeper::measureOne(const std::string& knobId, const std::string& setting, const std::string& backend,
                                Renderer& renderer, const Scene& scene, const RenderSettings& settings, int width,
                                int height, const RenderOutput& reference, RenderOutput* outputCopy) {
  RenderOutput out;
  const Timing timing = timeRenderer(renderer, scene, settings, width, height, frames_, out);
  ReportPoint p = makePoint(setting, backend, timing, compare(out, reference));
  std::ostringstream line;
  line << knobId << " " << setting << ", " << backend << ": " << std::fixed << std::setprecision(2) << p.msMedian
       << " ms median, " << p.msMin << " fastest, rmse " << p.vsReference.rmse << " levels vs reference";
  say(line.str());
  if (outputCopy) *outputCopy = std::move(out);
  return p;
}

void Sweeper::measureBoth(KnobResult& knob, const std::string& setting, const Scene& scene,
                          const RenderSettings& settings, int width, int height, const RenderOutput& reference,
                          RenderOutput* cpuCopy, RenderOutput* glCopy) {
  std::unique_ptr<Renderer> cpu = makeCpuRenderer();
  RenderOutput cpuOut, glOut;
  knob.points.push_back(measureOne(knob.id, setting, "cpu", *cpu, scene, settings, width, height, reference, &cpuOut));
  ReportPoint glPoint = measureOne(knob.id, setting, "gl", gl(), scene, settings, width, height, reference, &glOut);
  glPoint.cpuVsGl = compare(cpuOut, glOut);
  knob.points.push_back(std::move(glPoint));
  if (cpuCopy) *cpuCopy = std::move(cpuOut);
  if (glCopy) *glCopy = std::move(glOut);
}

// Marks the shortcut rows of `knob` (setting `shortcut`) with their difference from the same
// backend at the exact setting.
void addVsExact(KnobResult& knob, const std::string& shortcut, const std::string& exact, const std::string& backend,
                const RenderOutput& shortcutOut, const RenderOutput& exactOut) {
  for (ReportPoint& p : knob.points) {
    if (p.setting == shortcut && p.backend == backend) {
      p.vsExactSetting = compare(shortcutOut, exactOut);
      p.exactSetting = exact;
    }
  }
}

// The child's output file: magic, width, height (int32), frames (int32), ms median and min
// (double), then RGBA8 top row first. Written and read on the same machine.
void writeChildFile(const std::string& path, const RenderOutput& out, const Timing& timing) {
  std::ofstream file(path, std::ios::binary);
  const std::int32_t header[3] = {out.width, out.height, timing.frames};
  const double ms[2] = {timing.msMedian, timing.msMin};
  file.write(kChildMagic, sizeof kChildMagic);
  file.write(reinterpret_cast<const char*>(header), sizeof header);
  file.write(reinterpret_cast<const char*>(ms), sizeof ms);
  file.write(reinterpret_cast<const char*>(out.rgba.data()), static_cast<std::streamsize>(out.rgba.size()));
  if (!file) throw InputError("report: cannot write '" + path + "'");
}

bool readChildFile(const std::string& path, RenderOutput& out, Timing& timing) {
  std::ifstream file(path, std::ios::binary);
  char magic[sizeof kChildMagic];
  std::int32_t header[3];
  double ms[2];
  file.read(magic, sizeof magic);
  file.read(reinterpret_cast<char*>(header), sizeof header);
  file.read(reinterpret_cast<char*>(ms), sizeof ms);
  if (!file || std::memcmp(magic, kChildMagic, sizeof magic) != 0 || header[0] < 1 || header[1] < 1 ||
      header[0] > kMaxImageSide || header[1] > kMaxImageSide) {
    return false;
  }
  out = RenderOutput{};
  out.width = header[0];
  out.height = header[1];
  out.rgba.resize(static_cast<std::size_t>(out.width) * static_cast<std::size_t>(out.height) * 4);
  file.read(reinterpret_cast<char*>(out.rgba.data()), static_cast<std::streamsize>(out.rgba.size()));
  timing.frames = header[2];
  timing.msMedian = ms[0];
  timing.msMin = ms[1];
  return static_cast<bool>(file);
}

// Runs `argv` with this process's environment minus GALLIVM_PERF (the child picks its own
// sampling mode) and with LP_NUM_THREADS set when `llvmpipeThreads` > 0. Returns the exit
// code, or -1 when it could not start or did not exit normally.
int runGlChildProcess(const std::vector<std::string>& argv, int llvmpipeThreads, const std::string& stderrPath) {
  ChildProcess child;
  child.argv = argv;
  child.unsetVariables = {"GALLIVM_PERF", "LP_NUM_THREADS"};
  if (llvmpipeThreads > 0) child.setVariables = {{"LP_NUM_THREADS", std::to_string(llvmpipeThreads)}};
  child.stderrPath = stderrPath;
  return runChildProcess(child).exitCode;
}

std::string firstLine(const std::string& path) {
  std::ifstream file(path);
  std::string line;
  std::getline(file, line);
  return line;
}

bool Sweeper::measureGlChild(KnobResult& knob, const std::string& setting, const std::string& sceneFile, int width,
                             int height, bool fastSampling, int llvmpipeThreads, const RenderOutput& reference,
                             const RenderOutput* cpuOutput, RenderOutput* glCopy) {
  const std::string stem = options_.workDir + "/gl_child_" + std::to_string(childCount_++);
  std::vector<std::string> argv = {options_.selfExecutable, "report-gl-child", sceneFile,
                                   "--width", std::to_string(width), "--height", std::to_string(height),
                                   "--frames", std::to_string(frames_), "--out", stem + ".bin"};
  if (fastSampling) argv.push_back("--fast-sampling");
  for (const std::string& argument : options_.glChildArguments) argv.push_back(argument);
  const int code = runGlChildProcess(argv, llvmpipeThreads, stem + ".stderr.txt");
  RenderOutput out;
  Timing timing;
  if (code != 0 || !readChildFile(stem + ".bin", out, timing) || out.width != width || out.height != height) {
    knob.skipped = "the GL child process failed (exit " + std::to_string(code) + "): " + firstLine(stem + ".stderr.txt");
    say(knob.id + " " + setting + ": " + knob.skipped);
    return false;
  }
  ReportPoint p = makePoint(setting, "gl", timing, compare(out, reference));
  if (cpuOutput) p.cpuVsGl = compare(*cpuOutput, out);
  std::ostringstream line;
  line << knob.id << " " << setting << ", gl (child process): " << std::fixed << std::setprecision(2) << p.msMedian
       << " ms median, " << p.msMin << " fastest, rmse " << p.vsReference.rmse << " levels vs reference";
  say(line.str());
  knob.points.push_back(std::move(p));
  if (glCopy) *glCopy = std::move(out);
  std::filesystem::remove(stem + ".bin");
  std::filesystem::remove(stem + ".stderr.txt");
  return true;
}

// A lit, textured sphere alone at the origin, the scene of the tessellation knob.
Scene sphereScene(const std::shared_ptr<const Texture>& albedo, int stacks, int slices) {
  Scene scene;
  scene.camera.position = vec3(0.0f, 0.6f, 3.0f);
  scene.camera.target = vec3(0.0f);
  scene.camera.fovDeg = 45.0f;
  scene.camera.near = 0.1f;
  scene.camera.far = 20.0f;
  scene.ambient = vec3(0.1f);
  Light light;
  light.posWorld = vec3(2.5f, 2.0f, 3.0f);
  light.attenuation = vec3(1.0f, 0.0f, 0.0f);
  scene.lights.push_back(light);
  Material material;
  material.name = "bricks";
  material.kd = vec3(0.9f);
  material.ks = vec3(0.6f);
  material.shininess = 48.0f;
  material.diffuseMap = albedo;
  scene.materials.push_back(material);
  MeshDesc desc;
  desc.type = MeshType::Sphere;
  desc.radius = 1.0f;
  desc.stacks = stacks;
  desc.slices = slices;
  scene.meshDescs.push_back(desc);
  scene.meshes.push_back(buildMesh(desc));
  Node node;
  node.name = "sphere";
  node.meshIndex = 0;
  node.materialIndex = 0;
  scene.nodes.push_back(node);
  return scene;
}

KnobResult Sweeper::tessellation() {
  KnobResult knob;
  knob.id = "tessellation";
  knob.title = "Sphere tessellation (stacks x slices)";
  knob.question = "More triangles follow the round silhouette, the smooth normal and the uv mapping more closely, "
                  "at the cost of vertex work and more, smaller triangles.";
  knob.reference = "The exact sphere, ray-traced in double with " + std::to_string(kReferenceSamplesPerAxis) + "x" +
                   std::to_string(kReferenceSamplesPerAxis) +
                   " samples per pixel and shaded by the pipeline's own fragment stage from the analytic "
                   "position, normal, tangent and uv (report/analytic_sphere.cpp).";
  knob.scene = "a unit sphere with the brick albedo map and a specular highlight, " + sizeText(width_, height_);
  auto albedo = std::make_shared<const Texture>(loadTexture(options_.assetsDir + "/textures/bricks_diffuse.png"));
  const Scene exact = sphereScene(albedo, 4, 8);
  say("tessellation: analytic sphere reference (ray traced, " + std::to_string(kReferenceSamplesPerAxis) + "x" +
      std::to_string(kReferenceSamplesPerAxis) + " samples) at " + sizeText(width_, height_));
  const RenderOutput reference = renderAnalyticSphere(exact, exact.settings, width_, height_, kReferenceSamplesPerAxis);
  const std::vector<int> stacks = options_.quick ? std::vector<int>{4, 16, 64, 256}
                                                 : std::vector<int>{4, 8, 16, 32, 64, 128, 256};
  for (int s : stacks) {
    const Scene scene = sphereScene(albedo, s, 2 * s);
    measureBoth(knob, std::to_string(s) + "x" + std::to_string(2 * s), scene, scene.settings, width_, height_,
                reference);
  }
  return knob;
}

// A floor seen at grazing angles: 200 x 200 world units, the brick albedo repeating 100 times
// across, the camera 0.6 units above it looking at the horizon. Albedo view, so only texture
// filtering differs between the settings.
Scene grazingFloorScene(const std::shared_ptr<const Texture>& albedo) {
  Scene scene;
  scene.camera.position = vec3(0.0f, 0.6f, 4.0f);
  scene.camera.target = vec3(0.0f, 0.0f, -40.0f);
  scene.camera.fovDeg = 60.0f;
  scene.camera.near = 0.1f;
  scene.camera.far = 300.0f;
  scene.output.background = vec4(0.0f, 0.0f, 0.0f, 1.0f);
  Material material;
  material.diffuseMap = albedo;
  scene.materials.push_back(material);
  constexpr float kFloorSide = 200.0f;  // world units
  constexpr float kRepeats = 100.0f;    // the texture across the floor
  MeshDesc desc;
  desc.type = MeshType::Plane;
  desc.planeSize = vec2(kFloorSide);
  desc.uvScale = kRepeats;
  scene.meshDescs.push_back(desc);
  scene.meshes.push_back(makePlane(desc.planeSize, desc.uvScale));
  Node node;
  node.name = "floor";
  node.meshIndex = 0;
  node.materialIndex = 0;
  scene.nodes.push_back(node);
  scene.settings.view = View::Albedo;
  scene.settings.cull = CullMode::None;
  return scene;
}

std::string anisotropicSetting(float ratio) {
  return "trilinear_aniso_" + std::to_string(static_cast<int>(ratio)) + "x";
}

KnobResult Sweeper::minification() {
  KnobResult knob;
  knob.id = "minification";
  knob.title = "Minification: mipmaps on a grazing floor";
  // N of the N x N reference: a pixel near the horizon covers hundreds of texels, so the
  // reference averages many more samples than the other knobs' (256 per pixel; quick: 64).
  const int samples = options_.quick ? 8 : 16;
  knob.question = "Far away a pixel covers many texels: sampling level 0 (nearest, bilinear) picks a few of them "
                  "and aliases; mipmaps read a pre-averaged level chosen by the LOD of each 2x2 quad, blending two "
                  "levels with trilinear, but one LOD per pixel blurs along the floor's short axis as much as its "
                  "long one. Anisotropic filtering (llvmpipe's elliptical weighted average) reads the level of the "
                  "footprint's short axis and averages along the long one.";
  knob.reference = "The same stages in double with bilinear filtering of level 0 and " + std::to_string(samples) + "x" +
                   std::to_string(samples) + " samples per pixel (box filter): the texture averaged over each "
                   "pixel's footprint.";
  knob.scene = "a 200 x 200 floor with the brick albedo repeated 100 times, camera 0.6 above it, albedo view, " +
               sizeText(width_, height_);
  auto albedo = std::make_shared<const Texture>(loadTexture(options_.assetsDir + "/textures/bricks_diffuse.png"));
  const Scene scene = grazingFloorScene(albedo);
  RenderSettings exact = scene.settings;
  exact.textureFilter = TextureFilter::Bilinear;
  say("minification: reference (double, " + std::to_string(samples) + "x" + std::to_string(samples) + " samples) at " +
      sizeText(width_, height_));
  ReferenceOptions options;
  options.samplesPerAxis = samples;
  options.threads = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  const RenderOutput ref = makeReferenceRenderer(options)->render(scene, exact, width_, height_);
  for (const TextureFilter filter : kAllTextureFilters) {
    RenderSettings settings = scene.settings;
    settings.textureFilter = filter;
    measureBoth(knob, std::string(toString(filter)), scene, settings, width_, height_, ref);
  }
  // Anisotropy on the trilinear chain (on level 0 each far pixel's ellipse would hold thousands
  // of texels: minutes per frame on both renderers). 2x and 16x, to show that llvmpipe's filter
  // does not depend on the ratio (quick: 16x only).
  const std::vector<float> ratios = options_.quick ? std::vector<float>{16.0f} : std::vector<float>{2.0f, 16.0f};
  for (const float ratio : ratios) {
    RenderSettings settings = scene.settings;
    settings.textureFilter = TextureFilter::Trilinear;
    settings.anisotropy = ratio;
    measureBoth(knob, anisotropicSetting(ratio), scene, settings, width_, height_, ref);
  }
  return knob;
}

// The knobs with two settings measured on an asset scene: texture filter, lighting space,
// tangent transform. The reference uses the exact setting (bilinear, world, model).
KnobResult Sweeper::twoSettings(const std::string& id) {
  KnobResult knob;
  knob.id = id;
  std::string sceneFile = "default.json";
  if (id == "texture_filter") {
    knob.title = "Texture filter";
    knob.question = "Bilinear filtering blends four texels per sample where nearest reads one.";
    knob.reference = "The same stages in double with bilinear filtering and " + std::to_string(kReferenceSamplesPerAxis) +
                     "x" + std::to_string(kReferenceSamplesPerAxis) + " samples per pixel (box filter).";
  } else if (id == "lighting_space") {
    knob.title = "Lighting space";
    knob.question = "Tangent-space lighting moves the light and eye vectors into each vertex's tangent frame and "
                    "interpolates them, saving the per-pixel TBN multiply at the cost of interpolating directions "
                    "that should be recomputed per pixel.";
    knob.reference = "The same stages in double with world-space lighting and " +
                     std::to_string(kReferenceSamplesPerAxis) + "x" + std::to_string(kReferenceSamplesPerAxis) +
                     " samples per pixel.";
  } else {
    sceneFile = "nonuniform_scale.json";
    knob.title = "Tangent transform under non-uniform scale";
    knob.question = "Tangents lie in the surface and transform with the model matrix; transforming them with the "
                    "normal matrix (inverse transpose) is a common mistake that only shows under non-uniform scale.";
    knob.reference = "The same stages in double with tangents transformed by the model matrix and " +
                     std::to_string(kReferenceSamplesPerAxis) + "x" + std::to_string(kReferenceSamplesPerAxis) +
                     " samples per pixel.";
  }
  const Scene scene = loadSceneFile(scenePath(sceneFile));
  knob.scene = "assets/scenes/" + sceneFile + ", " + sizeText(width_, height_);
  RenderSettings exact = scene.settings;
  RenderSettings other = scene.settings;
  std::string exactName, otherName;
  if (id == "texture_filter") {
    exact.textureFilter = TextureFilter::Bilinear;
    other.textureFilter = TextureFilter::Nearest;
    exactName = "bilinear";
    otherName = "nearest";
  } else if (id == "lighting_space") {
    exact.lightingSpace = LightingSpace::World;
    other.lightingSpace = LightingSpace::Tangent;
    exactName = "world";
    otherName = "tangent";
  } else {
    exact.tangentTransform = TangentTransform::Model;
    other.tangentTransform = TangentTransform::InverseTranspose;
    exactName = "model";
    otherName = "inverse_transpose";
  }
  const RenderOutput ref = reference(scene, exact, width_, height_, id);
  RenderOutput cpuShortcut, glShortcut, cpuExact, glExact;
  measureBoth(knob, otherName, scene, other, width_, height_, ref, &cpuShortcut, &glShortcut);
  measureBoth(knob, exactName, scene, exact, width_, height_, ref, &cpuExact, &glExact);
  addVsExact(knob, otherName, exactName, "cpu", cpuShortcut, cpuExact);
  addVsExact(knob, otherName, exactName, "gl", glShortcut, glExact);
  return knob;
}

KnobResult Sweeper::glSampling() {
  KnobResult knob;
  knob.id = "gl_sampling";
  knob.title = "llvmpipe texture sampling: precise versus fast";
  knob.question = "llvmpipe's default (fast) path uses 8-bit bilinear weights and one level of detail per 2x2 "
                  "quad; GALLIVM_PERF=no_aos_sampling,no_quad_lod makes it exact. llvmpipe reads the variable "
                  "once per process, so each point runs in its own child process.";
  knob.reference = "The same stages in double, bilinear, " + std::to_string(kReferenceSamplesPerAxis) + "x" +
                   std::to_string(kReferenceSamplesPerAxis) + " samples per pixel.";
  const std::string file = scenePath("default.json");
  knob.scene = "assets/scenes/default.json, " + sizeText(width_, height_);
  const Scene scene = loadSceneFile(file);
  const RenderOutput ref = reference(scene, scene.settings, width_, height_, knob.id);
  RenderOutput cpuOut;
  std::unique_ptr<Renderer> cpu = makeCpuRenderer();
  knob.points.push_back(measureOne(knob.id, "cpu pipeline", "cpu", *cpu, scene, scene.settings, width_, height_, ref, &cpuOut));
  RenderOutput precise, fast;
  if (!measureGlChild(knob, "precise", file, width_, height_, false, 0, ref, &cpuOut, &precise)) return knob;
  if (measureGlChild(knob, "fast", file, width_, height_, true, 0, ref, &cpuOut, &fast)) {
    addVsExact(knob, "fast", "precise", "gl", fast, precise);
  }
  return knob;
}

KnobResult Sweeper::resolution() {
  KnobResult knob;
  knob.id = "resolution";
  knob.title = "Resolution";
  knob.question = "Time grows with the pixel count; the error against a reference of the same size measures the "
                  "aliasing and interpolation error per pixel.";
  knob.reference = "The same stages in double with " + std::to_string(kReferenceSamplesPerAxis) + "x" +
                   std::to_string(kReferenceSamplesPerAxis) + " samples per pixel, at each resolution.";
  knob.scene = "assets/scenes/default.json";
  const Scene scene = loadSceneFile(scenePath("default.json"));
  const std::vector<std::pair<int, int>> sizes =
      options_.quick ? std::vector<std::pair<int, int>>{{80, 60}, {160, 120}, {320, 240}}
                     : std::vector<std::pair<int, int>>{{160, 120}, {320, 240}, {640, 480}, {1280, 960}};
  for (const auto& [w, h] : sizes) {
    const RenderOutput ref = reference(scene, scene.settings, w, h, knob.id);
    measureBoth(knob, sizeText(w, h), scene, scene.settings, w, h, ref);
  }
  return knob;
}

KnobResult Sweeper::threads() {
  KnobResult knob;
  knob.id = "threads";
  knob.title = "Thread count";
  const unsigned hardware = std::max(1u, std::thread::hardware_concurrency());
  knob.question = "The CPU pipeline splits rows into bands, one per thread (CpuOptions::threads); llvmpipe splits "
                  "the screen into tiles over LP_NUM_THREADS threads (set per child process). The image does not "
                  "change, only the time. This machine reports " + std::to_string(hardware) + " hardware threads.";
  knob.reference = "The same stages in double with " + std::to_string(kReferenceSamplesPerAxis) + "x" +
                   std::to_string(kReferenceSamplesPerAxis) + " samples per pixel.";
  const std::string file = scenePath("default.json");
  const int w = options_.quick ? kWidthQuick : 640, h = options_.quick ? kHeightQuick : 480;
  knob.scene = "assets/scenes/default.json, " + sizeText(w, h);
  const Scene scene = loadSceneFile(file);
  const RenderOutput ref = reference(scene, scene.settings, w, h, knob.id);
  const std::vector<int> counts = options_.quick ? std::vector<int>{1, 2} : std::vector<int>{1, 2, 4};
  for (int n : counts) {
    CpuOptions cpuOptions;
    cpuOptions.threads = n;
    std::unique_ptr<Renderer> cpu = makeCpuRenderer(cpuOptions);
    const std::string setting = std::to_string(n) + (n == 1 ? " thread" : " threads");
    RenderOutput cpuOut;
    knob.points.push_back(measureOne(knob.id, setting, "cpu", *cpu, scene, scene.settings, w, h, ref, &cpuOut));
    if (knob.skipped.empty()) measureGlChild(knob, setting, file, w, h, false, n, ref, &cpuOut);
  }
  return knob;
}

KnobResult Sweeper::precision() {
  KnobResult knob;
  knob.id = "precision";
  knob.title = "Float versus double pipeline";
  knob.question = "The same stage code instantiated with double instead of float, one sample per pixel: what does "
                  "float precision cost in accuracy, and what would double cost in time? Both are timed through "
                  "the same simple loop (the reference renderer's, with one sample), so the ratio is the cost of "
                  "double itself; the CPU renderer's own, optimised loop is shown as \"float\" for scale.";
  knob.reference = "The same stages in double with " + std::to_string(kReferenceSamplesPerAxis) + "x" +
                   std::to_string(kReferenceSamplesPerAxis) + " samples per pixel.";
  knob.scene = "assets/scenes/default.json, " + sizeText(width_, height_);
  const Scene scene = loadSceneFile(scenePath("default.json"));
  const RenderOutput ref = reference(scene, scene.settings, width_, height_, knob.id);
  std::unique_ptr<Renderer> cpu = makeCpuRenderer();
  ReferenceOptions loopOptions;
  loopOptions.samplesPerAxis = 1;
  loopOptions.doublePrecision = false;
  std::unique_ptr<Renderer> floatLoop = makeReferenceRenderer(loopOptions);
  loopOptions.doublePrecision = true;
  std::unique_ptr<Renderer> doubleLoop = makeReferenceRenderer(loopOptions);
  RenderOutput floatOut, floatLoopOut, doubleLoopOut, glOut;
  knob.points.push_back(measureOne(knob.id, "float", "cpu", *cpu, scene, scene.settings, width_, height_, ref, &floatOut));
  knob.points.push_back(measureOne(knob.id, kFloatLoop, "cpu", *floatLoop, scene, scene.settings, width_, height_, ref,
                                   &floatLoopOut));
  knob.points.push_back(measureOne(knob.id, kDoubleLoop, "cpu", *doubleLoop, scene, scene.settings, width_, height_,
                                   ref, &doubleLoopOut));
  addVsExact(knob, kFloatLoop, kDoubleLoop, "cpu", floatLoopOut, doubleLoopOut);
  addVsExact(knob, "float", kDoubleLoop, "cpu", floatOut, doubleLoopOut);
  ReportPoint g = measureOne(knob.id, "float", "gl", gl(), scene, scene.settings, width_, height_, ref, &glOut);
  g.cpuVsGl = compare(floatOut, glOut);
  knob.points.push_back(std::move(g));
  return knob;
}

// One backend at one point of the height-field section: timed as every knob's points, its
// error over the interior pixels only (compare/interior.h), the silhouettes counted apart.
ReportPoint Sweeper::measureHeightPoint(const std::string& viewId, const HeightFieldPointInfo& info,
                                        const std::string& setting, const std::string& backend, Renderer& renderer,
                                        const Scene& scene, int width, int height, const RenderOutput& reference,
                                        RenderOutput* outputCopy) {
  RenderOutput out;
  const Timing timing = timeRenderer(renderer, scene, scene.settings, width, height, frames_, out);
  const InteriorComparison c = compareInterior(out, reference);
  ReportPoint p = makePoint(setting, backend, timing, c.interior);
  p.heightField = info;
  p.heightField->interiorPixels = c.split.interiorPixels;
  p.heightField->silhouetteApproxOnly = c.split.approxOnly;
  p.heightField->silhouetteReferenceOnly = c.split.referenceOnly;
  p.heightField->partialPixels = c.split.partial;
  std::ostringstream line;
  line << viewId << " " << setting << ", " << backend << ": " << std::fixed << std::setprecision(2) << p.msMedian
       << " ms median, " << p.msMin << " fastest, interior rmse " << p.vsReference.rmse << " levels over "
       << c.split.interiorPixels << " px, silhouette " << c.split.silhouette() << " px";
  say(line.str());
  if (outputCopy) *outputCopy = std::move(out);
  return p;
}

void Sweeper::heightFields(HeightFieldSection& section, const std::string& outDir) {
  const int referenceSamples = options_.quick ? kHeightReferenceSamplesQuick : kReferenceSamplesPerAxis;
  section.referenceSamplesPerAxis = referenceSamples;
  const std::vector<ivec2> layerSets = options_.quick ? std::vector<ivec2>{{8, 32}, {32, 128}}
                                                      : std::vector<ivec2>{{4, 8}, {8, 32}, {16, 64}, {32, 128}};
  std::vector<HeightFieldMethod> methods;
  for (SurfaceDetail d : {SurfaceDetail::NormalMap, SurfaceDetail::BumpBlinn, SurfaceDetail::BumpEmboss,
                          SurfaceDetail::Parallax, SurfaceDetail::ParallaxOffsetLimited}) {
    methods.push_back({d, ivec2(8, 32)});
  }
  for (const ivec2 layers : layerSets) {
    for (SurfaceDetail d : {SurfaceDetail::SteepParallax, SurfaceDetail::Relief, SurfaceDetail::ParallaxOcclusion}) {
      methods.push_back({d, layers});
    }
  }
  std::string layerText;
  for (const ivec2 l : layerSets) {
    layerText += (layerText.empty() ? "" : ", ") + std::string("[") + std::to_string(l.x) + ", " + std::to_string(l.y) + "]";
  }
  section.question =
      "Each surface_detail method draws a plane whose material carries a height map; the displaced mesh is what "
      "they fake. normal_map reads no height at all (the baseline), the bump methods only bend the normal, the "
      "parallax family shifts the uv every map is read at, and the marching ones (steep_parallax, relief, "
      "parallax_occlusion) pay per layer: parallax_layers " + layerText +
      " here. What does each cost per frame, and how close does it come to the true surface, by view angle?";
  section.reference =
      "The same view with the plane replaced by the true displaced surface (mesh type heightfield: same size, "
      "uv_scale, height map and height_scale " + fmtFixed(kHeightFieldScale, 2) +
      ", one vertex per texel, the plane at the top of the relief as the methods assume), drawn by the CPU stages in "
      "double with " + std::to_string(referenceSamples) + "x" + std::to_string(referenceSamples) +
      " samples per pixel. Its material is the plane's without the height and normal maps (surface_detail "
      "normal_map with no normal map), so the mesh's own normals light it and nothing shifts its uv a second "
      "time; the plane's normal map is derived from the same height map at the same depth, so a method that "
      "finds the right uv also lights like the mesh. Diffuse only (bump_emboss draws no specular) and no "
      "self-shadowing (the rasterised mesh casts none), trilinear filtering on both. Error: RMSE over the "
      "interior pixels, those both images cover wholly; parallax does not move silhouettes, so the pixels only "
      "one image covers are counted apart, and the reference's part-covered edge pixels are left out.";
  section.scene = heightFieldViewText() + " at 0, 45, 70 and 85 degrees from its normal; " + sizeText(width_, height_) +
                  "; bricks: assets/textures/bricks_*.png, blocks (raised blocks with vertical walls): "
                  "assets/textures/blocks_*.png";

  std::unique_ptr<Renderer> cpu = makeCpuRenderer();
  ReferenceOptions referenceOptions;
  referenceOptions.samplesPerAxis = referenceSamples;
  referenceOptions.threads = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  std::unique_ptr<Renderer> referenceRenderer = makeReferenceRenderer(referenceOptions);
  // The settings the pictures show, left to right after the reference.
  const std::vector<std::string> pictured = {"normal_map", "parallax", "steep_parallax 8-32", "relief 8-32",
                                             "parallax_occlusion 8-32"};
  for (const std::string field : {"bricks", "blocks"}) {
    const HeightFieldAsset asset = loadHeightFieldAsset(options_.assetsDir, field);
    const Mesh mesh = heightFieldMesh(asset);
    for (const int angle : kHeightFieldAngles) {
      HeightFieldView view;
      view.field = field;
      view.angleDeg = angle;
      KnobResult& knob = view.result;
      knob.id = "height_fields_" + field + "_" + std::to_string(angle);
      knob.title = "Height field " + field + " at " + std::to_string(angle) + " degrees";
      knob.scene = field + ", " + std::to_string(angle) + " degrees from the normal, " + sizeText(width_, height_);
      const Scene meshScene = heightFieldMeshScene(asset, mesh, angle);
      say(knob.id + ": displaced-mesh reference (" + std::to_string(mesh.triangleCount()) + " triangles, double, " +
          std::to_string(referenceSamples) + "x" + std::to_string(referenceSamples) + " samples) at " +
          sizeText(width_, height_));
      const RenderOutput reference = referenceRenderer->render(meshScene, meshScene.settings, width_, height_);
      const bool picture = angle == kHeightFieldPictureAngle;
      std::vector<MontageTile> tiles, heats;
      if (picture) tiles.push_back({"displaced mesh (reference)", viewImage(reference, BackgroundMode::Checker)});

      // The true geometry at one sample per pixel: the floor one-sample images stand on.
      std::vector<std::pair<std::string, HeightFieldPointInfo>> points;
      HeightFieldPointInfo meshInfo;
      meshInfo.method = kTrueGeometry;
      points.push_back({kTrueGeometry, meshInfo});
      for (const HeightFieldMethod& m : methods) {
        HeightFieldPointInfo info;
        info.method = std::string(toString(m.method));
        if (marchesLayers(m.method)) {
          info.layersMin = m.layers.x;
          info.layersMax = m.layers.y;
        }
        points.push_back({methodSetting(m), info});
      }
      for (std::size_t i = 0; i < points.size(); ++i) {
        const auto& [setting, info] = points[i];
        const Scene scene = i == 0 ? meshScene : heightFieldPlaneScene(asset, angle, methods[i - 1]);
        RenderOutput cpuOut, glOut;
        knob.points.push_back(measureHeightPoint(knob.id, info, setting, "cpu", *cpu, scene, width_, height_,
                                                 reference, &cpuOut));
        ReportPoint g = measureHeightPoint(knob.id, info, setting, "gl", gl(), scene, width_, height_, reference, &glOut);
        g.cpuVsGl = compare(cpuOut, glOut);
        knob.points.push_back(std::move(g));
        if (picture && std::find(pictured.begin(), pictured.end(), setting) != pictured.end()) {
          tiles.push_back({setting, viewImage(cpuOut, BackgroundMode::Checker)});
          heats.push_back({setting,
                           makeInteriorHeatMap(cpuOut, reference, splitInterior(cpuOut, reference))});
        }
      }
      if (picture && !heats.empty()) {
        // Under the reference, the key to the difference row.
        heats.insert(heats.begin(), {"difference, interior",
                                     legendTile(width_, height_,
                                                {"Below each method:", "its difference from", "the reference on",
                                                 "interior pixels.", "black: 0 levels", "bright: up to 255 (log)",
                                                 "magenta: method only", "cyan: reference only"})});
        for (MontageTile& t : heats) tiles.push_back(std::move(t));
        MontageOptions montage;
        montage.columns = static_cast<int>(tiles.size() / 2);
        const std::string name = "height_fields_" + field + "_" + std::to_string(angle) + ".png";
        savePng((std::filesystem::path(outDir) / name).string(), makeMontage(tiles, montage));
        section.images.push_back(name);
        say("height fields: wrote " + name);
      }
      section.views.push_back(std::move(view));
    }
  }
  section.imagesCaption =
      "Top row: the displaced mesh (the reference) and the CPU images of normal_map, parallax, steep_parallax, relief "
      "and parallax_occlusion (layers 8-32) at " + std::to_string(kHeightFieldPictureAngle) +
      " degrees. Bottom row: each one's difference from the reference over the interior pixels (black 0, the "
      "inferno ramp on a log scale up to 255 levels); magenta where only the method's image covers the pixel, cyan "
      "where only the reference does.";

  // The speed target, on the CPU fast path: parallax_occlusion at its default layers
  // against normal_map, 1280 x 720, bricks at kCostAngle.
  HeightFieldCost& cost = section.cost720p;
  const HeightFieldAsset bricks = loadHeightFieldAsset(options_.assetsDir, "bricks");
  const HeightFieldMethod normal{SurfaceDetail::NormalMap, ivec2(8, 32)};
  const HeightFieldMethod pom{SurfaceDetail::ParallaxOcclusion, ivec2(8, 32)};
  const Scene normalScene = heightFieldPlaneScene(bricks, kCostAngle, normal);
  const Scene pomScene = heightFieldPlaneScene(bricks, kCostAngle, pom);
  const int costFrames = std::max(frames_, kCostFrames);
  const auto [normalTiming, pomTiming] = timeScenesInTurn(*cpu, normalScene, pomScene, kCostWidth, kCostHeight, costFrames);
  cost.measured = true;
  cost.scene = "bricks at " + std::to_string(kCostAngle) + " degrees";
  cost.cpuPath = cpuPathName(CpuOptions{}) + ", 1 thread";
  cost.pomSetting = methodSetting(pom);
  cost.normalMapMs = normalTiming.msMin;
  cost.pomMs = pomTiming.msMin;
  cost.normalMapMsMedian = normalTiming.msMedian;
  cost.pomMsMedian = pomTiming.msMedian;
  cost.frames = costFrames;
  std::ostringstream line;
  line << "height fields 720p: normal_map " << std::fixed << std::setprecision(2) << cost.normalMapMs
       << " ms, parallax_occlusion 8-32 " << cost.pomMs << " ms (fastest frames), ratio "
       << (cost.normalMapMs > 0.0 ? cost.pomMs / cost.normalMapMs : 0.0);
  say(line.str());
  section.measured = true;
}

void Sweeper::bases(ReportData& data) {
  say("orthonormal bases: measuring four constructions");
  const std::size_t sphereCount = options_.quick ? 100000 : 1000000;
  const std::size_t nearAxisCount = options_.quick ? 2000 : 20000;
  const std::vector<vec3> directions = basisTestDirections(sphereCount, nearAxisCount);
  data.basisDirections = directions.size();
  for (BasisMethod method : kAllBasisMethods) {
    BasisRow row;
    row.method = method;
    row.stats = measureBasisError(method, directions);
    // Time: build every basis, fold the results into a sum the compiler must keep; the best
    // of a few repetitions, since other processes share the machine.
    double bestNs = 0.0;
    for (int repetition = 0; repetition < kBasisTimingRepetitions; ++repetition) {
      const auto start = std::chrono::steady_clock::now();
      float sink = 0.0f;
      for (const vec3& n : directions) {
        const OrthonormalBasis b = basisFromNormal(n, method);
        sink += b.b1.x + b.b2.y;
      }
      const double ns = std::chrono::duration<double, std::nano>(std::chrono::steady_clock::now() - start).count();
      volatile float keep = sink;  // a store the compiler must make, so the loop is not dropped
      static_cast<void>(keep);
      if (repetition == 0 || ns < bestNs) bestNs = ns;
    }
    row.nsPerBasis = bestNs / static_cast<double>(directions.size());
    data.bases.push_back(row);
  }
  const KnobReading reading = readBases(data.bases);
  data.basisSummary = reading.summary;
  data.basisReading = reading.detail;
}

// An error picture (levels per direction, an equirect grid) as the heat map's colours, with
// +Y along the top row and -Z at the centre.
Image errorPicture(const std::vector<double>& levels, int width, int height) {
  Image image = makeImage(width, height);
  const HeatRamp ramp{64, HeatScale::Log};  // 64 levels and more get the top colour
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      const double e = levels[static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x)];
      const Rgb8 c = heatColour(static_cast<int>(std::lround(std::min(e, 255.0))), ramp);
      std::uint8_t* p = image.pixel(x, y);
      p[0] = c.r;
      p[1] = c.g;
      p[2] = c.b;
      p[3] = 255;
    }
  }
  return image;
}

// A built map's level 0 as an image, each layer side by side, v = 1 (+Y) along the top row.
Image layersPicture(const ParameterizedMap& map) {
  const CubeMapLevel& level = map.levels.front();
  Image image = makeImage(level.size * map.layers, level.size);
  for (int layer = 0; layer < map.layers; ++layer) {
    for (int y = 0; y < level.size; ++y) {
      for (int x = 0; x < level.size; ++x) {
        const vec3 c = glm::clamp(level.texel(layer, x, level.size - 1 - y), vec3(0.0f), vec3(1.0f));
        std::uint8_t* p = image.pixel(layer * level.size + x, y);
        p[0] = static_cast<std::uint8_t>(std::lround(c.r * 255.0f));
        p[1] = static_cast<std::uint8_t>(std::lround(c.g * 255.0f));
        p[2] = static_cast<std::uint8_t>(std::lround(c.b * 255.0f));
        p[3] = 255;
      }
    }
  }
  return image;
}

std::optional<CubeMap> Sweeper::loadSky(std::string& skipped) const {
  // The asset tool's sky: six 256-texel faces with a sun, a horizon and a grid of fine lines.
  const std::filesystem::path textures = std::filesystem::path(options_.assetsDir) / "textures";
  std::array<FaceImage, kCubeFaces> faces;
  std::array<std::string, kCubeFaces> paths;
  const char* names[kCubeFaces] = {"px", "nx", "py", "ny", "pz", "nz"};
  try {
    for (int f = 0; f < kCubeFaces; ++f) {
      paths[static_cast<std::size_t>(f)] = (textures / (std::string("sky_") + names[f] + ".png")).string();
      faces[static_cast<std::size_t>(f)] = loadEnvironmentImage(paths[static_cast<std::size_t>(f)]);
    }
  } catch (const InputError& e) {
    skipped = std::string("no sky to measure: ") + e.what();
    return std::nullopt;
  }
  std::vector<std::string> warnings;
  return cubeMapFromFaces(std::move(faces), paths, warnings);
}

void Sweeper::parameterizations(ParameterizationSection& section, const std::string& outDir) {
  const std::optional<CubeMap> sky = loadSky(section.skipped);
  if (!sky) return;
  const CubeMap& cube = *sky;
  section.source = "the asset tool's sky (textures/sky_*.png), " + std::to_string(cube.size()) + " texels per face";
  const std::vector<int> sizes = options_.quick ? std::vector<int>{64, 256} : std::vector<int>{64, 128, 256, 512, 1024};
  const std::size_t directions = options_.quick ? 20000 : 200000;
  const int pictureWidth = options_.quick ? 256 : 512, pictureHeight = pictureWidth / 2;
  for (EnvironmentParameterization kind : {EnvironmentParameterization::Sphere, EnvironmentParameterization::DualParaboloid}) {
    for (int size : sizes) {
      say("environment: " + std::string(toString(kind)) + " map at " + std::to_string(size));
      ParameterizationRow row;
      row.kind = kind;
      row.size = size;
      const auto start = std::chrono::steady_clock::now();
      const ParameterizedMap map = parameterizedMapFromCube(cube, kind, size);
      row.buildMs = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
      row.error = measureParameterizationError(cube, map, directions);
      section.rows.push_back(row);
      if (size != 256) continue;
      const std::string mapName = "env_" + std::string(toString(kind)) + "_map.png";
      savePng((std::filesystem::path(outDir) / mapName).string(), layersPicture(map));
      section.pictures.push_back(mapName);
      section.captions.push_back(std::string(toString(kind)) + " map at 256 texels, level 0" +
                                 (kind == EnvironmentParameterization::Sphere ? " (centre +Z, rim -Z)"
                                                                              : " (left: the +Z half, right: -Z)"));
      const std::string errorName = "env_" + std::string(toString(kind)) + "_error.png";
      savePng((std::filesystem::path(outDir) / errorName).string(),
              errorPicture(parameterizationErrorImage(cube, map, pictureWidth, pictureHeight), pictureWidth, pictureHeight));
      section.pictures.push_back(errorName);
      section.captions.push_back("its error per direction against the cube, as an equirect (-Z at the centre, +Y at "
                                 "the top; black 0, the ramp's top 64 levels and more)");
    }
  }
}

// Linear colours as an image, clamped to [0, 1] (as the parameterization pictures show a map).
Image colourPicture(const std::vector<glm::dvec3>& colours, int width, int height) {
  Image image = makeImage(width, height);
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      const glm::dvec3 c = glm::clamp(
          colours[static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x)],
          glm::dvec3(0.0), glm::dvec3(1.0));
      std::uint8_t* p = image.pixel(x, y);
      p[0] = static_cast<std::uint8_t>(std::lround(c.r * 255.0));
      p[1] = static_cast<std::uint8_t>(std::lround(c.g * 255.0));
      p[2] = static_cast<std::uint8_t>(std::lround(c.b * 255.0));
      p[3] = 255;
    }
  }
  return image;
}

void Sweeper::diffuseLight(DiffuseLightSection& section, const std::string& outDir) {
  const std::optional<CubeMap> sky = loadSky(section.skipped);
  if (!sky) return;
  section.source = "the asset tool's sky (textures/sky_*.png)";
  say("environment: irradiance cube and SH9 against Monte Carlo");
  auto start = std::chrono::steady_clock::now();
  const CubeMap irradiance = irradianceCubeFromCube(*sky);
  section.irradianceMs = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  start = std::chrono::steady_clock::now();
  const Sh9Irradiance sh = sh9IrradianceFromCube(*sky);
  section.sh9Ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  // Normals and samples: the quick run's reference noise is about four times the full run's.
  const std::size_t normals = options_.quick ? 200 : 2000;
  const std::size_t samples = options_.quick ? 2048 : 32768;
  constexpr std::uint64_t kSeed = 20261125;  // fixed: the same reference every run
  section.error = measureDiffuseLightError(*sky, irradiance, sh, normals, samples, kSeed);
  const int width = options_.quick ? 256 : 512, height = width / 2;
  const std::vector<glm::dvec3> fromCube = irradianceCubeImage(irradiance, width, height);
  const std::vector<glm::dvec3> fromSh = sh9Image(sh, width, height);
  std::vector<double> apart(fromCube.size());
  for (std::size_t i = 0; i < apart.size(); ++i) {
    const glm::dvec3 d = glm::abs(fromSh[i] - fromCube[i]);
    apart[i] = std::max({d.x, d.y, d.z}) * 255.0;
  }
  const std::filesystem::path dir(outDir);
  savePng((dir / "env_irradiance.png").string(), colourPicture(fromCube, width, height));
  savePng((dir / "env_sh9.png").string(), colourPicture(fromSh, width, height));
  savePng((dir / "env_sh9_error.png").string(), errorPicture(apart, width, height));
  section.pictures = {"env_irradiance.png", "env_sh9.png", "env_sh9_error.png"};
  section.captions = {"D(n) from the irradiance cube, as an equirect of normals (-Z at the centre, +Y at the top)",
                      "D(n) from SH9, the same normals",
                      "|SH9 - irradiance cube| per normal (black 0, the ramp's top 64 levels and more)"};
}

void Sweeper::glossy(GlossySection& section, const std::string& outDir) {
  const std::optional<CubeMap> sky = loadSky(section.skipped);
  if (!sky) return;
  section.source = "the asset tool's sky (textures/sky_*.png)";
  say("environment: prefiltered glossy reflection against Monte Carlo");
  const auto start = std::chrono::steady_clock::now();
  const CubeMap specular = specularCubeFromCube(*sky);
  section.buildMs = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  section.cubeSize = specular.size();
  section.levels = specular.levelCount();
  // Every level's own lobe (e_l = (N_l / 2)^2) and the geometric midpoints between them, where
  // textureLod blends two lobes, from 1 up to e_0; and two sharper lobes than level 0's, which
  // read level 0 (the chain's clamp): 4 e_0, 2 e_0, e_0, e_0 / 2, ... 1.
  const double e0 = specularExponentOfSide(specular.size());
  section.levelZeroExponent = e0;
  std::vector<double> shininesses;
  for (double e = 4.0 * e0; e >= 1.0; e *= 0.5) shininesses.push_back(e);
  const std::size_t directions = options_.quick ? 200 : 1000;
  const std::size_t samples = options_.quick ? 2048 : 16384;
  constexpr std::uint64_t kSeed = 20261127;  // fixed: the same reference every run
  section.error = measureGlossyError(*sky, specular, shininesses, directions, samples, kSeed);
  // The sky as three shininesses see it: level 0's lobe, and two further down the chain.
  const int width = options_.quick ? 256 : 512, height = width / 2;
  const std::filesystem::path dir(outDir);
  for (const double shininess : {e0, e0 / 16.0, e0 / 128.0}) {
    const double lod = specularLodFromShininess(specular, shininess);
    const std::string name = "env_glossy_" + std::to_string(static_cast<int>(shininess)) + ".png";
    savePng((dir / name).string(), colourPicture(glossyImage(specular, lod, width, height), width, height));
    section.pictures.push_back(name);
    section.captions.push_back("The sky through a Phong lobe of exponent " + std::to_string(static_cast<int>(shininess)) +
                               " (the prefiltered cube at LOD " + fmtFixed(lod, 2) +
                               "), as an equirect of reflected directions");
  }
}

void Sweeper::shadows(ShadowSection& section, const std::string& outDir) {
  const std::string file = options_.assetsDir + "/scenes/shadow_directional.json";
  Scene scene;
  try {
    scene = loadSceneFile(file);
  } catch (const InputError& e) {
    section.skipped = e.what();
    return;
  }
  if (scene.lights.empty() || !scene.lights[0].shadow) {
    section.skipped = file + " has no shadowed light 0";
    return;
  }
  // Seen from the side the shadows fall to (the light travels towards -x and -z), from above,
  // so that they fill a good part of the frame.
  scene.camera.position = vec3(-3.0f, 5.0f, -2.5f);
  scene.camera.target = vec3(0.2f, 0.0f, -0.2f);
  const int width = width_, height = height_;
  section.scene = "shadow_directional.json at " + sizeText(width, height) +
                  ", light 0 (directional), seen from (-3, 5, -2.5) towards the shadows";
  say("shadows: the map's side and PCF against shadow rays traced in double");
  CpuOptions cpuOptions;
  cpuOptions.path = CpuPath::Fast;
  cpuOptions.threads = 1;
  std::unique_ptr<Renderer> cpu = makeCpuRenderer(cpuOptions);
  const int frames = options_.quick ? 3 : kCostFrames;
  Scene unshadowed = scene;
  unshadowed.lights[0].shadow.reset();
  RenderOutput frame;
  section.unshadowedMs = timeRenderer(*cpu, unshadowed, unshadowed.settings, width, height, frames, frame).msMedian;
  const TriangleBvh bvh(scene);
  const std::vector<int> sizes = options_.quick ? std::vector<int>{256, 1024, 4096}
                                                : std::vector<int>{256, 512, 1024, 2048, 4096};
  bool traced = false;
  ShadowVisibility pictured;
  for (const int size : sizes) {
    for (const int pcf : {1, 3, 5}) {
      Scene s = scene;
      s.lights[0].shadow->size = size;
      s.lights[0].shadow->pcf = pcf;
      // timeRenderer's loop, keeping each timed frame's shadow pass share (RenderStats).
      for (int i = 0; i < kWarmupFrames; ++i) frame = cpu->render(s, s.settings, width, height);
      std::vector<double> frameMs, passMs;
      for (int f = 0; f < frames; ++f) {
        const auto begin = std::chrono::steady_clock::now();
        frame = cpu->render(s, s.settings, width, height);
        frameMs.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - begin).count());
        passMs.push_back(frame.stats.shadowMilliseconds);
      }
      Timing timing;
      timing.msMedian = medianOf(frameMs);
      const auto start = std::chrono::steady_clock::now();
      const ShadowVisibility v = measureShadowVisibility(s, 0, frame, bvh);
      if (!traced) {
        section.traceMs = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
        section.measured = v.measured;
        section.tracedShadowed = v.tracedShadowed;
        traced = true;
      }
      ShadowRow row;
      row.size = size;
      row.pcf = pcf;
      row.msMedian = timing.msMedian;
      row.shadowPassMs = medianOf(passMs);
      row.wrongPercent = v.wrongPercent();
      row.partialPercent = v.measured ? 100.0 * static_cast<double>(v.partial) / static_cast<double>(v.measured) : 0.0;
      row.meanAbsError = v.meanAbsError;
      section.rows.push_back(row);
      if (size == 1024 && pcf == 1) pictured = v;
    }
  }
  // Where the 1024^2 hard map and the traced shadow disagree: red the map shadows a lit point,
  // blue it lights a shadowed one, grey both agree (lit light, shadowed dark), black not measured.
  const std::filesystem::path dir(outDir);
  Image image = makeImage(pictured.width, pictured.height, 0x000000FFu);
  for (int y = 0; y < pictured.height; ++y) {
    for (int x = 0; x < pictured.width; ++x) {
      const std::size_t i = static_cast<std::size_t>(y) * static_cast<std::size_t>(pictured.width) + static_cast<std::size_t>(x);
      if (std::isnan(pictured.traced[i])) continue;
      std::uint8_t* p = image.pixel(x, y);
      const double d = pictured.map[i] - pictured.traced[i];
      if (d < -0.5) {
        p[0] = 255, p[1] = 40, p[2] = 40;
      } else if (d > 0.5) {
        p[0] = 40, p[1] = 120, p[2] = 255;
      } else {
        const std::uint8_t g = pictured.traced[i] > 0.5 ? 200 : 70;
        p[0] = p[1] = p[2] = g;
      }
    }
  }
  savePng((dir / "shadow_vs_traced.png").string(), image);
  section.pictures = {"shadow_vs_traced.png"};
  section.captions = {"The 1024\u00b2 map with one texel (PCF 1) against the traced shadow: red where the map shadows a "
                      "lit point (acne, or an edge one texel too wide), blue where it lights a shadowed one; grey "
                      "where both agree (light: lit, dark: shadowed); black: no surface turned to the light"};
}

namespace {

// A CPU frame timed as timeRenderer does, keeping the reflection pass's share (RenderStats).
Timing timeSsrFrame(Renderer& cpu, const Scene& scene, int width, int height, int frames, RenderOutput& out,
                    double& ssrMs) {
  for (int i = 0; i < kWarmupFrames; ++i) out = cpu.render(scene, scene.settings, width, height);
  std::vector<double> frameMs, passMs;
  for (int f = 0; f < frames; ++f) {
    const auto begin = std::chrono::steady_clock::now();
    out = cpu.render(scene, scene.settings, width, height);
    frameMs.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - begin).count());
    passMs.push_back(out.stats.ssrMilliseconds);
  }
  Timing t;
  t.msMedian = medianOf(frameMs);
  t.msMin = *std::min_element(frameMs.begin(), frameMs.end());
  t.frames = frames;
  ssrMs = medianOf(passMs);
  return t;
}

}  // namespace

void Sweeper::ssr(SsrSection& section, const std::string& outDir) {
  if (!rayTracerAvailable()) {
    section.skipped = rayTracerDescription();
    return;
  }
  Scene floor, cave;
  try {
    floor = loadSceneFile(scenePath("ssr_mirror_floor.json"));
    cave = loadSceneFile(scenePath("ssr_cave.json"));
  } catch (const InputError& e) {
    section.skipped = e.what();
    return;
  }
  const int width = width_, height = height_;
  section.tracer = rayTracerDescription();
  section.scene = "ssr_mirror_floor.json at " + sizeText(width, height);
  section.indirectScene = "ssr_cave.json at " + sizeText(width, height);
  say("ssr: every march against rays traced with " + section.tracer);
  CpuOptions cpuOptions;
  cpuOptions.path = CpuPath::Fast;
  cpuOptions.threads = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  std::unique_ptr<Renderer> cpu = makeCpuRenderer(cpuOptions);
  const int frames = options_.quick ? 1 : 3;

  // The mirror floor's reference: its mirror rays only (no indirect light there).
  floor.settings.ssr.enabled = true;
  floor.settings.ssr.indirectSamples = 0;
  const RenderOutput floorBase = cpu->render(floor, ssrBaseSettings(floor.settings), width, height);
  {
    RenderOutput unused;
    Scene plain = floor;
    plain.settings.ssr.enabled = false;
    section.baseMs = timeRenderer(*cpu, plain, plain.settings, width, height, frames, unused).msMedian;
  }
  const RayScene floorRays(floor);
  const SsrReference floorRef = traceSsrReference(floor, floor.settings, floorBase, floorRays);
  section.traceMs = floorRef.milliseconds;
  for (const std::uint64_t n : floorRef.mirrorRays) section.reflecting += n;
  section.blindRays = floorRef.mirrorRays[static_cast<std::size_t>(SsrTruth::OffScreen)] +
                      floorRef.mirrorRays[static_cast<std::size_t>(SsrTruth::Occluded)];

  const auto measureMarch = [&](SsrMarch march, int steps, float thickness, RenderOutput* keep) {
    Scene s = floor;
    s.settings.ssr.march = march;
    s.settings.ssr.maxSteps = steps;
    s.settings.ssr.thickness = thickness;
    RenderOutput out;
    SsrMarchRow row;
    row.march = std::string(toString(march));
    row.maxSteps = steps;
    row.thickness = thickness;
    row.msMedian = timeSsrFrame(*cpu, s, width, height, frames, out, row.ssrMs).msMedian;
    const SsrReferenceError e = measureSsrError(floorRef, out);
    const SsrErrorRow& visible = e.byClass[static_cast<std::size_t>(SsrErrorClass::Visible)];
    row.meanAbs = e.all.meanAbs;
    row.visibleMeanAbs = visible.meanAbs;
    row.missedVisible = visible.over3;
    row.falseHits = e.byClass[static_cast<std::size_t>(SsrErrorClass::Sky)].over3;
    std::ostringstream line;
    line << "ssr " << row.march << " " << steps << " steps, thickness " << thickness << ": " << std::fixed
         << std::setprecision(1) << row.msMedian << " ms, mean " << std::setprecision(2) << row.meanAbs
         << " levels vs traced";
    say(line.str());
    if (keep) *keep = std::move(out);
    return std::pair<SsrMarchRow, SsrReferenceError>(row, e);
  };
  const std::vector<int> steps = options_.quick ? std::vector<int>{16, 64} : std::vector<int>{8, 16, 32, 64, 128, 256};
  const std::vector<float> thicknesses =
      options_.quick ? std::vector<float>{0.02f, 0.4f} : std::vector<float>{0.02f, 0.05f, 0.1f, 0.2f, 0.4f, 0.8f};
  const float sceneThickness = floor.settings.ssr.thickness;
  RenderOutput pictured;
  SsrReferenceError picturedError;
  double bestMean = -1.0;
  for (const SsrMarch march : {SsrMarch::LinearWorld, SsrMarch::AdaptiveWorld, SsrMarch::DdaScreen, SsrMarch::Hiz}) {
    for (const int n : steps) {
      const bool keep = march == SsrMarch::Hiz && n == 64;
      auto [row, e] = measureMarch(march, n, sceneThickness, keep ? &pictured : nullptr);
      if (keep) picturedError = e;
      if (bestMean < 0.0 || row.meanAbs < bestMean) {
        bestMean = row.meanAbs;
        const double blind = e.byClass[static_cast<std::size_t>(SsrErrorClass::OffScreen)].sumAbs +
                             e.byClass[static_cast<std::size_t>(SsrErrorClass::Occluded)].sumAbs;
        section.blindErrorShare = e.all.sumAbs > 0.0 ? blind / e.all.sumAbs : 0.0;
      }
      section.steps.push_back(row);
    }
  }
  for (const SsrMarch march : {SsrMarch::LinearWorld, SsrMarch::Hiz}) {
    for (const float t : thicknesses) section.thickness.push_back(measureMarch(march, 64, t, nullptr).first);
  }
  const std::filesystem::path dir(outDir);
  if (!pictured.rgba.empty()) {
    savePng((dir / "ssr_vs_traced.png").string(),
            ssrReferenceMontage(floorRef, {{"cpu", &pictured, picturedError}}));
    section.pictures.push_back("ssr_vs_traced.png");
    section.captions.push_back(
        "The mirror floor: the ray-traced reference, the CPU's hiz march at 64 steps, each reflecting pixel's class (grey: its mirror ray meets nothing; green: a surface the frame shows; yellow: one off the "
        "screen; red: one hidden behind another) and the march's error against the reference");
  }

  // The cave's indirect light: every sample count against a converged reference (many more
  // rays from the same sequence) and against the reference of the same rays.
  cave.settings.ssr.enabled = true;
  const int referenceSamples = options_.quick ? 32 : 256;
  section.referenceSamples = referenceSamples;
  const RenderOutput caveBase = cpu->render(cave, ssrBaseSettings(cave.settings), width, height);
  const RayScene caveRays(cave);
  SsrReferenceOptions converged;
  converged.indirectSamples = referenceSamples;
  const SsrReference caveRef = traceSsrReference(cave, cave.settings, caveBase, caveRays, converged);
  section.indirectTraceMs = caveRef.milliseconds;
  say("ssr: the cave's converged reference, " + std::to_string(referenceSamples) + " rays per pixel, " +
      fmtFixed(caveRef.milliseconds, 0) + " ms");
  RenderOutput indirectPictured;
  SsrReferenceError indirectError;
  const std::vector<int> sampleCounts = options_.quick ? std::vector<int>{1, 4} : std::vector<int>{1, 2, 4, 8, 16, 32, 64};
  for (const int n : sampleCounts) {
    Scene s = cave;
    s.settings.ssr.indirectSamples = n;
    RenderOutput out;
    SsrSamplesRow row;
    row.samples = n;
    row.msMedian = timeSsrFrame(*cpu, s, width, height, frames, out, row.ssrMs).msMedian;
    const SsrReferenceError e = measureSsrError(caveRef, out);
    row.meanAbs = e.all.meanAbs;
    row.marchMeanAbs = measureSsrError(traceSsrReference(s, s.settings, caveBase, caveRays), out).all.meanAbs;
    say("ssr indirect " + std::to_string(n) + " samples: " + fmtFixed(row.msMedian, 1) + " ms, mean " +
        fmtFixed(row.meanAbs, 2) + " levels vs converged, " + fmtFixed(row.marchMeanAbs, 2) + " vs the same rays");
    if (n == 4) {
      indirectPictured = std::move(out);
      indirectError = e;
    }
    section.samples.push_back(row);
  }
  if (!indirectPictured.rgba.empty()) {
    savePng((dir / "ssr_indirect_vs_traced.png").string(),
            ssrReferenceMontage(caveRef, {{"cpu", &indirectPictured, indirectError}}));
    section.pictures.push_back("ssr_indirect_vs_traced.png");
    section.captions.push_back("The cave: the reference traced with " + std::to_string(referenceSamples) +
                               " rays per pixel, the CPU's indirect light with 4 samples per pixel, the classes and "
                               "the error (noise and march together)");
  }
}

std::string machineDescription() {
  std::ifstream cpuinfo("/proc/cpuinfo");
  std::string line, model = "unknown CPU";
  while (std::getline(cpuinfo, line)) {
    if (line.rfind("model name", 0) == 0) {
      model = line.substr(line.find(':') + 2);
      break;
    }
  }
  return model + ", " + std::to_string(std::thread::hardware_concurrency()) + " hardware threads";
}

ReportData Sweeper::run() {
  ReportData data;
  data.quick = options_.quick;
  data.referenceSamplesPerAxis = kReferenceSamplesPerAxis;
  data.width = width_;
  data.height = height_;
  const std::time_t now = std::time(nullptr);
  char when[64];
  std::strftime(when, sizeof when, "%Y-%m-%d %H:%M:%S", std::localtime(&now));
  data.generatedAt = when;

  data.knobs.push_back(tessellation());
  data.knobs.push_back(twoSettings("texture_filter"));
  data.knobs.push_back(minification());
  data.knobs.push_back(twoSettings("lighting_space"));
  data.knobs.push_back(twoSettings("tangent_transform"));
  data.knobs.push_back(glSampling());
  data.knobs.push_back(resolution());
  data.knobs.push_back(threads());
  data.knobs.push_back(precision());
  for (KnobResult& knob : data.knobs) {
    const KnobReading reading = readKnob(knob);
    knob.summary = reading.summary;
    knob.reading = reading.detail;
  }
  heightFields(data.heightFields, options_.outDir);
  const KnobReading heightReading = readHeightFields(data.heightFields);
  data.heightFields.summary = heightReading.summary;
  data.heightFields.reading = heightReading.detail;
  parameterizations(data.parameterizations, options_.outDir);
  const KnobReading parameterizationReading = readParameterizations(data.parameterizations);
  data.parameterizations.summary = parameterizationReading.summary;
  data.parameterizations.reading = parameterizationReading.detail;
  diffuseLight(data.diffuseLight, options_.outDir);
  const KnobReading diffuseReading = readDiffuseLight(data.diffuseLight);
  data.diffuseLight.summary = diffuseReading.summary;
  data.diffuseLight.reading = diffuseReading.detail;
  glossy(data.glossy, options_.outDir);
  const KnobReading glossyReading = readGlossy(data.glossy);
  data.glossy.summary = glossyReading.summary;
  data.glossy.reading = glossyReading.detail;
  shadows(data.shadows, options_.outDir);
  const KnobReading shadowReading = readShadows(data.shadows);
  data.shadows.summary = shadowReading.summary;
  data.shadows.reading = shadowReading.detail;
  ssr(data.ssr, options_.outDir);
  const KnobReading ssrReading = readSsr(data.ssr);
  data.ssr.summary = ssrReading.summary;
  data.ssr.reading = ssrReading.detail;
  bases(data);
  data.machine =
      machineDescription() + "; GL: " + glRendererString() + ", " + glVersionString() + "; " + glContextString();
  data.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  say("done");
  return data;
}

}  // namespace

ReportData runReportSweeps(const ReportOptions& options, std::ostream& progress) {
  Sweeper sweeper(options, progress);
  return sweeper.run();
}

void runGlChild(const std::string& scenePath, int width, int height, int frames, bool fastSampling,
                GlOptions options, const std::string& outPath) {
  const Scene scene = loadSceneFile(scenePath);
  options.fastSampling = fastSampling;
  std::unique_ptr<Renderer> renderer = makeGlRenderer(options);
  RenderOutput out;
  const Timing timing = timeRenderer(*renderer, scene, scene.settings, width, height, frames, out);
  const std::string expected = fastSampling ? "fast" : "precise";
  if (glSamplingMode() != expected) {
    throw InputError("report-gl-child: llvmpipe samples in " + glSamplingMode() + " mode, expected " + expected);
  }
  writeChildFile(outPath, out, timing);
}

}  // namespace twr::report
