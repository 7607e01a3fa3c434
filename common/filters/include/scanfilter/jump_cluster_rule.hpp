#pragma once
#include <cstdint>
#include <span>
#include <vector>

#include "scanfilter/jump_filter_params.hpp"

namespace scanfilter {

// What eq. 6-7 (with keep_unresolved_returns and keep_foreground_clusters)
// make of one cluster.
enum class ClusterVerdict : std::uint8_t {
  kLongEnough,  // spans eq. 7's minimum tangential length, or is a lone return eq. 7 cannot resolve
  kForeground,  // too short, but stands in front of both sides (keep_foreground_clusters)
  kTooShort,    // removed as jump points
};

// The parts of step 1 that both implementations must compute identically:
// the neighbour radius of equation (5) and the span test of (6)-(7).
class JumpClusterRule {
 public:
  explicit JumpClusterRule(const JumpFilterParams& params);
  void useNoiseModel(const RangeNoiseModel& model) { setNoiseModel(params_, model); }

  // d_th of equation (5) for a point at `range` (proportional to the range,
  // so the ratio is computed once), widened by `radius_noise_sigmas` · σ(range)
  // beyond the paper: two returns of one surface also differ by range noise,
  // which at fine angular steps exceeds eq. 5's radius and breaks a wall
  // into clusters eq. 7 deletes.
  double neighbourRadius(double range) const { return radius_per_metre_ * range + noiseWidening(range); }
  // The largest radius per metre of range over [range_lo, range_hi]: what
  // bounds the angular window a neighbour can lie in.
  double maxRadiusPerMetre(double range_lo, double range_hi) const;

  // Equations (6) and (7) on one cluster. `members` are beam indices in
  // increasing order; `full_turn` says whether the span can wrap across the
  // seam (ranges.size() is the beam count); the seed is the first index.
  ClusterVerdict judge(std::span<const std::uint32_t> members, std::span<const double> ranges, bool full_turn,
                       double angle_increment) const;

  // θ_th of equation (7) for a cluster of mean range d_ave (and seed range d_seed).
  double spanThreshold(double d_ave, double d_seed) const;

  // Span of a cluster in beams (eq. 6), the smallest arc on a full turn.
  static std::uint32_t spanInBeams(std::span<const std::uint32_t> members, std::size_t beam_count,
                                   bool full_turn);

 private:
  // keep_foreground_clusters: the beams just outside the cluster on both
  // sides return farther than its farthest member by more than the
  // off-surface tolerance, or return nothing.
  bool standsInFront(std::span<const std::uint32_t> members, std::span<const double> ranges, bool full_turn) const;

  double noiseWidening(double range) const {
    return params_.radius_noise_sigmas * rangeNoiseSigma(params_, range);
  }

  JumpFilterParams params_;
  double radius_per_metre_;
};

}  // namespace scanfilter
