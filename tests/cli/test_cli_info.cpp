// `twinraster info`: runs the built CLI and checks exit codes, the text listing, the JSON
// object, and that bad scenes exit 2 naming the file.
#include "cli_run.h"

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace twr::testcli {
namespace {

const std::string kDefaultScene = kSource + "/assets/scenes/default.json";

RunResult runCli(const std::string& args) { return runProgram(TWINRASTER_CLI, args, testDir("cli_info")); }

TEST(CliInfo, TextListingOfTheDefaultScene) {
  const RunResult r = runCli("info \"" + kDefaultScene + "\"");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(r.err, "");
  // Hand-counted: sphere 32 stacks x 64 slices has (32 + 1) * (64 + 1) = 2145 vertices and
  // 64 * (2 * 32 - 2) = 3968 triangles; the plane 4 and 2, the cube 24 and 12.
  expectContains(r.out, "  floor: plane 8 x 8, uv_scale 4; 2 triangles, 4 vertices; material floor");
  expectContains(r.out, "  ball: sphere radius 0.8, 32 stacks x 64 slices; 3968 triangles, 2145 vertices; material bricks");
  expectContains(r.out, "  box: cube size 1.2; 12 triangles, 24 vertices; material bricks");
  expectContains(r.out, "total: 3982 triangles, 2173 vertices in 3 drawn meshes");
  expectContains(r.out, "materials (2):");
  expectContains(r.out, "shininess 32; maps: diffuse " + kSource + "/assets/textures/bricks_diffuse.png (512x512 PNG, 10 levels built), normal " +
                            kSource + "/assets/textures/bricks_normal.png (512x512 PNG, 10 levels built), specular ");
  expectContains(r.out, "lights (2)");
  expectContains(r.out, "[1] position (-4, 3, -1)");
  expectContains(r.out, "camera: position (0.3, 1.7, 4.4), target (0, 0.5, 0), fov_deg 50");
  expectContains(r.out, "output: 640x480");
  expectContains(r.out, "view shaded, pipeline forward, lighting_space world, tangent_transform model, texture_filter bilinear, interpolation perspective");
}

TEST(CliInfo, ObjPartsShowAsAChildTree) {
  const RunResult r = runCli("info \"" + kSource + "/tests/scene/data_scenes/obj_parts.json\"");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  expectContains(r.out, "  model: (no mesh)\n    model/red: obj part of ");
  expectContains(r.out, "    extra: cube size 1; 12 triangles, 24 vertices; material (default)");
  expectContains(r.out, "total: 20 triangles, 40 vertices in 5 drawn meshes");
}

TEST(CliInfo, JsonIsOneObjectWithTheDocumentedKeys) {
  const RunResult r = runCli("info --json \"" + kDefaultScene + "\"");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  nlohmann::json j;
  ASSERT_NO_THROW(j = nlohmann::json::parse(r.out)) << r.out;
  ASSERT_TRUE(j.is_object());
  for (const char* key : {"nodes", "triangles", "vertices", "materials", "lights", "camera", "settings", "output"}) {
    EXPECT_TRUE(j.contains(key)) << key;
  }
  EXPECT_EQ(j["triangles"], 3982);
  EXPECT_EQ(j["vertices"], 2173);
  ASSERT_EQ(j["nodes"].size(), 3u);
  EXPECT_EQ(j["nodes"][1]["name"], "ball");
  EXPECT_EQ(j["nodes"][1]["mesh"]["type"], "sphere");
  EXPECT_EQ(j["nodes"][1]["mesh"]["stacks"], 32);
  EXPECT_EQ(j["nodes"][1]["triangles"], 3968);
  EXPECT_EQ(j["nodes"][1]["material"], "bricks");
  EXPECT_EQ(j["nodes"][1]["translate"], nlohmann::json::parse("[-1.0, 0.8, 0.0]"));
  ASSERT_EQ(j["materials"].size(), 2u);
  EXPECT_EQ(j["materials"][0]["name"], "bricks");
  EXPECT_EQ(j["materials"][0]["normal_map"]["width"], 512);
  EXPECT_TRUE(j["materials"][1]["specular_map"].is_null());
  ASSERT_EQ(j["lights"].size(), 2u);
  EXPECT_EQ(j["lights"][0]["attenuation"], nlohmann::json::parse("[1.0, 0.045, 0.0075]"));
  EXPECT_EQ(j["camera"]["fov_deg"], 50.0);
  EXPECT_EQ(j["settings"]["cull"], "back");
  EXPECT_EQ(j["settings"]["tbn_lines"]["mode"], "core");
  EXPECT_EQ(j["output"]["width"], 640);
  EXPECT_EQ(j["output"]["height"], 480);
}

// A captured environment has no cube until a renderer draws one: info says where it comes
// from and what each renderer will build, in text and JSON.
TEST(CliInfo, CapturedEnvironment) {
  const std::string scene = kSource + "/assets/scenes/env_capture_glossy.json";
  const RunResult text = runCli("info \"" + scene + "\"");
  ASSERT_EQ(text.exitCode, 0) << text.err;
  expectContains(text.out, "environment: captured from node \"probe\" by each renderer before each frame, 64x64 per face, "
                           "7 levels, intensity 1, no sky box");
  expectContains(text.out, "  read as a dual_paraboloid map built from each capture at 256x256");
  expectContains(text.out, "  satin: prefiltered, reflectivity 0.7, fresnel schlick, diffuse irradiance_map");
  const RunResult json = runCli("info --json \"" + scene + "\"");
  ASSERT_EQ(json.exitCode, 0) << json.err;
  const nlohmann::json j = nlohmann::json::parse(json.out);
  const nlohmann::json& env = j["environment"];
  EXPECT_EQ(env["source"], "capture");
  EXPECT_EQ(env["capture"]["node"], "probe");
  EXPECT_EQ(env["capture"]["size"], 64);
  EXPECT_EQ(env["face_size"], 64);
  EXPECT_EQ(env["levels"], 7);
  EXPECT_EQ(env["map_size"], 256);
  EXPECT_TRUE(env["materials"].contains("satin"));
  EXPECT_EQ(j["camera"]["up"], nlohmann::json::parse("[0.0, 1.0, 0.0]"));
}

TEST(CliInfo, DirectionalLights) {
  const std::string scene = kSource + "/assets/scenes/light_directional.json";
  const RunResult text = runCli("info \"" + scene + "\"");
  ASSERT_EQ(text.exitCode, 0) << text.err;
  expectContains(text.out, "  [0] directional, direction (");
  expectContains(text.out, "unattenuated");
  const RunResult json = runCli("info --json \"" + scene + "\"");
  ASSERT_EQ(json.exitCode, 0) << json.err;
  const nlohmann::json j = nlohmann::json::parse(json.out);
  ASSERT_EQ(j["lights"].size(), 2u);
  EXPECT_EQ(j["lights"][0]["type"], "directional");
  EXPECT_TRUE(j["lights"][0]["position"].is_null());
  EXPECT_EQ(j["lights"][0]["attenuation"], nlohmann::json::parse("[1.0, 0.0, 0.0]"));
  const std::vector<double> d = j["lights"][0]["direction"].get<std::vector<double>>();
  ASSERT_EQ(d.size(), 3u);
  EXPECT_NEAR(d[0] * d[0] + d[1] * d[1] + d[2] * d[2], 1.0, 1e-6);  // made unit length at load
  const RunResult plain = runCli("info --json \"" + kDefaultScene + "\"");
  EXPECT_EQ(nlohmann::json::parse(plain.out)["lights"][0]["type"], "point");
}

TEST(CliInfo, ShadowMaps) {
  const std::string scene = kSource + "/assets/scenes/shadow_point_cube.json";
  const RunResult text = runCli("info \"" + scene + "\"");
  ASSERT_EQ(text.exitCode, 0) << text.err;
  expectContains(text.out, "shadow map: cube 512^2 x 6, bias 0.01 world units + 1 texels of slope, pcf 3x3, extent from the scene's bounds");
  const RunResult json = runCli("info --json \"" + scene + "\"");
  ASSERT_EQ(json.exitCode, 0) << json.err;
  const nlohmann::json shadow = nlohmann::json::parse(json.out)["lights"][0]["shadow"];
  EXPECT_EQ(shadow["kind"], "cube");
  EXPECT_EQ(shadow["size"], 512);
  EXPECT_EQ(shadow["layers"], 6);
  EXPECT_EQ(shadow["pcf"], 3);
  const RunResult plain = runCli("info --json \"" + kDefaultScene + "\"");
  EXPECT_TRUE(nlohmann::json::parse(plain.out)["lights"][0]["shadow"].is_null());
  EXPECT_TRUE(nlohmann::json::parse(plain.out)["lights"][0]["spot"].is_null());
  // A spot light: its cone, and one perspective map over it.
  const std::string spotScene = kSource + "/assets/scenes/shadow_spot.json";
  const RunResult spotText = runCli("info \"" + spotScene + "\"");
  ASSERT_EQ(spotText.exitCode, 0) << spotText.err;
  expectContains(spotText.out, "full within 22 deg, none beyond 32 deg");
  expectContains(spotText.out, "shadow map: perspective (the spot's cone) 1024^2, bias");
  const RunResult spotJson = runCli("info --json \"" + spotScene + "\"");
  const nlohmann::json spot = nlohmann::json::parse(spotJson.out)["lights"][0];
  EXPECT_EQ(spot["shadow"]["kind"], "perspective");
  EXPECT_EQ(spot["shadow"]["layers"], 1);
  EXPECT_EQ(spot["spot"]["outer_deg"], 32.0);
  EXPECT_EQ(spot["spot"]["inner_deg"], 22.0);
}

TEST(CliInfo, NamesTheCpuTargetActuallyUsedAndEverySupportedOne) {
  const RunResult r = runCli("info --json \"" + kDefaultScene + "\"");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(r.out);
  ASSERT_TRUE(j.contains("cpu_isa"));
  ASSERT_TRUE(j["cpu_isas_supported"].is_array());
  const nlohmann::json& supported = j["cpu_isas_supported"];
  // Best first, scalar always there and last (but in a build whose kernels CMake's
  // TWINRASTER_KERNEL_TARGETS chose, as the sanitizer build's); auto resolves to the best one.
  ASSERT_FALSE(supported.empty());
#ifdef TWINRASTER_KERNEL_TARGETS
  for (const auto& name : supported) expectContains("," TWINRASTER_KERNEL_TARGETS ",", "," + name.get<std::string>() + ",");
#else
  EXPECT_EQ(supported.back(), "scalar");
#endif
  EXPECT_EQ(j["cpu_isa"], supported.front());
  for (const auto& name : supported) {
    const std::string text = name.get<std::string>();
    EXPECT_TRUE(text == "avx512" || text == "avx2" || text == "sse4" || text == "neon" || text == "scalar") << text;
  }
  const RunResult t = runCli("info \"" + kDefaultScene + "\"");
  ASSERT_EQ(t.exitCode, 0) << t.err;
  expectContains(t.out, "cpu: the fast path runs on " + j["cpu_isa"].get<std::string>() + " here (--cpu-isa auto)");
  expectContains(t.out, "targets this machine runs: " + supported.front().get<std::string>());
}

TEST(CliInfo, BadSceneExitsTwoNamingTheFileAndKey) {
  const std::string scene = kSource + "/tests/scene/data_scenes/bad_texture.json";
  const RunResult r = runCli("info \"" + scene + "\"");
  EXPECT_EQ(r.exitCode, 2);
  expectContains(r.err, scene + ": materials.bricks.normal_map: ");
  EXPECT_EQ(r.out, "");
}

TEST(CliInfo, SyntaxErrorExitsTwoWithLine) {
  const std::string scene = kSource + "/tests/scene/data_scenes/syntax_error.json";
  const RunResult r = runCli("info --json \"" + scene + "\"");
  EXPECT_EQ(r.exitCode, 2);
  expectContains(r.err, scene + ": line 4, column 9:");
}

TEST(CliInfo, MissingFileExitsTwo) {
  const RunResult r = runCli("info /nonexistent/scene.json");
  EXPECT_EQ(r.exitCode, 2);
  expectContains(r.err, "/nonexistent/scene.json: cannot open scene file");
}

TEST(CliInfo, MissingArgumentExitsTwo) {
  const RunResult r = runCli("info");
  EXPECT_EQ(r.exitCode, 2);
  expectContains(r.err, "scene is required");
}

TEST(CliInfo, HelpDescribesTheCommand) {
  const RunResult r = runCli("info --help");
  EXPECT_EQ(r.exitCode, 0);
  expectContains(r.out, "--json");
  expectContains(r.out, "triangle and vertex counts");
  const RunResult top = runCli("--help");
  EXPECT_EQ(top.exitCode, 0);
  expectContains(top.out, "info");
}

}  // namespace
}  // namespace twr::testcli
