// `twinraster info`'s description of a loaded scene: the counts are the built meshes', floats
// print as their shortest decimal, and the text and the JSON tell the same tree.
#include "scene/scene_description.h"
#include "scene/scene_file.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <sstream>
#include <string>

namespace twr {
namespace {

const std::string kDataDir = std::string(TWINRASTER_SOURCE_DIR) + "/tests/scene/data_scenes/";

Scene twoNodeScene() {
  return parseScene(R"({
    "materials": {"plain": {"kd": [0.05, 0.5, 1]}},
    "nodes": [
      {"name": "ball", "material": "plain", "mesh": {"type": "sphere", "radius": 1, "stacks": 4, "slices": 8},
       "children": [{"name": "box", "mesh": {"type": "cube", "size": 0.3}}]}
    ],
    "lights": [{"type": "point", "position": [0, 4, 2]}]})",
                    "description.json", kDataDir);
}

TEST(SceneDescription, JsonCountsTheBuiltMeshesAndKeepsShortDecimals) {
  const nlohmann::ordered_json j = sceneDescriptionJson(twoNodeScene());
  ASSERT_EQ(j["nodes"].size(), 1u);
  EXPECT_EQ(j["nodes"][0]["name"], "ball");
  ASSERT_EQ(j["nodes"][0]["children"].size(), 1u);
  EXPECT_EQ(j["nodes"][0]["children"][0]["name"], "box");
  // A UV sphere of 4 stacks and 8 slices has 2 * 8 * (4 - 1) triangles; a cube 12.
  EXPECT_EQ(j["triangles"].get<int>(), 2 * 8 * 3 + 12);
  ASSERT_EQ(j["materials"].size(), 1u);
  EXPECT_EQ(j["materials"][0]["kd"][0].get<double>(), 0.05);  // not 0.05000000074505806
  EXPECT_EQ(j["lights"].size(), 1u);
  for (const char* key : {"scene", "nodes", "triangles", "vertices", "materials", "lights", "ambient", "camera",
                          "settings", "output"}) {
    EXPECT_TRUE(j.contains(key)) << key;
  }
}

TEST(SceneDescription, TextListsTheTreeIndentedAndTheTotals) {
  std::ostringstream out;
  printSceneDescription(out, twoNodeScene());
  const std::string text = out.str();
  const std::size_t ball = text.find("ball");
  const std::size_t box = text.find("  box");
  ASSERT_NE(ball, std::string::npos) << text;
  ASSERT_NE(box, std::string::npos) << text;
  EXPECT_LT(ball, box) << text;
  EXPECT_NE(text.find("total: " + std::to_string(2 * 8 * 3 + 12) + " triangles"), std::string::npos) << text;
  EXPECT_NE(text.find("plain"), std::string::npos) << text;
}

}  // namespace
}  // namespace twr
