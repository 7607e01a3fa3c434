#pragma once
// Baseline: radius outlier removal, as PCL's RadiusOutlierRemoval and
// laser_filters' RadiusOutlierFilter offer it: a return with fewer than
// `min_neighbors` other returns within `radius` metres is removed.
#include <vector>

#include <Eigen/Core>

#include "scanfilter/scan_filter.hpp"
#include "scanfilter/scan_geometry.hpp"

namespace scanfilter::baselines {

struct RadiusOutlierParams {
  double radius = 0.10;  // m, PCL's setRadiusSearch
  int min_neighbors = 2;  // PCL's setMinNeighborsInRadius (the point itself not counted)
};

class RadiusOutlierFilter final : public ScanFilter {
 public:
  explicit RadiusOutlierFilter(const RadiusOutlierParams& params);
  void apply(const Scan& scan, const SensorInfo& sensor, std::span<std::uint8_t> labels) override;

 private:
  bool hasEnoughNeighbours(std::size_t i) const;

  RadiusOutlierParams params_;
  BeamDirectionTable directions_;
  std::vector<Eigen::Vector2d> points_;
};

}  // namespace scanfilter::baselines
