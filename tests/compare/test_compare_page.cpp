// The comparison page's data (compare/compare_page.h): base64 as RFC 4648 gives it, the planes
// of pixels.js in their order, aligned and little-endian, and the page's text.
#include "compare/compare_page.h"

#include "compare/page_style.h"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

namespace twr {
namespace {

std::vector<std::uint8_t> bytesOf(const std::string& text) { return {text.begin(), text.end()}; }

TEST(ComparePage, Base64IsRfc4648sTestVectors) {
  EXPECT_EQ(base64Of(bytesOf("")), "");
  EXPECT_EQ(base64Of(bytesOf("f")), "Zg==");
  EXPECT_EQ(base64Of(bytesOf("fo")), "Zm8=");
  EXPECT_EQ(base64Of(bytesOf("foo")), "Zm9v");
  EXPECT_EQ(base64Of(bytesOf("foob")), "Zm9vYg==");
  EXPECT_EQ(base64Of(bytesOf("fooba")), "Zm9vYmE=");
  EXPECT_EQ(base64Of(bytesOf("foobar")), "Zm9vYmFy");
  EXPECT_EQ(base64Of({0xFF, 0xFE}), "//4=");
}

TEST(ComparePage, PlanesComeInOrderAlignedAndLittleEndian) {
  RenderOutput cpu, gl;
  cpu.width = gl.width = 2;
  cpu.height = gl.height = 1;
  cpu.rgba = {1, 2, 3, 255, 4, 5, 6, 255};
  gl.rgba = {1, 2, 4, 255, 0, 0, 0, 0};
  cpu.depth = {0.5f, 1.0f};
  gl.depth = {0.5f, 1.0f};
  cpu.triangleId = {0x01020304u, kNoTriangle};
  gl.triangleId = {0x01020304u, kNoTriangle};
  PixelAnalysis pixels;
  pixels.width = 2;
  pixels.height = 1;
  pixels.diffLevels = {1, 0};
  pixels.pixelClass = {PixelClass::Shading, PixelClass::CoverageCpu};
  const PixelPlanes planes = pixelPlanesOf(cpu, gl, pixels);
  const std::vector<std::string> names = {"cpu_rgba",     "gl_rgba",     "cpu_depth", "gl_depth",
                                          "cpu_triangle", "gl_triangle", "class",     "diff"};
  ASSERT_EQ(planes.planes.size(), names.size());
  std::size_t offset = 0;
  for (std::size_t i = 0; i < names.size(); ++i) {
    EXPECT_EQ(planes.planes[i].name, names[i]);
    EXPECT_EQ(planes.planes[i].offset, offset);
    if (planes.planes[i].type != "u8") {
      EXPECT_EQ(planes.planes[i].offset % 4, 0u) << names[i];
    }
    offset += planes.planes[i].bytes;
  }
  EXPECT_EQ(planes.bytes.size(), offset);
  EXPECT_EQ(planes.bytes.size(), 2u * 26u);  // 26 bytes per pixel
  // 0.5f is 0x3F000000: little-endian, its bytes 00 00 00 3F.
  const std::size_t depth = planes.planes[2].offset;
  EXPECT_EQ(planes.bytes[depth + 3], 0x3F);
  EXPECT_EQ(planes.bytes[depth], 0x00);
  const std::size_t triangle = planes.planes[4].offset;
  EXPECT_EQ(planes.bytes[triangle], 0x04);
  EXPECT_EQ(planes.bytes[triangle + 3], 0x01);
  EXPECT_EQ(planes.bytes[planes.planes[6].offset], static_cast<std::uint8_t>(PixelClass::Shading));
  EXPECT_EQ(planes.bytes[planes.planes[6].offset + 1], static_cast<std::uint8_t>(PixelClass::CoverageCpu));
  EXPECT_EQ(planes.bytes[planes.planes[7].offset], 1);
}

TEST(ComparePage, AMissingBufferIsFilledWithNothingDrawn) {
  RenderOutput cpu, gl;  // GL's lean frame: no depth, no triangle ids
  cpu.width = gl.width = 1;
  cpu.height = gl.height = 1;
  cpu.rgba = gl.rgba = {9, 9, 9, 255};
  cpu.depth = {0.25f};
  cpu.triangleId = {7};
  PixelAnalysis pixels;
  pixels.width = pixels.height = 1;
  pixels.diffLevels = {0};
  pixels.pixelClass = {PixelClass::Same};
  const PixelPlanes planes = pixelPlanesOf(cpu, gl, pixels);
  const std::size_t glDepth = planes.planes[3].offset, glTriangle = planes.planes[5].offset;
  EXPECT_EQ(planes.bytes[glDepth + 3], 0x3F);  // 1.0f: 0x3F800000
  EXPECT_EQ(planes.bytes[glDepth + 2], 0x80);
  for (int b = 0; b < 4; ++b) EXPECT_EQ(planes.bytes[glTriangle + b], 0xFF);  // kNoTriangle
}

TEST(ComparePage, ThePageNamesTheVerdictAndEscapesTheScene) {
  nlohmann::json metrics = {{"scene", "a<b>&\"c\".json"}, {"width", 4}, {"height", 2}, {"max_abs_diff", 3},
                            {"thresholds", {{"limits", {{"max_abs_diff", 2}}},
                                            {"violations", {{{"key", "max_abs_diff"}, {"message", "max_abs_diff 3 > 2"}}}},
                                            {"passed", false}}}};
  const std::string page = comparePageHtml(metrics);
  EXPECT_NE(page.find("a&lt;b&gt;&amp;&quot;c&quot;.json"), std::string::npos);
  // Unescaped only inside the metrics' JSON script, where only "</" could end it.
  EXPECT_EQ(page.substr(0, page.find("id=\"twr-metrics\"")).find("a<b>"), std::string::npos);
  EXPECT_NE(page.find("over the targets"), std::string::npos);
  EXPECT_NE(page.find("max_abs_diff 3 &gt; 2"), std::string::npos);
  EXPECT_NE(page.find("<td class=\"bad\">over</td>"), std::string::npos);
  metrics["thresholds"] = {{"limits", nlohmann::json::object()}, {"violations", nlohmann::json::array()}, {"passed", true}};
  EXPECT_NE(comparePageHtml(metrics).find("no targets"), std::string::npos);
}

TEST(ComparePage, JsonInsideTheScriptCannotCloseIt) {
  const nlohmann::json metrics = {{"scene", "</script><b>x"}, {"width", 1}, {"height", 1}};
  const std::string page = comparePageHtml(metrics);
  EXPECT_EQ(page.find("</script><b>"), std::string::npos);
  EXPECT_NE(page.find("<\\/script><b>x"), std::string::npos);
}

TEST(PageStyle, EscapesTheFiveCharacters) {
  EXPECT_EQ(escapeHtml("a&<>\"b'"), "a&amp;&lt;&gt;&quot;b'");
  EXPECT_NE(pageHead("t<").find("<title>t&lt;</title>"), std::string::npos);
  EXPECT_NE(pageHead("t").find(std::string(pageStyleSheet())), std::string::npos);
}

}  // namespace
}  // namespace twr
