#pragma once
// Baseline: ROS laser_filters LaserScanSpeckleFilter.
// Source: ros-perception/laser_filters, speckle_filter.h; defaults from its
// example configuration (distance mode, max_range 2 m, difference 0.1 m,
// window 2).
#include "scanfilter/scan_filter.hpp"

namespace scanfilter::baselines {

enum class SpeckleMode {
  kDistance,   // laser_filters filter_type 0: consecutive ranges differ by at most max_range_difference
  kEuclidean,  // filter_type 1: at least `window` neighbours within max_range_difference metres
};

struct SpeckleParams {
  SpeckleMode mode = SpeckleMode::kDistance;
  double max_range = 2.0;             // m; returns beyond it are never removed
  double max_range_difference = 0.1;  // m
  int filter_window = 2;              // beams
};

// Distance mode: the window of `filter_window` beams starting at i is valid
// when every range in it is within max_range_difference of r_i. Euclidean
// mode: the window at i is valid when at least `filter_window` beams within
// ±filter_window lie within max_range_difference (chord length) of point i.
// Either way a valid window at i keeps beams i .. i + filter_window - 1; a
// return kept by no window (and not beyond max_range) is removed.
class SpeckleFilter final : public ScanFilter {
 public:
  explicit SpeckleFilter(const SpeckleParams& params);
  void apply(const Scan& scan, const SensorInfo& sensor, std::span<std::uint8_t> labels) override;

 private:
  bool distanceWindowValid(const Scan& scan, std::size_t i) const;
  bool euclideanWindowValid(const Scan& scan, std::size_t i) const;

  SpeckleParams params_;
  std::vector<std::uint8_t> kept_;
};

}  // namespace scanfilter::baselines
