#pragma once
#include <array>
#include <cstddef>
#include <optional>
#include <span>
#include <vector>

#include <Eigen/Core>

#include "scanfilter/jump_filter_params.hpp"

namespace scanfilter {

// Beyond the paper: the sensor's range noise, measured on its own scans.
//
// Step 1's tolerances (the widened neighbour radius, the off-surface and
// straight-run tests) are multiples of σ(range). The configured σ fits one
// sensor: a triangulation unit noisier than the default (3 mm + 1 mm/m²)
// breaks its far walls into clusters eq. 7 deletes, and a time-of-flight
// scanner's 1-2 cm at every range is above the default's near range.
//
// Where three consecutive returns lie on one surface seen at moderate
// incidence, the middle one's range minus the range at which its beam meets
// the line through the outer two is range noise: σ·sqrt(1.5) for equal σ
// (its own noise and half of each neighbour's). Corners, edges and mixed
// returns give larger residuals too, so each 1 m range band keeps a decaying
// histogram of the residuals' magnitudes, and σ of the band is the median
// (robust while at most half the triples are not on one surface); a band
// whose median lies beyond kLargest (ghosts beyond the walls) does not count.
// σ = base + quadratic·d² is fitted to the bands with enough samples
// (weighted least squares, both terms >= 0, a second pass without the bands
// far off the first).
//
// Each fitted term replaces the configured one (the floor) only when
// larger: the estimate widens step 1's tolerances for a noisier sensor and
// never narrows them. Narrowing was measured and not kept
// (docs/beyond-the-paper.md, 18): on the real SICK logs the default's wide
// far tolerance also absorbs what is not noise (clutter that is not a
// straight line at 1°), and narrowing it removed more returns seen again
// from elsewhere. With fewer
// than two bands the configured model stays. Step 2 measures with a zero
// floor: the measured model alone (evidence_radius.hpp).
class RangeNoiseEstimate {
 public:
  // Step 1's: the configured model as the floor, bands up to d_max.
  explicit RangeNoiseEstimate(const JumpFilterParams& params);
  // Each fitted term replaces the floor's only when larger (a zero floor:
  // the measured model alone); 1 m bands from 0 to max_range.
  RangeNoiseEstimate(const RangeNoiseModel& floor, const RangeNoiseSampling& sampling, double max_range);

  // Adds one scan: sensor-frame points (NaN without a return) and ranges; on
  // a full turn the neighbours wrap across the seam. Older scans' weight
  // decays by 1 - 1/sampling.window_scans a scan.
  void add(std::span<const Eigen::Vector2d> points, std::span<const double> ranges, bool full_turn);

  // Per term the larger of the fitted one and the floor's (step 1: the
  // configured model); the floor until two bands hold enough samples.
  RangeNoiseModel model() const { return model_; }

  // The range noise of one band (its median residual / sqrt(1.5) · 1.4826), or 0 with too few samples.
  double bandSigma(std::size_t band) const;

  static constexpr double kBandWidth = 1.0;  // m
  // |residual| histogram: bins from kSmallest upwards, kBinsPerOctave a factor of 2.
  static constexpr double kSmallest = 2.5e-4;  // m: below a millimetre range resolution's rounding
  static constexpr int kBinsPerOctave = 4;
  static constexpr int kBins = 10 * kBinsPerOctave + 1;  // up to 0.256 m, then one overflow bin
  static constexpr double kLargest = kSmallest * 1024.0;
  // The fit's second pass leaves out bands whose σ is this far (as a factor) off the first.
  static constexpr double kOutlierFactor = 2.0;

 private:
  // The residual of point i against the line through a and b, or nothing if
  // the three do not look like one surface at moderate incidence.
  static bool residual(const Eigen::Vector2d& a, const Eigen::Vector2d& p, const Eigen::Vector2d& b, double range,
                       double& out);
  static int binOf(double magnitude);
  // σ(d) fitted to the bands with enough samples, leaving out those far off
  // `previous` when given; nothing with fewer than two bands.
  std::optional<RangeNoiseModel> fit(const RangeNoiseModel* previous) const;
  void refit();

  RangeNoiseModel configured_;
  RangeNoiseModel model_;
  double keep_;         // weight kept per scan
  double min_samples_;  // weight a band needs
  using Histogram = std::array<double, kBins>;
  std::vector<Histogram> bands_;
  std::vector<double> band_weight_;
};

}  // namespace scanfilter
