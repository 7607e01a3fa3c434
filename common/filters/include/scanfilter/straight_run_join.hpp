#pragma once
#include <cstdint>
#include <span>
#include <vector>

#include <Eigen/Core>

#include "scanfilter/jump_filter_params.hpp"
#include "scanfilter/wrapped_returns.hpp"

namespace scanfilter {

// Beyond the paper, between the clustering of eq. 5 and the span test of
// eq. 6-7: clusters that one straight run of returns passes through are one
// surface seen at grazing incidence, and are joined (jump_filter_params.hpp,
// straight_runs). Shared by both implementations of step 1, so they still
// agree label for label.
class StraightRunJoin {
 public:
  explicit StraightRunJoin(const JumpFilterParams& params);
  void useNoiseModel(const RangeNoiseModel& model) { setNoiseModel(params_, model); }

  // `cluster_of[i]`: the cluster of beam i (kNoCluster without a return),
  // clusters numbered 0..cluster_count-1. Returns each cluster's
  // representative after the joins (a cluster not joined represents itself).
  const std::vector<std::uint32_t>& join(std::span<const Eigen::Vector2d> points, std::span<const double> ranges,
                                         bool full_turn, double angle_increment,
                                         std::span<const std::uint32_t> cluster_of, std::uint32_t cluster_count);

  static constexpr std::uint32_t kNoCluster = ~std::uint32_t{0};

 private:
  // True when beam i (wrapped) lies on the line through its two neighbours,
  // between them, and each is at most a grazing surface's spacing away: the
  // inside of a straight run.
  bool insideRun(std::int64_t i) const;
  std::uint32_t find(std::uint32_t c);
  void unite(std::uint32_t a, std::uint32_t b);
  void joinRun(std::int64_t first, std::int64_t last, std::span<const std::uint32_t> cluster_of);

  JumpFilterParams params_;
  double gap_per_metre_ = 0.0;  // largest spacing of a run's returns, per metre of range
  double min_sin_to_beam_ = 0.0;  // sine of the smallest angle between a run and the beam
  WrappedReturns returns_;
  std::vector<std::uint32_t> parent_;
};

}  // namespace scanfilter
