#include "scanfilter/evidence_radius.hpp"

#include <algorithm>

#include "scanfilter/plausible_bounds.hpp"

namespace scanfilter {

EvidenceRadius::EvidenceRadius(double floor, double noise_sigmas, const RangeNoiseSampling& sampling)
    : floor_(floor), noise_sigmas_(noise_sigmas), sampling_(sampling) {}

void EvidenceRadius::measure(const Scan& scan, const SensorInfo& sensor) {
  if (!(noise_sigmas_ > 0.0)) return;
  // A sensor without a finite range still has its returns within plausible bounds.
  const double max_range = std::min(sensor.range_max, kMaxPlausibleRange);
  if (!estimate_ || max_range != sized_for_) {
    estimate_.emplace(RangeNoiseModel{}, sampling_, max_range);
    sized_for_ = max_range;
  }
  sensorFramePoints(scan, sensor, directions_, points_);
  estimate_->add(points_, scan.ranges, isFullTurn(scan));
  noise_ = estimate_->model();
}

double EvidenceRadius::at(double range) const {
  return std::max(floor_, noise_sigmas_ * (noise_.base + noise_.quadratic * range * range));
}

}  // namespace scanfilter
