// EGL headless contexts against OSMesa: the same llvmpipe behind two loaders must draw the
// same bits. Every scene of assets/scenes/ (the scene suite) is rendered through EGL's
// surfaceless platform and through OSMesa, and every output (colour, depth, triangle ids,
// line mask) must be identical; also every EGL device EGL lists that is llvmpipe, immediate
// mode lines in compatibility contexts, the errors, and that the EGL path never loads OSMesa.
// The tests skip only when libEGL.so.1 itself is missing (CI installs libegl1 + libegl-mesa0).
#include "glrender/context_egl.h"
#include "glrender/gl_renderer.h"
#include "scene/errors.h"
#include "scene/scene_file.h"
#include "tests/missing_dependency.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace twr {
namespace {

const std::string kScenes = std::string(TWINRASTER_SOURCE_DIR) + "/assets/scenes";

#define SKIP_WITHOUT_EGL()                                                          \
  do {                                                                              \
    const std::string problem = eglLibraryProblem();                                \
    if (!problem.empty()) TWR_MISSING_DEPENDENCY("EGL") << problem; \
  } while (false)

GlOptions eglOptions(int device = kEglSurfaceless) {
  GlOptions options;
  options.context = GlContextKind::Egl;
  options.eglDevice = device;
  return options;
}

GlOptions osmesaOptions() {
  GlOptions options;
  options.context = GlContextKind::OsMesa;
  return options;
}

// The first pixel (x, y, top row first) where two buffers differ, and how many do.
template <typename T>
std::string firstDifference(const std::vector<T>& a, const std::vector<T>& b, int width, int channels) {
  if (a.size() != b.size()) return "sizes " + std::to_string(a.size()) + " and " + std::to_string(b.size());
  std::size_t count = 0, first = 0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    // Bit patterns, not values: -0 against +0 or two NaNs must count as they are stored.
    if (std::memcmp(&a[i], &b[i], sizeof(T)) == 0) continue;
    if (count++ == 0) first = i;
  }
  if (count == 0) return {};
  const std::size_t pixel = first / static_cast<std::size_t>(channels);
  std::ostringstream text;
  text << count << " values differ, the first at pixel (" << pixel % static_cast<std::size_t>(width) << ", "
       << pixel / static_cast<std::size_t>(width) << ")";
  return text.str();
}

void expectIdentical(const RenderOutput& egl, const RenderOutput& osmesa, const std::string& what) {
  ASSERT_EQ(egl.width, osmesa.width) << what;
  ASSERT_EQ(egl.height, osmesa.height) << what;
  EXPECT_EQ(firstDifference(egl.rgba, osmesa.rgba, egl.width, 4), "") << what << ": colour";
  EXPECT_EQ(firstDifference(egl.depth, osmesa.depth, egl.width, 1), "") << what << ": depth";
  EXPECT_EQ(firstDifference(egl.triangleId, osmesa.triangleId, egl.width, 1), "") << what << ": triangle ids";
  EXPECT_EQ(firstDifference(egl.lineMask, osmesa.lineMask, egl.width, 1), "") << what << ": line mask";
  EXPECT_EQ(egl.stats.pixelsShaded, osmesa.stats.pixelsShaded) << what << ": GL_SAMPLES_PASSED";
  EXPECT_FALSE(egl.rgba.empty()) << what;
  EXPECT_FALSE(egl.depth.empty()) << what;
}

std::vector<std::string> sceneFiles() {
  std::vector<std::string> names;
  for (const auto& entry : std::filesystem::directory_iterator(kScenes)) {
    if (entry.path().extension() == ".json") names.push_back(entry.path().filename().string());
  }
  std::sort(names.begin(), names.end());
  return names;
}

class EglSceneSuite : public ::testing::TestWithParam<std::string> {};

// Each scene in its own settings and size: the suite's renders, twice.
TEST_P(EglSceneSuite, EglSurfacelessDrawsWhatOsMesaDraws) {
  SKIP_WITHOUT_EGL();
  const Scene scene = loadSceneFile(kScenes + "/" + GetParam());
  const RenderOutput egl = makeGlRenderer(eglOptions())->render(scene, scene.settings, scene.output.width,
                                                                scene.output.height);
  EXPECT_NE(glContextString().find("EGL surfaceless"), std::string::npos) << glContextString();
  EXPECT_TRUE(isLlvmpipe(glRendererString())) << glRendererString();
  const RenderOutput osmesa = makeGlRenderer(osmesaOptions())->render(scene, scene.settings, scene.output.width,
                                                                      scene.output.height);
  EXPECT_NE(glContextString().find("OSMesa"), std::string::npos) << glContextString();
  EXPECT_EQ(glSamplingMode(), "precise");
  expectIdentical(egl, osmesa, GetParam());
}

INSTANTIATE_TEST_SUITE_P(Scenes, EglSceneSuite, ::testing::ValuesIn(sceneFiles()),
                         [](const ::testing::TestParamInfo<std::string>& info) {
                           std::string name = info.param.substr(0, info.param.find('.'));
                           return name;
                         });

// Every debug view on the two scenes with maps, one renderer per context kept across views
// (its programs and uploads are reused, as in the GUI and the report).
TEST(EglContext, EveryViewOfTheMappedScenesMatchesOsMesa) {
  SKIP_WITHOUT_EGL();
  const std::unique_ptr<Renderer> egl = makeGlRenderer(eglOptions());
  const std::unique_ptr<Renderer> osmesa = makeGlRenderer(osmesaOptions());
  for (const char* file : {"default.json", "tangent_space.json"}) {
    Scene scene = loadSceneFile(kScenes + "/" + file);
    for (const View view : kAllViews) {
      scene.settings.view = view;
      const int width = scene.output.width / 2, height = scene.output.height / 2;
      expectIdentical(egl->render(scene, scene.settings, width, height),
                      osmesa->render(scene, scene.settings, width, height),
                      std::string(file) + " view " + std::string(toString(view)));
    }
  }
}

// Immediate-mode lines need compatibility contexts on both sides.
TEST(EglContext, ImmediateModeLinesMatchOsMesa) {
  SKIP_WITHOUT_EGL();
  Scene scene = loadSceneFile(kScenes + "/tbn_lines.json");
  scene.settings.tbnLines.enabled = true;
  scene.settings.tbnLines.mode = LineMode::Immediate;
  const RenderOutput egl =
      makeGlRenderer(eglOptions())->render(scene, scene.settings, scene.output.width, scene.output.height);
  const RenderOutput osmesa =
      makeGlRenderer(osmesaOptions())->render(scene, scene.settings, scene.output.width, scene.output.height);
  expectIdentical(egl, osmesa, "tbn_lines.json, immediate mode");
  EXPECT_GT(std::count(egl.lineMask.begin(), egl.lineMask.end(), std::uint8_t{1}), 0) << "no line drawn";
}

// Each device EGL lists: llvmpipe ones must match OSMesa bit for bit; any other driver (a GPU)
// must at least draw the scene (its rasteriser and filtering legitimately differ).
TEST(EglContext, EveryListedDeviceRendersAndLlvmpipeDevicesMatchOsMesa) {
  SKIP_WITHOUT_EGL();
  const std::vector<EglDeviceInfo> devices = listEglDevices();
  ASSERT_FALSE(devices.empty()) << "Mesa lists at least its software device";
  const Scene scene = loadSceneFile(kScenes + "/default.json");
  const int width = scene.output.width / 2, height = scene.output.height / 2;
  const RenderOutput osmesa = makeGlRenderer(osmesaOptions())->render(scene, scene.settings, width, height);
  for (const EglDeviceInfo& device : devices) {
    const RenderOutput out = makeGlRenderer(eglOptions(device.index))->render(scene, scene.settings, width, height);
    const std::string what = "EGL device " + std::to_string(device.index) + " (" + glRendererString() + ")";
    EXPECT_NE(glContextString().find("EGL device " + std::to_string(device.index)), std::string::npos)
        << glContextString();
    if (isLlvmpipe(glRendererString())) {
      expectIdentical(out, osmesa, what);
    } else {
      EXPECT_EQ(out.width, width) << what;
      std::size_t covered = 0;
      for (std::size_t i = 3; i < out.rgba.size(); i += 4) covered += out.rgba[i] == 255 ? 1 : 0;
      EXPECT_GT(covered, 0u) << what << " drew nothing";
    }
  }
}

TEST(EglContext, ANonexistentDeviceIsAnInputErrorThatCountsTheDevices) {
  SKIP_WITHOUT_EGL();
  const std::size_t count = listEglDevices().size();
  const Scene scene = loadSceneFile(kScenes + "/default.json");
  try {
    makeGlRenderer(eglOptions(99))->render(scene, scene.settings, 8, 8);
    FAIL() << "device 99 rendered";
  } catch (const InputError& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find("no EGL device 99"), std::string::npos) << message;
    EXPECT_NE(message.find("lists " + std::to_string(count) + " device"), std::string::npos) << message;
  }
}

TEST(EglContext, AMissingEglLibraryIsAnInputErrorNamingIt) {
  GlOptions options = eglOptions();
  options.eglLibrary = "libEGL-not-installed.so.1";
  const Scene scene = loadSceneFile(kScenes + "/default.json");
  try {
    makeGlRenderer(options)->render(scene, scene.settings, 8, 8);
    FAIL() << "a missing library rendered";
  } catch (const InputError& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find("cannot load the EGL library 'libEGL-not-installed.so.1'"), std::string::npos) << message;
    EXPECT_NE(message.find("libegl-mesa0"), std::string::npos) << message;
  }
}

bool processHasLoaded(const std::string& part) {
  std::ifstream maps("/proc/self/maps");
  std::string line;
  while (std::getline(maps, line)) {
    if (line.find(part) != std::string::npos) return true;
  }
  return false;
}

// The EGL path works where OSMesa does not exist: it never opens the OSMesa library (each
// test runs in its own process under ctest, so nothing else loaded it either).
TEST(EglContext, TheEglPathNeverLoadsOsMesa) {
  SKIP_WITHOUT_EGL();
  if (processHasLoaded("libOSMesa")) {
    GTEST_SKIP() << "libOSMesa is already in this process (linked in, or another test in this process loaded it: "
                    "run this test alone)";
  }
  GlOptions options = eglOptions();
  options.osmesaLibrary = "/nonexistent/libOSMesa.so.8";
  Scene scene = loadSceneFile(kScenes + "/tbn_lines.json");
  scene.settings.tbnLines.mode = LineMode::Immediate;  // the compatibility context too
  const RenderOutput out = makeGlRenderer(options)->render(scene, scene.settings, 64, 48);
  EXPECT_FALSE(out.rgba.empty());
  EXPECT_FALSE(processHasLoaded("libOSMesa")) << "the EGL path loaded OSMesa";
  EXPECT_TRUE(processHasLoaded("libEGL")) << "EGL was not loaded at all?";
}

// Auto falls back to EGL where OSMesa does not load, and is OSMesa where it does.
TEST(EglContext, AutoIsOsMesaWhereItLoadsElseEgl) {
  SKIP_WITHOUT_EGL();
  const Scene scene = loadSceneFile(kScenes + "/default.json");
  GlOptions options;
  options.context = GlContextKind::Auto;
  makeGlRenderer(options)->render(scene, scene.settings, 16, 16);
  EXPECT_NE(glContextString().find("OSMesa"), std::string::npos) << glContextString();
  options.osmesaLibrary = "libOSMesa-not-installed.so.8";
  makeGlRenderer(options)->render(scene, scene.settings, 16, 16);
  EXPECT_NE(glContextString().find("EGL surfaceless"), std::string::npos) << glContextString();
}

TEST(EglContext, ContextKindNamesRoundTrip) {
  for (const GlContextKind kind : {GlContextKind::OsMesa, GlContextKind::Egl, GlContextKind::Auto}) {
    GlContextKind parsed = GlContextKind::OsMesa;
    ASSERT_TRUE(parse(toString(kind), parsed)) << toString(kind);
    EXPECT_EQ(parsed, kind);
  }
  GlContextKind ignored = GlContextKind::OsMesa;
  EXPECT_FALSE(parse("glx", ignored));
  EXPECT_TRUE(isLlvmpipe("llvmpipe (LLVM 15.0.6, 256 bits)"));
  EXPECT_FALSE(isLlvmpipe("softpipe"));
  EXPECT_FALSE(isLlvmpipe("NVIDIA GeForce RTX 3060/PCIe/SSE2"));
}

// info --gl's listing: OSMesa, the surfaceless platform and every device, each with strings.
TEST(EglContext, ProbeListsOsMesaSurfacelessAndEveryDevice) {
  SKIP_WITHOUT_EGL();
  const std::vector<GlContextProbe> probes = probeGlContexts();
  ASSERT_EQ(probes.size(), 2 + listEglDevices().size());
  EXPECT_EQ(probes[0].kind, GlContextKind::OsMesa);
  EXPECT_EQ(probes[1].kind, GlContextKind::Egl);
  EXPECT_EQ(probes[1].eglDevice, kEglSurfaceless);
  for (std::size_t i = 1; i < probes.size(); ++i) {
    const GlContextProbe& p = probes[i];
    EXPECT_EQ(p.error, "") << i;
    EXPECT_FALSE(p.vendor.empty()) << i;
    EXPECT_FALSE(p.renderer.empty()) << i;
    EXPECT_NE(p.version.find("Core Profile"), std::string::npos) << p.version;
    if (i >= 2) {
      EXPECT_EQ(p.eglDevice, static_cast<int>(i - 2));
    }
  }
}

}  // namespace
}  // namespace twr
