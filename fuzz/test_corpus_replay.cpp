// Replays every input kept under tests/corpus/<target>/ through the fuzz target body that
// found it (fuzz/targets.h), with any compiler and no libFuzzer: each crash the fuzzers
// found, once fixed, stays fixed. Also checks that the targets' checks can fail at all.
#include "fuzz/support.h"
#include "fuzz/targets.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>
#include <vector>

namespace twr::fuzz {
namespace {

namespace fs = std::filesystem;

const fs::path kCorpusRoot = fs::path(TWINRASTER_SOURCE_DIR) / "tests" / "corpus";

std::vector<std::uint8_t> readBytes(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

void runTarget(const std::string& target, const Workspace& workspace, const std::vector<std::uint8_t>& bytes) {
  const std::uint8_t* data = bytes.data();
  if (target == "scene_file") fuzzSceneFile(workspace, data, bytes.size());
  else if (target == "obj_file") fuzzObjFile(workspace, data, bytes.size());
  else if (target == "image_file") fuzzImageFile(workspace, data, bytes.size());
  else if (target == "pipeline") fuzzPipeline(data, bytes.size());
  else FAIL() << "unknown target " << target;
}

class CorpusReplay : public ::testing::TestWithParam<std::string> {};

TEST_P(CorpusReplay, EveryKeptInputPasses) {
  const std::string target = GetParam();
  const fs::path dir = kCorpusRoot / target;
  ASSERT_TRUE(fs::is_directory(dir)) << dir << " is missing";
  std::vector<fs::path> files;
  for (const fs::directory_entry& entry : fs::directory_iterator(dir)) {
    if (entry.is_regular_file() && entry.path().filename() != "README.md") files.push_back(entry.path());
  }
  std::sort(files.begin(), files.end());
  ASSERT_FALSE(files.empty()) << "no inputs in " << dir;
  const Workspace workspace(fs::path(TWINRASTER_TEST_OUT) / "corpus-replay" / target);
  for (const fs::path& file : files) {
    try {
      runTarget(target, workspace, readBytes(file));
    } catch (const std::exception& e) {
      ADD_FAILURE() << file.filename().string() << ": " << e.what();
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Targets, CorpusReplay,
                         ::testing::ValuesIn(std::vector<std::string>(std::begin(kTargetNames), std::end(kTargetNames))),
                         [](const ::testing::TestParamInfo<std::string>& info) { return info.param; });

// ---- the checks themselves must be able to fail ----

RenderOutput cleanOutput(int width, int height) {
  const std::size_t pixels = static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
  RenderOutput out;
  out.width = width;
  out.height = height;
  out.rgba.assign(4 * pixels, 0);
  out.depth.assign(pixels, 1.0f);
  out.triangleId.assign(pixels, kNoTriangle);
  out.lineMask.assign(pixels, 0);
  return out;
}

TEST(FuzzChecks, RenderOutputChecksCatchEachBrokenPromise) {
  EXPECT_NO_THROW(checkRenderOutput(cleanOutput(3, 2), 3, 2, 0, 0, "clean"));
  RenderOutput nanDepth = cleanOutput(3, 2);
  nanDepth.depth[4] = std::numeric_limits<float>::quiet_NaN();
  EXPECT_THROW(checkRenderOutput(nanDepth, 3, 2, 0, 0, "nan"), InvariantViolation);
  RenderOutput farDepth = cleanOutput(3, 2);
  farDepth.depth[0] = 1.5f;
  EXPECT_THROW(checkRenderOutput(farDepth, 3, 2, 0, 0, "far"), InvariantViolation);
  RenderOutput badId = cleanOutput(3, 2);
  badId.triangleId[1] = 7;  // only 7 triangles: ids 0..6
  badId.rgba[4 * 1 + 3] = 255;
  EXPECT_THROW(checkRenderOutput(badId, 3, 2, 7, 0, "id"), InvariantViolation);
  badId.triangleId[1] = 6;
  EXPECT_NO_THROW(checkRenderOutput(badId, 3, 2, 7, 0, "id"));
  RenderOutput shortBuffer = cleanOutput(3, 2);
  shortBuffer.rgba.pop_back();
  EXPECT_THROW(checkRenderOutput(shortBuffer, 3, 2, 0, 0, "short"), InvariantViolation);
  RenderOutput strayAlpha = cleanOutput(3, 2);
  strayAlpha.rgba[3] = 255;  // nothing drawn there, the background's alpha is 0
  EXPECT_THROW(checkRenderOutput(strayAlpha, 3, 2, 0, 0, "alpha"), InvariantViolation);
  // An opaque background: every empty pixel must hold its alpha, not 0.
  EXPECT_THROW(checkRenderOutput(strayAlpha, 3, 2, 0, 255, "opaque"), InvariantViolation);
  RenderOutput opaque = cleanOutput(3, 2);
  for (std::size_t i = 3; i < opaque.rgba.size(); i += 4) opaque.rgba[i] = 255;
  EXPECT_NO_THROW(checkRenderOutput(opaque, 3, 2, 0, 255, "opaque"));
}

TEST(FuzzChecks, AnInputErrorMustNameTheInput) {
  EXPECT_NO_THROW(requireNamesInput(InputError("a.obj:3: bad"), "a.obj"));
  EXPECT_THROW(requireNamesInput(InputError("bad number on line 3"), "a.obj"), InvariantViolation);
}

TEST(FuzzChecks, ByteReaderIsTotalAndBounded) {
  // Past the end every read is zero, and intIn stays inside its inclusive bounds.
  const std::uint8_t bytes[] = {0xff, 0x80, 0x7f};
  ByteReader r(bytes, sizeof bytes);
  EXPECT_EQ(r.intIn(-3, 3), -3 + 0xff % 7);
  EXPECT_EQ(r.intIn(10, 10), 10);
  EXPECT_EQ(r.byte(), 0x7f);
  EXPECT_TRUE(r.exhausted());
  EXPECT_EQ(r.byte(), 0);
  EXPECT_EQ(r.u32(), 0u);
  EXPECT_EQ(r.hostileFloat(), 0.0f);  // selector 0 is the first special value, 0
}

}  // namespace
}  // namespace twr::fuzz
