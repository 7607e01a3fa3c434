#include "scanfilter/baselines/radius_outlier_filter.hpp"

namespace scanfilter::baselines {

RadiusOutlierFilter::RadiusOutlierFilter(const RadiusOutlierParams& params) : params_(params) {}

bool RadiusOutlierFilter::hasEnoughNeighbours(std::size_t i) const {
  // Every point of the scan is a candidate (no angular shortcut): a close
  // point's neighbours can be many beams away. Stops at the count needed.
  const double radius_sq = params_.radius * params_.radius;
  int found = 0;
  for (std::size_t j = 0; j < points_.size() && found < params_.min_neighbors; ++j) {
    if (j != i && (points_[j] - points_[i]).squaredNorm() <= radius_sq) ++found;  // NaN: never
  }
  return found >= params_.min_neighbors;
}

void RadiusOutlierFilter::apply(const Scan& scan, const SensorInfo& sensor, std::span<std::uint8_t> labels) {
  labelReturns(scan, labels);
  sensorFramePoints(scan, sensor, directions_, points_);
  for (std::size_t i = 0; i < scan.size(); ++i)
    if (scan.hasReturn(i) && !hasEnoughNeighbours(i)) labels[i] = static_cast<std::uint8_t>(PointCode::kJump);
}

}  // namespace scanfilter::baselines
