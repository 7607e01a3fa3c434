#include "scanfilter/precision_recall_chart.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>

namespace scanfilter {

namespace {
constexpr int kPlotSize = 560;  // pixels of the unit square
constexpr int kLeft = 90, kTop = 80, kRight = 540, kBottom = 80;
constexpr int kTextScale = 2;
constexpr Rgb kAxis{60, 60, 60}, kGridLine{225, 225, 225}, kIsoF1{200, 200, 235}, kText{0, 0, 0};
constexpr std::array<double, 3> kIsoF1Levels = {0.5, 0.7, 0.9};
constexpr double kTickStep = 0.2;

}  // namespace

Rgb seriesColour(std::size_t k) {
  static constexpr std::array<Rgb, 9> kPalette = {{{214, 39, 40},
                                                    {31, 119, 180},
                                                    {44, 160, 44},
                                                    {255, 127, 14},
                                                    {148, 103, 189},
                                                    {140, 86, 75},
                                                    {227, 119, 194},
                                                    {127, 127, 127},
                                                    {23, 190, 207}}};
  return kPalette[k % kPalette.size()];
}

void PrecisionRecallChart::add(const std::string& name, double precision, double recall, Rgb colour) {
  entries_.push_back({name, precision, recall, colour});
}

PngImage PrecisionRecallChart::draw() const {
  PngImage image(kLeft + kPlotSize + kRight, kTop + kPlotSize + kBottom);
  const auto px = [](double recall) { return kLeft + static_cast<int>(std::lround(recall * kPlotSize)); };
  const auto py = [](double precision) { return kTop + kPlotSize - static_cast<int>(std::lround(precision * kPlotSize)); };
  image.text(kLeft, 12, title_, kText, kTextScale);
  char tick[16];
  for (double v = 0.0; v <= 1.0 + 1e-9; v += kTickStep) {
    image.line(px(v), py(0), px(v), py(1), kGridLine);
    image.line(px(0), py(v), px(1), py(v), kGridLine);
    std::snprintf(tick, sizeof tick, "%.1f", v);
    image.text(px(v) - 12, py(0) + 10, tick, kText, kTextScale);
    image.text(kLeft - 50, py(v) - 7, tick, kText, kTextScale);
  }
  // Iso-F1 curves: precision = F r / (2 r - F), for recall from F/2 (+eps) to 1.
  for (double f : kIsoF1Levels) {
    int last_x = -1, last_y = -1;
    for (int step = 0; step <= kPlotSize; ++step) {
      const double r = static_cast<double>(step) / kPlotSize;
      if (2 * r - f <= 0) continue;
      const double p = f * r / (2 * r - f);
      if (p > 1.0) continue;
      if (last_x >= 0) image.line(last_x, last_y, px(r), py(p), kIsoF1);
      last_x = px(r), last_y = py(p);
    }
    std::snprintf(tick, sizeof tick, "F1=%.1f", f);
    image.text(px(1) + 4, py(f / (2 - f)) - 7, tick, kIsoF1, kTextScale);
  }
  image.line(px(0), py(0), px(1), py(0), kAxis);
  image.line(px(0), py(0), px(0), py(1), kAxis);
  image.text(px(0.5) - 30, py(0) + 40, "RECALL", kText, kTextScale);
  image.text(8, kTop - 28, "PRECISION", kText, kTextScale);
  // Markers, and a legend on the right (labels beside markers would overlap).
  int legend_y = kTop + 10;
  for (const auto& e : entries_) {
    image.disc(px(std::clamp(e.recall, 0.0, 1.0)), py(std::clamp(e.precision, 0.0, 1.0)), 6, e.colour);
    image.disc(kLeft + kPlotSize + 96, legend_y + 6, 6, e.colour);
    image.text(kLeft + kPlotSize + 110, legend_y, e.name, kText, kTextScale);
    legend_y += 24;
  }
  return image;
}

}  // namespace scanfilter
