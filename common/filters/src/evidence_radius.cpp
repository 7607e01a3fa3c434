#include "scanfilter/evidence_radius.hpp"

#include <algorithm>
#include <cmath>

#include "scanfilter/plausible_bounds.hpp"

namespace scanfilter {

EvidenceRadius::EvidenceRadius(const EvidenceRadiusParams& params) : params_(params) {}

void EvidenceRadius::measure(const Scan& scan, const SensorInfo& sensor) {
  if (!(params_.noise_sigmas > 0.0) && !params_.measure_noise) return;
  // The estimate's bands run from the sensor to its range_max: without a
  // finite positive one there is nothing to size them by (NaN fails both).
  if (!(std::isfinite(sensor.range_max) && sensor.range_max > 0.0)) return;
  const double max_range = std::min(sensor.range_max, kMaxPlausibleRange);
  if (!estimate_ || max_range != sized_for_) {
    estimate_.emplace(RangeNoiseModel{}, params_.sampling, max_range);
    sized_for_ = max_range;
  }
  sensorFramePoints(scan, sensor, directions_, points_);
  estimate_->add(points_, scan.ranges, isFullTurn(scan));
  noise_ = estimate_->model();
}

double EvidenceRadius::at(double range) const {
  const double noise_reach = params_.noise_sigmas * noise_.sigmaAt(range);
  return std::clamp(noise_reach, params_.min_radius, std::max(params_.min_radius, params_.max_radius));
}

}  // namespace scanfilter
