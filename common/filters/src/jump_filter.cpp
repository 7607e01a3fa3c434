#include "scanfilter/jump_filter.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "scanfilter/point_code.hpp"
#include "scanfilter/scan_geometry.hpp"

namespace scanfilter {

void JumpFilter::apply(const Scan& scan, const SensorInfo& sensor, std::span<std::uint8_t> labels) {
  const std::size_t n = scan.size();
  sensorFramePoints(scan, sensor, directions_, points_);
  full_turn_ = isFullTurn(scan);
  if (params_.noise_estimate) followNoiseEstimate(scan);
  free_.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    free_[i] = scan.hasReturn(i) ? 1 : 0;
    labels[i] = static_cast<std::uint8_t>(scan.hasReturn(i) ? PointCode::kValid : PointCode::kNoReturn);
  }
  prepare(scan);
  cluster_of_.assign(n, StraightRunJoin::kNoCluster);
  std::uint32_t clusters = 0;
  for (std::uint32_t seed = 0; seed < n; ++seed) {
    if (!free_[seed]) continue;
    cluster_.clear();
    growCluster(seed, scan);
    for (std::uint32_t m : cluster_) cluster_of_[m] = clusters;
    ++clusters;
  }
  judgeClusters(scan, clusters, labels);
  off_surface_.apply(points_, scan.ranges, full_turn_, foreground_, labels);
}

void JumpFilter::followNoiseEstimate(const Scan& scan) {
  noise_.add(points_, scan.ranges, full_turn_);
  const RangeNoiseModel model = noise_.model();
  if (model == noiseModel()) return;
  // The rule and both checks hold their own copy of the parameters.
  setNoiseModel(params_, model);
  rule_.useNoiseModel(model);
  off_surface_.useNoiseModel(model);
  runs_.useNoiseModel(model);
}

void JumpFilter::judgeClusters(const Scan& scan, std::uint32_t cluster_count, std::span<std::uint8_t> labels) {
  const std::size_t n = scan.size();
  const auto& joined = runs_.join(points_, scan.ranges, full_turn_, scan.angle_increment, cluster_of_, cluster_count);
  // Group the beams by joined cluster, each group in index order (a counting
  // sort), so the span and mean range do not depend on how clusters grew.
  group_start_.assign(cluster_count + 1, 0);
  for (std::size_t i = 0; i < n; ++i)
    if (cluster_of_[i] != StraightRunJoin::kNoCluster) ++group_start_[joined[cluster_of_[i]] + 1];
  for (std::uint32_t c = 0; c < cluster_count; ++c) group_start_[c + 1] += group_start_[c];
  grouped_.resize(group_start_[cluster_count]);
  group_fill_ = group_start_;
  for (std::uint32_t i = 0; i < n; ++i)
    if (cluster_of_[i] != StraightRunJoin::kNoCluster) grouped_[group_fill_[joined[cluster_of_[i]]]++] = i;
  foreground_.assign(n, 0);
  for (std::uint32_t c = 0; c < cluster_count; ++c) {
    const std::span<const std::uint32_t> members(grouped_.data() + group_start_[c], group_start_[c + 1] - group_start_[c]);
    if (members.empty()) continue;
    const ClusterVerdict verdict = rule_.judge(members, scan.ranges, full_turn_, scan.angle_increment);
    if (verdict == ClusterVerdict::kLongEnough) continue;
    const bool foreground = verdict == ClusterVerdict::kForeground;
    for (std::uint32_t m : members)
      if (foreground) foreground_[m] = 1;
      else labels[m] = static_cast<std::uint8_t>(PointCode::kJump);
  }
}

// --- Reference: the paper's steps 2-5 literally -----------------------------

void ReferenceJumpFilter::growCluster(std::uint32_t seed, const Scan& scan) {
  free_[seed] = 0;
  cluster_.push_back(seed);
  const auto n = static_cast<std::uint32_t>(scan.size());
  // Breadth-first: every new member searches all free points of the scan.
  for (std::size_t k = 0; k < cluster_.size(); ++k) {
    const std::uint32_t m = cluster_[k];
    const double radius = rule_.neighbourRadius(scan.ranges[m]);
    const double radius_sq = radius * radius;
    for (std::uint32_t j = 0; j < n; ++j) {
      if (free_[j] && isNeighbour(m, j, radius_sq)) {
        free_[j] = 0;
        cluster_.push_back(j);
      }
    }
  }
}

// --- Fast: angular window plus skip list ------------------------------------

void FastJumpFilter::prepare(const Scan& scan) {
  const auto n = static_cast<std::uint32_t>(scan.size());
  next_free_.resize(n + 1);
  for (std::uint32_t i = 0; i <= n; ++i) next_free_[i] = i;
  for (std::uint32_t i = 0; i < n; ++i)
    if (!free_[i]) next_free_[i] = i + 1;

  // A disc of radius k·d around a point at range d subtends asin(k) from the
  // sensor; one beam of margin absorbs rounding. k >= 1 means no bound.
  double nearest = std::numeric_limits<double>::infinity(), farthest = 0.0;
  for (std::size_t i = 0; i < scan.size(); ++i) {
    if (!scan.hasReturn(i)) continue;
    nearest = std::min(nearest, scan.ranges[i]);
    farthest = std::max(farthest, scan.ranges[i]);
  }
  const double k = farthest > 0.0 ? rule_.maxRadiusPerMetre(nearest, farthest) : 0.0;
  const double increment = std::abs(scan.angle_increment);
  if (k >= 1.0 || increment <= 0.0) {
    half_window_ = n;
  } else {
    const double beams = std::floor(std::asin(k) / increment) + 1.0;
    half_window_ = beams >= n ? n : static_cast<std::uint32_t>(beams);
  }
}

std::uint32_t FastJumpFilter::nextFree(std::uint32_t i) {
  std::uint32_t root = i;
  while (next_free_[root] != root) root = next_free_[root];
  while (next_free_[i] != root) {  // path compression
    const std::uint32_t next = next_free_[i];
    next_free_[i] = root;
    i = next;
  }
  return root;
}

void FastJumpFilter::claim(std::uint32_t i) {
  free_[i] = 0;
  next_free_[i] = i + 1;
  cluster_.push_back(i);
}

void FastJumpFilter::visitFreeIn(std::uint32_t from, std::uint32_t to, std::uint32_t member,
                                 double radius_sq) {
  for (std::uint32_t j = nextFree(from); j <= to; j = nextFree(j + 1)) {
    if (isNeighbour(member, j, radius_sq)) claim(j);
  }
}

void FastJumpFilter::growCluster(std::uint32_t seed, const Scan& scan) {
  claim(seed);
  const auto n = static_cast<std::uint32_t>(scan.size());
  const bool whole_scan = 2 * static_cast<std::uint64_t>(half_window_) + 1 >= n;
  for (std::size_t k = 0; k < cluster_.size(); ++k) {
    const std::uint32_t m = cluster_[k];
    const double radius = rule_.neighbourRadius(scan.ranges[m]);
    const double radius_sq = radius * radius;
    if (whole_scan) {
      visitFreeIn(0, n - 1, m, radius_sq);
      continue;
    }
    const std::int64_t lo = static_cast<std::int64_t>(m) - half_window_;
    const std::int64_t hi = static_cast<std::int64_t>(m) + half_window_;
    visitFreeIn(static_cast<std::uint32_t>(std::max<std::int64_t>(lo, 0)),
                static_cast<std::uint32_t>(std::min<std::int64_t>(hi, n - 1)), m, radius_sq);
    if (!full_turn_) continue;
    // Across the seam: the window continues at the other end of the scan.
    if (lo < 0) visitFreeIn(static_cast<std::uint32_t>(lo + n), n - 1, m, radius_sq);
    if (hi >= n) visitFreeIn(0, static_cast<std::uint32_t>(hi - n), m, radius_sq);
  }
}

std::unique_ptr<JumpFilter> makeJumpFilter(const JumpFilterParams& params, Implementation impl) {
  if (impl == Implementation::kReference) return std::make_unique<ReferenceJumpFilter>(params);
  return std::make_unique<FastJumpFilter>(params);
}

}  // namespace scanfilter
