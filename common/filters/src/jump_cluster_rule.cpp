#include "scanfilter/jump_cluster_rule.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "scanfilter/scan_geometry.hpp"

namespace scanfilter {

JumpClusterRule::JumpClusterRule(const JumpFilterParams& params)
    : params_(params),
      radius_per_metre_(2.0 * std::sin(degreesToRadians(params.angular_accuracy_deg)) * params.alpha /
                        std::cos(degreesToRadians(params.theta_k_deg))) {}

double JumpClusterRule::maxRadiusPerMetre(double range_lo, double range_hi) const {
  // σ(d)/d = base/d + quadratic·d is convex in d: its largest value over an
  // interval is at one of the ends.
  const auto per_metre = [&](double d) { return radius_per_metre_ + noiseWidening(d) / d; };
  return range_lo > 0.0 ? std::max(per_metre(range_lo), per_metre(range_hi)) : std::numeric_limits<double>::infinity();
}

double JumpClusterRule::spanThreshold(double d_ave, double d_seed) const {
  const double d = params_.span_range == SpanRange::kClusterMean ? d_ave : d_seed;
  const double d_span = params_.d_max - params_.d_min;
  const double t = d_span > 0.0 ? std::clamp((d - params_.d_min) / d_span, 0.0, 1.0) : 0.0;
  const double l = params_.l_min + (params_.l_max - params_.l_min) * t;
  return 2.0 * std::atan(l / (2.0 * d_ave));
}

std::uint32_t JumpClusterRule::spanInBeams(std::span<const std::uint32_t> members,
                                          std::size_t beam_count, bool full_turn) {
  const std::uint32_t linear = members.back() - members.front();
  if (!full_turn || members.size() < 2) return linear;
  // Smallest arc covering the cluster: the whole turn less its largest gap.
  std::uint32_t largest_gap =
      static_cast<std::uint32_t>(beam_count) - members.back() + members.front();
  for (std::size_t k = 1; k < members.size(); ++k)
    largest_gap = std::max(largest_gap, members[k] - members[k - 1]);
  return static_cast<std::uint32_t>(beam_count) - largest_gap;
}

ClusterVerdict JumpClusterRule::judge(std::span<const std::uint32_t> members, std::span<const double> ranges,
                                      bool full_turn, double angle_increment) const {
  double sum = 0.0;
  for (std::uint32_t m : members) sum += ranges[m];  // index order: same sum in both filters
  const double d_ave = sum / static_cast<double>(members.size());
  const double span =
      static_cast<double>(spanInBeams(members, ranges.size(), full_turn)) * std::abs(angle_increment);
  if (span >= spanThreshold(d_ave, ranges[members.front()])) return ClusterVerdict::kLongEnough;
  if (params_.keep_unresolved_returns && members.size() == 1 && d_ave * std::abs(angle_increment) >= params_.l_max)
    return ClusterVerdict::kLongEnough;
  if (params_.keep_foreground_clusters && standsInFront(members, ranges, full_turn)) return ClusterVerdict::kForeground;
  return ClusterVerdict::kTooShort;
}

bool JumpClusterRule::standsInFront(std::span<const std::uint32_t> members, std::span<const double> ranges,
                                    bool full_turn) const {
  const auto n = static_cast<std::int64_t>(ranges.size());
  double back = 0.0;  // the farthest member
  for (std::uint32_t m : members) back = std::max(back, ranges[m]);
  const double tolerance = offSurfaceTolerance(params_, back);
  // On a full turn a cluster can wrap across the seam: its outside beams are
  // then next to its largest inside gap, not its first and last index.
  std::int64_t before = static_cast<std::int64_t>(members.front()) - 1, after = members.back() + 1;
  if (full_turn && members.size() > 1) {
    std::uint32_t largest_gap = static_cast<std::uint32_t>(n) - members.back() + members.front();
    for (std::size_t k = 1; k < members.size(); ++k)
      if (members[k] - members[k - 1] > largest_gap) {
        largest_gap = members[k] - members[k - 1];
        before = static_cast<std::int64_t>(members[k]) - 1;
        after = members[k - 1] + 1;
      }
  }
  const auto fartherThanTheCluster = [&](std::int64_t beam) {
    // Past the end of a partial scan the field of view ends, not the
    // object: no evidence that anything stands behind it.
    if ((beam < 0 || beam >= n) && !full_turn) return false;
    const double r = ranges[static_cast<std::size_t>((beam % n + n) % n)];
    return r != r || r > back + tolerance;  // NaN: no return, nothing within range behind it
  };
  return fartherThanTheCluster(before) && fartherThanTheCluster(after);
}

}  // namespace scanfilter
