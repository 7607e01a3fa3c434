#pragma once
// A grouped bar chart of shares (0-1) as PNG: one group per category, one
// coloured bar per series in each; for the recall per artefact cause of
// every filter in docs/accuracy.md.
#include <cstddef>
#include <string>
#include <utility>
#include <vector>

#include "scanfilter/png_image.hpp"

namespace scanfilter {

class GroupedBarChart {
 public:
  GroupedBarChart(std::string title, std::vector<std::string> groups)
      : title_(std::move(title)), groups_(std::move(groups)) {}
  // One value per group, in [0, 1]; NaN: no bar (nothing to measure there).
  void addSeries(const std::string& name, std::vector<double> values, Rgb colour);
  PngImage draw() const;

 private:
  // Group g's bars from x0, their 0 line at `base`, and its label below.
  void drawGroup(PngImage& image, std::size_t g, int x0, int base, int group_width) const;
  // One swatch and name per series, a line each, from x.
  void drawLegend(PngImage& image, int x) const;

  struct Series {
    std::string name;
    std::vector<double> values;
    Rgb colour;
  };
  std::string title_;
  std::vector<std::string> groups_;
  std::vector<Series> series_;
};

// `text` broken at spaces into lines of at most `max_chars` characters (a
// longer word stays whole on its own line).
std::vector<std::string> wrapWords(const std::string& text, std::size_t max_chars);

}  // namespace scanfilter
