#include "scanfilter/frame_alignment.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>

#include <Eigen/Dense>

#include "scanfilter/floor_to_int.hpp"
#include "scanfilter/scan_geometry.hpp"

namespace scanfilter {

namespace {

// A step smaller than this (m, rad) has converged.
constexpr double kConvergedShift = 1e-4;
constexpr double kConvergedTurn = 1e-5;
// Relative to the matches' count: far below what one constraining normal adds.
constexpr double kRidge = 1e-6;
// Distances here carry rounding errors of ~1e-16 m; a repeated answer is
// trusted only this far (m) inside the distance that makes it sure.
constexpr double kDistanceRoundingSlack = 1e-9;

Eigen::Vector2d perpendicular(const Eigen::Vector2d& v) { return {-v.y(), v.x()}; }

}  // namespace

void FrameAligner::snapshotObstacles(const PenetrationGrid& grid, std::span<const Eigen::Vector2d> points) {
  const Eigen::AlignedBox2d box = returnBounds(points);
  cell_size_ = grid.cellSize();
  if (box.isEmpty()) {
    width_ = height_ = 0;  // align() returns before any lookup; the next snapshot's reset clears cells_
    return;
  }
  const double reach = params_.max_match_distance + cell_size_;
  lo_ = grid.cellOf(box.min().array() - reach);
  const CellIndex top = grid.cellOf(box.max().array() + reach);
  width_ = top.x - lo_.x + 1;
  height_ = top.y - lo_.y + 1;
  cells_.reset(static_cast<std::size_t>(width_) * static_cast<std::size_t>(height_));
  occupied_bits_.reset(width_, height_);
  centroids_.clear();
  grid.forEachObstacleIn(lo_, top, [&](CellIndex c) {
    const int x = c.x - lo_.x, y = c.y - lo_.y;
    cells_.set(static_cast<std::size_t>(y * width_ + x), static_cast<std::int32_t>(centroids_.size()));
    occupied_bits_.set(x, y);
    centroids_.push_back(grid.centroid(c));
  });
}

FrameAligner::BlockSearch FrameAligner::searchBlock(const Eigen::Vector2d& p, int reach) const {
  const double max_distance = params_.max_match_distance;
  const int cell_x = floorToInt(p.x() / cell_size_);
  const int cell_y = floorToInt(p.y() / cell_size_);
  const auto cx = cell_x - lo_.x;
  const auto cy = cell_y - lo_.y;
  BlockSearch out;
  out.best_sq = max_distance * max_distance;
  out.edge = std::min({p.x() - (cell_x - reach) * cell_size_, (cell_x + reach + 1) * cell_size_ - p.x(),
                       p.y() - (cell_y - reach) * cell_size_, (cell_y + reach + 1) * cell_size_ - p.y()});
  const int x_lo = std::max(0, cx - reach), x_hi = std::min(width_ - 1, cx + reach);
  for (int y = std::max(0, cy - reach); y <= std::min(height_ - 1, cy + reach) && x_lo <= x_hi; ++y) {
    // The obstacle cells of this row in x order, as the cell-by-cell scan
    // visited them (ties keep going to the last one seen).
    for (int x0 = x_lo; x0 <= x_hi; x0 += CellBitmap::kMaxRun) {
      for (std::uint64_t bits = occupied_bits_.run(y, x0, std::min(CellBitmap::kMaxRun, x_hi - x0 + 1)); bits != 0; bits &= bits - 1) {
        const int x = x0 + std::countr_zero(bits);
        const Eigen::Vector2d& q = centroids_[static_cast<std::size_t>(cells_[static_cast<std::size_t>(y * width_ + x)])];
        const double d = (q - p).squaredNorm();
        if (d <= out.best_sq) {
          if (out.best != nullptr) out.runner_up_sq = std::min(out.runner_up_sq, out.best_sq);
          out.best_sq = d;
          out.best = &q;
        } else {
          out.runner_up_sq = std::min(out.runner_up_sq, d);
        }
      }
    }
  }
  return out;
}

const Eigen::Vector2d* FrameAligner::nearestObstacle(const Eigen::Vector2d& p, double* unchanged_within) const {
  const double max_distance = params_.max_match_distance;
  // Most points lie on a surface whose centroids are within a cell: the 3 x 3
  // cells around p settle the answer when it is nearer than their edge (every
  // centroid outside is at least that far), and only otherwise is the whole
  // reach searched. The answer is the same either way: the edge must be
  // farther by the rounding slack used below (a centroid may lie a rounding
  // error outside its cell, as a cell's sum drifts while points come and go),
  // so no centroid outside can tie with the answer or beat it.
  const auto reach = static_cast<int>(std::ceil(max_distance / cell_size_));
  BlockSearch found = searchBlock(p, std::min(1, reach));
  if (reach > 1 && (found.best == nullptr || !(std::sqrt(found.best_sq) + kDistanceRoundingSlack < found.edge)))
    found = searchBlock(p, reach);
  const double best = std::sqrt(found.best_sq);
  // The nearest centroid but the answer (or the nearest of all when there is
  // none); a centroid outside the cells searched is at least as far as their edge.
  const double runner_up = std::min(std::sqrt(found.runner_up_sq), found.edge);
  // The answer holds while no other centroid can come as near as it (both
  // distances change by at most the move) and it stays within reach; "none"
  // holds while every centroid stays out of reach. Strictly: a tie is never
  // assumed away.
  const double sure = found.best != nullptr ? std::min((runner_up - best) / 2.0, max_distance - best)
                                            : runner_up - max_distance;
  *unchanged_within = sure - kDistanceRoundingSlack;
  return found.best;
}

void FrameAligner::findNormals(std::span<const Eigen::Vector2d> points, const BeamMask& usable) {
  with_normal_points_.clear();
  normals_.clear();
  for (std::size_t i = 1; i + 1 < points.size(); ++i) {
    if (!usable[i] || !usable[i - 1] || !usable[i + 1]) continue;
    const Eigen::Vector2d& a = points[i - 1];
    const Eigen::Vector2d& b = points[i + 1];
    const Eigen::Vector2d along = b - a;
    const double span = along.norm();
    if (!(span > 0.0 && span <= params_.max_neighbour_span)) continue;
    if (isFartherFromLineThan(points[i], a, b, params_.max_off_line)) continue;
    with_normal_points_.push_back(points[i]);
    normals_.push_back(perpendicular(along) / span);
  }
  thinToMaxFitPoints();
}

void FrameAligner::thinToMaxFitPoints() {
  const auto max_points = static_cast<std::size_t>(params_.max_fit_points);
  const std::size_t n = with_normal_points_.size();
  if (max_points == 0 || n <= max_points) return;
  // max_points of them spread evenly over the scan: the k-th kept is k·n/max
  // (increasing, so copying in place never overwrites one still to come).
  for (std::size_t k = 0; k < max_points; ++k) {
    const std::size_t from = k * n / max_points;
    with_normal_points_[k] = with_normal_points_[from];
    normals_[k] = normals_[from];
  }
  with_normal_points_.resize(max_points);
  normals_.resize(max_points);
}

int FrameAligner::matchPoints(const Eigen::Isometry2d& correction) {
  matches_.clear();
  for (std::size_t k = 0; k < with_normal_points_.size(); ++k) {
    const Eigen::Vector2d p = correction * with_normal_points_[k];
    LastQuery& last = last_queries_[k];
    if (!((p - last.at).norm() < last.unchanged_within)) {
      last.nearest = nearestObstacle(p, &last.unchanged_within);
      last.at = p;
    }
    if (last.nearest != nullptr) matches_.push_back({with_normal_points_[k], normals_[k], *last.nearest});
  }
  return static_cast<int>(matches_.size());
}

Eigen::Isometry2d FrameAligner::step(const Eigen::Isometry2d& correction, const Eigen::Vector2d& origin) const {
  // Unknowns: shift (x, y) and turn about the corrected sensor origin.
  const Eigen::Vector2d centre = correction * origin;
  Eigen::Matrix3d h = Eigen::Matrix3d::Zero();
  Eigen::Vector3d g = Eigen::Vector3d::Zero();
  for (const auto& m : matches_) {
    const Eigen::Vector2d p = correction * m.point;
    const Eigen::Vector2d n = correction.linear() * m.normal;
    const Eigen::Vector3d jacobian(n.x(), n.y(), n.dot(perpendicular(p - centre)));
    h += jacobian * jacobian.transpose();
    g += jacobian * n.dot(p - m.target);
  }
  // A direction no match constrains (all normals across a corridor) gets no
  // step: a tiny ridge keeps the solve well posed without moving the others.
  h.diagonal().array() += kRidge * static_cast<double>(matches_.size());
  const Eigen::Vector3d delta = -h.ldlt().solve(g);
  Eigen::Isometry2d update = Eigen::Isometry2d::Identity();
  update.translate(centre + Eigen::Vector2d(delta.x(), delta.y()));
  update.rotate(delta.z());
  update.translate(-centre);
  return update * correction;
}

double FrameAligner::rms(const Eigen::Isometry2d& correction) const {
  if (matches_.empty()) return 0.0;
  double sum = 0.0;
  for (const auto& m : matches_) {
    const double d = (correction.linear() * m.normal).dot(correction * m.point - m.target);
    sum += d * d;
  }
  return std::sqrt(sum / static_cast<double>(matches_.size()));
}

Eigen::Isometry2d FrameAligner::fit(const Eigen::Vector2d& origin) {
  Eigen::Isometry2d correction = Eigen::Isometry2d::Identity();
  for (int iteration = 0; iteration < params_.max_iterations; ++iteration) {
    // The first iteration's matches (no correction) are align's own.
    const int matched = iteration == 0 ? static_cast<int>(matches_.size()) : matchPoints(correction);
    if (matched < params_.min_matches) break;
    const Eigen::Isometry2d next = step(correction, origin);
    const Eigen::Isometry2d delta = next * correction.inverse();
    correction = next;
    if (delta.translation().norm() < kConvergedShift &&
        std::abs(Eigen::Rotation2Dd(delta.linear()).angle()) < kConvergedTurn)
      break;
  }
  return correction;
}

FrameAlignment FrameAligner::align(const PenetrationGrid& grid, std::span<const Eigen::Vector2d> points,
                                   const BeamMask& usable, const Eigen::Vector2d& origin) {
  FrameAlignment out;
  snapshotObstacles(grid, points);
  findNormals(points, usable);
  out.candidates = static_cast<int>(with_normal_points_.size());
  last_queries_.assign(with_normal_points_.size(), {Eigen::Vector2d::Zero(), nullptr, -1.0});
  if (width_ == 0 || out.candidates == 0) return out;
  const Eigen::Isometry2d identity = Eigen::Isometry2d::Identity();
  const int matched_as_is = matchPoints(identity);
  const double rms_as_is = rms(identity);
  Eigen::Isometry2d correction = fit(origin);
  // fit leaves the matches of no correction only when it took no step.
  const bool moved = correction.matrix() != identity.matrix();
  out.matches = moved ? matchPoints(correction) : matched_as_is;
  out.rms = moved ? rms(correction) : rms_as_is;
  const bool gained = out.matches >= matched_as_is && out.rms <= rms_as_is - params_.min_rms_gain;
  if (!gained) {  // the frame fits as well where odometry put it: keep that
    out.matches = matched_as_is;
    out.rms = rms_as_is;
    correction = identity;
  }
  out.correction = correction;
  out.good = out.matches >= params_.min_matches &&
             out.matches >= params_.min_matched_share * static_cast<double>(out.candidates) &&
             out.rms <= params_.max_rms;
  return out;
}

}  // namespace scanfilter
