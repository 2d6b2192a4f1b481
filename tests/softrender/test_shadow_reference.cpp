// Shadow maps against shadow rays (softrender/shadow_reference.h) on the shadow_directional
// scene: the traced shadow is there and the map agrees with it nearly everywhere at 2048^2,
// less so at 64^2; a map made wrong on purpose (a huge bias) loses the shadow, and the
// measurement says so.
#include "softrender/shadow_reference.h"

#include "scene/errors.h"
#include "scene/scene_file.h"
#include "softrender/cpu_renderer.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace twr {
namespace {

constexpr int kWidth = 160, kHeight = 120;

Scene shadowScene() { return loadSceneFile(std::string(TWINRASTER_SOURCE_DIR) + "/assets/scenes/shadow_directional.json"); }

ShadowVisibility measure(const Scene& scene) {
  const RenderOutput frame = makeCpuRenderer()->render(scene, scene.settings, kWidth, kHeight);
  return measureShadowVisibility(scene, 0, frame, TriangleBvh(scene));
}

TEST(ShadowReference, TheMapAgreesWithTheTracedShadowAndLessSoWhenCoarse) {
  Scene scene = shadowScene();
  const ShadowVisibility fine = measure(scene);
  EXPECT_GT(fine.measured, static_cast<std::uint64_t>(kWidth * kHeight / 4));
  EXPECT_GT(fine.tracedShadowed, 50u) << "the cube and the ball cast a shadow on the floor";
  EXPECT_LT(fine.wrongPercent(), 1.0);
  scene.lights[0].shadow->size = 64;
  scene.lights[0].shadow->pcf = 1;
  const ShadowVisibility coarse = measure(scene);
  EXPECT_EQ(coarse.measured, fine.measured);  // the same pixels: only the map changed
  EXPECT_EQ(coarse.tracedShadowed, fine.tracedShadowed);
  EXPECT_GT(coarse.wrong, fine.wrong);
  // Unmeasured pixels are NaN on both sides, measured ones 0 or 1 traced.
  for (std::size_t i = 0; i < fine.traced.size(); ++i) {
    EXPECT_EQ(std::isnan(fine.traced[i]), std::isnan(fine.map[i]));
    if (!std::isnan(fine.traced[i])) {
      EXPECT_TRUE(fine.traced[i] == 0.0 || fine.traced[i] == 1.0);
    }
  }
}

TEST(ShadowReference, AHugeBiasLosesTheShadowAndTheMeasurementSeesIt) {
  Scene scene = shadowScene();
  scene.lights[0].shadow->bias = vec2(50.0f, 0.0f);  // world units: deeper than the scene, nothing shadows
  const ShadowVisibility v = measure(scene);
  EXPECT_GT(v.tracedShadowed, 0u);
  EXPECT_EQ(v.wrong, v.tracedShadowed) << "every traced shadow is lit by the map";
}

TEST(ShadowReference, RefusesALightWithoutAMap) {
  Scene scene = shadowScene();
  scene.lights[0].shadow.reset();
  const RenderOutput frame = makeCpuRenderer()->render(scene, scene.settings, kWidth, kHeight);
  EXPECT_THROW(measureShadowVisibility(scene, 0, frame, TriangleBvh(scene)), InputError);
}

}  // namespace
}  // namespace twr
