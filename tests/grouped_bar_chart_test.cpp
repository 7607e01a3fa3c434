// The grouped bar chart of docs/accuracy.md's recall by cause.
#include <cmath>
#include <stdexcept>

#include <gtest/gtest.h>

#include "scanfilter/grouped_bar_chart.hpp"

namespace scanfilter {
namespace {

TEST(WrapWords, BreaksAtSpacesWithinTheWidthAndKeepsALongWordWhole) {
  EXPECT_EQ(wrapWords("displaced at grazing incidence", 10),
            (std::vector<std::string>{"displaced", "at grazing", "incidence"}));
  EXPECT_EQ(wrapWords("through a pane", 20), (std::vector<std::string>{"through a pane"}));
  EXPECT_EQ(wrapWords("a transflectometer", 5), (std::vector<std::string>{"a", "transflectometer"}));
  EXPECT_TRUE(wrapWords("", 5).empty());
}

// Counts the pixels of one colour in a column of the image.
int pixelsInColumn(const PngImage& image, int x, Rgb colour) {
  int n = 0;
  for (int y = 0; y < image.height(); ++y) n += image.get(x, y) == colour;
  return n;
}

// The column through the middle of series s's bar in group g, of `series`
// bars a group: the left margin, then per group half a gap, the bars, half a
// gap (grouped_bar_chart.cpp's layout).
int barColumn(int series, int g, int s) {
  constexpr int kBar = 16, kGap = 40, kLeft = 80;
  return kLeft + g * (series * kBar + kGap) + kGap / 2 + s * kBar + kBar / 2 - 1;
}

TEST(GroupedBarChart, BarsAreAsTallAsTheirShareAndNaNDrawsNone) {
  const Rgb red{214, 39, 40}, blue{31, 119, 180};
  GroupedBarChart chart("t", {"one", "two"});
  chart.addSeries("a", {1.0, 0.25}, red);
  chart.addSeries("b", {0.5, std::nan("")}, blue);
  const PngImage image = chart.draw();
  const int full = pixelsInColumn(image, barColumn(2, 0, 0), red);
  EXPECT_GT(full, 100);
  EXPECT_NEAR(pixelsInColumn(image, barColumn(2, 1, 0), red), full / 4, 2);
  EXPECT_NEAR(pixelsInColumn(image, barColumn(2, 0, 1), blue), full / 2, 2);
  EXPECT_EQ(pixelsInColumn(image, barColumn(2, 1, 1), blue), 0) << "nothing measured is no bar";
}

TEST(GroupedBarChart, ASeriesNeedsOneValuePerGroup) {
  GroupedBarChart chart("t", {"one", "two"});
  EXPECT_THROW(chart.addSeries("a", {0.5}, Rgb{0, 0, 0}), std::invalid_argument);
}

}  // namespace
}  // namespace scanfilter
