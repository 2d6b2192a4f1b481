// makeMontage: canvas size and tile placement by hand, refusals; makeInteriorHeatMap: the
// colour of each pixel class.
#include "compare/draw.h"
#include "compare/montage.h"
#include "scene/errors.h"
#include "synthetic_outputs.h"

#include <gtest/gtest.h>

namespace twr {
namespace {

Image solid(int w, int h, std::uint8_t grey) {
  Image image = makeImage(w, h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) setPixel(image, x, y, Rgb8{grey, grey, grey});
  return image;
}

Rgb8 at(const Image& image, int x, int y) {
  const std::uint8_t* p = image.pixel(x, y);
  return {p[0], p[1], p[2]};
}

TEST(Montage, LayoutByHand) {
  // Five 20 x 10 tiles, three columns, gap 2: two rows.
  std::vector<MontageTile> tiles;
  for (int i = 0; i < 5; ++i) {
    std::string label = "t";
    label += std::to_string(i);
    tiles.push_back({label, solid(20, 10, static_cast<std::uint8_t>(50 * i + 10))});
  }
  const Image m = makeMontage(tiles, {3, 2});
  const int label = montageLabelHeight(20);
  EXPECT_GT(label, 0);
  EXPECT_EQ(m.width, 3 * 20 + 2 * 2);
  EXPECT_EQ(m.height, 2 * (label + 10) + 2);
  // Tile 4 (row 1, column 1): its top-left pixel, and the gap beside it is panel colour.
  EXPECT_EQ(at(m, 22, label + 10 + 2 + label), (Rgb8{210, 210, 210}));
  EXPECT_EQ(at(m, 20, label), kColourPanel);
  // Tile 0's image starts under its label strip.
  EXPECT_EQ(at(m, 0, label), (Rgb8{10, 10, 10}));
  // The last cell of row 1 (no sixth tile) stays panel.
  EXPECT_EQ(at(m, 2 * 22 + 5, label + 10 + 2 + label + 5), kColourPanel);
  for (std::size_t i = 3; i < m.rgba.size(); i += 4) ASSERT_EQ(m.rgba[i], 255);
}

TEST(Montage, Refusals) {
  EXPECT_THROW(makeMontage({}), InputError);
  EXPECT_THROW(makeMontage({{"a", solid(4, 4, 0)}, {"b", solid(4, 5, 0)}}), InputError);
  EXPECT_THROW(makeMontage({{"a", solid(4, 4, 0)}}, {0, 2}), InputError);
  EXPECT_THROW(makeMontage({{"a", solid(4, 4, 0)}}, {1, -1}), InputError);
}

TEST(InteriorHeatMap, ColoursPerClass) {
  using testing::clearPixel;
  using testing::rgbaAt;
  RenderOutput approx = testing::makeSolidOutput(3, 1, 100, 100, 100);
  RenderOutput reference = testing::makeSolidOutput(3, 1, 100, 100, 100);
  rgbaAt(reference, 0, 0)[0] = 140;  // interior, 40 levels off
  clearPixel(reference, 1, 0);       // approximation only
  clearPixel(approx, 2, 0);          // reference only
  const InteriorSplit split = splitInterior(approx, reference);
  const HeatRamp ramp;
  const Image heat = makeInteriorHeatMap(approx, reference, split, ramp);
  EXPECT_EQ(at(heat, 0, 0), heatColour(40, ramp));
  EXPECT_EQ(at(heat, 1, 0), kColourCpuOnly);
  EXPECT_EQ(at(heat, 2, 0), kColourGlOnly);
  InteriorSplit wrong = split;
  wrong.width = 2;
  EXPECT_THROW(makeInteriorHeatMap(approx, reference, wrong), InputError);
}

}  // namespace
}  // namespace twr
