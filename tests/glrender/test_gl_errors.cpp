// Errors the GL path reports as InputError (exit 2) instead of crashing: a shader that
// does not compile (with file and line), a missing shader file, a missing OSMesa
// library, requests beyond the limits, immediate mode without a display for GLFW.
#include "gl_test_scenes.h"
#include "glrender/context_glfw.h"
#include "glrender/embedded_shaders.h"
#include "glrender/gl_renderer.h"
#include "scene/errors.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

namespace twr {
namespace {

namespace fs = std::filesystem;

Scene quadScene() {
  Scene scene = gltest::emptyScene();
  gltest::addNode(scene, gltest::quadAt(-2.0f, -1.0f, -1.0f, 1.0f, 1.0f), "quad");
  return scene;
}

// Runs `body`, expecting an InputError; returns its message.
template <typename Body>
std::string inputErrorOf(Body&& body) {
  try {
    body();
  } catch (const InputError& error) {
    return error.what();
  }
  ADD_FAILURE() << "expected an InputError";
  return "";
}

// A folder holding every embedded shader, so a test can break one of them.
fs::path shaderCopy(const std::string& name) {
  const fs::path dir = fs::path(TWINRASTER_TEST_OUT) / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  for (const EmbeddedShader& shader : embeddedShaders()) {
    std::ofstream(dir / shader.name, std::ios::binary) << shader.source;
  }
  return dir;
}

TEST(GlErrors, ShadersFromAFolderRenderLikeTheEmbeddedOnes) {
  const fs::path dir = shaderCopy("gl_shaders_intact");
  const Scene scene = quadScene();
  GlOptions options;
  options.shaderDir = dir.string();
  const RenderOutput fromDisk = makeGlRenderer(options)->render(scene, scene.settings, gltest::kSide, gltest::kSide);
  const RenderOutput embedded = makeGlRenderer()->render(scene, scene.settings, gltest::kSide, gltest::kSide);
  EXPECT_EQ(fromDisk.rgba, embedded.rgba);
}

TEST(GlErrors, ShaderCompileErrorNamesTheFileAndLine) {
  const fs::path dir = shaderCopy("gl_shader_broken");
  // Line 1 of phong.frag becomes a syntax error; common.glsl is joined before it, so the
  // line only comes out right if the log is mapped back per file.
  std::string source;
  for (const EmbeddedShader& shader : embeddedShaders()) {
    if (std::string(shader.name) == "phong.frag") source = shader.source;
  }
  ASSERT_FALSE(source.empty());
  std::ofstream(dir / "phong.frag", std::ios::binary) << "float brokenValue = ;\n" << source;

  const Scene scene = quadScene();
  GlOptions options;
  options.shaderDir = dir.string();
  const std::string message = inputErrorOf(
      [&] { makeGlRenderer(options)->render(scene, scene.settings, gltest::kSide, gltest::kSide); });
  const std::string where = (dir / "phong.frag").string() + ":1:";
  EXPECT_NE(message.find(where), std::string::npos) << message;
  EXPECT_NE(message.find("fragment shader of program 'phong'"), std::string::npos) << message;
  EXPECT_NE(message.find("failed to compile"), std::string::npos) << message;
  EXPECT_NE(message.find("VIEW_SHADED"), std::string::npos) << message;  // which permutation
}

TEST(GlErrors, MissingShaderFileIsNamed) {
  const fs::path dir = fs::path(TWINRASTER_TEST_OUT) / "gl_shaders_empty";
  fs::remove_all(dir);
  fs::create_directories(dir);
  const Scene scene = quadScene();
  GlOptions options;
  options.shaderDir = dir.string();
  const std::string message = inputErrorOf(
      [&] { makeGlRenderer(options)->render(scene, scene.settings, gltest::kSide, gltest::kSide); });
  EXPECT_NE(message.find((dir / "common.glsl").string()), std::string::npos) << message;
}

TEST(GlErrors, MissingOsMesaLibraryIsACleanError) {
  const Scene scene = quadScene();
  GlOptions options;
  options.osmesaLibrary = "libOSMesa-not-installed.so.0";
  const std::string message = inputErrorOf(
      [&] { makeGlRenderer(options)->render(scene, scene.settings, gltest::kSide, gltest::kSide); });
  EXPECT_NE(message.find("libOSMesa-not-installed.so.0"), std::string::npos) << message;
}

TEST(GlErrors, RequestsBeyondTheLimits) {
  Scene scene = quadScene();
  const auto renderer = makeGlRenderer();
  EXPECT_NE(inputErrorOf([&] { renderer->render(scene, scene.settings, 0, 10); }).find("image size"),
            std::string::npos);
  RenderSettings settings = scene.settings;
  settings.userClipPlanes.assign(kMaxUserClipPlanes + 1, vec4(0.0f, 0.0f, 0.0f, 1.0f));
  EXPECT_NE(inputErrorOf([&] { renderer->render(scene, settings, 8, 8); }).find("user clip planes"),
            std::string::npos);
  scene.lights.assign(kMaxLights + 1, Light{});
  EXPECT_NE(inputErrorOf([&] { renderer->render(scene, scene.settings, 8, 8); }).find("lights"),
            std::string::npos);
}

TEST(GlErrors, GlfwWithoutADisplayIsACleanError) {
  if (std::getenv("DISPLAY") || std::getenv("WAYLAND_DISPLAY")) GTEST_SKIP() << "a display is available";
  GlfwWindowDesc desc;
  desc.visible = false;
  const std::string message = inputErrorOf([&] { GlfwContext context(desc); });
  EXPECT_NE(message.find("GLFW"), std::string::npos) << message;
}

}  // namespace
}  // namespace twr
