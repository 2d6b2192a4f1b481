// SSR against the ray tracer (raytrace/ssr_reference.h): the reference adds traced light to
// exactly the pixels that reflect and leaves the rest as the lit frame drew them; its rays land
// in the right class (a ceiling out of the frame is off_screen, the ball's underside occluded,
// an open sky sky); an SSR frame's error against it is small where the truth is visible and
// large where SSR cannot see; and bad requests are refused.
#include "raytrace/ssr_reference.h"

#include "scene/errors.h"
#include "scene/scene_file.h"
#include "softrender/cpu_renderer.h"
#include "softrender/vertex.h"
#include "tests/missing_dependency.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <string>

namespace twr {
namespace {

constexpr int kWidth = 160, kHeight = 120;

Scene mirrorFloor() {
  return loadSceneFile(std::string(TWINRASTER_SOURCE_DIR) + "/assets/scenes/ssr_mirror_floor.json");
}

// A mirror floor under a ceiling that stays above the frame, and a bright box the frame shows.
Scene floorUnderCeiling() {
  return parseScene(R"({
    "camera": {"position": [0, 2, 3], "target": [0, 0, 0], "fov_deg": 50, "near": 0.1, "far": 50},
    "ambient": [0.3, 0.3, 0.3],
    "lights": [{"type": "directional", "direction": [0.3, -1, -0.2], "diffuse": [1, 1, 1]}],
    "materials": {"mirror": {"kd": [0.1, 0.1, 0.1], "ssr_reflect": 1},
                  "lamp": {"kd": [0.9, 0.8, 0.2]}},
    "nodes": [
      {"name": "floor", "material": "mirror", "mesh": {"type": "plane", "size": [6, 6]}},
      {"name": "ceiling", "material": "lamp", "translate": [0, 5, 0], "rotate_deg": [180, 0, 0],
       "mesh": {"type": "plane", "size": [40, 40]}},
      {"name": "box", "material": "lamp", "translate": [0.8, 0.4, -0.5], "mesh": {"type": "cube", "size": 0.8}}
    ],
    "settings": {"ssr": {"enabled": true, "march": "dda_screen", "max_steps": 512, "thickness": 0.2}}})",
                    "floor_under_ceiling", ".");
}

RenderOutput baseOf(const Scene& scene) {
  return makeCpuRenderer()->render(scene, ssrBaseSettings(scene.settings), kWidth, kHeight);
}

std::uint64_t sum(const std::array<std::uint64_t, kSsrTruthCount>& counts) {
  return std::accumulate(counts.begin(), counts.end(), std::uint64_t{0});
}

TEST(SsrReference, TracesEveryReflectingPixelAndLeavesTheRestAsTheLitFrameDrewThem) {
  if (!rayTracerAvailable()) TWR_MISSING_DEPENDENCY("Embree") << rayTracerDescription();
  const Scene scene = mirrorFloor();
  const RenderOutput base = baseOf(scene);
  const SsrReference ref = traceSsrReference(scene, scene.settings, base, RayScene(scene));
  std::uint64_t reflecting = 0;
  for (std::size_t i = 0; i < ref.mirror.size(); ++i) {
    const bool reflects = base.triangleId[i] != kNoTriangle && base.gbuffer->specular[i].w > 0.0f;
    reflecting += reflects;
    EXPECT_EQ(reflects, ref.mirror[i] != SsrTruth::None) << i;
    if (reflects) continue;
    for (std::size_t c = 0; c < 4; ++c) ASSERT_EQ(ref.frame.rgba[4 * i + c], base.rgba[4 * i + c]) << i;
  }
  EXPECT_GT(reflecting, static_cast<std::uint64_t>(kWidth * kHeight / 3));
  EXPECT_EQ(sum(ref.mirrorRays), reflecting);
  EXPECT_EQ(ref.mirrorRays[static_cast<std::size_t>(SsrTruth::None)], 0u);
  EXPECT_GT(ref.mirrorRays[static_cast<std::size_t>(SsrTruth::Visible)], 200u) << "the cube and the ball";
  EXPECT_GT(ref.mirrorRays[static_cast<std::size_t>(SsrTruth::Sky)], 200u) << "the floor far from them";
  EXPECT_GT(ref.mirrorRays[static_cast<std::size_t>(SsrTruth::Occluded)], 0u) << "the ball's underside";
  EXPECT_EQ(sum(ref.indirectRays), 0u);
  // The traced light brightens: a reflecting pixel never gets darker.
  for (std::size_t i = 0; i < ref.mirror.size(); ++i) {
    for (std::size_t c = 0; c < 3; ++c) ASSERT_GE(ref.frame.rgba[4 * i + c], base.rgba[4 * i + c]) << i;
  }
}

TEST(SsrReference, AMarchIsCloseWhereTheTruthIsVisibleAndBlindOffScreen) {
  if (!rayTracerAvailable()) TWR_MISSING_DEPENDENCY("Embree") << rayTracerDescription();
  const Scene scene = floorUnderCeiling();
  const RenderOutput base = baseOf(scene);
  const SsrReference ref = traceSsrReference(scene, scene.settings, base, RayScene(scene));
  const auto count = [&](SsrTruth t) { return ref.mirrorRays[static_cast<std::size_t>(t)]; };
  EXPECT_GT(count(SsrTruth::OffScreen), 1000u) << "the ceiling above the frame";
  EXPECT_GT(count(SsrTruth::Visible), 50u) << "the box";
  const RenderOutput ssr = makeCpuRenderer()->render(scene, scene.settings, kWidth, kHeight);
  const SsrReferenceError e = measureSsrError(ref, ssr);
  const SsrErrorRow& visible = e.byClass[static_cast<std::size_t>(SsrErrorClass::Visible)];
  const SsrErrorRow& offScreen = e.byClass[static_cast<std::size_t>(SsrErrorClass::OffScreen)];
  EXPECT_EQ(visible.pixels, count(SsrTruth::Visible));
  EXPECT_EQ(offScreen.pixels, count(SsrTruth::OffScreen));
  EXPECT_LT(visible.meanAbs, 6.0) << "a march of one pixel a step finds what the frame shows";
  EXPECT_GT(offScreen.meanAbs, 40.0) << "the lit ceiling SSR cannot see";
  EXPECT_EQ(e.all.pixels, sum(ref.mirrorRays));
  // Against itself the reference has no error.
  const SsrReferenceError none = measureSsrError(ref, ref.frame);
  EXPECT_EQ(none.all.maxAbs, 0);
  EXPECT_EQ(none.all.pixels, e.all.pixels);
}

TEST(SsrReference, IndirectRaysUnderAnOpenSkyBringNothing) {
  if (!rayTracerAvailable()) TWR_MISSING_DEPENDENCY("Embree") << rayTracerDescription();
  Scene scene = floorUnderCeiling();
  scene.nodes.resize(1);  // the floor alone
  scene.settings.ssr.indirectSamples = 4;
  const RenderOutput base = baseOf(scene);
  const SsrReference ref = traceSsrReference(scene, scene.settings, base, RayScene(scene));
  EXPECT_EQ(ref.indirectSamples, 4);
  EXPECT_EQ(ref.indirectRays[static_cast<std::size_t>(SsrTruth::Sky)], 4 * sum(ref.mirrorRays));
  EXPECT_EQ(ref.mirrorRays[static_cast<std::size_t>(SsrTruth::Sky)], sum(ref.mirrorRays));
  EXPECT_EQ(ref.frame.rgba, base.rgba);
  // More samples than the frame's: the same sequence, longer.
  SsrReferenceOptions more;
  more.indirectSamples = 16;
  EXPECT_EQ(sum(traceSsrReference(scene, scene.settings, base, RayScene(scene), more).indirectRays),
            16 * sum(ref.mirrorRays));
}

TEST(SsrReference, IndirectLightUnderTheCeilingComesFromOffScreen) {
  if (!rayTracerAvailable()) TWR_MISSING_DEPENDENCY("Embree") << rayTracerDescription();
  Scene scene = floorUnderCeiling();
  Material& floor = scene.materials.at(0);
  ASSERT_EQ(floor.name, "mirror");
  floor.ssrReflect = 0.0f;
  floor.kd = vec3(0.3f);  // dim enough that the light it gets shows
  scene.settings.ssr.indirectSamples = 4;
  const RenderOutput base = baseOf(scene);
  const SsrReference ref = traceSsrReference(scene, scene.settings, base, RayScene(scene));
  EXPECT_EQ(sum(ref.mirrorRays), 0u);
  EXPECT_GT(ref.indirectRays[static_cast<std::size_t>(SsrTruth::OffScreen)],
            ref.indirectRays[static_cast<std::size_t>(SsrTruth::Sky)]);
  const SsrReferenceError e = measureSsrError(ref, makeCpuRenderer()->render(scene, scene.settings, kWidth, kHeight));
  EXPECT_GT(e.byClass[static_cast<std::size_t>(SsrErrorClass::IndirectOnly)].pixels, 0u);
  EXPECT_GT(e.byClass[static_cast<std::size_t>(SsrErrorClass::IndirectOnly)].meanAbs, 5.0);
}

TEST(SsrReference, AHitIsLitAsTheFrameLightsTheSameSurface) {
  if (!rayTracerAvailable()) TWR_MISSING_DEPENDENCY("Embree") << rayTracerDescription();
  // Rays from the eye through pixel centres: where the ray meets the triangle the frame shows
  // there, the hit shader's colour is the frame's, shadows and specular included.
  const Scene scene = mirrorFloor();
  const RenderOutput frame = baseOf(scene);
  const RayScene rays(scene);
  const HitShader shader(scene, scene.settings, frame.shadowMaps, kWidth, kHeight);
  const glm::dmat4 worldFromClip = glm::inverse(glm::dmat4(clipFromWorldFor(scene.camera, kWidth, kHeight)));
  const glm::dvec3 eye(scene.camera.position);
  int compared = 0, over2 = 0, largest = 0;
  for (int y = 0; y < kHeight; y += 2) {
    for (int x = 0; x < kWidth; x += 2) {
      const std::size_t i = static_cast<std::size_t>(y) * kWidth + static_cast<std::size_t>(x);
      if (frame.triangleId[i] == kNoTriangle) continue;
      const glm::dvec4 far = worldFromClip * glm::dvec4((x + 0.5) / kWidth * 2.0 - 1.0,
                                                        1.0 - (y + 0.5) / kHeight * 2.0, 1.0, 1.0);
      const glm::dvec3 dir = glm::normalize(glm::dvec3(far) / far.w - eye);
      const RayHit hit = rays.intersect(eye, dir, 0.0, 1e9);
      if (!hit.hit || hit.triangleId != frame.triangleId[i]) continue;
      const glm::dvec3 lit = shader.litAt(hit);
      int diff = 0;
      for (int c = 0; c < 3; ++c) {
        diff = std::max(diff, std::abs(static_cast<int>(std::lround(lit[c] * 255.0)) - frame.rgba[4 * i + static_cast<std::size_t>(c)]));
      }
      ++compared;
      over2 += diff > 2;
      largest = std::max(largest, diff);
    }
  }
  EXPECT_GT(compared, kWidth * kHeight / 8);
  EXPECT_LE(over2, compared / 200) << "largest " << largest << " levels";
}

TEST(SsrReference, RefusesWhatItCannotMeasure) {
  if (!rayTracerAvailable()) TWR_MISSING_DEPENDENCY("Embree") << rayTracerDescription();
  Scene scene = mirrorFloor();
  const RenderOutput base = baseOf(scene);
  const RayScene rays(scene);
  RenderSettings off = scene.settings;
  off.ssr.enabled = false;
  EXPECT_THROW(traceSsrReference(scene, off, base, rays), InputError);
  RenderSettings view = scene.settings;
  view.view = View::SsrHit;
  EXPECT_THROW(traceSsrReference(scene, view, base, rays), InputError);
  RenderSettings forward = scene.settings;
  forward.ssr.enabled = false;
  const RenderOutput noGBuffer = makeCpuRenderer()->render(scene, forward, kWidth, kHeight);
  EXPECT_THROW(traceSsrReference(scene, scene.settings, noGBuffer, rays), InputError);
  SsrReferenceOptions tooMany;
  tooMany.indirectSamples = kMaxSsrReferenceSamples + 1;
  EXPECT_THROW(traceSsrReference(scene, scene.settings, base, rays, tooMany), InputError);
  const SsrReference ref = traceSsrReference(scene, scene.settings, base, rays);
  const RenderOutput small = makeCpuRenderer()->render(scene, scene.settings, kWidth / 2, kHeight / 2);
  EXPECT_THROW(measureSsrError(ref, small), InputError);
}

}  // namespace
}  // namespace twr
