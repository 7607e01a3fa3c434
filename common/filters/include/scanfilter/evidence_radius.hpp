#pragma once
#include <optional>
#include <vector>

#include <Eigen/Core>

#include "scanfilter/range_noise_estimate.hpp"
#include "scanfilter/range_noise_sampling.hpp"
#include "scanfilter/scan.hpp"
#include "scanfilter/scan_geometry.hpp"
#include "scanfilter/sensor_info.hpp"

namespace scanfilter {

// How far around a point step 2 counts returns from elsewhere
// (PenetrationFilterParams: rescue_radius, evidence_noise_*).
// The defaults are PenetrationFilterParams'.
struct EvidenceRadiusParams {
  double min_radius = 0.0;      // m, rescue_radius: the radius wherever the noise is smaller
  double noise_sigmas = 0.0;    // the radius is at least this many σ(range); 0: min_radius everywhere
  double max_radius = 0.0;      // m, and at most this (at least min_radius)
  RangeNoiseSampling sampling;  // how the noise is measured
  // Measure the noise even where noise_sigmas is 0: another check reads
  // noise() (the sparse-surface search, docs/beyond-the-paper.md, 42).
  bool measure_noise = false;
};

// Beyond the paper (docs/beyond-the-paper.md, 33): how far around a
// point step 2 counts the returns that vouch for a surface there (the
// rescue, the free-space veto, the thin-object check's spare). Returns of one
// surface scatter along their beams by the range noise: within rescue_radius
// for the sensor the defaults were chosen with, farther for a noisier one,
// whose thin legs then found too little evidence and were deleted. So the
// radius is `noise_sigmas` σ(range) where that is more than min_radius, up
// to max_radius (beyond it the count would reach across the depth edges the
// checks look at, and cost more cells than it is worth), with σ(d) = base +
// quadratic·d² measured on the scans as step 1 measures it
// (range_noise_estimate.hpp), the measured model alone: step 1's configured
// model is only a floor for its own tolerances, and as a floor here its d²
// term would widen the radius for every sensor (0.4 m of σ at 20 m on a
// time-of-flight scanner whose noise is 1-2 cm). Until the estimate has two
// range bands, and for a sensor without a finite positive range_max (no
// bands to measure in), min_radius.
class EvidenceRadius {
 public:
  explicit EvidenceRadius(const EvidenceRadiusParams& params);

  // Measures the range noise on one scan (a no-op with noise_sigmas 0).
  void measure(const Scan& scan, const SensorInfo& sensor);
  // The radius at `range` m from the sensor.
  double at(double range) const;
  // The measured model (zero terms until measured).
  RangeNoiseModel noise() const { return noise_; }

 private:
  EvidenceRadiusParams params_;
  // Sized for one sensor's range_max; built again when a scan's differs.
  std::optional<RangeNoiseEstimate> estimate_;
  double sized_for_ = 0.0;
  RangeNoiseModel noise_;
  BeamDirectionTable directions_;
  std::vector<Eigen::Vector2d> points_;  // sensor frame, reused between scans
};

}  // namespace scanfilter
