// A frame that covers nothing (compare/empty_frame.h): each way a scene can draw nothing is named
// in a user's terms, with where the scene and the camera are; a frame that draws is not.
#include "compare/empty_frame.h"

#include "scene/scene_file.h"
#include "softrender/cpu_renderer.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

namespace twr {
namespace {

Scene sceneFromText(const std::string& name, const std::string& text) {
  const std::string dir = std::string(TWINRASTER_TEST_OUT) + "/empty_frame";
  std::filesystem::create_directories(dir);
  const std::string path = dir + "/" + name + ".json";
  std::ofstream(path) << text;
  return loadSceneFile(path);
}

std::string reasonOf(const Scene& scene) {
  return emptyFrameReason(scene, makeCpuRenderer()->render(scene, scene.settings, 160, 120));
}

TEST(EmptyFrame, ACubeBehindTheCameraLiesOutsideTheView) {
  const Scene scene = sceneFromText("behind", R"({"camera": {"position": [0, 0, 4], "target": [0, 0, 0]},
    "nodes": [{"name": "cube", "translate": [0, 0, 20], "mesh": {"type": "cube", "size": 1}}]})");
  const std::string reason = reasonOf(scene);
  EXPECT_NE(reason.find("nothing was drawn: all its 12 triangles lie outside the view"), std::string::npos) << reason;
  EXPECT_NE(reason.find("the scene spans (-0.5, -0.5, 19.5) to (0.5, 0.5, 20.5)"), std::string::npos) << reason;
  EXPECT_NE(reason.find("the camera at (0, 0, 4) looks at (0, 0, 0)"), std::string::npos) << reason;
}

TEST(EmptyFrame, AQuadTurnedAwayIsCulled) {
  // The plane faces +Y; seen from below, back-face culling removes both its triangles.
  const Scene scene = sceneFromText("culled", R"({"camera": {"position": [0, -3, 0.01], "target": [0, 0, 0]},
    "nodes": [{"name": "floor", "mesh": {"type": "plane", "size": [2, 2]}}]})");
  const std::string reason = reasonOf(scene);
  EXPECT_NE(reason.find("all its 2 triangles were culled"), std::string::npos) << reason;
}

TEST(EmptyFrame, NoTriangleAtAll) {
  const Scene scene = sceneFromText("none", R"({"nodes": []})");
  const std::string reason = reasonOf(scene);
  EXPECT_NE(reason.find("the scene has no triangle to draw"), std::string::npos) << reason;
  EXPECT_NE(reason.find("the scene has no vertex"), std::string::npos) << reason;
}

TEST(EmptyFrame, AnotherRenderersFrameSaysWhatItCannotTell) {
  const Scene scene = sceneFromText("behind_gl", R"({"camera": {"position": [0, 0, 4], "target": [0, 0, 0]},
    "nodes": [{"name": "cube", "translate": [0, 0, 20], "mesh": {"type": "cube", "size": 1}}]})");
  RenderOutput frame = makeCpuRenderer()->render(scene, scene.settings, 160, 120);
  frame.stats.trianglesCulled = frame.stats.trianglesClipped = frame.stats.trianglesProduced = 0;  // as GL reports
  const std::string reason = emptyFrameReason(scene, frame, false);
  EXPECT_NE(reason.find("none of its 12 triangles covers a pixel"), std::string::npos) << reason;
}

TEST(EmptyFrame, AFrameThatDrawsHasNoReason) {
  const Scene scene = loadSceneFile(std::string(TWINRASTER_SOURCE_DIR) + "/assets/scenes/default.json");
  EXPECT_EQ(reasonOf(scene), "");
}

TEST(EmptyFrame, TheSceneFileSaysWhenAnEmptyFrameIsMeant) {
  const Scene meant = sceneFromText("meant", R"({"output": {"expect_empty": true}, "nodes": []})");
  EXPECT_TRUE(meant.output.expectEmpty);
  EXPECT_FALSE(sceneFromText("default", R"({"nodes": []})").output.expectEmpty);
  EXPECT_THROW(sceneFromText("bad", R"({"output": {"expect_empty": 1}, "nodes": []})"), std::exception);
}

}  // namespace
}  // namespace twr
