// Hostile inputs through `twinraster` as a user runs it: real-world OBJ files from Debian's
// assimp-testmodels (a sample; fuzz/test_real_world_models.cpp loads every one in process)
// and bad scene files, textures and special files. Each run either writes an image or exits
// with code 2, "twinraster: error: " and a message that names the file and the problem,
// and writes no image. Never a crash (any other exit code, or a signal, fails).
#include "cli_run.h"

#include "scene/image.h"
#include "scene/scene_file.h"
#include "tests/missing_dependency.h"

#include <nlohmann/json.hpp>

#include <fstream>
#include <iterator>

namespace twr::testcli {
namespace {

namespace fs = std::filesystem;

const fs::path kAssimpObj = "/usr/share/assimp/models/OBJ";

RunResult runCli(const std::string& args, const fs::path& dir) { return runProgram(TWINRASTER_CLI, args, dir); }

std::string quoted(const fs::path& path) { return "\"" + path.string() + "\""; }

void writeText(const fs::path& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out << text;
}

// A scene showing one OBJ file from a fixed camera (the model's size does not matter here).
fs::path objScene(const fs::path& dir, const fs::path& obj) {
  const fs::path scene = dir / (obj.stem().string() + ".json");
  writeText(scene, R"({"settings": {"cull": "none"}, "nodes": [{"name": "m", "mesh": {"type": "obj", "path": )" +
                       nlohmann::json(obj.string()).dump() + "}}]}");
  return scene;
}

// `render` with one backend must succeed and write an image of the requested size.
void expectRenders(const fs::path& dir, const fs::path& scene, const std::string& backend) {
  const fs::path png = dir / (scene.stem().string() + "-" + backend + ".png");
  const RunResult r =
      runCli("render " + quoted(scene) + " --backend " + backend + " --width 64 --height 48 --out " + quoted(png), dir);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const Image image = loadPng(png.string());
  EXPECT_EQ(image.width, 64);
  EXPECT_EQ(image.height, 48);
}

// `render` must exit 2 with "twinraster: error: <start>..." containing `detail`, and write nothing.
void expectRefused(const fs::path& dir, const std::string& sceneArgument, const std::string& start,
                   const std::string& detail) {
  const fs::path png = dir / "refused.png";
  fs::remove(png);
  const RunResult r = runCli("render " + sceneArgument + " --out " + quoted(png), dir);
  EXPECT_EQ(r.exitCode, 2) << r.err;
  EXPECT_EQ(r.err.rfind("twinraster: error: " + start, 0), 0u) << r.err;
  expectContains(r.err, detail);
  EXPECT_FALSE(fs::exists(png)) << "a refused render wrote an image";
}

// An override with an empty value names no setting (issue 22, class 15): exit 2 naming the
// option, for each of them, rather than silently using the scene's own.
TEST(CliHostile, EmptyOverrideValuesAreRefused) {
  const fs::path dir = fs::path(TWINRASTER_TEST_OUT) / "cli_hostile_empty_overrides";
  fs::create_directories(dir);
  const std::string scene = quoted(fs::path(TWINRASTER_SOURCE_DIR) / "assets/scenes/default.json");
  for (const char* option : {"--view", "--cull", "--front-face", "--lighting-space", "--tangent-transform", "--interpolation",
                             "--filter"}) {
    const fs::path png = dir / "empty.png";
    fs::remove(png);
    const RunResult r = runCli("render " + scene + " " + option + " \"\" --out " + quoted(png), dir);
    EXPECT_EQ(r.exitCode, 2) << option << ": " << r.err;
    expectContains(r.err, std::string(option) + ": an empty value names no setting");
    EXPECT_FALSE(fs::exists(png)) << option;
  }
}

// A scene file whose name is not UTF-8 (issue 22, class 13): the JSON outputs replace the bad
// byte (U+FFFD) instead of ending in nlohmann's type_error with a 0-byte metrics.json.
TEST(CliHostile, NonUtf8SceneNameInJsonOutputs) {
  const fs::path dir = fs::path(TWINRASTER_TEST_OUT) / "cli_hostile_non_utf8";
  fs::create_directories(dir);
  std::ifstream in(fs::path(TWINRASTER_SOURCE_DIR) / "assets/scenes/default.json", std::ios::binary);
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::string textures = (fs::path(TWINRASTER_SOURCE_DIR) / "assets/textures/").string();
  for (std::size_t at = text.find("../textures/"); at != std::string::npos; at = text.find("../textures/", at)) {
    text.replace(at, 12, textures);
  }
  const fs::path scene = dir / std::string("scene\xff\xfe.json");
  writeText(scene, text);
  const RunResult compare = runCli("compare " + quoted(scene) + " --width 64 --height 48 --out-dir " + quoted(dir / "out"), dir);
  EXPECT_EQ(compare.exitCode, 0) << compare.err;
  std::ifstream metricsFile(dir / "out" / "metrics.json");
  const nlohmann::json metrics = nlohmann::json::parse(metricsFile, nullptr, false);
  ASSERT_FALSE(metrics.is_discarded()) << "metrics.json is not JSON";
  EXPECT_NE(metrics.value("scene", std::string()).find("\xEF\xBF\xBD"), std::string::npos) << "expected U+FFFD";
  const RunResult info = runCli("info --json " + quoted(scene), dir);
  EXPECT_EQ(info.exitCode, 0) << info.err;
  EXPECT_FALSE(nlohmann::json::parse(info.out, nullptr, false).is_discarded()) << info.out.substr(0, 200);
}

TEST(CliHostile, RealWorldObjSample) {
  if (!fs::is_directory(kAssimpObj)) {
    TWR_MISSING_DEPENDENCY("assimp-testmodels") << kAssimpObj << " is missing: install Debian's assimp-testmodels (scripts/install-deps.sh does)";
  }
  const auto dir = testDir("cli_hostile");
  // UTF-16, material names with spaces, Windows texture paths to JPEGs: rendered by both.
  for (const char* name : {"box_UTF16BE.obj", "space_in_material_name.obj", "spider.obj"}) {
    SCOPED_TRACE(name);
    const fs::path scene = objScene(dir, kAssimpObj / name);
    expectRenders(dir, scene, "cpu");
    expectRenders(dir, scene, "gl");
  }
  // A malformed number and a points-only file: refused, naming scene, key, OBJ and line.
  const fs::path numbers = objScene(dir, kAssimpObj / "number_formats.obj");
  expectRefused(dir, quoted(numbers), numbers.string() + ": nodes[0].mesh.path: " + (kAssimpObj / "number_formats.obj").string(),
                "number_formats.obj:11: 'v' expects finite numbers, got '3.1+e2'");
  const fs::path points = objScene(dir, kAssimpObj / "point_cloud.obj");
  expectRefused(dir, quoted(points), points.string() + ": nodes[0].mesh.path: ", "has no triangles");
  // `compare` runs both renderers in one process on a model that loads.
  const RunResult r = runCli("compare " + quoted(objScene(dir, kAssimpObj / "concave_polygon.obj")) + " --out-dir " +
                                 quoted(dir / "compare") + " --width 64 --height 48 --repeat 1 --json",
                             dir);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(nlohmann::json::parse(r.out).at("nan_pixels"), 0);
}

// Models the default camera does not see (three of assimp-testmodels' OBJ files lie outside
// the view or cover no pixel): compare says nothing was drawn, and why, and --targets fails;
// a scene that says it expects an empty frame passes without the warning.
TEST(CliHostile, AComparisonOfNothingFailsTheTargets) {
  if (!fs::is_directory(kAssimpObj)) {
    TWR_MISSING_DEPENDENCY("assimp-testmodels") << kAssimpObj << " is missing: install Debian's assimp-testmodels (scripts/install-deps.sh does)";
  }
  const auto dir = testDir("cli_hostile_empty");
  for (const char* name : {"regr01.obj", "regr_3429812.obj", "multiple_spaces.obj"}) {
    SCOPED_TRACE(name);
    // The scene's own defaults: back faces culled, the default camera.
    const fs::path scene = dir / (fs::path(name).stem().string() + ".json");
    writeText(scene, R"({"nodes": [{"name": "m", "mesh": {"type": "obj", "path": )" +
                         nlohmann::json((kAssimpObj / name).string()).dump() + "}}]}");
    const RunResult r = runCli("compare " + quoted(scene) + " --out-dir " + quoted(dir / "out") +
                                   " --width 160 --height 120 --repeat 1 --targets --json",
                               dir);
    EXPECT_EQ(r.exitCode, 1) << r.out << r.err;
    expectContains(r.err, "warning: nothing was drawn: ");
    expectContains(r.err, "the camera at (0, 1, 4) looks at (0, 0, 0)");
    const nlohmann::json j = nlohmann::json::parse(r.out);
    EXPECT_EQ(j.at("covered_cpu"), 0);
    EXPECT_TRUE(j.at("empty_frame").is_string());
    const RunResult render = runCli("render " + quoted(scene) + " --backend cpu --width 160 --height 120 --out " +
                                        quoted(dir / "empty.png"),
                                    dir);
    EXPECT_EQ(render.exitCode, 0) << render.err;
    expectContains(render.err, "warning: nothing was drawn: ");
  }
  // The same scene with output.expect_empty: no warning, and the targets hold.
  const fs::path meant = dir / "meant.json";
  writeText(meant, R"({"output": {"expect_empty": true}, "nodes": [{"name": "m", "mesh": {"type": "obj", "path": )" +
                       nlohmann::json((kAssimpObj / "regr01.obj").string()).dump() + "}}]}");
  const RunResult r = runCli("compare " + quoted(meant) + " --out-dir " + quoted(dir / "out") +
                                 " --width 160 --height 120 --repeat 1 --targets",
                             dir);
  EXPECT_EQ(r.exitCode, 0) << r.out << r.err;
  EXPECT_EQ(r.err.find("nothing was drawn"), std::string::npos) << r.err;
}

// Cameras beyond what float resolves (issue 22, classes 7-9): refused with exit 2 when no
// faithful picture exists (a view narrower than one float step, a projection out of range),
// drawn as OpenGL draws it with a "warning:" line when the picture is GL's but not what the
// scene means (depth rounding to the cleared 1.0), silent for an ordinary camera.
TEST(CliHostile, CamerasBeyondFloatAreRefusedOrWarned) {
  const auto dir = testDir("cli_hostile_projection");
  const auto sceneWithCamera = [&](const std::string& name, const std::string& camera) {
    const fs::path path = dir / (name + ".json");
    writeText(path, R"({"camera": )" + camera + R"(, "nodes": [{"name": "box", "mesh": {"type": "cube"}}]})");
    return path;
  };
  for (const char* fov : {"1e-30", "1e-12", "1e-7"}) {
    const fs::path scene = sceneWithCamera(std::string("fov") + fov, std::string(R"({"fov_deg": )") + fov + "}");
    expectRefused(dir, quoted(scene), scene.string() + ": camera: fov_deg", "Use fov_deg >=");
  }
  const fs::path far = sceneWithCamera("far", R"({"near": 2e38, "far": 3e38, "position": [0, 1e38, 3e38]})");
  expectRefused(dir, quoted(far), far.string() + ": camera: near 2e+38 and far 3e+38", "beyond float's range");

  const RunResult big = runCli("render " + quoted(sceneWithCamera("size", "{}")) + " --width 16384 --height 16384 --out " +
                                    quoted(dir / "big.png"), dir);
  EXPECT_EQ(big.exitCode, 2) << big.err;
  expectContains(big.err, "--width/--height: image size 16384x16384 is 268435456 pixels, at most 67108864");
  EXPECT_FALSE(fs::exists(dir / "big.png"));

  const fs::path lost = sceneWithCamera("lost", R"({"near": 1e-9})");
  const RunResult drawn = runCli("render " + quoted(lost) + " --width 64 --height 48 --out " + quoted(dir / "lost.png"), dir);
  EXPECT_EQ(drawn.exitCode, 0) << drawn.err;
  expectContains(drawn.err, "warning: camera.near 1e-09: every vertex in view ('box' 100 %) get window depth 1.0");
  const fs::path fine = sceneWithCamera("fine", R"({"near": 0.1, "fov_deg": 0.5})");
  const RunResult quiet = runCli("render " + quoted(fine) + " --width 64 --height 48 --out " + quoted(dir / "fine.png"), dir);
  EXPECT_EQ(quiet.exitCode, 0) << quiet.err;
  EXPECT_EQ(quiet.err.find("warning:"), std::string::npos) << quiet.err;
}

TEST(CliHostile, BadSceneFiles) {
  const auto dir = testDir("cli_hostile");
  writeText(dir / "empty.json", "");
  expectRefused(dir, quoted(dir / "empty.json"), (dir / "empty.json").string() + ": line 1, column 1:", "invalid JSON");
  writeText(dir / "truncated.json", R"({"nodes": [{"name": "a", "mesh": {"type": "sph)");
  expectRefused(dir, quoted(dir / "truncated.json"), (dir / "truncated.json").string() + ": line 1,", "invalid JSON");
  expectRefused(dir, quoted(dir), dir.string() + ": cannot open scene file (it is a directory)", "directory");
  if (fs::exists("/dev/zero")) expectRefused(dir, "/dev/zero", "/dev/zero: cannot open scene file", "not a regular file");
  const fs::path huge = dir / "huge.json";
  writeText(huge, "{");
  fs::resize_file(huge, kMaxSceneFileBytes + 1);
  expectRefused(dir, quoted(huge), huge.string() + ": scene file is ", "larger than the limit of 32 MiB");
  writeText(dir / "deep.json", R"({"nodes": [], "ambient": )" + std::string(100000, '[') + std::string(100000, ']') + "}");
  expectRefused(dir, quoted(dir / "deep.json"), (dir / "deep.json").string() + ": ambient[0]", "JSON nests deeper than");
  writeText(dir / "many.json", R"({"nodes": [{"mesh": {"type": "sphere", "stacks": 4096, "slices": 4096}}]})");
  expectRefused(dir, quoted(dir / "many.json"), (dir / "many.json").string() + ": nodes[0].mesh: ",
                "at most 20000000 are allowed");
  writeText(dir / "bright.json", R"({"nodes": [], "lights": [{"diffuse": [1e30, 1, 1]}]})");
  expectRefused(dir, quoted(dir / "bright.json"), (dir / "bright.json").string() + ": lights[0].diffuse[0]: ",
                "expected a number in [0, 10000]");
}

TEST(CliHostile, BadTexturesAndModels) {
  const auto dir = testDir("cli_hostile");
  writeText(dir / "truncated.png", std::string("\x89PNG\r\n\x1a\n\0\0\0\x0dIHDR", 16));
  writeText(dir / "tex.json", R"({"materials": {"m": {"diffuse_map": "truncated.png"}}, "nodes": []})");
  expectRefused(dir, quoted(dir / "tex.json"), (dir / "tex.json").string() + ": materials.m.diffuse_map: " +
                                                   (dir / "truncated.png").string() + ": ",
                "image");
  writeText(dir / "gif.png", "GIF89a");
  writeText(dir / "gif.json", R"({"materials": {"m": {"normal_map": "gif.png"}}, "nodes": []})");
  expectRefused(dir, quoted(dir / "gif.json"), (dir / "gif.json").string() + ": materials.m.normal_map: ",
                "expected a PNG, JPEG, BMP, TGA, DDS or Radiance HDR file");
  writeText(dir / "bad.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4\n");
  writeText(dir / "obj.json", R"({"nodes": [{"mesh": {"type": "obj", "path": "bad.obj"}}]})");
  expectRefused(dir, quoted(dir / "obj.json"), (dir / "obj.json").string() + ": nodes[0].mesh.path: " +
                                                   (dir / "bad.obj").string() + ":4: a face references",
                "index");
  // `info` loads the same way and refuses the same way.
  const RunResult r = runCli("info " + quoted(dir / "obj.json"), dir);
  EXPECT_EQ(r.exitCode, 2);
  expectContains(r.err, "bad.obj:4");
}

}  // namespace
}  // namespace twr::testcli
