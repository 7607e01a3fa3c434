#pragma once
// Baseline: the image-based filter the paper compares step 2 with (its
// ref. [8], Wang): the points are rasterised into a grey-level image, a
// median filter smooths it over a local window, cells whose smoothed grey
// level reaches a threshold are kept and the rest dropped. Wang then puts the
// cell centre in place of the point; with per-beam labels a point is removed
// when its cell is dropped, and kept points keep their measured position.
//
// The grey level of a cell is the number of returns it received over the
// last `frames` scans (the current one included), in the world frame, capped
// at 255. A one-cell-thick wall fills 3 of the 9 cells of a 3x3 window, so a
// median over all cells erases walls; `ignore_empty` takes the median over
// the occupied cells of the window only. The sweep chooses (docs/baselines.md).
#include <cstdint>
#include <deque>
#include <unordered_map>
#include <vector>

#include <Eigen/Core>

#include "scanfilter/scan_filter.hpp"
#include "scanfilter/scan_geometry.hpp"

namespace scanfilter::baselines {

struct MedianImageParams {
  double cell_size = 0.05;   // m, image pixel
  int frames = 10;           // scans rasterised, the current one included
  int window = 3;            // odd side of the median window (cells)
  bool ignore_empty = true;  // median over the window's occupied cells only
  int threshold = 3;         // smallest smoothed grey level kept
};

class MedianImageFilter final : public ScanFilter {
 public:
  explicit MedianImageFilter(const MedianImageParams& params);
  void apply(const Scan& scan, const SensorInfo& sensor, std::span<std::uint8_t> labels) override;

  // Smoothed grey level of the cell holding world point p (for tests).
  int smoothedGrey(const Eigen::Vector2d& p);

 private:
  using CellKey = std::uint64_t;
  std::int32_t cellIndex(double coordinate) const;  // along one axis
  CellKey cellOf(const Eigen::Vector2d& p) const;
  static CellKey key(std::int32_t x, std::int32_t y);
  void addFrame(const std::vector<CellKey>& cells, int delta);
  int greyAt(std::int32_t x, std::int32_t y) const;

  MedianImageParams params_;
  BeamDirectionTable directions_;
  std::vector<Eigen::Vector2d> points_;
  std::deque<std::vector<CellKey>> frames_;
  std::unordered_map<CellKey, int> hits_;
  std::vector<int> window_values_;
};

}  // namespace scanfilter::baselines
