#include "scanfilter/penetration_filter.hpp"

#include <algorithm>
#include <cmath>

#include <spdlog/spdlog.h>

#include "scanfilter/point_code.hpp"
#include "scanfilter/scan_geometry.hpp"

namespace scanfilter {

PenetrationFilter::PenetrationFilter(const PenetrationFilterParams& params)
    : params_(params), rule_(params), grid_(params.cell_size), evidence_(params.cell_size) {}

void PenetrationFilter::reset() {
  cache_.clear();
  grid_.clear();
  evidence_.clear();
  frames_seen_ = 0;
  last_origin_.reset();
}

void PenetrationFilter::resetOnPoseJump(const Eigen::Vector2d& origin, double stamp) {
  if (last_origin_ && (origin - *last_origin_).norm() > params_.pose_jump_reset) {
    // A relocalisation or a bad pose: the cached frames no longer line up
    // with the new one, so judging against them would delete good points.
    spdlog::info("penetration filter: sensor moved {:.3f} m between frames at stamp {:.3f} "
                 "(limit {:.3f} m); cache reset",
                 (origin - *last_origin_).norm(), stamp, params_.pose_jump_reset);
    reset();
    ++resets_;
  }
  last_origin_ = origin;
}

void PenetrationFilter::expireFrames(double stamp) {
  while (!cache_.empty() && (stamp - cache_.front().stamp > params_.frame_lifetime ||
                             cache_.size() >= params_.max_cache_frames)) {
    for (const auto& p : cache_.front().points) {
      grid_.remove(p);
      if (params_.rescue_persistent_points) evidence_.remove(p);
    }
    for (const auto& p : cache_.front().others) evidence_.remove(p);
    cache_.pop_front();
  }
}

void PenetrationFilter::cacheFrame(double stamp, std::span<const std::uint8_t> labels) {
  CachedFrame frame{stamp, {}, {}};
  for (std::size_t i = 0; i < labels.size(); ++i) {
    const auto code = static_cast<PointCode>(labels[i]);
    if (code == PointCode::kNoReturn) continue;
    const bool votes = code == PointCode::kValid ||
                       (code == PointCode::kMisdetected && params_.cache_misdetected_points);
    if (votes) {
      frame.points.push_back(points_[i]);
      grid_.add(points_[i]);
    } else if (params_.rescue_persistent_points) {
      frame.others.push_back(points_[i]);
    }
    if (params_.rescue_persistent_points) evidence_.add(points_[i]);
  }
  cache_.push_back(std::move(frame));
}

void PenetrationFilter::apply(const Scan& scan, const SensorInfo& sensor,
                              std::span<std::uint8_t> labels) {
  const Eigen::Vector2d origin = sensorOrigin(scan.pose, sensor.mount);
  resetOnPoseJump(origin, scan.stamp);
  ++frames_seen_;
  expireFrames(scan.stamp);
  worldPoints(scan, sensor, points_);

  if (warmedUp()) {
    if (params_.rescue_persistent_points) rescuePersistentPoints(labels);
    prepareJudging();
    for (std::size_t i = 0; i < labels.size(); ++i) {
      if (labels[i] != static_cast<std::uint8_t>(PointCode::kValid)) continue;
      if (isMisdetected(origin, points_[i]))
        labels[i] = static_cast<std::uint8_t>(PointCode::kMisdetected);
    }
  }
  cacheFrame(scan.stamp, labels);
}

int PenetrationFilter::evidenceAround(CellIndex c) const {
  const int r = params_.rescue_radius_cells;
  int sum = 0;
  for (int dy = -r; dy <= r; ++dy)
    for (int dx = -r; dx <= r; ++dx) sum += evidence_.count({c.x + dx, c.y + dy});
  return sum;
}

void PenetrationFilter::rescuePersistentPoints(std::span<std::uint8_t> labels) {
  // The evidence holds only earlier frames, so a point cannot vouch for itself.
  for (std::size_t i = 0; i < labels.size(); ++i) {
    if (labels[i] != static_cast<std::uint8_t>(PointCode::kJump)) continue;
    if (evidenceAround(evidence_.cellOf(points_[i])) >= params_.rescue_min_count)
      labels[i] = static_cast<std::uint8_t>(PointCode::kValid);
  }
}

// --- Reference ---------------------------------------------------------------

void ReferencePenetrationFilter::prepareJudging() {
  // Step 6: cells counting more than obs_th points are the obstacle set Q.
  obstacles_.clear();
  grid_.forEachCellAbove(params_.obstacle_threshold,
                         [this](CellIndex c, int) { obstacles_.push_back(grid_.cellCentre(c)); });
}

bool ReferencePenetrationFilter::isMisdetected(const Eigen::Vector2d& r,
                                               const Eigen::Vector2d& p) {
  const double own_sq = rule_.ownMarginSq((p - r).norm());
  for (const auto& q : obstacles_)  // steps a-f: every obstacle cell in turn
    if (rule_.penetrates(r, p, q, own_sq)) return true;
  return false;
}

// --- Fast ----------------------------------------------------------------------

namespace {

// Cells whose centre can lie within `half_width` of the segment a-b, visited
// column by column along the segment's dominant axis. `axis` 0 walks x.
template <typename Visit>
bool visitThickRay(const PenetrationGrid& grid, const Eigen::Vector2d& a, const Eigen::Vector2d& b,
                   double half_width, int axis, Visit&& visit) {
  const int other = 1 - axis;
  const double w = grid.cellSize();
  const Eigen::Vector2d d = b - a;
  const double slope = d[other] / d[axis];
  // A centre within half_width of the line sits within half_width / |cos| of
  // it along the other axis; one cell of margin absorbs rounding.
  const double band = half_width * std::sqrt(1.0 + slope * slope) + w;
  const auto lo = static_cast<std::int32_t>(std::floor((std::min(a[axis], b[axis]) - half_width) / w));
  const auto hi = static_cast<std::int32_t>(std::floor((std::max(a[axis], b[axis]) + half_width) / w));
  for (std::int32_t i = lo; i <= hi; ++i) {
    const double centre = (i + 0.5) * w;
    const double line = a[other] + (centre - a[axis]) * slope;
    const auto j_lo = static_cast<std::int32_t>(std::floor((line - band) / w));
    const auto j_hi = static_cast<std::int32_t>(std::floor((line + band) / w));
    for (std::int32_t j = j_lo; j <= j_hi; ++j) {
      const CellIndex c = axis == 0 ? CellIndex{i, j} : CellIndex{j, i};
      if (visit(c)) return true;
    }
  }
  return false;
}

}  // namespace

bool FastPenetrationFilter::isMisdetected(const Eigen::Vector2d& r, const Eigen::Vector2d& p) {
  const Eigen::Vector2d v = p - r;
  const double length = v.norm();
  if (length <= 0.0) return false;
  const double own_sq = rule_.ownMarginSq(length);
  // Penetrating cells project onto the beam between r and p + behind margin.
  const Eigen::Vector2d end = r + v * ((length + rule_.behindMargin()) / length);
  const int axis = std::abs(v.x()) >= std::abs(v.y()) ? 0 : 1;
  return visitThickRay(grid_, r, end, rule_.corridorHalfWidth(), axis, [&](CellIndex c) {
    return grid_.count(c) > params_.obstacle_threshold &&
           rule_.penetrates(r, p, grid_.cellCentre(c), own_sq);
  });
}

std::unique_ptr<PenetrationFilter> makePenetrationFilter(const PenetrationFilterParams& params,
                                                         Implementation impl) {
  if (impl == Implementation::kReference)
    return std::make_unique<ReferencePenetrationFilter>(params);
  return std::make_unique<FastPenetrationFilter>(params);
}

}  // namespace scanfilter
