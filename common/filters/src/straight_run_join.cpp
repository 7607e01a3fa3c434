#include "scanfilter/straight_run_join.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "scanfilter/scan_geometry.hpp"

namespace scanfilter {

StraightRunJoin::StraightRunJoin(const JumpFilterParams& params) : params_(params) {}

bool StraightRunJoin::insideRun(std::int64_t i) const {
  const Eigen::Vector2d* p = returns_.at(i - 1);
  const Eigen::Vector2d* q = returns_.at(i);
  const Eigen::Vector2d* r = returns_.at(i + 1);
  if (!p || !q || !r) return false;
  const double max_gap = gap_per_metre_ * q->norm();
  if ((*q - *p).norm() > max_gap || (*r - *q).norm() > max_gap) return false;
  // A line the beam runs along (beyond the largest incidence) is no surface
  // it could see: a trail of mixed returns between an edge and its background.
  const Eigen::Vector2d along = *r - *p;
  if (std::abs(cross(along, *q)) < min_sin_to_beam_ * along.norm() * q->norm()) return false;
  return (*q - *p).dot(*r - *q) > 0.0 && !isFartherFromLineThan(*q, *p, *r, offSurfaceTolerance(params_, q->norm()));
}

std::uint32_t StraightRunJoin::find(std::uint32_t c) {
  while (parent_[c] != c) c = parent_[c] = parent_[parent_[c]];
  return c;
}

void StraightRunJoin::unite(std::uint32_t a, std::uint32_t b) {
  a = find(a);
  b = find(b);
  if (a != b) parent_[std::max(a, b)] = std::min(a, b);  // the smaller id: independent of order
}

void StraightRunJoin::joinRun(std::int64_t first, std::int64_t last, std::span<const std::uint32_t> cluster_of) {
  // The run's inside is first..last; a beam beyond either end belongs to it
  // too when it lies on the line of the two inside beams next to it (a
  // mixed return beside a wall run lies off that line, if near the beam
  // pair the inside test saw).
  const auto continues = [&](std::int64_t end, std::int64_t a, std::int64_t b) {
    const Eigen::Vector2d* p = returns_.at(end);
    return first < last && p &&
           !isFartherFromLineThan(*p, *returns_.at(a), *returns_.at(b), offSurfaceTolerance(params_, p->norm()));
  };
  if (continues(first - 1, first, first + 1)) --first;
  if (continues(last + 1, last - 1, last)) ++last;
  if (last - first + 1 < params_.straight_run_min_points) return;
  const auto n = static_cast<std::int64_t>(cluster_of.size());
  const auto cluster = [&](std::int64_t k) { return cluster_of[static_cast<std::size_t>(((k % n) + n) % n)]; };
  for (std::int64_t k = first + 1; k <= last; ++k) unite(cluster(first), cluster(k));
}

const std::vector<std::uint32_t>& StraightRunJoin::join(std::span<const Eigen::Vector2d> points,
                                                        std::span<const double> ranges, bool full_turn,
                                                        double angle_increment,
                                                        std::span<const std::uint32_t> cluster_of,
                                                        std::uint32_t cluster_count) {
  parent_.resize(cluster_count);
  std::iota(parent_.begin(), parent_.end(), 0u);
  if (!params_.straight_runs || points.size() < 3) return parent_;
  returns_ = WrappedReturns(points, ranges, full_turn);
  // A surface at incidence ι puts consecutive returns range·Δθ / cos ι apart.
  const double incidence = degreesToRadians(params_.straight_run_max_incidence_deg);
  gap_per_metre_ = std::abs(angle_increment) / std::cos(incidence);
  min_sin_to_beam_ = std::cos(incidence);
  const auto n = static_cast<std::int64_t>(points.size());
  // Runs are maximal stretches of beams inside a run. On a full turn one may
  // cross the seam: start at a beam that is not inside one, so none is cut in
  // two (a turn straight all round is one run).
  std::int64_t start = 0;
  if (full_turn) {
    while (start < n && insideRun(start)) ++start;
    if (start == n) start = 0;
  }
  std::int64_t run_first = -1;
  for (std::int64_t k = start; k < start + n; ++k) {
    const bool inside = insideRun(k);
    if (inside && run_first < 0) run_first = k;
    if (run_first >= 0 && (!inside || k + 1 == start + n)) {
      joinRun(run_first, inside ? k : k - 1, cluster_of);
      run_first = -1;
    }
  }
  for (std::uint32_t c = 0; c < cluster_count; ++c) parent_[c] = find(c);
  return parent_;
}

}  // namespace scanfilter
