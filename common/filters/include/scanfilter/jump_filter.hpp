#pragma once
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include <Eigen/Core>

#include "scanfilter/implementation.hpp"
#include "scanfilter/jump_cluster_rule.hpp"
#include "scanfilter/off_surface_check.hpp"
#include "scanfilter/range_noise_estimate.hpp"
#include "scanfilter/straight_run_join.hpp"
#include "scanfilter/scan.hpp"
#include "scanfilter/scan_geometry.hpp"
#include "scanfilter/sensor_info.hpp"

namespace scanfilter {

// Step 1: clustering on radial distance and tangential span (paper eq. 5-7).
// Writes one code per beam: no return, jump, or valid.
class JumpFilter {
 public:
  explicit JumpFilter(const JumpFilterParams& params)
      : params_(params), rule_(params), off_surface_(params), runs_(params), noise_(params) {}
  virtual ~JumpFilter() = default;

  void apply(const Scan& scan, const SensorInfo& sensor, std::span<std::uint8_t> labels);

  // The range-noise model the last scan was judged with (noise_estimate: measured).
  RangeNoiseModel noiseModel() const { return noiseModelOf(params_); }

 protected:
  // Called once per scan after free_ is set, before the first cluster grows.
  virtual void prepare(const Scan& /*scan*/) {}
  // Grows the cluster of `seed` into cluster_ (any order), marking members not free.
  virtual void growCluster(std::uint32_t seed, const Scan& scan) = 0;
  // True when point j lies within the neighbour radius of member m (eq. 5).
  bool isNeighbour(std::uint32_t m, std::uint32_t j, double radius_sq) const {
    return (points_[j] - points_[m]).squaredNorm() < radius_sq;
  }

  JumpFilterParams params_;  // noise_sigma_* follow the estimate
  JumpClusterRule rule_;
  OffSurfaceCheck off_surface_;
  StraightRunJoin runs_;
  RangeNoiseEstimate noise_;
  BeamDirectionTable directions_;
  std::vector<Eigen::Vector2d> points_;  // sensor frame
  std::vector<std::uint8_t> free_;       // 1 while a point belongs to no cluster
  std::vector<std::uint32_t> cluster_;
  bool full_turn_ = false;

 private:
  // Adds the scan to the noise estimate and judges with the model it gives.
  void followNoiseEstimate(const Scan& scan);
  // Eq. 6-7 on every cluster, after the straight runs joined those they pass through.
  void judgeClusters(const Scan& scan, std::uint32_t cluster_count, std::span<std::uint8_t> labels);

  std::vector<std::uint32_t> cluster_of_;  // per beam; StraightRunJoin::kNoCluster without a return
  std::vector<std::uint32_t> group_start_;  // members of each joined cluster, grouped, in index order
  std::vector<std::uint32_t> group_fill_;   // next free slot of each group while grouping
  std::vector<std::uint32_t> grouped_;
  std::vector<std::uint8_t> foreground_;    // per beam: 1 in a cluster kept as foreground (the off-surface check spares it)
};

// The paper's steps as written: every member is compared with every free point.
class ReferenceJumpFilter final : public JumpFilter {
 public:
  using JumpFilter::JumpFilter;

 private:
  void growCluster(std::uint32_t seed, const Scan& scan) override;
};

// The same clusters in about O(N): a point within d_th = k·d of a point at
// range d lies within asin(k) of its beam, so only an angular window is
// searched, and a skip list jumps over points already clustered.
class FastJumpFilter final : public JumpFilter {
 public:
  using JumpFilter::JumpFilter;

 private:
  void prepare(const Scan& scan) override;
  void growCluster(std::uint32_t seed, const Scan& scan) override;
  void visitFreeIn(std::uint32_t from, std::uint32_t to, std::uint32_t member, double radius_sq);
  std::uint32_t nextFree(std::uint32_t i);

  void claim(std::uint32_t i);

  std::vector<std::uint32_t> next_free_;  // skip pointers over clustered points; [N] = N
  std::uint32_t half_window_ = 0;         // beams either side that can hold a neighbour
};

std::unique_ptr<JumpFilter> makeJumpFilter(const JumpFilterParams& params, Implementation impl);

}  // namespace scanfilter
