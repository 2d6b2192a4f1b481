// The march record's helpers (scene/ssr_trace.h, scene/ssr_trace_report.h): where two traces
// part, which steps end a march, the text table and the JSON `trace` prints.
#include "scene/ssr_trace.h"
#include "scene/errors.h"
#include "scene/settings.h"
#include "scene/ssr_trace_report.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <string>

namespace twr {
namespace {

SsrMarchTrace threeSteps() {
  SsrMarchTrace t;
  t.marched = true;
  t.direction = vec3(0.0f, 0.0f, -1.0f);
  t.steps = {SsrMarchStep{vec2(10.0f, 20.0f), 4.0f, 5.0f, 0, 1.0f, SsrStepKind::InFront},
             SsrMarchStep{vec2(12.0f, 20.0f), 4.5f, 6.0f, 2, 3.0f, SsrStepKind::CellSkipped},
             SsrMarchStep{vec2(14.0f, 21.0f), 5.05f, 5.0f, 0, 4.0f, SsrStepKind::Hit}};
  return t;
}

TEST(SsrTrace, FirstDifferingStep) {
  const SsrMarchTrace a = threeSteps();
  SsrMarchTrace b = a;
  EXPECT_FALSE(firstDifferingStep(a, b));
  b.steps[2].rayDistance *= 1.000001f;  // within the tolerance
  EXPECT_FALSE(firstDifferingStep(a, b));
  b.steps[1].level = 1;
  EXPECT_EQ(firstDifferingStep(a, b), 1u);
  b = a;
  b.steps[2].pixel.x = 15.0f;
  EXPECT_EQ(firstDifferingStep(a, b), 2u);
  b = a;
  b.steps[0].surfaceDistance = 5.01f;
  EXPECT_EQ(firstDifferingStep(a, b), 0u);
  b = a;
  b.steps.pop_back();
  EXPECT_EQ(firstDifferingStep(a, b), 2u) << "one has a step the other has not";
}

TEST(SsrTrace, EndingKinds) {
  for (const SsrStepKind k : {SsrStepKind::Hit, SsrStepKind::Behind, SsrStepKind::OffScreen, SsrStepKind::Ended}) {
    EXPECT_TRUE(endsMarch(k)) << toString(k);
  }
  for (const SsrStepKind k : {SsrStepKind::InFront, SsrStepKind::Refine, SsrStepKind::CellSkipped, SsrStepKind::CellDescend}) {
    EXPECT_FALSE(endsMarch(k)) << toString(k);
  }
  EXPECT_STREQ(toString(SsrStepKind::CellSkipped), "cell_skipped");
}

TEST(SsrTrace, TextAndJson) {
  const SsrMarchTrace a = threeSteps();
  SsrMarchTrace b = a;
  b.steps[1].kind = SsrStepKind::CellDescend;
  const std::string text = formatSsrMarchTraces("cpu", a, "gl", &b);
  EXPECT_NE(text.find("cell_skipped L2"), std::string::npos) << text;
  EXPECT_NE(text.find("*   2"), std::string::npos) << text;
  EXPECT_NE(text.find("cpu and gl part at step 2"), std::string::npos) << text;
  EXPECT_NE(formatSsrMarchTraces("cpu", a, "gl", &a).find("take the same 3 steps"), std::string::npos);
  SsrMarchTrace unfinished = a;
  unfinished.steps.pop_back();
  EXPECT_NE(formatSsrMarchTraces("cpu", unfinished, "", nullptr).find("max_steps ran out"), std::string::npos);
  EXPECT_NE(formatSsrMarchTraces("cpu", SsrMarchTrace{}, "", nullptr).find("nothing drawn"), std::string::npos);
  const nlohmann::json j = ssrMarchTraceToJson(a);
  EXPECT_EQ(j["steps"].size(), 3u);
  EXPECT_EQ(j["steps"][1]["kind"], "cell_skipped");
  EXPECT_EQ(j["steps"][1]["level"], 2);
  EXPECT_EQ(j["steps"][2]["pixel"][0], 14.0);
  EXPECT_TRUE(j["marched"].get<bool>());
  EXPECT_EQ(j["ray"], "mirror");
  EXPECT_EQ(text.find("directions differ"), std::string::npos) << text;
  EXPECT_EQ(text.find("sample weight"), std::string::npos) << "a mirror ray has no weight to show";
  // An indirect sample's trace shows its weight, and directions an ulp apart are shown in full.
  SsrMarchTrace sample = a;
  sample.ray = 3;
  sample.weight = 1.5f;
  SsrMarchTrace other = sample;
  other.direction.z = std::nextafter(other.direction.z, 0.0f);
  const std::string sampleText = formatSsrMarchTraces("cpu", sample, "gl", &other);
  EXPECT_NE(sampleText.find("sample weight 1.50000"), std::string::npos) << sampleText;
  EXPECT_NE(sampleText.find("directions differ: cpu (0, 0, -1), gl (0, 0, -0.99999994)"), std::string::npos)
      << sampleText;
  EXPECT_EQ(ssrMarchTraceToJson(sample)["ray"], 3);
  EXPECT_EQ(ssrMarchTraceToJson(sample)["weight"], 1.5);
}

TEST(SsrTrace, RaysTheSettingsHave) {
  RenderSettings settings;
  settings.ssr.indirectSamples = 0;
  EXPECT_NO_THROW(checkSsrRay(settings, kSsrMirrorRay));
  try {
    checkSsrRay(settings, 0);
    ADD_FAILURE() << "no samples, no sample 0";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("indirect_samples is 0 (the mirror ray is the only one)"), std::string::npos)
        << e.what();
  }
  settings.ssr.indirectSamples = 4;
  for (int k = 0; k < 4; ++k) EXPECT_NO_THROW(checkSsrRay(settings, k)) << k;
  EXPECT_THROW(checkSsrRay(settings, 4), InputError);
  EXPECT_THROW(checkSsrRay(settings, -2), InputError);
  EXPECT_EQ(ssrRayName(kSsrMirrorRay), "mirror ray");
  EXPECT_EQ(ssrRayName(2), "indirect sample 2");
}

}  // namespace
}  // namespace twr
