#pragma once
// Baseline: the OPTICS density-clustering filter the paper compares with
// (its ref. [18], Zhu et al.: OPTICS with an elliptical density search
// region). OPTICS as Ankerst et al. (SIGMOD 1999) define it: core distance,
// reachability distance, the cluster ordering grown from a priority queue,
// and clusters extracted from the ordering at eps_cluster <= eps
// ("ExtractDBSCAN-Clustering"). Points in no cluster, or in a cluster
// smaller than min_cluster_size, are removed.
//
// The ellipse: its axes follow the mean beam direction of the two points.
// Along that direction (range) distances are divided by axis_ratio, so with
// axis_ratio < 1 the region is long along the scan line and short in depth,
// where a surface's points lie and a mixed point does not. The metric is
// symmetric, as OPTICS needs. Zhu et al. do not publish the orientation for
// 2D scans; this is our reading, documented in docs/baselines.md.
#include <vector>

#include <Eigen/Core>

#include "scanfilter/scan_filter.hpp"
#include "scanfilter/scan_geometry.hpp"

namespace scanfilter::baselines {

struct OpticsParams {
  double eps = 0.20;          // m, generating distance (tangential semi-axis of the search ellipse)
  double axis_ratio = 0.5;    // radial / tangential semi-axis, in (0, 1]
  int min_pts = 4;            // points (itself included) within a core distance
  double eps_cluster = 0.15;  // m, extraction threshold on the reachability plot, <= eps
  int min_cluster_size = 4;   // smaller clusters are removed as noise
};

class OpticsFilter final : public ScanFilter {
 public:
  explicit OpticsFilter(const OpticsParams& params);
  void apply(const Scan& scan, const SensorInfo& sensor, std::span<std::uint8_t> labels) override;

  // The last scan's cluster ordering and reachability (for tests and plots):
  // reachability is +inf where undefined.
  const std::vector<std::uint32_t>& ordering() const { return ordering_; }
  const std::vector<double>& reachability() const { return reachability_; }

 private:
  struct Neighbour {
    std::uint32_t index;
    double distance;
  };
  double ellipticalDistance(std::uint32_t a, std::uint32_t b) const;
  void findNeighbours(std::uint32_t p, std::vector<Neighbour>& out) const;
  double coreDistance(std::vector<Neighbour>& neighbours) const;
  void expandFrom(std::uint32_t start);
  void extractClusters(std::span<std::uint8_t> labels);

  OpticsParams params_;
  BeamDirectionTable directions_;
  std::vector<Eigen::Vector2d> points_;
  std::vector<double> ranges_;
  double angle_increment_ = 0.0;
  bool full_turn_ = false;
  std::vector<std::uint8_t> processed_;
  std::vector<double> reachability_;
  std::vector<double> core_distance_;
  std::vector<std::uint32_t> ordering_;
  std::vector<Neighbour> neighbours_;
};

}  // namespace scanfilter::baselines
