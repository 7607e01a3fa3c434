#include "scanfilter/baselines/optics_filter.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <queue>

namespace scanfilter::baselines {

namespace {
constexpr double kUndefined = std::numeric_limits<double>::infinity();
}

OpticsFilter::OpticsFilter(const OpticsParams& params) : params_(params) {}

double OpticsFilter::ellipticalDistance(std::uint32_t a, std::uint32_t b) const {
  const Eigen::Vector2d d = points_[b] - points_[a];
  const Eigen::Vector2d radial = (points_[a] / ranges_[a] + points_[b] / ranges_[b]).normalized();
  const double along_range = d.dot(radial);
  const double across = d.x() * -radial.y() + d.y() * radial.x();
  const double scaled = along_range / params_.axis_ratio;
  return std::sqrt(across * across + scaled * scaled);
}

void OpticsFilter::findNeighbours(std::uint32_t p, std::vector<Neighbour>& out) const {
  out.clear();
  const auto n = static_cast<std::int64_t>(points_.size());
  // With axis_ratio <= 1 the elliptical distance is at least the Euclidean
  // one, so a neighbour lies within asin(eps / r) of p's beam.
  std::int64_t half = n;
  if (params_.eps < ranges_[p] && angle_increment_ != 0.0)
    half = static_cast<std::int64_t>(std::ceil(std::asin(params_.eps / ranges_[p]) / std::abs(angle_increment_))) + 1;
  std::int64_t from = p - half, to = p + half;
  if (to - from + 1 >= n) {
    from = 0;
    to = n - 1;
  } else if (!full_turn_) {
    from = std::max<std::int64_t>(from, 0);
    to = std::min<std::int64_t>(to, n - 1);
  }
  for (std::int64_t k = from; k <= to; ++k) {
    const auto q = static_cast<std::uint32_t>((k % n + n) % n);
    if (ranges_[q] != ranges_[q]) continue;  // no return
    const double d = q == p ? 0.0 : ellipticalDistance(p, q);
    if (d <= params_.eps) out.push_back({q, d});
  }
}

double OpticsFilter::coreDistance(std::vector<Neighbour>& neighbours) const {
  const auto k = static_cast<std::size_t>(params_.min_pts);
  if (k == 0 || neighbours.size() < k) return kUndefined;
  auto kth = neighbours.begin() + static_cast<std::ptrdiff_t>(k - 1);
  std::nth_element(neighbours.begin(), kth, neighbours.end(),
                   [](const Neighbour& a, const Neighbour& b) { return a.distance < b.distance; });
  return kth->distance;
}

void OpticsFilter::expandFrom(std::uint32_t start) {
  using Seed = std::pair<double, std::uint32_t>;  // (reachability, index): ties broken by index
  std::priority_queue<Seed, std::vector<Seed>, std::greater<>> seeds;
  seeds.push({kUndefined, start});
  while (!seeds.empty()) {
    const auto [reach, p] = seeds.top();
    seeds.pop();
    if (processed_[p] || reach > reachability_[p]) continue;  // stale queue entry
    processed_[p] = 1;
    ordering_.push_back(p);
    findNeighbours(p, neighbours_);
    core_distance_[p] = coreDistance(neighbours_);
    if (core_distance_[p] == kUndefined) continue;
    for (const auto& [q, distance] : neighbours_) {
      if (processed_[q]) continue;
      const double new_reach = std::max(core_distance_[p], distance);
      if (new_reach < reachability_[q]) {
        reachability_[q] = new_reach;
        seeds.push({new_reach, q});
      }
    }
  }
}

void OpticsFilter::extractClusters(std::span<std::uint8_t> labels) {
  // Ankerst et al., ExtractDBSCAN-Clustering: walk the ordering; a point not
  // reachable within eps_cluster starts a new cluster if it is a core point
  // at eps_cluster, else it is noise; any other point joins the current one.
  constexpr std::uint32_t kNoise = std::numeric_limits<std::uint32_t>::max();
  std::vector<std::uint32_t> cluster_of(ordering_.size());
  std::vector<std::uint32_t> cluster_size;
  std::uint32_t current = kNoise;
  for (std::size_t k = 0; k < ordering_.size(); ++k) {
    const std::uint32_t p = ordering_[k];
    if (reachability_[p] > params_.eps_cluster) {
      if (core_distance_[p] <= params_.eps_cluster) {
        current = static_cast<std::uint32_t>(cluster_size.size());
        cluster_size.push_back(0);
        cluster_of[k] = current;
      } else {
        cluster_of[k] = kNoise;
      }
    } else {
      cluster_of[k] = current;
    }
    if (cluster_of[k] != kNoise) ++cluster_size[cluster_of[k]];
  }
  for (std::size_t k = 0; k < ordering_.size(); ++k) {
    const bool removed = cluster_of[k] == kNoise ||
                         static_cast<int>(cluster_size[cluster_of[k]]) < params_.min_cluster_size;
    if (removed) labels[ordering_[k]] = static_cast<std::uint8_t>(PointCode::kJump);
  }
}

void OpticsFilter::apply(const Scan& scan, const SensorInfo& sensor, std::span<std::uint8_t> labels) {
  labelReturns(scan, labels);
  sensorFramePoints(scan, sensor, directions_, points_);
  const auto n = static_cast<std::uint32_t>(scan.size());
  ranges_.assign(scan.ranges.begin(), scan.ranges.end());
  angle_increment_ = scan.angle_increment;
  full_turn_ = isFullTurn(scan);
  processed_.assign(n, 0);
  reachability_.assign(n, kUndefined);
  core_distance_.assign(n, kUndefined);
  ordering_.clear();
  for (std::uint32_t p = 0; p < n; ++p)
    if (scan.hasReturn(p) && !processed_[p]) expandFrom(p);
  extractClusters(labels);
}

}  // namespace scanfilter::baselines
