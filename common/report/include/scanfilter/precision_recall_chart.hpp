#pragma once
// A precision/recall scatter chart as PNG: one labelled marker per filter,
// with iso-F1 curves, for the accuracy comparison in docs/accuracy.md.
#include <string>
#include <vector>

#include "scanfilter/png_image.hpp"

namespace scanfilter {

class PrecisionRecallChart {
 public:
  explicit PrecisionRecallChart(std::string title) : title_(std::move(title)) {}
  void add(const std::string& name, double precision, double recall, Rgb colour);
  PngImage draw() const;

 private:
  struct Entry {
    std::string name;
    double precision;
    double recall;
    Rgb colour;
  };
  std::string title_;
  std::vector<Entry> entries_;
};

// A distinct colour for series k (cycles after the palette's end).
Rgb seriesColour(std::size_t k);

}  // namespace scanfilter
