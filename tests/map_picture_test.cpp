#include "scanfilter/map_picture.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace scanfilter {
namespace {

constexpr Rgb kMarked = {255, 0, 0};  // a colour no map, text or frame uses
constexpr Rgb kBlack = {0, 0, 0};

PngImage cellsWithOneMarked(int width, int height) {
  PngImage cells(width, height, {205, 205, 205});
  cells.set(width / 2, height / 2, kMarked);
  return cells;
}

int count(const PngImage& image, Rgb colour) {
  int n = 0;
  for (int y = 0; y < image.height(); ++y)
    for (int x = 0; x < image.width(); ++x) n += image.get(x, y) == colour;
  return n;
}

int longestBlackRun(const PngImage& image) {
  int longest = 0;
  for (int y = 0; y < image.height(); ++y)
    for (int x = 0, run = 0; x < image.width(); ++x) {
      run = image.get(x, y) == kBlack ? run + 1 : 0;
      longest = std::max(longest, run);
    }
  return longest;
}

// A room (100 x 60 cells at 5 cm) would be a thumbnail one pixel a cell.
TEST(MapPicture, SmallMapCellsBecomeSquares) {
  const PngImage picture = mapPicture({cellsWithOneMarked(100, 60)}, 0.05, "ROOM");
  EXPECT_EQ(count(picture, kMarked), 8 * 8);
  EXPECT_GE(picture.width(), 800);
}

TEST(MapPicture, LargeMapKeepsOnePixelACell) {
  const PngImage picture = mapPicture({cellsWithOneMarked(1200, 900)}, 0.05, "BUILDING");
  EXPECT_EQ(count(picture, kMarked), 1);
  EXPECT_GE(picture.width(), 1200);
}

TEST(MapPicture, PanelsSideBySide) {
  const PngImage one = mapPicture({cellsWithOneMarked(100, 60)}, 0.05, "A");
  const PngImage two = mapPicture({cellsWithOneMarked(100, 60), cellsWithOneMarked(100, 60)}, 0.05, "A");
  EXPECT_EQ(count(two, kMarked), 2 * count(one, kMarked));
  EXPECT_GE(two.width(), 2 * 800);
}

// 8 pixels a cell of 5 cm is 160 pixels a metre; a quarter of the picture
// (820 px) holds 1.3 m, so the bar is 1 m: 160 pixels, the longest black
// line in the picture (text and swatches are far shorter).
TEST(MapPicture, ScaleBarIsARoundLengthAtTheMapsScale) {
  const PngImage picture = mapPicture({cellsWithOneMarked(100, 60)}, 0.05, "ROOM");
  EXPECT_EQ(longestBlackRun(picture), 160);
  const PngImage coarse = mapPicture({cellsWithOneMarked(1200, 900)}, 0.05, "BUILDING");
  // 20 pixels a metre, a quarter of 1,220 px is 15 m: the bar is 10 m.
  EXPECT_EQ(longestBlackRun(coarse), 200);
}

// A corridor (20 cells wide) would cut the legend off at the map's width.
TEST(MapPicture, ANarrowMapsPictureHoldsItsLegendAndItsTitle) {
  const std::vector<std::pair<Rgb, std::string>> legend = {
      {{0, 0, 0}, "OCCUPIED"}, {{254, 254, 254}, "FREE"}, {{205, 205, 205}, "UNKNOWN"}};
  const PngImage corridor = mapPicture({cellsWithOneMarked(20, 150)}, 0.05, "C");
  EXPECT_GT(corridor.width(), PngImage::legendWidth(legend));
  const std::string long_title(80, 'T');
  const PngImage titled = mapPicture({cellsWithOneMarked(20, 150)}, 0.05, long_title);
  EXPECT_GT(titled.width(), static_cast<int>(long_title.size()) * PngImage::glyphAdvance(2));
}

TEST(MapPicture, NoMapOrNoCellSizeIsAnError) {
  EXPECT_THROW(mapPicture({}, 0.05, "NONE"), std::invalid_argument);
  EXPECT_THROW(mapPicture({cellsWithOneMarked(10, 10)}, 0.0, "ZERO"), std::invalid_argument);
  EXPECT_THROW(mapPicture({cellsWithOneMarked(10, 10)}, std::nan(""), "NAN"), std::invalid_argument);
}

}  // namespace
}  // namespace scanfilter
