#pragma once
// Baseline: ROS laser_filters ScanShadowsFilter (veiling points).
// Source: ros-perception/laser_filters, scan_shadows_filter.h; parameters and
// defaults as in its example configuration (min 10°, max 170°, window 1,
// neighbors 20). With the filter's own default neighbors = 0 it removes
// nothing, which is why every published configuration sets it.
#include "scanfilter/scan_filter.hpp"

namespace scanfilter::baselines {

struct ScanShadowsParams {
  double min_angle_deg = 10.0;   // a return seen at less than this from its neighbour's line is a shadow edge
  double max_angle_deg = 170.0;  // ... or at more than this
  int window = 1;                // neighbours compared on each side
  int neighbors = 20;            // beams either side of an edge removed when farther than the edge point
  bool remove_shadow_start_point = false;  // newer laser_filters: also remove the edge point itself
};

// For each beam i and each j within `window`, the angle at point i between
// the sensor-to-i line and the i-to-j line is
//   atan2(r_j sin(Δφ), r_i - r_j cos(Δφ)),  Δφ = (j - i) · angle_increment.
// Outside [min, max] the two points lie almost on one line of sight: beams
// within `neighbors` of i that are farther than i are veiling points.
class ScanShadowsFilter final : public ScanFilter {
 public:
  explicit ScanShadowsFilter(const ScanShadowsParams& params);
  void apply(const Scan& scan, const SensorInfo& sensor, std::span<std::uint8_t> labels) override;

 private:
  bool isShadowEdge(const Scan& scan, std::size_t i, std::size_t j) const;

  ScanShadowsParams params_;
};

}  // namespace scanfilter::baselines
