// --gl-context / --gl-device on the CLI: compare through EGL gives OSMesa's metrics, also
// with the OSMesa library hidden; render's images are the same bytes; info --gl lists the
// contexts; a driver that is not llvmpipe (softpipe, standing in for a GPU) gets metrics
// without --targets verdicts; bad combinations exit 2 naming what is missing.
// Skips only when libEGL.so.1 is missing (CI installs it).
#include "cli_run.h"
#include "tests/missing_dependency.h"

#include <dlfcn.h>

#include <nlohmann/json.hpp>

#include <string>

namespace twr::testcli {
namespace {

const std::string kDefaultScene = kSource + "/assets/scenes/default.json";

RunResult runCli(const std::string& args, const std::filesystem::path& dir) {
  return runProgram(TWINRASTER_CLI, args, dir);
}

// Runs the CLI with extra environment variables ("NAME=value ...").
RunResult runCliWith(const std::string& environment, const std::string& args, const std::filesystem::path& dir) {
  return runProgram("env", environment + " \"" + std::string(TWINRASTER_CLI) + "\" " + args, dir);
}

bool eglInstalled() {
  void* library = dlopen("libEGL.so.1", RTLD_NOW | RTLD_LOCAL);
  if (!library) return false;
  dlclose(library);
  return true;
}

#define SKIP_WITHOUT_EGL() \
  if (!eglInstalled()) TWR_MISSING_DEPENDENCY("EGL") << "libEGL.so.1 is not installed here (Debian: libegl1, libegl-mesa0)"

// compare's JSON without what legitimately differs between two runs or two contexts.
nlohmann::json metricsOnly(nlohmann::json j) {
  for (const char* key : {"cpu_ms", "gl_ms", "gl_context"}) j.erase(key);
  return j;
}

TEST(CliGlContext, CompareThroughEglGivesTheOsMesaMetrics) {
  SKIP_WITHOUT_EGL();
  const auto dir = testDir("cli_gl_context");
  const RunResult egl =
      runCli("compare \"" + kDefaultScene + "\" --gl-context egl --repeat 1 --json --targets --out-dir \"" +
                 (dir / "egl").string() + "\"",
             dir);
  ASSERT_EQ(egl.exitCode, 0) << egl.err;
  const RunResult osmesa =
      runCli("compare \"" + kDefaultScene + "\" --gl-context osmesa --repeat 1 --json --targets --out-dir \"" +
                 (dir / "osmesa").string() + "\"",
             dir);
  ASSERT_EQ(osmesa.exitCode, 0) << osmesa.err;
  const nlohmann::json e = nlohmann::json::parse(egl.out), o = nlohmann::json::parse(osmesa.out);
  EXPECT_NE(e["gl_context"].get<std::string>().find("EGL surfaceless"), std::string::npos) << e["gl_context"];
  EXPECT_NE(o["gl_context"].get<std::string>().find("OSMesa"), std::string::npos) << o["gl_context"];
  EXPECT_EQ(e["targets"]["applied"], true);
  EXPECT_EQ(metricsOnly(e), metricsOnly(o));
  EXPECT_EQ(readFile(dir / "egl" / "gl.png"), readFile(dir / "osmesa" / "gl.png"));
}

// A libOSMesa.so.8 that does not load, first on the search path: OSMesa is gone, EGL is not.
TEST(CliGlContext, CompareThroughEglWorksWithTheOsMesaLibraryHidden) {
  SKIP_WITHOUT_EGL();
  const auto dir = testDir("cli_gl_context");
  const auto hidden = dir / "hidden";
  std::filesystem::create_directories(hidden);
  std::ofstream(hidden / "libOSMesa.so.8").put('\0');  // not an ELF file: dlopen fails
  const std::string environment = "LD_LIBRARY_PATH=\"" + hidden.string() + "\"";
  const RunResult osmesa = runCliWith(environment,
                                      "render \"" + kDefaultScene + "\" --backend gl --width 32 --height 24 --out \"" +
                                          (dir / "osmesa.png").string() + "\"",
                                      dir);
  ASSERT_EQ(osmesa.exitCode, 2) << "OSMesa was not hidden: " << osmesa.out << osmesa.err;
  expectContains(osmesa.err, "cannot load the OSMesa library 'libOSMesa.so.8'");
  expectContains(osmesa.err, "--gl-context egl");
  const RunResult egl = runCliWith(environment,
                                   "compare \"" + kDefaultScene + "\" --gl-context egl --repeat 1 --targets "
                                   "--out-dir \"" + (dir / "out").string() + "\"",
                                   dir);
  ASSERT_EQ(egl.exitCode, 0) << egl.err;
  expectContains(egl.out, "gl context: EGL surfaceless platform");
  const RunResult automatic = runCliWith(environment,
                                         "render \"" + kDefaultScene + "\" --backend gl --gl-context auto -v "
                                         "--width 32 --height 24 --out \"" + (dir / "auto.png").string() + "\"",
                                         dir);
  ASSERT_EQ(automatic.exitCode, 0) << automatic.err;
  expectContains(automatic.err, "EGL surfaceless platform");
}

TEST(CliGlContext, RenderThroughEglWritesTheOsMesaBytes) {
  SKIP_WITHOUT_EGL();
  const auto dir = testDir("cli_gl_context");
  for (const char* context : {"egl", "osmesa"}) {
    const std::string png = (dir / (std::string(context) + ".png")).string();
    const RunResult r = runCli("render \"" + kDefaultScene + "\" --backend gl --gl-context " + context +
                                   " --width 160 --height 120 --out \"" + png + "\"",
                               dir);
    ASSERT_EQ(r.exitCode, 0) << context << ": " << r.err;
  }
  EXPECT_EQ(readFile(dir / "egl.png"), readFile(dir / "osmesa.png"));
}

TEST(CliGlContext, EglDeviceZeroRenders) {
  SKIP_WITHOUT_EGL();
  const auto dir = testDir("cli_gl_context");
  const RunResult r = runCli("render \"" + kDefaultScene + "\" --backend gl --gl-context egl --gl-device 0 -v "
                             "--width 32 --height 24 --out \"" + (dir / "device0.png").string() + "\"",
                             dir);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  expectContains(r.err, "EGL device 0");
}

TEST(CliGlContext, AMissingDeviceExitsTwoCountingTheDevices) {
  SKIP_WITHOUT_EGL();
  const auto dir = testDir("cli_gl_context");
  const RunResult r = runCli("compare \"" + kDefaultScene + "\" --gl-context egl --gl-device 99 --out-dir \"" +
                                 (dir / "out").string() + "\"",
                             dir);
  EXPECT_EQ(r.exitCode, 2);
  expectContains(r.err, "no EGL device 99: EGL lists ");
  expectContains(r.err, "info --gl");
}

TEST(CliGlContext, ADeviceWithOsMesaOrAnUnknownContextExitsTwo) {
  const auto dir = testDir("cli_gl_context");
  const RunResult device = runCli("render \"" + kDefaultScene + "\" --backend gl --gl-device 0 --out \"" +
                                      (dir / "x.png").string() + "\"",
                                  dir);
  EXPECT_EQ(device.exitCode, 2);
  expectContains(device.err, "--gl-device 0: devices are EGL's; add --gl-context egl");
  const RunResult unknown = runCli("bench \"" + kDefaultScene + "\" --gl-context glx", dir);
  EXPECT_EQ(unknown.exitCode, 2);
  expectContains(unknown.err, "--gl-context");
}

TEST(CliGlContext, InfoGlListsEveryContextWithItsRenderer) {
  SKIP_WITHOUT_EGL();
  const auto dir = testDir("cli_gl_context");
  const RunResult text = runCli("info --gl", dir);
  ASSERT_EQ(text.exitCode, 0) << text.err;
  expectContains(text.out, "  --gl-context osmesa: OSMesa 3.3 core context\n    GL_VENDOR ");
  expectContains(text.out, "  --gl-context egl: EGL surfaceless platform");
  expectContains(text.out, "  --gl-context egl --gl-device 0: EGL device 0");
  expectContains(text.out, "GL_RENDERER llvmpipe");
  const RunResult json = runCli("info --gl --json \"" + kDefaultScene + "\"", dir);
  ASSERT_EQ(json.exitCode, 0) << json.err;
  const nlohmann::json j = nlohmann::json::parse(json.out);
  EXPECT_EQ(j["triangles"], 3982);  // the scene's keys are still there
  ASSERT_TRUE(j["gl_contexts"].is_array());
  ASSERT_GE(j["gl_contexts"].size(), 3u);
  EXPECT_EQ(j["gl_contexts"][0]["context"], "osmesa");
  EXPECT_TRUE(j["gl_contexts"][0]["device"].is_null());
  EXPECT_EQ(j["gl_contexts"][1]["context"], "egl");
  EXPECT_EQ(j["gl_contexts"][2]["device"], 0);
  EXPECT_EQ(j["gl_contexts"][2]["options"], "--gl-context egl --gl-device 0");
  for (const nlohmann::json& c : j["gl_contexts"]) {
    EXPECT_TRUE(c["error"].is_null()) << c.dump();
    EXPECT_NE(c["gl_renderer"].get<std::string>().find("llvmpipe"), std::string::npos) << c.dump();
    EXPECT_EQ(c["llvmpipe"], true);
  }
}

TEST(CliGlContext, InfoWithoutSceneOrGlExitsTwo) {
  const auto dir = testDir("cli_gl_context");
  const RunResult r = runCli("info", dir);
  EXPECT_EQ(r.exitCode, 2);
  expectContains(r.err, "info: scene is required (a SCENE file, or --gl alone)");
}

// softpipe stands in for a GPU: not llvmpipe, so --targets gives no verdict and says so.
// (Mesa 22.3's softpipe draws nothing with these programs, so only the reporting is tested.)
TEST(CliGlContext, CompareOnADriverThatIsNotLlvmpipeReportsMetricsWithoutTargetVerdicts) {
  SKIP_WITHOUT_EGL();
  const auto dir = testDir("cli_gl_context");
  const RunResult r = runCliWith("GALLIUM_DRIVER=softpipe",
                                 "compare \"" + kDefaultScene + "\" --gl-context egl --repeat 1 --json --targets "
                                 "--width 80 --height 60 --out-dir \"" + (dir / "out").string() + "\"",
                                 dir);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(r.out);
  ASSERT_EQ(j["gl_renderer"], "softpipe") << "GALLIUM_DRIVER=softpipe was not honoured";
  EXPECT_EQ(j["gl_sampling"], "driver");
  EXPECT_EQ(j["targets"]["requested"], true);
  EXPECT_EQ(j["targets"]["applied"], false);
  expectContains(j["targets"]["note"].get<std::string>(), "is not llvmpipe");
  EXPECT_TRUE(j["thresholds"]["violations"].empty());
  EXPECT_TRUE(j.contains("max_abs_diff"));
  expectContains(r.err, "--targets not applied: GL_RENDERER 'softpipe' is not llvmpipe");
}

}  // namespace
}  // namespace twr::testcli
