#include "scanfilter/grouped_bar_chart.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <stdexcept>

namespace scanfilter {

namespace {
constexpr int kPlotHeight = 320;  // pixels from 0 to 1
constexpr int kBarWidth = 16, kGroupGap = 40;
constexpr int kLeft = 80, kTop = 60, kLabelLines = 4;
constexpr int kLegendGap = 20, kSwatchToText = 20;  // pixels: plot to swatch, swatch to its name
constexpr int kTextScale = 2;
constexpr int kLineHeight = 20;  // pixels a text line takes at kTextScale
constexpr double kTickStep = 0.25;
constexpr Rgb kAxis{60, 60, 60}, kGridLine{225, 225, 225}, kText{0, 0, 0};
}  // namespace

std::vector<std::string> wrapWords(const std::string& text, std::size_t max_chars) {
  std::vector<std::string> lines;
  std::istringstream words(text);
  std::string word, line;
  while (words >> word) {
    if (!line.empty() && line.size() + 1 + word.size() > max_chars) lines.push_back(std::move(line)), line.clear();
    line += (line.empty() ? "" : " ") + word;
  }
  if (!line.empty()) lines.push_back(std::move(line));
  return lines;
}

void GroupedBarChart::addSeries(const std::string& name, std::vector<double> values, Rgb colour) {
  if (values.size() != groups_.size())
    throw std::invalid_argument("GroupedBarChart: series '" + name + "' has " + std::to_string(values.size()) +
                                " values for " + std::to_string(groups_.size()) + " groups");
  series_.push_back({name, std::move(values), colour});
}

namespace {

// The y of share v on the plot whose 0 line is at `base`.
int shareY(int base, double v) { return base - static_cast<int>(std::lround(std::clamp(v, 0.0, 1.0) * kPlotHeight)); }

// Grid lines and their shares, drawn under the bars.
void drawShareGrid(PngImage& image, int base, int plot_width) {
  char tick[16];
  for (double v = 0.0; v <= 1.0 + 1e-9; v += kTickStep) {
    image.line(kLeft, shareY(base, v), kLeft + plot_width, shareY(base, v), kGridLine);
    std::snprintf(tick, sizeof tick, "%.2f", v);
    image.text(kLeft - 60, shareY(base, v) - 7, tick, kText, kTextScale);
  }
}

// The axes, drawn over the bars' feet.
void drawAxes(PngImage& image, int base, int plot_width) {
  image.line(kLeft, base, kLeft + plot_width, base, kAxis);
  image.line(kLeft, base, kLeft, kTop, kAxis);
}

}  // namespace

PngImage GroupedBarChart::draw() const {
  const int bars = static_cast<int>(std::max<std::size_t>(series_.size(), 1));
  const int group_width = bars * kBarWidth + kGroupGap;
  const int plot_width = static_cast<int>(groups_.size()) * group_width;
  const int legend_height = static_cast<int>(series_.size()) * kLineHeight;
  std::size_t longest_name = 0;
  for (const auto& s : series_) longest_name = std::max(longest_name, s.name.size());
  const int legend_width =
      kLegendGap + kSwatchToText + static_cast<int>(longest_name) * PngImage::glyphAdvance(kTextScale) + kLegendGap;
  const int height = kTop + std::max(kPlotHeight + kLabelLines * kLineHeight + kLineHeight, legend_height) + kLineHeight;
  PngImage image(kLeft + plot_width + legend_width, height);
  const int base = kTop + kPlotHeight;
  image.text(kLeft, 16, title_, kText, kTextScale);
  drawShareGrid(image, base, plot_width);
  for (std::size_t g = 0; g < groups_.size(); ++g)
    drawGroup(image, g, kLeft + static_cast<int>(g) * group_width + kGroupGap / 2, base, group_width);
  drawAxes(image, base, plot_width);
  drawLegend(image, kLeft + plot_width + kLegendGap);
  return image;
}

void GroupedBarChart::drawGroup(PngImage& image, std::size_t g, int x0, int base, int group_width) const {
  for (std::size_t s = 0; s < series_.size(); ++s) {
    const double v = series_[s].values[g];
    if (std::isnan(v)) continue;  // nothing measured: no bar, not a zero
    const int x = x0 + static_cast<int>(s) * kBarWidth;
    image.fillRect(x, shareY(base, v), x + kBarWidth - 2, base, series_[s].colour);
  }
  // A label keeps half a gap clear of the next group's.
  const auto chars_per_line =
      static_cast<std::size_t>((group_width - kGroupGap / 2) / PngImage::glyphAdvance(kTextScale));
  int y = base + 10;
  for (const auto& line : wrapWords(groups_[g], chars_per_line)) {
    image.text(x0, y, line, kText, kTextScale);
    y += kLineHeight;
  }
}

void GroupedBarChart::drawLegend(PngImage& image, int x) const {
  int y = kTop;
  for (const auto& s : series_) {
    image.fillRect(x, y, x + 12, y + 12, s.colour);
    image.text(x + kSwatchToText, y, s.name, kText, kTextScale);
    y += kLineHeight;
  }
}

}  // namespace scanfilter
